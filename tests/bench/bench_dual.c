/* bench_dual.c - driver of bench_dual.py: triangulate + refine one .poly at a uniform size (or
 * read a mesh given as .node + .ele by the script), measure the power dual, optimise it, measure
 * again, check the mesh, and print one line of key=value pairs. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <time.h>

#include "cvmesh.h"

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double measure(cvm_mesh *m, cvm_measure which)
{
    double v = -1;
    if (cvm_mesh_get_measure(&v, m, which)) {
        fprintf(stderr, "measure %d: %s\n", (int)which, cvm_mesh_errmsg(m));
        exit(1);
    }
    return v;
}

/* Smallest power dual edge over its primal edge, over interior edges (public arrays only). */
static double power_ratio(cvm_mesh *m)
{
    size_t nv, ne, nt, k, t;
    double *xy, *len, best = 1e300;
    cvm_index *ev, *tri, *nb;
    unsigned char *interior;
    cvm_mesh_count(&nv, m, CVM_ENT_VERTEX);
    cvm_mesh_count(&ne, m, CVM_ENT_EDGE);
    cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE);
    xy = malloc(2 * nv * sizeof *xy + 1);
    len = malloc(ne * sizeof *len + 1);
    ev = malloc(2 * ne * sizeof *ev + 4);
    tri = malloc(3 * nt * sizeof *tri + 4);
    nb = malloc(3 * nt * sizeof *nb + 4);
    interior = calloc(ne + 1, 1);
    cvm_mesh_copy_points(xy, 2 * nv, m);
    cvm_mesh_copy_cells(ev, 2 * ne, m, CVM_ENT_EDGE);
    cvm_mesh_copy_cells(tri, 3 * nt, m, CVM_ENT_TRIANGLE);
    cvm_mesh_copy_neighbors(nb, 3 * nt, m);
    cvm_mesh_copy_dual_edge_lengths(len, ne, m);
    for (t = 0; t < nt; t++) {
        int j;
        for (j = 0; j < 3; j++) {
            cvm_index a = tri[3 * t + (size_t)(j + 1) % 3], b = tri[3 * t + (size_t)(j + 2) % 3];
            cvm_index lo = a < b ? a : b, hi = a < b ? b : a;
            size_t l = 0, r = ne;
            if (nb[3 * t + (size_t)j] < 0)
                continue;
            while (l < r) {
                size_t mid = (l + r) / 2;
                if (ev[2 * mid] < lo || (ev[2 * mid] == lo && ev[2 * mid + 1] < hi))
                    l = mid + 1;
                else
                    r = mid;
            }
            if (l < ne)
                interior[l] = 1;
        }
    }
    for (k = 0; k < ne; k++) {
        const double *p = xy + 2 * (size_t)ev[2 * k], *q = xy + 2 * (size_t)ev[2 * k + 1];
        double r = len[k] / sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]));
        if (interior[k] && r < best)
            best = r;
    }
    free(xy);
    free(len);
    free(ev);
    free(tri);
    free(nb);
    free(interior);
    return best;
}

static void print_state(cvm_mesh *m, const char *tag)
{
    size_t nt;
    cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE);
    printf(" %s_powerratio=%.4g", tag, power_ratio(m));
    printf(" %s_nt=%lu %s_out=%.4f %s_nc=%.4f %s_ncb=%.4f %s_merged=%.4f %s_minang=%.3f"
           " %s_dualratio=%.4g %s_step=%.6g",
           tag, (unsigned long)nt, tag, measure(m, CVM_MEASURE_DUAL_OUTSIDE_PCT), tag,
           measure(m, CVM_MEASURE_DUAL_NONCOMPLIANT_PCT), tag,
           measure(m, CVM_MEASURE_DUAL_NONCOMPLIANT_BOUNDARY_PCT), tag,
           measure(m, CVM_MEASURE_DUAL_MERGED_PCT), tag, measure(m, CVM_MEASURE_MIN_ANGLE_DEG), tag,
           measure(m, CVM_MEASURE_MIN_DUAL_EDGE_RATIO), tag,
           measure(m, CVM_MEASURE_TIME_STEP_PROXY));
}

int main(int argc, char **argv)
{
    double h, t0, t_ref = 0, t_opt;
    int algo, solver;
    cvm_mesh *m;
    cvm_sizing *s = NULL;
    cvm_status st;
    double grade = 0; /* grade=G: boundary grading of the refinement's sizing */
    if (argc < 5) {
        fprintf(stderr, "usage: bench_dual IN.poly|IN.node H ALGO(0 none|1|2) SOLVER(1|2) "
                        "[grade=G] [OPTION=VALUE ...] [-o OUT.node]\n");
        return 2;
    }
    h = atof(argv[2]);
    algo = atoi(argv[3]);
    solver = atoi(argv[4]);
    if (cvm_mesh_create(&m) || cvm_mesh_read(m, argv[1])) {
        fprintf(stderr, "%s\n", cvm_mesh_errmsg(m));
        return 1;
    }
    cvm_mesh_set_option(m, CVM_OPT_DUAL_SOLVER, solver);
    {
        int i;
        for (i = 5; i < argc; i++) {
            int key;
            double val;
            if (!strcmp(argv[i], "-o")) {
                i++;
                continue;
            }
            if (sscanf(argv[i], "grade=%lf", &grade) == 1)
                continue;
            if (sscanf(argv[i], "%d=%lf", &key, &val) == 2 &&
                cvm_mesh_set_option(m, (cvm_option)key, val)) {
                fprintf(stderr, "%s\n", cvm_mesh_errmsg(m));
                return 1;
            }
        }
    }
    t0 = now();
    if (cvm_mesh_triangulate(m)) {
        fprintf(stderr, "%s\n", cvm_mesh_errmsg(m));
        return 1;
    }
    if (algo) {
        if (cvm_sizing_create(&s) || cvm_sizing_set_uniform(s, h) ||
            (grade > 0 && cvm_sizing_set_boundary_grading(s, grade)))
            return 1;
        if ((st = cvm_mesh_refine(m, s, (cvm_algorithm)algo)) != CVM_OK) {
            fprintf(stderr, "refine: %s\n", cvm_mesh_errmsg(m));
            return 1;
        }
    }
    t_ref = now() - t0;
    printf("case=%s", argv[1]);
    print_state(m, "before");
    t0 = now();
    st = cvm_mesh_optimise_dual(m, NULL);
    t_opt = now() - t0;
    if (cvm_status_is_error(st)) {
        fprintf(stderr, "optimise: %s\n", cvm_mesh_errmsg(m));
        return 1;
    }
    print_state(m, "after");
    printf(" status=%d sweeps=%.0f moves=%.0f flips=%.0f fixes=%.0f t_refine=%.4f t_opt=%.4f"
           " vanished=%.0f",
           (int)st, measure(m, CVM_MEASURE_DUAL_OPT_SWEEPS), measure(m, CVM_MEASURE_DUAL_OPT_MOVES),
           measure(m, CVM_MEASURE_DUAL_OPT_FLIPS), measure(m, CVM_MEASURE_DUAL_OPT_WEIGHT_FIXES),
           t_ref, t_opt, measure(m, CVM_MEASURE_VANISHED_VERTICES));
    if (cvm_mesh_check(m)) {
        printf(" check=FAIL\n");
        fprintf(stderr, "check: %s\n", cvm_mesh_errmsg(m));
        return 1;
    }
    printf(" check=ok\n");
    {
        int i;
        for (i = 5; i + 1 < argc; i++)
            if (!strcmp(argv[i], "-o") && cvm_mesh_write(m, argv[i + 1])) {
                fprintf(stderr, "write: %s\n", cvm_mesh_errmsg(m));
                return 1;
            }
    }
    cvm_sizing_free(s);
    cvm_mesh_free(m);
    return 0;
}
