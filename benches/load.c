/* The loading cost of a FOCAS library as a C host sees it (benches/floor.rs
 * compiles and runs this, one fresh process per sample):
 *
 *   load LIB PORT   dlopen LIB, cnc_allclibhndl3("127.0.0.1", PORT, 10, &h),
 *                   cnc_freelibhndl(h), dlclose
 *   load LIB        dlopen LIB, dlclose (any library: the mechanism's floor)
 *
 * Prints the microseconds of each step on one line:
 *   dlopen ALLOC FREE dlclose   (ALLOC and FREE are 0 without PORT)
 * and exits 1 if a step failed. */
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

typedef short (*alloc_fn)(const char *, unsigned short, long, unsigned short *);
typedef short (*free_fn)(unsigned short);

static double now_us(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec * 1e6 + t.tv_nsec / 1e3;
}

int main(int argc, char **argv)
{
    if (argc < 2)
        return 2;
    double t0 = now_us();
    void *lib = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    double t1 = now_us();
    if (!lib) {
        fprintf(stderr, "%s\n", dlerror());
        return 1;
    }
    double t2 = t1, t3 = t1;
    if (argc > 2) {
        alloc_fn alloc = (alloc_fn)dlsym(lib, "cnc_allclibhndl3");
        free_fn release = (free_fn)dlsym(lib, "cnc_freelibhndl");
        if (!alloc || !release) {
            fprintf(stderr, "cnc_allclibhndl3 or cnc_freelibhndl missing\n");
            return 1;
        }
        unsigned short h = 0;
        short r = alloc("127.0.0.1", (unsigned short)atoi(argv[2]), 10, &h);
        t2 = now_us();
        if (r != 0) {
            fprintf(stderr, "cnc_allclibhndl3: %d\n", r);
            return 1;
        }
        r = release(h);
        t3 = now_us();
        if (r != 0) {
            fprintf(stderr, "cnc_freelibhndl: %d\n", r);
            return 1;
        }
    }
    double t4 = now_us();
    if (dlclose(lib) != 0) {
        fprintf(stderr, "%s\n", dlerror());
        return 1;
    }
    double t5 = now_us();
    printf("%.1f %.1f %.1f %.1f\n", t1 - t0, t2 - t1, t3 - t2, t5 - t4);
    return 0;
}
