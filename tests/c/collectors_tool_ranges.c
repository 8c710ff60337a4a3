/* Tool life groups by range and by count (cnc_rdtoolrng, cnc_rdusetlno,
 * cnc_rdtltool, cnc_rdexchgtgrp), the offsets' ranges (cnc_tofs_rnge,
 * cnc_zofs_rnge, cnc_wksft_rnge), the fixture offset in effect
 * (cnc_rdactfixofs), the volumetric compensation (cnc_rdvolccomp) and the
 * tool data writes
 * (cnc_wr1tlifedata, cnc_wr1tlifedat2), called through the .so against
 * focas-sim; prints key=value lines that tests/artifacts compares with the
 * simulator's machine state.
 * Usage: collectors_tool_ranges HOST PORT */
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

/* Group `grp`'s tools 1..=n: number, H, D, information each. */
static void tools(unsigned short h, const char *key, long grp, short n) {
    IODBTLTOOL t[8];
    memset(t, 0, sizeof t);
    short num = n;
    check(key, cnc_rdtltool(h, grp, 1, &num, t));
    printf("%s=%d", key, num);
    for (int i = 0; i < num; i++)
        printf(",%d,%d,%d,%d", (int)t[i].tool_num, (int)t[i].h_code, (int)t[i].d_code,
               (int)t[i].tool_inf);
    printf("\n");
}

static void range(const char *key, short rc, const ODBDATRNG *r) {
    check(key, rc);
    printf("%s=%d,%d,%d\n", key, (int)r->data_min, (int)r->data_max, (int)r->status);
}

int main(int argc, char **argv) {
    unsigned short h;
    if (argc != 3) return 2;
    check("allclibhndl3", cnc_allclibhndl3(argv[1], (unsigned short)atoi(argv[2]), 10, &h));

    /* Groups 1..=3 asked: the table's two answered. */
    IODBTR tr;
    memset(&tr, 0, sizeof tr);
    check("rdtoolrng", cnc_rdtoolrng(h, 1, 3, (short)sizeof tr, &tr));
    printf("rdtoolrng=%d,%d", tr.datano_s, tr.datano_e);
    for (int i = 0; i < tr.datano_e - tr.datano_s + 1; i++)
        printf(",%d,%d,%d", (int)tr.data[i].ntool, (int)tr.data[i].life, (int)tr.data[i].count);
    printf("\n");
    /* Room for the head and one group: EW_LENGTH. */
    printf("rdtoolrng.short=%d\n", cnc_rdtoolrng(h, 1, 2, 8 + 12, &tr));

    ODBTLUSE u;
    memset(&u, 0, sizeof u);
    check("rdusetlno", cnc_rdusetlno(h, 1, 2, (short)sizeof u, &u));
    printf("rdusetlno=%d,%d,%d,%d\n", u.s_grp, u.e_grp, (int)u.data[0], (int)u.data[1]);

    tools(h, "rdtltool", 1, 8);
    /* Asked one: one written. */
    tools(h, "rdtltool.one", 1, 1);
    short num = 0;
    IODBTLTOOL t1;
    printf("rdtltool.zero=%d\n", cnc_rdtltool(h, 1, 1, &num, &t1));

    ODBEXGP x[4];
    memset(x, 0, sizeof x);
    num = 4;
    check("rdexchgtgrp", cnc_rdexchgtgrp(h, &num, x));
    printf("rdexchgtgrp=%d", num);
    for (int i = 0; i < num; i++) printf(",%d,%d", (int)x[i].grp_no, (int)x[i].opt_grpno);
    printf("\n");

    ODBDATRNG r;
    range("tofs_rnge", cnc_tofs_rnge(h, 3, 1, &r), &r);
    range("zofs_rnge", cnc_zofs_rnge(h, 1, 2, &r), &r);
    range("wksft_rnge", cnc_wksft_rnge(h, 3, &r), &r);
    printf("tofs_rnge.type=%d\n", cnc_tofs_rnge(h, 3, 9, &r));
    printf("tofs_rnge.number=%d\n", cnc_tofs_rnge(h, 999, 1, &r));
    printf("zofs_rnge.axis=%d\n", cnc_zofs_rnge(h, 1, 9, &r));

    /* The fixture offset in effect: every axis, then axis 2. */
    IODBZOFS z;
    memset(&z, 0, sizeof z);
    check("rdactfixofs", cnc_rdactfixofs(h, -1, &z));
    printf("rdactfixofs=%d,%d,%d,%d,%d\n", z.datano, z.type, (int)z.data[0], (int)z.data[1],
           (int)z.data[2]);
    memset(&z, 0, sizeof z);
    check("rdactfixofs.axis", cnc_rdactfixofs(h, 2, &z));
    printf("rdactfixofs.axis=%d,%d,%d\n", z.datano, z.type, (int)z.data[0]);

    ODBVOLCOMP vc;
    memset(&vc, 0x55, sizeof vc);
    check("rdvolccomp", cnc_rdvolccomp(h, &vc));
    printf("rdvolccomp=%d,%d,%d,%d,%d\n", (int)vc.comp[0], (int)vc.comp[1], (int)vc.comp[2],
           (int)vc.comp[3], (int)vc.comp[4]);

    /* Group 1's second tool rewritten, read back; then refused writes
     * (absent group, tool past the group, tool number 0) change nothing. */
    IODBTD td;
    memset(&td, 0, sizeof td);
    td.datano = 1;
    td.type = 2;
    td.tool_num = 21;
    td.h_code = 22;
    td.d_code = 23;
    td.tool_inf = 4;
    check("wr1tlifedata", cnc_wr1tlifedata(h, &td));
    tools(h, "written", 1, 8);
    td.datano = 99;
    printf("wr1tlifedata.group=%d\n", cnc_wr1tlifedata(h, &td));
    td.datano = 1;
    td.type = 9;
    printf("wr1tlifedata.tool=%d\n", cnc_wr1tlifedata(h, &td));
    td.type = 1;
    td.tool_num = 0;
    printf("wr1tlifedata.number=%d\n", cnc_wr1tlifedata(h, &td));
    tools(h, "refused", 1, 8);

    IODBTD2 t2;
    memset(&t2, 0, sizeof t2);
    t2.datano = 2;
    t2.type = 1;
    t2.tool_num = 31;
    t2.h_code = 32;
    t2.d_code = 33;
    t2.tool_inf = 1;
    check("wr1tlifedat2", cnc_wr1tlifedat2(h, &t2));
    tools(h, "written2", 2, 8);

    check("freelibhndl", cnc_freelibhndl(h));
    return 0;
}
