/* geom_tests.h - TCases of the geom suite and the exact references they compare against. */
#ifndef CVMTEST_GEOM_TESTS_H
#define CVMTEST_GEOM_TESTS_H
#include <check.h>
#include <math.h>
#include <stdint.h>

TCase *geom_expansion_tcase(void); /* test_expansion.c: error-free sums, products, expansions */
TCase *geom_exact_det_tcase(void); /* test_exact_det.c: the exact stages alone vs the oracle */
TCase *geom_orient2d_tcase(void);  /* test_orient2d.c */
TCase *geom_incircle_tcase(void);  /* test_incircle.c */
TCase *geom_power2d_tcase(void);   /* test_power2d.c */
TCase *geom_orient3d_tcase(void);  /* test_orient3d.c */
TCase *geom_insphere_tcase(void);  /* test_insphere.c */
TCase *geom_sos_tcase(void);       /* test_sos.c: symbolic perturbation of the lifted tests */
TCase *geom_power3d_tcase(void);   /* test_power3d.c */
TCase *geom_sos3d_tcase(void);     /* test_sos3d.c: symbolic perturbation of insphere/power3d */
TCase *geom_construct_tcase(void); /* test_construct.c: circumcentre, segment crossing */
TCase *geom_measure_tcase(void);   /* test_measure.c: the smallest-angle shortcut */
TCase *geom_tet_centre_tcase(void); /* test_tet_centre.c: exact circumcentre containment */

/* oracle.c: exact signs (-1, 0, 1) of the determinants for any finite doubles
 * of moderate exponent spread, by big-integer arithmetic. */
int oracle_orient2d(const double *a, const double *b, const double *c);
int oracle_incircle(const double *a, const double *b, const double *c, const double *d);
int oracle_power2d(const double *a, const double *b, const double *c, const double *d, double wa,
                   double wb, double wc, double wd);
int oracle_orient3d(const double *a, const double *b, const double *c, const double *d);
int oracle_insphere(const double *a, const double *b, const double *c, const double *d,
                    const double *e);
int oracle_power3d(const double *a, const double *b, const double *c, const double *d,
                   const double *e, double wa, double wb, double wc, double wd, double we);
/* 1 when sum(e) == sum(terms) + sum(prod_a[i] * prod_b[i]) exactly. */
int oracle_expansion_equals(const double *e, int elen, const double *terms, int nterms,
                            const double *prod_a, const double *prod_b, int nprod);

/* intdet.c: the same determinants in int64 for small-integer coordinates
 * (|x| <= 2^12 in 2D, |x| <= 2^8 in 3D, |w| <= 2^24). */
int64_t intdet_orient2d(const double *a, const double *b, const double *c);
int64_t intdet_power2d(const double *a, const double *b, const double *c, const double *d,
                       double wa, double wb, double wc, double wd);
int64_t intdet_incircle(const double *a, const double *b, const double *c, const double *d);
int64_t intdet_orient3d(const double *a, const double *b, const double *c, const double *d);
int64_t intdet_insphere(const double *a, const double *b, const double *c, const double *d,
                        const double *e);

/* Deterministic generator (splitmix64) so every run sees the same cases. */
typedef struct {
    uint64_t s;
} geomtest_rng;

static inline uint64_t geomtest_u64(geomtest_rng *r)
{
    uint64_t z = (r->s += 0x9E3779B97F4A7C15u);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}

/* Uniform in [lo, hi). */
static inline double geomtest_uniform(geomtest_rng *r, double lo, double hi)
{
    return lo + (hi - lo) * ((double)(geomtest_u64(r) >> 11) * 0x1p-53);
}

/* Integer in [lo, hi] as a double. */
static inline double geomtest_int(geomtest_rng *r, int lo, int hi)
{
    return (double)(lo + (int)(geomtest_u64(r) % (uint64_t)(hi - lo + 1)));
}

/* x moved k ulps (k may be negative). */
static inline double geomtest_ulps(double x, int k)
{
    for (; k > 0; k--)
        x = nextafter(x, INFINITY);
    for (; k < 0; k++)
        x = nextafter(x, -INFINITY);
    return x;
}

static inline int geomtest_sign(double x)
{
    return (x > 0.0) - (x < 0.0);
}

static inline int geomtest_sign64(int64_t x)
{
    return (x > 0) - (x < 0);
}

#endif
