/* The tool_axis collector reads added from FANUC's library (position
 * deviations, spindles, commanded values, tool tip, magazine, set zone),
 * called through the .so against focas-sim; prints key=value lines that
 * tests/artifacts compares with the simulator's machine state.
 * Usage: collectors_tool_axis HOST PORT */
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

    short nspdl = -1;
    check("rdnspdl", cnc_rdnspdl(h, &nspdl));
    printf("nspdl=%d\n", nspdl);

    /* The spindles' actual speeds, which the deviations follow. */
    ODBACT2 act;
    memset(&act, 0, sizeof act);
    check("acts2", cnc_acts2(h, -1, &act));
    printf("speeds=");
    for (int i = 0; i < nspdl && i < 8; i++) printf("%s%ld", i ? "," : "", (long)(int)act.data[i]);
    printf("\n");

    /* One 4-byte long per spindle (at most 8), as FANUC's x86-64 library
     * writes them. */
    int errs[8];
    memset(errs, 0, sizeof errs);
    check("rdposerrs", cnc_rdposerrs(h, (long *)errs));
    printf("poserrs=");
    for (int i = 0; i < nspdl && i < 8; i++) printf("%s%d", i ? "," : "", errs[i]);
    printf("\n");

    /* The servo delay of each axis, which the Z deviation is one of. */
    ODBAXIS dly;
    memset(&dly, 0, sizeof dly);
    check("srvdelay", cnc_srvdelay(h, -1, sizeof dly, &dly));
    printf("srvdelay=");
    for (int i = 0; i < 3; i++) printf("%s%d", i ? "," : "", (int)dly.data[i]);
    printf("\n");

    int z = -1;
    check("rdposerrz", cnc_rdposerrz(h, (long *)&z));
    printf("poserrz=%d\n", z);

    cnc_freelibhndl(h);
    return 0;
}
