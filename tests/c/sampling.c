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

    /* A NULL output: refused before any traffic. */
    printf("null=%d\n", cnc_sdtread1shot(h, NULL));

    cnc_freelibhndl(h);
    return 0;
}
