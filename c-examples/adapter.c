/*
 * adapter.c - the calls the MTConnect FANUC adapter makes, in its order:
 * connect, system information, axis and spindle names, figures, then a
 * polling loop (status, dynamic data, spindle speeds and loads, servo loads,
 * program name and block, modal data, alarms, operator messages, tool,
 * parameter, diagnosis, macro and PMC reads), and a program upload.
 *
 *   cc -Wall -Wextra -Werror -I../include adapter.c -L../target/release -lfwlib32 -o adapter
 *   ./adapter [--batch] [host [port [polls [interval_ms]]]]
 *
 * With --batch each poll's reads go in one batch (fwlib32_ext.h:
 * fwlib_batch_begin, the calls, fwlib_batch_end): a few request frames
 * instead of one round trip per call, the same values.
 *
 * Every value read is printed as one `poll.key=value` line, so a test (or
 * you) can check it against the simulator's profile while its program runs.
 * Written against the FOCAS2 API as FANUC documents it: the same source
 * builds against FANUC's fwlib32.h.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "fwlib32.h"
#if defined(__has_include)
#if __has_include("fwlib32_ext.h")
#include "fwlib32_ext.h" /* fwlib32-rs's extensions: --batch */
#define HAVE_BATCH 1
#endif
#endif

static unsigned short h;

/* Calls a FOCAS function; on failure prints it and exits. */
#define CALL(expr)                                                       \
    do {                                                                 \
        short ret_ = (expr);                                             \
        if (ret_ != EW_OK) {                                             \
            fprintf(stderr, "%s failed: %d\n", #expr, ret_);             \
            cnc_freelibhndl(h);                                          \
            exit(1);                                                     \
        }                                                                \
    } while (0)

static void sleep_ms(long ms)
{
    struct timespec t = {ms / 1000, (ms % 1000) * 1000000L};
    nanosleep(&t, NULL);
}

/* A value with `dec` decimals, as text. */
static void print_scaled(const char *key, int poll, long v, int dec)
{
    double d = (double)v;
    int i;
    for (i = 0; i < dec; i++)
        d /= 10.0;
    printf("%d.%s=%.*f\n", poll, key, dec, d);
}

int main(int argc, char **argv)
{
    int batch = argc > 1 && strcmp(argv[1], "--batch") == 0;
    if (batch) {
        argv++;
        argc--;
    }
#ifndef HAVE_BATCH
    if (batch) {
        fprintf(stderr, "--batch needs fwlib32-rs's fwlib32_ext.h\n");
        return 2;
    }
#endif
    const char *host = argc > 1 ? argv[1] : "127.0.0.1";
    unsigned short port = (unsigned short)(argc > 2 ? atoi(argv[2]) : 8193);
    int polls = argc > 3 ? atoi(argv[3]) : 5;
    long interval = argc > 4 ? atol(argv[4]) : 500;
    ODBSYS sys;
    ODBAXISNAME axes[MAX_AXIS];
    ODBSPDLNAME spdl[MAX_SPINDLE];
    short naxes = MAX_AXIS, nspdl = MAX_SPINDLE, nfig = 0, i;
    short fig_in[MAX_AXIS], fig_out[MAX_AXIS];
    int poll;

    cnc_startupprocess(0, "focas.log"); /* no log file (FANUC's library needs the call) */
    if (cnc_allclibhndl3(host, port, 10, &h) != EW_OK) {
        fprintf(stderr, "cannot connect to %s:%u\n", host, port);
        return 1;
    }
    CALL(cnc_sysinfo(h, &sys));
    printf("series=%.4s\nversion=%.4s\nmt_type=%.2s\n", sys.series, sys.version, sys.mt_type);

    CALL(cnc_rdaxisname(h, &naxes, axes));
    printf("axes=%d\n", naxes);
    for (i = 0; i < naxes; i++)
        printf("axis%d=%c%c\n", i + 1, axes[i].name, axes[i].suff ? axes[i].suff : ' ');
    CALL(cnc_rdspdlname(h, &nspdl, spdl));
    printf("spindles=%d\n", nspdl);
    for (i = 0; i < nspdl; i++)
        printf("spindle%d=%c\n", i + 1, spdl[i].name);
    CALL(cnc_getfigure(h, 0, &nfig, fig_in, fig_out));
    printf("figures=%d\n", nfig);
    for (i = 0; i < nfig && i < naxes; i++)
        printf("figure%d=%d\n", i + 1, fig_in[i]);

    for (poll = 0; poll < polls; poll++) {
        ODBST st;
        ODBDY2 dyn;
        ODBACT2 act;
        ODBSPLOAD spload[MAX_SPINDLE];
        ODBSVLOAD svload[MAX_AXIS];
        short n_sp = MAX_SPINDLE, n_sv = MAX_AXIS, n_alm = 10;
        char name[256];
        char block[256];
        unsigned short len = sizeof block - 1;
        short blknum = 0;
        ODBMDL mdl;
        ODBALMMSG2 alm[10];
        OPMSG msg;
        ODBTLIFE4 tool;
        ODBTLIFE3 ntool;
        ODBPARAIF pif;
        IODBPSD prm;
        ODBDIAGIF dif;
        ODBDGN dgn;
        ODBM mcr;
        IODBPMC feed, spindle;

        if (poll > 0)
            sleep_ms(interval);

        /* The reads: each into its own variables, so that in a batch they
         * are all filled at fwlib_batch_end. */
#ifdef HAVE_BATCH
        if (batch)
            CALL(fwlib_batch_begin(h));
#endif
        CALL(cnc_statinfo(h, &st));
        /* All axes: 540 bytes, positions at MAX_AXIS strides. */
        CALL(cnc_rddynamic2(h, ALL_AXES, sizeof dyn, &dyn));
        CALL(cnc_acts2(h, ALL_SPINDLES, &act));
        CALL(cnc_rdspmeter(h, 0, &n_sp, spload));
        CALL(cnc_rdsvmeter(h, &n_sv, svload));
        CALL(cnc_exeprgname2(h, name));
        CALL(cnc_rdexecprog(h, &len, &blknum, block));
        CALL(cnc_modal(h, 0, 0, &mdl)); /* group 01: G00/G01/G02/G03 */
        CALL(cnc_rdalmmsg2(h, -1, &n_alm, alm));
        memset(&msg, 0, sizeof msg);
        CALL(cnc_rdopmsg(h, 0, 6 + 256, &msg));
        CALL(cnc_toolnum(h, 0, 0, &tool));
        CALL(cnc_rdntool(h, 0, &ntool));
        /* Part count: parameter 6711, found through rdparainfo first. */
        CALL(cnc_rdparainfo(h, 6711, 1, &pif));
        CALL(cnc_rdparam(h, 6711, 0, 8, &prm));
        /* Servo motor temperature of axis 1, diagnosis 308 (a byte per axis). */
        CALL(cnc_rddiaginfo(h, 308, 1, &dif));
        CALL(cnc_diagnoss(h, 308, 1, 4 + 1, &dgn));
        CALL(cnc_rdmacro(h, 500, 10, &mcr));
        /* Feed override, G12 (inverted: 0x9b = !100 %), and spindle override, G30. */
        CALL(pmc_rdpmcrng(h, 0 /* G */, 0 /* byte */, 12, 12, 8 + 1, &feed));
        CALL(pmc_rdpmcrng(h, 0 /* G */, 0 /* byte */, 30, 30, 8 + 1, &spindle));
#ifdef HAVE_BATCH
        if (batch) {
            short res[32];
            CALL(fwlib_batch_end(h, res, 32));
            for (i = 0; i < 20; i++)
                CALL(res[i]);
        }
#endif

        printf("%d.aut=%d\n%d.run=%d\n%d.motion=%d\n%d.emergency=%d\n%d.alarm=%d\n",
               poll, st.aut, poll, st.run, poll, st.motion, poll, st.emergency, poll, st.alarm);
        printf("%d.prgnum=%d\n%d.prgmnum=%d\n%d.seqnum=%d\n%d.actf=%d\n%d.acts=%d\n",
               poll, (int)dyn.prgnum, poll, (int)dyn.prgmnum, poll, (int)dyn.seqnum, poll,
               (int)dyn.actf, poll, (int)dyn.acts);
        for (i = 0; i < naxes; i++) {
            char key[32];
            snprintf(key, sizeof key, "abs%c", axes[i].name);
            print_scaled(key, poll, dyn.pos.faxis.absolute[i], fig_in[i]);
            snprintf(key, sizeof key, "mach%c", axes[i].name);
            print_scaled(key, poll, dyn.pos.faxis.machine[i], fig_in[i]);
        }
        for (i = 0; i < nspdl; i++)
            printf("%d.speed%d=%d\n", poll, i + 1, (int)act.data[i]);
        for (i = 0; i < n_sp; i++)
            printf("%d.spload%d=%d\n", poll, i + 1, (int)spload[i].spload.data);
        for (i = 0; i < n_sv; i++)
            printf("%d.svload%c=%d\n", poll, svload[i].svload.name, (int)svload[i].svload.data);
        printf("%d.program=%s\n", poll, name);
        block[len < sizeof block ? len : sizeof block - 1] = '\0';
        for (i = 0; block[i]; i++)
            if (block[i] == '\n' || block[i] == '\r') {
                block[i] = '\0';
                break;
            }
        printf("%d.block=%s\n", poll, block);
        printf("%d.gcode01=%d\n", poll, mdl.modal.g_data & 0x7f);
        printf("%d.alarms=%d\n", poll, n_alm);
        for (i = 0; i < n_alm; i++)
            printf("%d.alarm%d=%d %.*s\n", poll, i + 1, (int)alm[i].alm_no, (int)alm[i].msg_len,
                   alm[i].alm_msg);
        printf("%d.opmsg=%d %.*s\n", poll, msg.datano, msg.char_num > 0 ? msg.char_num : 0,
               msg.data);
        printf("%d.tool=%d\n%d.toolgroups=%d\n", poll, (int)tool.data, poll, (int)ntool.data);
        printf("%d.param6711.type=%d\n%d.parts=%d\n", poll, pif.info[0].prm_type, poll,
               (int)prm.u.ldata);
        printf("%d.diag308.type=%d\n%d.diag308=%d\n", poll, dif.info[0].diag_type, poll,
               (int)(unsigned char)dgn.u.cdata);
        print_scaled("macro500", poll, mcr.mcr_val, mcr.dec_val);
        printf("%d.feed_override=%d\n", poll, (unsigned char)~feed.u.cdata[0]);
        printf("%d.spindle_override=%d\n", poll, (unsigned char)spindle.u.cdata[0]);
        fflush(stdout);
    }

    /* Upload the program in cycle. */
    {
        ODBPRO pro;
        char buf[1281];
        long total = 0;
        short ret;
        CALL(cnc_rdprgnum(h, &pro));
        CALL(cnc_upstart3(h, 0, pro.mdata, pro.mdata));
        printf("upload-begin\n");
        for (;;) {
            long len = sizeof buf - 1;
            ret = cnc_upload3(h, &len, buf);
            if (ret == EW_BUFFER) { /* nothing received yet */
                sleep_ms(5);
                continue;
            }
            if (ret != EW_OK)
                break;
            fwrite(buf, 1, (size_t)len, stdout);
            total += len;
        }
        CALL(cnc_upend3(h));
        printf("\nupload-end\nuploaded=%ld\nupload_ret=%d\n", total, ret);
    }

    cnc_freelibhndl(h);
    return 0;
}
