/* The long-tail PMC control functions (family C: the control data group
 * numbers, the ladders and backup memory), called through the .so against focas-sim; the key=value lines
 * it prints are compared by tests/artifacts/c_examples/collectors_pmcctl.rs
 * with the profile. Usage: collectors_pmcctl HOST PORT */
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

int main(int argc, char **argv) {
    if (argc != 3) return 2;
    unsigned short h = connect(argv[1], argv[2]);
    short g = -1;

    /* The data table's control data group number: read, written, a
     * refused number (kept), then unit 2's own. */
    check("rdcntlgrp", pmc_rdcntlgrp(h, &g));
    printf("cntlgrp=%d\n", g);
    check("wrcntlgrp", pmc_wrcntlgrp(h, 25));
    check("rdcntlgrp", pmc_rdcntlgrp(h, &g));
    printf("cntlgrp.set=%d\n", g);
    printf("wrcntlgrp.refused=%d\n", pmc_wrcntlgrp(h, 2001));
    check("rdcntlgrp", pmc_rdcntlgrp(h, &g));
    printf("cntlgrp.kept=%d\n", g);

    /* The extended relay's. */
    check("rdcntl_exrelay_grp", pmc_rdcntl_exrelay_grp(h, &g));
    printf("exrelay=%d\n", g);
    check("wrcntl_exrelay_grp", pmc_wrcntl_exrelay_grp(h, 9));
    check("rdcntl_exrelay_grp", pmc_rdcntl_exrelay_grp(h, &g));
    printf("exrelay.set=%d\n", g);
    printf("wrexrelay.refused=%d\n", pmc_wrcntl_exrelay_grp(h, -1));

    /* The extended backup memory's size (4 bytes written) and the ladders. */
    unsigned long size = 0;
    long ladders = 0; /* 4 bytes written: the rest stays 0 */
    memset(&size, 0xee, sizeof size);
    check("kpmsiz", pmc_kpmsiz(h, &size));
    printf("kpmsiz.low=%lu\n", size & 0xffffffffUL);
    printf("kpmsiz.high=%lu\n", (unsigned long)(size >> 31 >> 1));
    check("get_number_of_ladder", pmc_get_number_of_ladder(h, &ladders));
    printf("ladders=%ld\n", ladders);

    /* Another connection sees the machine's state; unit 2 has its own. */
    unsigned short h2 = connect(argv[1], argv[2]);
    check("rdcntlgrp", pmc_rdcntlgrp(h2, &g));
    printf("cntlgrp.other=%d\n", g);
    check("rdcntl_exrelay_grp", pmc_rdcntl_exrelay_grp(h2, &g));
    printf("exrelay.other=%d\n", g);
    check("select_pmc_unit", pmc_select_pmc_unit(h2, 2));
    check("rdcntlgrp", pmc_rdcntlgrp(h2, &g));
    printf("cntlgrp.unit2=%d\n", g);
    check("rdcntl_exrelay_grp", pmc_rdcntl_exrelay_grp(h2, &g));
    printf("exrelay.unit2=%d\n", g);
    check("kpmsiz", pmc_kpmsiz(h2, &size));
    printf("kpmsiz.unit2=%lu\n", size & 0xffffffffUL);
    check("get_number_of_ladder", pmc_get_number_of_ladder(h2, &ladders));
    printf("ladders.unit2=%ld\n", ladders);

    cnc_freelibhndl(h2);
    cnc_freelibhndl(h);
    return 0;
}
