/* smooth.c - post-processing by "smart" Laplacian smoothing and relaxation: a free Steiner vertex moves to the best of its candidate positions (steps towards the centroid of its neighbours and the ODT point, equilateral apexes, a pattern search) when no star triangle inverts (exact orient2d) and the star gets more regular without losing angle or size bounds (star evaluation: smooth_star.c). */
#include <limits.h>
#include <math.h>
#include <string.h>

#include "smooth.h"
#include "delaunay/tri2_store.h"
#include "geom/geom_internal.h"

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
static void sm_apex(const cvm__sm_ring *r, size_t k, double *pc)
{
    const double *a = r->a + 2 * k, *b = r->a + 2 * (k + 1 < r->n ? k + 1 : 0);
    pc[0] = (a[0] + b[0]) / 2 - 0.8660254037844386 * (b[1] - a[1]);
    pc[1] = (a[1] + b[1]) / 2 + 0.8660254037844386 * (b[0] - a[0]);
}

/* 1 when star triangle k of ring r, with the vertex at p, has an angle
 * outside [55, 65] degrees (the test of cvm__sm_ring_eval). */
static int sm_tri_irregular(const cvm__sm_ring *r, const double *p, size_t k)
{
    const double *a = r->a + 2 * k, *b = r->a + 2 * (k + 1 < r->n ? k + 1 : 0);
    return !cvm__sm_sides_regular(cvm__sm_d2(a, p), cvm__sm_d2(b, p), r->lab[k]);
}

/* Try candidate pc for the vertex at x: when it meets the bounds (qlo, bigmax),
 * keeps every spoke at least sqrt(minsp2) long and scores below *bb, it
 * becomes the best (*bb, best). Returns 1 then. */
static int sm_try(const cvm__sm_ring *r, const double *x, const double *pc, double qlo, int bigmax,
                  double minsp2, double *bb, double *best)
{
    double b1, q1;
    size_t k;
    int big1;
    if ((pc[0] == x[0] && pc[1] == x[1]) || !isfinite(pc[0]) || !isfinite(pc[1]) ||
        !cvm__sm_ring_eval(r, pc, *bb, qlo, bigmax, &b1, &q1, &big1) || !(b1 < *bb))
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
static void sm_more_candidates(const cvm__sm_ring *r, const double *x, double l2, double qlo,
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

cvm_status cvm__rf_smooth(cvm__refiner *R, size_t first, const uint8_t *only, int relax, int sweeps,
                         size_t *moves_out)
{
    cvm__tri2 *T = R->T;
    int32_t *star = NULL;
    cvm__sm_ring ring = {0, 0, NULL, NULL, NULL, NULL, 1.0};
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
        cvm__sm_mark_only(T, first, only, relax > 0, cur, next);
    else {
        cvm__sm_mark_imperfect(T, cur);
        if (relax > 0)
            cvm__sm_dilate(T, cur, next);
    }
    for (sweep = 0; sweep < relax + sweeps; sweep++) {
        size_t moved_before = moves;
        int relaxing = sweep < relax;
        if (sweep == relax && relax > 0) { /* the smart sweeps start afresh */
            if (only)
                cvm__sm_mark_only(T, first, only, 0, cur, next);
            else
                cvm__sm_mark_imperfect(T, cur);
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
            n = cvm__sm_star(T, (int32_t)v, &star, &cap, &err);
            /* a smart sweep leaves a star whose angles are all in [55, 65]
             * degrees alone (below): tested before gathering its ring */
            if (!err && !relaxing && n >= 3 && cvm__sm_all_perfect(T, star, n))
                continue;
            if (!err && n >= 3) {
                sm_targets(T, (int32_t)v, x, star, n, c, o, &l2, &lmax2);
                /* graded stars are left to the smart sweeps: the ODT point is
                 * the target of a uniform size only */
                if (relaxing && lmax2 > SM_RELAX_GRADED2 * l2)
                    continue;
            }
            if (err || (n >= 3 && !cvm__sm_ring_build(R, (int32_t)v, star, n, &ring))) {
                cvm__sm_ring_free(T->ctx, &ring);
                cvm__free(T->ctx, star);
                cvm__free(T->ctx, cur);
                cvm__free(T->ctx, next);
                return cvm__nomem(T->ctx);
            }
            if (n < 3)
                continue;
            if (!isfinite(c[0]) || !isfinite(c[1]) || !isfinite(o[0]) || !isfinite(o[1]))
                continue;
            if (!cvm__sm_ring_eval(&ring, x, HUGE_VAL, -1.0, INT_MAX, &b0, &q0, &big0))
                continue;
            qlo = q0 < R->sin2_min ? q0 : R->sin2_min;
            if (relaxing) {
                /* relaxation: straight to the ODT point unless the star loses more
                 * than one unit of the regularity count or a bound; only moves
                 * longer than about 3% of the shortest edge wake the neighbours */
                double dx = o[0] - x[0], dy = o[1] - x[1];
                if ((dx == 0 && dy == 0) ||
                    !cvm__sm_ring_eval(&ring, o, b0 + SM_RELAX_SLACK + 1e-9, qlo, big0, &b1, &q1,
                                       &big1) ||
                    b1 > b0 + SM_RELAX_SLACK || !cvm__sm_ring_exact(&ring, o))
                    continue;
                x[0] = o[0];
                x[1] = o[1];
                moves++;
                if (dx * dx + dy * dy > SM_RELAX_WAKE2 * l2)
                    cvm__sm_moved(T, v, star, n, cur, next);
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
                        !cvm__sm_ring_eval(&ring, pc, bb, qlo, big0, &b1, &q1, &big1) || !(b1 < bb))
                        continue;
                    bb = b1;
                    best[0] = pc[0];
                    best[1] = pc[1];
                    found = 1;
                }
                if ((sweep - relax >= SM_EXTRA_FROM && b0 > -3.0 * (double)n + SM_EXTRA_MIN_BAD) ||
                    (sweep - relax >= SM_EXTRA_FROM_GRADED && lmax2 > SM_RELAX_GRADED2 * l2))
                    sm_more_candidates(&ring, x, l2, qlo, big0, &bb, best, &found);
                if (!found || !cvm__sm_ring_exact(&ring, best))
                    continue;
                x[0] = best[0];
                x[1] = best[1];
            }
            /* this sweep's later vertices see the move already; the next
             * sweep re-evaluates the whole neighbourhood */
            cvm__sm_moved(T, v, star, n, cur, next);
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
    cvm__sm_ring_free(T->ctx, &ring);
    cvm__free(T->ctx, star);
    cvm__free(T->ctx, cur);
    cvm__free(T->ctx, next);
    if (moves_out)
        *moves_out = moves;
    return stop ? cvm__sm_stopped(T->ctx, stop) : CVM_OK;
}
