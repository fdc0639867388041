/*
 * geom_internal.h - exact geometric predicates and inexact constructions.
 *
 * Predicates (Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast
 * Robust Geometric Predicates", 1997): a floating-point filter with a proven
 * error bound, then adaptive expansion arithmetic; the returned sign is always
 * the sign of the exact determinant of the double inputs. Error bounds are
 * compile-time constants (no exactinit(), no global state).
 *
 * The *_sos variants add Simulation of Simplicity by point index so that they
 * never return 0 where the caller needs a decision.
 *
 * Requires IEEE 754 double arithmetic with round-to-nearest and no extended
 * precision (x87): build with -msse2 -mfpmath=sse on 32-bit x86, and never
 * with -ffast-math. Thread-safety: all functions are pure.
 */
#ifndef CVM_GEOM_INTERNAL_H
#define CVM_GEOM_INTERNAL_H

#include <math.h>
#include <stdint.h>

/* Sign convention: > 0 when a, b, c are counter-clockwise, < 0 clockwise,
 * 0 exactly collinear. The magnitude approximates twice the signed area. */
double cvm__orient2d(const double *a, const double *b, const double *c);

/* > 0 when d lies strictly inside the circle through a, b, c, provided a, b, c
 * are counter-clockwise (the sign flips when they are clockwise); 0 when
 * cocircular. */
double cvm__incircle(const double *a, const double *b, const double *c, const double *d);

/* incircle with symbolic perturbation (Simulation of Simplicity). When the
 * exact determinant is 0, every point's lifted coordinate z = x^2 + y^2 is
 * raised by an infinitesimal eps_i, where eps_i >> eps_j whenever i > j (the
 * LARGEST index is lifted most). The determinant is linear in each z, so the
 * answer is the sign of the first nonzero derivative, taken in order of
 * decreasing index:
 *   dDet/dz_a = orient2d(d, b, c)    dDet/dz_b = orient2d(a, d, c)
 *   dDet/dz_c = orient2d(a, b, d)    dDet/dz_d = -orient2d(a, b, c)
 * So among exactly cocircular points the one of largest index counts as
 * outside the circle of the others. This is one global perturbation: the
 * result is alternating in the four (point, index) pairs, whatever the
 * orientation of a, b, c. Precondition: a, b, c strictly counter-clockwise
 * (for the "+1 means inside" reading) and the four points pairwise distinct;
 * then some derivative is nonzero. Returns +1 (d inside) or -1 (outside),
 * never 0 (-1 if all four points are collinear, outside the precondition).
 * ia..id are the points' indices, pairwise distinct. */
int cvm__incircle_sos(const double *a, const double *b, const double *c, const double *d,
                      int64_t ia, int64_t ib, int64_t ic, int64_t id);

/* Power (weighted in-circle) test, weights in squared length units, power
 * distance |x - p|^2 - w. > 0 when the weighted point (d, wd) is in conflict
 * with the orthocircle of (a,wa), (b,wb), (c,wc) (a, b, c counter-clockwise),
 * i.e. the lifted point d' = (d, |d|^2 - wd) lies below the plane through the
 * lifted a', b', c'. With all weights 0 it equals incircle's sign. */
double cvm__power2d(const double *a, const double *b, const double *c, const double *d,
                    double wa, double wb, double wc, double wd);

/* power2d with the same symbolic perturbation as incircle_sos, applied to the
 * lifted coordinate z = x^2 + y^2 - w (same derivatives, same order). */
int cvm__power2d_sos(const double *a, const double *b, const double *c, const double *d,
                     double wa, double wb, double wc, double wd,
                     int64_t ia, int64_t ib, int64_t ic, int64_t id);

/* > 0 when d lies below the plane through a, b, c, where a, b, c appear
 * counter-clockwise seen from above (Shewchuk's convention: positive when d
 * sees a, b, c clockwise... i.e. the sign of det[a-d; b-d; c-d]). */
double cvm__orient3d(const double *a, const double *b, const double *c, const double *d);

/* > 0 when e lies inside the sphere through a, b, c, d, provided
 * orient3d(a, b, c, d) > 0; 0 when cospherical. */
double cvm__insphere(const double *a, const double *b, const double *c, const double *d,
                     const double *e);

/* insphere with symbolic perturbation, the 3D twin of cvm__incircle_sos: when
 * the exact determinant is 0, every point's lifted coordinate |x|^2 is raised
 * by eps_i, eps_i >> eps_j whenever i > j (the LARGEST index is lifted most),
 * and the sign is that of the first nonzero derivative in order of decreasing
 * index:
 *   dDet/dz_a = orient3d(e, b, c, d)   dDet/dz_b = orient3d(a, e, c, d)
 *   dDet/dz_c = orient3d(a, b, e, d)   dDet/dz_d = orient3d(a, b, c, e)
 *   dDet/dz_e = -orient3d(a, b, c, d)
 * So among exactly cospherical points the one of largest index counts as
 * outside the sphere of the others. Precondition: orient3d(a, b, c, d) > 0
 * (for the "+1 means inside" reading), the five points pairwise distinct; then
 * some derivative is nonzero. Returns +1 (e inside) or -1 (outside), never 0
 * (-1 when all five are coplanar, outside the precondition). ia..ie are the
 * points' indices, pairwise distinct. */
int cvm__insphere_sos(const double *a, const double *b, const double *c, const double *d,
                      const double *e, int64_t ia, int64_t ib, int64_t ic, int64_t id,
                      int64_t ie);

/* Power (weighted insphere) test, the lifted orient4d: weights in squared
 * length units, power distance |x - p|^2 - w. > 0 when the weighted point
 * (e, we) is in conflict with the orthosphere of (a,wa) .. (d,wd), provided
 * orient3d(a, b, c, d) > 0, i.e. the lifted e' = (e, |e|^2 - we) lies below the
 * hyperplane through the lifted a' .. d'. With all weights 0 it equals
 * insphere's sign; 0 exactly on a tie. */
double cvm__power3d(const double *a, const double *b, const double *c, const double *d,
                    const double *e, double wa, double wb, double wc, double wd, double we);

/* power3d with the perturbation of insphere_sos applied to the lifted
 * coordinate z = |x|^2 - w (same derivatives, same order, same result). */
int cvm__power3d_sos(const double *a, const double *b, const double *c, const double *d,
                     const double *e, double wa, double wb, double wc, double wd, double we,
                     int64_t ia, int64_t ib, int64_t ic, int64_t id, int64_t ie);

/* Where the power vertex (circumcentre when w is NULL) of the tetrahedron
 * (a, b, c, d) lies, exactly: s[i] is the sign of its barycentric coordinate
 * for corner i (a = 0 .. d = 3): +1 strictly on corner i's side of the
 * opposite face, 0 on that face's plane, -1 beyond it. w: the four weights
 * (power distance |x - p|^2 - w) or NULL. Any orientation. Returns 0, or -1
 * when the tetrahedron is flat (orient3d exactly 0; s unset). Exactness range
 * as below. */
int cvm__tet_centre_side(const double *a, const double *b, const double *c, const double *d,
                         const double *w, int s[4]);
/* From cvm__tet_centre_side: 1 when the power vertex lies strictly inside, 0
 * on the boundary (a face, edge or corner), -1 outside, -2 for a flat
 * tetrahedron. */
int cvm__tet_centre_inside(const double *a, const double *b, const double *c, const double *d,
                           const double *w);

/*
 * Exactness range: the sign is exact for all finite inputs as long as, within
 * one call, every nonzero coordinate is at least 2^-100 times the largest
 * coordinate magnitude (for the power tests, treat sqrt|w| as a coordinate).
 * Scale alone never matters: the slow stages rescale by a power of two, so
 * clusters at 1e-300 or 1e300 are exact too, and then the returned magnitude is
 * saturated to a nonzero finite double of the right sign. Outside that range
 * (say, the points (1e-200, 1) and (1, 1) in one orient2d) underflow inside the
 * exact stage can, in principle, lose bits, as in Shewchuk's predicates.
 */

/* The stages behind the filters of cvm__orient2d and cvm__incircle (same
 * results, no filter): for the inline versions below. */
double cvm__orient2d_adapt(const double *a, const double *b, const double *c);
double cvm__incircle_adapt(const double *a, const double *b, const double *c, const double *d);
/* The same for cvm__orient3d and cvm__insphere. */
double cvm__orient3d_adapt(const double *a, const double *b, const double *c, const double *d);
double cvm__insphere_adapt(const double *a, const double *b, const double *c, const double *d,
                           const double *e);

/* Filter bounds (Shewchuk 1997, epsilon = 2^-53). The floor added to each bound
 * sends results small enough to have underflowed to the exact stages. */
static const double cvm__o2d_errbound_a = (3.0 + 16.0 * 0x1p-53) * 0x1p-53;
static const double cvm__icc_errbound_a = (10.0 + 96.0 * 0x1p-53) * 0x1p-53;
static const double cvm__o3d_errbound_a = (7.0 + 56.0 * 0x1p-53) * 0x1p-53;
static const double cvm__isp_errbound_a = (16.0 + 224.0 * 0x1p-53) * 0x1p-53;
static const double cvm__filter_floor = 0x1p-1020;

/* cvm__orient2d with its filter inlined into the caller (hot loops). */
static inline double cvm__orient2d_inline(const double *a, const double *b, const double *c)
{
    double acx = a[0] - c[0], bcx = b[0] - c[0];
    double acy = a[1] - c[1], bcy = b[1] - c[1];
    double detleft = acx * bcy, detright = acy * bcx;
    double det = detleft - detright;
    double errbound = cvm__o2d_errbound_a * (fabs(detleft) + fabs(detright)) + cvm__filter_floor;
    if (fabs(det) > errbound)
        return det;
    return cvm__orient2d_adapt(a, b, c);
}

/* cvm__incircle with its filter inlined into the caller (hot loops). */
static inline double cvm__incircle_inline(const double *a, const double *b, const double *c,
                                          const double *d)
{
    double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
    double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
    double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy, alift = adx * adx + ady * ady;
    double cdxady = cdx * ady, adxcdy = adx * cdy, blift = bdx * bdx + bdy * bdy;
    double adxbdy = adx * bdy, bdxady = bdx * ady, clift = cdx * cdx + cdy * cdy;
    double det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy)
                 + clift * (adxbdy - bdxady);
    double permanent = (fabs(bdxcdy) + fabs(cdxbdy)) * alift
                       + (fabs(cdxady) + fabs(adxcdy)) * blift
                       + (fabs(adxbdy) + fabs(bdxady)) * clift;
    double errbound = cvm__icc_errbound_a * permanent + cvm__filter_floor;
    if (fabs(det) > errbound)
        return det;
    return cvm__incircle_adapt(a, b, c, d);
}

/* Two-lane (SSE2) versions of the hot filters below evaluate each lane with the
 * scalar operations in the scalar order: the same bits, so the same error
 * bounds hold. CVM_NO_SSE2 turns them off. */
#if defined(__SSE2__) && !defined(CVM_NO_SSE2)
#include <emmintrin.h>
#define CVM__GEOM_SSE2 1
#endif

/* cvm__orient3d with its filter inlined into the caller (hot loops). */
static inline double cvm__orient3d_inline(const double *a, const double *b, const double *c,
                                          const double *d)
{
    double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
    double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
    double adz = a[2] - d[2], bdz = b[2] - d[2], cdz = c[2] - d[2];
    double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
    double cdxady = cdx * ady, adxcdy = adx * cdy;
    double adxbdy = adx * bdy, bdxady = bdx * ady;
    double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
    double permanent = (fabs(bdxcdy) + fabs(cdxbdy)) * fabs(adz)
                       + (fabs(cdxady) + fabs(adxcdy)) * fabs(bdz)
                       + (fabs(adxbdy) + fabs(bdxady)) * fabs(cdz);
    double errbound = cvm__o3d_errbound_a * permanent + cvm__filter_floor;
    if (fabs(det) > errbound)
        return det;
    return cvm__orient3d_adapt(a, b, c, d);
}

/* The four sides of a point-location step at once: bit f set when
 * orient3d(q0, q1, q2, q3) < 0 with q = (a, b, c, d) and q_f replaced by p
 * (p strictly beyond face f). Each is an orient3d with p moved last
 * (orient3d(p, b, c, d) = -orient3d(b, c, d, p), orient3d(a, p, c, d) =
 * orient3d(a, c, d, p), orient3d(a, b, p, d) = -orient3d(a, b, d, p)), and
 * orient3d(x, y, z, p) is evaluated by cvm__orient3d_inline's operations on the
 * differences to p, which the four share: twelve differences, twelve products
 * x_u y_v, six 2x2 minors (a swapped minor is the exact negative) instead of
 * four times nine differences and six products. Same values, so the same
 * filter bound; an undecided side goes to the exact stage alone. */
static inline unsigned cvm__orient3d_sides(const double *a, const double *b, const double *c,
                                           const double *d, const double *p)
{
    double ax = a[0] - p[0], bx = b[0] - p[0], cx = c[0] - p[0], dx = d[0] - p[0];
    double ay = a[1] - p[1], by = b[1] - p[1], cy = c[1] - p[1], dy = d[1] - p[1];
    double az = a[2] - p[2], bz = b[2] - p[2], cz = c[2] - p[2], dz = d[2] - p[2];
    double pab = ax * by, pba = bx * ay, pac = ax * cy, pca = cx * ay, pad = ax * dy;
    double pda = dx * ay, pbc = bx * cy, pcb = cx * by, pbd = bx * dy, pdb = dx * by;
    double pcd = cx * dy, pdc = dx * cy;
    double mab = pab - pba, mac = pac - pca, mad = pad - pda, mbc = pbc - pcb;
    double mbd = pbd - pdb, mcd = pcd - pdc;
    double sab = fabs(pab) + fabs(pba), sac = fabs(pac) + fabs(pca);
    double sad = fabs(pad) + fabs(pda), sbc = fabs(pbc) + fabs(pcb);
    double sbd = fabs(pbd) + fabs(pdb), scd = fabs(pcd) + fabs(pdc);
    double aza = fabs(az), bza = fabs(bz), cza = fabs(cz), dza = fabs(dz);
    /* orient3d(x, y, z, p) = xz m(y, z) + yz m(z, x) + zz m(x, y) */
    double det0 = bz * mcd - cz * mbd + dz * mbc; /* (b, c, d) */
    double det1 = az * mcd - cz * mad + dz * mac; /* (a, c, d) */
    double det2 = az * mbd - bz * mad + dz * mab; /* (a, b, d) */
    double det3 = az * mbc - bz * mac + cz * mab; /* (a, b, c) */
    double per0 = scd * bza + sbd * cza + sbc * dza;
    double per1 = scd * aza + sad * cza + sac * dza;
    double per2 = sbd * aza + sad * bza + sab * dza;
    double per3 = sbc * aza + sac * bza + sab * cza;
    unsigned m = (unsigned)(det0 > 0.0) | (unsigned)(det1 < 0.0) << 1
                 | (unsigned)(det2 > 0.0) << 2 | (unsigned)(det3 < 0.0) << 3;
    if (!(fabs(det0) > cvm__o3d_errbound_a * per0 + cvm__filter_floor))
        m = (m & ~1u) | (unsigned)(cvm__orient3d_adapt(b, c, d, p) > 0.0);
    if (!(fabs(det1) > cvm__o3d_errbound_a * per1 + cvm__filter_floor))
        m = (m & ~2u) | (unsigned)(cvm__orient3d_adapt(a, c, d, p) < 0.0) << 1;
    if (!(fabs(det2) > cvm__o3d_errbound_a * per2 + cvm__filter_floor))
        m = (m & ~4u) | (unsigned)(cvm__orient3d_adapt(a, b, d, p) > 0.0) << 2;
    if (!(fabs(det3) > cvm__o3d_errbound_a * per3 + cvm__filter_floor))
        m = (m & ~8u) | (unsigned)(cvm__orient3d_adapt(a, b, c, p) < 0.0) << 3;
    return m;
}

/* The insphere determinant in plain floating point, and the permanent that
 * bounds its rounding error (the filter of cvm__insphere_inline). When every
 * coordinate is an integer of magnitude at most 256, every difference is at
 * most D = 512 and every intermediate value an integer of magnitude at most
 * 72 D^5 < 2^53, so the result is exact. */
static inline double cvm__insphere_fp(const double *a, const double *b, const double *c,
                                      const double *d, const double *e, double *permanent)
{
    double aex = a[0] - e[0], bex = b[0] - e[0], cex = c[0] - e[0], dex = d[0] - e[0];
    double aey = a[1] - e[1], bey = b[1] - e[1], cey = c[1] - e[1], dey = d[1] - e[1];
    double aez = a[2] - e[2], bez = b[2] - e[2], cez = c[2] - e[2], dez = d[2] - e[2];
    double aexbey = aex * bey, bexaey = bex * aey, bexcey = bex * cey, cexbey = cex * bey;
    double cexdey = cex * dey, dexcey = dex * cey, dexaey = dex * aey, aexdey = aex * dey;
    double aexcey = aex * cey, cexaey = cex * aey, bexdey = bex * dey, dexbey = dex * bey;
    double ab = aexbey - bexaey, bc = bexcey - cexbey, cd = cexdey - dexcey;
    double da = dexaey - aexdey, ac = aexcey - cexaey, bd = bexdey - dexbey;
    double abc = aez * bc - bez * ac + cez * ab;
    double bcd = bez * cd - cez * bd + dez * bc;
    double cda = cez * da + dez * ac + aez * cd;
    double dab = dez * ab + aez * bd + bez * da;
    double alift = aex * aex + aey * aey + aez * aez;
    double blift = bex * bex + bey * bey + bez * bez;
    double clift = cex * cex + cey * cey + cez * cez;
    double dlift = dex * dex + dey * dey + dez * dez;
    double aezp = fabs(aez), bezp = fabs(bez), cezp = fabs(cez), dezp = fabs(dez);
    double abp = fabs(aexbey) + fabs(bexaey), bcp = fabs(bexcey) + fabs(cexbey);
    double cdp = fabs(cexdey) + fabs(dexcey), dap = fabs(dexaey) + fabs(aexdey);
    double acp = fabs(aexcey) + fabs(cexaey), bdp = fabs(bexdey) + fabs(dexbey);
    *permanent = (aezp * bcp + bezp * acp + cezp * abp) * dlift
                 + (dezp * abp + aezp * bdp + bezp * dap) * clift
                 + (cezp * dap + dezp * acp + aezp * cdp) * blift
                 + (bezp * cdp + cezp * bdp + dezp * bcp) * alift;
    return (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
}

/* The determinant of cvm__insphere_inline and the largest of its four lifts
 * (*lmax), in plain doubles, operation for operation as written. */
static inline double cvm__insphere_det_scalar(const double *a, const double *b, const double *c,
                                              const double *d, const double *e, double *lmax)
{
    double aex = a[0] - e[0], bex = b[0] - e[0], cex = c[0] - e[0], dex = d[0] - e[0];
    double aey = a[1] - e[1], bey = b[1] - e[1], cey = c[1] - e[1], dey = d[1] - e[1];
    double aez = a[2] - e[2], bez = b[2] - e[2], cez = c[2] - e[2], dez = d[2] - e[2];
    double ab = aex * bey - bex * aey, bc = bex * cey - cex * bey, cd = cex * dey - dex * cey;
    double da = dex * aey - aex * dey, ac = aex * cey - cex * aey, bd = bex * dey - dex * bey;
    double abc = aez * bc - bez * ac + cez * ab;
    double bcd = bez * cd - cez * bd + dez * bc;
    double cda = cez * da + dez * ac + aez * cd;
    double dab = dez * ab + aez * bd + bez * da;
    double alift = aex * aex + aey * aey + aez * aez;
    double blift = bex * bex + bey * bey + bez * bez;
    double clift = cex * cex + cey * cey + cez * cez;
    double dlift = dex * dex + dey * dey + dez * dez;
    double l1 = alift > blift ? alift : blift, l2 = clift > dlift ? clift : dlift;
    *lmax = l1 > l2 ? l1 : l2;
    return (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
}

#ifdef CVM__GEOM_SSE2
/* cvm__insphere_det_scalar on two lanes: the same IEEE operations on the same
 * operands in the same order (x - y taken as x + (-y), which IEEE 754 defines
 * to be the same), so the same bits, in about half the instructions. Lane
 * pairs: x, y, z differences (a, c) and (b, d); minors (ab, cd), (bc, da),
 * (ac, bd); cofactors (abc, cda) and (dab, bcd); lifts (a, c) and (b, d). */
static inline double cvm__insphere_det_sse2(const double *a, const double *b, const double *c,
                                            const double *d, const double *e, double *lmax)
{
    __m128d ex = _mm_set1_pd(e[0]), ey = _mm_set1_pd(e[1]), ez = _mm_set1_pd(e[2]);
    __m128d xac = _mm_sub_pd(_mm_set_pd(c[0], a[0]), ex), xbd = _mm_sub_pd(_mm_set_pd(d[0], b[0]), ex);
    __m128d yac = _mm_sub_pd(_mm_set_pd(c[1], a[1]), ey), ybd = _mm_sub_pd(_mm_set_pd(d[1], b[1]), ey);
    __m128d zac = _mm_sub_pd(_mm_set_pd(c[2], a[2]), ez), zbd = _mm_sub_pd(_mm_set_pd(d[2], b[2]), ez);
    __m128d neg0 = _mm_set_pd(0.0, -0.0), neg1 = _mm_set_pd(-0.0, 0.0);
    __m128d zca = _mm_shuffle_pd(zac, zac, 1), zdb = _mm_shuffle_pd(zbd, zbd, 1);
    __m128d abcd = _mm_sub_pd(_mm_mul_pd(xac, ybd), _mm_mul_pd(xbd, yac));
    __m128d bcda = _mm_sub_pd(_mm_mul_pd(xbd, _mm_shuffle_pd(yac, yac, 1)),
                              _mm_mul_pd(_mm_shuffle_pd(xac, xac, 1), ybd));
    __m128d acbd = _mm_sub_pd(_mm_mul_pd(_mm_unpacklo_pd(xac, xbd), _mm_unpackhi_pd(yac, ybd)),
                              _mm_mul_pd(_mm_unpackhi_pd(xac, xbd), _mm_unpacklo_pd(yac, ybd)));
    __m128d p1 = _mm_add_pd(
        _mm_add_pd(_mm_mul_pd(zac, bcda),
                   _mm_xor_pd(_mm_mul_pd(zbd, _mm_unpacklo_pd(acbd, acbd)), neg0)),
        _mm_mul_pd(zca, abcd));
    __m128d p2 = _mm_add_pd(
        _mm_add_pd(_mm_mul_pd(zdb, abcd),
                   _mm_xor_pd(_mm_mul_pd(zac, _mm_unpackhi_pd(acbd, acbd)), neg1)),
        _mm_mul_pd(zbd, _mm_shuffle_pd(bcda, bcda, 1)));
    __m128d lac = _mm_add_pd(_mm_add_pd(_mm_mul_pd(xac, xac), _mm_mul_pd(yac, yac)),
                             _mm_mul_pd(zac, zac));
    __m128d lbd = _mm_add_pd(_mm_add_pd(_mm_mul_pd(xbd, xbd), _mm_mul_pd(ybd, ybd)),
                             _mm_mul_pd(zbd, zbd));
    __m128d q = _mm_sub_pd(_mm_mul_pd(_mm_shuffle_pd(lbd, lbd, 1), p1),
                           _mm_mul_pd(_mm_shuffle_pd(lac, lac, 1), p2));
    __m128d m = _mm_max_pd(lac, lbd); /* (l1, l2) of the scalar version */
    *lmax = _mm_cvtsd_f64(_mm_max_sd(m, _mm_unpackhi_pd(m, m)));
    return _mm_cvtsd_f64(q) + _mm_cvtsd_f64(_mm_unpackhi_pd(q, q));
}
#endif

/* cvm__insphere with its filter inlined into the caller (hot loops). A
 * semi-static stage comes first: every product in the permanent of
 * cvm__insphere_fp is at most m^2 or m^3 and every lift at most 3 m^2, m the
 * largest magnitude of the twelve differences to e, so the permanent is at
 * most 72 m^5 <= 72 L^(5/2), L the largest lift (m^2 <= L); 73 covers the
 * rounding of both sides. The bound costs three max, a square root and three
 * products instead of the permanent's ~50 operations; the permanent's filter
 * decides when it is too loose. L > 2^-400 keeps L^(5/2) normal. With SSE2
 * the determinant is evaluated two lanes at a time, to the same bits. */
static inline double cvm__insphere_inline(const double *a, const double *b, const double *c,
                                          const double *d, const double *e)
{
    double l;
#ifdef CVM__GEOM_SSE2
    double det = cvm__insphere_det_sse2(a, b, c, d, e, &l);
#else
    double det = cvm__insphere_det_scalar(a, b, c, d, e, &l);
#endif
    if (l > 0x1p-400 && fabs(det) > cvm__isp_errbound_a * 73.0 * (l * l * sqrt(l)) + cvm__filter_floor)
        return det;
    return cvm__insphere(a, b, c, d, e); /* the permanent's filter, then the exact stages */
}

/* The orient3d determinant in plain floating point: exact when every
 * coordinate is an integer of magnitude at most 256 (6 * 512^3 < 2^53). */
static inline double cvm__orient3d_fp(const double *a, const double *b, const double *c,
                                      const double *d)
{
    double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
    double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
    double adz = a[2] - d[2], bdz = b[2] - d[2], cdz = c[2] - d[2];
    return adz * (bdx * cdy - cdx * bdy) + bdz * (cdx * ady - adx * cdy)
           + cdz * (adx * bdy - bdx * ady);
}

/* The tie-breaking stage of cvm__insphere_sos / cvm__power3d_sos alone, for
 * a caller that already knows the determinant is exactly 0: the sign of the
 * first nonzero lift derivative. fp_exact != 0 promises coordinates that make
 * cvm__orient3d_fp exact (integers of magnitude <= 256). */
int cvm__sos3d_tie(const double *a, const double *b, const double *c, const double *d,
                   const double *e, int64_t ia, int64_t ib, int64_t ic, int64_t id, int64_t ie,
                   int fp_exact);

/* Constructions: plain doubles, possibly inexact; every later decision about
 * their result is taken by the exact predicates above. */

/* Circumcentre of triangle a, b, c (non-degenerate) into out[2]. */
void cvm__circumcenter2d(const double *a, const double *b, const double *c, double *out);

/* Intersection point of lines ab and cd (which properly cross) into out[2];
 * the result is clamped to lie within the bounding boxes of both segments. */
void cvm__segment_intersection2d(const double *a, const double *b, const double *c,
                                 const double *d, double *out);

#endif
