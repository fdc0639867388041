/* test_fmt_double.c - the fast double formatter gives the C library's bytes; integers as %lld. */
#include <fenv.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/fmt_double.h"
#include "io/io_tests.h"
#include "io/io_text.h"

static uint64_t next(uint64_t *z)
{
    *z ^= *z << 13;
    *z ^= *z >> 7;
    *z ^= *z << 17;
    return *z;
}

typedef struct tally {
    long tried, fast;
} tally;

/* x's fast text, when the fast path gives one, equals the reference text. */
static void same_as_libc(tally *t, double x)
{
    char fast[64], ref[64];
    size_t nf, nr;
    if (!isfinite(x))
        return;
    t->tried++;
    nf = cvm__format_double_fast(fast, x);
    if (nf == 0)
        return;
    t->fast++;
    nr = cvm__format_double_libc(ref, x);
    ck_assert_msg(nf == nr && strcmp(fast, ref) == 0, "%a: fast \"%s\", libc \"%s\"", x, fast, ref);
    ck_assert_uint_eq(strlen(fast), nf);
}

static double from_bits(uint64_t b)
{
    double x;
    memcpy(&x, &b, sizeof x);
    return x;
}

/* x and its two neighbours. */
static void around(tally *t, double x)
{
    same_as_libc(t, x);
    same_as_libc(t, nextafter(x, HUGE_VAL));
    same_as_libc(t, nextafter(x, -HUGE_VAL));
}

/* The fast path must carry nearly everything, or it is no faster. */
static void mostly_fast(const tally *t)
{
#if defined(__SIZEOF_INT128__) && (defined(__GNUC__) || defined(__clang__))
    ck_assert_msg(t->fast >= t->tried - t->tried / 1000, "fast path took %ld of %ld", t->fast, t->tried);
#else
    (void)t;
#endif
}

START_TEST(fast_format_matches_libc_on_random_bit_patterns)
{
    tally t = {0, 0};
    uint64_t z = 0x9E3779B97F4A7C15ull;
    long i;
    for (i = 0; i < 800000; i++)
        same_as_libc(&t, from_bits(next(&z)));
    ck_assert_int_gt(t.tried, 790000);
    mostly_fast(&t);
}
END_TEST

START_TEST(fast_format_matches_libc_on_subnormals_and_extremes)
{
    static const double ext[] = {DBL_MAX, DBL_MIN, 4.9406564584124654e-324, 2.2250738585072009e-308,
                                 1.7976931348623155e308, 0.0, 1.0, 0.1, 0.5, 9007199254740992.0,
                                 9007199254740993.0, 1e15, 1e16, 1e17, 1e22, 1e23, 5e-324, 1e-5, 1e-4};
    tally t = {0, 0};
    uint64_t z = 12345;
    size_t i;
    char buf[64];
    for (i = 0; i < sizeof ext / sizeof ext[0]; i++) {
        around(&t, ext[i]);
        around(&t, -ext[i]);
    }
    for (i = 0; i < 50000; i++) /* subnormals, either sign */
        same_as_libc(&t, from_bits(next(&z) & 0x800FFFFFFFFFFFFFull));
    for (i = 0; i < 2100; i++) /* every power of two, 2^-1074 .. 2^1023 */
        around(&t, ldexp(1.0, (int)i - 1074));
    for (i = 0; i < 633; i++) { /* the doubles nearest every power of ten */
        snprintf(buf, sizeof buf, "1e%d", (int)i - 324);
        around(&t, strtod(buf, NULL));
    }
    ck_assert_uint_eq(cvm__format_double_fast(buf, -0.0), 2);
    ck_assert_str_eq(buf, "-0");
    ck_assert_uint_eq(cvm__format_double_fast(buf, 0.0), 1);
    ck_assert_str_eq(buf, "0");
    ck_assert_uint_eq(cvm__format_double_fast(buf, HUGE_VAL), 0);
    ck_assert_uint_eq(cvm__format_double_fast(buf, NAN), 0);
    mostly_fast(&t);
}
END_TEST

/* Integers, halves and decimals of 15 to 19 digits: exact ties in the
 * rounding to 15, 16 or 17 digits, and decimals halfway between doubles. */
START_TEST(fast_format_matches_libc_on_ties_and_integers)
{
    tally t = {0, 0};
    uint64_t z = 777;
    long i;
    char buf[64];
    for (i = 0; i < 20000; i++)
        same_as_libc(&t, (double)i);
    for (i = 0; i < 60000; i++) {
        uint64_t r = next(&z);
        same_as_libc(&t, (double)(r >> (r % 64))); /* integers of every size */
        same_as_libc(&t, (double)(r >> 11 >> (r % 40)) + 0.5);
        same_as_libc(&t, (double)(r % 100000000000000000ull) / (double)(1u << (next(&z) % 12)));
    }
    for (i = 0; i < 60000; i++) {
        uint64_t r = next(&z);
        snprintf(buf, sizeof buf, "%llu%se%d", (unsigned long long)(r % 10000000000000000000ull),
                 (r & 1) ? "5" : "", (int)(next(&z) % 660) - 345);
        around(&t, strtod(buf, NULL));
    }
    mostly_fast(&t);
}
END_TEST

/* Coordinates as meshes have them: decimals of a few digits at any scale. */
START_TEST(fast_format_matches_libc_on_short_decimals)
{
    tally t = {0, 0};
    uint64_t z = 4242;
    long i;
    for (i = 0; i < 60000; i++) {
        uint64_t r = next(&z);
        same_as_libc(&t, (double)(r % 100000000) * pow(10.0, (double)((int)(next(&z) % 60) - 30)));
        same_as_libc(&t, (double)(r >> 11) * 0x1p-53);
    }
    mostly_fast(&t);
}
END_TEST

/* printf and strtod follow the rounding mode: in another mode the fast
 * path steps aside and the output stays the C library's. */
START_TEST(format_double_follows_libc_in_other_rounding_modes)
{
    static const int modes[] = {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO};
    static const double vals[] = {0.1, 1.0 / 3.0, 2.5e15 + 0.5, 7826059021929695.0, 1e23, 5e-324};
    size_t i, k;
    for (k = 0; k < sizeof modes / sizeof modes[0]; k++) {
        if (fesetround(modes[k]) != 0)
            continue;
        for (i = 0; i < sizeof vals / sizeof vals[0]; i++) {
            char a[64], b[64], c[64];
            ck_assert_uint_eq(cvm__format_double_fast(c, vals[i]), 0);
            cvm__format_double(a, vals[i]);
            cvm__format_double_libc(b, vals[i]);
            ck_assert_str_eq(a, b);
        }
        fesetround(FE_TONEAREST);
    }
}
END_TEST

START_TEST(format_long_matches_printf)
{
    static const long long vals[] = {0, 1, -1, 9, 10, 99, 100, 101, 999, 1000, -1000, 123456789,
                                     2147483647, -2147483647 - 1, LLONG_MAX, LLONG_MIN};
    char a[CVM__INT_BUF], b[64];
    uint64_t z = 99;
    size_t i;
    for (i = 0; i < sizeof vals / sizeof vals[0]; i++) {
        snprintf(b, sizeof b, "%lld", vals[i]);
        ck_assert_uint_eq(cvm__format_long(a, vals[i]), strlen(b));
        ck_assert_str_eq(a, b);
    }
    snprintf(b, sizeof b, "%llu", ULLONG_MAX);
    ck_assert_uint_eq(cvm__format_ulong(a, ULLONG_MAX), strlen(b));
    ck_assert_str_eq(a, b);
    for (i = 0; i < 100000; i++) {
        long long v = (long long)(next(&z) >> (next(&z) % 64));
        if (i & 1)
            v = -v;
        snprintf(b, sizeof b, "%lld", v);
        ck_assert_uint_eq(cvm__format_long(a, v), strlen(b));
        ck_assert_str_eq(a, b);
    }
}
END_TEST

#if defined(__SIZEOF_INT128__) && (defined(__GNUC__) || defined(__clang__))
__extension__ typedef unsigned __int128 u128;

/* Each entry is ten times the one before, renormalised: exactly while 10^k
 * is an integer below 2^128 (k <= 55), within rounding after. 10^0 = 2^127 * 2^-127
 * anchors the chain. */
START_TEST(power_of_ten_table_is_consistent)
{
    const cvm__pow10_entry *t = cvm__pow10_table;
    int k;
    ck_assert(t[-CVM__POW10_KMIN].hi == 1ull << 63 && t[-CVM__POW10_KMIN].lo == 0);
    ck_assert_int_eq(t[-CVM__POW10_KMIN].b, -127);
    for (k = CVM__POW10_KMIN; k < CVM__POW10_KMAX; k++) {
        const cvm__pow10_entry *p = &t[k - CVM__POW10_KMIN], *q = p + 1;
        u128 P = ((u128)p->hi << 64) | p->lo, Q = ((u128)q->hi << 64) | q->lo;
        /* P * 10 = P * 8 + P * 2 has 131 or 132 bits: keep the top 128 */
        u128 lo8 = P << 3, lo2 = P << 1, low = lo8 + lo2;
        uint64_t high = (uint64_t)(P >> 125) + (uint64_t)(P >> 127) + (low < lo8);
        int sh = high >> 3 ? 4 : 3;
        u128 R = ((u128)high << (128 - sh)) | (low >> sh);
        int lost = (low << (128 - sh)) != 0;
        ck_assert_msg(q->hi >> 63, "10^%d not normalised", k + 1);
        ck_assert_msg(q->b == p->b + sh, "10^%d: exponent %d, expected %d", k + 1, (int)q->b, (int)p->b + sh);
        if (k >= 0 && k < 55) {
            ck_assert_msg(!lost && R == Q, "10^%d is not exact", k + 1);
        } else {
            u128 d = R > Q ? R - Q : Q - R;
            ck_assert_msg(d <= 2, "10^%d differs from 10 * 10^%d by more than rounding", k + 1, k);
        }
    }
}
END_TEST
#endif

TCase *io_fmt_double_tcase(void)
{
    TCase *tc = tcase_create("fmt_double");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, fast_format_matches_libc_on_random_bit_patterns);
    tcase_add_test(tc, fast_format_matches_libc_on_subnormals_and_extremes);
    tcase_add_test(tc, fast_format_matches_libc_on_ties_and_integers);
    tcase_add_test(tc, fast_format_matches_libc_on_short_decimals);
    tcase_add_test(tc, format_double_follows_libc_in_other_rounding_modes);
    tcase_add_test(tc, format_long_matches_printf);
#if defined(__SIZEOF_INT128__) && (defined(__GNUC__) || defined(__clang__))
    tcase_add_test(tc, power_of_ten_table_is_consistent);
#endif
    return tc;
}
