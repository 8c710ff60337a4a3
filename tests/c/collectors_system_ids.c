/* The system ID collector functions (cnc_rdsyshard, cnc_rdsyssoft3,
 * cnc_rdsyssoft, cnc_rdsyssoft2, cnc_rdsyssoft3_str,
 * cnc_rdservoid, cnc_rdspindleid, cnc_rdfromservoid, cnc_rdfromspindleid), called
 * through the .so against focas-sim; the key=value lines it prints are
 * compared by tests/artifacts/c_examples/collectors_system_ids.rs with the
 * profile's [system] section. Usage: collectors_system_ids HOST PORT */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "fwlib32.h"

static void check(const char *what, short rc) {
    if (rc != EW_OK) {
        fprintf(stderr, "%s: %d\n", what, rc);
        exit(1);
    }
}

/* Boards s_no.. (num asked): key=count;id1,id2,group,hard,num,slot,f1,f2|... */
static void boards(unsigned short h, const char *key, short s_no, short num) {
    ODBSYSH b[8];
    memset(b, 0xee, sizeof b);
    check(key, cnc_rdsyshard(h, s_no, &num, b));
    printf("%s=%d;", key, num);
    for (int i = 0; i < num; i++)
        printf("%s%lu,%lu,%d,%d,%d,%d,%d,%d", i ? "|" : "", (unsigned long)b[i].id1,
               (unsigned long)b[i].id2, b[i].group_id, b[i].hard_id, b[i].hard_num, b[i].slot_no,
               b[i].id1_format, b[i].id2_format);
    /* The entry after the last written is left as it was. */
    printf(";%s\n", num < 8 && b[num].group_id == (short)0xeeee ? "untouched" : "written");
}

/* Software s_no.. (num asked): key=count,total;id:series:edition|... */
static void software(unsigned short h, const char *key, short s_no, short num) {
    ODBSYSS3 s[8];
    short total = -1;
    memset(s, 0xee, sizeof s);
    check(key, cnc_rdsyssoft3(h, s_no, &num, &total, s));
    printf("%s=%d,%d;", key, num, total);
    for (int i = 0; i < num; i++)
        printf("%s%d:%.4s:%.4s:%d%d", i ? "|" : "", s[i].soft_id, s[i].soft_series,
               s[i].soft_edition, s[i].soft_series[4], s[i].soft_edition[4]);
    printf("\n");
}

/* Software with names s_no.. (num asked): key=count,total;id:name:series:edition|... */
static void software_str(unsigned short h, const char *key, short s_no, short num) {
    ODBSYSS3_STR s[8];
    short total = -1;
    memset(s, 0xee, sizeof s);
    check(key, cnc_rdsyssoft3_str(h, s_no, &num, &total, s));
    printf("%s=%d,%d;", key, num, total);
    for (int i = 0; i < num; i++)
        printf("%s%d:%.13s:%.4s:%.4s", i ? "|" : "", s[i].soft_id, s[i].soft_name,
               s[i].soft_series, s[i].soft_edition);
    printf(";%s\n", num < 8 && s[num].soft_id == (short)0xeeee ? "untouched" : "written");
}

/* cnc_rdsyssoft / cnc_rdsyssoft2's common part (both structs begin alike):
 * key=phys:logical:module:soft:series:version|... over the physical slots up
 * to the 0xff ending them; then the entry after the last, the named series
 * and versions, soft_inst. */
#define SYSSOFT(key, s)                                                                           \
    do {                                                                                          \
        int n_ = 0;                                                                               \
        printf("%s=", key);                                                                       \
        while (n_ < 16 && (unsigned char)(s).slot_no_p[n_] != 0xff) {                             \
            printf("%s%02x:%d:%d:%d:%s:%s", n_ ? "|" : "", (unsigned char)(s).slot_no_p[n_],       \
                   (unsigned char)(s).slot_no_l[n_], (s).module_id[n_], (s).soft_id[n_],            \
                   (s).soft_series[n_], (s).soft_version[n_]);                                     \
            n_++;                                                                                 \
        }                                                                                         \
        printf("\n%s.after=%02x:%d:%d:%d:%d\n", key, (unsigned char)(s).slot_no_l[n_],            \
               (s).module_id[n_], (s).soft_id[n_], (s).soft_series[n_][0], (s).soft_version[n_][4]); \
        printf("%s.named=%s:%s|%s:%s|%s:%s|%s:%s|%s:%s\n", key, (s).boot_ser, (s).boot_ver,       \
               (s).servo_ser, (s).servo_ver, (s).pmc_ser, (s).pmc_ver, (s).ladder_ser,             \
               (s).ladder_ver, (s).eth_boot_ser, (s).eth_boot_ver);                               \
        printf("%s.inst=%d\n", key, (s).soft_inst);                                              \
    } while (0)

/* A drive's eight ID strings, `|`-separated (each NUL-terminated in its field). */
#define ID8(key, d, a, b, c, e, f, g, i, j)                                                  \
    printf("%s=%.*s|%.*s|%.*s|%.*s|%.*s|%.*s|%.*s|%.*s\n", key, (int)sizeof d.a, d.a,           \
           (int)sizeof d.b, d.b, (int)sizeof d.c, d.c, (int)sizeof d.e, d.e, (int)sizeof d.f, d.f, \
           (int)sizeof d.g, d.g, (int)sizeof d.i, d.i, (int)sizeof d.j, d.j)

static void servo(const char *key, const ODBCSVID *d) {
    ID8(key, (*d), mt_spc, mt_srn, plc_spc, plc_srn, svm_spc, svm_srn, psm_spc, psm_srn);
}

static void spindle(const char *key, const ODBCSPID *d) {
    ID8(key, (*d), mt_spc, mt_srn, sbmt_spc, sbmt_srn, spm_spc, spm_srn, psm_spc, psm_srn);
}

int main(int argc, char **argv) {
    unsigned short h;
    if (argc != 3) return 2;
    check("allclibhndl3", cnc_allclibhndl3(argv[1], (unsigned short)atoi(argv[2]), 10, &h));

    boards(h, "hard.all", 1, 8);
    boards(h, "hard.second", 2, 1);
    boards(h, "hard.past", 100, 4);
    short num = 0;
    ODBSYSH one;
    printf("hard.none=%d\n", cnc_rdsyshard(h, 1, &num, &one));

    software(h, "soft.all", 1, 8);
    software(h, "soft.last", 3, 5);
    num = 2;
    short total = 0;
    ODBSYSS3 two[2];
    printf("soft.zero=%d\n", cnc_rdsyssoft3(h, 0, &num, &total, two));

    software_str(h, "softstr.all", 1, 8);
    software_str(h, "softstr.second", 2, 1);

    /* The slots and their software, as cnc_rdsyssoft and cnc_rdsyssoft2 read them. */
    ODBSYSS ss;
    ODBSYSS2 ss2;
    memset(&ss, 0xee, sizeof ss);
    check("rdsyssoft", cnc_rdsyssoft(h, &ss));
    SYSSOFT("syssoft", ss);
    memset(&ss2, 0xee, sizeof ss2);
    check("rdsyssoft2", cnc_rdsyssoft2(h, &ss2));
    SYSSOFT("syssoft2", ss2);
    printf("syssoft2.embethe=%s:%s\n", ss2.embEthe_ser, ss2.embEthe_ver);
    printf("syssoft.same=%d\n", memcmp(&ss, &ss2, sizeof ss) == 0);
    printf("syssoft.null=%d\n", cnc_rdsyssoft(h, NULL));

    /* The servo and spindle drives' ID information, now and as saved. */
    ODBCSVID sv;
    ODBCSPID sp;
    memset(&sv, 0xee, sizeof sv);
    check("rdservoid", cnc_rdservoid(h, 2, 0, &sv));
    servo("servo.2", &sv);
    memset(&sv, 0xee, sizeof sv);
    check("rdfromservoid", cnc_rdfromservoid(h, 3, &sv));
    servo("fromservo.3", &sv);
    printf("servo.none=%d\n", cnc_rdservoid(h, 0, 0, &sv));
    memset(&sp, 0xee, sizeof sp);
    check("rdspindleid", cnc_rdspindleid(h, 1, 0, &sp));
    spindle("spindle.1", &sp);
    memset(&sp, 0xee, sizeof sp);
    check("rdfromspindleid", cnc_rdfromspindleid(h, 1, &sp));
    spindle("fromspindle.1", &sp);
    printf("spindle.none=%d\n", cnc_rdfromspindleid(h, 9, &sp));

    check("freelibhndl", cnc_freelibhndl(h));
    return 0;
}
