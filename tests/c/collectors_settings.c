/* The settings-family functions added from FANUC's library (cnc_rdmacronum),
 * called through the .so against focas-sim; prints key=value lines that
 * tests/artifacts compares with the simulator's machine state.
 * Usage: collectors_settings HOST PORT */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "fwlib32.h"

static void number_of(unsigned short h, const char *key, const char *name, long length) {
    char buf[64];
    long number = 0; /* FANUC's x86-64 library writes 4 bytes of it */
    short attr = -1;
    short rc;
    memset(buf, 0, sizeof buf);
    memcpy(buf, name, strlen(name));
    rc = cnc_rdmacronum(h, buf, length, &number, &attr);
    printf("%s=%d,%ld,%d\n", key, rc, number, attr);
}

int main(int argc, char **argv) {
    unsigned short h;
    if (argc != 3) return 2;
    if (cnc_allclibhndl3(argv[1], (unsigned short)atoi(argv[2]), 10, &h) != EW_OK) return 1;

    number_of(h, "num.gauge1", "GAUGE1", 6);
    number_of(h, "num.count", "COUNT", 5);
    /* The terminating NUL sent too. */
    number_of(h, "num.nul", "GAUGE1", 7);
    /* `length` is only a request word: the name is the string. */
    number_of(h, "num.length", "GAUGE1", 3);
    /* A prefix of a name, and a name the CNC does not have. */
    number_of(h, "num.prefix", "GAU", 3);
    number_of(h, "num.absent", "NONAME", 6);
    /* 64 characters without a NUL: refused before any traffic. */
    {
        char name[65];
        long number = 0; /* FANUC's x86-64 library writes 4 bytes of it */
        short attr = -1;
        short rc;
        memset(name, 'A', 64);
        name[64] = 'B';
        rc = cnc_rdmacronum(h, name, 65, &number, &attr);
        printf("num.long=%d,%ld,%d\n", rc, number, attr);
    }

    cnc_freelibhndl(h);
    return 0;
}
