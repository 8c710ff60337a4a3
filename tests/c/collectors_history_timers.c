/* The history, timer and panel long-tail functions (cnc_rdalmhisno3,
 * cnc_getrtmrvar, cnc_wropnlgnrl2 ...), called through the .so against
 * focas-sim: each write is read back from C; the key=value lines it
 * prints are compared by tests/artifacts/c_examples/collectors_history_timers.rs
 * with the profile and the simulator's state.
 * Usage: collectors_history_timers HOST PORT */
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

int main(int argc, char **argv) {
    unsigned short h;
    if (argc != 3) return 2;
    check("allclibhndl3", cnc_allclibhndl3(argv[1], (unsigned short)atoi(argv[2]), 10, &h));

    /* The histories' counts: the *3 forms and the older ones agree. */
    unsigned short alm = 0xffff, alm3 = 0xffff, op = 0xffff, op3 = 0xffff;
    check("rdalmhisno", cnc_rdalmhisno(h, &alm));
    check("rdalmhisno3", cnc_rdalmhisno3(h, &alm3));
    check("rdophisno", cnc_rdophisno(h, &op));
    check("rdophisno3", cnc_rdophisno3(h, &op3));
    printf("almhisno=%u,%u\n", alm, alm3);
    printf("ophisno=%u,%u\n", op, op3);

    /* The signals the operation history records, the 16i's form: the
     * same entries as cnc_rdhissgnl3's first 20. */
    IODBSIG sg;
    memset(&sg, 0x55, sizeof sg);
    check("rdhissgnl", cnc_rdhissgnl(h, &sg));
    IODBSIG3 sg3;
    memset(&sg3, 0, sizeof sg3);
    check("rdhissgnl3", cnc_rdhissgnl3(h, &sg3));
    int same = 1;
    for (int k = 0; k < 20; k++) {
        same &= sg.data[k].ent_no == sg3.data[k].ent_no && sg.data[k].sig_no == sg3.data[k].sig_no &&
                sg.data[k].sig_name == sg3.data[k].sig_name &&
                sg.data[k].mask_pat == sg3.data[k].mask_pat;
    }
    printf("hissgnl.same=%d\n", same);
    printf("hissgnl.first=%d,%d,%d,%u;%d\n", sg.data[0].ent_no, sg.data[0].sig_no,
           sg.data[0].sig_name, (unsigned)(unsigned char)sg.data[0].mask_pat, sg.data[19].ent_no);

    /* The MAC address: 12 digits and a NUL. */
    char mac[16];
    memset(mac, 0x55, sizeof mac);
    check("getmacaddress", cnc_getmacaddress(h, mac));
    printf("mac=%s;%d\n", mac, mac[13]);

    /* The real-time custom macro variables' counts (4 bytes written into
     * each long, as FANUC's x86-64 library writes them). */
    long v = 0, vs = 0;
    check("getrtmrvar", cnc_getrtmrvar(h, &v));
    check("getrtmrvars", cnc_getrtmrvars(h, &vs));
    printf("rtmr=%d,%d\n", (int)v, (int)vs);

    /* cnc_wropnlgnrl2: switches 1..4 set as 0101 (type 0x0f), then
     * switch 8 on alone; read back through both reads. */
    IODBGNRL2 gw;
    memset(&gw, 0, sizeof gw);
    gw.type = 0x0f;
    gw.sgnal = 0x05;
    check("wropnlgnrl2", cnc_wropnlgnrl2(h, &gw));
    gw.type = 0x80;
    gw.sgnal = 0xff;
    check("wropnlgnrl2 8", cnc_wropnlgnrl2(h, &gw));
    IODBGNRL2 gr;
    memset(&gr, 0x55, sizeof gr);
    check("rdopnlgnrl2", cnc_rdopnlgnrl2(h, 0xff, &gr));
    IODBGNRL g1;
    memset(&g1, 0, sizeof g1);
    check("rdopnlgnrl", cnc_rdopnlgnrl(h, 0xff, &g1));
    printf("gnrl2=%d,%d,%u\n", gr.type, gr.sgnal, (unsigned)(unsigned char)g1.sgnal);

    /* cnc_rdopnlgsname2 / cnc_wropnlgsname2: the profile's names, then
     * switches 2 and 12 renamed (only selected names change; 8
     * characters go). */
    IODBRDNA2 na;
    memset(&na, 0x55, sizeof na);
    check("rdopnlgsname2", cnc_rdopnlgsname2(h, -1, &na));
    printf("gsname2.before=%d;%s|%s|%s|%s|%s|%s\n", na.type, na.sgnl1_name, na.sgnl2_name,
           na.sgnl3_name, na.sgnl4_name, na.sgnl5_name, na.sgnl16_name);
    IODBRDNA2 nw;
    memset(&nw, 0, sizeof nw);
    nw.type = (1 << 1) | (1 << 11);
    memcpy(nw.sgnl1_name, "IGNORED", 8);
    memcpy(nw.sgnl2_name, "TABLEAIR", 8);
    nw.sgnl2_name[8] = 'X';
    memcpy(nw.sgnl12_name, "MIST", 5);
    check("wropnlgsname2", cnc_wropnlgsname2(h, &nw));
    memset(&na, 0x55, sizeof na);
    check("rdopnlgsname2", cnc_rdopnlgsname2(h, -1, &na));
    printf("gsname2.after=%s|%s|%s|%s|%s\n", na.sgnl1_name, na.sgnl2_name, na.sgnl3_name,
           na.sgnl11_name, na.sgnl12_name);
    IODBRDNA n1;
    memset(&n1, 0, sizeof n1);
    check("rdopnlgsname", cnc_rdopnlgsname(h, 0xff, &n1));
    printf("gsname.after=%s|%s\n", n1.sgnl1_name, n1.sgnl2_name);

    cnc_freelibhndl(h);
    return 0;
}
