/* The 3D handle collector read added from FANUC's library (cnc_rd3dtooltip),
 * called through the .so against focas-sim; prints key=value lines that
 * tests/artifacts compares with the simulator's machine state.
 * Usage: collectors_3dhandle HOST PORT */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "fwlib32.h"

int main(int argc, char **argv) {
    unsigned short h;
    if (argc != 3) return 2;
    short rc = cnc_allclibhndl3(argv[1], (unsigned short)atoi(argv[2]), 10, &h);
    if (rc != EW_OK) {
        fprintf(stderr, "allclibhndl3: %d\n", rc);
        return 1;
    }

    /* Filled with 0x5a first: the elements past the CNC's axes keep it. */
    ODB3DHDL tip;
    memset(&tip, 0x5a, sizeof tip);
    rc = cnc_rd3dtooltip(h, &tip);
    printf("rc=%d\n", rc);
    printf("axes=");
    for (int i = 0; i < 5; i++) printf("%s%d", i ? "," : "", tip.axes[i]);
    printf("\ndata=");
    for (int i = 0; i < 5; i++) printf("%s%ld", i ? "," : "", (long)(int)tip.data[i]);
    printf("\n");

    /* A NULL struct: refused before any traffic. */
    printf("null=%d\n", cnc_rd3dtooltip(h, NULL));

    cnc_freelibhndl(h);
    return 0;
}
