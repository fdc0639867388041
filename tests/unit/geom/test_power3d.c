/* test_power3d.c - power3d (weighted insphere) has the exact sign on integers, near-ties, zero weights and extreme scales. */
#include <math.h>

#include "geom/geom_internal.h"
#include "geom/geom_tests.h"

static int pw_sign(double (*p)[3], const double *w)
{
    return geomtest_sign(cvm__power3d(p[0], p[1], p[2], p[3], p[4], w[0], w[1], w[2], w[3], w[4]));
}

static int pw_oracle(double (*p)[3], const double *w)
{
    return oracle_power3d(p[0], p[1], p[2], p[3], p[4], w[0], w[1], w[2], w[3], w[4]);
}

START_TEST(power3d_agrees_with_oracle_on_small_integers)
{
    geomtest_rng r = { 301 };
    int i, j, k, zeros = 0;
    for (i = 0; i < 20000; i++) {
        int lim = (i % 2) ? 2 : 64;
        double p[5][3], w[5];
        int want;
        for (j = 0; j < 5; j++) {
            for (k = 0; k < 3; k++)
                p[j][k] = geomtest_int(&r, -lim, lim);
            w[j] = geomtest_int(&r, -lim, lim);
        }
        want = pw_oracle(p, w);
        zeros += want == 0;
        ck_assert_int_eq(pw_sign(p, w), want);
    }
    ck_assert_int_gt(zeros, 100);
}
END_TEST

START_TEST(power3d_with_zero_weights_is_insphere)
{
    geomtest_rng r = { 302 };
    int i, j, k;
    double w[5] = { 0, 0, 0, 0, 0 };
    for (i = 0; i < 20000; i++) {
        double p[5][3];
        int lim = (i % 3) ? 3 : 1000;
        for (j = 0; j < 5; j++)
            for (k = 0; k < 3; k++)
                p[j][k] = (i % 2) ? geomtest_int(&r, -lim, lim) : geomtest_uniform(&r, -1, 1);
        ck_assert_int_eq(pw_sign(p, w),
                         geomtest_sign(cvm__insphere(p[0], p[1], p[2], p[3], p[4])));
        ck_assert_int_eq(geomtest_sign(cvm__insphere(p[0], p[1], p[2], p[3], p[4])),
                         oracle_insphere(p[0], p[1], p[2], p[3], p[4]));
    }
}
END_TEST

/* Weighted points built to tie exactly (e's weight on the orthosphere), then
 * nudged by ulps of a weight: the sign must follow the oracle each time. */
START_TEST(power3d_near_ties_follow_the_oracle)
{
    geomtest_rng r = { 303 };
    int i, j, k, u;
    for (i = 0; i < 2000; i++) {
        double p[5][3], w[5], c[3] = { 0.5, -0.25, 0.125 }, rad;
        for (j = 0; j < 5; j++)
            for (k = 0; k < 3; k++)
                p[j][k] = geomtest_uniform(&r, -1, 1);
        rad = geomtest_uniform(&r, 0.1, 2);
        /* power of c to (p, w) = |c - p|^2 - w = rad for every point: a tie */
        for (j = 0; j < 5; j++) {
            double d0 = c[0] - p[j][0], d1 = c[1] - p[j][1], d2 = c[2] - p[j][2];
            w[j] = d0 * d0 + d1 * d1 + d2 * d2 - rad;
        }
        for (u = -2; u <= 2; u++) {
            double ww[5];
            for (j = 0; j < 5; j++)
                ww[j] = w[j];
            ww[4] = geomtest_ulps(w[4], u);
            ck_assert_int_eq(pw_sign(p, ww), pw_oracle(p, ww));
        }
    }
}
END_TEST

START_TEST(power3d_sign_survives_huge_and_tiny_scales)
{
    geomtest_rng r = { 304 };
    static const int exps[] = { -1000, -600, -300, 300, 600, 900 };
    int i, j, k, e;
    for (i = 0; i < 2000; i++) {
        double p[5][3], w[5], q[5][3], v[5];
        int want;
        for (j = 0; j < 5; j++) {
            for (k = 0; k < 3; k++)
                p[j][k] = geomtest_int(&r, -4, 4);
            w[j] = geomtest_int(&r, -8, 8);
        }
        want = pw_oracle(p, w);
        for (e = 0; e < 6; e++) {
            int s = exps[e] / 2;
            for (j = 0; j < 5; j++) {
                for (k = 0; k < 3; k++)
                    q[j][k] = ldexp(p[j][k], s);
                v[j] = ldexp(w[j], 2 * s);
            }
            ck_assert_int_eq(pw_sign(q, v), want);
        }
    }
}
END_TEST

START_TEST(power3d_sign_convention)
{
    double p[5][3] = { { 1, 0, 0 }, { 0, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 0.25, 0.25, 0.25 } };
    double w[5] = { 0, 0, 0, 0, 0 };
    ck_assert(cvm__orient3d(p[0], p[1], p[2], p[3]) > 0.0);
    ck_assert_int_eq(pw_sign(p, w), 1);
    w[4] = -10.0; /* a very light e is in conflict with nothing */
    ck_assert_int_eq(pw_sign(p, w), -1);
    w[4] = 10.0; /* a heavy e conflicts */
    ck_assert_int_eq(pw_sign(p, w), 1);
}
END_TEST

TCase *geom_power3d_tcase(void)
{
    TCase *tc = tcase_create("power3d");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, power3d_agrees_with_oracle_on_small_integers);
    tcase_add_test(tc, power3d_with_zero_weights_is_insphere);
    tcase_add_test(tc, power3d_near_ties_follow_the_oracle);
    tcase_add_test(tc, power3d_sign_survives_huge_and_tiny_scales);
    tcase_add_test(tc, power3d_sign_convention);
    return tc;
}
