/*
 * bench_delaunay3.c - times the 3D engine (lib/delaunay3) on one point file.
 * Usage: bench_delaunay3 POINTS.bin REPS [THREADS [WEIGHTS.bin]]
 * POINTS.bin holds n * 3 doubles (x y z per point, native byte order);
 * WEIGHTS.bin, when given, n doubles (a regular tetrahedralisation). Prints
 * one JSON object: median wall and CPU seconds of REPS builds (build plus
 * canonical output, as a caller would get it), median CPU seconds of the
 * build alone (cpu_build), finite tetrahedra, redundant (hidden) points, points
 * settled by parallel passes (par_done; the rest went serially), peak heap
 * bytes through a counting allocator, an FNV-1a digest of the canonical
 * tetrahedra and the points' fates (to compare builds byte for byte), and the
 * status of cvm__tet3_check() on
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

static uint64_t fnv1a(uint64_t h, const void *data, size_t len)
{
    const unsigned char *b = data;
    size_t i;
    for (i = 0; i < len; i++)
        h = (h ^ b[i]) * UINT64_C(0x100000001B3);
    return h;
}

/* n doubles from path into a fresh buffer (NULL on failure), their count in *n. */
static double *read_doubles(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    long bytes;
    double *d;
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    bytes = ftell(f);
    fseek(f, 0, SEEK_SET);
    *n = bytes > 0 ? (size_t)bytes / sizeof(double) : 0;
    d = malloc(*n * sizeof *d + 1);
    if (d && fread(d, sizeof(double), *n, f) != *n) {
        free(d);
        d = NULL;
    }
    fclose(f);
    return d;
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
    size_t n, nw = 0, nt = 0, red = 0, par = 0;
    double *xyz, *w = NULL, wall[64], cpu[64], cpu_build[64];
    int reps, r, check = -1, threads = 1;
    uint64_t digest = UINT64_C(0xCBF29CE484222325);
    counter cnt = { 0, 0 };
    if (argc < 3 || argc > 5) {
        fprintf(stderr, "usage: bench_delaunay3 POINTS.bin REPS [THREADS [WEIGHTS.bin]]\n");
        return 2;
    }
    if (argc >= 4)
        threads = atoi(argv[3]);
    reps = atoi(argv[2]);
    reps = reps < 1 ? 1 : reps > 64 ? 64 : reps;
    xyz = read_doubles(argv[1], &n);
    n /= 3;
    if (!xyz || (argc == 5 && (!(w = read_doubles(argv[4], &nw)) || nw != n))) {
        fprintf(stderr, "bench_delaunay3: cannot read %s (or %zu weights for %zu points)\n",
                argv[1], nw, n);
        return 2;
    }
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
        s = cvm__tet3_build(&T, xyz, w, n, 1);
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
        red = T.n_redundant;
        par = T.n_par_done;
        if (r == reps - 1) {
            unsigned char *fate = malloc(n + 1);
            digest = fnv1a(digest, tets, 4 * nt * sizeof *tets);
            if (fate) {
                cvm__tet3_point_fates(&T, fate, NULL);
                digest = fnv1a(digest, fate, n);
                free(fate);
            }
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
           "\"redundant\": %zu, \"par_done\": %zu, \"peak_bytes\": %zu, \"digest\": \"%016llx\", \"check\": %d}\n",
           n, threads, wall[reps / 2], cpu[reps / 2], cpu_build[reps / 2], nt, red, par, cnt.peak,
           (unsigned long long)digest, check);
    free(xyz);
    free(w);
    return check == CVM_OK ? 0 : 1;
}
