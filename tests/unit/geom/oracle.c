/* oracle.c - slow exact determinant signs for double inputs with a small bignum, independent of lib/geom. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "geom/geom_tests.h"

/*
 * Every double is an integer times 2^e. All inputs of one call are written as
 * integers times a common 2^E (weights times 2^2E), so each determinant is
 * evaluated by schoolbook integer arithmetic on sign-magnitude numbers. It
 * shares nothing with the expansion code it checks.
 */

#define BIG_LIMBS 200 /* 6400 bits */

typedef struct {
    int neg;
    int n; /* limbs in use, no leading zero limbs; 0 means zero */
    uint32_t d[BIG_LIMBS];
} big;

static void big_fail(void)
{
    abort(); /* capacity exceeded: a test input outside the oracle's range */
}

static void big_trim(big *x)
{
    while (x->n > 0 && x->d[x->n - 1] == 0)
        x->n--;
    if (x->n == 0)
        x->neg = 0;
}

static int mag_cmp(const big *a, const big *b)
{
    int i;
    if (a->n != b->n)
        return a->n < b->n ? -1 : 1;
    for (i = a->n - 1; i >= 0; i--)
        if (a->d[i] != b->d[i])
            return a->d[i] < b->d[i] ? -1 : 1;
    return 0;
}

/* r = |a| + |b| */
static void mag_add(big *r, const big *a, const big *b)
{
    uint64_t carry = 0;
    int i, n = a->n > b->n ? a->n : b->n;
    if (n + 1 > BIG_LIMBS)
        big_fail();
    for (i = 0; i < n; i++) {
        uint64_t s = carry + (i < a->n ? a->d[i] : 0) + (i < b->n ? b->d[i] : 0);
        r->d[i] = (uint32_t)s;
        carry = s >> 32;
    }
    r->d[n] = (uint32_t)carry;
    r->n = n + 1;
}

/* r = |a| - |b|, requires |a| >= |b| */
static void mag_sub(big *r, const big *a, const big *b)
{
    int64_t borrow = 0;
    int i;
    for (i = 0; i < a->n; i++) {
        int64_t s = (int64_t)a->d[i] - (i < b->n ? b->d[i] : 0) - borrow;
        borrow = s < 0;
        r->d[i] = (uint32_t)(s + (borrow ? ((int64_t)1 << 32) : 0));
    }
    r->n = a->n;
}

static void big_addsub(big *r, const big *a, const big *b, int negate_b)
{
    big t;
    int bneg = b->neg ^ (negate_b && b->n > 0);
    if (a->neg == bneg) {
        mag_add(&t, a, b);
        t.neg = a->neg;
    } else if (mag_cmp(a, b) >= 0) {
        mag_sub(&t, a, b);
        t.neg = a->neg;
    } else {
        mag_sub(&t, b, a);
        t.neg = bneg;
    }
    big_trim(&t);
    *r = t;
}

static void big_add(big *r, const big *a, const big *b)
{
    big_addsub(r, a, b, 0);
}

static void big_sub(big *r, const big *a, const big *b)
{
    big_addsub(r, a, b, 1);
}

static void big_mul(big *r, const big *a, const big *b)
{
    big t;
    int i, j;
    if (a->n == 0 || b->n == 0) {
        r->n = 0;
        r->neg = 0;
        return;
    }
    if (a->n + b->n > BIG_LIMBS)
        big_fail();
    memset(t.d, 0, sizeof(uint32_t) * (size_t)(a->n + b->n));
    for (i = 0; i < a->n; i++) {
        uint64_t carry = 0;
        for (j = 0; j < b->n; j++) {
            uint64_t cur = (uint64_t)a->d[i] * b->d[j] + t.d[i + j] + carry;
            t.d[i + j] = (uint32_t)cur;
            carry = cur >> 32;
        }
        t.d[i + b->n] = (uint32_t)carry;
    }
    t.n = a->n + b->n;
    t.neg = a->neg ^ b->neg;
    big_trim(&t);
    *r = t;
}

static int big_sign(const big *a)
{
    return a->n == 0 ? 0 : (a->neg ? -1 : 1);
}

/* Exponent of the lowest bit a nonzero double can have: x = M 2^(e - 53). */
static int low_exponent(double x)
{
    int e;
    (void)frexp(x, &e);
    return e - 53;
}

/* r = a * 2^s, s >= 0 */
static void big_shl(big *r, const big *a, int s)
{
    big t;
    int i, limbs = s / 32, bits = s % 32;
    if (s < 0 || a->n + limbs + 1 > BIG_LIMBS)
        big_fail();
    memset(t.d, 0, sizeof(uint32_t) * (size_t)(a->n + limbs + 1));
    for (i = 0; i < a->n; i++) {
        uint64_t v = (uint64_t)a->d[i] << bits;
        t.d[i + limbs] |= (uint32_t)v;
        t.d[i + limbs + 1] |= (uint32_t)(v >> 32);
    }
    t.n = a->n + limbs + 1;
    t.neg = a->neg;
    big_trim(&t);
    *r = t;
}

/* x as an integer times 2^base (base <= low_exponent(x)). */
static void big_from_double(big *r, double x, int base)
{
    int e;
    uint64_t m;
    r->n = 0;
    r->neg = 0;
    if (x == 0.0)
        return;
    m = (uint64_t)ldexp(fabs(frexp(x, &e)), 53);
    r->d[0] = (uint32_t)m;
    r->d[1] = (uint32_t)(m >> 32);
    r->n = 2;
    r->neg = x < 0.0;
    big_trim(r);
    big_shl(r, r, e - 53 - base);
}

/* Common base exponent for coordinates v[0..nv) and weights w[0..nw). */
static int common_base(const double *v, int nv, const double *w, int nw)
{
    int i, base = 1 << 20;
    for (i = 0; i < nv; i++)
        if (v[i] != 0.0 && low_exponent(v[i]) < base)
            base = low_exponent(v[i]);
    for (i = 0; i < nw; i++) {
        if (w[i] != 0.0) {
            int h = low_exponent(w[i]);
            int half = h >= 0 ? h / 2 : -((-h + 1) / 2); /* floor(h / 2) */
            if (half < base)
                base = half;
        }
    }
    return base;
}

/* 2x2, 3x3, 4x4 determinants of big matrices by cofactor expansion. */
static void det2(big *r, const big *a, const big *b, const big *c, const big *d)
{
    big t, u;
    big_mul(&t, a, d);
    big_mul(&u, b, c);
    big_sub(r, &t, &u);
}

static void detn(big *r, big *m, int n) /* m row-major n x n */
{
    big acc, minor, term;
    big sub[16];
    int j, i, k, col;
    if (n == 2) {
        det2(r, &m[0], &m[1], &m[2], &m[3]);
        return;
    }
    acc.n = 0;
    acc.neg = 0;
    for (j = 0; j < n; j++) {
        for (i = 1; i < n; i++)
            for (k = 0, col = 0; k < n; k++)
                if (k != j)
                    sub[(i - 1) * (n - 1) + col++] = m[i * n + k];
        detn(&minor, sub, n - 1);
        big_mul(&term, &m[j], &minor);
        if (j % 2 == 0)
            big_add(&acc, &acc, &term);
        else
            big_sub(&acc, &acc, &term);
    }
    *r = acc;
}

/* Fill row i of an n x n matrix with p - q (dim entries) and, when lifted,
 * |p - q|^2 - (wp - wq). */
static void fill_row(big *row, const double *p, const double *q, int dim, int lifted, double wp,
                     double wq, int base)
{
    big bp, bq, sq;
    int j;
    for (j = 0; j < dim; j++) {
        big_from_double(&bp, p[j], base);
        big_from_double(&bq, q[j], base);
        big_sub(&row[j], &bp, &bq);
    }
    if (!lifted)
        return;
    row[dim].n = 0;
    row[dim].neg = 0;
    for (j = 0; j < dim; j++) {
        big_mul(&sq, &row[j], &row[j]);
        big_add(&row[dim], &row[dim], &sq);
    }
    big_from_double(&bp, wp, 2 * base);
    big_from_double(&bq, wq, 2 * base);
    big_sub(&row[dim], &row[dim], &bp);
    big_add(&row[dim], &row[dim], &bq);
}

int oracle_orient2d(const double *a, const double *b, const double *c)
{
    double v[6] = { a[0], a[1], b[0], b[1], c[0], c[1] };
    int base = common_base(v, 6, NULL, 0);
    big m[4], r;
    fill_row(&m[0], a, c, 2, 0, 0.0, 0.0, base);
    fill_row(&m[2], b, c, 2, 0, 0.0, 0.0, base);
    detn(&r, m, 2);
    return big_sign(&r);
}

int oracle_power2d(const double *a, const double *b, const double *c, const double *d, double wa,
                   double wb, double wc, double wd)
{
    double v[8] = { a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1] };
    double w[4] = { wa, wb, wc, wd };
    int base = common_base(v, 8, w, 4);
    big m[9], r;
    fill_row(&m[0], a, d, 2, 1, wa, wd, base);
    fill_row(&m[3], b, d, 2, 1, wb, wd, base);
    fill_row(&m[6], c, d, 2, 1, wc, wd, base);
    detn(&r, m, 3);
    return big_sign(&r);
}

int oracle_incircle(const double *a, const double *b, const double *c, const double *d)
{
    return oracle_power2d(a, b, c, d, 0.0, 0.0, 0.0, 0.0);
}

int oracle_orient3d(const double *a, const double *b, const double *c, const double *d)
{
    double v[12] = { a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2] };
    int base = common_base(v, 12, NULL, 0);
    big m[9], r;
    fill_row(&m[0], a, d, 3, 0, 0.0, 0.0, base);
    fill_row(&m[3], b, d, 3, 0, 0.0, 0.0, base);
    fill_row(&m[6], c, d, 3, 0, 0.0, 0.0, base);
    detn(&r, m, 3);
    return big_sign(&r);
}

int oracle_insphere(const double *a, const double *b, const double *c, const double *d,
                    const double *e)
{
    double v[15];
    int base, i;
    big m[16], r;
    for (i = 0; i < 3; i++)
        v[i] = a[i], v[3 + i] = b[i], v[6 + i] = c[i], v[9 + i] = d[i], v[12 + i] = e[i];
    base = common_base(v, 15, NULL, 0);
    fill_row(&m[0], a, e, 3, 1, 0.0, 0.0, base);
    fill_row(&m[4], b, e, 3, 1, 0.0, 0.0, base);
    fill_row(&m[8], c, e, 3, 1, 0.0, 0.0, base);
    fill_row(&m[12], d, e, 3, 1, 0.0, 0.0, base);
    detn(&r, m, 4);
    return big_sign(&r);
}

int oracle_power3d(const double *a, const double *b, const double *c, const double *d,
                   const double *e, double wa, double wb, double wc, double wd, double we)
{
    double v[15], w[5];
    int base, i;
    big m[16], r;
    for (i = 0; i < 3; i++)
        v[i] = a[i], v[3 + i] = b[i], v[6 + i] = c[i], v[9 + i] = d[i], v[12 + i] = e[i];
    w[0] = wa, w[1] = wb, w[2] = wc, w[3] = wd, w[4] = we;
    base = common_base(v, 15, w, 5);
    fill_row(&m[0], a, e, 3, 1, wa, we, base);
    fill_row(&m[4], b, e, 3, 1, wb, we, base);
    fill_row(&m[8], c, e, 3, 1, wc, we, base);
    fill_row(&m[12], d, e, 3, 1, wd, we, base);
    detn(&r, m, 4);
    return big_sign(&r);
}

int oracle_expansion_equals(const double *e, int elen, const double *terms, int nterms,
                            const double *prod_a, const double *prod_b, int nprod)
{
    /* sum(e) == sum(terms) + sum(prod_a[i] * prod_b[i]) exactly? */
    double v[512];
    int base, i, nv = 0;
    big lhs, rhs, x, y, t;
    if (elen + nterms + 2 * nprod > 512)
        big_fail();
    for (i = 0; i < elen; i++)
        v[nv++] = e[i];
    for (i = 0; i < nterms; i++)
        v[nv++] = terms[i];
    base = common_base(v, nv, NULL, 0);
    for (i = 0; i < nprod; i++) {
        /* a product of two doubles has its lowest bit at the sum of theirs */
        int lb = (prod_a[i] != 0.0 && prod_b[i] != 0.0)
                     ? low_exponent(prod_a[i]) + low_exponent(prod_b[i])
                     : base;
        if (lb < base)
            base = lb;
    }
    lhs.n = rhs.n = 0;
    lhs.neg = rhs.neg = 0;
    for (i = 0; i < elen; i++) {
        big_from_double(&x, e[i], base);
        big_add(&lhs, &lhs, &x);
    }
    for (i = 0; i < nterms; i++) {
        big_from_double(&x, terms[i], base);
        big_add(&rhs, &rhs, &x);
    }
    for (i = 0; i < nprod; i++) {
        if (prod_a[i] == 0.0 || prod_b[i] == 0.0)
            continue;
        big_from_double(&x, prod_a[i], low_exponent(prod_a[i]));
        big_from_double(&y, prod_b[i], low_exponent(prod_b[i]));
        big_mul(&t, &x, &y);
        big_shl(&t, &t, low_exponent(prod_a[i]) + low_exponent(prod_b[i]) - base);
        big_add(&rhs, &rhs, &t);
    }
    big_sub(&t, &lhs, &rhs);
    return big_sign(&t) == 0;
}
