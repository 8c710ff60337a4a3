/* The P-code macro functions added from FANUC's library (cnc_rdpmacroinfo2,
 * cnc_rdpmacro, cnc_wrpmacro, cnc_rdpmacror, cnc_wrpmacror), called through the .so against focas-sim; prints
 * key=value lines that tests/artifacts compares with the simulator's
 * machine state. Usage: collectors_pcode HOST PORT */
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "fwlib32.h"

/* An IODBPR of `n` records (FANUC's declares 5; `length` = 12 + 8 * n). */
static IODBPR *range_buf(int n) {
    IODBPR *p = calloc(1, offsetof(IODBPR, data) + (size_t)n * sizeof(IODBPR_data));
    if (!p) exit(3);
    return p;
}

static IODBPR_data *rec(IODBPR *p, int i) {
    return (IODBPR_data *)((char *)p + offsetof(IODBPR, data)) + i;
}

/* #10000..#10199 read back, 100 a call, as `key=v,d;v,d...`. */
static void print_200(unsigned short h, const char *key);

static int check(const char *what, short rc) {
    if (rc != EW_OK) {
        fprintf(stderr, "%s: %d\n", what, rc);
        exit(1);
    }
    return 0;
}

int main(int argc, char **argv) {
    unsigned short h;
    long n;
    if (argc != 3) return 2;
    check("allclibhndl3", cnc_allclibhndl3(argv[1], (unsigned short)atoi(argv[2]), 10, &h));

    ODBPMINF2 inf;
    memset(&inf, 0, sizeof inf);
    check("rdpmacroinfo2", cnc_rdpmacroinfo2(h, &inf));
    printf("pmacroinfo2=%d,%d,%d,%d,%d,%d\n", (int)inf.use_no1, (int)inf.use_no2,
           (int)inf.use_no20, inf.v1_type, inf.v2_type, inf.v20_type);

    for (n = 10000; n <= 10002; n++) {
        ODBPM pm;
        memset(&pm, 0, sizeof pm);
        check("rdpmacro", cnc_rdpmacro(h, n, &pm));
        printf("pmacro.%ld=%d,%d,%d\n", n, (int)pm.datano, (int)pm.mcr_val, pm.dec_val);
    }
    /* A number the CNC does not have. */
    {
        ODBPM pm;
        printf("pmacro.absent=%d\n", cnc_rdpmacro(h, 9999, &pm));
    }

    /* Write #10002 = -4.75, then #10003 vacant, and read both back. */
    check("wrpmacro", cnc_wrpmacro(h, 10002, -475, 2));
    check("wrpmacro", cnc_wrpmacro(h, 10003, 0, -1));
    for (n = 10002; n <= 10003; n++) {
        ODBPM pm;
        memset(&pm, 0, sizeof pm);
        check("rdpmacro", cnc_rdpmacro(h, n, &pm));
        printf("written.%ld=%d,%d,%d\n", n, (int)pm.datano, (int)pm.mcr_val, pm.dec_val);
    }
    /* #10000..#10004 in one read: room for 5 records (12 + 5 * 8 bytes). */
    {
        IODBPR pr;
        int i;
        memset(&pr, 0, sizeof pr);
        check("rdpmacror", cnc_rdpmacror(h, 10000, 10004, 52, &pr));
        printf("range=%d,%d", (int)pr.datano_s, (int)pr.datano_e);
        for (i = 0; i < 5; i++) printf(";%d,%d", (int)pr.data[i].mcr_val, pr.data[i].dec_val);
        printf("\n");
        printf("range.short=%d\n", cnc_rdpmacror(h, 10000, 10004, 44, &pr));
        printf("range.backwards=%d\n", cnc_rdpmacror(h, 10004, 10000, 52, &pr));
    }
    /* Refused before any traffic: a local variable, decimals past a byte;
     * by the CNC: a number it does not have (nothing written). */
    printf("wr.local=%d\n", cnc_wrpmacro(h, 99, 1, 0));
    printf("wr.dec=%d\n", cnc_wrpmacro(h, 10004, 1, 128));
    printf("wr.absent=%d\n", cnc_wrpmacro(h, 9999, 1, 0));

    /* cnc_wrpmacror: #10000..#10199 in one call (two requests: 177, 23). */
    {
        IODBPR *w = range_buf(200);
        int i;
        w->datano_s = 10000;
        w->datano_e = 10199;
        for (i = 0; i < 200; i++) {
            rec(w, i)->mcr_val = i * 3 - 100;
            rec(w, i)->dec_val = (short)(i % 4);
        }
        check("wrpmacror", cnc_wrpmacror(h, 12 + 8 * 200, w));
        print_200(h, "wr200");
        /* #10023..#10222 with other values: the first request (#10023..#10199)
         * is written, the second (#10200.., which the CNC does not have)
         * refused whole. */
        w->datano_s = 10023;
        w->datano_e = 10222;
        for (i = 0; i < 200; i++) {
            rec(w, i)->mcr_val = 1000 + i;
            rec(w, i)->dec_val = 0;
        }
        printf("wr200.refused=%d\n", cnc_wrpmacror(h, 12 + 8 * 200, w));
        print_200(h, "wr200.after");
        /* Refused before any traffic: too short for the 5 records, a
         * local variable, backwards, decimals past a byte. */
        w->datano_s = 10000;
        w->datano_e = 10004;
        rec(w, 2)->dec_val = 0;
        printf("wrr.length=%d\n", cnc_wrpmacror(h, 49, w));
        w->datano_s = 99;
        printf("wrr.local=%d\n", cnc_wrpmacror(h, 52, w));
        w->datano_s = 10004;
        w->datano_e = 10000;
        printf("wrr.backwards=%d\n", cnc_wrpmacror(h, 52, w));
        w->datano_s = 10000;
        w->datano_e = 10004;
        rec(w, 2)->dec_val = 128;
        printf("wrr.dec=%d\n", cnc_wrpmacror(h, 52, w));
        /* By the CNC: #10200.. do not exist (nothing written). */
        rec(w, 2)->dec_val = 0;
        w->datano_s = 10198;
        w->datano_e = 10202;
        printf("wrr.absent=%d\n", cnc_wrpmacror(h, 52, w));
        free(w);
    }
    print_200(h, "wr200.end");

    cnc_freelibhndl(h);
    return 0;
}

static void print_200(unsigned short h, const char *key) {
    IODBPR *r = range_buf(100);
    int part, i;
    printf("%s=", key);
    for (part = 0; part < 2; part++) {
        long s = 10000 + 100 * part;
        check("rdpmacror", cnc_rdpmacror(h, s, s + 99, 12 + 8 * 100, r));
        if (r->datano_s != s || r->datano_e != s + 99) {
            fprintf(stderr, "rdpmacror: %d..%d\n", (int)r->datano_s, (int)r->datano_e);
            exit(1);
        }
        for (i = 0; i < 100; i++)
            printf("%s%d,%d", part + i ? ";" : "", (int)rec(r, i)->mcr_val, rec(r, i)->dec_val);
    }
    printf("\n");
    free(r);
}
