/* test_insphere.c - insphere has the exact sign on integers, cospherical lattices, near-spheres and extreme scales. */
#include <math.h>
#include <string.h>

#include "geom/geom_internal.h"
#include "geom/geom_tests.h"

static void check_isp(double (*p)[3])
{
    int want = oracle_insphere(p[0], p[1], p[2], p[3], p[4]);
    ck_assert_int_eq(geomtest_sign(cvm__insphere(p[0], p[1], p[2], p[3], p[4])), want);
    ck_assert_int_eq(geomtest_sign(cvm__insphere(p[1], p[0], p[2], p[3], p[4])), -want);
    ck_assert_int_eq(geomtest_sign(cvm__insphere(p[1], p[2], p[3], p[0], p[4])), -want);
}

START_TEST(insphere_agrees_with_int64_on_small_integers)
{
    geomtest_rng r = { 61 };
    int i, j, k, zeros = 0;
    for (i = 0; i < 100000; i++) {
        int lim = (i % 2) ? 2 : 128;
        double p[5][3];
        int64_t want;
        for (j = 0; j < 5; j++)
            for (k = 0; k < 3; k++)
                p[j][k] = geomtest_int(&r, -lim, lim);
        want = intdet_insphere(p[0], p[1], p[2], p[3], p[4]);
        zeros += want == 0;
        ck_assert_int_eq(geomtest_sign(cvm__insphere(p[0], p[1], p[2], p[3], p[4])),
                         geomtest_sign64(want));
    }
    ck_assert_int_gt(zeros, 1000);
}
END_TEST

START_TEST(insphere_sign_convention)
{
    double a[3] = { 1, 0, 0 }, b[3] = { 0, 0, 0 }, c[3] = { 0, 1, 0 }, d[3] = { 0, 0, 1 };
    double in[3] = { 0.25, 0.25, 0.25 }, out[3] = { 5, 5, 5 }, on[3] = { 1, 1, 1 };
    ck_assert(cvm__orient3d(a, b, c, d) > 0.0);
    ck_assert(cvm__insphere(a, b, c, d, in) > 0.0);
    ck_assert(cvm__insphere(a, b, c, d, out) < 0.0);
    ck_assert(cvm__insphere(a, b, c, d, on) == 0.0);
}
END_TEST

START_TEST(insphere_cospherical_lattice_is_exactly_zero)
{
    /* the 30 lattice points at distance 3 from (2, -1, 5) */
    double p[32][3];
    int n = 0, x, y, z, i, j, k, l, m;
    for (x = -3; x <= 3; x++)
        for (y = -3; y <= 3; y++)
            for (z = -3; z <= 3; z++)
                if (x * x + y * y + z * z == 9)
                    p[n][0] = 2 + x, p[n][1] = -1 + y, p[n][2] = 5 + z, n++;
    ck_assert_int_eq(n, 30);
    for (i = 0; i < n; i += 2)
        for (j = i + 1; j < n; j += 3)
            for (k = j + 1; k < n; k += 2)
                for (l = k + 1; l < n; l++)
                    for (m = 0; m < n; m += 5)
                        ck_assert(cvm__insphere(p[i], p[j], p[k], p[l], p[m]) == 0.0);
}
END_TEST

/* The corners of any axis-parallel box are cospherical; mixed magnitudes make
 * the differences inexact, so only the final exact stage sees the zero. */
START_TEST(insphere_boxes_of_mixed_magnitude_are_exactly_zero)
{
    geomtest_rng r = { 64 };
    int i, j, k;
    for (i = 0; i < 1000; i++) {
        double lo[3], hi[3], p[5][3];
        for (k = 0; k < 3; k++) {
            lo[k] = geomtest_uniform(&r, -1e-4, 1e-4);
            hi[k] = geomtest_uniform(&r, 1e1, 1e3);
        }
        for (j = 0; j < 5; j++) {
            int corner = (int)(geomtest_u64(&r) % 8);
            for (k = 0; k < 3; k++)
                p[j][k] = ((corner >> k) & 1) ? hi[k] : lo[k];
        }
        ck_assert(cvm__insphere(p[0], p[1], p[2], p[3], p[4]) == 0.0);
        ck_assert_int_eq(oracle_insphere(p[0], p[1], p[2], p[3], p[4]), 0);
        p[4][1] = geomtest_ulps(p[4][1], 1);
        check_isp(p);
    }
}
END_TEST

/* Five points rounded onto a sphere, the last nudged. */
static void near_sphere(geomtest_rng *r, double cx, double rad, double (*p)[3])
{
    int j;
    for (j = 0; j < 5; j++) {
        double t = geomtest_uniform(r, 0.0, 6.283185307179586);
        double u = geomtest_uniform(r, -1.0, 1.0), s = sqrt(1.0 - u * u);
        p[j][0] = cx + rad * s * cos(t);
        p[j][1] = -cx + rad * s * sin(t);
        p[j][2] = 0.5 * cx + rad * u;
    }
    p[4][2] = geomtest_ulps(p[4][2], (int)(geomtest_u64(r) % 3) - 1);
}

START_TEST(insphere_near_cospherical_doubles_match_the_oracle)
{
    geomtest_rng r = { 62 };
    int i;
    for (i = 0; i < 5000; i++) {
        double p[5][3];
        near_sphere(&r, (i % 3 == 0) ? 1e3 : 0.0, (i % 2) ? 1.0 : 1e-3, p);
        check_isp(p);
    }
}
END_TEST

START_TEST(insphere_huge_and_tiny_scales_keep_the_sign)
{
    double pow2[] = { 0x1p-1000, 0x1p-300, 0x1p150, 0x1p900 };
    double dec[] = { 1e-150, 1e150 };
    geomtest_rng r = { 63 };
    int i, k, j, m;
    for (i = 0; i < 1000; i++) {
        double p[5][3], s[5][3], v;
        int want;
        near_sphere(&r, 0.0, 1.0, p);
        want = oracle_insphere(p[0], p[1], p[2], p[3], p[4]);
        for (k = 0; k < 4; k++) {
            for (j = 0; j < 5; j++)
                for (m = 0; m < 3; m++)
                    s[j][m] = p[j][m] * pow2[k];
            v = cvm__insphere(s[0], s[1], s[2], s[3], s[4]);
            ck_assert_int_eq(geomtest_sign(v), want);
            ck_assert(isfinite(v));
        }
        for (k = 0; k < 2; k++) {
            for (j = 0; j < 5; j++)
                for (m = 0; m < 3; m++)
                    s[j][m] = p[j][m] * dec[k];
            check_isp(s);
        }
    }
}
END_TEST

/* The two-lane determinant of cvm__insphere_inline gives the scalar one's bits
 * (and the same largest lift), on unit, integer, offset and wide-range input. */
START_TEST(insphere_sse2_determinant_matches_scalar_bits)
{
#ifdef CVM__GEOM_SSE2
    geomtest_rng r = { 67 };
    int i, j, k;
    for (i = 0; i < 200000; i++) {
        double p[5][3], d1, d2, l1, l2;
        for (j = 0; j < 5; j++)
            for (k = 0; k < 3; k++) {
                double u = geomtest_uniform(&r, 0.0, 1.0);
                switch (i % 4) {
                case 0: p[j][k] = u; break;
                case 1: p[j][k] = geomtest_int(&r, -4, 4); break;
                case 2: p[j][k] = 1e5 + 1e-3 * u; break;
                default: p[j][k] = ldexp(u - 0.5, (int)geomtest_int(&r, -300, 300)); break;
                }
            }
        if (i % 8 == 1)
            p[4][0] = p[0][0], p[4][1] = p[0][1], p[4][2] = p[0][2];
        d1 = cvm__insphere_det_scalar(p[0], p[1], p[2], p[3], p[4], &l1);
        d2 = cvm__insphere_det_sse2(p[0], p[1], p[2], p[3], p[4], &l2);
        ck_assert(memcmp(&d1, &d2, sizeof d1) == 0);
        ck_assert(memcmp(&l1, &l2, sizeof l1) == 0);
    }
#endif
}
END_TEST

TCase *geom_insphere_tcase(void)
{
    TCase *tc = tcase_create("insphere");
    tcase_add_test(tc, insphere_agrees_with_int64_on_small_integers);
    tcase_add_test(tc, insphere_sign_convention);
    tcase_add_test(tc, insphere_cospherical_lattice_is_exactly_zero);
    tcase_add_test(tc, insphere_near_cospherical_doubles_match_the_oracle);
    tcase_add_test(tc, insphere_boxes_of_mixed_magnitude_are_exactly_zero);
    tcase_add_test(tc, insphere_huge_and_tiny_scales_keep_the_sign);
    tcase_add_test(tc, insphere_sse2_determinant_matches_scalar_bits);
    tcase_set_timeout(tc, 180);
    return tc;
}
