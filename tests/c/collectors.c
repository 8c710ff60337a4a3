/* The collector reads added from FANUC's library (cnc_rdprgnumo8,
 * cnc_rdspcss, cnc_rdopnlsgnl, cnc_rdtlinfo), called through the .so
 * against focas-sim; prints key=value lines that tests/artifacts compares
 * with the simulator's machine state. Usage: collectors HOST PORT */
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
    if (argc != 3) return 2;
    check("allclibhndl3", cnc_allclibhndl3(argv[1], (unsigned short)atoi(argv[2]), 10, &h));

    ODBPROO8 prg;
    check("rdprgnumo8", cnc_rdprgnumo8(h, &prg));
    printf("prgnumo8.data=%d\nprgnumo8.mdata=%d\n", (int)prg.data, (int)prg.mdata);

    ODBCSS css;
    check("rdspcss", cnc_rdspcss(h, &css));
    printf("css.srpm=%d\ncss.sspm=%d\ncss.smax=%d\n", (int)css.srpm, (int)css.sspm, (int)css.smax);

    ODBTLINFO tl;
    check("rdtlinfo", cnc_rdtlinfo(h, &tl));
    printf("tlinfo=%d,%d,%d,%d\n", (int)tl.max_group, (int)tl.max_tool, (int)tl.max_minute,
           (int)tl.max_cycle);

    /* The panel's signals and the F bytes they come from (F73..F80). */
    IODBSGNL sg;
    memset(&sg, 0, sizeof sg);
    check("rdopnlsgnl", cnc_rdopnlsgnl(h, 0x1fff, &sg));
    printf("panel=%d,%d,%d,%d,%d,%d,%d,%d,%d,%d,%d,%d,%d\n", sg.type, sg.mode, sg.hndl_ax,
           sg.hndl_mv, sg.rpd_ovrd, sg.jog_ovrd, sg.feed_ovrd, sg.blck_del, sg.sngl_blck,
           sg.machn_lock, sg.dry_run, sg.mem_prtct, sg.feed_hold);
    IODBPMC f;
    check("pmc_rdpmcrng", pmc_rdpmcrng(h, 1, 0, 73, 77, 8 + 5, &f));
    IODBPMC f2;
    check("pmc_rdpmcrng", pmc_rdpmcrng(h, 1, 0, 78, 80, 8 + 3, &f2));
    printf("f73_80=%u,%u,%u,%u,%u,%u,%u,%u\n", (unsigned char)f.u.cdata[0],
           (unsigned char)f.u.cdata[1], (unsigned char)f.u.cdata[2], (unsigned char)f.u.cdata[3],
           (unsigned char)f.u.cdata[4], (unsigned char)f2.u.cdata[0],
           (unsigned char)f2.u.cdata[1], (unsigned char)f2.u.cdata[2]);

    cnc_freelibhndl(h);
    return 0;
}
