/* bench_delaunay.c - times cvmesh on one point set or PSLG and prints one JSON line.
 *
 * Usage: bench_delaunay points FILE.bin REPEATS   (raw little-endian float64 x,y pairs)
 *        bench_delaunay poly FILE.poly REPEATS
 * Prints {"median_s":..., "triangles":..., "peak_bytes":..., "check":0|status}.
 * Peak bytes come from a counting allocator given to the handle, so they are
 * the library's own heap use, not the process RSS.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cvmesh.h"

typedef struct counter {
    size_t live, peak;
} counter;

/* Blocks carry their size in a 16-byte header so free can account for them. */
static void *c_malloc(void *p, size_t n)
{
    counter *c = p;
    size_t *b = malloc(n + 16);
    if (!b)
        return NULL;
    b[0] = n;
    c->live += n;
    if (c->live > c->peak)
        c->peak = c->live;
    return (char *)b + 16;
}

static void c_free(void *p, void *q)
{
    counter *c = p;
    size_t *b;
    if (!q)
        return;
    b = (size_t *)((char *)q - 16);
    c->live -= b[0];
    free(b);
}

static void *c_realloc(void *p, void *q, size_t n)
{
    counter *c = p;
    size_t *b, old;
    if (!q)
        return c_malloc(p, n);
    b = (size_t *)((char *)q - 16);
    old = b[0];
    b = realloc(b, n + 16);
    if (!b)
        return NULL;
    b[0] = n;
    c->live = c->live - old + n;
    if (c->live > c->peak)
        c->peak = c->live;
    return (char *)b + 16;
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double *read_points(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    long len;
    double *xy;
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    len = ftell(f);
    fseek(f, 0, SEEK_SET);
    xy = malloc((size_t)len);
    if (!xy || fread(xy, 1, (size_t)len, f) != (size_t)len) {
        fclose(f);
        free(xy);
        return NULL;
    }
    fclose(f);
    *n = (size_t)len / (2 * sizeof(double));
    return xy;
}

int main(int argc, char **argv)
{
    int poly, reps, r;
    double *xy = NULL, times[64];
    size_t n = 0, nt = 0;
    counter cnt = {0, 0};
    cvm_status chk = CVM_OK;
    if (argc != 4) {
        fprintf(stderr, "usage: %s points|poly FILE REPEATS\n", argv[0]);
        return 2;
    }
    poly = strcmp(argv[1], "poly") == 0;
    reps = atoi(argv[3]);
    if (reps < 1 || reps > 64)
        reps = 5;
    if (!poly && !(xy = read_points(argv[2], &n))) {
        fprintf(stderr, "cannot read %s\n", argv[2]);
        return 2;
    }
    for (r = 0; r < reps; r++) {
        cvm_mesh *m;
        cvm_status s;
        double t0, t1;
        cnt.live = cnt.peak = 0;
        if (cvm_mesh_create_with_allocator(&m, c_malloc, c_realloc, c_free, &cnt) != CVM_OK)
            return 3;
        if (poly)
            s = cvm_mesh_read(m, argv[2]);
        else
            s = cvm_mesh_set_points(m, xy, n, 2);
        if (s != CVM_OK) {
            fprintf(stderr, "input: %s\n", cvm_mesh_errmsg(m));
            return 3;
        }
        t0 = now();
        s = cvm_mesh_triangulate(m);
        t1 = now();
        if (s != CVM_OK) {
            fprintf(stderr, "triangulate: %s\n", cvm_mesh_errmsg(m));
            return 3;
        }
        times[r] = t1 - t0;
        cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE);
        if (r == reps - 1)
            chk = cvm_mesh_check(m);
        cvm_mesh_free(m);
    }
    qsort(times, (size_t)reps, sizeof times[0], cmp_double);
    printf("{\"median_s\": %.6f, \"triangles\": %lu, \"peak_bytes\": %lu, \"check\": %d}\n",
           times[reps / 2], (unsigned long)nt, (unsigned long)cnt.peak, (int)chk);
    free(xy);
    return chk == CVM_OK ? 0 : 1;
}
