/* segment.c - recovery of constraint segments: constrained Delaunay triangulation by cavity re-triangulation (Anglada 1997; Shewchuk's pseudo-polygon method). */
#include <math.h>

#include "delaunay_internal.h"
#include "tri2_store.h"
#include "cavity.h"
#include "geom/geom_internal.h"

typedef struct seg_work {
    int32_t *pairs; size_t npairs, cap_pairs;    /* stack of (a, b) still to recover */
    int32_t *cav; size_t ncav, cap_cav;          /* crossed triangles */
    int32_t *left; size_t nleft, cap_left;       /* chain left of a->b, from a to b */
    int32_t *right; size_t nright, cap_right;    /* chain right of a->b, from b to a */
    int32_t *newtri; size_t nnew, cap_new;
    int32_t *rng; size_t cap_rng;                /* ranges for the pseudo-polygon stack */
    int32_t *xe; size_t nxe, cap_xe;             /* crossed edges as vertex pairs */
    int32_t *ends; size_t nends, cap_ends;       /* every piece end so far: the chain's vertices */
    size_t reroutes;                             /* crossings routed through an existing vertex */
    int32_t A, B;                                /* the ends of the input segment */
} seg_work;

static cvm_status push(cvm__tri2 *T, int32_t **arr, size_t *n, size_t *cap, int32_t v)
{
    if (*n >= *cap && cvm__grow(T->ctx, (void **)arr, cap, *n + 1, sizeof(int32_t)))
        return CVM_E_NOMEM;
    (*arr)[(*n)++] = v;
    return CVM_OK;
}

static void set_constrained(cvm__tri2 *T, int32_t t, int j, int32_t seg)
{
    size_t h = 3 * (size_t)t + j;
    if (T->seg_keep_below > 0 && seg >= T->seg_keep_below && T->te[h] >= 0 &&
        T->te[h] < T->seg_keep_below)
        return;
    T->te[h] = seg;
    T->te[T->tn[h]] = seg;
}

/* x on the ray from a through b, given that the three are collinear. */
static int ahead(const double *a, const double *b, const double *x)
{
    if (a[0] != b[0])
        return (x[0] > a[0]) == (b[0] > a[0]) && x[0] != a[0];
    return (x[1] > a[1]) == (b[1] > a[1]) && x[1] != a[1];
}

/* Triangulate the pseudo-polygon C[0..n) whose chain C[1..n-1) lies left of
 * C[0] -> C[n-1], appending counter-clockwise triangles to w->newtri. */
static cvm_status fill_pseudo_polygon(cvm__tri2 *T, seg_work *w, const int32_t *C, size_t n)
{
    size_t nr = 0;
    cvm_status s;
    if (n < 3)
        return CVM_OK;
    if ((s = push(T, &w->rng, &nr, &w->cap_rng, 0)) ||
        (s = push(T, &w->rng, &nr, &w->cap_rng, (int32_t)(n - 1))))
        return s;
    while (nr) {
        int32_t hi = w->rng[--nr], lo = w->rng[--nr], c = lo + 1, d;
        const double *plo = cvm__tri2_pt(T, C[lo]), *phi = cvm__tri2_pt(T, C[hi]);
        for (d = lo + 2; d < hi; d++) {
            if (cvm__incircle_sos(plo, phi, cvm__tri2_pt(T, C[c]), cvm__tri2_pt(T, C[d]), C[lo],
                                  C[hi], C[c], C[d]) > 0)
                c = d;
        }
        if ((s = push(T, &w->newtri, &w->nnew, &w->cap_new, C[lo])) ||
            (s = push(T, &w->newtri, &w->nnew, &w->cap_new, C[hi])) ||
            (s = push(T, &w->newtri, &w->nnew, &w->cap_new, C[c])))
            return s;
        if (c - lo >= 2) {
            if ((s = push(T, &w->rng, &nr, &w->cap_rng, lo)) ||
                (s = push(T, &w->rng, &nr, &w->cap_rng, c)))
                return s;
        }
        if (hi - c >= 2) {
            if ((s = push(T, &w->rng, &nr, &w->cap_rng, c)) ||
                (s = push(T, &w->rng, &nr, &w->cap_rng, hi)))
                return s;
        }
    }
    return CVM_OK;
}

enum { STEP_DONE, STEP_SPLIT, STEP_CROSS };

/* p moved k units in the last place, in each coordinate, to the side of the
 * line x-y given by side (+1: left of x -> y): straight across the line. */
static void nudge_across(double *p, const double *x, const double *y, int side, int k)
{
    double n[2];
    int i, j;
    n[0] = -(y[1] - x[1]) * side;
    n[1] = (y[0] - x[0]) * side;
    for (i = 0; i < 2; i++)
        for (j = 0; j < k && n[i] != 0; j++)
            p[i] = nextafter(p[i], n[i] > 0 ? INFINITY : -INFINITY);
}

/* Split constrained edge hj of triangle ht (piece x-y of another segment) at
 * the rounded crossing p, or with nudge set at p moved 1, 2, 4, ... 64 ulps
 * across the piece to either side: when p rounded past a sliver beside the
 * piece, the exact crossing lies inside the two triangles, and a nearby
 * double on the right side usually does too. *nv_out is the new vertex, or -1
 * when no candidate could be inserted (nothing changed). */
static cvm_status split_at_crossing(cvm__tri2 *T, const double *p, int32_t ht, int hj, int nudge,
                                    int32_t *nv_out)
{
    const int32_t *tv = T->tv + 3 * (size_t)ht;
    double px[2], py[2]; /* copies: adding a vertex may move T->xy */
    int attempt, last = nudge ? 14 : 0;
    px[0] = cvm__tri2_pt(T, tv[(hj + 1) % 3])[0];
    px[1] = cvm__tri2_pt(T, tv[(hj + 1) % 3])[1];
    py[0] = cvm__tri2_pt(T, tv[(hj + 2) % 3])[0];
    py[1] = cvm__tri2_pt(T, tv[(hj + 2) % 3])[1];
    *nv_out = -1;
    for (attempt = nudge ? 0 : -1; attempt < last; attempt++) {
        double q[2];
        int32_t nv;
        cvm__ins res;
        cvm_status s;
        q[0] = p[0];
        q[1] = p[1];
        if (attempt >= 0)
            nudge_across(q, px, py, attempt % 2 ? -1 : 1, 1 << (attempt / 2));
        if ((s = cvm__tri2_add_vertex(T, q, &nv)))
            return s;
        if ((s = cvm__tri2_split_edge(T, nv, ht, hj, &res))) {
            T->nv--;
            return s;
        }
        if (res == CVM__INS_DONE) {
            *nv_out = nv;
            return CVM_OK;
        }
        T->nv--;
    }
    return CVM_OK;
}

/* Whether q lies on segment a-b within the tolerance of a segment's chain
 * stated at cvm_mesh_triangulate(): 2^-40 (M + L) across it and along it. */
static int within_chain(const double *pa, const double *pb, const double *q)
{
    double dx = pb[0] - pa[0], dy = pb[1] - pa[1], len = sqrt(dx * dx + dy * dy);
    double mag = fmax(fmax(fabs(pa[0]), fabs(pa[1])), fmax(fabs(pb[0]), fabs(pb[1])));
    double tol = 0x1p-40 * (mag + len);
    double along = ((q[0] - pa[0]) * dx + (q[1] - pa[1]) * dy) / len;
    return along >= -tol && along <= len + tol && fabs(cvm__orient2d(pa, pb, q)) <= tol * len;
}

/* q lies strictly between a and b along the axis on which a-b is longer
 * (exact comparisons; q need not be on the line). */
static int strictly_between(const double *a, const double *b, const double *q)
{
    int i = fabs(b[0] - a[0]) >= fabs(b[1] - a[1]) ? 0 : 1;
    return q[i] != a[i] && q[i] != b[i] && (q[i] > a[i]) != (q[i] > b[i]);
}

/* No double splits the piece x-y: the two slivers beside it are thinner than
 * an ulp where a-b crosses it (a-b and the piece nearly coincide). Of x and y
 * the end nearer the line a-b, if within_chain() of a-b, is where they meet;
 * else -1. */
static int32_t near_end(const double *pa, const double *pb, int32_t x, const double *px,
                        int32_t y, const double *py)
{
    double ox = fabs(cvm__orient2d(pa, pb, px)), oy = fabs(cvm__orient2d(pa, pb, py));
    if (ox <= oy)
        return within_chain(pa, pb, px) ? x : -1;
    return within_chain(pa, pb, py) ? y : -1;
}

/* 1 if q is within 16 ulps of p in both coordinates: p is then that vertex,
 * rounded differently. A choice of construction, not a topological decision. */
static int at_vertex(const double *p, const double *q)
{
    int i;
    for (i = 0; i < 2; i++) {
        double m = fmax(fabs(p[i]), fabs(q[i]));
        if (fabs(p[i] - q[i]) > 16 * (nextafter(m, INFINITY) - m))
            return 0;
    }
    return 1;
}

/* Vertex z lies exactly on the input segment w->A - w->B, strictly inside it
 * and strictly between the ends a, b of the piece being recovered, which is
 * not that segment: the piece runs from or to a rounded crossing a few ulps
 * off the segment's line, so z may lie off the piece. An input point lying
 * exactly in the interior of a segment splits it (cvm_mesh_triangulate()): z
 * joins the chain. A point on the line beyond an end does not (with a piece
 * from a rounded vertex an ulp behind that end it sent the pieces back and
 * forth: tests/fuzz/corpus/cdt/regression_segment_start_rerouted_an_ulp_behind_near_offset). */
static int on_input_segment(const cvm__tri2 *T, const seg_work *w, int32_t a, int32_t b, int32_t z)
{
    const double *pz;
    size_t k;
    if (!w || z < 0 || (a == w->A && b == w->B))
        return 0;
    pz = cvm__tri2_pt(T, z);
    if (!(cvm__orient2d(cvm__tri2_pt(T, w->A), cvm__tri2_pt(T, w->B), pz) == 0 &&
          ahead(cvm__tri2_pt(T, w->A), cvm__tri2_pt(T, w->B), pz) &&
          ahead(cvm__tri2_pt(T, w->B), cvm__tri2_pt(T, w->A), pz) &&
          ahead(cvm__tri2_pt(T, a), cvm__tri2_pt(T, b), pz) &&
          ahead(cvm__tri2_pt(T, b), cvm__tri2_pt(T, a), pz)))
        return 0;
    /* z already ends a piece: the chain was routed back past it, through a
     * crossing an ulp behind a piece's start, and joining z again would send
     * the pieces back and forth between z and that crossing
     * (tests/fuzz/corpus/cdt/regression_crossing_behind_a_piece_start_not_revisited). */
    for (k = 0; k < w->nends; k++)
        if (w->ends[k] == z)
            return 0;
    return 1;
}

/* Find, around a, the edge a-b or the first triangle the segment enters.
 * Returns STEP_DONE (edge exists, now constrained), STEP_SPLIT (*v_out on the
 * segment, edge a-v constrained), or STEP_CROSS with *t_out, *i_out: triangle
 * (a, x, y) with a at i whose edge x-y the segment crosses. */
static int start_at(cvm__tri2 *T, const seg_work *w, int32_t a, int32_t b, int32_t seg,
                    int32_t *t_out, int *i_out, int32_t *v_out)
{
    const double *pa = cvm__tri2_pt(T, a), *pb = cvm__tri2_pt(T, b);
    int32_t t0 = T->vtri[a], t = t0;
    do {
        const int32_t *tv = T->tv + 3 * (size_t)t;
        int i = tv[0] == a ? 0 : tv[1] == a ? 1 : 2;
        int32_t x = tv[(i + 1) % 3], y = tv[(i + 2) % 3];
        if (x == b || y == b) {
            set_constrained(T, t, x == b ? (i + 2) % 3 : (i + 1) % 3, seg);
            return STEP_DONE;
        }
        if (x >= 0 && y >= 0) {
            double ox = cvm__orient2d(pa, pb, cvm__tri2_pt(T, x));
            double oy = cvm__orient2d(pa, pb, cvm__tri2_pt(T, y));
            if ((ox == 0 && ahead(pa, pb, cvm__tri2_pt(T, x))) || on_input_segment(T, w, a, b, x)) {
                set_constrained(T, t, (i + 2) % 3, seg);
                *v_out = x;
                return STEP_SPLIT;
            }
            if ((oy == 0 && ahead(pa, pb, cvm__tri2_pt(T, y))) || on_input_segment(T, w, a, b, y)) {
                set_constrained(T, t, (i + 1) % 3, seg);
                *v_out = y;
                return STEP_SPLIT;
            }
            if (ox < 0 && oy > 0) {
                *t_out = t;
                *i_out = i;
                return STEP_CROSS;
            }
        }
        t = T->tn[3 * (size_t)t + (i + 1) % 3] / 3;
    } while (t != t0);
    return -1;
}

/* 1 if a vertex occurs twice in c[0..n): a vertex whose whole star the
 * segment crosses (possible beside constrained slivers), so the crossed
 * triangles do not form two pseudo-polygons. */
static int has_repeat(const int32_t *c, size_t n)
{
    size_t i, j;
    for (i = 0; i < n; i++)
        for (j = i + 1; j < n; j++)
            if (c[i] == c[j])
                return 1;
    return 0;
}

/* Find edge x-y: *t_out, *j_out with edge j of t joining x and y. */
static int find_edge(const cvm__tri2 *T, int32_t x, int32_t y, int32_t *t_out, int *j_out)
{
    int32_t t0 = T->vtri[x], t = t0;
    if (t0 < 0)
        return 0;
    do {
        const int32_t *v = T->tv + 3 * (size_t)t;
        int i = v[0] == x ? 0 : v[1] == x ? 1 : 2;
        if (v[(i + 1) % 3] == y || v[(i + 2) % 3] == y) {
            *t_out = t;
            *j_out = v[(i + 1) % 3] == y ? (i + 2) % 3 : (i + 1) % 3;
            return 1;
        }
        t = T->tn[3 * (size_t)t + (i + 1) % 3] / 3;
    } while (t != t0);
    return 0;
}

/* Edge x-y properly crosses segment a-b (exact). */
static int crosses(const cvm__tri2 *T, int32_t a, int32_t b, int32_t x, int32_t y)
{
    const double *pa = cvm__tri2_pt(T, a), *pb = cvm__tri2_pt(T, b);
    const double *px = cvm__tri2_pt(T, x), *py = cvm__tri2_pt(T, y);
    double ox, oy, oa, ob;
    if (x == a || x == b || y == a || y == b)
        return 0;
    ox = cvm__orient2d(pa, pb, px);
    oy = cvm__orient2d(pa, pb, py);
    oa = cvm__orient2d(px, py, pa);
    ob = cvm__orient2d(px, py, pb);
    return ((ox > 0 && oy < 0) || (ox < 0 && oy > 0)) && ((oa > 0 && ob < 0) || (oa < 0 && ob > 0));
}

/* Recover a-b by flipping the edges it crosses (Sloan 1993): an edge whose
 * quadrilateral is convex is flipped, else retried later; a new edge that
 * still crosses is queued again. Then restore the constrained Delaunay
 * property around the touched vertices by Lawson flips. Used when the crossed
 * triangles are not two pseudo-polygons. */
static cvm_status flip_recover(cvm__tri2 *T, seg_work *w, int32_t a, int32_t b, int32_t seg)
{
    size_t head = 0, guard = 0, limit;
    int32_t t, v0 = -1;
    int j, i;
    cvm_status s;
    limit = 64 + 16 * w->nxe * w->nxe;
    while (head < w->nxe) {
        int32_t x = w->xe[head], y = w->xe[head + 1], u, k, pv, pw;
        const int32_t *tv;
        head += 2;
        if (++guard > limit)
            return cvm__error(T->ctx, CVM_E_INTERNAL, CVM_ENT_INPUT_SEGMENT, seg,
                              "segment %ld: flip-based recovery did not converge", (long)seg);
        if (!find_edge(T, x, y, &t, &j) || !crosses(T, a, b, x, y))
            continue;
        tv = T->tv + 3 * (size_t)t;
        u = T->tn[3 * (size_t)t + j] / 3;
        k = T->tn[3 * (size_t)t + j] % 3;
        pv = tv[j];
        pw = T->tv[3 * (size_t)u + k];
        if (pv < 0 || pw < 0 ||
            cvm__orient2d(cvm__tri2_pt(T, pv), cvm__tri2_pt(T, tv[(j + 1) % 3]), cvm__tri2_pt(T, pw)) <= 0 ||
            cvm__orient2d(cvm__tri2_pt(T, pw), cvm__tri2_pt(T, tv[(j + 2) % 3]), cvm__tri2_pt(T, pv)) <= 0) {
            if ((s = push(T, &w->xe, &w->nxe, &w->cap_xe, x)) ||
                (s = push(T, &w->xe, &w->nxe, &w->cap_xe, y)))
                return s;
            continue;
        }
        cvm__tri2_flip(T, t, j);
        if (crosses(T, a, b, pv, pw)) {
            if ((s = push(T, &w->xe, &w->nxe, &w->cap_xe, pv)) ||
                (s = push(T, &w->xe, &w->nxe, &w->cap_xe, pw)))
                return s;
        }
    }
    if (start_at(T, NULL, a, b, seg, &t, &i, &v0) != STEP_DONE)
        return cvm__error(T->ctx, CVM_E_INTERNAL, CVM_ENT_INPUT_SEGMENT, seg,
                          "segment %ld: edge %ld-%ld missing after flip-based recovery",
                          (long)seg, (long)a, (long)b);
    if ((s = push(T, &w->left, &w->nleft, &w->cap_left, b)) ||
        (s = push(T, &w->left, &w->nleft, &w->cap_left, a)))
        return s;
    if ((s = cvm__tri2_legalize_stars(T, w->left, w->nleft)))
        return s;
    return cvm__tri2_legalize_stars(T, w->right, w->nright);
}

static cvm_status recover(cvm__tri2 *T, seg_work *w, int32_t a, int32_t b, int32_t seg, int split,
                          int32_t *other_seg_out)
{
    const double *pa = cvm__tri2_pt(T, a), *pb = cvm__tri2_pt(T, b);
    int32_t t, x, y, v = -1;
    int i, r;
    size_t h;
    cvm_status s;

    r = start_at(T, w, a, b, seg, &t, &i, &v);
    if (r == STEP_DONE)
        return CVM_OK;
    if (r == STEP_SPLIT) {
        if ((s = push(T, &w->pairs, &w->npairs, &w->cap_pairs, v)) ||
            (s = push(T, &w->pairs, &w->npairs, &w->cap_pairs, b)))
            return s;
        return CVM_OK;
    }
    if (r != STEP_CROSS)
        return cvm__error(T->ctx, CVM_E_INTERNAL, CVM_ENT_INPUT_SEGMENT, seg,
                          "segment recovery: no triangle around vertex %ld faces vertex %ld",
                          (long)a, (long)b);
    w->ncav = w->nleft = w->nright = w->nnew = 0;
    x = T->tv[3 * (size_t)t + (i + 1) % 3];
    y = T->tv[3 * (size_t)t + (i + 2) % 3];
    h = 3 * (size_t)t + i;
    w->nxe = 0;
    if ((s = push(T, &w->cav, &w->ncav, &w->cap_cav, t)) ||
        (s = push(T, &w->left, &w->nleft, &w->cap_left, a)) ||
        (s = push(T, &w->left, &w->nleft, &w->cap_left, y)) ||
        (s = push(T, &w->right, &w->nright, &w->cap_right, x)))
        return s;
    for (;;) {
        int32_t u, z;
        int k, px, py;
        double oz;
        if (T->te[h] >= 0) {
            int32_t s2 = T->te[h];
            int32_t ht = (int32_t)(h / 3);
            int hj = (int)(h % 3);
            double p[2];
            int32_t nv;
            if (!split) {
                *other_seg_out = s2;
                return CVM_E_INPUT_INTERSECTING;
            }
            cvm__segment_intersection2d(pa, pb, cvm__tri2_pt(T, x), cvm__tri2_pt(T, y), p);
            /* On or beside an end of the piece x-y, strictly between a and b,
             * a rounded crossing where a third segment meets these two
             * (concurrent segments, or two overlapping ones crossing the same
             * piece): that end is the crossing, so a-b is routed through it
             * (the budget keeps a pathological cycle finite) rather than split
             * x-y again an ulp from it. */
            {
                int32_t end = at_vertex(p, cvm__tri2_pt(T, x))   ? x
                              : at_vertex(p, cvm__tri2_pt(T, y)) ? y
                                                                 : -1;
                const double *pe = end >= 0 ? cvm__tri2_pt(T, end) : NULL;
                nv = -1;
                if (pe && strictly_between(pa, pb, pe) && within_chain(pa, pb, pe) &&
                    w->reroutes++ <= 64 + T->nv)
                    nv = end;
            }
            if (nv < 0 && (s = split_at_crossing(T, p, ht, hj, 0, &nv)))
                return s;
            if (nv < 0) {
                /* p cannot split x-y. On or beside an end of the piece (also
                 * one an ulp behind a or beyond b), that end is the crossing;
                 * elsewhere p rounded past a sliver: nudge it. Positions are
                 * read afresh: adding a candidate vertex may move T->xy, so
                 * pa and pb are stale here. */
                int32_t end = at_vertex(p, cvm__tri2_pt(T, x))   ? x
                              : at_vertex(p, cvm__tri2_pt(T, y)) ? y
                                                                 : -1;
                if (end >= 0 &&
                    within_chain(cvm__tri2_pt(T, a), cvm__tri2_pt(T, b), cvm__tri2_pt(T, end)) &&
                    w->reroutes++ <= 64 + T->nv)
                    nv = end;
                else if ((s = split_at_crossing(T, p, ht, hj, 1, &nv)))
                    return s;
                if (nv < 0 && w->reroutes++ <= 64 + T->nv)
                    nv = near_end(cvm__tri2_pt(T, a), cvm__tri2_pt(T, b), x, cvm__tri2_pt(T, x), y,
                                  cvm__tri2_pt(T, y));
                if (nv < 0)
                    return cvm__error(T->ctx, CVM_E_INTERNAL, CVM_ENT_VERTEX, (int64_t)T->nv,
                                      "vertex %ld, computed where two segments cross, rounded too "
                                      "far off them to be inserted", (long)T->nv);
            }
            if ((s = push(T, &w->pairs, &w->npairs, &w->cap_pairs, nv)) ||
                (s = push(T, &w->pairs, &w->npairs, &w->cap_pairs, b)) ||
                (s = push(T, &w->pairs, &w->npairs, &w->cap_pairs, a)) ||
                (s = push(T, &w->pairs, &w->npairs, &w->cap_pairs, nv)))
                return s;
            return CVM_OK;
        }
        u = T->tn[h] / 3;
        k = T->tn[h] % 3;
        z = T->tv[3 * (size_t)u + k];
        if ((s = push(T, &w->cav, &w->ncav, &w->cap_cav, u)) ||
            (s = push(T, &w->xe, &w->nxe, &w->cap_xe, x)) ||
            (s = push(T, &w->xe, &w->nxe, &w->cap_xe, y)))
            return s;
        if (z == b)
            break;
        oz = cvm__orient2d(pa, pb, cvm__tri2_pt(T, z));
        if (oz == 0 || on_input_segment(T, w, a, b, z)) {
            /* z lies on the segment: recover a-z first, then z-b */
            if ((s = push(T, &w->pairs, &w->npairs, &w->cap_pairs, z)) ||
                (s = push(T, &w->pairs, &w->npairs, &w->cap_pairs, b)) ||
                (s = push(T, &w->pairs, &w->npairs, &w->cap_pairs, a)) ||
                (s = push(T, &w->pairs, &w->npairs, &w->cap_pairs, z)))
                return s;
            return CVM_OK;
        }
        px = T->tv[3 * (size_t)u] == x ? 0 : T->tv[3 * (size_t)u + 1] == x ? 1 : 2;
        py = T->tv[3 * (size_t)u] == y ? 0 : T->tv[3 * (size_t)u + 1] == y ? 1 : 2;
        if (oz > 0) {
            if ((s = push(T, &w->left, &w->nleft, &w->cap_left, z)))
                return s;
            y = z;
            h = 3 * (size_t)u + py;
        } else {
            if ((s = push(T, &w->right, &w->nright, &w->cap_right, z)))
                return s;
            x = z;
            h = 3 * (size_t)u + px;
        }
    }
    if (has_repeat(w->left, w->nleft) || has_repeat(w->right, w->nright))
        return flip_recover(T, w, a, b, seg);
    /* left chain: a, L..., b (chain left of a->b); right chain: b, R reversed, a */
    if ((s = push(T, &w->left, &w->nleft, &w->cap_left, b)))
        return s;
    if ((s = fill_pseudo_polygon(T, w, w->left, w->nleft)))
        return s;
    {
        /* reverse the right chain in place and close it with b first, a last */
        size_t lo = 0, hi = w->nright;
        if ((s = push(T, &w->right, &w->nright, &w->cap_right, a)))
            return s;
        if ((s = push(T, &w->right, &w->nright, &w->cap_right, b)))
            return s;
        /* right = R0..Rk-1, a, b  ->  b, Rk-1..R0, a */
        {
            int32_t *R = w->right;
            size_t n = w->nright, m;
            int32_t bb = R[n - 1];
            for (m = n - 1; m > 0; m--)
                R[m] = R[m - 1];
            R[0] = bb;
            /* now b, R0..Rk-1, a: reverse the middle */
            lo = 1;
            hi = n - 2;
            while (lo < hi) {
                int32_t tmp = R[lo];
                R[lo] = R[hi];
                R[hi] = tmp;
                lo++;
                hi--;
            }
        }
        if ((s = fill_pseudo_polygon(T, w, w->right, w->nright)))
            return s;
    }
    return cvm__tri2_replace(T, w->cav, w->ncav, w->newtri, w->nnew / 3, a, b, seg);
}

cvm_status cvm__tri2_insert_segment(cvm__tri2 *T, int32_t a, int32_t b, int32_t seg, int split,
                                    int32_t *other_seg_out)
{
    seg_work w = {0};
    cvm_status s = CVM_OK;
    size_t pieces = 0;
    *other_seg_out = -1;
    w.A = a;
    w.B = b;
    if ((s = cvm__tri2_enable_constraints(T)))
        return s;
    if ((s = push(T, &w.pairs, &w.npairs, &w.cap_pairs, a)) ||
        (s = push(T, &w.pairs, &w.npairs, &w.cap_pairs, b)))
        goto done;
    while (w.npairs) {
        int32_t bb = w.pairs[--w.npairs], aa = w.pairs[--w.npairs];
        /* each piece ends at a vertex on the segment that none before ended
         * at, so there are fewer pieces than vertices; more means the
         * collinearity tests disagree (coordinates whose products underflow
         * are not decided exactly) and the walk would cycle between them */
        if (++pieces > 2 * (size_t)T->nv + 2) {
            s = cvm__error(T->ctx, CVM_E_INTERNAL, CVM_ENT_INPUT_SEGMENT, seg,
                           "segment %ld (points %ld-%ld): recovery made no progress at the piece "
                           "%ld-%ld: the collinearity tests along it disagree (coordinates too "
                           "small to decide exactly?)", (long)seg, (long)a, (long)b, (long)aa,
                           (long)bb);
            break;
        }
        if ((s = push(T, &w.ends, &w.nends, &w.cap_ends, aa)) ||
            (s = push(T, &w.ends, &w.nends, &w.cap_ends, bb)))
            break;
        s = recover(T, &w, aa, bb, seg, split, other_seg_out);
        if (s)
            break;
    }
done:
    cvm__free(T->ctx, w.pairs);
    cvm__free(T->ctx, w.cav);
    cvm__free(T->ctx, w.left);
    cvm__free(T->ctx, w.right);
    cvm__free(T->ctx, w.newtri);
    cvm__free(T->ctx, w.rng);
    cvm__free(T->ctx, w.xe);
    cvm__free(T->ctx, w.ends);
    return s;
}
