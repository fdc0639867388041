/* test_power_side.c - the exact side-of-edge test of the power vertex (lib/dual/power_side.c). */
#include <math.h>
#include <stdint.h>

#include "dual/dual_tests.h"
#include "dual/dual_internal.h"

/* splitmix64: the test's own generator. */
static uint64_t next(uint64_t *s)
{
    uint64_t z = (*s += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

static long irand(uint64_t *s, long lo, long hi)
{
    return lo + (long)(next(s) % (uint64_t)(hi - lo + 1));
}

/* The defining determinant in 64-bit integers (|values| < 2^62 here). */
static int int_side(const long *a, const long *b, const long *c, long wa, long wb, long wc)
{
    int64_t bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
    int64_t bb = bx * bx + by * by, cc = cx * cx + cy * cy, bc = bx * cx + by * cy;
    int64_t d = bb * (cc + wa - wc) - bc * (bb + wa - wb);
    return d > 0 ? 1 : d < 0 ? -1 : 0;
}

static int dbl_side(const long *a, const long *b, const long *c, long wa, long wb, long wc,
                    int k)
{
    double pa[2], pb[2], pc[2];
    int i;
    for (i = 0; i < 2; i++) {
        pa[i] = ldexp((double)a[i], k);
        pb[i] = ldexp((double)b[i], k);
        pc[i] = ldexp((double)c[i], k);
    }
    return cvm__power_side2d(pa, pb, pc, ldexp((double)wa, 2 * k), ldexp((double)wb, 2 * k),
                             ldexp((double)wc, 2 * k));
}

/* Small integer triangles and weights, ties included, at three scales
 * (weights scale by 2^2k, so 2^-400 and 2^450 keep them normal doubles). */
START_TEST(power_side_agrees_with_integer_arithmetic)
{
    uint64_t s = 12345;
    int n, zeros = 0, scales[3] = {0, -400, 450}, k;
    for (n = 0; n < 20000; n++) {
        long a[2], b[2], c[2], wa, wb, wc;
        int want;
        a[0] = irand(&s, -8, 8); a[1] = irand(&s, -8, 8);
        b[0] = irand(&s, -8, 8); b[1] = irand(&s, -8, 8);
        c[0] = irand(&s, -8, 8); c[1] = irand(&s, -8, 8);
        if ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) <= 0)
            continue; /* counter-clockwise triangles only */
        wa = n % 3 ? irand(&s, -64, 64) : 0;
        wb = n % 3 ? irand(&s, -64, 64) : 0;
        wc = n % 3 ? irand(&s, -64, 64) : 0;
        want = int_side(a, b, c, wa, wb, wc);
        zeros += want == 0;
        for (k = 0; k < 3; k++)
            ck_assert_msg(dbl_side(a, b, c, wa, wb, wc, scales[k]) == want, "scale %d: a (%ld %ld) b (%ld %ld) c (%ld %ld) w %ld %ld %ld want %d", scales[k], a[0], a[1], b[0], b[1], c[0], c[1], wa, wb, wc, want);
    }
    ck_assert_int_gt(zeros, 20); /* the battery does contain exact ties */
}
END_TEST

/* Without weights the test is "angle at c acute": (a - c).(b - c) > 0. */
START_TEST(power_side_without_weights_is_angle_test)
{
    static const double a[2] = {0, 0}, b[2] = {2, 0};
    static const double acute[2] = {1, 5}, right[2] = {1, 1}, obtuse[2] = {1, 0.5};
    ck_assert_int_eq(cvm__power_side2d(a, b, acute, 0, 0, 0), 1);
    ck_assert_int_eq(cvm__power_side2d(a, b, right, 0, 0, 0), 0);
    ck_assert_int_eq(cvm__power_side2d(a, b, obtuse, 0, 0, 0), -1);
    /* one ulp above the right angle decides exactly */
    {
        double up[2] = {1, nextafter(1.0, 2.0)}, dn[2] = {1, nextafter(1.0, 0.0)};
        ck_assert_int_eq(cvm__power_side2d(a, b, up, 0, 0, 0), 1);
        ck_assert_int_eq(cvm__power_side2d(a, b, dn, 0, 0, 0), -1);
    }
}
END_TEST

/* Coordinates far from the origin with tiny differences and weights: the
 * filter must hand the close cases to the exact stage. */
START_TEST(power_side_near_ties_far_from_origin)
{
    uint64_t s = 99;
    int n;
    for (n = 0; n < 5000; n++) {
        long a[2], b[2], c[2], wa = irand(&s, -9, 9), wb = irand(&s, -9, 9), wc = irand(&s, -9, 9);
        double pa[2], pb[2], pc[2], off = 1e6; /* 1e6 + small integers: exact doubles */
        int i;
        a[0] = irand(&s, -4, 4); a[1] = irand(&s, -4, 4);
        b[0] = irand(&s, -4, 4); b[1] = irand(&s, -4, 4);
        c[0] = irand(&s, -4, 4); c[1] = irand(&s, -4, 4);
        if ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) <= 0)
            continue;
        for (i = 0; i < 2; i++) {
            pa[i] = off + (double)a[i];
            pb[i] = off + (double)b[i];
            pc[i] = off + (double)c[i];
        }
        ck_assert_int_eq(cvm__power_side2d(pa, pb, pc, (double)wa + 1e12, (double)wb + 1e12,
                                           (double)wc + 1e12),
                         int_side(a, b, c, wa, wb, wc));
    }
}
END_TEST

TCase *dual_power_side_tcase(void)
{
    TCase *tc = tcase_create("power_side");
    tcase_add_test(tc, power_side_agrees_with_integer_arithmetic);
    tcase_add_test(tc, power_side_without_weights_is_angle_test);
    tcase_add_test(tc, power_side_near_ties_far_from_origin);
    return tc;
}
