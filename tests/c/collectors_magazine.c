/* The magazine and tool management family added from FANUC's library
 * (cnc_rdmaxgrp, cnc_rdmaxtool, cnc_rdusegrpid, cnc_rd1tlifedata,
 * cnc_rd2tlifedata, cnc_wrmagazine, cnc_wrtool, and the paging cnc_rdmagazine,
 * cnc_regmagazine, cnc_delmagazine, cnc_regtool, cnc_regtool_f2), called through the .so against focas-sim; prints
 * key=value lines that tests/artifacts compares with the simulator's
 * machine state. Usage: collectors_magazine HOST PORT */
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

static void print_td(const char *key, const IODBTD *t) {
    printf("%s=%d,%d,%d,%d,%d,%d\n", key, t->datano, t->type, (int)t->tool_num, (int)t->h_code,
           (int)t->d_code, (int)t->tool_inf);
}

int main(int argc, char **argv) {
    unsigned short h;
    if (argc != 3) return 2;
    check("allclibhndl3", cnc_allclibhndl3(argv[1], (unsigned short)atoi(argv[2]), 10, &h));

    ODBLFNO no;
    memset(&no, 0, sizeof no);
    check("rdmaxgrp", cnc_rdmaxgrp(h, &no));
    printf("maxgrp=%d\n", no.data);
    check("rdmaxtool", cnc_rdmaxtool(h, &no));
    printf("maxtool=%d\n", no.data);

    ODBUSEGR use;
    memset(&use, 0, sizeof use);
    check("rdusegrpid", cnc_rdusegrpid(h, &use));
    printf("usegrp=%d,%d,%d\n", (int)use.next, (int)use.use, (int)use.slct);

    /* Every tool of groups 1 and 2 through both reads. */
    for (short g = 1; g <= 2; g++) {
        for (short n = 1;; n++) {
            IODBTD t1, t2;
            char key[32];
            memset(&t1, 0, sizeof t1);
            memset(&t2, 0, sizeof t2);
            short r1 = cnc_rd1tlifedata(h, g, n, &t1);
            short r2 = cnc_rd2tlifedata(h, g, n, &t2);
            if (r1 != r2) {
                fprintf(stderr, "group %d tool %d: rd1tlifedata %d, rd2tlifedata %d\n", g, n, r1, r2);
                return 1;
            }
            if (r1 != EW_OK) {
                printf("tools%d=%d,%d\n", g, n - 1, r1);
                break;
            }
            snprintf(key, sizeof key, "rd1.%d.%d", g, n);
            print_td(key, &t1);
            snprintf(key, sizeof key, "rd2.%d.%d", g, n);
            print_td(key, &t2);
        }
    }

    /* The magazine: tool management data 2 to magazine 2 pot 5, read back
     * with cnc_rdtool; a data number the table lacks is refused. */
    check("wrmagazine", cnc_wrmagazine(h, 2, 5, 2));
    IODBTLMNG tool;
    short num = 1;
    check("rdtool", cnc_rdtool(h, 2, &num, &tool));
    printf("mag.tool2=%d,%d\n", tool.magazine, tool.pot);
    printf("mag.refused=%d\n", cnc_wrmagazine(h, 1, 1, 999));
    num = 1;
    check("rdtool", cnc_rdtool(h, 1, &num, &tool));
    printf("mag.tool1=%d,%d\n", tool.magazine, tool.pot);
    /* Tool 1 into the pot tool 2 now holds: tool 2 leaves the magazine. */
    check("wrmagazine", cnc_wrmagazine(h, 2, 5, 1));
    num = 1;
    check("rdtool", cnc_rdtool(h, 1, &num, &tool));
    printf("mag.moved1=%d,%d\n", tool.magazine, tool.pot);
    num = 1;
    check("rdtool", cnc_rdtool(h, 2, &num, &tool));
    printf("mag.moved2=%d,%d\n", tool.magazine, tool.pot);

    /* cnc_wrtool: data number 2 rewritten from what cnc_rdtool read, then
     * read back; a life status the CNC does not know is refused. */
    num = 1;
    check("rdtool", cnc_rdtool(h, 2, &num, &tool));
    tool.T_code = 4711;
    tool.life_count = 7;
    tool.max_life = 250;
    tool.life_stat = 1;
    tool.H_code = 21;
    tool.D_code = -4;
    tool.spindle_speed = 2200;
    tool.feedrate = 333;
    tool.magazine = 3;
    tool.pot = 9;
    tool.grp = 0;
    tool.custom1 = -5;
    tool.custom20 = 20;
    check("wrtool", cnc_wrtool(h, 2, &tool));
    IODBTLMNG back;
    num = 1;
    check("rdtool", cnc_rdtool(h, 2, &num, &back));
    printf("tool2=%d,%d,%d,%d,%d,%d,%d,%d,%d,%d,%d,%d,%d\n", (int)back.T_code,
           (int)back.life_count, (int)back.max_life, (int)back.rest_life, back.life_stat,
           back.H_code, back.D_code, (int)back.spindle_speed, (int)back.feedrate, back.magazine,
           back.pot, (int)back.custom1, (int)back.custom20);
    tool.life_stat = 9;
    tool.T_code = 1;
    printf("tool.refused=%d\n", cnc_wrtool(h, 2, &tool));
    printf("tool.refused_no=%d\n", cnc_wrtool(h, 0, &tool));
    num = 1;
    check("rdtool", cnc_rdtool(h, 2, &num, &back));
    printf("tool2.after=%d,%d\n", (int)back.T_code, back.life_stat);

    /* cnc_rdmagazine: 130 pots in one call (two exchanges: 118, 12). Pot
     * 0 is magazine 2 pot 5 (data number 1), pot 129 magazine 3 pot 9
     * (data number 2), the others magazine 4's pots 2..129 (empty). */
    short rc;
    static IODBTLMAG pots[200];
    for (int k = 0; k < 130; k++) {
        pots[k].magazine = 4;
        pots[k].pot = (short)(k + 1);
        pots[k].tool_index = -1;
    }
    pots[0].magazine = 2, pots[0].pot = 5;
    pots[129].magazine = 3, pots[129].pot = 9;
    num = 130;
    check("rdmagazine", cnc_rdmagazine(h, &num, pots));
    int others = 0;
    for (int k = 1; k < 129; k++) others += pots[k].tool_index != 0;
    printf("rdmag=%d,%d,%d,%d,%d,%d\n", num, pots[0].magazine, pots[0].pot, pots[0].tool_index,
           pots[129].tool_index, others);
    num = 0;
    rc = cnc_rdmagazine(h, &num, pots);
    printf("rdmag.num0=%d,%d\n", rc, num);

    /* cnc_regmagazine: data number 2 to magazine 5 pot 1, data number 1
     * to pot 2; read back with cnc_rdmagazine. A pot already holding a
     * tool is refused (EW_DATA) and changes nothing. */
    IODBTLMAG reg[2] = {{5, 1, 2}, {5, 2, 1}};
    num = 2;
    check("regmagazine", cnc_regmagazine(h, &num, reg));
    printf("regmag=%d\n", num);
    IODBTLMAG rd[4] = {{5, 1, 0}, {5, 2, 0}, {2, 5, 0}, {3, 9, 0}};
    num = 4;
    check("rdmagazine", cnc_rdmagazine(h, &num, rd));
    printf("regmag.back=%d,%d,%d,%d\n", rd[0].tool_index, rd[1].tool_index, rd[2].tool_index,
           rd[3].tool_index);
    IODBTLMAG taken = {5, 1, 1};
    num = 1;
    rc = cnc_regmagazine(h, &num, &taken);
    printf("regmag.refused=%d,%d\n", rc, num);
    num = 1;
    check("rdmagazine", cnc_rdmagazine(h, &num, rd));
    printf("regmag.after=%d\n", rd[0].tool_index);
    /* 150 pots of magazine 6 in one call (118, then 32): data number 1
     * through each, ending in pot 150. */
    for (int k = 0; k < 150; k++) {
        pots[k].magazine = 6;
        pots[k].pot = (short)(k + 1);
        pots[k].tool_index = 1;
    }
    num = 150;
    check("regmagazine", cnc_regmagazine(h, &num, pots));
    num = 1;
    check("rdtool", cnc_rdtool(h, 1, &num, &tool));
    printf("regmag.paged=%d,%d\n", tool.magazine, tool.pot);

    /* cnc_delmagazine: magazine 6 pot 150 and magazine 5 pot 1 emptied
     * (data numbers 1 and 2 leave the magazine); a pot 0 is refused. */
    IODBTLMAG2 del[2] = {{6, 150}, {5, 1}};
    num = 2;
    check("delmagazine", cnc_delmagazine(h, &num, del));
    printf("delmag=%d\n", num);
    IODBTLMAG rd2[2] = {{6, 150, -1}, {5, 1, -1}};
    num = 2;
    check("rdmagazine", cnc_rdmagazine(h, &num, rd2));
    printf("delmag.back=%d,%d\n", rd2[0].tool_index, rd2[1].tool_index);
    IODBTLMAG2 bad = {0, 1};
    num = 1;
    printf("delmag.refused=%d\n", cnc_delmagazine(h, &num, &bad));

    /* cnc_regtool: 10 new entries from data number 3 on (9, then 1 per
     * exchange), read back with cnc_rdtool; a data number past the end
     * (20) and one below 1 are refused. */
    static IODBTLMNG tools[10];
    for (int k = 0; k < 10; k++) {
        memset(&tools[k], 0, sizeof tools[k]);
        tools[k].T_code = 100 + k;
        tools[k].max_life = 50 + k;
        tools[k].life_count = k;
        tools[k].H_code = (short)(k + 1);
        tools[k].magazine = 7;
        tools[k].pot = (short)(k + 1);
    }
    num = 10;
    check("regtool", cnc_regtool(h, 3, &num, tools));
    printf("regtool=%d\n", num);
    static IODBTLMNG back10[10];
    num = 10;
    check("rdtool", cnc_rdtool(h, 3, &num, back10));
    printf("regtool.back=%d,%d,%d,%d,%d,%d,%d\n", num, (int)back10[0].T_code,
           (int)back10[9].T_code, (int)back10[9].max_life, (int)back10[9].life_count,
           back10[9].H_code, back10[9].pot);
    num = 1;
    rc = cnc_regtool(h, 20, &num, tools);
    printf("regtool.refused=%d,%d\n", rc, num);
    num = 1;
    rc = cnc_regtool(h, 0, &num, tools);
    printf("regtool.refused0=%d,%d\n", rc, num);

    /* cnc_regtool_f2: 7 entries with 40 custom data from data number 13
     * on (6, then 1 per exchange), read back with cnc_rdtool (custom 1..20). */
    static IODBTLMNG_F2 f2[7];
    for (int k = 0; k < 7; k++) {
        memset(&f2[k], 0, sizeof f2[k]);
        f2[k].T_code = 200 + k;
        f2[k].max_life = 70;
        f2[k].custom20 = 2000 + k;
        f2[k].custom40 = 4000 + k;
    }
    num = 7;
    check("regtool_f2", cnc_regtool_f2(h, 13, &num, f2));
    printf("regtool_f2=%d\n", num);
    num = 7;
    check("rdtool", cnc_rdtool(h, 13, &num, back10));
    printf("regtool_f2.back=%d,%d,%d,%d\n", num, (int)back10[0].T_code, (int)back10[6].T_code,
           (int)back10[6].custom20);

    cnc_freelibhndl(h);
    return 0;
}
