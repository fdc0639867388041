/* test_orient2d.c - orient2d has the exact sign on integers, ulp-perturbed lines and extreme scales. */
#include <math.h>

#include "geom/geom_internal.h"
#include "geom/geom_tests.h"

static void check_o2d(const double *a, const double *b, const double *c)
{
    int want = oracle_orient2d(a, b, c);
    ck_assert_int_eq(geomtest_sign(cvm__orient2d(a, b, c)), want);
    ck_assert_int_eq(geomtest_sign(cvm__orient2d_inline(a, b, c)), want);
    ck_assert_int_eq(geomtest_sign(cvm__orient2d(b, c, a)), want);
    ck_assert_int_eq(geomtest_sign(cvm__orient2d(b, a, c)), -want);
}

START_TEST(orient2d_agrees_with_int64_on_small_integers)
{
    geomtest_rng r = { 21 };
    int i, zeros = 0;
    for (i = 0; i < 200000; i++) {
        int lim = (i % 2) ? 6 : 4096;
        double a[2], b[2], c[2];
        int64_t want;
        a[0] = geomtest_int(&r, -lim, lim), a[1] = geomtest_int(&r, -lim, lim);
        b[0] = geomtest_int(&r, -lim, lim), b[1] = geomtest_int(&r, -lim, lim);
        c[0] = geomtest_int(&r, -lim, lim), c[1] = geomtest_int(&r, -lim, lim);
        want = intdet_orient2d(a, b, c);
        zeros += want == 0;
        ck_assert_int_eq(geomtest_sign(cvm__orient2d(a, b, c)), geomtest_sign64(want));
        /* both products are below 2^53 here, so the filter's value is the exact one */
        ck_assert(cvm__orient2d(a, b, c) == (double)want);
    }
    ck_assert_int_gt(zeros, 1000); /* the small range produced plenty of collinear triples */
}
END_TEST

/* Kettner et al.'s classroom example: p is moved by up to 32 ulps in x and y
 * around (0.5, 0.5) on the line y = x through q = (12, 12), r = (24, 24). */
START_TEST(orient2d_one_ulp_off_a_line_gets_the_right_sign)
{
    double q[2] = { 12.0, 12.0 }, r[2] = { 24.0, 24.0 }, p[2];
    int i, j, pos = 0, neg = 0, zero = 0;
    for (i = -32; i <= 32; i++) {
        for (j = -32; j <= 32; j++) {
            int s;
            p[0] = geomtest_ulps(0.5, i);
            p[1] = geomtest_ulps(0.5, j);
            s = geomtest_sign(cvm__orient2d(p, q, r));
            /* y = x exactly: the sign is that of y - x, i.e. of j - i */
            ck_assert_int_eq(s, (j > i) - (j < i));
            ck_assert_int_eq(s, oracle_orient2d(p, q, r));
            pos += s > 0, neg += s < 0, zero += s == 0;
        }
    }
    ck_assert_int_eq(zero, 65);
    ck_assert_int_eq(pos, neg);
}
END_TEST

/* Points rounded onto lines through random points, nudged by a few ulps. */
static void near_line(geomtest_rng *r, double scale, double *a, double *b, double *c)
{
    double t = geomtest_uniform(r, -2.0, 3.0);
    a[0] = scale * geomtest_uniform(r, -1.0, 1.0), a[1] = scale * geomtest_uniform(r, -1.0, 1.0);
    b[0] = scale * geomtest_uniform(r, -1.0, 1.0), b[1] = scale * geomtest_uniform(r, -1.0, 1.0);
    c[0] = a[0] + t * (b[0] - a[0]);
    c[1] = a[1] + t * (b[1] - a[1]);
    c[0] = geomtest_ulps(c[0], (int)(geomtest_u64(r) % 5) - 2);
    c[1] = geomtest_ulps(c[1], (int)(geomtest_u64(r) % 5) - 2);
}

START_TEST(orient2d_near_collinear_doubles_match_the_oracle)
{
    geomtest_rng r = { 22 };
    int i;
    for (i = 0; i < 20000; i++) {
        double a[2], b[2], c[2];
        near_line(&r, (i % 3 == 0) ? 1e6 : 1.0, a, b, c);
        check_o2d(a, b, c);
    }
}
END_TEST

START_TEST(orient2d_huge_and_tiny_scales_keep_the_sign)
{
    /* exact power-of-two scalings must not change anything; 1e+-150 scalings
     * round, so there the oracle decides */
    double pow2[] = { 0x1p-1000, 0x1p-540, 0x1p-100, 0x1p100, 0x1p500, 0x1p900 };
    double dec[] = { 1e-150, 1e150, 1e-300, 1e300 };
    geomtest_rng r = { 23 };
    int i, k, j;
    for (i = 0; i < 3000; i++) {
        double a[2], b[2], c[2], sa[2], sb[2], sc[2], v;
        int want;
        near_line(&r, 1.0, a, b, c);
        want = oracle_orient2d(a, b, c);
        for (k = 0; k < 6; k++) {
            for (j = 0; j < 2; j++)
                sa[j] = a[j] * pow2[k], sb[j] = b[j] * pow2[k], sc[j] = c[j] * pow2[k];
            v = cvm__orient2d(sa, sb, sc);
            ck_assert_int_eq(geomtest_sign(v), want);
            ck_assert(isfinite(v));
        }
        for (k = 0; k < 4; k++) {
            for (j = 0; j < 2; j++)
                sa[j] = a[j] * dec[k], sb[j] = b[j] * dec[k], sc[j] = c[j] * dec[k];
            check_o2d(sa, sb, sc);
        }
    }
}
END_TEST

START_TEST(orient2d_magnitude_is_twice_the_area)
{
    double a[2] = { 0.0, 0.0 }, b[2] = { 4.0, 0.0 }, c[2] = { 0.0, 3.0 };
    double ta[2] = { 0.0, 0.0 }, tb[2] = { 4e-200, 0.0 }, tc[2] = { 0.0, 3e-200 };
    ck_assert(cvm__orient2d(a, b, c) == 12.0);
    ck_assert(cvm__orient2d(a, c, b) == -12.0);
    /* rescaled slow path: the value is unscaled back (12e-400 underflows to
     * the smallest subnormal, keeping its sign) */
    ck_assert(cvm__orient2d(ta, tb, tc) > 0.0);
    ck_assert(cvm__orient2d(ta, tc, tb) < 0.0);
}
END_TEST

TCase *geom_orient2d_tcase(void)
{
    TCase *tc = tcase_create("orient2d");
    tcase_add_test(tc, orient2d_agrees_with_int64_on_small_integers);
    tcase_add_test(tc, orient2d_one_ulp_off_a_line_gets_the_right_sign);
    tcase_add_test(tc, orient2d_near_collinear_doubles_match_the_oracle);
    tcase_add_test(tc, orient2d_huge_and_tiny_scales_keep_the_sign);
    tcase_add_test(tc, orient2d_magnitude_is_twice_the_area);
    tcase_set_timeout(tc, 60);
    return tc;
}
