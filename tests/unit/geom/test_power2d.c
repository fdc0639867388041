/* test_power2d.c - power2d is exact, reduces to incircle without weights, and knows the orthocircle. */
#include <math.h>

#include "geom/geom_internal.h"
#include "geom/geom_tests.h"

START_TEST(power2d_agrees_with_int64_on_small_integers)
{
    geomtest_rng r = { 41 };
    int i, j, zeros = 0;
    for (i = 0; i < 200000; i++) {
        int lim = (i % 2) ? 5 : 2048, wlim = (i % 2) ? 20 : (1 << 22);
        double p[4][2], w[4];
        int64_t want;
        for (j = 0; j < 4; j++) {
            p[j][0] = geomtest_int(&r, -lim, lim), p[j][1] = geomtest_int(&r, -lim, lim);
            w[j] = geomtest_int(&r, -wlim, wlim);
        }
        want = intdet_power2d(p[0], p[1], p[2], p[3], w[0], w[1], w[2], w[3]);
        zeros += want == 0;
        ck_assert_int_eq(
            geomtest_sign(cvm__power2d(p[0], p[1], p[2], p[3], w[0], w[1], w[2], w[3])),
            geomtest_sign64(want));
    }
    ck_assert_int_gt(zeros, 100);
}
END_TEST

START_TEST(power2d_without_weights_is_incircle)
{
    geomtest_rng r = { 42 };
    int i, j;
    for (i = 0; i < 20000; i++) {
        double p[4][2], w;
        int s;
        for (j = 0; j < 4; j++) {
            double t = geomtest_uniform(&r, 0.0, 6.283185307179586);
            p[j][0] = 1e3 + cos(t), p[j][1] = -0.5 + sin(t); /* nearly cocircular */
        }
        s = geomtest_sign(cvm__incircle(p[0], p[1], p[2], p[3]));
        ck_assert_int_eq(s, oracle_incircle(p[0], p[1], p[2], p[3]));
        ck_assert_int_eq(geomtest_sign(cvm__power2d(p[0], p[1], p[2], p[3], 0, 0, 0, 0)), s);
        /* a common weight shifts every lifted point by the same amount */
        w = geomtest_uniform(&r, -10.0, 10.0);
        ck_assert_int_eq(geomtest_sign(cvm__power2d(p[0], p[1], p[2], p[3], w, w, w, w)), s);
    }
}
END_TEST

/* a, b, c unweighted on the circle of radius 5 around o; d = o with weight w
 * is in conflict (> 0) exactly when w > -25, the power of o. */
START_TEST(power2d_orthocircle_known_answer)
{
    double o[2] = { 1.0, 2.0 };
    double a[2] = { 6.0, 2.0 }, b[2] = { 1.0, 7.0 }, c[2] = { -4.0, 2.0 }, e[2] = { 1.0, -3.0 };
    ck_assert(cvm__orient2d(a, b, c) > 0.0);
    ck_assert(cvm__power2d(a, b, c, o, 0, 0, 0, -25.0) == 0.0);
    ck_assert(cvm__power2d(a, b, c, o, 0, 0, 0, -24.0) > 0.0);
    ck_assert(cvm__power2d(a, b, c, o, 0, 0, 0, -26.0) < 0.0);
    ck_assert(cvm__power2d(a, b, c, o, 0, 0, 0, nextafter(-25.0, 0.0)) > 0.0);
    ck_assert(cvm__power2d(a, b, c, o, 0, 0, 0, nextafter(-25.0, -30.0)) < 0.0);
    /* e on the circle: raising a's weight lowers a', tilting the plane down
     * so that e' ends up above it (no conflict); lowering it does the reverse */
    ck_assert(cvm__power2d(a, b, c, e, 0, 0, 0, 0) == 0.0);
    ck_assert(cvm__power2d(a, b, c, e, 1.0, 0, 0, 0) < 0.0);
    ck_assert(cvm__power2d(a, b, c, e, -1.0, 0, 0, 0) > 0.0);
}
END_TEST

START_TEST(power2d_near_degenerate_weights_match_the_oracle)
{
    geomtest_rng r = { 43 };
    int i, j;
    for (i = 0; i < 20000; i++) {
        double p[4][2], w[4], scale = (i % 3 == 0) ? 1e-3 : 1.0, shift = (i % 2) ? 1e3 : 0.0;
        double ax, ay, bx, by, cx, cy, ox, oy, rr;
        for (j = 0; j < 4; j++) {
            p[j][0] = shift + scale * geomtest_uniform(&r, -1.0, 1.0);
            p[j][1] = scale * geomtest_uniform(&r, -1.0, 1.0);
            w[j] = scale * scale * geomtest_uniform(&r, 0.0, 0.1);
        }
        /* put d's weight (nearly) on the plane through a', b', c' (unweighted
         * circumcircle power of d, corrected by the weights' mean) */
        ax = p[0][0] - shift, ay = p[0][1], bx = p[1][0] - shift, by = p[1][1];
        cx = p[2][0] - shift, cy = p[2][1];
        {
            double dd = 2.0 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by));
            double a2 = ax * ax + ay * ay, b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
            ox = (a2 * (by - cy) + b2 * (cy - ay) + c2 * (ay - by)) / dd;
            oy = (a2 * (cx - bx) + b2 * (ax - cx) + c2 * (bx - ax)) / dd;
            rr = (ax - ox) * (ax - ox) + (ay - oy) * (ay - oy);
        }
        w[3] = ((p[3][0] - shift - ox) * (p[3][0] - shift - ox) + (p[3][1] - oy) * (p[3][1] - oy)
                - rr) + (w[0] + w[1] + w[2]) / 3.0;
        w[3] = geomtest_ulps(w[3], (int)(geomtest_u64(&r) % 5) - 2);
        ck_assert_int_eq(
            geomtest_sign(cvm__power2d(p[0], p[1], p[2], p[3], w[0], w[1], w[2], w[3])),
            oracle_power2d(p[0], p[1], p[2], p[3], w[0], w[1], w[2], w[3]));
    }
}
END_TEST

START_TEST(power2d_huge_and_tiny_scales_keep_the_sign)
{
    /* weights scale with the square: 2^-500 .. 2^500 keeps them finite and normal */
    double pow2[] = { 0x1p-500, 0x1p-250, 0x1p300, 0x1p500 };
    double o[2] = { 1.0, 2.0 };
    double p[3][2] = { { 6.0, 2.0 }, { 1.0, 7.0 }, { -4.0, 2.0 } };
    double w[3] = { -24.0, -25.0, -26.0 };
    int k, i, j;
    for (k = 0; k < 4; k++) {
        double s[4][2];
        for (j = 0; j < 3; j++)
            s[j][0] = p[j][0] * pow2[k], s[j][1] = p[j][1] * pow2[k];
        s[3][0] = o[0] * pow2[k], s[3][1] = o[1] * pow2[k];
        for (i = 0; i < 3; i++) {
            double v = cvm__power2d(s[0], s[1], s[2], s[3], 0, 0, 0, w[i] * pow2[k] * pow2[k]);
            ck_assert_int_eq(geomtest_sign(v), i == 0 ? 1 : (i == 1 ? 0 : -1));
            ck_assert(isfinite(v));
        }
    }
}
END_TEST

TCase *geom_power2d_tcase(void)
{
    TCase *tc = tcase_create("power2d");
    tcase_add_test(tc, power2d_agrees_with_int64_on_small_integers);
    tcase_add_test(tc, power2d_without_weights_is_incircle);
    tcase_add_test(tc, power2d_orthocircle_known_answer);
    tcase_add_test(tc, power2d_near_degenerate_weights_match_the_oracle);
    tcase_add_test(tc, power2d_huge_and_tiny_scales_keep_the_sign);
    tcase_set_timeout(tc, 120);
    return tc;
}
