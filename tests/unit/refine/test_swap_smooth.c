/* test_swap_smooth.c - post-processing of frontal refinement (lib/refine/swap.c, smooth.c): degree swapping, smart Laplacian smoothing and the Delaunay-restoring flips, through cvm_mesh_refine and its options. */
#include <math.h>
#include <stdlib.h>

#include "refine/refine_tests.h"
#include "support/failing_alloc.h"
#include "support/mesh_oracle.h"

/* Read, triangulate and refine name at uniform size h with CVM_ALGO_FRONTAL and
 * the given post-processing options. */
static cvm_mesh *post_refined(const char *path, double h, double swap, double sweeps)
{
    cvm_mesh *m;
    cvm_status s;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_SWAP, swap), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_SMOOTH_SWEEPS, sweeps), CVM_OK);
    ck_assert_msg(cvm_mesh_read(m, path) == CVM_OK, "%s: %s", path, cvm_mesh_errmsg(m));
    ck_assert_msg(cvm_mesh_triangulate(m) == CVM_OK, "%s: %s", path, cvm_mesh_errmsg(m));
    s = rtest_refine_uniform(m, h, CVM_ALGO_FRONTAL);
    ck_assert_msg(s == CVM_OK, "%s: refine returned %s: %s", path, cvm_status_str(s),
                  cvm_mesh_errmsg(m));
    return m;
}

/* Percentage of triangle angles in [55, 65] degrees, and the smallest angle,
 * measured here from the output coordinates. */
static double regular_pct(cvm_mesh *m, double *min_angle)
{
    size_t nv, nt, t, in = 0;
    double *xy;
    cvm_index *tri;
    int k;
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    xy = malloc(2 * nv * sizeof *xy + 1);
    tri = malloc(3 * nt * sizeof *tri + 1);
    ck_assert(xy && tri);
    ck_assert_int_eq(cvm_mesh_copy_points(xy, 2 * nv, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(tri, 3 * nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    *min_angle = 180;
    for (t = 0; t < nt; t++) {
        for (k = 0; k < 3; k++) {
            const double *o = xy + 2 * (size_t)tri[3 * t + (size_t)k];
            const double *a = xy + 2 * (size_t)tri[3 * t + (size_t)(k + 1) % 3];
            const double *b = xy + 2 * (size_t)tri[3 * t + (size_t)(k + 2) % 3];
            double ux = a[0] - o[0], uy = a[1] - o[1], wx = b[0] - o[0], wy = b[1] - o[1];
            double ang =
                atan2(fabs(ux * wy - uy * wx), ux * wx + uy * wy) * 180 / 3.14159265358979323846;
            if (ang >= 55 && ang <= 65)
                in++;
            if (ang < *min_angle)
                *min_angle = ang;
        }
    }
    free(xy);
    free(tri);
    return nt ? 100.0 * (double)in / (3.0 * (double)nt) : 0;
}

/* Swap + smoothing on a shared geometry: a valid constrained Delaunay mesh
 * keeping every segment, every angle >= 30, more regular than without, and
 * reproducible byte for byte. */
static void post_geometry(const char *name, double h, long euler)
{
    char path[1024];
    cvm_mesh *m, *m2, *m0;
    cvmtest_expect e;
    rtest_quality q;
    size_t nseg;
    double reg, reg0, amin, amin0;
    cvm_index *segs;
    rtest_shared_path(path, sizeof path, name);
    segs = rtest_poly_segments(path, &nseg);
    m = post_refined(path, h, 1, 2);
    cvmtest_expect_init(&e);
    e.delaunay = 1;
    e.segs = segs;
    e.nseg = nseg;
    e.check_euler = 1;
    e.euler = euler;
    cvmtest_assert_valid_ex(m, &e);
    rtest_measure(m, &q);
    ck_assert_msg(q.min_angle >= 30.0 - 1e-9, "%s: min angle %.17g < 30", name, q.min_angle);
    ck_assert_msg(q.max_circumradius <= h * (1 + 1e-9), "%s: circumradius %.17g > size %g", name,
                  q.max_circumradius, h);
    reg = regular_pct(m, &amin);
    ck_assert(amin >= 30.0 - 1e-9);
    m0 = post_refined(path, h, 0, 0);
    cvmtest_assert_valid_ex(m0, &e);
    reg0 = regular_pct(m0, &amin0);
    ck_assert_msg(reg > reg0, "%s: %.3f%% of angles in [55, 65] with swap + smoothing, %.3f%% "
                  "without", name, reg, reg0);
    m2 = post_refined(path, h, 1, 2);
    rtest_assert_identical(m, m2);
    cvm_mesh_free(m2);
    cvm_mesh_free(m0);
    cvm_mesh_free(m);
    free(segs);
}

START_TEST(square_post)
{
    post_geometry("square.poly", 0.03, 1);
}
END_TEST

START_TEST(channel_post)
{
    post_geometry("channel.poly", 0.05, 1);
}
END_TEST

START_TEST(annulus_post)
{
    post_geometry("annulus.poly", 0.2, 0);
}
END_TEST

START_TEST(cylinder_post)
{
    post_geometry("cylinder.poly", 0.5, 0);
}
END_TEST

START_TEST(naca0012_post)
{
    post_geometry("naca0012.poly", 0.5, 0);
}
END_TEST

/* Swapping alone never loses a segment or the bounds; smoothing never moves an
 * input point; the options have the documented bounds. */
START_TEST(swap_only_and_input_points_fixed)
{
    static const double sq[] = {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5};
    static const cvm_index seg[] = {0, 1, 1, 2, 2, 3, 3, 0};
    cvm_mesh *m;
    cvm_bounds b;
    double *xy, d;
    size_t nv;
    cvm_index map[5];
    int k;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_SMOOTH_SWEEPS, 5), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, sq, 5, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, seg, 4), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(rtest_refine_uniform(m, 0.05, CVM_ALGO_FRONTAL), CVM_OK);
    cvmtest_assert_valid(m);
    ck_assert_int_eq(cvm_mesh_copy_input_map(map, 5, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert(nv > 100);
    xy = malloc(2 * nv * sizeof *xy);
    ck_assert(xy != NULL);
    ck_assert_int_eq(cvm_mesh_copy_points(xy, 2 * nv, m), CVM_OK);
    for (k = 0; k < 5; k++) {
        ck_assert_int_eq(map[k], k);
        ck_assert(xy[2 * k] == sq[2 * k] && xy[2 * k + 1] == sq[2 * k + 1]);
    }
    free(xy);
    ck_assert_int_eq(cvm_mesh_get_measure(&d, m, CVM_MEASURE_REFINE_MET_ANGLE), CVM_OK);
    ck_assert(d >= 30.0 - 1e-9);
    cvm_mesh_free(m);

    ck_assert_int_eq(cvm_option_bounds(&b, CVM_OPT_SWAP), CVM_OK);
    ck_assert(b.lo == 0 && b.hi == 1 && b.def == 1 && b.is_integer);
    ck_assert_int_eq(cvm_option_bounds(&b, CVM_OPT_SMOOTH_SWEEPS), CVM_OK);
    ck_assert(b.lo == 0 && b.hi == 100 && b.def == 3 && b.is_integer);
    ck_assert_int_eq(cvm_option_bounds(&b, CVM_OPT_RESTORE_DELAUNAY), CVM_OK);
    ck_assert(b.lo == 1 && b.hi == 1 && b.def == 1 && b.is_integer);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_RESTORE_DELAUNAY, 0), CVM_E_OPTION_RANGE);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_SMOOTH_SWEEPS, 101), CVM_E_OPTION_RANGE);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_SWAP, 0.5), CVM_E_OPTION_RANGE);
    cvm_mesh_free(m);
}
END_TEST

/* Out of memory at every allocation of a frontal refinement with swap and
 * smoothing (transient and persistent): CVM_OK or CVM_E_NOMEM, and the mesh,
 * when kept, is a valid constrained Delaunay triangulation. */
/* An area bound alone (no sizing): swapping, smoothing and the Delaunay-restoring
 * flips must not leave a triangle above it or below the angle (measured here);
 * this once left 10 of 1444 triangles up to 1.24 x the bound. */
START_TEST(area_bound_survives_post_processing)
{
    static const double sq[] = {0, 0, 1, 0, 1, 1, 0, 1};
    static const cvm_index seg[] = {0, 1, 1, 2, 2, 3, 3, 0};
    cvm_mesh *m;
    size_t nv, nt, t;
    double *xy, amax = 0, amin;
    cvm_index *tri;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, sq, 4, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, seg, 4), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_MAX_AREA, 0.001), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_MIN_ANGLE_DEG, 20), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_msg(cvm_mesh_refine(m, NULL, CVM_ALGO_FRONTAL) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    xy = malloc(2 * nv * sizeof *xy + 1);
    tri = malloc(3 * nt * sizeof *tri + 1);
    ck_assert(xy && tri);
    ck_assert_int_eq(cvm_mesh_copy_points(xy, 2 * nv, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(tri, 3 * nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    for (t = 0; t < nt; t++) {
        const double *a = xy + 2 * (size_t)tri[3 * t], *b = xy + 2 * (size_t)tri[3 * t + 1];
        const double *c = xy + 2 * (size_t)tri[3 * t + 2];
        double ar = fabs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2;
        if (ar > amax)
            amax = ar;
    }
    ck_assert_msg(nt > 1000 && amax <= 0.001 * (1 + 1e-12), "%lu triangles, largest area %.17g",
                  (unsigned long)nt, amax);
    ck_assert(regular_pct(m, &amin) > 0);
    ck_assert_msg(amin >= 20 - 1e-9, "smallest angle %.17g", amin);
    free(xy);
    free(tri);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(out_of_memory_keeps_a_valid_mesh)
{
    static const double sq[] = {0, 0, 1, 0, 1, 1, 0, 1};
    static const cvm_index seg[] = {0, 1, 1, 2, 2, 3, 3, 0};
    int persistent;
    for (persistent = 0; persistent <= 1; persistent++) {
        long i;
        for (i = 1; i < 100000; i++) {
            cvmtest_alloc a;
            cvm_mesh *m;
            cvm_status st;
            long failed;
            cvmtest_alloc_init(&a, 0, 0);
            ck_assert_int_eq(cvmtest_mesh_create(&m, &a), CVM_OK);
            ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_SMOOTH_SWEEPS, 2), CVM_OK);
            ck_assert_int_eq(cvm_mesh_set_points(m, sq, 4, 2), CVM_OK);
            ck_assert_int_eq(cvm_mesh_set_segments(m, seg, 4), CVM_OK);
            ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
            cvmtest_alloc_arm(&a, a.n_calls + i, persistent);
            st = rtest_refine_uniform(m, 0.1, CVM_ALGO_FRONTAL);
            failed = a.n_failed;
            cvmtest_alloc_arm(&a, 0, 0);
            ck_assert_msg(st == CVM_OK || st == CVM_E_NOMEM, "allocation %ld: %s", i,
                          cvm_status_str(st));
            if (cvm_mesh_check(m) != CVM_E_STATE)
                cvmtest_assert_valid(m);
            cvm_mesh_free(m);
            ck_assert_int_eq(a.live_blocks, 0);
            if (failed == 0) {
                ck_assert_int_eq(st, CVM_OK);
                break;
            }
        }
        ck_assert_msg(i > 20 && i < 100000, "%ld allocations in the refinement", i);
    }
}
END_TEST

TCase *refine_swap_smooth_tcase(void)
{
    TCase *tc = tcase_create("swap_smooth");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, square_post);
    tcase_add_test(tc, channel_post);
    tcase_add_test(tc, annulus_post);
    tcase_add_test(tc, cylinder_post);
    tcase_add_test(tc, naca0012_post);
    tcase_add_test(tc, swap_only_and_input_points_fixed);
    tcase_add_test(tc, area_bound_survives_post_processing);
    tcase_add_test(tc, out_of_memory_keeps_a_valid_mesh);
    return tc;
}
