/* test_frontal.c - frontal-Delaunay refinement (lib/refine/frontal.c) through cvm_mesh_refine. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "refine/refine_tests.h"
#include "support/mesh_oracle.h"

void rtest_small_angle_terminates(cvm_algorithm algo, double angle, double h);
void rtest_jagged_star(cvm_algorithm algo, unsigned long seed);

START_TEST(square_meets_angle_and_size)
{
    rtest_shared_geometry("square.poly", 0.03, 1, CVM_ALGO_FRONTAL);
}
END_TEST

START_TEST(channel_meets_angle_and_size)
{
    rtest_shared_geometry("channel.poly", 0.05, 1, CVM_ALGO_FRONTAL);
}
END_TEST

START_TEST(annulus_meets_angle_and_size)
{
    rtest_shared_geometry("annulus.poly", 0.2, 0, CVM_ALGO_FRONTAL);
}
END_TEST

START_TEST(cylinder_meets_angle_and_size)
{
    rtest_shared_geometry("cylinder.poly", 0.5, 0, CVM_ALGO_FRONTAL);
}
END_TEST

START_TEST(naca0012_meets_angle_and_size)
{
    rtest_shared_geometry("naca0012.poly", 0.5, 0, CVM_ALGO_FRONTAL);
}
END_TEST

START_TEST(three_degree_wedge_terminates)
{
    rtest_small_angle_terminates(CVM_ALGO_FRONTAL, 3.0, 0.01);
}
END_TEST

START_TEST(jagged_star_terminates)
{
    rtest_jagged_star(CVM_ALGO_FRONTAL, 7);
    rtest_jagged_star(CVM_ALGO_FRONTAL, 8);
}
END_TEST

/* Frontal placement gives more regular meshes than circumcentres on the square. */
START_TEST(frontal_is_more_regular_than_delaunay)
{
    static const double sq[] = {0, 0, 1, 0, 1, 1, 0, 1};
    static const cvm_index seg[] = {0, 1, 1, 2, 2, 3, 3, 0};
    double reg[2];
    int k;
    for (k = 0; k < 2; k++) {
        cvm_mesh *m;
        ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
        ck_assert_int_eq(cvm_mesh_set_points(m, sq, 4, 2), CVM_OK);
        ck_assert_int_eq(cvm_mesh_set_segments(m, seg, 4), CVM_OK);
        ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
        ck_assert_int_eq(rtest_refine_uniform(m, 0.03, k ? CVM_ALGO_FRONTAL : CVM_ALGO_DELAUNAY), CVM_OK);
        ck_assert_int_eq(cvm_mesh_get_measure(&reg[k], m, CVM_MEASURE_REGULAR_PCT), CVM_OK);
        cvm_mesh_free(m);
    }
    ck_assert_double_gt(reg[1], reg[0] + 30);
}
END_TEST

/* Regularity measured here from the output: % of angles in [55, 65] degrees,
 * % of triangles with an angle above 90 degrees, and % of interior vertices
 * (on no edge that only one triangle has) with 6 edges. */
typedef struct fr_regularity {
    double reg, obtuse, deg6, min_edge;
} fr_regularity;

static int cmp_edge(const void *a, const void *b)
{
    const cvm_index *x = a, *y = b;
    return x[0] != y[0] ? (x[0] > y[0]) - (x[0] < y[0]) : (x[1] > y[1]) - (x[1] < y[1]);
}

static void fr_measure_regularity(cvm_mesh *m, fr_regularity *r)
{
    size_t nv, nt, t, i, in = 0, obt = 0, nint = 0, n6 = 0;
    double *xy;
    cvm_index *tri, *e;
    int *deg, *bnd, k;
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    xy = malloc(2 * nv * sizeof *xy + 1);
    tri = malloc(3 * nt * sizeof *tri + 1);
    e = malloc(6 * nt * sizeof *e + 1);
    deg = calloc(nv + 1, sizeof *deg);
    bnd = calloc(nv + 1, sizeof *bnd);
    ck_assert(xy && tri && e && deg && bnd);
    ck_assert_int_eq(cvm_mesh_copy_points(xy, 2 * nv, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(tri, 3 * nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    for (t = 0; t < nt; t++) {
        double amax = 0;
        for (k = 0; k < 3; k++) {
            const double *o = xy + 2 * (size_t)tri[3 * t + (size_t)k];
            const double *a = xy + 2 * (size_t)tri[3 * t + (size_t)(k + 1) % 3];
            const double *b = xy + 2 * (size_t)tri[3 * t + (size_t)(k + 2) % 3];
            double ux = a[0] - o[0], uy = a[1] - o[1], wx = b[0] - o[0], wy = b[1] - o[1];
            double ang = atan2(fabs(ux * wy - uy * wx), ux * wx + uy * wy) * 180 / 3.14159265358979323846;
            cvm_index p = tri[3 * t + (size_t)k], q = tri[3 * t + (size_t)(k + 1) % 3];
            in += ang >= 55 && ang <= 65;
            if (ang > amax)
                amax = ang;
            e[6 * t + 2 * (size_t)k] = p < q ? p : q;
            e[6 * t + 2 * (size_t)k + 1] = p < q ? q : p;
        }
        obt += amax > 90;
    }
    r->min_edge = HUGE_VAL;
    for (i = 0; i < 3 * nt; i++) {
        const double *a = xy + 2 * (size_t)e[2 * i], *b = xy + 2 * (size_t)e[2 * i + 1];
        double l = hypot(b[0] - a[0], b[1] - a[1]);
        if (l < r->min_edge)
            r->min_edge = l;
    }
    qsort(e, 3 * nt, 2 * sizeof *e, cmp_edge);
    for (i = 0; i < 3 * nt;) {
        size_t j = i + 1;
        while (j < 3 * nt && e[2 * j] == e[2 * i] && e[2 * j + 1] == e[2 * i + 1])
            j++;
        deg[e[2 * i]]++;
        deg[e[2 * i + 1]]++;
        if (j - i == 1)
            bnd[e[2 * i]] = bnd[e[2 * i + 1]] = 1;
        i = j;
    }
    for (i = 0; i < nv; i++)
        if (deg[i] > 0 && !bnd[i]) {
            nint++;
            n6 += deg[i] == 6;
        }
    r->reg = 100.0 * (double)in / (3.0 * (double)nt);
    r->obtuse = 100.0 * (double)obt / (double)nt;
    r->deg6 = nint ? 100.0 * (double)n6 / (double)nint : 0;
    free(xy);
    free(tri);
    free(e);
    free(deg);
    free(bnd);
}

/* The targets at uniform size, on the shared square (5.8e3 triangles)
 * and annulus (1.1e4), measured here: angles in [55, 65] degrees >= 95% (square;
 * curved annulus >= 94%), obtuse triangles <= 0.5%, degree-6 interior vertices
 * >= 95% on the square; with the default swap, smoothing and Delaunay restoration.
 * No crowded points either: every edge at least half the size (measured 0.59 h). */
static void frontal_regularity(const char *name, double h, double min_reg, double max_obt,
                               double min_deg6)
{
    char path[1024];
    cvm_mesh *m;
    fr_regularity r;
    rtest_data_path(path, sizeof path, name);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_msg(cvm_mesh_read(m, path) == CVM_OK, "%s: %s", path, cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(rtest_refine_uniform(m, h, CVM_ALGO_FRONTAL), CVM_OK);
    fr_measure_regularity(m, &r);
    ck_assert_msg(r.reg >= min_reg, "%s: %.2f%% of angles in [55, 65] < %.1f", name, r.reg, min_reg);
    ck_assert_msg(r.obtuse <= max_obt, "%s: %.2f%% obtuse > %.1f", name, r.obtuse, max_obt);
    ck_assert_msg(r.deg6 >= min_deg6, "%s: %.2f%% degree 6 < %.1f", name, r.deg6, min_deg6);
    ck_assert_msg(r.min_edge >= 0.5 * h, "%s: shortest edge %.3g < h / 2", name, r.min_edge);
    cvm_mesh_free(m);
}

START_TEST(square_regularity_targets)
{
    frontal_regularity("square.poly", 0.02, 95.0, 0.5, 95.0);
}
END_TEST

START_TEST(annulus_regularity_targets)
{
    frontal_regularity("annulus.poly", 0.1, 94.0, 0.5, 94.0);
}
END_TEST

TCase *refine_frontal_tcase(void)
{
    TCase *tc = tcase_create("frontal");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, square_meets_angle_and_size);
    tcase_add_test(tc, channel_meets_angle_and_size);
    tcase_add_test(tc, annulus_meets_angle_and_size);
    tcase_add_test(tc, cylinder_meets_angle_and_size);
    tcase_add_test(tc, naca0012_meets_angle_and_size);
    tcase_add_test(tc, three_degree_wedge_terminates);
    tcase_add_test(tc, jagged_star_terminates);
    tcase_add_test(tc, frontal_is_more_regular_than_delaunay);
    tcase_add_test(tc, square_regularity_targets);
    tcase_add_test(tc, annulus_regularity_targets);
    return tc;
}
