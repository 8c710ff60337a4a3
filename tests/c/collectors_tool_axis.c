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

    ODBPSER ps;
    memset(&ps, 0, sizeof ps);
    check("rdposerrs2", cnc_rdposerrs2(h, &ps));
    printf("poserrs2=%d,%d\n", (int)ps.poserr1, (int)ps.poserr2);

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

    /* The values in force in the block in execution, each with the value
     * cnc_modal gives for its address (types 100 + k, FANUC's order
     * B D E F H L M S T). */
    ODBCMD cmds[8];
    short ncmd = 8;
    memset(cmds, 0, sizeof cmds);
    check("rdcommand", cnc_rdcommand(h, -1, 0, &ncmd, cmds));
    printf("ncmd=%d\n", ncmd);
    for (int i = 0; i < ncmd && i < 8; i++) {
        const char *order = "BDEFHLMST";
        const char *at = strchr(order, cmds[i].adrs);
        ODBMDL md;
        memset(&md, 0, sizeof md);
        long modal = -1;
        if (at && cmds[i].adrs) {
            check("modal", cnc_modal(h, (short)(100 + (at - order)), 0, &md));
            modal = (long)md.modal.aux.aux_data;
        }
        printf("cmd%d=%c,%d,%d,%ld,%ld,%ld\n", i, cmds[i].adrs, cmds[i].num, cmds[i].flag,
               (long)cmds[i].cmd_val, (long)cmds[i].dec_val, modal);
    }
    /* One address: F (type 5, 'A' + 5). */
    short nf = 1;
    ODBCMD f;
    memset(&f, 0, sizeof f);
    check("rdcommand F", cnc_rdcommand(h, 5, 0, &nf, &f));
    printf("cmdF=%d,%c,%ld\n", nf, f.adrs, (long)f.cmd_val);
    /* Room for fewer values than the block has: EW_LENGTH, the count kept. */
    short one = 1;
    short rc = cnc_rdcommand(h, -1, 0, &one, cmds);
    printf("cmd_short=%d,%d\n", rc, one);

    cnc_freelibhndl(h);
    return 0;
}
