/* The P-code macro functions added from FANUC's library (cnc_rdpmacroinfo2,
 * cnc_rdpmacro, cnc_wrpmacro, cnc_rdpmacror, cnc_wrpmacror, cnc_rdpmacror2,
 * cnc_wrpmacror2), called through the .so against focas-sim; prints
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
/* The IEEE-double functions (cnc_wrpmacror2, cnc_rdpmacror2). */
static void doubles(unsigned short h);

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
    doubles(h);

    cnc_freelibhndl(h);
    return 0;
}

/* `key=d;d;...` of `n` doubles, each exactly (%.17g). */
static void print_doubles(const char *key, const double *d, unsigned long n) {
    unsigned long i;
    printf("%s=", key);
    for (i = 0; i < n; i++) printf("%s%.17g", i ? ";" : "", d[i]);
    printf("\n");
}

static void doubles(unsigned short h) {
    double three[3] = {2.5, -0.125, 1234.5}, back[3] = {0, 0, 0};
    double *many = calloc(200, sizeof(double)), *got = calloc(200, sizeof(double));
    unsigned long num;
    int i;
    if (!many || !got) exit(3);
    /* #10010..#10012 written as doubles, read back as doubles and as value
     * records (cnc_rdpmacror: the same store). */
    num = 3;
    check("wrpmacror2", cnc_wrpmacror2(h, 10010, &num, 0, three));
    printf("d.wr.num=%lu\n", num);
    num = 3;
    check("rdpmacror2", cnc_rdpmacror2(h, 10010, &num, 0, back));
    printf("d.rd.num=%lu\n", num);
    print_doubles("d.rd", back, 3);
    {
        IODBPR *r = range_buf(3);
        check("rdpmacror", cnc_rdpmacror(h, 10010, 10012, 12 + 8 * 3, r));
        printf("d.records=%d,%d,%d,%d,%d,%d\n", (int)rec(r, 0)->mcr_val, rec(r, 0)->dec_val,
               (int)rec(r, 1)->mcr_val, rec(r, 1)->dec_val, (int)rec(r, 2)->mcr_val,
               rec(r, 2)->dec_val);
        free(r);
    }
    /* 200 from #10000: two requests each way (177 + 23 written, 179 + 21 read). */
    for (i = 0; i < 200; i++) many[i] = i * 0.25 - 10;
    num = 200;
    check("wrpmacror2", cnc_wrpmacror2(h, 10000, &num, 1, many));
    printf("d.wr200.num=%lu\n", num);
    num = 200;
    check("rdpmacror2", cnc_rdpmacror2(h, 10000, &num, 2, got));
    printf("d.rd200.num=%lu\n", num);
    printf("d.rd200.same=%d\n", memcmp(many, got, sizeof(double) * 200) == 0);
    /* `*num` 0xffffffff from #10190: cut to the end of the range (#19999),
     * the simulator's #10199 ends the answer: 10 read. */
    num = 0xffffffffUL;
    check("rdpmacror2", cnc_rdpmacror2(h, 10190, &num, 0, got));
    printf("d.huge.num=%lu\n", num);
    /* Refused before any traffic: `*num` 0, `type` past 2; by the CNC:
     * #10200 does not exist (the request refused whole, `*num` kept). */
    num = 0;
    printf("d.zero=%d,%lu\n", cnc_wrpmacror2(h, 10000, &num, 0, three), num);
    num = 3;
    printf("d.type=%d,%lu\n", cnc_rdpmacror2(h, 10000, &num, 3, back), num);
    num = 3;
    printf("d.absent=%d,%lu\n", cnc_wrpmacror2(h, 10198, &num, 0, three), num);
    free(many);
    free(got);
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
