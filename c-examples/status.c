/*
 * status.c - connect to a CNC, read its system information, status and id.
 *
 *   cc -Wall -Wextra -Werror -I../include status.c -L../target/release -lfwlib32 -o status
 *   ./status [host [port]]
 *
 * Written against the FOCAS2 API as FANUC documents it: the same source
 * builds against FANUC's fwlib32.h.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "fwlib32.h"

static const char *mode_name(short aut)
{
    static const char *names[] = {"MDI", "MEM", "****", "EDIT", "HND", "JOG", "TJOG", "THND", "INC", "REF", "RMT"};
    return (aut >= 0 && aut < (short)(sizeof names / sizeof names[0])) ? names[aut] : "?";
}

static const char *run_name(short run)
{
    static const char *names[] = {"RESET", "STOP", "HOLD", "START", "MSTR"};
    return (run >= 0 && run < (short)(sizeof names / sizeof names[0])) ? names[run] : "?";
}

int main(int argc, char **argv)
{
    const char *host = argc > 1 ? argv[1] : "127.0.0.1";
    unsigned short port = (unsigned short)(argc > 2 ? atoi(argv[2]) : 8193);
    unsigned short h = 0;
    ODBSYS sys;
    ODBST st;
    unsigned long id[4] = {0, 0, 0, 0}; /* FANUC's spelling; 4-byte words are written into it */
    unsigned int words[4];
    short ret;

    ret = cnc_allclibhndl3(host, port, 10, &h);
    if (ret != EW_OK) {
        fprintf(stderr, "cnc_allclibhndl3(%s:%u) failed: %d\n", host, port, ret);
        return 1;
    }

    ret = cnc_sysinfo(h, &sys);
    if (ret != EW_OK) {
        fprintf(stderr, "cnc_sysinfo failed: %d\n", ret);
        cnc_freelibhndl(h);
        return 1;
    }
    printf("cnc_type=%.2s\n", sys.cnc_type);
    printf("mt_type=%.2s\n", sys.mt_type);
    printf("series=%.4s\n", sys.series);
    printf("version=%.4s\n", sys.version);
    printf("axes=%.2s\n", sys.axes);
    printf("max_axis=%d\n", sys.max_axis);

    ret = cnc_statinfo(h, &st);
    if (ret != EW_OK) {
        fprintf(stderr, "cnc_statinfo failed: %d\n", ret);
        cnc_freelibhndl(h);
        return 1;
    }
    printf("aut=%d (%s)\n", st.aut, mode_name(st.aut));
    printf("run=%d (%s)\n", st.run, run_name(st.run));
    printf("motion=%d\n", st.motion);
    printf("emergency=%d\n", st.emergency);
    printf("alarm=%d\n", st.alarm);

    ret = cnc_rdcncid(h, id);
    if (ret != EW_OK) {
        fprintf(stderr, "cnc_rdcncid failed: %d\n", ret);
        cnc_freelibhndl(h);
        return 1;
    }
    /* FANUC's x86-64 library writes four 32-bit words, whatever sizeof(long) is. */
    memcpy(words, id, sizeof words);
    printf("cnc_id=%08x-%08x-%08x-%08x\n", words[0], words[1], words[2], words[3]);

    ret = cnc_freelibhndl(h);
    if (ret != EW_OK) {
        fprintf(stderr, "cnc_freelibhndl failed: %d\n", ret);
        return 1;
    }
    return 0;
}
