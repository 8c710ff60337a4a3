/*
 * The oracle's probe: one C program, compiled against OUR include/fwlib32.h,
 * that makes FOCAS calls described by one text line each ("probe_cmd", the
 * words of focas-protocol/README.md) and prints one JSON line per call.
 *
 *     probe LIBRARY HOST PORT < commands
 *
 * LIBRARY is loaded with dlopen at run time, so the same binary runs FANUC's
 * library and ours. FANUC's x86-64 library reads and writes 4-byte `long`
 * struct fields, which is exactly our header's layout: no FANUC header is
 * needed. A function the library lacks answers {"missing": NAME}.
 *
 * Output buffers (b0, b1) are 4096 bytes pre-filled with 0xCC; each is
 * printed as hex up to its last byte that is not 0xCC. In-out counts come
 * back as named fields. Relative file names (cnc_startupprocess's log) are
 * created in a private temporary directory, removed when the probe exits.
 */
#define _GNU_SOURCE
#include <dirent.h>
#include <dlfcn.h>
#include <pthread.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* fwlib32_ext.h: our fwlib_* extensions, after fwlib32.h. */
#include "fwlib32_ext.h"
/* GENERATED_WORDS: one WORD per function of src/spec/table.rs, written by
 * tools/oracle/probe.rs from the same descriptions as the exports. */
#include "words.gen.h"

#define BUF 4096
#define FILL 0xCC
#define MAXARG 64

static void *lib;
static const char *host;
static unsigned short port;
static unsigned short slots[16] = {0xCCCC};
static int cur;
static unsigned char b0[BUF], b1[BUF];
static char *argv_[MAXARG];
static int argc_;
static jmp_buf missing;
static const char *missing_name;
static char fields[1024];

/* The library's function `name`, typed by our header's declaration. */
static void *need(const char *name) {
    void *f = dlsym(lib, name);
    if (!f) {
        missing_name = name;
        longjmp(missing, 1);
    }
    return f;
}
#define F(fn) ((__typeof__(&fn))need(#fn))

/* The i-th number after the word (1-based): decimal or 0x hex. */
static long long N(int i) {
    if (i >= argc_) {
        fprintf(stderr, "probe: argument %d missing\n", i);
        exit(2);
    }
    return strtoll(argv_[i], NULL, 0);
}
#define H (slots[cur])
#define B0 ((void *)b0)
#define B1 ((void *)b1)

static void field(const char *name, long long v) {
    size_t n = strlen(fields);
    snprintf(fields + n, sizeof fields - n, "%s\"%s\":%lld", n ? "," : "", name, v);
}

/* `hex:...` argument i into buffer b. */
static void fill_hex(unsigned char *b, int i) {
    const char *s = argv_[i];
    if (strncmp(s, "hex:", 4) == 0) s += 4;
    for (size_t k = 0; s[2 * k] && s[2 * k + 1] && k < BUF; k++) {
        unsigned v;
        sscanf(s + 2 * k, "%2x", &v);
        b[k] = (unsigned char)v;
    }
}

/* A `long` array argument of n elements from argument `from` on, 4 bytes
 * each (what `long *` parameters move) or 8 bytes with `wide`. */
static void *longs(int from, int n, int wide) {
    static unsigned char a[8 * MAXARG];
    for (int k = 0; k < n && k < MAXARG; k++) {
        long long v = N(from + k);
        if (wide) memcpy(a + 8 * k, &v, 8);
        else { int32_t w = (int32_t)v; memcpy(a + 4 * k, &w, 4); }
    }
    return a;
}

static short w_slot(void) {
    cur = (int)N(1) & 15;
    return 0;
}
static short w_seth(void) {
    slots[cur] = (unsigned short)N(1);
    return 0;
}
static short w_startup(void) {
    return F(cnc_startupprocess)(N(1), argc_ > 2 ? argv_[2] : "fwlib32.log");
}
static short w_alloc(void) {
    unsigned short h = slots[cur];
    const char *ip = argc_ > 2 ? argv_[2] : host;
    unsigned short p = argc_ > 3 ? (unsigned short)N(3) : port;
    short r = F(cnc_allclibhndl3)(ip, p, N(1), &h);
    slots[cur] = h;
    field("h", h);
    return r;
}
static short w_allclibhdl3(void) {
    unsigned short h = slots[cur];
    short r = F(cnc_allclibhdl3)(host, port, N(1), &h);
    slots[cur] = h;
    field("h", h);
    return r;
}
static short w_allclibhndl(void) {
    unsigned short h = slots[cur];
    short r = F(cnc_allclibhndl)(&h);
    field("h", h);
    return r;
}
static short w_alloc4(void) {
    unsigned short h = slots[cur];
    short r = F(cnc_allclibhndl4)(host, port, N(1), N(2), &h);
    slots[cur] = h;
    field("h", h);
    return r;
}

/* The thread words: the call made from a new thread. */
static void *t_statinfo(void *r) { *(short *)r = F(cnc_statinfo)(H, B0); return NULL; }
static void *t_free(void *r) { *(short *)r = F(cnc_freelibhndl)(H); return NULL; }
static void *t_alloc(void *r) {
    unsigned short h = slots[cur];
    *(short *)r = F(cnc_allclibhndl3)(host, port, N(1), &h);
    slots[cur] = h;
    return NULL;
}
static short in_thread(void *(*f)(void *)) {
    short r = -1;
    pthread_t t;
    pthread_create(&t, NULL, f, &r);
    pthread_join(t, NULL);
    return r;
}

/* In-out counts: start at argument i, come back as field `name`. */
#define SHORT_IO(name, i, call)                                                \
    do { short name = (short)N(i); short r_ = call; field(#name, name); return r_; } while (0)
#define USHORT_IO(name, i, call)                                               \
    do { unsigned short name = (unsigned short)N(i); short r_ = call; field(#name, name); return r_; } while (0)
/* A `long *` count: 4 bytes moved, as FANUC's x86-64 library does. */
#define LONG_IO(name, i, call)                                                 \
    do { int32_t name[2] = {(int32_t)N(i), (int32_t)0xCCCCCCCC}; short r_ = call; field(#name, name[0]); return r_; } while (0)

/*
 * Every word: WORD(name, body). The body returns the call's result.
 */
#define WORDS                                                                                     \
    GENERATED_WORDS /* the functions described as data: words.gen.h */                            \
    WORD(slot, return w_slot())                                                                   \
    WORD(seth, return w_seth())                                                                   \
    WORD(startup, return w_startup())                                                             \
    WORD(exitprocess, return F(cnc_exitprocess)())                                                \
    WORD(alloc, return w_alloc())                                                                 \
    WORD(alloc4, return w_alloc4())                                                               \
    WORD(free, return F(cnc_freelibhndl)(H))                                                      \
    WORD(thread_statinfo, return in_thread(t_statinfo))                                           \
    WORD(thread_free, return in_thread(t_free))                                                   \
    WORD(thread_alloc, return in_thread(t_alloc))                                                 \
    WORD(settimeout, return F(cnc_settimeout)(H, N(1)))                                           \
    WORD(resetconnect, return F(cnc_resetconnect)(H))                                             \
    WORD(setpath, return F(cnc_setpath)(H, N(1)))                                                 \
    WORD(getpath, return F(cnc_getpath)(H, B0, B1))                                               \
    WORD(getdtailerr, return F(cnc_getdtailerr)(H, B0))                                           \
    WORD(sysinfo, return F(cnc_sysinfo)(H, B0))                                                   \
    WORD(sysinfo_ex, return F(cnc_sysinfo_ex)(H, B0))                                             \
    WORD(statinfo, return F(cnc_statinfo)(H, B0))                                                 \
    WORD(statinfo2, return F(cnc_statinfo2)(H, B0))                                               \
    WORD(rdcncid, return F(cnc_rdcncid)(H, B0))                                                   \
    /* position */                                                                                \
    WORD(rdaxisname, SHORT_IO(num, 1, F(cnc_rdaxisname)(H, &num, B0)))                            \
    WORD(rdspdlname, SHORT_IO(num, 1, F(cnc_rdspdlname)(H, &num, B0)))                            \
    WORD(rddynamic2, return F(cnc_rddynamic2)(H, N(1), N(2), B0))                                 \
    WORD(rddynamic, return F(cnc_rddynamic)(H, N(1), N(2), B0))                                   \
    WORD(acts2, return F(cnc_acts2)(H, N(1), B0))                                                 \
    WORD(rdspeed, return F(cnc_rdspeed)(H, N(1), B0))                                             \
    WORD(rdspload, return F(cnc_rdspload)(H, N(1), B0))                                           \
    WORD(rdspmaxrpm, return F(cnc_rdspmaxrpm)(H, N(1), B0))                                       \
    WORD(rdspgear, return F(cnc_rdspgear)(H, N(1), B0))                                           \
    WORD(rdspmeter, SHORT_IO(num, 2, F(cnc_rdspmeter)(H, N(1), &num, B0)))                        \
    WORD(rdsvmeter, SHORT_IO(num, 1, F(cnc_rdsvmeter)(H, &num, B0)))                              \
    WORD(rdaxisdata, { short t[MAXARG]; int n = (int)N(2);                                        \
                       for (int k = 0; k < n && k < MAXARG; k++) t[k] = (short)N(3 + k);          \
                       SHORT_IO(len, 3 + n, F(cnc_rdaxisdata)(H, N(1), t, n, &len, B0)); })       \
    WORD(rdposition, SHORT_IO(num, 2, F(cnc_rdposition)(H, N(1), &num, B0)))                      \
    WORD(absolute, return F(cnc_absolute)(H, N(1), N(2), B0))                                     \
    WORD(absolute2, return F(cnc_absolute2)(H, N(1), N(2), B0))                                   \
    WORD(machine, return F(cnc_machine)(H, N(1), N(2), B0))                                       \
    WORD(relative, return F(cnc_relative)(H, N(1), N(2), B0))                                     \
    WORD(relative2, return F(cnc_relative2)(H, N(1), N(2), B0))                                   \
    WORD(distance, return F(cnc_distance)(H, N(1), N(2), B0))                                     \
    WORD(getfigure, { short v = (short)0xCCCC; short r = F(cnc_getfigure)(H, N(1), &v, B0, B1);   \
                      field("valid_fig", v); return r; })                                         \
    /* program */                                                                                 \
    WORD(exeprgname, return F(cnc_exeprgname)(H, B0))                                             \
    WORD(exeprgname2, return F(cnc_exeprgname2)(H, B0))                                          \
    WORD(rdexecprog, { unsigned short l = (unsigned short)N(1); short blk = (short)0xCCCC;        \
                       short r = F(cnc_rdexecprog)(H, &l, &blk, B0);                              \
                       field("length", l); field("blknum", blk); return r; })                     \
    WORD(modal, return F(cnc_modal)(H, N(1), N(2), B0))                                           \
    WORD(gettimer, { short t = (short)N(1); memcpy(b0, &t, 2); return F(cnc_gettimer)(H, B0); })  \
    WORD(settimer, { for (int k = 0; k < 4; k++) { short v = (short)N(1 + k);                     \
                         memcpy(b0 + (k ? 2 + 2 * k : 0), &v, 2); }                               \
                     return F(cnc_settimer)(H, B0); })                                            \
    WORD(rdopmode, return F(cnc_rdopmode)(H, B0))                                                 \
    WORD(rdprogdir, return F(cnc_rdprogdir)(H, N(1), N(2), N(3), N(4), B0))                       \
    WORD(rdprogdir3, { int32_t top[2] = {(int32_t)N(2), (int32_t)0xCCCCCCCC}; short n = N(3);     \
                       short r = F(cnc_rdprogdir3)(H, N(1), (long *)top, &n, B0);                 \
                       field("top_prog", (uint32_t)top[0]); field("num_prog", n); return r; })    \
    /* alarm */                                                                                   \
    WORD(alarm, return F(cnc_alarm)(H, B0))                                                       \
    WORD(alarm2, return F(cnc_alarm2)(H, B0))                                                     \
    WORD(rdalmmsg, SHORT_IO(num, 2, F(cnc_rdalmmsg)(H, N(1), &num, B0)))                          \
    WORD(rdalmmsg2, SHORT_IO(num, 2, F(cnc_rdalmmsg2)(H, N(1), &num, B0)))                        \
    WORD(rdalminfo, return F(cnc_rdalminfo)(H, N(1), N(2), N(3), B0))                             \
    WORD(rdopmsg, return F(cnc_rdopmsg)(H, N(1), N(2), B0))                                       \
    WORD(rdalmhisno, return F(cnc_rdalmhisno)(H, B0))                                             \
    WORD(rdalmhistry, return F(cnc_rdalmhistry)(H, N(1), N(2), N(3), B0))                         \
    WORD(rdalmhistry2, return F(cnc_rdalmhistry2)(H, N(1), N(2), N(3), B0))                       \
    /* param, diagnosis */                                                                        \
    WORD(rdparam, return F(cnc_rdparam)(H, N(1), N(2), N(3), B0))                                 \
    WORD(wrparam, { fill_hex(b0, 2); return F(cnc_wrparam)(H, N(1), B0); })                       \
    WORD(rdparam_ext, return F(cnc_rdparam_ext)(H, longs(2, N(1), 1), N(1), B0))                  \
    WORD(rdparam_ext32, return F(cnc_rdparam_ext)(H, longs(2, N(1), 0), N(1), B0))                \
    WORD(rddiag_ext32, return F(cnc_rddiag_ext)(H, longs(2, N(1), 0), N(1), B0))                  \
    WORD(rdparar, { short s = N(1), e = N(3), l = N(4);                                           \
                    short r = F(cnc_rdparar)(H, &s, N(2), &e, &l, B0);                            \
                    field("s_number", s); field("e_number", e); field("length", l); return r; })  \
    WORD(wrparas, { fill_hex(b0, 2); return F(cnc_wrparas)(H, N(1), B0); })                       \
    WORD(rdparainfo, return F(cnc_rdparainfo)(H, N(1), N(2), B0))                                 \
    WORD(rdparanum, return F(cnc_rdparanum)(H, B0))                                               \
    WORD(diagnoss, return F(cnc_diagnoss)(H, N(1), N(2), N(3), B0))                               \
    WORD(rddiag, return F(cnc_rddiag)(H, N(1), N(2), N(3), B0))                                   \
    WORD(rddiaginfo, return F(cnc_rddiaginfo)(H, N(1), N(2), B0))                                 \
    WORD(rddiagnum, return F(cnc_rddiagnum)(H, B0))                                               \
    /* macros */                                                                                  \
    WORD(rdmacro, return F(cnc_rdmacro)(H, N(1), N(2), B0))                                       \
    WORD(wrmacro, return F(cnc_wrmacro)(H, N(1), N(2), N(3), N(4)))                               \
    WORD(rdmacror, return F(cnc_rdmacror)(H, N(1), N(2), N(3), B0))                               \
    WORD(wrmacror, { fill_hex(b0, 2); return F(cnc_wrmacror)(H, N(1), B0); })                     \
    WORD(rdmacror2, LONG_IO(num, 2, F(cnc_rdmacror2)(H, N(1), (unsigned long *)num, B0)))         \
    WORD(wrmacror2, { fill_hex(b0, 3);                                                            \
                      LONG_IO(num, 2, F(cnc_wrmacror2)(H, N(1), (unsigned long *)num, B0)); })    \
    /* pmc */                                                                                     \
    WORD(pmc_rdpmcrng, return F(pmc_rdpmcrng)(H, N(1), N(2), N(3), N(4), N(5), B0))               \
    WORD(pmc_wrpmcrng, { fill_hex(b0, 2); return F(pmc_wrpmcrng)(H, N(1), B0); })                 \
    WORD(pmc_getdtailerr, return F(pmc_getdtailerr)(H, B0))                                       \
    WORD(pmc_rdpmcinfo, return F(pmc_rdpmcinfo)(H, N(1), B0))                                     \
    WORD(pmc_select_pmc_unit, return F(pmc_select_pmc_unit)(H, N(1)))                             \
    WORD(pmc_get_current_pmc_unit, return F(pmc_get_current_pmc_unit)(H, B0))                    \
    WORD(pmc_get_pmc_unit_types, LONG_IO(count, 1, F(pmc_get_pmc_unit_types)(H, B0, (long *)count))) \
    /* offsets, tools */                                                                          \
    WORD(rdtofs, return F(cnc_rdtofs)(H, N(1), N(2), N(3), B0))                                   \
    WORD(wrtofs, return F(cnc_wrtofs)(H, N(1), N(2), N(3), N(4)))                                 \
    WORD(rdtofsr, return F(cnc_rdtofsr)(H, N(1), N(2), N(3), N(4), B0))                           \
    WORD(rdzofs, return F(cnc_rdzofs)(H, N(1), N(2), N(3), B0))                                   \
    WORD(wrzofs, { fill_hex(b0, 2); return F(cnc_wrzofs)(H, N(1), B0); })                         \
    WORD(rdzofsr, return F(cnc_rdzofsr)(H, N(1), N(2), N(3), N(4), B0))                           \
    WORD(rdtoolgrp, return F(cnc_rdtoolgrp)(H, N(1), N(2), B0))                                   \
    WORD(rdtlctldata, return F(cnc_rdtlctldata)(H, B0))                                           \
    /* upload */                                                                                  \
    WORD(upstart, return F(cnc_upstart)(H, N(1)))                                                 \
    WORD(upstart3, return F(cnc_upstart3)(H, N(1), N(2), N(3)))                                   \
    WORD(upstart4, return F(cnc_upstart4)(H, N(1), argv_[2]))                                     \
    WORD(upload, USHORT_IO(length, 1, F(cnc_upload)(H, B0, &length)))                             \
    WORD(cupload, USHORT_IO(length, 1, F(cnc_cupload)(H, B0, &length)))                           \
    WORD(upload3, LONG_IO(length, 1, F(cnc_upload3)(H, (long *)length, B0)))                     \
    WORD(upload4, LONG_IO(length, 1, F(cnc_upload4)(H, (long *)length, B0)))                      \
    WORD(upend, return F(cnc_upend)(H))                                                           \
    WORD(upend3, return F(cnc_upend3)(H))                                                         \
    WORD(upend4, return F(cnc_upend4)(H))                                                         \
    /* histories */                                                                               \
    WORD(rdophistry, return F(cnc_rdophistry)(H, N(1), N(2), N(3), B0)) \
    WORD(rdomhistry, USHORT_IO(length, 2, F(cnc_rdomhistry)(H, N(1), &length, B0))) \
    WORD(rdomhistry2, return F(cnc_rdomhistry2)(H, N(1), N(2), N(3), B0)) \
    WORD(rdalmhistry5, return F(cnc_rdalmhistry5)(H, N(1), N(2), N(3), B0)) \
    WORD(accdecdly, return F(cnc_accdecdly)(H, N(1), N(2), B0)) \
    WORD(srvdelay, return F(cnc_srvdelay)(H, N(1), N(2), B0)) \
    WORD(skip, return F(cnc_skip)(H, N(1), N(2), B0)) \
    WORD(rdparam3, return F(cnc_rdparam3)(H, N(1), N(2), N(3), N(4), B0)) \
    WORD(rdparainfo3, { short n = N(2), pv = (short)0xCCCC, nx = (short)0xCCCC; short r = F(cnc_rdparainfo3)(H, N(1), &n, &pv, &nx, B0); field("num", n); field("prev", pv); field("next", nx); return r; }) \
    WORD(rdpitchr, return F(cnc_rdpitchr)(H, N(1), N(2), N(3), B0)) \
    /* declared by FANUC's header, not on Ethernet (EW_VERSION, EW_MMCSYS) */                     \
    WORD(allclibhdl3, return w_allclibhdl3())                                                     \
    WORD(allclibhndl, return w_allclibhndl())                                                     \
    WORD(rdexecpt, return F(cnc_rdexecpt)(H, B0, B1))                                             \
    WORD(rdprogline, return F(cnc_rdprogline)(H, N(1), N(2), B0, B1, (unsigned long *)(b1 + 8)))  \
    WORD(svdtstartrd, return F(cnc_svdtstartrd)(H, N(1)))                                         \
    WORD(svdtrddata, return F(cnc_svdtrddata)(H, B0, B1, b0 + 8))                                 \
    WORD(svdtendrd, return F(cnc_svdtendrd)(H))                                                   \
    WORD(rdspdlnamem, SHORT_IO(num, 1, F(cnc_rdspdlnamem)(H, &num, B0)))                          \
    WORD(rdalmmsg3, SHORT_IO(num, 2, F(cnc_rdalmmsg3)(H, N(1), &num, B0)))                        \
    /* our extensions (fwlib32_ext.h) */                                                          \
    WORD(fwlib_set_reconnect, return F(fwlib_set_reconnect)(H, N(1)))

#define WORD(name, ...) static short w__##name(void) { __VA_ARGS__; }
WORDS
#undef WORD

static const struct { const char *name; short (*fn)(void); } table[] = {
#define WORD(name, ...) {#name, w__##name},
    WORDS
#undef WORD
};

/* Removes the private directory and what the library wrote into it. */
static char tmpdir[] = "/tmp/focas-probe-XXXXXX";
static void remove_tmpdir(void) {
    DIR *d = opendir(tmpdir);
    if (d) {
        for (struct dirent *e; (e = readdir(d));) {
            if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0) continue;
            char path[sizeof tmpdir + 256];
            snprintf(path, sizeof path, "%s/%s", tmpdir, e->d_name);
            unlink(path);
        }
        closedir(d);
    }
    if (chdir("/") == 0) rmdir(tmpdir);
}

static void print_hex(const char *name, const unsigned char *b) {
    int end = BUF;
    while (end > 0 && b[end - 1] == FILL) end--;
    printf(",\"%s\":\"", name);
    for (int i = 0; i < end; i++) printf("%02x", b[i]);
    putchar('"');
}

int main(int argc, char **argv) {
    if (argc != 4) {
        fprintf(stderr, "usage: probe LIBRARY HOST PORT < commands\n");
        return 2;
    }
    lib = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    if (!lib) {
        fprintf(stderr, "probe: %s\n", dlerror());
        return 2;
    }
    host = argv[2];
    port = (unsigned short)atoi(argv[3]);
    if (!mkdtemp(tmpdir) || chdir(tmpdir) != 0) return 2;
    atexit(remove_tmpdir);
    setvbuf(stdout, NULL, _IOLBF, 0);
    for (int i = 0; i < 16; i++) slots[i] = 0xCCCC;

    char line[8192];
    while (fgets(line, sizeof line, stdin)) {
        argc_ = 0;
        for (char *t = strtok(line, " \t\r\n"); t && argc_ < MAXARG; t = strtok(NULL, " \t\r\n"))
            argv_[argc_++] = t;
        if (argc_ == 0) continue;
        memset(b0, FILL, BUF);
        memset(b1, FILL, BUF);
        fields[0] = 0;
        int found = 0;
        for (size_t k = 0; k < sizeof table / sizeof table[0]; k++) {
            if (strcmp(table[k].name, argv_[0]) != 0) continue;
            found = 1;
            if (setjmp(missing)) {
                printf("{\"missing\":\"%s\"}\n", missing_name);
                break;
            }
            short r = table[k].fn();
            printf("{\"return\":%d,\"fields\":{%s}", r, fields);
            print_hex("b0", b0);
            print_hex("b1", b1);
            printf("}\n");
            break;
        }
        if (!found) printf("{\"unknown\":\"%s\"}\n", argv_[0]);
    }
    return 0;
}
