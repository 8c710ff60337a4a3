/* The PMC long tail a data collector reads: the program's title (long
 * fields) and type, and the message functions FANUC's Linux library lacks; called
 * through the .so against focas-sim. The key=value lines it prints are
 * compared by tests/artifacts/c_examples/collectors_pmcdata.rs with the
 * profile. Usage: collectors_pmcdata HOST PORT */
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

static unsigned short connect(const char *host, const char *port) {
    unsigned short h;
    check("allclibhndl3", cnc_allclibhndl3(host, (unsigned short)atoi(port), 10, &h));
    return h;
}

/* A member's text: its characters up to the first NUL, at most n. */
static void text(const char *key, const char *m, size_t n) {
    size_t k = 0;
    while (k < n && m[k] != 0) k++;
    printf("%s=%.*s\n", key, (int)k, m);
}

static void title(const char *unit, unsigned short h) {
    ODBPMCTITLE2 t;
    char key[64];
    memset(&t, 0xcc, sizeof t);
    check("rdpmctitle2", pmc_rdpmctitle2(h, &t));
    snprintf(key, sizeof key, "%s.machine", unit);
    text(key, t.machine, sizeof t.machine);
    snprintf(key, sizeof key, "%s.prgno", unit);
    text(key, t.prgno, sizeof t.prgno);
    snprintf(key, sizeof key, "%s.prgvers", unit);
    text(key, t.prgvers, sizeof t.prgvers);
    snprintf(key, sizeof key, "%s.remarks", unit);
    text(key, t.remarks, sizeof t.remarks);
    /* Past what the CNC sends, each member is zeroed. */
    int zero = 1;
    for (size_t i = 8; i < sizeof t.prgno; i++) zero &= t.prgno[i] == 0 && t.prgvers[i] == 0;
    for (size_t i = 32; i < sizeof t.mtb; i++) zero &= t.mtb[i] == 0 && t.remarks[i] == 0;
    snprintf(key, sizeof key, "%s.zeroed", unit);
    printf("%s=%d\n", key, zero);
}

int main(int argc, char **argv) {
    if (argc != 3) return 2;
    unsigned short h = connect(argv[1], argv[2]);

    /* The title with its longer fields, on unit 1. */
    title("title", h);

    /* The program's and the memory's type. */
    ODBPMCLADMEMTYPE ty;
    memset(&ty, 0, sizeof ty);
    check("read_seq_program_and_memory_type", pmc_read_seq_program_and_memory_type(h, &ty));
    printf("type.system=%lu\n", (unsigned long)ty.SystemType);
    printf("type.system_attribute=%lu\n", (unsigned long)ty.SystemAttribute);
    printf("type.target=%lu\n", (unsigned long)ty.TargetType);
    printf("type.target_attribute=%lu\n", (unsigned long)ty.TargetAttribute);
    text("type.system_name", ty.SystemTypeStr, sizeof ty.SystemTypeStr);
    text("type.target_name", ty.TargetTypeStr, sizeof ty.TargetTypeStr);

    /* The message functions: EW_FUNC, as FANUC's Linux library. */
    short data[4] = {0}, len = 8;
    printf("rdmsg=%d\n", pmc_rdmsg(h, data, &len));
    printf("crdmsg=%d\n", pmc_crdmsg(h, data, &len));
    printf("wrmsg=%d\n", pmc_wrmsg(h, 8, data));
    printf("cwrmsg=%d\n", pmc_cwrmsg(h, 8, data));

    /* Unit 2 has its own title. */
    unsigned short h2 = connect(argv[1], argv[2]);
    check("select_pmc_unit", pmc_select_pmc_unit(h2, 2));
    title("unit2", h2);

    cnc_freelibhndl(h2);
    cnc_freelibhndl(h);
    return 0;
}
