/*
 * test_refine.c - the Delaunay-refinement free space
 * (CVM_GEN3_FREESPACE_REFINE): every point strictly inside, apart from the
 * others by its rejection distance and from the surface by half of it; the
 * point limit stops it with CVM_INCOMPLETE_STEINER_LIMIT and a valid mesh;
 * the same bytes every run; OOM at every allocation.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "generate3/g3_util.h"
#include "generate3/generate3_tests.h"
#include "support/oom_sweep.h"

static cvm_mesh *read_refine(const char *name)
{
    cvm_mesh *m;
    char path[1024];
    g3_data3d(path, sizeof path, name);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_msg(cvm_mesh_read(m, path) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_FREESPACE, CVM_GEN3_FREESPACE_REFINE),
                     CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_SIZE_FROM_SURFACE, 0), CVM_OK);
    return m;
}

static double report(const cvm_mesh *m, cvm_report which)
{
    double v;
    ck_assert_int_eq(cvm_mesh_get_report(&v, m, which), CVM_OK);
    return v;
}

/* The tetrahedron of tetra.off (corners (1,1,1), (1,-1,-1), (-1,1,-1),
 * (-1,-1,1)) at uniform size 0.3: its faces are the planes s . x = 1 for the
 * sign vectors s below, the inside s . x < 1; dm = 0.55 x 0.3. */
START_TEST(refine_points_inside_and_apart)
{
    static const double sgn[4][3] = {{-1, 1, 1}, {1, -1, 1}, {1, 1, -1}, {-1, -1, -1}};
    const double dm = 0.55 * 0.3, sq3 = sqrt(3.0);
    cvm_mesh *m = read_refine("tetra.off");
    double near_pts, ref_pts;
    size_t first, i, j;
    g3_mesh g;
    ck_assert_msg(cvm_mesh_generate3(m, 0.3) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    near_pts = report(m, CVM_REPORT_GEN3_NEAR_POINTS);
    ref_pts = report(m, CVM_REPORT_GEN3_REFINE_POINTS);
    ck_assert_double_gt(ref_pts, 100);
    ck_assert_double_ge(report(m, CVM_REPORT_GEN3_REFINE_ROUNDS), 3);
    ck_assert_double_eq(report(m, CVM_REPORT_GEN3_LATTICE_POINTS), 0);
    ck_assert_double_eq(report(m, CVM_REPORT_GEN3_OCTREE_POINTS), 0);
    g3_mesh_get(&g, m);
    first = 4 + (size_t)near_pts;
    ck_assert_uint_eq(g.nv, first + (size_t)ref_pts);
    ck_assert_int_eq(g3_euler(&g), 1);
    for (i = first; i < g.nv; i++) {
        const double *x = g.xyz + 3 * i;
        int f;
        for (f = 0; f < 4; f++) {
            /* distance to the plane of face f: (1 - s . x) / sqrt 3 */
            double d = (1 - (sgn[f][0] * x[0] + sgn[f][1] * x[1] + sgn[f][2] * x[2])) / sq3;
            ck_assert_double_ge(d, 0.5 * dm);
        }
        for (j = 0; j < g.nv; j++) {
            const double *y = g.xyz + 3 * j;
            double d2 = (x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) +
                        (x[2] - y[2]) * (x[2] - y[2]);
            if (j != i)
                ck_assert_double_ge(d2, dm * dm);
        }
    }
    g3_mesh_free(&g);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(refine_point_limit_stops_with_a_valid_mesh)
{
    cvm_mesh *m = read_refine("tetra.off");
    size_t nv;
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_MAX_STEINER, 10), CVM_OK);
    ck_assert_int_eq(cvm_mesh_generate3(m, 0.3), CVM_INCOMPLETE_STEINER_LIMIT);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "CVM_OPT_MAX_STEINER"));
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    ck_assert_double_eq(report(m, CVM_REPORT_GEN3_REFINE_POINTS), 10);
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_uint_eq(nv, 4 + (size_t)report(m, CVM_REPORT_GEN3_NEAR_POINTS) + 10);
    /* the limit does not bind the lattice */
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_FREESPACE, CVM_GEN3_FREESPACE_LATTICE),
                     CVM_OK);
    ck_assert_int_eq(cvm_mesh_generate3(m, 0.3), CVM_OK);
    ck_assert_double_eq(report(m, CVM_REPORT_GEN3_REFINE_POINTS), 0);
    cvm_mesh_free(m);
}
END_TEST

static void run_bytes(double seed, double threads, double **xyz, size_t *nv, cvm_index **tet,
                      size_t *nt)
{
    cvm_mesh *m = read_refine(g3_with_tetgen() ? "cube.off" : "tetra.off");
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_SEED, seed), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_THREADS, threads), CVM_OK);
    ck_assert_msg(cvm_mesh_generate3(m, g3_with_tetgen() ? 0.1 : 0.3) == CVM_OK, "%s",
                  cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_count(nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    *xyz = malloc(3 * *nv * sizeof **xyz);
    *tet = malloc(4 * *nt * sizeof **tet);
    ck_assert(*xyz && *tet);
    ck_assert_int_eq(cvm_mesh_copy_points_nd(*xyz, 3 * *nv, 3, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(*tet, 4 * *nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    cvm_mesh_free(m);
}

START_TEST(refine_same_bytes_for_every_run_seed_and_thread_count)
{
    double *x0, *x1;
    cvm_index *t0, *t1;
    size_t nv0, nt0, nv1, nt1;
    double runs[2][2] = {{1, 2}, {7, 0}};
    int r;
    run_bytes(1, 1, &x0, &nv0, &t0, &nt0);
    for (r = 0; r < 2; r++) {
        run_bytes(runs[r][0], runs[r][1], &x1, &nv1, &t1, &nt1);
        ck_assert_uint_eq(nv0, nv1);
        ck_assert_uint_eq(nt0, nt1);
        ck_assert(memcmp(x0, x1, 3 * nv0 * sizeof *x0) == 0);
        ck_assert(memcmp(t0, t1, 4 * nt0 * sizeof *t0) == 0);
        free(x1);
        free(t1);
    }
    free(x0);
    free(t0);
}
END_TEST

static void oom_setup(cvm_mesh *m, void *arg)
{
    char path[1024];
    g3_data3d(path, sizeof path, (const char *)arg);
    ck_assert_int_eq(cvm_mesh_read(m, path), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_FREESPACE, CVM_GEN3_FREESPACE_REFINE),
                     CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_SIZE_FROM_SURFACE, 0), CVM_OK);
}

static cvm_status oom_run(cvm_mesh *m, void *arg)
{
    (void)arg;
    return cvm_mesh_generate3(m, 0.6);
}

START_TEST(refine_oom_at_every_allocation)
{
    cvmtest_oom_sweep(oom_setup, oom_run, NULL, (void *)"tetra.off");
}
END_TEST

TCase *generate3_refine_tcase(void)
{
    TCase *tc = tcase_create("refine");
    tcase_set_timeout(tc, 300);
    tcase_add_test(tc, refine_points_inside_and_apart);
    tcase_add_test(tc, refine_point_limit_stops_with_a_valid_mesh);
    tcase_add_test(tc, refine_same_bytes_for_every_run_seed_and_thread_count);
    tcase_add_test(tc, refine_oom_at_every_allocation);
    return tc;
}
