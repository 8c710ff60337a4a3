/* The settings-family functions added from FANUC's library (cnc_rdmacronum,
 * cnc_rdset, cnc_wrset, cnc_rdsetr),
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

/* cnc_rdset of one setting without axis, `length` bytes of room. */
static void setting_of(unsigned short h, const char *key, short number, short length) {
    IODBPSD p;
    short rc;
    memset(&p, 0xcc, sizeof p);
    rc = cnc_rdset(h, number, 0, length, &p);
    printf("%s=%d,%d,%d,%d\n", key, rc, p.datano, p.type, (signed char)p.u.cdata);
}

/* cnc_wrset of a byte setting: `length` 5 (4 + one byte). */
static void write_setting(unsigned short h, const char *key, short number, short length, char v) {
    IODBPSD p;
    memset(&p, 0, sizeof p);
    p.datano = number;
    p.type = 0;
    p.u.cdata = v;
    printf("%s=%d\n", key, cnc_wrset(h, length, &p));
}

/* cnc_rdsetr of s..e without axis into `room` bytes: the code, the three
 * shorts after, then each packed record's number, type word and first
 * value byte (records of one byte value: 5 bytes, padded to 8). */
static void settings_in(unsigned short h, const char *key, short s, short e, short room) {
    unsigned char buf[256];
    short length = room, rc, at;
    memset(buf, 0xcc, sizeof buf);
    rc = cnc_rdsetr(h, &s, 0, &e, &length, buf);
    printf("%s=%d,%d,%d,%d", key, rc, s, e, length);
    for (at = 0; rc == EW_OK && at + 5 <= length; at += 8) {
        short number, type;
        memcpy(&number, buf + at, 2);
        memcpy(&type, buf + at + 2, 2);
        printf(",%d:%d:%d", number, type, (signed char)buf[at + 4]);
    }
    printf("\n");
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

    /* Setting data: the byte setting 20 and the bit setting 0. */
    setting_of(h, "set.read20", 20, 5);
    setting_of(h, "set.read0", 0, 8);
    /* Room for the header only: EW_LENGTH, the header written. */
    setting_of(h, "set.short", 20, 4);
    /* A parameter, not a setting (past the CNC's last setting number). */
    setting_of(h, "set.absent", 1001, 8);
    /* Written from C, read back as a setting and as the parameter. */
    write_setting(h, "set.write", 20, 5, 9);
    setting_of(h, "set.after", 20, 5);
    {
        IODBPSD p;
        short rc;
        memset(&p, 0, sizeof p);
        rc = cnc_rdparam(h, 20, 0, 5, &p);
        printf("set.param=%d,%d\n", rc, (signed char)p.u.cdata);
    }
    /* Refused writes change nothing: a wrong length (no traffic), a
     * parameter that is not a setting (the CNC refuses). */
    write_setting(h, "set.badlength", 20, 6, 11);
    write_setting(h, "set.notsetting", 1001, 5, 1);
    setting_of(h, "set.kept", 20, 5);
    /* Every setting, as packed records; then room for one record only. */
    settings_in(h, "setr.all", 0, 99, 100);
    settings_in(h, "setr.room", 0, 99, 10);
    /* Start past the end: refused before any traffic. */
    settings_in(h, "setr.backwards", 20, 0, 100);

    cnc_freelibhndl(h);
    return 0;
}
