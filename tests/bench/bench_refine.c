/* bench_refine.c - driver of bench_refine.py: triangulate + refine one .poly at a uniform size
 * (or, for H < 0, the graded annulus size 0.4 + (r - 1)/2.5), print the median time of REPS
 * runs, and dump the last mesh as raw arrays for the script. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#include <time.h>

#include "cvmesh.h"

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* The thesis's graded annulus size: 0.4 at r = 1 growing to 1.6 at r = 4. */
static double graded_annulus(void *payload, double x, double y)
{
    (void)payload;
    return 0.4 + (sqrt(x * x + y * y) - 1) / 2.5;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

int main(int argc, char **argv)
{
    double h, ts[64];
    int algo, reps, r;
    cvm_mesh *m = NULL;
    if (argc != 6) {
        fprintf(stderr, "usage: bench_refine IN.poly H ALGO(1|2|3) REPS OUT_PREFIX  (H < 0: graded annulus)\n");
        return 2;
    }
    h = atof(argv[2]);
    algo = atoi(argv[3]);
    reps = atoi(argv[4]);
    if (reps < 1 || reps > 64)
        reps = 5;
    /* r = -1: an untimed warm-up run (page faults of the first allocations, cold
     * caches), as Triangle runs warm in the Python process that times it */
    for (r = -1; r < reps; r++) {
        cvm_sizing *s;
        double t0;
        cvm_status st;
        cvm_mesh_free(m);
        if (cvm_mesh_create(&m) || cvm_sizing_create(&s) ||
            (h > 0 ? cvm_sizing_set_uniform(s, h) : cvm_sizing_set_callback(s, graded_annulus, NULL)))
            return 1;
        if (cvm_mesh_read(m, argv[1])) {
            fprintf(stderr, "%s\n", cvm_mesh_errmsg(m));
            return 1;
        }
        /* CVM_BENCH_SMOOTH_METHOD: CVM_OPT_SMOOTH_METHOD to compare (unset: the default) */
        if (getenv("CVM_BENCH_RELAX"))
            cvm_mesh_set_option(m, CVM_OPT_RELAX_SWEEPS, atof(getenv("CVM_BENCH_RELAX")));
        if (getenv("CVM_BENCH_SMOOTH"))
            cvm_mesh_set_option(m, CVM_OPT_SMOOTH_SWEEPS, atof(getenv("CVM_BENCH_SMOOTH")));
        if (getenv("CVM_BENCH_SMOOTH_METHOD") &&
            cvm_mesh_set_option(m, CVM_OPT_SMOOTH_METHOD, atof(getenv("CVM_BENCH_SMOOTH_METHOD")))) {
            fprintf(stderr, "%s\n", cvm_mesh_errmsg(m));
            return 1;
        }
        /* CVM_BENCH_RESAMPLE=1: CVM_OPT_KEEP_SEGMENT_VERTICES = 0 (smooth chains re-discretised) */
        if (getenv("CVM_BENCH_RESAMPLE") && atoi(getenv("CVM_BENCH_RESAMPLE")) &&
            cvm_mesh_set_option(m, CVM_OPT_KEEP_SEGMENT_VERTICES, 0)) {
            fprintf(stderr, "%s\n", cvm_mesh_errmsg(m));
            return 1;
        }
        t0 = now();
        if (cvm_mesh_triangulate(m) || (st = cvm_mesh_refine(m, s, (cvm_algorithm)algo)) != CVM_OK) {
            fprintf(stderr, "%s\n", cvm_mesh_errmsg(m));
            return 1;
        }
        if (r >= 0)
            ts[r] = now() - t0;
        cvm_sizing_free(s);
    }
    qsort(ts, (size_t)reps, sizeof ts[0], cmp);
    if (cvm_mesh_check(m)) {
        fprintf(stderr, "check: %s\n", cvm_mesh_errmsg(m));
        return 1;
    }
    {
        size_t nv, nt;
        double *xy;
        cvm_index *tri;
        char path[4096];
        FILE *f;
        cvm_mesh_count(&nv, m, CVM_ENT_VERTEX);
        cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE);
        xy = malloc(2 * nv * sizeof *xy + 1);
        tri = malloc(3 * nt * sizeof *tri + 1);
        cvm_mesh_copy_points(xy, 2 * nv, m);
        cvm_mesh_copy_cells(tri, 3 * nt, m, CVM_ENT_TRIANGLE);
        snprintf(path, sizeof path, "%s.xy", argv[5]);
        f = fopen(path, "wb");
        fwrite(xy, sizeof *xy, 2 * nv, f);
        fclose(f);
        snprintf(path, sizeof path, "%s.tri", argv[5]);
        f = fopen(path, "wb");
        fwrite(tri, sizeof *tri, 3 * nt, f);
        fclose(f);
        free(xy);
        free(tri);
    }
    printf("%.9f\n", ts[reps / 2]);
    cvm_mesh_free(m);
    return 0;
}
