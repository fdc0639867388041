/* expansion.h - error-free transformations and expansion arithmetic after Shewchuk (1997). */
#ifndef CVM_GEOM_EXPANSION_H
#define CVM_GEOM_EXPANSION_H

#include <math.h>

/*
 * An expansion is an array of doubles whose exact sum is the represented value,
 * sorted by increasing magnitude, nonoverlapping (Shewchuk, section 2). The
 * *_zeroelim routines drop zero components but always return at least one.
 *
 * Everything here assumes IEEE 754 binary64, round-to-nearest-even, and no
 * overflow or underflow; the predicates rescale their inputs by a power of two
 * before the exact stages so that this holds (see cvm__rescale_exponent).
 *
 * Contraction safety: the filters tolerate a*b+c being fused into fma (that only
 * removes roundings). The one place where fusing would break exactness is
 * Dekker's split inside two_product; when the target has fast fma
 * (FP_FAST_FMA) two_product uses fma() instead, so neither -march=native nor
 * -ffp-contract=fast can make the compiler fuse the split.
 */

/* Unit roundoff epsilon = 2^-53; the error bounds are polynomials in it. */
#define CVM__EPS 0x1p-53
/* 2^ceil(53/2) + 1, Dekker's splitter. */
#define CVM__SPLITTER 134217729.0
/* Relative error of estimating an expansion (Shewchuk's resulterrbound). */
#define CVM__RESULTERRBOUND ((3.0 + 8.0 * CVM__EPS) * CVM__EPS)

#if defined(__GNUC__)
#define CVM__NOINLINE __attribute__((noinline))
#else
#define CVM__NOINLINE
#endif

/* max(|a|, m) for finite a: the exact stages' range checks (no libm call). */
static inline double cvm__maxabs(double m, double a)
{
    double b = fabs(a);
    return b > m ? b : m;
}

/* x + y == a + b exactly, x = fl(a + b); requires |a| >= |b| (or a == 0). */
static inline void cvm__fast_two_sum(double a, double b, double *x, double *y)
{
    double s = a + b;
    double bv = s - a;
    *x = s;
    *y = b - bv;
}

/* x + y == a + b exactly, x = fl(a + b) (Knuth's TwoSum, no precondition). */
static inline void cvm__two_sum(double a, double b, double *x, double *y)
{
    double s = a + b;
    double bv = s - a;
    double av = s - bv;
    double br = b - bv;
    double ar = a - av;
    *x = s;
    *y = ar + br;
}

/* y = (a - b) - x exactly, where x was computed as fl(a - b). */
static inline double cvm__two_diff_tail(double a, double b, double x)
{
    double bv = a - x;
    double av = x + bv;
    double br = bv - b;
    double ar = a - av;
    return ar + br;
}

/* x + y == a - b exactly, x = fl(a - b). */
static inline void cvm__two_diff(double a, double b, double *x, double *y)
{
    double d = a - b;
    *x = d;
    *y = cvm__two_diff_tail(a, b, d);
}

/* a == hi + lo with hi, lo of at most 26 significant bits each (Dekker). */
static inline void cvm__split(double a, double *hi, double *lo)
{
    double c = CVM__SPLITTER * a;
    double abig = c - a;
    double h = c - abig;
    *hi = h;
    *lo = a - h;
}

/* y = a*b - x exactly, where x = fl(a*b) and b == bhi + blo is split. */
static inline double cvm__two_product_tail(double a, double b, double bhi, double blo, double x)
{
#if defined(FP_FAST_FMA)
    (void)bhi;
    (void)blo;
    return fma(a, b, -x);
#else
    double ahi, alo, err1, err2, err3;
    (void)b;
    cvm__split(a, &ahi, &alo);
    err1 = x - ahi * bhi;
    err2 = err1 - alo * bhi;
    err3 = err2 - ahi * blo;
    return alo * blo - err3;
#endif
}

/* x + y == a * b exactly, x = fl(a * b). */
static inline void cvm__two_product(double a, double b, double *x, double *y)
{
    double p = a * b;
    double bhi = 0.0, blo = 0.0;
#if !defined(FP_FAST_FMA)
    cvm__split(b, &bhi, &blo);
#endif
    *x = p;
    *y = cvm__two_product_tail(a, b, bhi, blo, p);
}

/* x[0..3] (increasing magnitude) == (a1 + a0) - (b1 + b0) exactly. */
static inline void cvm__two_two_diff(double a1, double a0, double b1, double b0, double *x)
{
    double i, j, k, z;
    /* (a1 + a0) - b0 = j + k + x0 */
    cvm__two_diff(a0, b0, &i, &x[0]);
    cvm__two_sum(a1, i, &j, &k);
    /* (j + k) - b1 = x3 + x2 + x1 */
    cvm__two_diff(k, b1, &i, &x[1]);
    cvm__two_sum(j, i, &z, &x[2]);
    x[3] = z;
}

/* h = a*d - b*c exactly as an expansion without zero components (1 to 4 of
 * them); returns the length. The 2x2 minor every determinant is built from. */
static inline int cvm__cross_zeroelim(double a, double d, double b, double c, double *h)
{
    double l1, l0, r1, r0, x[4];
    int i, n = 0;
    cvm__two_product(a, d, &l1, &l0);
    cvm__two_product(b, c, &r1, &r0);
    if (l0 == 0.0 && r0 == 0.0) { /* both products exact: common for grid-like input */
        cvm__two_diff(l1, r1, &x[1], &x[0]);
        if (x[0] != 0.0)
            h[n++] = x[0];
        h[n++] = x[1];
        return n;
    }
    cvm__two_two_diff(l1, l0, r1, r0, x);
    for (i = 0; i < 4; i++)
        if (x[i] != 0.0)
            h[n++] = x[i];
    if (n == 0)
        h[n++] = 0.0;
    return n;
}

/* h = e + b; h has room for elen + 1 components; returns the length of h. */
int cvm__grow_expansion_zeroelim(int elen, const double *e, double b, double *h);

/* h = e + f; h (distinct from e and f) has room for elen + flen components. */
int cvm__fast_expansion_sum_zeroelim(int elen, const double *e, int flen, const double *f,
                                     double *h);

/* h = b * e; h (distinct from e) has room for 2 * elen components. */
int cvm__scale_expansion_zeroelim(int elen, const double *e, double b, double *h);

/* A double close to the value of e (the sum of its components, smallest first). */
double cvm__estimate(int elen, const double *e);

/*
 * Power-of-two rescaling for the exact stages. m is the largest magnitude among
 * a predicate's coordinates (for weights, the square root of the largest |w|).
 * Returns 0 when m is 0 or lies in [2^-60, 2^60], where no exact stage can
 * overflow or lose bits to underflow as long as every nonzero coordinate is at
 * least 2^-100 * m; otherwise returns k with m * 2^k in [1, 2). Multiplying all
 * coordinates by 2^k (weights by 2^2k) is exact and scales a degree-n
 * determinant by the positive 2^(n k), so its sign is unchanged.
 */
int cvm__rescale_exponent(double m);

/* det * 2^-(degree * k) saturated to a nonzero finite double with det's sign
 * (0 stays 0): undoes a rescale for the returned magnitude. */
double cvm__unscale(double det, int degree, int k);

#endif
