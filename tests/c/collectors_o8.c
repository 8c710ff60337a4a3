/* The 8-digit program reads (cnc_rddynamico8, cnc_rdprogdiro8,
 * cnc_rdprogdir2o8), cnc_rdmdiprgstat and cnc_rdmultipieceno, called through the .so against focas-sim; prints
 * key=value lines that tests/artifacts compares with the simulator's
 * machine state. Usage: collectors_o8 HOST PORT */
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

int main(int argc, char **argv) {
    unsigned short h;
    if (argc != 3) return 2;
    check("allclibhndl3", cnc_allclibhndl3(argv[1], (unsigned short)atoi(argv[2]), 10, &h));

    /* All axes, then one. The program numbers are their low 16 bits, as
     * FANUC's library writes them (as cnc_rddynamic2). */
    ODBDYO8 dy;
    memset(&dy, 0, sizeof dy);
    check("rddynamico8", cnc_rddynamico8(h, -1, (short)sizeof dy, &dy));
    printf("dyo8.axis=%d\ndyo8.prgnum=%d\ndyo8.prgmnum=%d\ndyo8.seqnum=%d\n", dy.axis,
           (int)dy.prgnum, (int)dy.prgmnum, (int)dy.seqnum);
    printf("dyo8.alarm=%d\ndyo8.actf=%d\n", dy.alarm, (int)dy.actf);
    printf("dyo8.absolute=%d,%d,%d\n", (int)dy.pos.faxis.absolute[0],
           (int)dy.pos.faxis.absolute[1], (int)dy.pos.faxis.absolute[2]);
    printf("dyo8.machine=%d,%d,%d\n", (int)dy.pos.faxis.machine[0],
           (int)dy.pos.faxis.machine[1], (int)dy.pos.faxis.machine[2]);
    ODBDYO8 one;
    memset(&one, 0, sizeof one);
    check("rddynamico8 2", cnc_rddynamico8(h, 2, 44, &one));
    printf("dyo8_2.axis=%d\ndyo8_2.absolute=%d\n", one.axis, (int)one.pos.oaxis.absolute);
    printf("dyo8.short_length=%d\n", cnc_rddynamico8(h, -1, 539, &one));
    ODBDY2 dy2;
    memset(&dy2, 0, sizeof dy2);
    check("rddynamic2", cnc_rddynamic2(h, -1, (short)sizeof dy2, &dy2));
    printf("dy2.prgmnum=%d\n", (int)dy2.prgmnum);

    /* The directory as text between two 8-digit numbers. */
    PRGDIR dir;
    memset(&dir, 0, sizeof dir);
    check("rdprogdiro8", cnc_rdprogdiro8(h, 0, 1, 99999999, 255, &dir));
    printf("diro8=%s\n", dir.prg_data);
    memset(&dir, 0, sizeof dir);
    check("rdprogdiro8 8", cnc_rdprogdiro8(h, 0, 10000000, 99999999, 255, &dir));
    printf("diro8_high=%s\n", dir.prg_data);
    printf("diro8.reversed=%d\n", cnc_rdprogdiro8(h, 0, 99999999, 10000000, 255, &dir));

    /* Records from an 8-digit number on; *top_prog gives back the first. */
    PRGDIR2O8 rec[4];
    memset(rec, 0, sizeof rec);
    long top = 200;
    short num = 4;
    check("rdprogdir2o8", cnc_rdprogdir2o8(h, 2, &top, &num, rec));
    printf("dir2o8.num=%d\ndir2o8.top=%ld\n", num, top);
    for (int i = 0; i < num; i++)
        printf("dir2o8.%d=%ld,%ld,%.51s\n", i, (long)rec[i].number, (long)rec[i].length,
               rec[i].comment);

    /* The MDI program's status before and after one is written, and with
     * its execution pointer moved off the top. */
    unsigned short stat = 0xffff;
    check("rdmdiprgstat", cnc_rdmdiprgstat(h, &stat));
    printf("mdistat.none=%u\n", stat);
    char mdi[] = "G91 G00 X1.;\n%";
    check("wrmdiprog", cnc_wrmdiprog(h, (short)strlen(mdi), mdi));
    check("wrmdipntr", cnc_wrmdipntr(h, 0));
    check("rdmdiprgstat", cnc_rdmdiprgstat(h, &stat));
    printf("mdistat.top=%u\n", stat);
    check("wrmdipntr", cnc_wrmdipntr(h, 5));
    check("rdmdiprgstat", cnc_rdmdiprgstat(h, &stat));
    printf("mdistat.pointer=%u\n", stat);

    long piece = -1;
    check("rdmultipieceno", cnc_rdmultipieceno(h, &piece));
    printf("multipiece=%d\n", (int)piece);

    cnc_freelibhndl(h);
    return 0;
}
