/* test_incircle.c - incircle has the exact sign on integers, cocircular lattices, near-circles and extreme scales. */
#include <math.h>

#include "geom/geom_internal.h"
#include "geom/geom_tests.h"

static void check_icc(const double *a, const double *b, const double *c, const double *d)
{
    int want = oracle_incircle(a, b, c, d);
    ck_assert_int_eq(geomtest_sign(cvm__incircle(a, b, c, d)), want);
    ck_assert_int_eq(geomtest_sign(cvm__incircle_inline(a, b, c, d)), want);
    ck_assert_int_eq(geomtest_sign(cvm__incircle(b, c, a, d)), want);
    ck_assert_int_eq(geomtest_sign(cvm__incircle(b, a, c, d)), -want);
}

START_TEST(incircle_agrees_with_int64_on_small_integers)
{
    geomtest_rng r = { 31 };
    int i, j, zeros = 0;
    for (i = 0; i < 200000; i++) {
        int lim = (i % 2) ? 5 : 4096;
        double p[4][2];
        int64_t want;
        for (j = 0; j < 4; j++)
            p[j][0] = geomtest_int(&r, -lim, lim), p[j][1] = geomtest_int(&r, -lim, lim);
        want = intdet_incircle(p[0], p[1], p[2], p[3]);
        zeros += want == 0;
        ck_assert_int_eq(geomtest_sign(cvm__incircle(p[0], p[1], p[2], p[3])),
                         geomtest_sign64(want));
    }
    ck_assert_int_gt(zeros, 1000);
}
END_TEST

/* The 24 lattice points on x^2 + y^2 = 325 around (cx, cy). */
static int lattice_circle(double cx, double cy, double (*p)[2])
{
    int x, y, n = 0;
    for (x = -18; x <= 18; x++)
        for (y = -18; y <= 18; y++)
            if (x * x + y * y == 325)
                p[n][0] = cx + x, p[n][1] = cy + y, n++;
    return n;
}

START_TEST(incircle_cocircular_lattice_is_exactly_zero)
{
    double p[32][2], off[2];
    int n = lattice_circle(3.0, -7.0, p), i, j, k, l;
    ck_assert_int_eq(n, 24);
    for (i = 0; i < n; i++)
        for (j = i + 1; j < n; j++)
            for (k = j + 1; k < n; k++)
                for (l = k + 1; l < n; l++) {
                    ck_assert(cvm__incircle(p[i], p[j], p[k], p[l]) == 0.0);
                    ck_assert(cvm__incircle(p[l], p[k], p[i], p[j]) == 0.0);
                }
    /* one ulp off the circle is not on it: just outside or inside */
    off[0] = geomtest_ulps(p[5][0], p[5][0] > 3.0 ? 1 : -1);
    off[1] = p[5][1];
    ck_assert_int_eq(geomtest_sign(cvm__incircle(p[0], p[8], p[16], off))
                         * geomtest_sign(cvm__orient2d(p[0], p[8], p[16])),
                     -1);
    off[0] = geomtest_ulps(p[5][0], p[5][0] > 3.0 ? -1 : 1);
    ck_assert_int_eq(geomtest_sign(cvm__incircle(p[0], p[8], p[16], off))
                         * geomtest_sign(cvm__orient2d(p[0], p[8], p[16])),
                     1);
}
END_TEST

/* Four points rounded onto a circle of radius rad around (cx, cy), nudged. */
static void near_circle(geomtest_rng *r, double cx, double cy, double rad, double (*p)[2])
{
    int j;
    for (j = 0; j < 4; j++) {
        double t = geomtest_uniform(r, 0.0, 6.283185307179586);
        p[j][0] = cx + rad * cos(t);
        p[j][1] = cy + rad * sin(t);
        if (j == 3)
            p[j][0] = geomtest_ulps(p[j][0], (int)(geomtest_u64(r) % 5) - 2);
    }
}

START_TEST(incircle_near_cocircular_doubles_match_the_oracle)
{
    geomtest_rng r = { 32 };
    int i;
    for (i = 0; i < 20000; i++) {
        double p[4][2];
        double c = (i % 3 == 0) ? 0.0 : ((i % 3 == 1) ? 1e3 : 0.75);
        near_circle(&r, c, -c, (i % 2) ? 1.0 : 1e-3, p);
        check_icc(p[0], p[1], p[2], p[3]);
    }
}
END_TEST

START_TEST(incircle_huge_and_tiny_scales_keep_the_sign)
{
    double pow2[] = { 0x1p-1000, 0x1p-600, 0x1p-300, 0x1p200, 0x1p600, 0x1p900 };
    double dec[] = { 1e-150, 1e150 };
    geomtest_rng r = { 33 };
    int i, k, j;
    for (i = 0; i < 2000; i++) {
        double p[4][2], s[4][2], v;
        int want;
        near_circle(&r, (i % 2) ? 0.0 : 0.25, 0.5, 1.0, p);
        want = oracle_incircle(p[0], p[1], p[2], p[3]);
        for (k = 0; k < 6; k++) {
            for (j = 0; j < 4; j++)
                s[j][0] = p[j][0] * pow2[k], s[j][1] = p[j][1] * pow2[k];
            v = cvm__incircle(s[0], s[1], s[2], s[3]);
            ck_assert_int_eq(geomtest_sign(v), want);
            ck_assert(isfinite(v));
        }
        for (k = 0; k < 2; k++) {
            for (j = 0; j < 4; j++)
                s[j][0] = p[j][0] * dec[k], s[j][1] = p[j][1] * dec[k];
            check_icc(s[0], s[1], s[2], s[3]);
        }
    }
}
END_TEST

/* The corners of any axis-parallel rectangle are cocircular. With corner
 * coordinates of very different magnitudes the differences to d are inexact,
 * so the zero is only found by the final exact stage. */
START_TEST(incircle_rectangles_of_mixed_magnitude_are_exactly_zero)
{
    geomtest_rng r = { 34 };
    int i, j, zero_paths = 0;
    for (i = 0; i < 5000; i++) {
        double x[2], y[2], p[4][2], q[4][2], pw[4];
        int perm[4] = { 0, 1, 2, 3 }, t;
        x[0] = geomtest_uniform(&r, -1e-3, 1e-3), x[1] = geomtest_uniform(&r, 1e2, 1e3);
        y[0] = geomtest_uniform(&r, -1e3, -1e2), y[1] = geomtest_uniform(&r, -1e-6, 1e-6);
        p[0][0] = x[0], p[0][1] = y[0];
        p[1][0] = x[1], p[1][1] = y[0];
        p[2][0] = x[1], p[2][1] = y[1];
        p[3][0] = x[0], p[3][1] = y[1];
        for (j = 3; j > 0; j--) { /* random order */
            int k = (int)(geomtest_u64(&r) % (uint64_t)(j + 1));
            t = perm[j], perm[j] = perm[k], perm[k] = t;
        }
        for (j = 0; j < 4; j++)
            q[j][0] = p[perm[j]][0], q[j][1] = p[perm[j]][1];
        ck_assert(cvm__incircle(q[0], q[1], q[2], q[3]) == 0.0);
        pw[0] = pw[1] = pw[2] = pw[3] = 1.5;
        ck_assert(cvm__power2d(q[0], q[1], q[2], q[3], pw[0], pw[1], pw[2], pw[3]) == 0.0);
        zero_paths++;
        /* and one ulp off the corner */
        q[3][1] = geomtest_ulps(q[3][1], (i % 2) ? 1 : -1);
        check_icc(q[0], q[1], q[2], q[3]);
    }
    ck_assert_int_eq(zero_paths, 5000);
}
END_TEST

START_TEST(incircle_sign_convention)
{
    double a[2] = { 1.0, 0.0 }, b[2] = { 0.0, 1.0 }, c[2] = { -1.0, 0.0 };
    double in[2] = { 0.0, 0.0 }, out[2] = { 0.0, -2.0 }, on[2] = { 0.0, -1.0 };
    ck_assert(cvm__orient2d(a, b, c) > 0.0);
    ck_assert(cvm__incircle(a, b, c, in) > 0.0);
    ck_assert(cvm__incircle(a, b, c, out) < 0.0);
    ck_assert(cvm__incircle(a, b, c, on) == 0.0);
    ck_assert(cvm__incircle(c, b, a, in) < 0.0); /* clockwise flips the sign */
}
END_TEST

TCase *geom_incircle_tcase(void)
{
    TCase *tc = tcase_create("incircle");
    tcase_add_test(tc, incircle_agrees_with_int64_on_small_integers);
    tcase_add_test(tc, incircle_cocircular_lattice_is_exactly_zero);
    tcase_add_test(tc, incircle_near_cocircular_doubles_match_the_oracle);
    tcase_add_test(tc, incircle_huge_and_tiny_scales_keep_the_sign);
    tcase_add_test(tc, incircle_rectangles_of_mixed_magnitude_are_exactly_zero);
    tcase_add_test(tc, incircle_sign_convention);
    tcase_set_timeout(tc, 120);
    return tc;
}
