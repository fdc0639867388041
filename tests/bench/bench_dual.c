/* bench_dual.c - driver of bench_dual.py: triangulate + refine one .poly at a uniform size (or
 * read a mesh given as .node + .ele by the script), measure the power dual, optimise it, measure
 * again, check the mesh, and print one line of key=value pairs. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
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

static void print_state(cvm_mesh *m, const char *tag)
{
    size_t nt;
    cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE);
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
    if (argc < 5) {
        fprintf(stderr, "usage: bench_dual IN.poly|IN.node H ALGO(0 none|1|2) SOLVER(1|2) "
                        "[OPTION=VALUE ...] [-o OUT.node]\n");
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
        if (cvm_sizing_create(&s) || cvm_sizing_set_uniform(s, h))
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
