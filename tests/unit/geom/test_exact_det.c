/* test_exact_det.c - the exact last stages, called directly, match the oracle on hard inputs. */
#include <math.h>

#include "geom/exact_det.h"
#include "geom/geom_tests.h"

/* Coordinates near 'base' with a few random low bits: the differences are
 * inexact and the determinants tiny, so no cancellation is harmless. */
static double jitter(geomtest_rng *r, double base, double scale)
{
    return base + scale * geomtest_int(r, -4, 4);
}

START_TEST(exact_stages_match_the_oracle)
{
    geomtest_rng r = { 71 };
    int i, j, k;
    for (i = 0; i < 4000; i++) {
        double p[5][3], w[4];
        double base = (i % 2) ? 1e3 + 0.1 : 0.3, sc = (i % 3) ? 1e-13 : 0.25;
        for (j = 0; j < 5; j++)
            for (k = 0; k < 3; k++)
                p[j][k] = (i % 5 == 0) ? geomtest_uniform(&r, -2.0, 2.0) : jitter(&r, base, sc);
        for (j = 0; j < 4; j++)
            w[j] = (i % 4 == 0) ? 0.0 : geomtest_int(&r, -3, 3) * sc * sc;
        ck_assert_int_eq(geomtest_sign(cvm__orient2d_exact(p[0], p[1], p[2])),
                         oracle_orient2d(p[0], p[1], p[2]));
        ck_assert_int_eq(geomtest_sign(cvm__incircle_exact(p[0], p[1], p[2], p[3])),
                         oracle_incircle(p[0], p[1], p[2], p[3]));
        ck_assert_int_eq(
            geomtest_sign(cvm__power2d_exact(p[0], p[1], p[2], p[3], w[0], w[1], w[2], w[3])),
            oracle_power2d(p[0], p[1], p[2], p[3], w[0], w[1], w[2], w[3]));
        ck_assert_int_eq(geomtest_sign(cvm__orient3d_exact(p[0], p[1], p[2], p[3])),
                         oracle_orient3d(p[0], p[1], p[2], p[3]));
        ck_assert_int_eq(geomtest_sign(cvm__insphere_exact(p[0], p[1], p[2], p[3], p[4])),
                         oracle_insphere(p[0], p[1], p[2], p[3], p[4]));
    }
}
END_TEST

START_TEST(raw_orient2d_expansion_is_exact)
{
    /* the expansion's components sum exactly to the cross products */
    geomtest_rng r = { 72 };
    int i;
    for (i = 0; i < 5000; i++) {
        double p[2], q[2], s[2], h[12], pa[6], pb[6];
        int n;
        p[0] = jitter(&r, 1.1, 1e-9), p[1] = jitter(&r, -7.3, 1e-9);
        q[0] = jitter(&r, 1.1, 1e-9), q[1] = jitter(&r, -7.3, 1e-9);
        s[0] = geomtest_uniform(&r, -9, 9), s[1] = geomtest_uniform(&r, -9, 9);
        n = cvm__orient2d_raw(p, q, s, h);
        ck_assert_int_le(n, 12);
        /* pq + qs + sp with pq = px qy - qx py */
        pa[0] = p[0], pb[0] = q[1], pa[1] = -q[0], pb[1] = p[1];
        pa[2] = q[0], pb[2] = s[1], pa[3] = -s[0], pb[3] = q[1];
        pa[4] = s[0], pb[4] = p[1], pa[5] = -p[0], pb[5] = s[1];
        ck_assert(oracle_expansion_equals(h, n, NULL, 0, pa, pb, 6));
    }
}
END_TEST

TCase *geom_exact_det_tcase(void)
{
    TCase *tc = tcase_create("exact_det");
    tcase_add_test(tc, exact_stages_match_the_oracle);
    tcase_add_test(tc, raw_orient2d_expansion_is_exact);
    tcase_set_timeout(tc, 120);
    return tc;
}
