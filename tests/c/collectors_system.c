/* The long-tail system functions (family A: the drives' *2 IDs, the CNC
 * model and language, protection levels, screen and program state), called
 * through the .so against focas-sim; the key=value lines it prints are
 * compared by tests/artifacts/c_examples/collectors_system.rs with the
 * profile and the simulator's state. Usage: collectors_system HOST PORT */
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

/* One ID string, NUL-terminated in its field, then `|` or the line's end. */
#define S(d, f, last) printf("%.*s%s", (int)sizeof(d).f, (d).f, (last) ? "\n" : "|")

static void servo2(const char *key, const ODBCSVID2 *d) {
    printf("%s=", key);
    S(*d, mt_spc, 0), S(*d, mt_srn, 0), S(*d, plc_spc, 0), S(*d, plc_srn, 0);
    S(*d, svm_spc, 0), S(*d, svm_srn, 0), S(*d, psm_spc, 0), S(*d, psm_srn, 0);
    S(*d, svs_see, 0), S(*d, pss_see, 0), S(*d, pm1_spc, 0), S(*d, pm1_srn, 0);
    S(*d, pm2_spc, 0), S(*d, pm2_srn, 1);
}

static void spindle2(const char *key, const ODBCSPID2 *d) {
    printf("%s=", key);
    S(*d, mt_spc, 0), S(*d, mt_srn, 0), S(*d, sbmt_spc, 0), S(*d, sbmt_srn, 0);
    S(*d, spm_spc, 0), S(*d, spm_srn, 0), S(*d, psm_spc, 0), S(*d, psm_srn, 0);
    S(*d, pss_see, 1);
}

int main(int argc, char **argv) {
    unsigned short h;
    if (argc != 3) return 2;
    check("allclibhndl3", cnc_allclibhndl3(argv[1], (unsigned short)atoi(argv[2]), 10, &h));

    /* The drives' ID information with software and power modules, now and as saved. */
    ODBCSVID2 sv;
    ODBCSPID2 sp;
    memset(&sv, 0xee, sizeof sv);
    check("rdservoid2", cnc_rdservoid2(h, 1, 0, &sv));
    servo2("servo2.1", &sv);
    memset(&sv, 0xee, sizeof sv);
    check("rdfromservoid2", cnc_rdfromservoid2(h, 3, &sv));
    servo2("fromservo2.3", &sv);
    printf("servo2.none=%d\n", cnc_rdservoid2(h, 0, 0, &sv));
    memset(&sp, 0xee, sizeof sp);
    check("rdspindleid2", cnc_rdspindleid2(h, 1, 0, &sp));
    spindle2("spindle2.1", &sp);
    memset(&sp, 0xee, sizeof sp);
    check("rdfromspindleid2", cnc_rdfromspindleid2(h, 1, &sp));
    spindle2("fromspindle2.1", &sp);
    printf("spindle2.none=%d\n", cnc_rdfromspindleid2(h, 9, &sp));

    /* The model, the display language: changed, then a refused change. */
    short v = -1, rd = -1, wt = -1;
    check("getcncmodel", cnc_getcncmodel(h, &v));
    printf("model=%d\n", v);
    check("getlanguage", cnc_getlanguage(h, &v));
    printf("language=%d\n", v);
    check("chglang", cnc_chglang(h, 2));
    check("getlanguage", cnc_getlanguage(h, &v));
    printf("language.changed=%d\n", v);
    printf("chglang.refused=%d\n", cnc_chglang(h, 16));
    check("getlanguage", cnc_getlanguage(h, &v));
    printf("language.kept=%d\n", v);

    /* The operation level; data kind 1's protection levels, set, then a refused set. */
    check("rdope_lvl", cnc_rdope_lvl(h, &v));
    printf("ope_lvl=%d\n", v);
    check("rdprt_lvl", cnc_rdprt_lvl(h, 1, &rd, &wt));
    printf("prt_lvl.1=%d,%d\n", rd, wt);
    check("wrprt_lvl", cnc_wrprt_lvl(h, 1, 2, 3));
    check("rdprt_lvl", cnc_rdprt_lvl(h, 1, &rd, &wt));
    printf("prt_lvl.1.set=%d,%d\n", rd, wt);
    printf("wrprt_lvl.refused=%d\n", cnc_wrprt_lvl(h, 1, 8, 0));
    check("rdprt_lvl", cnc_rdprt_lvl(h, 1, &rd, &wt));
    printf("prt_lvl.1.kept=%d,%d\n", rd, wt);
    printf("prt_lvl.none=%d\n", cnc_rdprt_lvl(h, 99, &rd, &wt));

    /* The menu switches: the low four set from 0x0a. */
    check("rdmenuswitch", cnc_rdmenuswitch(h, &v));
    printf("menu=%d\n", v);
    check("wrmenuswitch", cnc_wrmenuswitch(h, 0x0a, 0x0f));
    check("rdmenuswitch", cnc_rdmenuswitch(h, &v));
    printf("menu.set=%d\n", v);

    /* The counts: additional work coordinate systems, axes, spindles, repeats. */
    check("rdcoordnum", cnc_rdcoordnum(h, &v));
    printf("coordnum=%d\n", v);
    check("axisnum", cnc_axisnum(h, 0, &v));
    printf("axisnum.0=%d\n", v);
    check("axisnum", cnc_axisnum(h, 1, &v));
    printf("axisnum.1=%d\n", v);
    /* 4 bytes are written into the long (as FANUC's x86-64 library writes it). */
    long repeats = 0;
    check("rdrepeatval", cnc_rdrepeatval(h, &repeats));
    printf("repeat=%d\n", (int)repeats);

    /* The canned cycle in force. */
    ODBFIX fix;
    memset(&fix, 0xee, sizeof fix);
    check("rdfixcycle", cnc_rdfixcycle(h, &fix));
    printf("fixcycle=%d;%d,%d;%d;%d,%d,%d;%d,%d;%d;%d,%d\n", fix.mode, fix.pln_axes[0],
           fix.pln_axes[1], fix.drl_axes, (int)fix.i_pos, (int)fix.r_pos, (int)fix.z_pos,
           (int)fix.cmd_cnt, (int)fix.act_cnt, (int)fix.cut, (int)fix.shift[0], (int)fix.shift[1]);

    /* The main program's cursor: refused while it runs; after a reset, a
     * search (then one for a number it lacks, refused) and a rewind. */
    ODBSEQ seq;
    memset(&seq, 0, sizeof seq); /* 4 bytes are written into its long */
    printf("seqsrch.running=%d\n", cnc_seqsrch(h, 70));
    check("reset", cnc_reset(h));
    check("seqsrch", cnc_seqsrch(h, 70));
    check("rdseqnum", cnc_rdseqnum(h, &seq));
    printf("seq.searched=%d\n", (int)seq.data);
    printf("seqsrch.missing=%d\n", cnc_seqsrch(h, 75));
    check("rdseqnum", cnc_rdseqnum(h, &seq));
    printf("seq.kept=%d\n", (int)seq.data);
    check("rewind", cnc_rewind(h));
    check("rdseqnum", cnc_rdseqnum(h, &seq));
    printf("seq.rewound=%d\n", (int)seq.data);

    check("freelibhndl", cnc_freelibhndl(h));
    return 0;
}
