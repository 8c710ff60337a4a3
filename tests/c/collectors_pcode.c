/* The P-code macro functions added from FANUC's library (cnc_rdpmacroinfo2,
 * cnc_rdpmacro, cnc_wrpmacro, cnc_rdpmacror), called through the .so against focas-sim; prints
 * key=value lines that tests/artifacts compares with the simulator's
 * machine state. Usage: collectors_pcode HOST PORT */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "fwlib32.h"

static int check(const char *what, short rc) {
    if (rc != EW_OK) {
        fprintf(stderr, "%s: %d\n", what, rc);
        exit(1);
    }
    return 0;
}

int main(int argc, char **argv) {
    unsigned short h;
    long n;
    if (argc != 3) return 2;
    check("allclibhndl3", cnc_allclibhndl3(argv[1], (unsigned short)atoi(argv[2]), 10, &h));

    ODBPMINF2 inf;
    memset(&inf, 0, sizeof inf);
    check("rdpmacroinfo2", cnc_rdpmacroinfo2(h, &inf));
    printf("pmacroinfo2=%d,%d,%d,%d,%d,%d\n", (int)inf.use_no1, (int)inf.use_no2,
           (int)inf.use_no20, inf.v1_type, inf.v2_type, inf.v20_type);

    for (n = 10000; n <= 10002; n++) {
        ODBPM pm;
        memset(&pm, 0, sizeof pm);
        check("rdpmacro", cnc_rdpmacro(h, n, &pm));
        printf("pmacro.%ld=%d,%d,%d\n", n, (int)pm.datano, (int)pm.mcr_val, pm.dec_val);
    }
    /* A number the CNC does not have. */
    {
        ODBPM pm;
        printf("pmacro.absent=%d\n", cnc_rdpmacro(h, 9999, &pm));
    }

    /* Write #10002 = -4.75, then #10003 vacant, and read both back. */
    check("wrpmacro", cnc_wrpmacro(h, 10002, -475, 2));
    check("wrpmacro", cnc_wrpmacro(h, 10003, 0, -1));
    for (n = 10002; n <= 10003; n++) {
        ODBPM pm;
        memset(&pm, 0, sizeof pm);
        check("rdpmacro", cnc_rdpmacro(h, n, &pm));
        printf("written.%ld=%d,%d,%d\n", n, (int)pm.datano, (int)pm.mcr_val, pm.dec_val);
    }
    /* #10000..#10004 in one read: room for 5 records (12 + 5 * 8 bytes). */
    {
        IODBPR pr;
        int i;
        memset(&pr, 0, sizeof pr);
        check("rdpmacror", cnc_rdpmacror(h, 10000, 10004, 52, &pr));
        printf("range=%d,%d", (int)pr.datano_s, (int)pr.datano_e);
        for (i = 0; i < 5; i++) printf(";%d,%d", (int)pr.data[i].mcr_val, pr.data[i].dec_val);
        printf("\n");
        printf("range.short=%d\n", cnc_rdpmacror(h, 10000, 10004, 44, &pr));
        printf("range.backwards=%d\n", cnc_rdpmacror(h, 10004, 10000, 52, &pr));
    }
    /* Refused before any traffic: a local variable, decimals past a byte;
     * by the CNC: a number it does not have (nothing written). */
    printf("wr.local=%d\n", cnc_wrpmacro(h, 99, 1, 0));
    printf("wr.dec=%d\n", cnc_wrpmacro(h, 10004, 1, 128));
    printf("wr.absent=%d\n", cnc_wrpmacro(h, 9999, 1, 0));

    cnc_freelibhndl(h);
    return 0;
}
