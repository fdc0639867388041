/* test_sizing.c - the cvm_sizing handle (lib/sizing/sizing.c): combination by minimum, invalid sizes named. */
#include <math.h>
#include <string.h>

#include <stdlib.h>

#include "refine/refine_tests.h"
#include "support/failing_alloc.h"
#include "support/oom_sweep.h"

START_TEST(empty_sizing_has_no_bound)
{
    cvm_sizing *s;
    double h;
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 1, 2), CVM_OK);
    ck_assert(isinf(h) && h > 0);
    cvm_sizing_free(s);
    cvm_sizing_free(NULL);
}
END_TEST

START_TEST(sources_combine_by_minimum)
{
    cvm_sizing *s;
    double h;
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_uniform(s, 1.0), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_point_source(s, 0, 0, 0.1, 0.5), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_line_source(s, 10, -1, 10, 1, 0.2, 0.1), CVM_OK);
    /* at the point source */
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 0, 0), CVM_OK);
    ck_assert_double_eq_tol(h, 0.1, 1e-15);
    /* distance 1 from it: 0.1 + 0.5 */
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 0, 1), CVM_OK);
    ck_assert_double_eq_tol(h, 0.6, 1e-15);
    /* far from both sources: the uniform size caps it */
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 0, 8), CVM_OK);
    ck_assert_double_eq_tol(h, 1.0, 1e-15);
    /* near the line source: 0.2 + 0.1 x its distance 0.5 */
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 10.5, 0.5), CVM_OK);
    ck_assert_double_eq_tol(h, 0.25, 1e-15);
    cvm_sizing_free(s);
}
END_TEST

static double cb_half_x(void *payload, double x, double y)
{
    (void)y;
    return *(const double *)payload + 0.5 * x;
}

static double cb_negative(void *payload, double x, double y)
{
    (void)payload;
    (void)x;
    (void)y;
    return -1.0;
}

static double cb_nan(void *payload, double x, double y)
{
    (void)payload;
    (void)x;
    (void)y;
    return NAN;
}

START_TEST(callback_is_called_with_payload)
{
    cvm_sizing *s;
    double base = 0.25, h;
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_callback(s, cb_half_x, &base), CVM_OK);
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 1, 0), CVM_OK);
    ck_assert_double_eq_tol(h, 0.75, 1e-15);
    ck_assert_int_eq(cvm_sizing_set_callback(s, NULL, NULL), CVM_OK);
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 1, 0), CVM_OK);
    ck_assert(isinf(h));
    cvm_sizing_free(s);
}
END_TEST

START_TEST(bad_sizes_are_rejected_and_named)
{
    static const double bad[] = {0.0, -1.0};
    cvm_sizing *s;
    double h;
    size_t i;
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    for (i = 0; i < 2; i++) {
        ck_assert_int_eq(cvm_sizing_set_uniform(s, bad[i]), CVM_E_ARGUMENT);
        ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "uniform size"));
    }
    ck_assert_int_eq(cvm_sizing_set_uniform(s, NAN), CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "uniform size"));
    ck_assert_int_eq(cvm_sizing_set_uniform(s, INFINITY), CVM_E_INPUT_NONFINITE);
    /* the handle is unchanged by the failures */
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 0, 0), CVM_OK);
    ck_assert(isinf(h));
    ck_assert_int_eq(cvm_sizing_add_point_source(s, 0, 0, 1, 0), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_point_source(s, 0, 0, -2, 0), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "point source 1"));
    ck_assert_int_eq(cvm_sizing_add_point_source(s, NAN, 0, 1, 0), CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "point source 1"));
    ck_assert_int_eq(cvm_sizing_add_point_source(s, 0, 0, 1, -0.1), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "growth"));
    ck_assert_int_eq(cvm_sizing_add_line_source(s, 0, 0, 1, 1, 0, 0), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "line source 0"));
    ck_assert_int_eq(cvm_sizing_add_line_source(s, 0, 0, 1, 1, NAN, 0), CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "line source 0"));
    ck_assert_int_eq(cvm_sizing_eval(&h, s, NAN, 0), CVM_E_INPUT_NONFINITE);
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 0, 0), CVM_OK);
    ck_assert_str_eq(cvm_sizing_errmsg(s), "");
    ck_assert_double_eq(h, 1.0);
    cvm_sizing_free(s);
}
END_TEST

START_TEST(bad_callback_values_stop_eval_and_refine)
{
    static const double sq[] = {0, 0, 1, 0, 1, 1, 0, 1};
    static const cvm_index seg[] = {0, 1, 1, 2, 2, 3, 3, 0};
    cvm_sizing *s;
    cvm_mesh *m;
    double h;
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_callback(s, cb_negative, NULL), CVM_OK);
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 0.5, 0.5), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "sizing callback"));
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, sq, 4, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, seg, 4), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_refine(m, s, CVM_ALGO_DELAUNAY), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "sizing callback"));
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_callback(s, cb_nan, NULL), CVM_OK);
    ck_assert_int_eq(cvm_mesh_refine(m, s, CVM_ALGO_FRONTAL), CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "sizing callback"));
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    cvm_mesh_free(m);
    cvm_sizing_free(s);
}
END_TEST

START_TEST(null_arguments_and_unsupported)
{
    cvm_sizing *s;
    double h;
    ck_assert_int_eq(cvm_sizing_create(NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_set_uniform(NULL, 1), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_add_point_source(NULL, 0, 0, 1, 0), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_add_line_source(NULL, 0, 0, 1, 0, 1, 0), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_set_callback(NULL, NULL, NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_set_automatic(NULL, 1, 1), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_eval(&h, NULL, 0, 0), CVM_E_NULL_ARG);
    ck_assert_str_eq(cvm_sizing_errmsg(NULL), "no sizing handle");
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_eval(NULL, s, 0, 0), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_set_background(NULL, NULL, 0, NULL, 0), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_set_background(s, NULL, 3, NULL, 0), CVM_E_NULL_ARG);
    cvm_sizing_free(s);
}
END_TEST

/* ---- automatic sizing (sizing_auto.c) ---- */

START_TEST(automatic_parameters_are_checked)
{
    cvm_sizing *s;
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_automatic(s, 0, 4), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "R = 0"));
    ck_assert_int_eq(cvm_sizing_set_automatic(s, 3, -1), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "grading G = -1"));
    ck_assert_int_eq(cvm_sizing_set_automatic(s, NAN, 4), CVM_E_INPUT_NONFINITE);
    ck_assert_int_eq(cvm_sizing_set_automatic(s, 3, INFINITY), CVM_E_INPUT_NONFINITE);
    ck_assert_int_eq(cvm_sizing_set_automatic(s, 3, 4), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_automatic(s, 0, 0), CVM_OK); /* off again */
    cvm_sizing_free(s);
}
END_TEST

/* Mean edge length of the domain triangles whose centroid satisfies
 * lo <= |centroid - c| < hi (the test's own measurement). */
static double mean_edge_in_ring(cvm_mesh *m, double cx, double cy, double lo, double hi)
{
    size_t nv, nt, t, n = 0;
    double *xy, sum = 0;
    cvm_index *tri;
    rtest_fetch(m, &xy, &nv, &tri, &nt);
    for (t = 0; t < nt; t++) {
        const double *a = xy + 2 * tri[3 * t], *b = xy + 2 * tri[3 * t + 1],
                     *c = xy + 2 * tri[3 * t + 2];
        double gx = (a[0] + b[0] + c[0]) / 3 - cx, gy = (a[1] + b[1] + c[1]) / 3 - cy;
        double r = sqrt(gx * gx + gy * gy);
        if (r < lo || r >= hi)
            continue;
        sum += (hypot(a[0] - b[0], a[1] - b[1]) + hypot(b[0] - c[0], b[1] - c[1]) +
                hypot(c[0] - a[0], c[1] - a[1])) / 3;
        n++;
    }
    free(xy);
    free(tri);
    ck_assert_uint_gt(n, 0);
    return sum / (double)n;
}

/* The square's local feature size is its side (1) on the whole boundary, so
 * with hardly any grading the automatic size is the uniform size 1/R: same
 * bounds (circumradius <= 1/R) and about the same triangle count. */
START_TEST(automatic_square_matches_uniform_side_over_r)
{
    char path[512];
    cvm_mesh *a, *u;
    cvm_sizing *s;
    rtest_quality qa, qu;
    rtest_data_path(path, sizeof path, "square.poly");
    ck_assert_int_eq(cvm_mesh_create(&a), CVM_OK);
    ck_assert_int_eq(cvm_mesh_create(&u), CVM_OK);
    ck_assert_int_eq(cvm_mesh_read(a, path), CVM_OK);
    ck_assert_int_eq(cvm_mesh_read(u, path), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(a), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(u), CVM_OK);
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_automatic(s, 20, 1e9), CVM_OK);
    ck_assert_int_eq(cvm_mesh_refine(a, s, CVM_ALGO_DELAUNAY), CVM_OK);
    ck_assert_int_eq(rtest_refine_uniform(u, 1.0 / 20, CVM_ALGO_DELAUNAY), CVM_OK);
    rtest_measure(a, &qa);
    rtest_measure(u, &qu);
    ck_assert_int_eq(cvm_mesh_check(a), CVM_OK);
    ck_assert(qa.max_circumradius <= 1.0 / 20 * (1 + 1e-9));
    ck_assert(qa.min_angle >= 30 - 1e-9);
    ck_assert(fabs((double)qa.nt - (double)qu.nt) <= 0.1 * (double)qu.nt);
    cvm_sizing_free(s);
    cvm_mesh_free(a);
    cvm_mesh_free(u);
}
END_TEST

/* Annulus r = 1..4: the inner circle has radius of curvature 1 (its 64-gon
 * turns 5.6 degrees a vertex), the outer circle's feature size is the gap 3;
 * so with R = 3, G = 4 the size is about 1/3 at r = 1 and grows by 1/4 per
 * unit towards 1 at r = 4. Measured on the output: the mean edge near the
 * inner circle is about 1/3 and at least twice as short as near the outer one;
 * the mesh is valid, meets 30 degrees and is reproducible. */
START_TEST(automatic_annulus_follows_curvature_and_gap)
{
    char path[512];
    cvm_mesh *m, *m2;
    cvm_sizing *s;
    rtest_quality q;
    double inner, outer;
    rtest_data_path(path, sizeof path, "annulus.poly");
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_automatic(s, 3, 4), CVM_OK);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_read(m, path), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_refine(m, s, CVM_ALGO_FRONTAL), CVM_OK);
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    rtest_measure(m, &q);
    ck_assert(q.min_angle >= 30 - 1e-9);
    /* near the boundaries the input polylines (spacing 0.098 and 0.196) bound the
       edges; in between the size grows from about 0.4 at r = 1.3 to 0.9 at r = 3.3 */
    inner = mean_edge_in_ring(m, 0, 0, 1.2, 1.5);
    outer = mean_edge_in_ring(m, 0, 0, 3.0, 3.5);
    ck_assert(inner > 0.1 && inner < 0.6);
    ck_assert(outer > 1.5 * inner);
    ck_assert_int_eq(cvm_mesh_create(&m2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_read(m2, path), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_refine(m2, s, CVM_ALGO_FRONTAL), CVM_OK);
    rtest_assert_identical(m, m2);
    cvm_sizing_free(s);
    cvm_mesh_free(m);
    cvm_mesh_free(m2);
}
END_TEST

/* A slot 0.05 wide cut into a unit square: the feature size across the slot
 * is 0.05, so the automatic size resolves it (edges near the slot about
 * 0.05/R) while the far corner stays coarse; the two slot walls are not
 * incident, so the slot is not skipped as one feature. */
START_TEST(automatic_resolves_a_narrow_slot)
{
    static const double xy[] = {0, 0, 1, 0, 1, 1, 0.525, 1, 0.525, 0.3, 0.475, 0.3, 0.475, 1, 0, 1};
    static const cvm_index seg[] = {0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 0};
    cvm_mesh *m;
    cvm_sizing *s;
    rtest_quality q;
    double slot, corner;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 8, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, seg, 8), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_automatic(s, 2, 5), CVM_OK);
    ck_assert_int_eq(cvm_mesh_refine(m, s, CVM_ALGO_DELAUNAY), CVM_OK);
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    rtest_measure(m, &q);
    ck_assert(q.min_angle >= 30 - 1e-9);
    slot = mean_edge_in_ring(m, 0.5, 0.65, 0, 0.1);
    corner = mean_edge_in_ring(m, 0, 0, 0, 0.15);
    ck_assert(slot < 0.05);
    ck_assert(corner > 2 * slot);
    cvm_sizing_free(s);
    cvm_mesh_free(m);
}
END_TEST

/* Out of memory while the automatic field is built: a status, the mesh still
 * valid, no leak (the counting allocator checks live blocks). */
START_TEST(automatic_out_of_memory_is_a_status)
{
    char path[512];
    cvm_sizing *s;
    long k;
    int hit = 0;
    rtest_data_path(path, sizeof path, "annulus.poly");
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_automatic(s, 1, 4), CVM_OK);
    for (k = 1; k < 200; k += 2) {
        cvmtest_alloc al;
        cvm_mesh *m;
        cvm_status st;
        cvmtest_alloc_init(&al, 0, 0);
        ck_assert_int_eq(cvmtest_mesh_create(&m, &al), CVM_OK);
        ck_assert_int_eq(cvm_mesh_read(m, path), CVM_OK);
        ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
        cvmtest_alloc_arm(&al, k, 0); /* transient: only allocation k fails */
        st = cvm_mesh_refine(m, s, CVM_ALGO_DELAUNAY);
        ck_assert(st == CVM_OK || st == CVM_E_NOMEM);
        if (st == CVM_E_NOMEM) {
            hit++;
            cvmtest_alloc_arm(&al, 0, 0);
            /* valid, or dropped as a whole when the vertex data could not follow */
            st = cvm_mesh_check(m);
            ck_assert(st == CVM_OK || st == CVM_E_STATE);
        }
        cvm_mesh_free(m);
        ck_assert_int_eq(al.live_blocks, 0);
    }
    ck_assert_int_gt(hit, 0);
    cvm_sizing_free(s);
}
END_TEST

/* ---- boundary grading (cvm_sizing_set_boundary_grading) ---- */

START_TEST(boundary_grading_parameters_are_checked)
{
    cvm_sizing *s;
    double h;
    ck_assert_int_eq(cvm_sizing_set_boundary_grading(NULL, 0.3), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_boundary_grading(s, NAN), CVM_E_INPUT_NONFINITE);
    ck_assert_int_eq(cvm_sizing_set_boundary_grading(s, INFINITY), CVM_E_INPUT_NONFINITE);
    ck_assert_int_eq(cvm_sizing_set_boundary_grading(s, -0.5), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "boundary grading"));
    ck_assert_int_eq(cvm_sizing_set_boundary_grading(s, 0.3), CVM_OK);
    /* no domain here: the field is built by refine and optimise only */
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 0.5, 0.5), CVM_OK);
    ck_assert(isinf(h));
    ck_assert_int_eq(cvm_sizing_set_boundary_grading(s, 0), CVM_OK); /* off again */
    cvm_sizing_free(s);
}
END_TEST

/* The unit square with its bottom side given as 100 segments of 0.01: the size
 * the test expects (its own computation, no library code) is
 *   h(p) = min(0.25, min over the bottom points v of 0.01 + 0.3 |p - v|)
 * (the other sides are 1 long and never beat 0.25). */
#define BG_N 100
#define BG_H 0.25
#define BG_G 0.3

/* The unit square, its bottom side in n segments. */
static void bg_square_n(cvm_mesh *m, size_t n_bottom)
{
    double xy[2 * (BG_N + 3)];
    cvm_index seg[2 * (BG_N + 3)];
    size_t i, n = n_bottom + 3;
    ck_assert_uint_le(n_bottom, BG_N);
    for (i = 0; i <= n_bottom; i++) {
        xy[2 * i] = (double)i / (double)n_bottom;
        xy[2 * i + 1] = 0;
    }
    xy[2 * (n_bottom + 1)] = 1;
    xy[2 * (n_bottom + 1) + 1] = 1;
    xy[2 * (n_bottom + 2)] = 0;
    xy[2 * (n_bottom + 2) + 1] = 1;
    for (i = 0; i < n; i++) {
        seg[2 * i] = (cvm_index)i;
        seg[2 * i + 1] = (cvm_index)((i + 1) % n);
    }
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, n, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, seg, n), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
}

static void bg_square(cvm_mesh *m)
{
    bg_square_n(m, BG_N);
}

static double bg_expected(const double *p)
{
    double best = BG_H;
    int i;
    for (i = 0; i <= BG_N; i++) {
        double d = 1.0 / BG_N + BG_G * hypot(p[0] - (double)i / BG_N, p[1]);
        best = d < best ? d : best;
    }
    return best;
}

/* Triangles that break their algorithm's size rule against the expected sizes
 * of their corners (frontal and AFLR: mean edge <= 1.5 x the largest of them;
 * Delaunay: circumradius <= the largest), or that lie along the fine side
 * (centroid below 0.1) with a mean edge of 0.08 or more. */
static size_t bg_violations(cvm_mesh *m, cvm_algorithm algo)
{
    size_t nv, nt, t, bad = 0;
    double *xy;
    cvm_index *tri;
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    xy = malloc(2 * nv * sizeof *xy);
    tri = malloc(3 * nt * sizeof *tri);
    ck_assert_int_eq(cvm_mesh_copy_points(xy, 2 * nv, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(tri, 3 * nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    for (t = 0; t < nt; t++) {
        const double *a = xy + 2 * tri[3 * t], *b = xy + 2 * tri[3 * t + 1], *c = xy + 2 * tri[3 * t + 2];
        double la = hypot(b[0] - c[0], b[1] - c[1]), lb = hypot(a[0] - c[0], a[1] - c[1]);
        double lc = hypot(a[0] - b[0], a[1] - b[1]);
        double area = 0.5 * fabs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
        double hmax = fmax(bg_expected(a), fmax(bg_expected(b), bg_expected(c)));
        if (algo == CVM_ALGO_DELAUNAY ? la * lb * lc / (4 * area) > hmax * (1 + 1e-9)
                                      : (la + lb + lc) / 3 > 1.5 * hmax * (1 + 1e-9))
            bad++;
        else if ((a[1] + b[1] + c[1]) / 3 < 0.1 && (la + lb + lc) / 3 >= 0.08)
            bad++;
    }
    free(xy);
    free(tri);
    return bad;
}

START_TEST(boundary_grading_follows_the_wall_spacing)
{
    static const cvm_algorithm algos[] = {CVM_ALGO_DELAUNAY, CVM_ALGO_FRONTAL, CVM_ALGO_AFLR};
    size_t k;
    for (k = 0; k < 3; k++) {
        cvm_mesh *m, *u, *m2;
        cvm_sizing *s;
        ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
        ck_assert_int_eq(cvm_sizing_set_uniform(s, BG_H), CVM_OK);
        ck_assert_int_eq(cvm_mesh_create(&u), CVM_OK);
        bg_square(u);
        ck_assert_int_eq(cvm_mesh_refine(u, s, algos[k]), CVM_OK);
        /* without the grading the size jumps to 0.25 a few layers off the wall */
        ck_assert_uint_gt(bg_violations(u, algos[k]), 0);
        ck_assert_int_eq(cvm_sizing_set_boundary_grading(s, BG_G), CVM_OK);
        ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
        bg_square(m);
        ck_assert_int_eq(cvm_mesh_refine(m, s, algos[k]), CVM_OK);
        ck_assert_uint_eq(bg_violations(m, algos[k]), 0);
        ck_assert_int_eq(cvm_mesh_create(&m2), CVM_OK);
        bg_square(m2);
        ck_assert_int_eq(cvm_mesh_refine(m2, s, algos[k]), CVM_OK);
        rtest_assert_identical(m, m2);
        cvm_sizing_free(s);
        cvm_mesh_free(m);
        cvm_mesh_free(m2);
        cvm_mesh_free(u);
    }
}
END_TEST

/* cvm_mesh_optimise_dual() builds the field from its own mesh: with the
 * graded sizing it ends compliant and valid. */
START_TEST(boundary_grading_drives_the_dual_optimiser)
{
    cvm_mesh *m;
    cvm_sizing *s;
    double nc = -1;
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_uniform(s, BG_H), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_boundary_grading(s, BG_G), CVM_OK);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    bg_square(m);
    ck_assert_int_eq(cvm_mesh_refine(m, s, CVM_ALGO_FRONTAL), CVM_OK);
    ck_assert_int_eq(cvm_mesh_optimise_dual(m, s), CVM_OK);
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_measure(&nc, m, CVM_MEASURE_DUAL_NONCOMPLIANT_PCT), CVM_OK);
    ck_assert(nc == 0);
    cvm_sizing_free(s);
    cvm_mesh_free(m);
}
END_TEST

/* Out of memory at every allocation while the field is built and used
 * (refine, then optimise on a refined mesh): a status, the mesh valid, no leak. */
typedef struct bg_oom {
    cvm_sizing *s;
    int optimise;
} bg_oom;

static void bg_oom_setup(cvm_mesh *m, void *arg)
{
    const bg_oom *o = arg;
    bg_square_n(m, 10); /* small: the sweep runs the call once per allocation */
    if (o->optimise)
        ck_assert_int_eq(cvm_mesh_refine(m, o->s, CVM_ALGO_FRONTAL), CVM_OK);
}

static cvm_status bg_oom_run(cvm_mesh *m, void *arg)
{
    const bg_oom *o = arg;
    return o->optimise ? cvm_mesh_optimise_dual(m, o->s) : cvm_mesh_refine(m, o->s, CVM_ALGO_FRONTAL);
}

START_TEST(boundary_grading_out_of_memory_is_a_status)
{
    bg_oom o;
    ck_assert_int_eq(cvm_sizing_create(&o.s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_uniform(o.s, BG_H), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_boundary_grading(o.s, BG_G), CVM_OK);
    for (o.optimise = 0; o.optimise < 2; o.optimise++)
        cvmtest_oom_sweep(bg_oom_setup, bg_oom_run, NULL, &o);
    cvm_sizing_free(o.s);
}
END_TEST

/* ---- background mesh (sizing_background.c) ---- */

static const double bg_xyh[] = {0, 0, 1, 2, 0, 3, 2, 2, 7, 0, 2, 5};
static const cvm_index bg_tri[] = {0, 1, 2, 0, 3, 2}; /* second one clockwise */

START_TEST(background_interpolates_linearly)
{
    cvm_sizing *s;
    double h;
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_background(s, bg_xyh, 4, bg_tri, 2), CVM_OK);
    /* h = 1 + x + 2y on the square [0,2]^2 is reproduced exactly by linear pieces */
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 0.3, 0.4), CVM_OK);
    ck_assert_double_eq_tol(h, 1 + 0.3 + 0.8, 1e-12);
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 1.5, 0.25), CVM_OK);
    ck_assert_double_eq_tol(h, 1 + 1.5 + 0.5, 1e-12);
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 2, 2), CVM_OK); /* a node */
    ck_assert_double_eq_tol(h, 7, 1e-12);
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 2.5, 1), CVM_OK); /* outside: no bound */
    ck_assert(isinf(h));
    /* combined with a uniform size by the minimum */
    ck_assert_int_eq(cvm_sizing_set_uniform(s, 2.0), CVM_OK);
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 1.5, 0.25), CVM_OK);
    ck_assert_double_eq_tol(h, 2.0, 1e-15);
    /* removed */
    ck_assert_int_eq(cvm_sizing_set_background(s, NULL, 0, NULL, 0), CVM_OK);
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 0.3, 0.4), CVM_OK);
    ck_assert_double_eq_tol(h, 2.0, 1e-15);
    cvm_sizing_free(s);
}
END_TEST

START_TEST(background_bad_input_is_named)
{
    cvm_sizing *s;
    double bad[12];
    cvm_index badtri[6];
    double h;
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_background(s, bg_xyh, 4, bg_tri, 2), CVM_OK);
    memcpy(bad, bg_xyh, sizeof bad);
    bad[7] = NAN;
    ck_assert_int_eq(cvm_sizing_set_background(s, bad, 4, bg_tri, 2), CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "node 2"));
    memcpy(bad, bg_xyh, sizeof bad);
    bad[11] = 0;
    ck_assert_int_eq(cvm_sizing_set_background(s, bad, 4, bg_tri, 2), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "node 3"));
    memcpy(badtri, bg_tri, sizeof badtri);
    badtri[4] = 4;
    ck_assert_int_eq(cvm_sizing_set_background(s, bg_xyh, 4, badtri, 2), CVM_E_INPUT_INDEX);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "triangle 1"));
    memcpy(badtri, bg_tri, sizeof badtri);
    badtri[5] = 0;
    ck_assert_int_eq(cvm_sizing_set_background(s, bg_xyh, 4, badtri, 2), CVM_E_INPUT_DEGENERATE);
    ck_assert_ptr_nonnull(strstr(cvm_sizing_errmsg(s), "triangle 1"));
    /* the earlier background is untouched by the failures */
    ck_assert_int_eq(cvm_sizing_eval(&h, s, 0.3, 0.4), CVM_OK);
    ck_assert_double_eq_tol(h, 2.1, 1e-12);
    cvm_sizing_free(s);
}
END_TEST

/* Refinement with a background size: edges near the small-size corner are
 * shorter than near the large-size corner. */
START_TEST(background_drives_refinement)
{
    static const double xyh[] = {0, 0, 0.05, 1, 0, 0.3, 1, 1, 0.3, 0, 1, 0.3};
    static const cvm_index tri[] = {0, 1, 2, 0, 2, 3};
    char path[512];
    cvm_mesh *m;
    cvm_sizing *s;
    rtest_quality q;
    rtest_data_path(path, sizeof path, "square.poly");
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_read(m, path), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_background(s, xyh, 4, tri, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_refine(m, s, CVM_ALGO_FRONTAL), CVM_OK);
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    rtest_measure(m, &q);
    ck_assert(q.min_angle >= 30 - 1e-9);
    ck_assert(2 * mean_edge_in_ring(m, 0, 0, 0, 0.15) < mean_edge_in_ring(m, 1, 1, 0, 0.3));
    cvm_sizing_free(s);
    cvm_mesh_free(m);
}
END_TEST

TCase *refine_sizing_tcase(void)
{
    TCase *tc = tcase_create("sizing");
    tcase_add_test(tc, empty_sizing_has_no_bound);
    tcase_add_test(tc, sources_combine_by_minimum);
    tcase_add_test(tc, callback_is_called_with_payload);
    tcase_add_test(tc, bad_sizes_are_rejected_and_named);
    tcase_add_test(tc, bad_callback_values_stop_eval_and_refine);
    tcase_add_test(tc, null_arguments_and_unsupported);
    tcase_add_test(tc, automatic_parameters_are_checked);
    tcase_add_test(tc, automatic_square_matches_uniform_side_over_r);
    tcase_add_test(tc, automatic_annulus_follows_curvature_and_gap);
    tcase_add_test(tc, automatic_resolves_a_narrow_slot);
    tcase_add_test(tc, automatic_out_of_memory_is_a_status);
    tcase_add_test(tc, boundary_grading_parameters_are_checked);
    tcase_add_test(tc, boundary_grading_follows_the_wall_spacing);
    tcase_add_test(tc, boundary_grading_drives_the_dual_optimiser);
    tcase_add_test(tc, boundary_grading_out_of_memory_is_a_status);
    tcase_add_test(tc, background_interpolates_linearly);
    tcase_add_test(tc, background_bad_input_is_named);
    tcase_add_test(tc, background_drives_refinement);
    /* the out-of-memory sweeps rebuild the field once per allocation: about 1 s
       of CPU, more under ASan or on a loaded machine */
    tcase_set_timeout(tc, 60);
    return tc;
}
