/* test_expansion.c - error-free transformations and expansion arithmetic are exact and well formed. */
#include <float.h>
#include <math.h>

#include "geom/expansion.h"
#include "geom/geom_tests.h"

/* Random double with a random exponent in [lo, hi]. */
static double wide(geomtest_rng *r, int lo, int hi)
{
    double m = geomtest_uniform(r, 0.5, 1.0);
    int e = lo + (int)(geomtest_u64(r) % (uint64_t)(hi - lo + 1));
    return (geomtest_u64(r) & 1u ? -1.0 : 1.0) * ldexp(m, e);
}

/* Exponent of the highest and lowest set bit of a nonzero double. */
static int high_bit(double x)
{
    int e;
    (void)frexp(x, &e);
    return e - 1;
}

static int low_bit(double x)
{
    int k = high_bit(x) - 52;
    while (fmod(ldexp(fabs(x), -(k + 1)), 1.0) == 0.0)
        k++;
    return k;
}

/* Increasing magnitude, no zeros (unless the single component), nonoverlapping. */
static int well_formed(const double *h, int n)
{
    int i;
    if (n == 1)
        return 1;
    for (i = 0; i < n; i++)
        if (h[i] == 0.0)
            return 0;
    for (i = 0; i + 1 < n; i++)
        if (!(low_bit(h[i + 1]) > high_bit(h[i])))
            return 0;
    return 1;
}

START_TEST(two_sum_and_two_diff_are_error_free)
{
    geomtest_rng r = { 11 };
    int i;
    for (i = 0; i < 20000; i++) {
        double a = wide(&r, -60, 60), b = wide(&r, -60, 60), x, y, e[2], t[2];
        cvm__two_sum(a, b, &x, &y);
        ck_assert(x == a + b);
        e[0] = y, e[1] = x, t[0] = a, t[1] = b;
        ck_assert(oracle_expansion_equals(e, 2, t, 2, NULL, NULL, 0));
        cvm__two_diff(a, b, &x, &y);
        ck_assert(x == a - b);
        e[0] = y, e[1] = x, t[0] = a, t[1] = -b;
        ck_assert(oracle_expansion_equals(e, 2, t, 2, NULL, NULL, 0));
        if (fabs(a) < fabs(b)) {
            double s = a;
            a = b, b = s;
        }
        cvm__fast_two_sum(a, b, &x, &y);
        e[0] = y, e[1] = x, t[0] = a, t[1] = b;
        ck_assert(oracle_expansion_equals(e, 2, t, 2, NULL, NULL, 0));
    }
}
END_TEST

START_TEST(two_product_and_two_two_diff_are_error_free)
{
    geomtest_rng r = { 12 };
    int i;
    for (i = 0; i < 20000; i++) {
        double a = wide(&r, -200, 200), b = wide(&r, -200, 200), x, y, e[4];
        double c = wide(&r, -200, 200), d = wide(&r, -200, 200), x1, y1;
        double pa[2], pb[2];
        cvm__two_product(a, b, &x, &y);
        ck_assert(x == a * b);
        e[0] = y, e[1] = x, pa[0] = a, pb[0] = b;
        ck_assert(oracle_expansion_equals(e, 2, NULL, 0, pa, pb, 1));
        cvm__two_product(c, d, &x1, &y1);
        cvm__two_two_diff(x, y, x1, y1, e);
        pa[1] = -c, pb[1] = d;
        ck_assert(oracle_expansion_equals(e, 4, NULL, 0, pa, pb, 2));
    }
}
END_TEST

/* An expansion of n random doubles grown one at a time. */
static int random_expansion(geomtest_rng *r, int n, double *terms, double *h)
{
    double tmp[64];
    int len = 1, i, j;
    terms[0] = wide(r, -80, 80);
    h[0] = terms[0];
    for (i = 1; i < n; i++) {
        terms[i] = wide(r, -80, 80);
        len = cvm__grow_expansion_zeroelim(len, h, terms[i], tmp);
        for (j = 0; j < len; j++)
            h[j] = tmp[j];
    }
    return len;
}

START_TEST(grow_and_sum_are_exact_and_nonoverlapping)
{
    geomtest_rng r = { 13 };
    int i;
    for (i = 0; i < 3000; i++) {
        double te[24], tf[24], e[32], f[32], h[64], all[48];
        int ne = 1 + (int)(geomtest_u64(&r) % 20), nf = 1 + (int)(geomtest_u64(&r) % 20);
        int le = random_expansion(&r, ne, te, e), lf = random_expansion(&r, nf, tf, f), lh, j;
        ck_assert(well_formed(e, le));
        ck_assert(oracle_expansion_equals(e, le, te, ne, NULL, NULL, 0));
        if (i % 7 == 0) { /* exact cancellation to zero */
            for (j = 0; j < le; j++)
                f[j] = -e[j];
            lf = le;
            for (j = 0; j < ne; j++)
                tf[j] = -te[j];
            nf = ne;
        }
        lh = cvm__fast_expansion_sum_zeroelim(le, e, lf, f, h);
        ck_assert_int_le(lh, le + lf);
        ck_assert(well_formed(h, lh));
        for (j = 0; j < ne; j++)
            all[j] = te[j];
        for (j = 0; j < nf; j++)
            all[ne + j] = tf[j];
        ck_assert(oracle_expansion_equals(h, lh, all, ne + nf, NULL, NULL, 0));
        if (i % 7 == 0)
            ck_assert(lh == 1 && h[0] == 0.0);
        /* the estimate has the sign of the exact sum */
        ck_assert_int_eq(geomtest_sign(cvm__estimate(lh, h)), geomtest_sign(h[lh - 1]));
    }
}
END_TEST

START_TEST(scale_expansion_is_exact_and_nonoverlapping)
{
    geomtest_rng r = { 14 };
    int i, j;
    for (i = 0; i < 3000; i++) {
        double te[16], e[32], h[64], pa[32], pb[32];
        int ne = 1 + (int)(geomtest_u64(&r) % 12), le = random_expansion(&r, ne, te, e), lh;
        double b = (i % 5 == 0) ? 0.0 : wide(&r, -80, 80);
        lh = cvm__scale_expansion_zeroelim(le, e, b, h);
        ck_assert_int_le(lh, 2 * le);
        ck_assert(well_formed(h, lh));
        for (j = 0; j < le; j++)
            pa[j] = e[j], pb[j] = b;
        ck_assert(oracle_expansion_equals(h, lh, NULL, 0, pa, pb, le));
    }
}
END_TEST

START_TEST(rescale_exponent_brings_extremes_to_one)
{
    double ms[] = { 1e-300, 4.9e-324, 1e-30, 1e30, 1e300, DBL_MAX, 0x1p-61, 0x1p61 };
    size_t i;
    ck_assert_int_eq(cvm__rescale_exponent(0.0), 0);
    ck_assert_int_eq(cvm__rescale_exponent(1.0), 0);
    ck_assert_int_eq(cvm__rescale_exponent(0x1p60), 0);
    ck_assert_int_eq(cvm__rescale_exponent(0x1p-60), 0);
    for (i = 0; i < sizeof ms / sizeof ms[0]; i++) {
        int k = cvm__rescale_exponent(ms[i]);
        double s = ldexp(ms[i], k);
        ck_assert(s >= 1.0 && s < 2.0);
    }
    ck_assert(cvm__unscale(3.0, 2, 0) == 3.0);
    ck_assert(cvm__unscale(-3.0, 4, 600) == -0x1p-1074); /* underflow keeps the sign */
    ck_assert(cvm__unscale(3.0, 4, -600) == DBL_MAX);    /* overflow saturates */
    ck_assert(cvm__unscale(0.0, 4, 600) == 0.0);
    ck_assert(cvm__unscale(1.5, 2, 10) == 1.5 * 0x1p-20);
}
END_TEST

TCase *geom_expansion_tcase(void)
{
    TCase *tc = tcase_create("expansion");
    tcase_add_test(tc, two_sum_and_two_diff_are_error_free);
    tcase_add_test(tc, two_product_and_two_two_diff_are_error_free);
    tcase_add_test(tc, grow_and_sum_are_exact_and_nonoverlapping);
    tcase_add_test(tc, scale_expansion_is_exact_and_nonoverlapping);
    tcase_add_test(tc, rescale_exponent_brings_extremes_to_one);
    tcase_set_timeout(tc, 60);
    return tc;
}
