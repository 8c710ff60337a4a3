/* The 8-digit program functions and the P-code macro variables added from
 * FANUC's library, called through the .so against focas-sim; prints
 * key=value lines that tests/artifacts compares with the simulator's
 * machine state. Usage: collectors_programs_macros HOST PORT */
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

    /* Select an 8-digit program as the main program, read it back. */
    ODBPROO8 prg;
    check("searcho8", cnc_searcho8(h, 12345678));
    check("rdprgnumo8", cnc_rdprgnumo8(h, &prg));
    printf("searched.mdata=%d\n", (int)prg.mdata);
    /* A program that is not stored: refused, the main program stays. */
    printf("search_missing=%d\n", cnc_searcho8(h, 99999999));
    check("rdprgnumo8", cnc_rdprgnumo8(h, &prg));
    printf("after_missing.mdata=%d\n", (int)prg.mdata);

    /* Delete an 8-digit program; a second delete finds none. */
    check("deleteo8", cnc_deleteo8(h, 87654321));
    printf("delete_again=%d\n", cnc_deleteo8(h, 87654321));
    printf("search_deleted=%d\n", cnc_searcho8(h, 87654321));

    /* The MDI execution pointer, written then read with 8-digit numbers. */
    ODBMDIPO8 mdi;
    memset(&mdi, 0x55, sizeof mdi);
    check("wrmdipntr", cnc_wrmdipntr(h, 4321));
    check("rdmdipntro8", cnc_rdmdipntro8(h, &mdi));
    printf("mdipntro8=%d,%d,%d,%d\n", (int)mdi.mdiprog, (int)mdi.mdipntr, (int)mdi.crntprog,
           (int)mdi.crntpntr);

    /* The P-code macro variables the path has. */
    ODBPMINF pm;
    memset(&pm, 0x55, sizeof pm);
    check("rdpmacroinfo", cnc_rdpmacroinfo(h, &pm));
    printf("pmacroinfo=%d,%d,%d\n", pm.use_no1, pm.use_no2, pm.v2_type);

    cnc_freelibhndl(h);
    return 0;
}
