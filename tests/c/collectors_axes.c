/* The axes, modes and settings long tail (positions with extra digits,
 * extended axis names, synchronous errors, [MEASURE] keys, interference
 * check, coordinate rotation, the timers' write), called through the .so against focas-sim;
 * the key=value lines it prints are compared by
 * tests/artifacts/c_examples/collectors_axes.rs with the profile and the
 * simulator's state. Usage: collectors_axes HOST PORT */
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

/* One position kind: the first three axes' records with extra digits
 * (data as an integer of 10^-dec units, dec, digit), then the same
 * positions as cnc_absolute & co. read them. */
static void exdgt(unsigned short h, const char *key,
                  short (*ex)(unsigned short, ODBEXPOS *),
                  short (*plain)(unsigned short, short, short, ODBAXIS *)) {
    ODBEXPOS pos[MAX_AXIS];
    ODBAXIS ax;
    int i, k;
    memset(pos, 0xee, sizeof pos);
    check(key, ex(h, pos));
    check(key, plain(h, -1, 4 + 4 * MAX_AXIS, &ax));
    printf("%s=", key);
    for (i = 0; i < 3; i++) {
        double scaled = pos[i].data;
        for (k = 0; k < pos[i].dec; k++) scaled *= 10.0;
        printf("%s%.0f;%d;%d", i ? "|" : "", scaled, (int)pos[i].dec, (int)pos[i].digit);
    }
    printf("\n%s.plain=%d,%d,%d\n", key, (int)ax.data[0], (int)ax.data[1], (int)ax.data[2]);
}

int main(int argc, char **argv) {
    unsigned short h;
    if (argc != 3) return 2;
    check("allclibhndl3", cnc_allclibhndl3(argv[1], (unsigned short)atoi(argv[2]), 10, &h));

    exdgt(h, "absolute", cnc_absolute2_exdgt, cnc_absolute2);
    exdgt(h, "machine", cnc_machine_exdgt, cnc_machine);
    exdgt(h, "relative", cnc_relative2_exdgt, cnc_relative2);
    exdgt(h, "distance", cnc_distance_exdgt, cnc_distance);

    long sy = 0, rg = 0;
    check("rdsynerrsy", cnc_rdsynerrsy(h, &sy));
    check("rdsynerrrg", cnc_rdsynerrrg(h, &rg));
    printf("synerr=%d,%d\n", (int)sy, (int)rg);

    char enbl = 0x55, cenbl = 0x55;
    check("rdenblinfo", cnc_rdenblinfo(h, &enbl));
    check("rdcenblinfo", cnc_rdcenblinfo(h, &cenbl));
    printf("measure=%d,%d\n", enbl, cenbl);

    IODBTLINTF intf;
    memset(&intf, 0xee, sizeof intf);
    check("rdinterference", cnc_rdinterference(h, &intf));
    printf("interference=%d,%d\n", intf.inf_tool[0], intf.inf_tool[1]);

    ODBROT rot;
    memset(&rot, 0xee, sizeof rot);
    check("rdcdrotate", cnc_rdcdrotate(h, &rot));
    printf("rotation=%d;%d,%d;%d,%d;%d\n", rot.mode, rot.pln_axes[0], rot.pln_axes[1],
           (int)rot.center[0], (int)rot.center[1], (int)rot.angle);

    /* The module configuration bytes (the profile's), zeros after them. */
    char mdl[128];
    int i;
    memset(mdl, 0xee, sizeof mdl);
    check("rdmdlconfig2", cnc_rdmdlconfig2(h, mdl));
    printf("mdlconfig=");
    for (i = 0; i < 9; i++) printf("%s%d", i ? "," : "", mdl[i]);
    printf(";%d\n", mdl[127]);

    /* The free timer written and read back; negative minutes refused and
     * the timer kept. */
    IODBTIME t;
    t.minute = 4321;
    t.msec = 12345;
    check("wrtimer", cnc_wrtimer(h, 4, &t));
    memset(&t, 0xee, sizeof t);
    check("rdtimer", cnc_rdtimer(h, 4, &t));
    printf("timer.written=%d,%d\n", (int)t.minute, (int)t.msec);
    t.minute = -1;
    t.msec = 0;
    printf("wrtimer.refused=%d\n", cnc_wrtimer(h, 4, &t));
    check("rdtimer", cnc_rdtimer(h, 4, &t));
    printf("timer.kept=%d,%d\n", (int)t.minute, (int)t.msec);

    cnc_freelibhndl(h);
    return 0;
}
