/*
 * fmt_double.c - "%.15g"/"%.16g"/"%.17g" text of a double, the first that
 * reads back exactly, computed with 128-bit integer arithmetic.
 *
 * x = m * 2^e. With q the decimal exponent of x's leading digit minus 16,
 * X = x * 10^-q * 2^64 is formed as m * P >> s from the table entry
 * 10^-q ~= P * 2^b: the integer part of X / 2^64 holds x's first 17 decimal
 * digits and the low 64 bits the fraction beyond them. The 15, 16 and 17
 * digit roundings of x then follow from X by integer division, and a
 * rounding D * 10^t reads back to x exactly when it lies strictly inside the
 * interval of reals that round to x: within half an ulp above x and half the
 * gap to x's predecessor below, measured with H = 2^(e-1) * 10^-q * 2^64
 * (half an ulp) in the same units.
 *
 * When P is exact (0 <= -q <= 55) and no bits are shifted out, X and H are
 * exact and every comparison is decided exactly; otherwise X and H are each
 * within 2 units of the truth (P's relative error is below 2^-128 and X <
 * 2^122), so a comparison closer than MARGIN units is left undecided and the
 * caller falls back to the C library. Exact ties are settled as printf and
 * strtod settle them when rounding to nearest: a digit string ending in
 * exactly 5 rounds to even, and a decimal exactly halfway between x and a
 * neighbour reads back to whichever has an even significand. In any other
 * rounding mode the caller is left to use the C library.
 */
#include <fenv.h>
#include <string.h>

#include "fmt_double.h"

#if defined(__SIZEOF_INT128__) && (defined(__GNUC__) || defined(__clang__))

__extension__ typedef unsigned __int128 u128;

#define MARGIN 8

static const uint64_t POW10_U64[] = {1ull,
                                     10ull,
                                     100ull,
                                     1000ull,
                                     10000ull,
                                     100000ull,
                                     1000000ull,
                                     10000000ull,
                                     100000000ull,
                                     1000000000ull,
                                     10000000000ull,
                                     100000000000ull,
                                     1000000000000ull,
                                     10000000000000ull,
                                     100000000000000ull,
                                     1000000000000000ull,
                                     10000000000000000ull,
                                     100000000000000000ull,
                                     1000000000000000000ull};

static const char DIGIT_PAIRS[] = "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
                                  "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
                                  "8081828384858687888990919293949596979899";

/* |a - b| <= margin; with margin 0, a == b. */
static int near(u128 a, u128 b, u128 margin)
{
    return (a > b ? a - b : b - a) <= margin;
}

/* floor(e2 * log10(2)) give or take one (the caller corrects). */
static int log10_pow2(int e2)
{
    long t = (long)e2 * 78913L;
    return (int)(t >= 0 ? t / 262144L : -((-t + 262143L) / 262144L));
}

/* X = m * 10^k * 2^(e + 64) and H = 2^(e-1) * 10^k * 2^64, truncated;
 * *exact = 1 when both are exact. 0 when k or the shift is out of range. */
static int scale(u128 *X, u128 *H, int *exact, uint64_t m, int e, int k)
{
    const cvm__pow10_entry *p;
    u128 a, c, mid;
    uint64_t w0, w1, w2;
    int s, lost;
    if (k < CVM__POW10_KMIN || k > CVM__POW10_KMAX)
        return 0;
    p = &cvm__pow10_table[k - CVM__POW10_KMIN];
    s = -(e + p->b + 64);
    if (s < 1 || s > 126)
        return 0;
    a = (u128)m * p->lo;
    c = (u128)m * p->hi;
    mid = (a >> 64) + (uint64_t)c;
    w0 = (uint64_t)a;
    w1 = (uint64_t)mid;
    w2 = (uint64_t)(c >> 64) + (uint64_t)(mid >> 64);
    if (s >= 64) {
        int t = s - 64;
        *X = (((u128)w2 << 64) | w1) >> t;
        lost = w0 != 0 || (t > 0 && (w1 << (64 - t)) != 0);
    } else {
        if (w2 >> s)
            return 0;
        *X = ((u128)w2 << (128 - s)) | ((((u128)w1 << 64) | w0) >> s);
        lost = (w0 << (64 - s)) != 0;
    }
    {
        u128 P = ((u128)p->hi << 64) | p->lo;
        int sh = s + 1;
        *H = P >> sh;
        lost |= (P << (128 - sh)) != 0;
    }
    *exact = k >= 0 && k <= 55 && !lost;
    return 1;
}

/* Text of the digits d (n of them, no trailing zero unless n == 1) times
 * 10^(exp10 - n + 1), as %g with precision prec would print it. */
static size_t layout(char *buf, int neg, uint64_t d, int n, int exp10, int prec)
{
    char dig[20];
    size_t len = 0;
    int i;
    for (i = n; i >= 2; i -= 2) {
        memcpy(dig + i - 2, DIGIT_PAIRS + 2 * (d % 100), 2);
        d /= 100;
    }
    if (i == 1)
        dig[0] = (char)('0' + d);
    if (neg)
        buf[len++] = '-';
    if (exp10 < -4 || exp10 >= prec) {
        unsigned ae = (unsigned)(exp10 < 0 ? -exp10 : exp10);
        buf[len++] = dig[0];
        if (n > 1) {
            buf[len++] = '.';
            memcpy(buf + len, dig + 1, (size_t)n - 1);
            len += (size_t)n - 1;
        }
        buf[len++] = 'e';
        buf[len++] = exp10 < 0 ? '-' : '+';
        if (ae >= 100)
            buf[len++] = (char)('0' + ae / 100);
        buf[len++] = (char)('0' + ae / 10 % 10);
        buf[len++] = (char)('0' + ae % 10);
    } else if (exp10 >= 0) {
        int ni = exp10 + 1; /* digits before the point */
        for (i = 0; i < ni; i++)
            buf[len++] = i < n ? dig[i] : '0';
        if (n > ni) {
            buf[len++] = '.';
            memcpy(buf + len, dig + ni, (size_t)(n - ni));
            len += (size_t)(n - ni);
        }
    } else {
        buf[len++] = '0';
        buf[len++] = '.';
        for (i = 0; i < -exp10 - 1; i++)
            buf[len++] = '0';
        memcpy(buf + len, dig, (size_t)n);
        len += (size_t)n;
    }
    buf[len] = '\0';
    return len;
}

/* layout() of D, the prec digits of x rounded, times 10^(exp10 - prec + 1): a
 * round-up to 10^prec carries into the exponent, trailing zeros are dropped. */
static size_t layout_rounded(char *buf, int neg, uint64_t D, int exp10, int prec)
{
    int n = prec;
    if (D == POW10_U64[prec]) {
        D /= 10;
        exp10++;
    }
    while (n > 1 && D % 10 == 0) {
        D /= 10;
        n--;
    }
    return layout(buf, neg, D, n, exp10, prec);
}

/* The integers from 10^17 to below 2^123: v = m * 2^e is formed exactly, so
 * every rounding and round-trip decision is exact here too, where the
 * inexact table entries for negative powers would leave the frequent exact
 * ties of integers undecided. below2 is twice the gap to the half-way point
 * below, in units of 2^(e-1). */
static size_t format_big_int(char *buf, int neg, uint64_t m, int e, int pow2)
{
    u128 v = (u128)m << e, top = (u128)POW10_U64[17] * 10, div;
    int e10 = 17, prec;
    while (v >= top) {
        top *= 10;
        e10++;
    }
    for (prec = 15; prec <= 17; prec++) {
        int t;
        uint64_t D;
        u128 r;
        for (t = 0, div = 1; t < e10 - prec + 1; t++)
            div *= 10;
        D = (uint64_t)(v / div);
        r = v % div;
        if (2 * r > div || (2 * r == div && (D & 1)))
            D++;
        if (prec < 17) {
            u128 C = (u128)D * div, diff2 = 2 * (C >= v ? C - v : v - C);
            u128 bound2 = C >= v || !pow2 ? (u128)1 << e : (u128)1 << (e - 1);
            if (diff2 > bound2 || (diff2 == bound2 && (m & 1)))
                continue;
        }
        return layout_rounded(buf, neg, D, e10, prec);
    }
    return 0;
}

size_t cvm__format_double_fast(char *buf, double x)
{
    uint64_t bits, frac, m, I, F, Iv[3];
    int be, e, e10, tries, exact, prec;
    u128 X = 0, H = 0, lo = (u128)POW10_U64[16] << 64, hi = (u128)POW10_U64[17] << 64, margin, below2;
    int neg;
    memcpy(&bits, &x, sizeof bits);
    neg = (int)(bits >> 63);
    be = (int)(bits >> 52 & 0x7ff);
    frac = bits & ((1ull << 52) - 1);
    if (be == 0x7ff || fegetround() != FE_TONEAREST)
        return 0;
    if (be == 0 && frac == 0) {
        size_t len = 0;
        if (neg)
            buf[len++] = '-';
        buf[len++] = '0';
        buf[len] = '\0';
        return len;
    }
    m = be ? frac | (1ull << 52) : frac;
    e = be ? be - 1075 : -1074;
    if (e >= 4 && e <= 70 && ((u128)m << e) >= (u128)POW10_U64[17])
        return format_big_int(buf, neg, m, e, frac == 0);
    e10 = log10_pow2(e + 63 - __builtin_clzll(m));
    for (tries = 0;; tries++) {
        if (tries == 3 || !scale(&X, &H, &exact, m, e, 16 - e10))
            return 0;
        margin = exact ? 0 : MARGIN;
        if (X + margin < lo)
            e10--;
        else if (X >= hi + margin)
            e10++;
        else if (X < lo + margin || X + margin >= hi)
            return 0; /* within the error of a power of ten */
        else
            break;
    }
    /* Twice the half-widths of the interval of reals that round to x: 2H
     * above; below too, except at a power of two (not the smallest normal),
     * whose predecessor is half as far away. Doubled so both stay integers. */
    below2 = frac == 0 && be > 1 ? H : 2 * H;
    I = (uint64_t)(X >> 64);
    F = (uint64_t)X;
    /* divided by constants ahead: multiplications, not divide instructions */
    Iv[0] = I / 100;
    Iv[1] = I / 10;
    Iv[2] = I;
    for (prec = 15; prec <= 17; prec++) {
        uint64_t d = POW10_U64[17 - prec], D = Iv[prec - 15];
        u128 rem = ((u128)(I - D * d) << 64) | F, half = (u128)d << 63, C, diff;
        if (rem == half && exact) {
            D += D & 1; /* a tie: to even, as printf rounds to nearest */
        } else {
            if (near(rem, half, margin))
                return 0;
            D += rem > half;
        }
        if (prec < 17) {
            u128 bound2;
            C = (u128)(D * d) << 64;
            diff = 2 * (C >= X ? C - X : X - C);
            bound2 = C >= X ? 2 * H : below2;
            if (diff == bound2 && exact) {
                if (m & 1)
                    continue; /* halfway to a neighbour, which is even: strtod picks it */
            } else {
                if (near(diff, bound2, 2 * margin))
                    return 0;
                if (diff > bound2)
                    continue; /* does not read back to x */
            }
        }
        return layout_rounded(buf, neg, D, e10, prec);
    }
    return 0;
}

#else

size_t cvm__format_double_fast(char *buf, double x)
{
    (void)buf;
    (void)x;
    return 0;
}

#endif
