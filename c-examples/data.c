/*
 * data.c - read and set machine data: a parameter (the part counter and a
 * real, per-axis one), a macro variable, a PMC word, a tool offset and a
 * work offset, then dump the alarm history.
 *
 *   cc -Wall -Wextra -Werror -I../include data.c -L../target/release -lfwlib32 -o data
 *   ./data [host [port [write|read]]]
 *
 * `write` (the default) writes new values, then reads everything back;
 * `read` only reads. Parameter writes need the CNC in MDI mode with
 * parameter write enabled (else EW_PASSWD, 17), as on a real CNC.
 * Every value is printed as one `key=value` line. Written against the
 * FOCAS2 API as FANUC documents it: the same source builds against
 * FANUC's fwlib32.h.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "fwlib32.h"

static unsigned short h;

#define CALL(expr)                                                       \
    do {                                                                 \
        short ret_ = (expr);                                             \
        if (ret_ != EW_OK) {                                             \
            fprintf(stderr, "%s failed: %d\n", #expr, ret_);             \
            cnc_freelibhndl(h);                                          \
            exit(1);                                                     \
        }                                                                \
    } while (0)

/* The values `write` sets. */
#define PARTS 4321
#define STROKE_X 812500 /* parameter 1320, X: 812.500 mm */
#define MACRO_VAL 12345 /* #500 = 12.345 */
#define MACRO_DEC 3
#define PMC_D100 0x1234
#define TOOL_WEAR (-25) /* offset 1, type 0: -0.025 mm */
#define G54_X (-300000) /* G54 X: -300.000 mm */

static void read_all(void)
{
    IODBPSD prm;
    ODBM mcr;
    IODBPMC pmc;
    ODBTOFS tofs;
    IODBZOFS zofs;
    unsigned short hisno = 0;
    ODBAHIS his;
    unsigned short i, n;

    CALL(cnc_rdparam(h, 6711, 0, 4 + 4, &prm));
    printf("param6711=%d\n", (int)prm.u.ldata);
    CALL(cnc_rdparam(h, 1320, 1, 4 + 8, &prm));
    printf("param1320.x=%d/%d\n", (int)prm.u.rdata.prm_val, (int)prm.u.rdata.dec_val);
    CALL(cnc_rdmacro(h, 500, 10, &mcr));
    printf("macro500=%d/%d\n", (int)mcr.mcr_val, mcr.dec_val);
    CALL(pmc_rdpmcrng(h, 9 /* D */, 1 /* word */, 100, 101, 8 + 2, &pmc));
    printf("pmcD100=%d\n", pmc.u.idata[0]);
    CALL(cnc_rdtofs(h, 1, 0, 8, &tofs));
    printf("tofs1.0=%d\n", (int)tofs.data);
    CALL(cnc_rdzofs(h, 1, 1, 4 + 4, &zofs)); /* number 1 = G54, axis 1 */
    printf("zofs54.x=%d\n", (int)zofs.data[0]);

    CALL(cnc_rdalmhisno(h, &hisno));
    printf("history=%u\n", hisno);
    n = hisno < 10 ? hisno : 10;
    if (n > 0) {
        CALL(cnc_rdalmhistry(h, 1, n, (unsigned short)(6 + 48 * n), &his));
        for (i = 0; i < his.e_no - his.s_no + 1 && i < n; i++) {
            printf("history%u=%02d/%02d/%02d %02d:%02d:%02d %d %.*s\n", i + 1,
                   his.alm_his[i].year, his.alm_his[i].month, his.alm_his[i].day,
                   his.alm_his[i].hour, his.alm_his[i].minute, his.alm_his[i].second,
                   his.alm_his[i].alm_no, his.alm_his[i].len_msg, his.alm_his[i].alm_msg);
        }
    }
}

static void write_all(void)
{
    IODBPSD prm;
    IODBPMC pmc;
    IODBZOFS zofs;

    memset(&prm, 0, sizeof prm);
    prm.datano = 6711;
    prm.type = 0;
    prm.u.ldata = PARTS;
    CALL(cnc_wrparam(h, 4 + 4, &prm));

    memset(&prm, 0, sizeof prm);
    prm.datano = 1320;
    prm.type = 1; /* axis 1 */
    prm.u.rdata.prm_val = STROKE_X;
    prm.u.rdata.dec_val = 3;
    CALL(cnc_wrparam(h, 4 + 8, &prm));

    CALL(cnc_wrmacro(h, 500, 10, MACRO_VAL, MACRO_DEC));

    memset(&pmc, 0, sizeof pmc);
    pmc.type_a = 9; /* D */
    pmc.type_d = 1; /* word */
    pmc.datano_s = 100;
    pmc.datano_e = 101;
    pmc.u.idata[0] = PMC_D100;
    CALL(pmc_wrpmcrng(h, 8 + 2, &pmc));

    CALL(cnc_wrtofs(h, 1, 0, 8, TOOL_WEAR));

    memset(&zofs, 0, sizeof zofs);
    zofs.datano = 1;
    zofs.type = 1;
    zofs.data[0] = G54_X;
    CALL(cnc_wrzofs(h, 4 + 4, &zofs));
    printf("written=ok\n");
}

int main(int argc, char **argv)
{
    const char *host = argc > 1 ? argv[1] : "127.0.0.1";
    unsigned short port = (unsigned short)(argc > 2 ? atoi(argv[2]) : 8193);
    int write = !(argc > 3 && strcmp(argv[3], "read") == 0);

    cnc_startupprocess(0, "focas.log"); /* no log file (FANUC's library needs the call) */
    if (cnc_allclibhndl3(host, port, 10, &h) != EW_OK) {
        fprintf(stderr, "cannot connect to %s:%u\n", host, port);
        return 1;
    }
    if (write)
        write_all();
    read_all();
    cnc_freelibhndl(h);
    return 0;
}
