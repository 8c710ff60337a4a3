/*
 * transfer.c - a small DNC tool: list the programs in memory, download an
 * NC program file, select it as the main program, start it, watch it run
 * to its end, upload it back and compare it with the file.
 *
 *   cc -Wall -Wextra -Werror -I../include transfer.c -L../target/release -lfwlib32 -o transfer
 *   ./transfer host port FILE.nc
 *
 * FILE.nc is punch format: "%", the program's "O<number>" block and its
 * blocks one per line, "%". The machine must be in MEMORY mode; the tool
 * resets it first (which stops a running program and clears the alarms a
 * reset clears). Written against the FOCAS2 API as FANUC documents it:
 * the same source builds against FANUC's fwlib32.h.
 *
 * Output: one "key=value" line per step; exit status 0 when the upload
 * equals the file.
 */
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "fwlib32.h"

static unsigned short h;

static int fail(const char *what, short ret)
{
    fprintf(stderr, "%s failed: %d\n", what, ret);
    cnc_freelibhndl(h);
    return 1;
}

static void pause_ms(long ms)
{
    struct timespec ts = {ms / 1000, (ms % 1000) * 1000000L};
    nanosleep(&ts, NULL);
}

/* The program's O number: the first "O<digits>" at the start of a line. */
static short program_number(const char *text)
{
    const char *p = text;
    while (p && *p) {
        if (p[0] == 'O' && p[1] >= '0' && p[1] <= '9')
            return (short)atoi(p + 1);
        p = strchr(p, '\n');
        if (p)
            p++;
    }
    return 0;
}

static void list_programs(void)
{
    PRGDIR2 dir[10];
    short top = 1, num;
    int total = 0;
    for (;;) {
        num = 10;
        if (cnc_rdprogdir2(h, 2, &top, &num, dir) != EW_OK || num <= 0)
            break;
        for (short i = 0; i < num; i++) {
            printf("program=O%04d length=%ld comment=%.51s\n", dir[i].number, (long)dir[i].length,
                   dir[i].comment);
            total++;
        }
        top = (short)(dir[num - 1].number + 1);
        if (num < 10)
            break;
    }
    printf("programs=%d\n", total);
}

/* The part counter: parameter 6711, which a program's M30 counts up. */
static long part_count(void)
{
    IODBPSD p;
    return cnc_rdparam(h, 6711, 0, 8, &p) == EW_OK ? (long)p.u.ldata : -1;
}

/* The whole upload of program `number` into a new buffer (NUL-terminated). */
static char *upload(short number, long *size)
{
    char *text = NULL, chunk[1280];
    long used = 0, len;
    short ret = cnc_upstart3(h, 0, number, number);
    if (ret != EW_OK)
        return NULL;
    for (;;) {
        len = sizeof chunk;
        ret = cnc_upload3(h, &len, chunk);
        if (ret == EW_BUFFER) {
            pause_ms(1);
            continue;
        }
        if (ret != EW_OK)
            break;
        text = realloc(text, used + len + 1);
        memcpy(text + used, chunk, len);
        used += len;
    }
    cnc_upend3(h);
    if (ret != EW_RESET) {
        free(text);
        return NULL;
    }
    if (!text)
        text = calloc(1, 1);
    text[used] = 0;
    *size = used;
    return text;
}

int main(int argc, char **argv)
{
    if (argc != 4) {
        fprintf(stderr, "usage: transfer host port FILE.nc\n");
        return 2;
    }
    FILE *f = fopen(argv[3], "rb");
    if (!f) {
        perror(argv[3]);
        return 2;
    }
    static char text[1 << 20];
    long size = (long)fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[size] = 0;
    short number = program_number(text);
    if (number <= 0) {
        fprintf(stderr, "%s: no O number\n", argv[3]);
        return 2;
    }

    short ret = cnc_allclibhndl3(argv[1], (unsigned short)atoi(argv[2]), 10, &h);
    if (ret != EW_OK) {
        fprintf(stderr, "cnc_allclibhndl3 failed: %d\n", ret);
        return 1;
    }
    list_programs();

    /* Replace an older copy, then download. */
    if (cnc_delete(h, number) == EW_OK)
        printf("deleted=O%04d\n", number);
    if ((ret = cnc_dwnstart3(h, 0)) != EW_OK)
        return fail("cnc_dwnstart3", ret);
    long len = size;
    if ((ret = cnc_download3(h, &len, text)) != EW_OK) {
        cnc_dwnend3(h);
        return fail("cnc_download3", ret);
    }
    if ((ret = cnc_dwnend3(h)) != EW_OK)
        return fail("cnc_dwnend3 (the CNC refused the program)", ret);
    printf("downloaded=O%04d bytes=%ld\n", number, size);

    /* Select it, reset, start, and watch it run to its end. */
    if ((ret = cnc_reset(h)) != EW_OK)
        return fail("cnc_reset", ret);
    if ((ret = cnc_search(h, number)) != EW_OK)
        return fail("cnc_search", ret);
    ODBPRO prg;
    if ((ret = cnc_rdprgnum(h, &prg)) != EW_OK)
        return fail("cnc_rdprgnum", ret);
    printf("main=O%04d\n", prg.mdata);
    long blocks0 = 0, blocks = 0, parts0 = part_count(), end_x = 0;
    cnc_rdblkcount(h, &blocks0);
    if ((ret = cnc_start(h)) != EW_OK)
        return fail("cnc_start", ret);
    ODBST st;
    ODBDY2 dyn;
    int polls = 0, seen_running = 0;
    for (;;) {
        if ((ret = cnc_statinfo(h, &st)) != EW_OK)
            return fail("cnc_statinfo", ret);
        if (st.run == 3)
            seen_running = 1;
        /* Where the first axis is. */
        if (cnc_rddynamic2(h, 1, sizeof dyn, &dyn) == EW_OK)
            end_x = dyn.pos.faxis.absolute[0];
        if (st.run == 0 || ++polls > 60000)
            break;
        pause_ms(1);
    }
    cnc_rdblkcount(h, &blocks);
    printf("end_x=%ld parts=%+ld\n", end_x, part_count() - parts0);
    printf("ran=O%04d started=%s ended=%s blocks=%ld\n", prg.data, seen_running ? "yes" : "no",
           st.run == 0 ? "yes" : "no", blocks - blocks0);

    /* Upload it back and compare. */
    long back_size = 0;
    char *back = upload(number, &back_size);
    if (!back)
        return fail("upload", -1);
    int same = back_size == size && memcmp(back, text, size) == 0;
    printf("upload=%s bytes=%ld\n", same ? "identical" : "different", back_size);
    free(back);
    cnc_freelibhndl(h);
    return same ? 0 : 1;
}
