/* The magazine and tool management family added from FANUC's library
 * (cnc_rdmaxgrp, cnc_rdmaxtool, cnc_rdusegrpid, cnc_rd1tlifedata,
 * cnc_rd2tlifedata, cnc_wrmagazine, cnc_wrtool), called through the .so against focas-sim; prints
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

    cnc_freelibhndl(h);
    return 0;
}
