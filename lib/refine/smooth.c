/* smooth.c - post-processing by "smart" Laplacian smoothing (a free Steiner vertex moves towards the centroid of its neighbours when no star triangle inverts (exact orient2d) and the star gets more regular without losing angle or size bounds) and by Freitag-Ollivier max-min optimisation of the sines of the star's angles (active-set method). */
#include <limits.h>
#include <math.h>
#include <string.h>

#include "refine_internal.h"
#include "delaunay/tri2_store.h"
#include "geom/geom_internal.h"

/* Weight of an obtuse angle against an angle in [55, 65] degrees in the
 * regularity count: high enough that the extra candidates never trade obtuse
 * triangles for regular angles (docs/design/refiners.md). */
#define SM_OBTUSE_WEIGHT 16
/* Relaxation accepts a move that worsens the star's count by at most this. */
#define SM_RELAX_SLACK 1.0
/* A relaxation move wakes the neighbours when longer than about 3% of the
 * vertex's shortest edge (the square of the fraction). */
#define SM_RELAX_WAKE2 1e-3
/* Relaxation skips a vertex whose longest spoke is more than 1.5 times its
 * shortest (squared): in a graded star the ODT point is not the target. */
#define SM_RELAX_GRADED2 2.25

/* Smart sweeps, after the six steps towards the centroid and the ODT point,
 * also try, for each outer edge of the star with an irregular star triangle
 * at it or beside it: the apex of the equilateral triangle on the edge (where
 * the vertex makes that star triangle equilateral), the point half-way to it,
 * and the midpoint of the apexes of this edge and the next; then a pattern
 * search around the best point so far: SM_PATTERN_ITERS rounds of the
 * SM_PATTERN_DIRS axis steps of SM_PATTERN_STEP x the shortest spoke, halved
 * after a round without gain. The six steps alone cannot reach the positions
 * that make single star triangles exactly regular, which graded stars (the
 * NACA wall rows) and the row where a curved boundary meets the interior
 * lattice need. */
#define SM_PATTERN_ITERS 3
#define SM_PATTERN_DIRS 4
#define SM_PATTERN_STEP 0.1
/* The extra candidates are tried from this smart sweep on (0 = the first):
 * in earlier sweeps they cost time and gain little, as the points still move. */
#define SM_EXTRA_FROM 2
/* Graded stars (longest spoke > 1.5x the shortest, as SM_RELAX_GRADED2) get
 * the extra candidates from this smart sweep on: they are the wall rows of a
 * graded boundary, which need them most, and are few elsewhere. */
#define SM_EXTRA_FROM_GRADED 1
/* Other stars get them only when at least this many of their angles are out
 * of [55, 65] degrees (their regularity count exceeds the perfect -3n by this
 * much; an obtuse angle counts 17): the nearly regular stars of a lattice
 * rarely gain from them. */
#define SM_EXTRA_MIN_BAD 6.5
/* The extra candidates never make a spoke shorter than this fraction of the
 * smaller of the size and the root mean square spoke of the star, so points
 * do not crowd; not the shortest spoke, as graded stars must shorten spokes. */
#define SM_MIN_SPOKE 0.6

/* Star of v into *star (triangles, counter-clockwise); returns the count, or 0
 * when v may not move: a star triangle outside the domain or a constrained
 * spoke edge. *err is set on NOMEM. */
static size_t sm_star(const cvm__tri2 *T, int32_t v, int32_t **star, size_t *cap, int *err)
{
    int32_t t0 = T->vtri[v], t = t0;
    size_t n = 0;
    if (t0 < 0)
        return 0;
    do {
        const int32_t *tv = T->tv + 3 * (size_t)t;
        int i = tv[0] == v ? 0 : tv[1] == v ? 1 : 2;
        if (!cvm__tri2_in_domain(T, t) || cvm__tri2_edge_seg(T, t, (i + 1) % 3) >= 0 ||
            cvm__tri2_edge_seg(T, t, (i + 2) % 3) >= 0)
            return 0;
        if (n >= *cap && cvm__grow(T->ctx, (void **)star, cap, n + 1, sizeof **star)) {
            *err = 1;
            return 0;
        }
        (*star)[n++] = t;
        t = T->tn[3 * (size_t)t + (i + 1) % 3] / 3;
    } while (t != t0 && n <= T->nt);
    return t == t0 ? n : 0;
}

/* The star of a visited vertex, gathered once per visit: ring vertex k is the
 * second corner of star triangle k, whose third corner is ring vertex k + 1
 * (mod n, sm_star walks counter-clockwise); per triangle the squared length
 * of its outer edge, 4 x its size squared (HUGE_VAL: no size) and twice its
 * area bound (0: none). */
typedef struct sm_ring {
    size_t n, cap;
    double *a;   /* 2 per ring vertex */
    double *lab; /* per triangle */
    double *ls4;  /* 4 x size2 x size^2 */
    double *amax2;
    double size2; /* the refiner's size2 */
} sm_ring;

static void sm_ring_free(cvm__ctx *ctx, sm_ring *r)
{
    cvm__free(ctx, r->a);
    cvm__free(ctx, r->lab);
    cvm__free(ctx, r->ls4);
    cvm__free(ctx, r->amax2);
}

/* Fill r from the star of v; returns 0 on NOMEM. */
static int sm_ring_build(const cvm__refiner *R, int32_t v, const int32_t *star, size_t n,
                         sm_ring *r)
{
    const cvm__tri2 *T = R->T;
    size_t k;
    if (n > r->cap) {
        size_t c2 = r->cap, c1 = r->cap, c3 = r->cap, c4 = r->cap;
        if (cvm__grow(T->ctx, (void **)&r->a, &c1, 2 * n, sizeof *r->a) ||
            cvm__grow(T->ctx, (void **)&r->lab, &c2, n, sizeof *r->lab) ||
            cvm__grow(T->ctx, (void **)&r->ls4, &c3, n, sizeof *r->ls4) ||
            cvm__grow(T->ctx, (void **)&r->amax2, &c4, n, sizeof *r->amax2))
            return 0;
        r->cap = n;
    }
    r->n = n;
    r->size2 = R->size2;
    for (k = 0; k < n; k++) {
        const int32_t *tv = T->tv + 3 * (size_t)star[k];
        int i = tv[0] == v ? 0 : tv[1] == v ? 1 : 2;
        int32_t ia = tv[(i + 1) % 3], ib = tv[(i + 2) % 3];
        const double *a = cvm__tri2_pt(T, ia), *b = cvm__tri2_pt(T, ib);
        double ls = (R->vls[v] + R->vls[ia] + R->vls[ib]) / 3, am = cvm__rf_max_area(R, star[k]);
        r->a[2 * k] = a[0];
        r->a[2 * k + 1] = a[1];
        r->lab[k] = (b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]);
        r->ls4[k] = isfinite(ls) ? 4 * R->size2 * ls * ls : HUGE_VAL;
        r->amax2[k] = am > 0 ? 2 * am : 0;
    }
    return 1;
}

/* Regularity of the star of v (gathered in r) with v at p: *bad (lower is
 * better) = SM_OBTUSE_WEIGHT x obtuse angles - angles in [55, 65] degrees + 1e-3 x the sum
 * of (1 - mean ratio); *q = smallest sin^2; *big = triangles above the size
 * bound (circumradius above the mean size, or the area bound). Returns 0 when
 * a triangle is not strictly counter-clockwise (exact orient2d), or as soon
 * as *bad is sure to end >= cut (HUGE_VAL: the full count).
 * A candidate (qmin >= 0) is also rejected (0) as soon as a triangle has an
 * angle whose sin^2 is below qmin or more than bigmax triangles exceed the
 * size bound; *q is then not computed. Orientation is screened in floating
 * point here (a candidate whose doubled area is not positive is rejected);
 * a move is made only after sm_ring_exact. */
static int sm_ring_eval(const sm_ring *r, const double *p, double cut, double qmin, int bigmax,
                        double *bad, double *q, int *big)
{
    const double lo2 = 0.42261826174069944 * 0.42261826174069944;
    const double hi2 = 0.57357643635104616 * 0.57357643635104616;
    size_t k, n = r->n;
    double smr = 0, sq = 1.0, lpa, lp0;
    int sbig = 0, nobt = 0, nreg = 0;
    lp0 = lpa = (r->a[0] - p[0]) * (r->a[0] - p[0]) + (r->a[1] - p[1]) * (r->a[1] - p[1]);
    for (k = 0; k < n; k++) {
        const double *a = r->a + 2 * k, *b = r->a + 2 * (k + 1 < n ? k + 1 : 0);
        double lpb = k + 1 < n ? (b[0] - p[0]) * (b[0] - p[0]) + (b[1] - p[1]) * (b[1] - p[1]) : lp0;
        double lab = r->lab[k], ar, num[3], den[3], s, lmin;
        int j;
        ar = (a[0] - p[0]) * (b[1] - p[1]) - (a[1] - p[1]) * (b[0] - p[0]); /* 2 x area */
        if (!(ar > 0))
            return 0;
        num[0] = lpa + lpb - lab;
        den[0] = 4 * lpa * lpb;
        num[1] = lpa + lab - lpb;
        den[1] = 4 * lpa * lab;
        num[2] = lpb + lab - lpa;
        den[2] = 4 * lpb * lab;
        for (j = 0; j < 3; j++) {
            double n2 = num[j] * num[j];
            nobt += num[j] < 0;
            nreg += (num[j] >= 0) & (n2 >= lo2 * den[j]) & (n2 <= hi2 * den[j]);
        }
        /* the rest of the star adds at least -3 per triangle and a positive
         * mean-ratio term: tested before the other terms of this triangle */
        if (SM_OBTUSE_WEIGHT * nobt - nreg - 3 * (int)(n - k - 1) + smr >= cut)
            return 0;
        smr += 1e-3 * (1 - 2 * 1.7320508075688772 * ar / (lpa + lpb + lab));
        lmin = lpa < lpb ? (lpa < lab ? lpa : lab) : (lpb < lab ? lpb : lab);
        if (qmin >= 0) {
            if (lmin * ar * ar < qmin * (lpa * lpb * lab))
                return 0;
        } else {
            s = lmin * ar * ar / (lpa * lpb * lab);
            if (s < sq)
                sq = s;
        }
        if ((lpa * lpb * lab > r->ls4[k] * ar * ar || (r->amax2[k] > 0 && ar > r->amax2[k])) &&
            ++sbig > bigmax)
            return 0;
        lpa = lpb;
    }
    *bad = SM_OBTUSE_WEIGHT * nobt - nreg + smr;
    *q = sq;
    *big = sbig;
    return 1;
}

/* 1 when every star triangle of r is strictly counter-clockwise with the
 * vertex at p (exact orient2d): sm_ring_eval screens candidates in floating
 * point, a move is made only after this test. */
static int sm_ring_exact(const sm_ring *r, const double *p)
{
    size_t k, n = r->n;
    for (k = 0; k < n; k++)
        if (cvm__orient2d_inline(p, r->a + 2 * k, r->a + 2 * (k + 1 < n ? k + 1 : 0)) <= 0)
            return 0;
    return 1;
}

/* 1 when every angle of the triangle with squared sides lpa = |pa|^2, lpb =
 * |pb|^2, lab = |ab|^2 is in [55, 65] degrees (the test of sm_ring_eval:
 * cos^2 of each angle between cos^2 65 and cos^2 55, and no obtuse one). */
static int sm_sides_regular(double lpa, double lpb, double lab)
{
    const double lo2 = 0.42261826174069944 * 0.42261826174069944;
    const double hi2 = 0.57357643635104616 * 0.57357643635104616;
    double num[3], den[3];
    int j;
    num[0] = lpa + lpb - lab;
    den[0] = 4 * lpa * lpb;
    num[1] = lpa + lab - lpb;
    den[1] = 4 * lpa * lab;
    num[2] = lpb + lab - lpa;
    den[2] = 4 * lpb * lab;
    for (j = 0; j < 3; j++)
        if (!(num[j] >= 0 && num[j] * num[j] >= lo2 * den[j] && num[j] * num[j] <= hi2 * den[j]))
            return 0;
    return 1;
}

static double sm_d2(const double *a, const double *b)
{
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]);
}

/* 1 when every angle of domain triangle t is in [55, 65] degrees. */
static int sm_perfect(const cvm__tri2 *T, int32_t t)
{
    const int32_t *tv = T->tv + 3 * (size_t)t;
    const double *p = cvm__tri2_pt(T, tv[0]), *a = cvm__tri2_pt(T, tv[1]), *b = cvm__tri2_pt(T, tv[2]);
    return sm_sides_regular(sm_d2(a, p), sm_d2(b, p), sm_d2(b, a));
}

/* 1 when every triangle of star[0..n-1] is perfect (sm_perfect). */
static int sm_all_perfect(const cvm__tri2 *T, const int32_t *star, size_t n)
{
    size_t k;
    for (k = 0; k < n; k++)
        if (!sm_perfect(T, star[k]))
            return 0;
    return 1;
}

/* Mark v and its neighbours (the vertices of its star) in mark[]. */
static void sm_mark_star(const cvm__tri2 *T, int32_t v, const int32_t *star, size_t n,
                         uint8_t *mark)
{
    size_t k;
    mark[v] = 1;
    for (k = 0; k < n; k++) {
        const int32_t *tv = T->tv + 3 * (size_t)star[k];
        mark[tv[0]] = mark[tv[1]] = mark[tv[2]] = 1;
    }
}

/* Vertex v moved: its star's vertices are revisited in the next sweep, and
 * those after v in this one. */
static void sm_moved(const cvm__tri2 *T, size_t v, const int32_t *star, size_t n, uint8_t *cur,
                     uint8_t *next)
{
    size_t k;
    sm_mark_star(T, (int32_t)v, star, n, next);
    for (k = 0; k < n; k++) {
        const int32_t *tv = T->tv + 3 * (size_t)star[k];
        cur[tv[0]] = cur[tv[0]] || (size_t)tv[0] > v;
        cur[tv[1]] = cur[tv[1]] || (size_t)tv[1] > v;
        cur[tv[2]] = cur[tv[2]] || (size_t)tv[2] > v;
    }
}

/* Mark in cur the vertices of domain triangles with an angle outside [55, 65]
 * degrees (the others are left alone by the smart rule anyway). */
static void sm_mark_imperfect(const cvm__tri2 *T, uint8_t *cur)
{
    size_t t;
    memset(cur, 0, T->nv);
    for (t = 0; t < T->nt; t++) {
        const int32_t *tv = T->tv + 3 * t;
        if (cvm__tri2_in_domain(T, (int32_t)t) && !sm_perfect(T, (int32_t)t))
            cur[tv[0]] = cur[tv[1]] = cur[tv[2]] = 1;
    }
}

/* 1 when a domain triangle at v has an angle outside [55, 65] degrees;
 * memo (NULL or per vertex: 0 unknown, 1 no, 2 yes) keeps the answers. */
static int sm_star_imperfect(const cvm__tri2 *T, int32_t v, uint8_t *memo)
{
    int32_t t0 = T->vtri[v], t = t0;
    size_t n = 0;
    int r = 0;
    if (memo && memo[v])
        return memo[v] == 2;
    if (t0 < 0)
        return 0;
    do {
        if (cvm__tri2_in_domain(T, t) && !sm_perfect(T, t)) {
            r = 1;
            break;
        }
        t = cvm__tri2_around(T, t, v);
    } while (t != t0 && ++n <= T->nt);
    if (memo)
        memo[v] = (uint8_t)(r + 1);
    return r;
}

/* The first marks when only the vertices v >= first with only[v] may move:
 * sm_mark_imperfect (then sm_dilate when dilate is set) restricted to them,
 * from their stars instead of a scan of every triangle; tmp is scratch of
 * T->nv bytes. */
static void sm_mark_only(const cvm__tri2 *T, size_t first, const uint8_t *only, int dilate,
                         uint8_t *cur, uint8_t *tmp)
{
    size_t v;
    memset(cur, 0, T->nv);
    memset(tmp, 0, T->nv);
    for (v = first; v < T->nv; v++) {
        int32_t t0, t;
        size_t n = 0;
        if (!only[v] || (t0 = T->vtri[v]) < 0)
            continue;
        cur[v] = (uint8_t)sm_star_imperfect(T, (int32_t)v, tmp);
        if (cur[v] || !dilate)
            continue;
        /* dilated: a vertex of a domain triangle at v is marked */
        t = t0;
        do {
            const int32_t *tv = T->tv + 3 * (size_t)t;
            int i = cvm__tri2_corner(T, t, (int32_t)v);
            if (cvm__tri2_in_domain(T, t) &&
                (sm_star_imperfect(T, tv[(i + 1) % 3], tmp) ||
                 sm_star_imperfect(T, tv[(i + 2) % 3], tmp))) {
                cur[v] = 1;
                break;
            }
            t = T->tn[3 * (size_t)t + (i + 1) % 3] / 3;
        } while (t != t0 && ++n <= T->nt);
    }
}

/* Add to cur every vertex sharing a domain triangle with a marked one; tmp
 * is scratch of T->nv bytes. */
static void sm_dilate(const cvm__tri2 *T, uint8_t *cur, uint8_t *tmp)
{
    size_t t;
    memcpy(tmp, cur, T->nv);
    for (t = 0; t < T->nt; t++) {
        const int32_t *tv = T->tv + 3 * t;
        if (cvm__tri2_in_domain(T, (int32_t)t) && (tmp[tv[0]] || tmp[tv[1]] || tmp[tv[2]]))
            cur[tv[0]] = cur[tv[1]] = cur[tv[2]] = 1;
    }
}

/* The two targets of v (at x) from its star: c = the centroid of its
 * neighbours, o = the optimal-Delaunay (ODT) point, the area-weighted mean of
 * the star's circumcentres (Chen and Xu), which makes uniform stars
 * equilateral where the centroid only evens out edge lengths; o = c when no
 * star triangle has positive area in floating point. *l2 and *lmax2 = the
 * squared lengths of v's shortest and longest edges. */
static void sm_targets(const cvm__tri2 *T, int32_t v, const double *x, const int32_t *star,
                       size_t n, double *c, double *o, double *l2, double *lmax2)
{
    double sx = 0, sy = 0, sa = 0;
    size_t k;
    c[0] = c[1] = 0;
    *l2 = HUGE_VAL;
    *lmax2 = 0;
    for (k = 0; k < n; k++) {
        const int32_t *tv = T->tv + 3 * (size_t)star[k];
        int i = tv[0] == v ? 0 : tv[1] == v ? 1 : 2;
        const double *a = cvm__tri2_pt(T, tv[(i + 1) % 3]), *b = cvm__tri2_pt(T, tv[(i + 2) % 3]);
        double ax = a[0] - x[0], ay = a[1] - x[1], bx = b[0] - x[0], by = b[1] - x[1];
        double d = 2 * (ax * by - ay * bx), la = ax * ax + ay * ay, lb = bx * bx + by * by;
        c[0] += a[0];
        c[1] += a[1];
        if (la < *l2)
            *l2 = la;
        if (la > *lmax2)
            *lmax2 = la;
        if (!(d > 0))
            continue;
        /* circumcentre x + ((by la - ay lb), (ax lb - bx la)) / d, weight area d / 4 */
        sx += 0.25 * d * x[0] + 0.25 * (by * la - ay * lb);
        sy += 0.25 * d * x[1] + 0.25 * (ax * lb - bx * la);
        sa += 0.25 * d;
    }
    c[0] /= (double)n;
    c[1] /= (double)n;
    if (sa > 0) {
        o[0] = sx / sa;
        o[1] = sy / sa;
    } else {
        o[0] = c[0];
        o[1] = c[1];
    }
}

/* The apex of the equilateral triangle on outer edge k of ring r, on the side
 * of the visited vertex (which lies left of a_k -> a_k+1). */
static void sm_apex(const sm_ring *r, size_t k, double *pc)
{
    const double *a = r->a + 2 * k, *b = r->a + 2 * (k + 1 < r->n ? k + 1 : 0);
    pc[0] = (a[0] + b[0]) / 2 - 0.8660254037844386 * (b[1] - a[1]);
    pc[1] = (a[1] + b[1]) / 2 + 0.8660254037844386 * (b[0] - a[0]);
}

/* 1 when star triangle k of ring r, with the vertex at p, has an angle
 * outside [55, 65] degrees (the test of sm_ring_eval). */
static int sm_tri_irregular(const sm_ring *r, const double *p, size_t k)
{
    const double *a = r->a + 2 * k, *b = r->a + 2 * (k + 1 < r->n ? k + 1 : 0);
    return !sm_sides_regular(sm_d2(a, p), sm_d2(b, p), r->lab[k]);
}

/* Try candidate pc for the vertex at x: when it meets the bounds (qlo, bigmax),
 * keeps every spoke at least sqrt(minsp2) long and scores below *bb, it
 * becomes the best (*bb, best). Returns 1 then. */
static int sm_try(const sm_ring *r, const double *x, const double *pc, double qlo, int bigmax,
                  double minsp2, double *bb, double *best)
{
    double b1, q1;
    size_t k;
    int big1;
    if ((pc[0] == x[0] && pc[1] == x[1]) || !isfinite(pc[0]) || !isfinite(pc[1]) ||
        !sm_ring_eval(r, pc, *bb, qlo, bigmax, &b1, &q1, &big1) || !(b1 < *bb))
        return 0;
    for (k = 0; k < r->n; k++) {
        const double *a = r->a + 2 * k;
        if ((a[0] - pc[0]) * (a[0] - pc[0]) + (a[1] - pc[1]) * (a[1] - pc[1]) < minsp2)
            return 0;
    }
    *bb = b1;
    best[0] = pc[0];
    best[1] = pc[1];
    return 1;
}

/* The candidates beyond the six steps (see SM_PATTERN_ITERS) for the vertex
 * at x: updates *bb, best and *found. l2: its squared shortest spoke. */
static void sm_more_candidates(const sm_ring *r, const double *x, double l2, double qlo,
                               int bigmax, double *bb, double *best, int *found)
{
    static const double dir[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    double p0[2], p1[2], pc[2], st, cx, cy;
    size_t k, n = r->n;
    int it, d;
    int irr_prev, irr_k, irr_next, irr0;
    double minsp2 = 0;
    /* no spoke shorter than SM_MIN_SPOKE x the smaller of the size and the
     * root mean square spoke now */
    for (k = 0; k < n; k++) {
        const double *a = r->a + 2 * k;
        minsp2 += ((a[0] - x[0]) * (a[0] - x[0]) + (a[1] - x[1]) * (a[1] - x[1])) / (double)n;
    }
    for (k = 0; k < n; k++)
        if (r->ls4[k] / (4 * r->size2) < minsp2)
            minsp2 = r->ls4[k] / (4 * r->size2);
    minsp2 *= SM_MIN_SPOKE * SM_MIN_SPOKE;
    irr0 = irr_k = sm_tri_irregular(r, x, 0);
    irr_prev = sm_tri_irregular(r, x, n - 1);
    sm_apex(r, 0, p0);
    for (k = 0; k < n; k++) {
        irr_next = k + 1 < n ? sm_tri_irregular(r, x, k + 1) : irr0;
        if (!irr_k && !irr_next && !irr_prev) {
            irr_prev = irr_k;
            irr_k = irr_next;
            continue;
        }
        irr_prev = irr_k;
        irr_k = irr_next;
        sm_apex(r, k, p1);
        *found |= sm_try(r, x, p1, qlo, bigmax, minsp2, bb, best);
        pc[0] = 0.5 * (x[0] + p1[0]);
        pc[1] = 0.5 * (x[1] + p1[1]);
        *found |= sm_try(r, x, pc, qlo, bigmax, minsp2, bb, best);
        if (k + 1 < n)
            sm_apex(r, k + 1, pc);
        else
            pc[0] = p0[0], pc[1] = p0[1];
        pc[0] = 0.5 * (p1[0] + pc[0]);
        pc[1] = 0.5 * (p1[1] + pc[1]);
        *found |= sm_try(r, x, pc, qlo, bigmax, minsp2, bb, best);
    }
    st = SM_PATTERN_STEP * sqrt(l2);
    cx = *found ? best[0] : x[0];
    cy = *found ? best[1] : x[1];
    for (it = 0; it < SM_PATTERN_ITERS; it++) {
        int gain = 0;
        for (d = 0; d < SM_PATTERN_DIRS; d++) {
            pc[0] = cx + st * dir[d][0];
            pc[1] = cy + st * dir[d][1];
            gain |= sm_try(r, x, pc, qlo, bigmax, minsp2, bb, best);
        }
        if (gain) {
            *found = 1;
            cx = best[0];
            cy = best[1];
        } else {
            st *= 0.5;
        }
    }
}

/* The status of a smoothing stopped by the time limit or the progress
 * callback (cvm__tick, polled per vertex visit): every move made keeps the
 * mesh valid, so it stops where it is. */
static cvm_status sm_stopped(cvm__ctx *ctx, cvm_status s)
{
    return cvm__error(ctx, s, CVM_ENT_NONE, -1,
                      "refinement %s while smoothing; the mesh is valid but some triangles may "
                      "not meet the bounds",
                      s == CVM_INCOMPLETE_CANCELLED ? "was cancelled" : "reached the time limit");
}

cvm_status cvm__rf_smooth(cvm__refiner *R, size_t first, const uint8_t *only, int relax, int sweeps,
                         size_t *moves_out)
{
    cvm__tri2 *T = R->T;
    int32_t *star = NULL;
    sm_ring ring = {0, 0, NULL, NULL, NULL, NULL, 1.0};
    uint8_t *cur = NULL, *next = NULL;
    size_t cap = 0, v, moves = 0;
    int sweep, err = 0;
    cvm_status stop = CVM_OK;
    if (moves_out)
        *moves_out = 0;
    if (relax < 0)
        relax = 0;
    if (sweeps < 0)
        sweeps = 0;
    if (sweeps + relax <= 0 || first >= T->nv)
        return CVM_OK;
    /* A vertex is evaluated again only when it or a neighbour moved in the
     * sweep before: otherwise its star is unchanged and so is the decision,
     * so the result is that of full sweeps. */
    cur = cvm__malloc(T->ctx, T->nv);
    next = cvm__malloc(T->ctx, T->nv);
    if (!cur || !next) {
        cvm__free(T->ctx, cur);
        cvm__free(T->ctx, next);
        return cvm__nomem(T->ctx);
    }
    if (only)
        sm_mark_only(T, first, only, relax > 0, cur, next);
    else {
        sm_mark_imperfect(T, cur);
        if (relax > 0)
            sm_dilate(T, cur, next);
    }
    for (sweep = 0; sweep < relax + sweeps; sweep++) {
        size_t moved_before = moves;
        int relaxing = sweep < relax;
        if (sweep == relax && relax > 0) { /* the smart sweeps start afresh */
            if (only)
                sm_mark_only(T, first, only, 0, cur, next);
            else
                sm_mark_imperfect(T, cur);
        }
        memset(next, 0, T->nv);
        for (v = first; v < T->nv; v++) {
            size_t n;
            double c[2], o[2], l2, lmax2, b0, b1, q0, q1, qlo;
            double *x = T->xy + 2 * v;
            int big0, big1;
            if (!cur[v] || (only && !only[v]))
                continue;
            if ((stop = cvm__tick(T->ctx, 1, CVM_STAGE_REFINE, 1.0)))
                break;
            n = sm_star(T, (int32_t)v, &star, &cap, &err);
            /* a smart sweep leaves a star whose angles are all in [55, 65]
             * degrees alone (below): tested before gathering its ring */
            if (!err && !relaxing && n >= 3 && sm_all_perfect(T, star, n))
                continue;
            if (!err && n >= 3) {
                sm_targets(T, (int32_t)v, x, star, n, c, o, &l2, &lmax2);
                /* graded stars are left to the smart sweeps: the ODT point is
                 * the target of a uniform size only */
                if (relaxing && lmax2 > SM_RELAX_GRADED2 * l2)
                    continue;
            }
            if (err || (n >= 3 && !sm_ring_build(R, (int32_t)v, star, n, &ring))) {
                sm_ring_free(T->ctx, &ring);
                cvm__free(T->ctx, star);
                cvm__free(T->ctx, cur);
                cvm__free(T->ctx, next);
                return cvm__nomem(T->ctx);
            }
            if (n < 3)
                continue;
            if (!isfinite(c[0]) || !isfinite(c[1]) || !isfinite(o[0]) || !isfinite(o[1]))
                continue;
            if (!sm_ring_eval(&ring, x, HUGE_VAL, -1.0, INT_MAX, &b0, &q0, &big0))
                continue;
            qlo = q0 < R->sin2_min ? q0 : R->sin2_min;
            if (relaxing) {
                /* relaxation: straight to the ODT point unless the star loses more
                 * than one unit of the regularity count or a bound; only moves
                 * longer than about 3% of the shortest edge wake the neighbours */
                double dx = o[0] - x[0], dy = o[1] - x[1];
                if ((dx == 0 && dy == 0) ||
                    !sm_ring_eval(&ring, o, b0 + SM_RELAX_SLACK + 1e-9, qlo, big0, &b1, &q1, &big1) ||
                    b1 > b0 + SM_RELAX_SLACK || !sm_ring_exact(&ring, o))
                    continue;
                x[0] = o[0];
                x[1] = o[1];
                moves++;
                if (dx * dx + dy * dy > SM_RELAX_WAKE2 * l2)
                    sm_moved(T, v, star, n, cur, next);
                continue;
            }
            /* a star whose angles are all in [55, 65] degrees is left alone */
            if (b0 < -3.0 * (double)n + 0.5)
                continue;
            {
                /* candidates: half, one and one and a half times the step towards
                 * the centroid and towards the ODT point; the most regular one that
                 * meets the bounds is taken (first found on ties) */
                static const double step[3] = {1.0, 0.5, 1.5};
                double best[2] = {0, 0}, bb = b0;
                int k, found = 0;
                for (k = 0; k < 6; k++) {
                    const double *tg = k < 3 ? c : o;
                    double f = step[k % 3], pc[2];
                    pc[0] = x[0] + f * (tg[0] - x[0]);
                    pc[1] = x[1] + f * (tg[1] - x[1]);
                    if ((pc[0] == x[0] && pc[1] == x[1]) ||
                        !sm_ring_eval(&ring, pc, bb, qlo, big0, &b1, &q1, &big1) || !(b1 < bb))
                        continue;
                    bb = b1;
                    best[0] = pc[0];
                    best[1] = pc[1];
                    found = 1;
                }
                if ((sweep - relax >= SM_EXTRA_FROM && b0 > -3.0 * (double)n + SM_EXTRA_MIN_BAD) ||
                    (sweep - relax >= SM_EXTRA_FROM_GRADED && lmax2 > SM_RELAX_GRADED2 * l2))
                    sm_more_candidates(&ring, x, l2, qlo, big0, &bb, best, &found);
                if (!found || !sm_ring_exact(&ring, best))
                    continue;
                x[0] = best[0];
                x[1] = best[1];
            }
            /* this sweep's later vertices see the move already; the next
             * sweep re-evaluates the whole neighbourhood */
            sm_moved(T, v, star, n, cur, next);
            moves++;
        }
        if (stop || (moves == moved_before && !relaxing))
            break;
        {
            uint8_t *sw = cur;
            cur = next;
            next = sw;
        }
    }
    sm_ring_free(T->ctx, &ring);
    cvm__free(T->ctx, star);
    cvm__free(T->ctx, cur);
    cvm__free(T->ctx, next);
    if (moves_out)
        *moves_out = moves;
    return stop ? sm_stopped(T->ctx, stop) : CVM_OK;
}

/* ---- Freitag-Ollivier max-min smoothing ---- */

/* Largest number of active-set iterations per vertex visit, and of step
 * halvings in each line search. */
#define MM_ITERS 12
#define MM_HALVINGS 10
/* functions within this of the minimum are active (Freitag's tolerance) */
#define MM_ACTIVE_TOL 1e-6

/* Sine of every angle of the star of v with v at p: f[3k..3k+2] for star
 * triangle k (angles at v, a, b) and their gradients with respect to p in
 * g (2 per function, when g is not NULL); *fmin = the smallest, *big = star
 * triangles above the size bound (as sm_ring_eval). Returns 0 when a
 * triangle is not strictly counter-clockwise (exact orient2d). */
static int mm_eval(const cvm__refiner *R, int32_t v, const double *p, const int32_t *star,
                   size_t n, double *f, double *g, double *fmin, int *big)
{
    const cvm__tri2 *T = R->T;
    size_t k;
    double m = 2.0;
    int sbig = 0;
    for (k = 0; k < n; k++) {
        const int32_t *tv = T->tv + 3 * (size_t)star[k];
        int i = tv[0] == v ? 0 : tv[1] == v ? 1 : 2;
        int32_t ia = tv[(i + 1) % 3], ib = tv[(i + 2) % 3];
        const double *a = cvm__tri2_pt(T, ia), *b = cvm__tri2_pt(T, ib);
        double la2, lb2, lab2, la, lb, lab, ar, ls, s[3];
        int j;
        if (cvm__orient2d_inline(p, a, b) <= 0)
            return 0;
        la2 = (a[0] - p[0]) * (a[0] - p[0]) + (a[1] - p[1]) * (a[1] - p[1]);
        lb2 = (b[0] - p[0]) * (b[0] - p[0]) + (b[1] - p[1]) * (b[1] - p[1]);
        lab2 = (b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]);
        la = sqrt(la2);
        lb = sqrt(lb2);
        lab = sqrt(lab2);
        ar = (a[0] - p[0]) * (b[1] - p[1]) - (a[1] - p[1]) * (b[0] - p[0]); /* 2 x area */
        if (!(ar > 0) || !(la > 0) || !(lb > 0))
            return 0;
        s[0] = ar / (la * lb);
        s[1] = ar / (la * lab);
        s[2] = ar / (lb * lab);
        for (j = 0; j < 3; j++) {
            if (s[j] < m)
                m = s[j];
            f[3 * k + (size_t)j] = s[j];
        }
        if (g) {
            /* grad(2 x area) = (a1 - b1, b0 - a0); grad |p - a| = (p - a) / |p - a| */
            double ga0 = (a[1] - b[1]) / ar, ga1 = (b[0] - a[0]) / ar;
            double da0 = (p[0] - a[0]) / la2, da1 = (p[1] - a[1]) / la2;
            double db0 = (p[0] - b[0]) / lb2, db1 = (p[1] - b[1]) / lb2;
            double *gk = g + 6 * k;
            gk[0] = s[0] * (ga0 - da0 - db0);
            gk[1] = s[0] * (ga1 - da1 - db1);
            gk[2] = s[1] * (ga0 - da0);
            gk[3] = s[1] * (ga1 - da1);
            gk[4] = s[2] * (ga0 - db0);
            gk[5] = s[2] * (ga1 - db1);
        }
        ls = (R->vls[v] + R->vls[ia] + R->vls[ib]) / 3;
        if ((isfinite(ls) && la2 * lb2 * lab2 > 4 * R->size2 * ls * ls * ar * ar) ||
            (cvm__rf_max_area(R, star[k]) > 0 && ar > 2 * cvm__rf_max_area(R, star[k])))
            sbig++;
    }
    *fmin = m;
    *big = sbig;
    return 1;
}

cvm_status cvm__rf_smooth_maxmin(cvm__refiner *R, size_t first, const uint8_t *only, int sweeps,
                                 int guard, size_t *moves_out)
{
    /* guard: only stars with an angle below 40 degrees (sin 40) */
    const double fmax = guard ? 0.64278760968653925 : 2.0;
    cvm__tri2 *T = R->T;
    int32_t *star = NULL;
    sm_ring ring = {0, 0, NULL, NULL, NULL, NULL, 1.0};
    double *f = NULL, *g = NULL, *f1 = NULL;
    size_t *act = NULL;
    uint8_t *cur = NULL, *next = NULL;
    size_t cap = 0, capf = 0, capg = 0, capf1 = 0, capa = 0, v, moves = 0;
    int sweep, err = 0;
    cvm_status s = CVM_OK;
    if (moves_out)
        *moves_out = 0;
    if (sweeps <= 0 || first >= T->nv)
        return CVM_OK;
    cur = cvm__malloc(T->ctx, T->nv);
    next = cvm__malloc(T->ctx, T->nv);
    if (!cur || !next) {
        s = cvm__nomem(T->ctx);
        goto done;
    }
    /* first sweep: the vertices of triangles with an angle outside [55, 65] degrees */
    memset(cur, 0, T->nv);
    if (only)
        sm_mark_only(T, first, only, 0, cur, next);
    else {
        size_t t;
        for (t = 0; t < T->nt; t++) {
            const int32_t *tv = T->tv + 3 * t;
            if (cvm__tri2_in_domain(T, (int32_t)t) && !sm_perfect(T, (int32_t)t))
                cur[tv[0]] = cur[tv[1]] = cur[tv[2]] = 1;
        }
    }
    for (sweep = 0; sweep < sweeps; sweep++) {
        size_t moved_before = moves;
        memset(next, 0, T->nv);
        for (v = first; v < T->nv; v++) {
            size_t n, nf, k, na, it;
            double *x = T->xy + 2 * v;
            double p[2], f0, fm, fmin1, lmin = INFINITY;
            int big0, bigm, big1, moved = 0;
            if (!cur[v] || (only && !only[v]))
                continue;
            if ((s = cvm__tick(T->ctx, 1, CVM_STAGE_REFINE, 1.0))) {
                s = sm_stopped(T->ctx, s);
                goto done;
            }
            n = sm_star(T, (int32_t)v, &star, &cap, &err);
            if (err)
                break;
            if (n < 3)
                continue;
            nf = 3 * n;
            if ((nf > capf && cvm__grow(T->ctx, (void **)&f, &capf, nf, sizeof *f)) ||
                (nf > capf1 && cvm__grow(T->ctx, (void **)&f1, &capf1, nf, sizeof *f1)) ||
                (2 * nf > capg && cvm__grow(T->ctx, (void **)&g, &capg, 2 * nf, sizeof *g)) ||
                (nf > capa && cvm__grow(T->ctx, (void **)&act, &capa, nf, sizeof *act))) {
                err = 1;
                break;
            }
            p[0] = x[0];
            p[1] = x[1];
            if (!mm_eval(R, (int32_t)v, p, star, n, f, g, &f0, &big0) || f0 >= fmax)
                continue;
            for (k = 0; k < n; k++) {
                const int32_t *tv = T->tv + 3 * (size_t)star[k];
                int i = tv[0] == (int32_t)v ? 0 : tv[1] == (int32_t)v ? 1 : 2;
                const double *a = cvm__tri2_pt(T, tv[(i + 1) % 3]);
                double l = hypot(a[0] - p[0], a[1] - p[1]);
                if (l < lmin)
                    lmin = l;
            }
            fm = f0;
            bigm = big0;
            for (it = 0; it < MM_ITERS; it++) {
                double d[2] = {0, 0}, dd, alpha = INFINITY, amax, q[2], gain;
                int h, ok = 0;
                na = 0;
                for (k = 0; k < nf; k++)
                    if (f[k] <= fm + MM_ACTIVE_TOL)
                        act[na++] = k;
                if (!cvm__minnorm_hull(g, 2, act, na, d))
                    break;
                dd = d[0] * d[0] + d[1] * d[1];
                /* first step at which an inactive function meets the active
                 * ones, to first order (Freitag's step) */
                for (k = 0; k < nf; k++) {
                    double gd = g[2 * k] * d[0] + g[2 * k + 1] * d[1];
                    if (f[k] > fm + MM_ACTIVE_TOL && gd < dd) {
                        double a = (f[k] - fm) / (dd - gd);
                        if (a < alpha)
                            alpha = a;
                    }
                }
                amax = 0.25 * lmin / sqrt(dd); /* never more than a quarter of the shortest spoke */
                if (!(alpha <= amax))
                    alpha = amax;
                for (h = 0; h < MM_HALVINGS; h++, alpha *= 0.5) {
                    q[0] = p[0] + alpha * d[0];
                    q[1] = p[1] + alpha * d[1];
                    if (!isfinite(q[0]) || !isfinite(q[1]))
                        continue;
                    if (mm_eval(R, (int32_t)v, q, star, n, f1, NULL, &fmin1, &big1) &&
                        big1 <= bigm && fmin1 > fm + 1e-12) {
                        ok = 1;
                        break;
                    }
                }
                if (!ok)
                    break;
                p[0] = q[0];
                p[1] = q[1];
                gain = fmin1 - fm;
                if (!mm_eval(R, (int32_t)v, p, star, n, f, g, &fm, &bigm))
                    break; /* cannot happen: p was just accepted */
                moved = 1;
                if (gain < 1e-6 * fm)
                    break; /* improvement has stopped */
            }
            if (!moved || !(fm > f0) || bigm > big0)
                continue;
            if (guard) {
                /* keep the regularity: no more obtuse angles - angles in [55, 65]
                 * (the integer part of sm_ring_eval's score; the mean-ratio
                 * term of a star is below 0.05) */
                double b0, b1, q0, q1;
                int g0, g1;
                if (!sm_ring_build(R, (int32_t)v, star, n, &ring)) {
                    err = 1;
                    break;
                }
                if (!sm_ring_eval(&ring, x, HUGE_VAL, -1.0, INT_MAX, &b0, &q0, &g0) ||
                    !sm_ring_eval(&ring, p, HUGE_VAL, -1.0, INT_MAX, &b1, &q1, &g1) ||
                    floor(b1 + 0.5) > floor(b0 + 0.5))
                    continue;
            }
            x[0] = p[0];
            x[1] = p[1];
            sm_moved(T, v, star, n, cur, next);
            moves++;
        }
        if (err || moves == moved_before)
            break;
        {
            uint8_t *sw = cur;
            cur = next;
            next = sw;
        }
    }
    if (err)
        s = cvm__nomem(T->ctx);
done:
    sm_ring_free(T->ctx, &ring);
    cvm__free(T->ctx, star);
    cvm__free(T->ctx, f);
    cvm__free(T->ctx, f1);
    cvm__free(T->ctx, g);
    cvm__free(T->ctx, act);
    cvm__free(T->ctx, cur);
    cvm__free(T->ctx, next);
    if (moves_out)
        *moves_out = moves;
    return s;
}
