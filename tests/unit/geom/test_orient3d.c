/* test_orient3d.c - orient3d has the exact sign on integers, coplanar lattices, near-planes and extreme scales. */
#include <math.h>

#include "geom/geom_internal.h"
#include "geom/geom_tests.h"

static void check_o3d(const double *a, const double *b, const double *c, const double *d)
{
    int want = oracle_orient3d(a, b, c, d);
    ck_assert_int_eq(geomtest_sign(cvm__orient3d(a, b, c, d)), want);
    ck_assert_int_eq(geomtest_sign(cvm__orient3d(b, c, a, d)), want);
    ck_assert_int_eq(geomtest_sign(cvm__orient3d(b, a, c, d)), -want);
    ck_assert_int_eq(geomtest_sign(cvm__orient3d(d, b, c, a)), -want);
}

START_TEST(orient3d_agrees_with_int64_on_small_integers)
{
    geomtest_rng r = { 51 };
    int i, j, k, zeros = 0;
    for (i = 0; i < 100000; i++) {
        int lim = (i % 2) ? 3 : 256;
        double p[4][3];
        int64_t want;
        for (j = 0; j < 4; j++)
            for (k = 0; k < 3; k++)
                p[j][k] = geomtest_int(&r, -lim, lim);
        want = intdet_orient3d(p[0], p[1], p[2], p[3]);
        zeros += want == 0;
        ck_assert_int_eq(geomtest_sign(cvm__orient3d(p[0], p[1], p[2], p[3])),
                         geomtest_sign64(want));
    }
    ck_assert_int_gt(zeros, 1000);
}
END_TEST

START_TEST(orient3d_sign_convention)
{
    double a[3] = { 0, 0, 0 }, b[3] = { 1, 0, 0 }, c[3] = { 0, 1, 0 };
    double below[3] = { 0.2, 0.2, -1.0 }, above[3] = { 0.2, 0.2, 1.0 }, on[3] = { 5, -3, 0 };
    ck_assert(cvm__orient3d(a, b, c, below) > 0.0);
    ck_assert(cvm__orient3d(a, b, c, above) < 0.0);
    ck_assert(cvm__orient3d(a, b, c, on) == 0.0);
}
END_TEST

/* d on the plane through a, b, c (rounded), nudged by a few ulps. */
static void near_plane(geomtest_rng *r, double scale, double shift, double (*p)[3])
{
    double s = geomtest_uniform(r, -1.0, 2.0), t = geomtest_uniform(r, -1.0, 2.0);
    int j, k;
    for (j = 0; j < 3; j++)
        for (k = 0; k < 3; k++)
            p[j][k] = shift + scale * geomtest_uniform(r, -1.0, 1.0);
    for (k = 0; k < 3; k++) {
        p[3][k] = p[0][k] + s * (p[1][k] - p[0][k]) + t * (p[2][k] - p[0][k]);
        p[3][k] = geomtest_ulps(p[3][k], (int)(geomtest_u64(r) % 3) - 1);
    }
}

START_TEST(orient3d_near_coplanar_doubles_match_the_oracle)
{
    geomtest_rng r = { 52 };
    int i;
    for (i = 0; i < 10000; i++) {
        double p[4][3];
        near_plane(&r, (i % 2) ? 1.0 : 1e-3, (i % 3) ? 0.0 : 1e3, p);
        check_o3d(p[0], p[1], p[2], p[3]);
    }
}
END_TEST

START_TEST(orient3d_coplanar_lattice_is_exactly_zero)
{
    /* integer points on x + 2y - 3z = 7 */
    geomtest_rng r = { 53 };
    int i, j;
    for (i = 0; i < 20000; i++) {
        double p[4][3];
        for (j = 0; j < 4; j++) {
            p[j][1] = geomtest_int(&r, -1000, 1000);
            p[j][2] = geomtest_int(&r, -1000, 1000);
            p[j][0] = 7.0 - 2.0 * p[j][1] + 3.0 * p[j][2];
        }
        ck_assert(cvm__orient3d(p[0], p[1], p[2], p[3]) == 0.0);
        p[3][0] = geomtest_ulps(p[3][0], 1);
        ck_assert_int_eq(geomtest_sign(cvm__orient3d(p[0], p[1], p[2], p[3])),
                         oracle_orient3d(p[0], p[1], p[2], p[3]));
    }
}
END_TEST

START_TEST(orient3d_huge_and_tiny_scales_keep_the_sign)
{
    double pow2[] = { 0x1p-1000, 0x1p-400, 0x1p300, 0x1p900 };
    double dec[] = { 1e-150, 1e150 };
    geomtest_rng r = { 54 };
    int i, k, j, m;
    for (i = 0; i < 2000; i++) {
        double p[4][3], s[4][3], v;
        int want;
        near_plane(&r, 1.0, 0.0, p);
        want = oracle_orient3d(p[0], p[1], p[2], p[3]);
        for (k = 0; k < 4; k++) {
            for (j = 0; j < 4; j++)
                for (m = 0; m < 3; m++)
                    s[j][m] = p[j][m] * pow2[k];
            v = cvm__orient3d(s[0], s[1], s[2], s[3]);
            ck_assert_int_eq(geomtest_sign(v), want);
            ck_assert(isfinite(v));
        }
        for (k = 0; k < 2; k++) {
            for (j = 0; j < 4; j++)
                for (m = 0; m < 3; m++)
                    s[j][m] = p[j][m] * dec[k];
            check_o3d(s[0], s[1], s[2], s[3]);
        }
    }
}
END_TEST

/* cvm__orient3d_sides gives the exact side of p for each face, on integers
 * (many exact zeros and filter failures), points on or just off one plane
 * and wide-range input. */
START_TEST(orient3d_sides_are_exact)
{
    geomtest_rng r = { 57 };
    int i, j, k, f;
    for (i = 0; i < 200000; i++) {
        double q[5][3], s[4][3];
        unsigned m;
        for (j = 0; j < 5; j++)
            for (k = 0; k < 3; k++) {
                double u = geomtest_uniform(&r, 0.0, 1.0);
                switch (i % 3) {
                case 0: q[j][k] = geomtest_int(&r, -3, 3); break;
                case 1: q[j][k] = ldexp(u - 0.5, (int)geomtest_int(&r, -300, 300)); break;
                default: /* four points on z = 0.5, the fifth on it or just off it */
                    q[j][k] = k < 2 ? u : j != 4 || i % 2 ? 0.5 : 0.5 + 0x1p-50 * (u - 0.5);
                    break;
                }
            }
        m = cvm__orient3d_sides(q[0], q[1], q[2], q[3], q[4]);
        for (f = 0; f < 4; f++) {
            for (j = 0; j < 4; j++)
                for (k = 0; k < 3; k++)
                    s[j][k] = q[j == f ? 4 : j][k];
            ck_assert_int_eq((int)((m >> f) & 1u), oracle_orient3d(s[0], s[1], s[2], s[3]) < 0);
        }
    }
}
END_TEST

TCase *geom_orient3d_tcase(void)
{
    TCase *tc = tcase_create("orient3d");
    tcase_add_test(tc, orient3d_agrees_with_int64_on_small_integers);
    tcase_add_test(tc, orient3d_sign_convention);
    tcase_add_test(tc, orient3d_near_coplanar_doubles_match_the_oracle);
    tcase_add_test(tc, orient3d_coplanar_lattice_is_exactly_zero);
    tcase_add_test(tc, orient3d_huge_and_tiny_scales_keep_the_sign);
    tcase_add_test(tc, orient3d_sides_are_exact);
    tcase_set_timeout(tc, 120);
    return tc;
}
