/* Servo data sampling (cnc_sdt*, FANUC's 32-bit library's functions)
 * called through the .so against focas-sim; prints key=value lines that
 * tests/artifacts compares with the simulator's servo state.
 * Usage: sampling HOST PORT */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "fwlib32.h"

/* The 8 channel values, 0x5a5a where nothing was written. */
static void one_shot(unsigned short h, const char *key) {
    unsigned short v[9];
    memset(v, 0x5a, sizeof v);
    short rc = cnc_sdtread1shot(h, v);
    printf("%s.rc=%d\n%s=", key, rc, key);
    for (int i = 0; i < 9; i++) printf("%s%u", i ? "," : "", v[i]);
    printf("\n");
}

int main(int argc, char **argv) {
    unsigned short h;
    if (argc != 3) return 2;
    short rc = cnc_allclibhndl3(argv[1], (unsigned short)atoi(argv[2]), 10, &h);
    if (rc != EW_OK) {
        fprintf(stderr, "allclibhndl3: %d\n", rc);
        return 1;
    }

    /* The profile's channels: each one's current value. */
    one_shot(h, "shot");
    printf("start=%d\n", cnc_sdtstartsmpl(h, 0, 8));
    one_shot(h, "running");
    printf("cancel=%d\n", cnc_sdtcancelsmpl(h));
    printf("restart=%d\n", cnc_sdtstartsmpl(h, 1, 100));
    printf("end=%d\n", cnc_sdtendsmpl(h));

    /* Channels cleared: nothing to read or start. */
    printf("clear=%d\n", cnc_sdtclrchnl(h));
    one_shot(h, "cleared");
    printf("start_cleared=%d\n", cnc_sdtstartsmpl(h, 0, 8));
    printf("end_cleared=%d\n", cnc_sdtendsmpl(h));

    /* Channels set: channel 1 the Y axis's type 1 (code 4, negated for
     * Y's even parameter 1023), channel 2 the X axis's type 0 (code 5),
     * channel 3 the spindle's type 0; each read back. */
    IDBSDTCHAN chan[3];
    memset(chan, 0, sizeof chan);
    chan[0].type = 1; chan[0].chno = 1; chan[0].axis = 2; chan[0].shift = 0;
    chan[1].type = 0; chan[1].chno = 2; chan[1].axis = 1; chan[1].shift = 3;
    chan[2].type = 0; chan[2].chno = 3; chan[2].axis = -1; chan[2].shift = 0;
    printf("set=%d\n", cnc_sdtsetchnl(h, 3, 8, chan));
    one_shot(h, "set_shot");
    /* Refused, nothing sent or changed: a type past the axis table, a
     * spindle type past its table, channel 9, a cycle of 7, n 9. */
    IDBSDTCHAN bad = chan[0];
    bad.type = 38;
    printf("bad_type=%d\n", cnc_sdtsetchnl(h, 1, 8, &bad));
    bad = chan[2];
    bad.type = 13;
    printf("bad_spindle=%d\n", cnc_sdtsetchnl(h, 1, 8, &bad));
    bad = chan[0];
    bad.chno = 9;
    printf("bad_chno=%d\n", cnc_sdtsetchnl(h, 1, 8, &bad));
    printf("bad_cycle=%d\n", cnc_sdtsetchnl(h, 1, 7, chan));
    printf("bad_n=%d\n", cnc_sdtsetchnl(h, 9, 8, chan));
    printf("null_chan=%d\n", cnc_sdtsetchnl(h, 1, 8, NULL));
    one_shot(h, "refused_shot");
    printf("start_set=%d\n", cnc_sdtstartsmpl(h, 0, 8));
    printf("end_set=%d\n", cnc_sdtendsmpl(h));
    /* cycle -1: the 30i class takes it, the 16i class refuses it. */
    printf("cycle_m1=%d\n", cnc_sdtsetchnl(h, 1, -1, chan));

    /* A NULL output: refused before any traffic. */
    printf("null=%d\n", cnc_sdtread1shot(h, NULL));

    cnc_freelibhndl(h);
    return 0;
}
