/* test_build.c - Delaunay triangulation of point sets (lib/delaunay/build.c, insert.c, locate.c, spatial_sort.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay_tests.h"
#include "support/mesh_oracle.h"

/* Triangles of a Delaunay triangulation of n points with h on the hull: 2n - 2 - h. */
static void assert_point_set_mesh(cvm_mesh *m, size_t n_distinct)
{
    size_t nt, ne, nv;
    cvmtest_assert_valid(m);
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_uint_eq(nv, n_distinct);
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&ne, m, CVM_ENT_EDGE), CVM_OK);
    /* Euler: V - E + F = 1 for a triangulated disc */
    ck_assert_int_eq((long)nv - (long)ne + (long)nt, 1);
}

static cvm_mesh *mesh_of(const double *xy, size_t n, double seed)
{
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, n, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_SEED, seed), CVM_OK);
    ck_assert_msg(cvm_mesh_triangulate(m) == CVM_OK, "triangulate: %s", cvm_mesh_errmsg(m));
    return m;
}

START_TEST(random_points_are_delaunay)
{
    size_t n = 20000;
    double *xy = malloc(2 * n * sizeof *xy);
    cvm_mesh *m;
    dtest_random_points(xy, n, 7);
    m = mesh_of(xy, n, 1);
    assert_point_set_mesh(m, n);
    cvm_mesh_free(m);
    free(xy);
}
END_TEST

/* Points on an exact integer lattice: every square's four corners are cocircular. */
static double *lattice(size_t k, double spacing, double jitter)
{
    double *xy = malloc(2 * k * k * sizeof *xy);
    size_t i, j;
    for (i = 0; i < k; i++)
        for (j = 0; j < k; j++) {
            xy[2 * (i * k + j)] = (double)j * spacing;
            xy[2 * (i * k + j) + 1] = (double)i * spacing;
            if (jitter != 0) {
                xy[2 * (i * k + j)] += jitter * (double)(((i * 7 + j * 13) % 11) - 5);
                xy[2 * (i * k + j) + 1] += jitter * (double)(((i * 3 + j * 5) % 7) - 3);
            }
        }
    return xy;
}

START_TEST(cocircular_lattice_is_consistent_for_any_insertion_order)
{
    size_t k = 60, n = k * k, nt0, nt;
    double *xy = lattice(k, 1.0, 0);
    cvm_index *t0, *t;
    double seeds[3] = {1, 2, 12345};
    int s;
    cvm_mesh *m = mesh_of(xy, n, seeds[0]);
    assert_point_set_mesh(m, n);
    t0 = dtest_triangles(m, &nt0);
    ck_assert_uint_eq(nt0, 2 * (k - 1) * (k - 1));
    dtest_canonical(t0, nt0);
    cvm_mesh_free(m);
    /* symbolic perturbation by index makes the triangulation unique */
    for (s = 1; s < 3; s++) {
        m = mesh_of(xy, n, seeds[s]);
        assert_point_set_mesh(m, n);
        t = dtest_triangles(m, &nt);
        dtest_canonical(t, nt);
        ck_assert_uint_eq(nt, nt0);
        ck_assert_int_eq(memcmp(t, t0, 3 * nt * sizeof *t), 0);
        free(t);
        cvm_mesh_free(m);
    }
    free(t0);
    free(xy);
}
END_TEST

/* The same cocircular lattice with 300 exact copies of its points, shuffled so that copies come
 * before their originals: the first of a group to be inserted depends on the seed, the
 * triangles do not (each group's vertex takes the lowest index of the group in the
 * perturbation). */
START_TEST(duplicates_on_a_cocircular_lattice_are_consistent_for_any_seed)
{
    size_t k = 30, ng = k * k, nd = 300, n = ng + nd, i, nt0, nt;
    double *g = lattice(k, 1.0, 0), *xy = malloc(2 * n * sizeof *xy);
    double seeds[3] = {1, 3, 99};
    uint64_t r = 777;
    cvm_index *t0 = NULL, *t;
    int s;
    memcpy(xy, g, 2 * ng * sizeof *xy);
    for (i = ng; i < n; i++) {
        r ^= r << 13, r ^= r >> 7, r ^= r << 17;
        memcpy(xy + 2 * i, g + 2 * (size_t)(r % ng), 2 * sizeof *xy);
    }
    for (i = n - 1; i > 0; i--) {
        size_t j;
        double tx, ty;
        r ^= r << 13, r ^= r >> 7, r ^= r << 17;
        j = (size_t)(r % (i + 1));
        tx = xy[2 * i], ty = xy[2 * i + 1];
        xy[2 * i] = xy[2 * j], xy[2 * i + 1] = xy[2 * j + 1];
        xy[2 * j] = tx, xy[2 * j + 1] = ty;
    }
    for (s = 0; s < 3; s++) {
        cvm_mesh *m = mesh_of(xy, n, seeds[s]);
        t = dtest_triangles(m, &nt);
        dtest_canonical(t, nt);
        ck_assert_uint_eq(nt, 2 * (k - 1) * (k - 1));
        if (s == 0) {
            t0 = t;
            nt0 = nt;
        } else {
            ck_assert_uint_eq(nt, nt0);
            ck_assert_msg(memcmp(t, t0, 3 * nt * sizeof *t) == 0, "seed %g: other triangles",
                          seeds[s]);
            free(t);
        }
        cvm_mesh_free(m);
    }
    free(t0);
    free(xy);
    free(g);
}
END_TEST

START_TEST(lattice_one_ulp_off_is_delaunay)
{
    size_t k = 40, n = k * k, i;
    double *xy = lattice(k, 1.0, 0);
    cvm_mesh *m;
    for (i = 0; i < 2 * n; i++)
        xy[i] += 1.0; /* one ulp off 0 would be a denormal, outside the exact range */
    for (i = 0; i < n; i += 3)
        xy[2 * i] = nextafter(xy[2 * i], 1e9);
    for (i = 1; i < n; i += 5)
        xy[2 * i + 1] = nextafter(xy[2 * i + 1], -1e9);
    m = mesh_of(xy, n, 3);
    assert_point_set_mesh(m, n);
    cvm_mesh_free(m);
    free(xy);
}
END_TEST

START_TEST(huge_and_tiny_scales)
{
    double scales[4] = {1e-300, 1e-150, 1e150, 1e300};
    size_t n = 2000, i;
    int s;
    double *xy = malloc(2 * n * sizeof *xy);
    for (s = 0; s < 4; s++) {
        cvm_mesh *m;
        dtest_random_points(xy, n, 11);
        for (i = 0; i < 2 * n; i++)
            xy[i] *= scales[s];
        m = mesh_of(xy, n, 1);
        assert_point_set_mesh(m, n);
        cvm_mesh_free(m);
    }
    free(xy);
}
END_TEST

START_TEST(points_on_a_line_then_one_off)
{
    /* 50 collinear points and one apex: a fan of 49 triangles */
    double xy[2 * 51];
    size_t i, nt;
    cvm_mesh *m;
    for (i = 0; i < 50; i++) {
        xy[2 * i] = (double)i;
        xy[2 * i + 1] = 3.0 * (double)i;
    }
    xy[100] = 10.0;
    xy[101] = 50.0;
    m = mesh_of(xy, 51, 1);
    assert_point_set_mesh(m, 51);
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_uint_eq(nt, 49);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(all_collinear_is_degenerate)
{
    double xy[20];
    size_t i, nt = 7;
    cvm_mesh *m;
    for (i = 0; i < 10; i++) {
        xy[2 * i] = (double)i;
        xy[2 * i + 1] = 2.0 * (double)i + 1.0;
    }
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 10, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_E_INPUT_DEGENERATE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "collinear"));
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_uint_eq(nt, 0);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 2, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_E_INPUT_DEGENERATE);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 0, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_E_INPUT_EMPTY);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(duplicates_are_merged_and_mapped)
{
    /* 4 corners of a square, each given twice, plus the centre given three times */
    double xy[] = {0, 0, 1, 0, 1, 1, 0, 1, 1, 0, 0.5, 0.5, 0, 0, 0.5, 0.5, 1, 1, 0, 1, 0.5, 0.5};
    size_t n = sizeof xy / sizeof xy[0] / 2, nd, nv, i;
    cvm_index map[11];
    double pts[10];
    cvm_mesh *m = mesh_of(xy, n, 1);
    ck_assert_int_eq(cvm_mesh_count(&nd, m, CVM_ENT_DUPLICATE), CVM_OK);
    ck_assert_uint_eq(nd, 6);
    assert_point_set_mesh(m, 5);
    ck_assert_int_eq(cvm_mesh_copy_input_map(map, n, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_points(pts, 2 * nv, m), CVM_OK);
    /* first occurrences keep their order: 0,1,2,3,5 -> 0..4 */
    ck_assert_int_eq(map[0], 0);
    ck_assert_int_eq(map[5], 4);
    for (i = 0; i < n; i++) {
        ck_assert(pts[2 * map[i]] == xy[2 * i]);
        ck_assert(pts[2 * map[i] + 1] == xy[2 * i + 1]);
    }
    cvm_mesh_free(m);
}
END_TEST

START_TEST(duplicates_rejected_when_asked)
{
    double xy[] = {0, 0, 1, 0, 0, 1, 1, 0};
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 4, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_REJECT_DUPLICATES, 1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_E_INPUT_DUPLICATE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "point 3"));
    cvm_mesh_free(m);
}
END_TEST

START_TEST(nonfinite_points_are_rejected_by_index)
{
    double xy[] = {0, 0, 1, 0, 0, 1, NAN, 2, 3, INFINITY};
    cvm_mesh *m;
    cvm_entity kind;
    int64_t idx;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 5, 2), CVM_E_INPUT_NONFINITE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "point 3"));
    ck_assert_int_eq(cvm_mesh_error_item(&kind, &idx, m), CVM_OK);
    ck_assert_int_eq(kind, CVM_ENT_INPUT_POINT);
    ck_assert_int_eq(idx, 3);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(output_is_reproducible)
{
    size_t n = 5000, nt1, nt2;
    double *xy = malloc(2 * n * sizeof *xy);
    cvm_index *a, *b;
    cvm_mesh *m1, *m2;
    dtest_random_points(xy, n, 99);
    m1 = mesh_of(xy, n, 5);
    m2 = mesh_of(xy, n, 5);
    a = dtest_triangles(m1, &nt1);
    b = dtest_triangles(m2, &nt2);
    ck_assert_uint_eq(nt1, nt2);
    ck_assert_int_eq(memcmp(a, b, 3 * nt1 * sizeof *a), 0);
    free(a);
    free(b);
    cvm_mesh_free(m1);
    cvm_mesh_free(m2);
    free(xy);
}
END_TEST

START_TEST(coordinates_beyond_exact_range_are_refused)
{
    double xy[] = {1e-300, -1e-300, 1e300, 0, 150, 2.5e-3, 0, 7};
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 4, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_E_INPUT_DEGENERATE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "point 0"));
    /* tiny but within range next to unit coordinates is fine */
    xy[0] = 1e-40;
    xy[1] = -1e-40;
    xy[2] = 1;
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 4, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    cvmtest_assert_valid(m);
    cvm_mesh_free(m);
}
END_TEST

static int cancel_at(void *payload, cvm_stage stage, double fraction)
{
    int *calls = payload;
    (void)stage;
    (void)fraction;
    return ++*calls >= 3;
}

START_TEST(cancel_leaves_an_empty_mesh)
{
    size_t n = 20000, nt = 1;
    int calls = 0;
    double *xy = malloc(2 * n * sizeof *xy);
    cvm_mesh *m;
    dtest_random_points(xy, n, 3);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, n, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_progress(m, cancel_at, 100, &calls), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_INCOMPLETE_CANCELLED);
    ck_assert_int_eq(calls, 3);
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_uint_eq(nt, 0);
    /* the handle is reusable */
    ck_assert_int_eq(cvm_mesh_set_progress(m, NULL, 0, NULL), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    cvmtest_assert_valid(m);
    cvm_mesh_free(m);
    free(xy);
}
END_TEST

TCase *delaunay_build_tcase(void)
{
    TCase *tc = tcase_create("build");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, random_points_are_delaunay);
    tcase_add_test(tc, cocircular_lattice_is_consistent_for_any_insertion_order);
    tcase_add_test(tc, duplicates_on_a_cocircular_lattice_are_consistent_for_any_seed);
    tcase_add_test(tc, lattice_one_ulp_off_is_delaunay);
    tcase_add_test(tc, huge_and_tiny_scales);
    tcase_add_test(tc, points_on_a_line_then_one_off);
    tcase_add_test(tc, all_collinear_is_degenerate);
    tcase_add_test(tc, duplicates_are_merged_and_mapped);
    tcase_add_test(tc, duplicates_rejected_when_asked);
    tcase_add_test(tc, nonfinite_points_are_rejected_by_index);
    tcase_add_test(tc, output_is_reproducible);
    tcase_add_test(tc, coordinates_beyond_exact_range_are_refused);
    tcase_add_test(tc, cancel_leaves_an_empty_mesh);
    return tc;
}
