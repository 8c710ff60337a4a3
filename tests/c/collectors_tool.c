/* The tool life, tool offset and compensation reads of family B
 * (cnc_rd1length ... cnc_t2info, cnc_rd1tlifedat2, cnc_rdgrpid,
 * cnc_rdtofsenbl, cnc_rdtldata, cnc_rdtlmsinfo, cnc_rdbtofsinfo, cnc_rdradofs, cnc_rd3dtofs) and
 * cnc_clrtofs, called through the .so against focas-sim; prints key=value
 * lines that tests/artifacts compares with the simulator's machine state.
 * Usage: collectors_tool HOST PORT */
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

static void life4(unsigned short h, const char *key,
                  short (*f)(unsigned short, short, short, ODBTLIFE4 *), short grp, short n) {
    ODBTLIFE4 t;
    memset(&t, 0, sizeof t);
    check(key, f(h, grp, n, &t));
    printf("%s=%d,%d,%d\n", key, t.datano, t.type, (int)t.data);
}

/* Offset `n` of type `type`, as cnc_rdtofs reads it. */
static long tofs(unsigned short h, short n, short type) {
    ODBTOFS o;
    check("rdtofs", cnc_rdtofs(h, n, type, 8, &o));
    return (long)o.data;
}

int main(int argc, char **argv) {
    unsigned short h;
    if (argc != 3) return 2;
    check("allclibhndl3", cnc_allclibhndl3(argv[1], (unsigned short)atoi(argv[2]), 10, &h));

    /* Group 1's second tool, by the 0x4f and the 0x4d requests. */
    life4(h, "rd1length", cnc_rd1length, 1, 2);
    life4(h, "rd1radius", cnc_rd1radius, 1, 2);
    life4(h, "t1info", cnc_t1info, 1, 2);
    life4(h, "rd2length", cnc_rd2length, 1, 2);
    life4(h, "rd2radius", cnc_rd2radius, 1, 2);
    life4(h, "t2info", cnc_t2info, 1, 2);
    IODBTD2 td;
    memset(&td, 0, sizeof td);
    td.dummy = 77;
    td.type = 88;
    check("rd1tlifedat2", cnc_rd1tlifedat2(h, 1, 2L, &td));
    printf("rd1tlifedat2=%d,%d,%d,%d,%d,%d,%d\n", td.datano, td.dummy, (int)td.type,
           (int)td.tool_num, (int)td.h_code, (int)td.d_code, (int)td.tool_inf);
    ODBTLIFE1 g;
    memset(&g, 0, sizeof g);
    g.dummy = 77;
    check("rdgrpid", cnc_rdgrpid(h, 5, &g));
    printf("rdgrpid=%d,%d,%d\n", g.dummy, g.type, (int)g.data);

    char enbl = 9;
    check("rdtofsenbl", cnc_rdtofsenbl(h, &enbl));
    printf("rdtofsenbl=%d\n", enbl);
    ODBTLDATA tl;
    check("rdtldata", cnc_rdtldata(h, &tl));
    printf("rdtldata=%d,%d\n", (int)tl.tl, (int)tl.tl_dp);
    ODBTLMSINF ms;
    check("rdtlmsinfo", cnc_rdtlmsinfo(h, &ms));
    printf("rdtlmsinfo=%d,%d,%d,%d,%d\n", (int)ms.t, (int)ms.m, (int)ms.hm, (int)ms.hm_dp,
           (int)ms.tlofs_no);
    ODBBTLINF b;
    check("rdbtofsinfo", cnc_rdbtofsinfo(h, &b));
    printf("rdbtofsinfo=%d,%d,%d\n", b.ofs_type, b.use_no, b.sub_no);
    ODBROFS r;
    check("rdradofs", cnc_rdradofs(h, &r));
    printf("rdradofs=%d,%d,%d,%d,%d\n", r.mode, r.pln_axes[0], r.pln_axes[1],
           (int)r.ofsvct[0], (int)r.ofsvct[1]);
    ODB3DTO t3;
    check("rd3dtofs", cnc_rd3dtofs(h, &t3));
    printf("rd3dtofs=%d,%d,%d,%d,%d,%d,%d\n", t3.mode, t3.ofs_axes[0], t3.ofs_axes[1],
           t3.ofs_axes[2], (int)t3.ofsvct[0], (int)t3.ofsvct[1], (int)t3.ofsvct[2]);

    /* cnc_clrtofs: type 1 (radius geometry) of every offset to 0, the
     * other types kept; a type the CNC lacks is refused, nothing cleared. */
    printf("before=%ld,%ld,%ld\n", tofs(h, 3, 0), tofs(h, 3, 1), tofs(h, 3, 3));
    check("clrtofs", cnc_clrtofs(h, 1));
    printf("after=%ld,%ld,%ld\n", tofs(h, 3, 0), tofs(h, 3, 1), tofs(h, 3, 3));
    printf("clrtofs.refused=%d\n", cnc_clrtofs(h, 9));
    printf("refused=%ld,%ld,%ld\n", tofs(h, 3, 0), tofs(h, 3, 1), tofs(h, 3, 3));
    /* The compensation follows: D3's radius is now its wear alone. */
    check("rdradofs", cnc_rdradofs(h, &r));
    printf("rdradofs.cleared=%d\n", (int)r.ofsvct[1]);

    cnc_freelibhndl(h);
    return 0;
}
