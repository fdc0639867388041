/*
 * bench_delaunay3.c - times the 3D engine (lib/delaunay3) on one point file.
 * Usage: bench_delaunay3 POINTS.bin REPS [THREADS]
 * POINTS.bin holds n * 3 doubles (x y z per point, native byte order). Prints
 * one JSON object: median wall and CPU seconds of REPS builds (build plus
 * canonical output, as a caller would get it), median CPU seconds of the
 * build alone (cpu_build), finite tetrahedra, peak heap
 * bytes through a counting allocator, and the status of cvm__tet3_check() on
 * the last run (speed on a wrong mesh does not count). THREADS (default 1) is
 * the build's thread count (cvm__tet3.threads; 0: OpenMP's default).
 * The engine has no public handle yet, so this driver includes its internal
 * header and links the static library.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "delaunay3/delaunay3_internal.h"

typedef struct {
    size_t live, peak;
} counter;

/* Each block carries its size in a 16-byte header so frees can be counted. */
static void *count_malloc(void *payload, size_t size)
{
    counter *c = payload;
    unsigned char *p = malloc(size + 16);
    if (!p)
        return NULL;
    memcpy(p, &size, sizeof size);
    c->live += size;
    if (c->live > c->peak)
        c->peak = c->live;
    return p + 16;
}

static void count_free(void *payload, void *ptr)
{
    counter *c = payload;
    size_t size;
    if (!ptr)
        return;
    memcpy(&size, (unsigned char *)ptr - 16, sizeof size);
    c->live -= size;
    free((unsigned char *)ptr - 16);
}

static void *count_realloc(void *payload, void *ptr, size_t size)
{
    counter *c = payload;
    size_t old;
    unsigned char *p;
    if (!ptr)
        return count_malloc(payload, size);
    memcpy(&old, (unsigned char *)ptr - 16, sizeof old);
    p = realloc((unsigned char *)ptr - 16, size + 16);
    if (!p)
        return NULL;
    memcpy(p, &size, sizeof size);
    c->live = c->live - old + size;
    if (c->live > c->peak)
        c->peak = c->live;
    return p + 16;
}

static double clock_s(clockid_t id)
{
    struct timespec t;
    clock_gettime(id, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
    FILE *f;
    long bytes;
    size_t n, nt = 0;
    double *xyz, wall[64], cpu[64], cpu_build[64];
    int reps, r, check = -1, threads = 1;
    counter cnt = { 0, 0 };
    if ((argc != 3 && argc != 4) || !(f = fopen(argv[1], "rb"))) {
        fprintf(stderr, "usage: bench_delaunay3 POINTS.bin REPS [THREADS]\n");
        return 2;
    }
    if (argc == 4)
        threads = atoi(argv[3]);
    reps = atoi(argv[2]);
    reps = reps < 1 ? 1 : reps > 64 ? 64 : reps;
    fseek(f, 0, SEEK_END);
    bytes = ftell(f);
    fseek(f, 0, SEEK_SET);
    n = (size_t)bytes / (3 * sizeof(double));
    xyz = malloc(3 * n * sizeof *xyz + 1);
    if (!xyz || fread(xyz, sizeof(double), 3 * n, f) != 3 * n) {
        fprintf(stderr, "bench_delaunay3: cannot read %s\n", argv[1]);
        return 2;
    }
    fclose(f);
    for (r = 0; r < reps; r++) {
        cvm__ctx ctx;
        cvm__tet3 T;
        int32_t *tets;
        double w0, c0;
        cvm_status s;
        cvm__ctx_init_default(&ctx);
        ctx.alloc_fn = count_malloc, ctx.realloc_fn = count_realloc, ctx.free_fn = count_free;
        ctx.payload = &cnt;
        cvm__tet3_init(&T, &ctx);
        T.threads = threads;
        w0 = clock_s(CLOCK_MONOTONIC), c0 = clock_s(CLOCK_PROCESS_CPUTIME_ID);
        s = cvm__tet3_build(&T, xyz, NULL, n, 1);
        cpu_build[r] = clock_s(CLOCK_PROCESS_CPUTIME_ID) - c0;
        tets = s == CVM_OK ? count_malloc(&cnt, 4 * T.n_finite * sizeof *tets) : NULL;
        if (s == CVM_OK)
            s = tets ? cvm__tet3_copy_tets(&T, tets) : CVM_E_NOMEM;
        wall[r] = clock_s(CLOCK_MONOTONIC) - w0, cpu[r] = clock_s(CLOCK_PROCESS_CPUTIME_ID) - c0;
        if (s != CVM_OK) {
            fprintf(stderr, "bench_delaunay3: status %d: %s\n", (int)s, ctx.errmsg);
            return 1;
        }
        nt = T.n_finite;
        if (r == reps - 1) {
            check = (int)cvm__tet3_check(&T);
            if (check != CVM_OK)
                fprintf(stderr, "bench_delaunay3: check failed: %s\n", ctx.errmsg);
        }
        count_free(&cnt, tets);
        cvm__tet3_free(&T);
    }
    qsort(wall, (size_t)reps, sizeof *wall, cmp_double);
    qsort(cpu, (size_t)reps, sizeof *cpu, cmp_double);
    qsort(cpu_build, (size_t)reps, sizeof *cpu_build, cmp_double);
    printf("{\"n\": %zu, \"threads\": %d, \"wall\": %.4f, \"cpu\": %.4f, \"cpu_build\": %.4f, \"tets\": %zu, "
           "\"peak_bytes\": %zu, \"check\": %d}\n",
           n, threads, wall[reps / 2], cpu[reps / 2], cpu_build[reps / 2], nt, cnt.peak, check);
    free(xyz);
    return check == CVM_OK ? 0 : 1;
}
