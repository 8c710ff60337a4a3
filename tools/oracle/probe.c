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
#include <ctype.h>
#include <dirent.h>
#include <dlfcn.h>
#include <pthread.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>

/* fwlib32_ext.h: our fwlib_* extensions, after fwlib32.h. */
#include "fwlib32_ext.h"
/* GENERATED_WORDS: one WORD per function of src/spec/table/, written by
 * tools/oracle/probe.rs from the same descriptions as the exports. */
#include "words.gen.h"

#define BUF 65536
#define FILL 0xCC
#define MAXARG 64

static void *lib;
static const char *host;
static unsigned short port;
static unsigned short slots[16] = {0xCCCC};
static int cur;
static unsigned char b0[BUF], b1[BUF];
/* The input a function reads beside two outputs (cnc_rdmacronum's name):
 * filled from its hex argument, never reported (the outputs are b0, b1). */
static unsigned char b2[BUF];
static char *argv_[MAXARG];
static int argc_;
static jmp_buf missing;
static const char *missing_name;
static char fields[1024];
/* The byte buffers are filled with before a call (callx sets it). */
static unsigned char fill = FILL;

/* Every socket of the library has TCP_NODELAY on (the probe is linked with
 * -rdynamic, so the library's connect and setsockopt are these). FANUC's
 * library turns Nagle on for connection 1: a download's data frames after
 * the first would then reach the fake CNC when the first is acknowledged,
 * during a later call, and which call sent which frame would be a matter of
 * timing. The bytes are the same either way. */
int setsockopt(int fd, int level, int name, const void *value, socklen_t len) {
    static int (*real)(int, int, int, const void *, socklen_t);
    static const int one = 1;
    if (!real) real = (int (*)(int, int, int, const void *, socklen_t))dlsym(RTLD_NEXT, "setsockopt");
    if (level == IPPROTO_TCP && name == TCP_NODELAY) value = &one, len = sizeof one;
    return real(fd, level, name, value, len);
}
/* The library's sockets (from its connects) and the bytes it has written
 * to them during the current command: printed as "sent", so that a test
 * waits for exactly those bytes to reach the fake CNC (frames without an
 * answer, such as a download's data, are still in flight when the call
 * returns) instead of waiting for quiet. */
static unsigned char is_sock[65536];
static long long sent;
int connect(int fd, const struct sockaddr *addr, socklen_t len) {
    static int (*real)(int, const struct sockaddr *, socklen_t);
    if (!real) real = (int (*)(int, const struct sockaddr *, socklen_t))dlsym(RTLD_NEXT, "connect");
    setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, NULL, 0);
    if (fd >= 0 && fd < 65536) is_sock[fd] = 1;
    return real(fd, addr, len);
}
int close(int fd) {
    static int (*real)(int);
    if (!real) real = (int (*)(int))dlsym(RTLD_NEXT, "close");
    if (fd >= 0 && fd < 65536) is_sock[fd] = 0;
    return real(fd);
}
ssize_t send(int fd, const void *b, size_t n, int flags) {
    static ssize_t (*real)(int, const void *, size_t, int);
    if (!real) real = (ssize_t (*)(int, const void *, size_t, int))dlsym(RTLD_NEXT, "send");
    ssize_t r = real(fd, b, n, flags);
    if (r > 0 && fd >= 0 && fd < 65536 && is_sock[fd]) sent += r;
    return r;
}
ssize_t write(int fd, const void *b, size_t n) {
    static ssize_t (*real)(int, const void *, size_t);
    if (!real) real = (ssize_t (*)(int, const void *, size_t))dlsym(RTLD_NEXT, "write");
    ssize_t r = real(fd, b, n);
    if (r > 0 && fd >= 0 && fd < 65536 && is_sock[fd]) sent += r;
    return r;
}

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
#define B2 ((void *)b2)

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

/* In-out counts: start at argument i, come back as field `name`. They are
 * static, and the last one is remembered (io_*): a call queued in a batch
 * (fwlib_batch_begin) writes it at batch_end, which prints it again. */
static struct { const char *name; void *p; int kind; } io[4]; /* kind: 1 short, 2 ushort, 4 int32 */
static int io_n;
static int batching; /* between batch_begin and batch_end: io[] collects */
static void io_note(const char *name, void *p, int kind) {
    if (io_n < 4) io[io_n].name = name, io[io_n].p = p, io[io_n++].kind = kind;
}
static long long io_value(int k) {
    return io[k].kind == 1 ? *(short *)io[k].p : io[k].kind == 2 ? *(unsigned short *)io[k].p : *(int32_t *)io[k].p;
}
#define SHORT_IO(name, i, call)                                                \
    do { static short name; name = (short)N(i); io_note(#name, &name, 1); short r_ = call; field(#name, name); return r_; } while (0)
#define USHORT_IO(name, i, call)                                               \
    do { static unsigned short name; name = (unsigned short)N(i); io_note(#name, &name, 2); short r_ = call; field(#name, name); return r_; } while (0)
/* A `long *` count: 4 bytes moved, as FANUC's x86-64 library does. */
#define LONG_IO(name, i, call)                                                 \
    do { static int32_t name[2]; name[0] = (int32_t)N(i); name[1] = (int32_t)0xCCCCCCCC; io_note(#name, name, 4); \
         short r_ = call; field(#name, name[0]); return r_; } while (0)

/* fwlib_batch_begin, and fwlib_batch_end printing each queued call's code
 * as field r<k> and the last in-out count queued (b0, b1: what the queued
 * calls wrote at the end). */
static short w_batch_begin(void) {
    io_n = 0;
    short r = F(fwlib_batch_begin)(H);
    batching = r == 0;
    return r;
}
static short w_batch_end(void) {
    static const char *names[] = {"r0", "r1", "r2", "r3", "r4", "r5", "r6", "r7",
                                  "r8", "r9", "r10", "r11", "r12", "r13", "r14", "r15"};
    short res[16];
    for (int k = 0; k < 16; k++) res[k] = 0x7fff;
    short r = F(fwlib_batch_end)(H, res, argc_ > 1 ? (int)N(1) : 16);
    for (int k = 0; k < 16 && res[k] != 0x7fff; k++) field(names[k], res[k]);
    for (int k = 0; k < io_n; k++) field(io[k].name, io_value(k));
    io_n = 0;
    batching = 0;
    return r;
}

/* Program text argument i: '|' stands for a line feed; "gen:N" is N
 * bytes of generated blocks. Its length goes to *n. */
static char *text(int i, long *n) {
    static char t[70000];
    if (i >= argc_) {
        fprintf(stderr, "probe: argument %d missing\n", i);
        exit(2);
    }
    if (strncmp(argv_[i], "gen:", 4) == 0) {
        long k = 0, want = atol(argv_[i] + 4);
        if (want > (long)sizeof t - 1) want = sizeof t - 1;
        for (; k < want; k++) t[k] = "G01X1.Y2.\n"[k % 10];
        t[k] = 0;
        *n = k;
        return t;
    }
    snprintf(t, sizeof t, "%s", argv_[i]);
    for (char *q = t; *q; q++)
        if (*q == '|') *q = '\n';
    *n = (long)strlen(t);
    return t;
}
/* cnc_download / cnc_dnc: TEXT [LENGTH]. */
#define TEXT_N(fn, type)                                                       \
    do { long n_; char *t_ = text(1, &n_); return F(fn)(H, t_, (type)(argc_ > 2 ? N(2) : n_)); } while (0)
/* cnc_download3/4, cnc_dnc2: TEXT [LENGTH] through a `long *`. */
#define TEXT_LONG(fn)                                                          \
    do { long n_; char *t_ = text(1, &n_); int32_t l_[2] = {(int32_t)(argc_ > 2 ? N(2) : n_), (int32_t)0xCCCCCCCC}; \
         short r_ = F(fn)(H, (long *)l_, t_); field("length", l_[0]); return r_; } while (0)

/* callx FILL NAME ARG...: any function of FANUC's header, called by its
 * symbol with up to 12 integer-class arguments (the x86-64 ABI passes
 * short, long and pointer arguments alike; a callee reads the ones it
 * declares). b0 and b1 are filled with FILL first. An ARG is a number
 * (decimal or 0x hex), `H` (the handle), `@OFF` (a pointer to b0 + OFF),
 * `@OFF!Z` (with a 0 at b0 + OFF + Z: a C string's end) or `@OFF=HEX`
 * (that pointer, its bytes set first). The learner
 * (tools/oracle/learn.rs) forms these from the header's prototypes. */
static short w_callx(void) {
    typedef short (*anyfn)(long, long, long, long, long, long, long, long, long, long, long, long);
    long a[12] = {0};
    fill = (unsigned char)N(1);
    memset(b0, fill, BUF);
    memset(b1, fill, BUF);
    anyfn f = (anyfn)need(argv_[2]);
    for (int i = 3; i < argc_ && i - 3 < 12; i++) {
        const char *s = argv_[i];
        if (strcmp(s, "H") == 0) {
            a[i - 3] = H;
        } else if (s[0] == '@') {
            char *end;
            long off = strtol(s + 1, &end, 0);
            if (off < 0 || off >= BUF) off = 0;
            if (*end == '!') {
                long z = strtol(end + 1, &end, 0);
                if (off + z >= 0 && off + z < BUF) b0[off + z] = 0;
            }
            if (*end == '=') {
                const char *h = end + 1;
                for (long k = 0; h[2 * k] && h[2 * k + 1] && off + k < BUF; k++) {
                    unsigned v;
                    sscanf(h + 2 * k, "%2x", &v);
                    b0[off + k] = (unsigned char)v;
                }
            }
            a[i - 3] = (long)(b0 + off);
        } else {
            a[i - 3] = (long)strtoll(s, NULL, 0);
        }
    }
    return f(a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7], a[8], a[9], a[10], a[11]);
}

/*
 * Every word: WORD(name, body). The body returns the call's result.
 */
#define WORDS                                                                                     \
    GENERATED_WORDS /* the functions described as data: words.gen.h */                            \
    WORD(slot, return w_slot())                                                                   \
    WORD(fwlib_batch_begin, return w_batch_begin())                                               \
    WORD(fwlib_batch_end, return w_batch_end())                                               \
    WORD(fwlib_batch_limits, return F(fwlib_batch_limits)(H, N(1), N(2)))                         \
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
    /* position */                                                                                \
    WORD(rddynamic2, return F(cnc_rddynamic2)(H, N(1), N(2), B0))                                 \
    WORD(rddynamic, return F(cnc_rddynamic)(H, N(1), N(2), B0))                                   \
    WORD(rddynamico8, return F(cnc_rddynamico8)(H, N(1), N(2), B0))                              \
    WORD(acts2, return F(cnc_acts2)(H, N(1), B0))                                                 \
    WORD(rdspeed, return F(cnc_rdspeed)(H, N(1), B0))                                             \
    WORD(rdspload, return F(cnc_rdspload)(H, N(1), B0))                                           \
    WORD(rdspmaxrpm, return F(cnc_rdspmaxrpm)(H, N(1), B0))                                       \
    WORD(rdspgear, return F(cnc_rdspgear)(H, N(1), B0))                                           \
    WORD(rdspmeter, SHORT_IO(num, 2, F(cnc_rdspmeter)(H, N(1), &num, B0)))                        \
    WORD(rdsvmeter, SHORT_IO(num, 1, F(cnc_rdsvmeter)(H, &num, B0)))                              \
    WORD(rdaxisdata, { static short t[MAXARG]; int n = (int)N(2);                                 \
                       for (int k = 0; k < n && k < MAXARG; k++) t[k] = (short)N(3 + k);          \
                       SHORT_IO(len, 3 + n, F(cnc_rdaxisdata)(H, N(1), t, n, &len, B0)); })       \
    WORD(rdposition, SHORT_IO(num, 2, F(cnc_rdposition)(H, N(1), &num, B0)))                      \
    WORD(getfigure, { static short v; v = (short)0xCCCC; io_note("valid_fig", &v, 1);            \
                      short r = F(cnc_getfigure)(H, N(1), &v, B0, B1);                            \
                      field("valid_fig", v); return r; })                                         \
    /* program */                                                                                 \
    WORD(rdexecprog, { static unsigned short l; static short blk; l = (unsigned short)N(1);       \
                       blk = (short)0xCCCC; io_note("length", &l, 2); io_note("blknum", &blk, 1); \
                       short r = F(cnc_rdexecprog)(H, &l, &blk, B0);                              \
                       field("length", l); field("blknum", blk); return r; })                     \
    WORD(modal, return F(cnc_modal)(H, N(1), N(2), B0))                                           \
    WORD(gettimer, { short t = (short)N(1); memcpy(b0, &t, 2); return F(cnc_gettimer)(H, B0); })  \
    WORD(settimer, { for (int k = 0; k < 4; k++) { short v = (short)N(1 + k);                     \
                         memcpy(b0 + (k ? 2 + 2 * k : 0), &v, 2); }                               \
                     return F(cnc_settimer)(H, B0); })                                            \
    WORD(rdprogdir, return F(cnc_rdprogdir)(H, N(1), N(2), N(3), N(4), B0))                       \
    WORD(rdprogdiro8, return F(cnc_rdprogdiro8)(H, N(1), N(2), N(3), N(4), B0))                   \
    WORD(rdprogdir3, { int32_t top[2] = {(int32_t)N(2), (int32_t)0xCCCCCCCC}; short n = N(3);     \
                       short r = F(cnc_rdprogdir3)(H, N(1), (long *)top, &n, B0);                 \
                       field("top_prog", (uint32_t)top[0]); field("num_prog", n); return r; })    \
    WORD(rdprogdir2, { short top = N(2), n = N(3); short r = F(cnc_rdprogdir2)(H, N(1), &top, &n, B0); \
                       field("top_prog", top); field("num_prog", n); return r; })                 \
    WORD(rdprogdir2o8, { int32_t top[2] = {(int32_t)N(2), (int32_t)0xCCCCCCCC}; short n = N(3);  \
                         short r = F(cnc_rdprogdir2o8)(H, N(1), (long *)top, &n, B0);             \
                         field("top_prog", top[0]); field("num_prog", n); return r; })            \
    WORD(rdproginfo, return F(cnc_rdproginfo)(H, N(1), N(2), B0))                                 \
    WORD(rdmdiprog, SHORT_IO(length, 1, F(cnc_rdmdiprog)(H, &length, B0)))                        \
    WORD(wrmdiprog, { fill_hex(b1, 2); return F(cnc_wrmdiprog)(H, N(1), B1); })                   \
    /* program data folders (30i) */                                                              \
    WORD(rdpdf_subdir, { short n = N(1); IDBPDFSDIR in; memset(&in, 0, sizeof in);                \
                         strncpy(in.path, argv_[2], sizeof in.path - 1); in.req_num = N(3);       \
                         short r = F(cnc_rdpdf_subdir)(H, &n, &in, B0); field("num", n);          \
                         return r; })                                                             \
    WORD(rdpdf_alldir, { short n = N(1); IDBPDFADIR in; memset(&in, 0, sizeof in);                \
                         strncpy(in.path, argv_[2], sizeof in.path - 1); in.req_num = N(3);       \
                         in.size_kind = N(4); in.type = N(5);                                     \
                         short r = F(cnc_rdpdf_alldir)(H, &n, &in, B0); field("num", n);          \
                         return r; })                                                             \
    WORD(pdf_rdactpt, LONG_IO(blk, 1, F(cnc_pdf_rdactpt)(H, B0, (long *)blk)))                    \
    WORD(pdf_wractpt, LONG_IO(blk, 3, F(cnc_pdf_wractpt)(H, argv_[1], N(2), (long *)blk)))        \
    WORD(rdpdf_line, { int32_t ln[2] = {(int32_t)N(3), (int32_t)0xCCCCCCCC};                      \
                       int32_t dl[2] = {(int32_t)N(4), (int32_t)0xCCCCCCCC};                      \
                       short r = F(cnc_rdpdf_line)(H, argv_[1], N(2), B0, (unsigned long *)ln,    \
                                                   (unsigned long *)dl);                          \
                       field("line_len", ln[0]); field("data_len", dl[0]); return r; })           \
    WORD(wrpdf_line, { fill_hex(b1, 3); return F(cnc_wrpdf_line)(H, argv_[1], N(2), B1, N(4)); }) \
    /* alarm */                                                                                   \
    WORD(rdalmmsg, SHORT_IO(num, 2, F(cnc_rdalmmsg)(H, N(1), &num, B0)))                          \
    WORD(rdalmmsg2, SHORT_IO(num, 2, F(cnc_rdalmmsg2)(H, N(1), &num, B0)))                        \
    WORD(rdalminfo, return F(cnc_rdalminfo)(H, N(1), N(2), N(3), B0))                             \
    WORD(rdopmsg, return F(cnc_rdopmsg)(H, N(1), N(2), B0))                                       \
    WORD(rdalmhistry, return F(cnc_rdalmhistry)(H, N(1), N(2), N(3), B0))                         \
    WORD(rdalmhistry2, return F(cnc_rdalmhistry2)(H, N(1), N(2), N(3), B0))                       \
    /* param, diagnosis */                                                                        \
    WORD(rdparam_ext, return F(cnc_rdparam_ext)(H, longs(2, N(1), 1), N(1), B0))                  \
    WORD(rdparam_ext32, return F(cnc_rdparam_ext)(H, longs(2, N(1), 0), N(1), B0))                \
    WORD(rddiag_ext32, return F(cnc_rddiag_ext)(H, longs(2, N(1), 0), N(1), B0))                  \
    WORD(wrparas, { fill_hex(b0, 2); return F(cnc_wrparas)(H, N(1), B0); })                       \
    WORD(rdparainfo, return F(cnc_rdparainfo)(H, N(1), N(2), B0))                                 \
    WORD(rddiaginfo, return F(cnc_rddiaginfo)(H, N(1), N(2), B0))                                 \
    /* macros */                                                                                  \
    WORD(rdmacro, return F(cnc_rdmacro)(H, N(1), N(2), B0))                                       \
    WORD(wrmacro, return F(cnc_wrmacro)(H, N(1), N(2), N(3), N(4)))                               \
    WORD(rdmacror, return F(cnc_rdmacror)(H, N(1), N(2), N(3), B0))                               \
    WORD(wrmacror, { fill_hex(b0, 2); return F(cnc_wrmacror)(H, N(1), B0); })                     \
    /* pmc */                                                                                     \
    WORD(pmc_rdpmcrng, return F(pmc_rdpmcrng)(H, N(1), N(2), N(3), N(4), N(5), B0))               \
    WORD(pmc_wrpmcrng, { fill_hex(b0, 2); return F(pmc_wrpmcrng)(H, N(1), B0); })                 \
    WORD(pmc_getdtailerr, return F(pmc_getdtailerr)(H, B0))                                       \
    WORD(pmc_rdpmcinfo, return F(pmc_rdpmcinfo)(H, N(1), B0))                                     \
    WORD(pmc_select_pmc_unit, return F(pmc_select_pmc_unit)(H, N(1)))                             \
    WORD(pmc_get_pmc_unit_types, LONG_IO(count, 1, F(pmc_get_pmc_unit_types)(H, B0, (long *)count))) \
    /* offsets, tools */                                                                          \
    WORD(rdtofs, return F(cnc_rdtofs)(H, N(1), N(2), N(3), B0))                                   \
    WORD(wrtofs, return F(cnc_wrtofs)(H, N(1), N(2), N(3), N(4)))                                 \
    WORD(rdtofsr, return F(cnc_rdtofsr)(H, N(1), N(2), N(3), N(4), B0))                           \
    WORD(rdzofs, return F(cnc_rdzofs)(H, N(1), N(2), N(3), B0))                                   \
    WORD(wrzofs, { fill_hex(b0, 2); return F(cnc_wrzofs)(H, N(1), B0); })                         \
    WORD(rdzofsr, return F(cnc_rdzofsr)(H, N(1), N(2), N(3), N(4), B0))                           \
    WORD(wrwkcdshft, { fill_hex(b0, 2); return F(cnc_wrwkcdshft)(H, N(1), B0); })                 \
    WORD(rdtoolgrp, return F(cnc_rdtoolgrp)(H, N(1), N(2), B0))                                   \
    WORD(rdtlctldata, return F(cnc_rdtlctldata)(H, B0))                                           \
    WORD(wrgrpinfo, { fill_hex(b0, 2); return F(cnc_wrgrpinfo)(H, N(1), B0); })                   \
    WORD(rdtlusegrp, return F(cnc_rdtlusegrp)(H, B0))                                             \
    WORD(rdtool, SHORT_IO(num, 2, F(cnc_rdtool)(H, N(1), &num, B0)))                              \
    WORD(rdtooldata, SHORT_IO(num, 2, F(cnc_rdtooldata)(H, N(1), &num, B0)))                      \
    WORD(rdtoolinfo, return F(cnc_rdtoolinfo)(H, B0))                                             \
    WORD(instlifedt, { fill_hex(b0, 1); return F(cnc_instlifedt)(H, B0); })                       \
    WORD(pmc_rdalmmsg, SHORT_IO(num, 2, F(pmc_rdalmmsg)(H, N(1), &num, (short *)B1, B0))) \
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
    /* download and DNC */                                                                        \
    WORD(dwnstart, return F(cnc_dwnstart)(H))                                                     \
    WORD(dwnstart3, return F(cnc_dwnstart3)(H, N(1)))                                             \
    WORD(dwnstart4, return F(cnc_dwnstart4)(H, N(1), argc_ > 2 ? argv_[2] : NULL))                \
    WORD(download, TEXT_N(cnc_download, short))                                                   \
    WORD(download3, TEXT_LONG(cnc_download3))                                                     \
    WORD(download4, TEXT_LONG(cnc_download4))                                                     \
    WORD(dwnend, return F(cnc_dwnend)(H))                                                         \
    WORD(dwnend3, return F(cnc_dwnend3)(H))                                                       \
    WORD(dwnend4, return F(cnc_dwnend4)(H))                                                       \
    WORD(dncstart, return F(cnc_dncstart)(H))                                                     \
    WORD(dncstart2, return F(cnc_dncstart2)(H, argc_ > 1 ? argv_[1] : NULL))                      \
    WORD(dnc, TEXT_N(cnc_dnc, unsigned short))                                                    \
    WORD(dnc2, TEXT_LONG(cnc_dnc2))                                                               \
    WORD(dncend, return F(cnc_dncend)(H))                                                         \
    WORD(dncend2, return F(cnc_dncend2)(H, N(1)))                                                 \
    /* histories */                                                                               \
    WORD(rdophistry, return F(cnc_rdophistry)(H, N(1), N(2), N(3), B0)) \
    WORD(rdomhistry, USHORT_IO(length, 2, F(cnc_rdomhistry)(H, N(1), &length, B0))) \
    WORD(rdomhistry2, return F(cnc_rdomhistry2)(H, N(1), N(2), N(3), B0)) \
    WORD(rdalmhistry5, return F(cnc_rdalmhistry5)(H, N(1), N(2), N(3), B0)) \
    WORD(rdparainfo3, { short n = N(2), pv = (short)0xCCCC, nx = (short)0xCCCC; short r = F(cnc_rdparainfo3)(H, N(1), &n, &pv, &nx, B0); field("num", n); field("prev", pv); field("next", nx); return r; }) \
    WORD(rdpitchr, return F(cnc_rdpitchr)(H, N(1), N(2), N(3), B0)) \
    /* machine data (issue 11) */                                                                \
    WORD(rdophistry4, { unsigned short e = N(2), l = N(3); short r = F(cnc_rdophistry4)(H, N(1), &e, &l, B0); field("e_no", e); field("length", l); return r; }) \
    WORD(rdopmsg3, SHORT_IO(num, 2, F(cnc_rdopmsg3)(H, N(1), &num, B0))) \
    WORD(wrhissgnl3, { short *d = (short *)b0; d[0] = N(1); d[1] = N(2); for (int k = 0; k < N(3) && k < 60; k++) { unsigned char *e = b0 + 4 + 8 * k; short en = k + 1, pm = 1, sn = 10 * k + 7; if (k == 0 && argc_ > 5) en = N(5); if (k == 0 && argc_ > 6) pm = N(6); if (k == 0 && argc_ > 7) sn = N(7); memcpy(e, &en, 2); memcpy(e + 2, &pm, 2); memcpy(e + 4, &sn, 2); e[6] = k == 0 && argc_ > 8 ? N(8) : k & 3; e[7] = (k * 37 + 1) & 0xff; } return F(cnc_wrhissgnl3)(H, argc_ > 4 && N(4) == 0 ? NULL : B0); }) \
    WORD(rdprstrinfo, return F(cnc_rdprstrinfo)(H, B0)) \
    /* declared by FANUC's header, not on Ethernet (EW_MMCSYS) */                                \
    WORD(allclibhdl3, return w_allclibhdl3())                                                     \
    WORD(allclibhndl, return w_allclibhndl())                                                     \
    /* our extensions (fwlib32_ext.h) */                                                          \
    WORD(fwlib_set_reconnect, return F(fwlib_set_reconnect)(H, N(1)))                             \
    WORD(callx, return w_callx())

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
    while (end > 0 && b[end - 1] == fill) end--;
    printf(",\"%s\":\"", name);
    for (int i = 0; i < end; i++) printf("%02x", b[i]);
    putchar('"');
}

/* `\xHH` in a word is the byte HH (a C string argument in another encoding,
 * e.g. a Latin-1 name, written in a command line that is UTF-8 text). */
static void unescape(char *t) {
    char *o = t;
    for (; *t; t++) {
        if (t[0] == '\\' && t[1] == 'x' && isxdigit((unsigned char)t[2]) &&
            isxdigit((unsigned char)t[3])) {
            char h[3] = {t[2], t[3], 0};
            *o++ = (char)strtol(h, NULL, 16);
            t += 3;
        } else {
            *o++ = *t;
        }
    }
    *o = 0;
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
        for (int i = 1; i < argc_; i++) unescape(argv_[i]);
        /* fwlib_batch_end: the queued calls write into the buffers as they are
         * (some read an input there, as cnc_gettimer its type). */
        if (!batching) io_n = 0;
        if (strcmp(argv_[0], "fwlib_batch_end") != 0) {
            fill = FILL;
            memset(b0, FILL, BUF);
            memset(b1, FILL, BUF);
            memset(b2, FILL, BUF);
        }
        fields[0] = 0;
        sent = 0;
        int found = 0;
        for (size_t k = 0; k < sizeof table / sizeof table[0]; k++) {
            if (strcmp(table[k].name, argv_[0]) != 0) continue;
            found = 1;
            if (setjmp(missing)) {
                printf("{\"missing\":\"%s\"}\n", missing_name);
                break;
            }
            short r = table[k].fn();
            printf("{\"return\":%d,\"sent\":%lld,\"fields\":{%s}", r, sent, fields);
            print_hex("b0", b0);
            print_hex("b1", b1);
            printf("}\n");
            break;
        }
        if (!found) printf("{\"unknown\":\"%s\"}\n", argv_[0]);
    }
    return 0;
}
