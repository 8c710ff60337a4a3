/* The panel and system collector functions (cnc_wropnlsgnl ...), called
 * through the .so against focas-sim: each write is read back from C; the
 * key=value lines it prints are compared by
 * tests/artifacts/c_examples/collectors_panel_system.rs with the profile
 * and the simulator's state. Usage: collectors_panel_system HOST PORT */
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

static void print_panel(const char *key, const IODBSGNL *sg) {
    printf("%s=%d,%d,%d,%d,%d,%d,%d,%d,%d,%d,%d,%d,%d\n", key, sg->mode, sg->hndl_ax,
           sg->hndl_mv, sg->rpd_ovrd, sg->jog_ovrd, sg->feed_ovrd, sg->spdl_ovrd, sg->blck_del,
           sg->sngl_blck, sg->machn_lock, sg->dry_run, sg->mem_prtct, sg->feed_hold);
}

int main(int argc, char **argv) {
    unsigned short h;
    if (argc != 3) return 2;
    check("allclibhndl3", cnc_allclibhndl3(argv[1], (unsigned short)atoi(argv[2]), 10, &h));

    /* cnc_wropnlsgnl: every signal written, then only the feed override;
     * a mode its signals cannot hold is refused and changes nothing. */
    IODBSGNL sg;
    memset(&sg, 0, sizeof sg);
    sg.type = 0x1fff;
    sg.mode = 1;
    sg.hndl_ax = 2;
    sg.hndl_mv = 3;
    sg.rpd_ovrd = 1;
    sg.jog_ovrd = 0x1234;
    sg.feed_ovrd = 100;
    sg.blck_del = 1;
    sg.machn_lock = 1;
    sg.mem_prtct = 1;
    check("wropnlsgnl", cnc_wropnlsgnl(h, &sg));
    IODBSGNL rd;
    memset(&rd, 0, sizeof rd);
    check("rdopnlsgnl", cnc_rdopnlsgnl(h, 0x1fff, &rd));
    print_panel("panel.all", &rd);
    memset(&sg, 0, sizeof sg);
    sg.type = 0x20;
    sg.feed_ovrd = 120;
    sg.mode = 4; /* not selected: not written */
    check("wropnlsgnl feed", cnc_wropnlsgnl(h, &sg));
    sg.type = 0x1fff;
    sg.mode = 8;
    printf("panel.refused=%d\n", cnc_wropnlsgnl(h, &sg));
    check("rdopnlsgnl", cnc_rdopnlsgnl(h, 0x1fff, &rd));
    print_panel("panel.feed", &rd);

    /* cnc_wropnlgnrl: switches 1..4 set as 0101 (type 0x0f; the library
     * leaves type's low byte), then switch 8 on alone. */
    IODBGNRL gw;
    memset(&gw, 0, sizeof gw);
    gw.type = 0x010f;
    gw.sgnal = 0x05;
    check("wropnlgnrl", cnc_wropnlgnrl(h, &gw));
    printf("gnrl.type_after=%d\n", gw.type);
    gw.type = 0x80;
    gw.sgnal = (char)0xff;
    check("wropnlgnrl 8", cnc_wropnlgnrl(h, &gw));
    IODBGNRL gr;
    memset(&gr, 0, sizeof gr);
    check("rdopnlgnrl", cnc_rdopnlgnrl(h, 0xff, &gr));
    printf("gnrl=%d,%u\n", gr.type, (unsigned)(unsigned char)gr.sgnal);

    /* cnc_rdopnlgsname / cnc_wropnlgsname: the profile's names, then
     * switch 2 renamed (only the selected name changes; 8 characters go). */
    IODBRDNA na;
    memset(&na, 0, sizeof na);
    check("rdopnlgsname", cnc_rdopnlgsname(h, 0xff, &na));
    printf("gsname.before=%s|%s|%s|%s|%s\n", na.sgnl1_name, na.sgnl2_name, na.sgnl3_name,
           na.sgnl4_name, na.sgnl5_name);
    IODBRDNA nw;
    memset(&nw, 0, sizeof nw);
    nw.type = 0x02;
    memcpy(nw.sgnl1_name, "IGNORED", 8);
    memcpy(nw.sgnl2_name, "TABLEAIR", 8);
    nw.sgnl2_name[8] = 'X';
    check("wropnlgsname", cnc_wropnlgsname(h, &nw));
    memset(&na, 0x55, sizeof na);
    check("rdopnlgsname", cnc_rdopnlgsname(h, 0xff, &na));
    printf("gsname.after=%s|%s|%s\n", na.sgnl1_name, na.sgnl2_name, na.sgnl3_name);

    /* cnc_rdsetnum: the setting data's numbers. */
    ODBSETNUM sn;
    memset(&sn, 0xff, sizeof sn);
    check("rdsetnum", cnc_rdsetnum(h, &sn));
    printf("setnum=%u,%u,%u\n", sn.set_min, sn.set_max, sn.total_no);

    cnc_freelibhndl(h);
    return 0;
}
