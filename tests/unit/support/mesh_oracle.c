/* mesh_oracle.c - independent exact validity checker of triangle meshes for the tests. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geom/geom_internal.h"
#include "mesh_oracle.h"

#ifndef CVMTEST_NO_CHECK
#include <check.h>
#endif

double cvmtest_tri_min_angle_deg(const double *a, const double *b, const double *c)
{
    const double *p[3];
    double best = 180.0;
    int k;
    p[0] = a;
    p[1] = b;
    p[2] = c;
    for (k = 0; k < 3; k++) {
        const double *o = p[k], *u = p[(k + 1) % 3], *w = p[(k + 2) % 3];
        double ux = u[0] - o[0], uy = u[1] - o[1], wx = w[0] - o[0], wy = w[1] - o[1];
        double ang = atan2(fabs(ux * wy - uy * wx), ux * wx + uy * wy) * 57.29577951308232;
        if (ang < best)
            best = ang;
    }
    return best;
}

/* A directed edge a->b of triangle t; sorted by the undirected key (lo, hi). */
typedef struct hedge {
    cvm_index lo, hi;
    cvm_index t;
    int fwd; /* 1: a = lo, b = hi */
} hedge;

typedef struct oracle {
    char *msg;
    size_t msglen;
    const double *xy;
    size_t nv;
    const cvm_index *tri;
    size_t nt;
    hedge *he;        /* 3*nt, sorted */
    cvm_index *cons;  /* 2*ncons, each pair (lo, hi), sorted */
    size_t ncons;
    size_t *adj_off;  /* nv+1: neighbours of v in adj[adj_off[v] .. adj_off[v+1]) */
    cvm_index *adj;
    size_t n_orig;    /* vertices below this id are input vertices */
    size_t *visit;    /* nv: stamp of the last segment search that visited each vertex */
    cvm_index *stack; /* nv: vertices to visit in a segment search */
} oracle;

static int ofail(oracle *o, const char *fmt, ...)
{
    va_list ap;
    if (o->msg && o->msglen) {
        va_start(ap, fmt);
        vsnprintf(o->msg, o->msglen, fmt, ap);
        va_end(ap);
    }
    return 0;
}

static const double *P(const oracle *o, cvm_index v)
{
    return o->xy + 2 * (size_t)v;
}

static int cmp_hedge(const void *pa, const void *pb)
{
    const hedge *a = (const hedge *)pa, *b = (const hedge *)pb;
    if (a->lo != b->lo)
        return a->lo < b->lo ? -1 : 1;
    if (a->hi != b->hi)
        return a->hi < b->hi ? -1 : 1;
    if (a->t != b->t)
        return a->t < b->t ? -1 : 1;
    return 0;
}

static int cmp_pair(const void *pa, const void *pb)
{
    const cvm_index *a = (const cvm_index *)pa, *b = (const cvm_index *)pb;
    if (a[0] != b[0])
        return a[0] < b[0] ? -1 : 1;
    if (a[1] != b[1])
        return a[1] < b[1] ? -1 : 1;
    return 0;
}

/* Index of the first half-edge with key (lo, hi), or -1. */
static long find_edge(const oracle *o, cvm_index a, cvm_index b)
{
    cvm_index lo = a < b ? a : b, hi = a < b ? b : a;
    size_t l = 0, r = 3 * o->nt;
    while (l < r) {
        size_t mid = l + (r - l) / 2;
        const hedge *h = o->he + mid;
        if (h->lo < lo || (h->lo == lo && h->hi < hi))
            l = mid + 1;
        else
            r = mid;
    }
    if (l < 3 * o->nt && o->he[l].lo == lo && o->he[l].hi == hi)
        return (long)l;
    return -1;
}

static int is_constrained(const oracle *o, cvm_index a, cvm_index b)
{
    cvm_index key[2];
    key[0] = a < b ? a : b;
    key[1] = a < b ? b : a;
    return o->cons && bsearch(key, o->cons, o->ncons, 2 * sizeof(cvm_index), cmp_pair) != NULL;
}

/* The vertex of triangle t that is neither a nor b. */
static cvm_index third(const oracle *o, cvm_index t, cvm_index a, cvm_index b)
{
    const cvm_index *v = o->tri + 3 * (size_t)t;
    int k;
    for (k = 0; k < 3; k++)
        if (v[k] != a && v[k] != b)
            return v[k];
    return -1;
}

/* Indices, distinct corners, strict counter-clockwise orientation. */
static int check_triangles(oracle *o)
{
    size_t t;
    for (t = 0; t < o->nt; t++) {
        const cvm_index *v = o->tri + 3 * t;
        int k;
        for (k = 0; k < 3; k++)
            if (v[k] < 0 || (size_t)v[k] >= o->nv)
                return ofail(o, "triangle %zu names vertex %ld, outside [0, %zu)", t, (long)v[k],
                            o->nv);
        if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2])
            return ofail(o, "triangle %zu repeats a vertex (%ld %ld %ld)", t, (long)v[0],
                        (long)v[1], (long)v[2]);
        if (!(cvm__orient2d(P(o, v[0]), P(o, v[1]), P(o, v[2])) > 0))
            return ofail(o, "triangle %zu (%ld %ld %ld) is not strictly counter-clockwise", t,
                        (long)v[0], (long)v[1], (long)v[2]);
    }
    return 1;
}

/* Build and sort half-edges; check each edge has at most two opposite sides. */
static int build_edges(oracle *o, size_t *n_edges, size_t *n_boundary)
{
    size_t t, i;
    o->he = (hedge *)malloc((3 * o->nt + 1) * sizeof(hedge));
    if (!o->he)
        return ofail(o, "oracle: out of memory");
    for (t = 0; t < o->nt; t++) {
        int k;
        for (k = 0; k < 3; k++) {
            cvm_index a = o->tri[3 * t + k], b = o->tri[3 * t + (k + 1) % 3];
            hedge *h = o->he + 3 * t + k;
            h->lo = a < b ? a : b;
            h->hi = a < b ? b : a;
            h->t = (cvm_index)t;
            h->fwd = a < b;
        }
    }
    qsort(o->he, 3 * o->nt, sizeof(hedge), cmp_hedge);
    *n_edges = *n_boundary = 0;
    for (i = 0; i < 3 * o->nt;) {
        size_t j = i + 1;
        while (j < 3 * o->nt && o->he[j].lo == o->he[i].lo && o->he[j].hi == o->he[i].hi)
            j++;
        if (j - i > 2)
            return ofail(o, "edge %ld-%ld lies in %zu triangles (non-manifold)", (long)o->he[i].lo,
                        (long)o->he[i].hi, j - i);
        if (j - i == 2 && o->he[i].fwd == o->he[i + 1].fwd)
            return ofail(o, "triangles %ld and %ld both run edge %ld-%ld in the same direction "
                        "(overlap or fold)", (long)o->he[i].t, (long)o->he[i + 1].t,
                        (long)o->he[i].lo, (long)o->he[i].hi);
        (*n_edges)++;
        if (j - i == 1)
            (*n_boundary)++;
        i = j;
    }
    return 1;
}

/* Vertex adjacency (CSR) from the unique edges. */
static int build_adjacency(oracle *o)
{
    size_t i, *fill;
    o->adj_off = (size_t *)calloc(o->nv + 1, sizeof(size_t));
    o->adj = (cvm_index *)malloc((6 * o->nt + 1) * sizeof(cvm_index));
    fill = (size_t *)calloc(o->nv + 1, sizeof(size_t));
    o->visit = (size_t *)calloc(o->nv + 1, sizeof(size_t));
    o->stack = (cvm_index *)malloc((o->nv + 1) * sizeof(cvm_index));
    if (!o->adj_off || !o->adj || !fill || !o->visit || !o->stack) {
        free(fill);
        return ofail(o, "oracle: out of memory");
    }
    for (i = 0; i < 3 * o->nt; i++) {
        if (i > 0 && o->he[i].lo == o->he[i - 1].lo && o->he[i].hi == o->he[i - 1].hi)
            continue;
        o->adj_off[o->he[i].lo + 1]++;
        o->adj_off[o->he[i].hi + 1]++;
    }
    for (i = 0; i < o->nv; i++)
        o->adj_off[i + 1] += o->adj_off[i];
    for (i = 0; i < 3 * o->nt; i++) {
        cvm_index a = o->he[i].lo, b = o->he[i].hi;
        if (i > 0 && a == o->he[i - 1].lo && b == o->he[i - 1].hi)
            continue;
        o->adj[o->adj_off[a] + fill[a]++] = b;
        o->adj[o->adj_off[b] + fill[b]++] = a;
    }
    free(fill);
    return 1;
}

/* Upper half-plane of directions around v, half-open: angles [0, pi). */
static int upper(const double *v, const double *w)
{
    return w[1] > v[1] || (w[1] == v[1] && w[0] > v[0]);
}

/* Every vertex with no boundary edge must be wound exactly once by its
 * triangles: count, per corner (v, w1, w2), sweeps across the ray at angle 0.
 * Exact: only coordinate comparisons. */
static int check_winding(oracle *o, const unsigned char *on_boundary, const unsigned char *used)
{
    long *wind = (long *)calloc(o->nv + 1, sizeof(long));
    size_t t, v;
    if (!wind)
        return ofail(o, "oracle: out of memory");
    for (t = 0; t < o->nt; t++) {
        int k;
        for (k = 0; k < 3; k++) {
            cvm_index a = o->tri[3 * t + k], b = o->tri[3 * t + (k + 1) % 3],
                      c = o->tri[3 * t + (k + 2) % 3];
            if (!upper(P(o, a), P(o, b)) && upper(P(o, a), P(o, c)))
                wind[a]++;
        }
    }
    for (v = 0; v < o->nv; v++) {
        if (used[v] && !on_boundary[v] && wind[v] != 1) {
            long w = wind[v];
            free(wind);
            return ofail(o, "interior vertex %zu is wound %ld times by its triangles (overlap)", v,
                        w);
        }
    }
    free(wind);
    return 1;
}

/* Every interior edge that is not constrained is locally Delaunay. */
static int check_delaunay(oracle *o)
{
    size_t i;
    for (i = 0; i + 1 < 3 * o->nt; i++) {
        const hedge *h = o->he + i, *g = o->he + i + 1;
        cvm_index a, b, c, d;
        if (g->lo != h->lo || g->hi != h->hi)
            continue;
        if (is_constrained(o, h->lo, h->hi))
            continue;
        /* h runs a->b in its triangle (counter-clockwise), g runs b->a. */
        a = h->fwd ? h->lo : h->hi;
        b = h->fwd ? h->hi : h->lo;
        c = third(o, h->t, a, b);
        d = third(o, g->t, a, b);
        if (cvm__incircle(P(o, a), P(o, b), P(o, c), P(o, d)) > 0)
            return ofail(o, "edge %ld-%ld is not locally Delaunay: vertex %ld lies inside the "
                        "circumcircle of triangle %ld (%ld %ld %ld)", (long)a, (long)b, (long)d,
                        (long)h->t, (long)a, (long)b, (long)c);
    }
    return 1;
}

/* Position of w along segment a-b on its major axis, compared with x:
 * all comparisons exact. Returns the coordinate of the axis chosen. */
static int axis_of(const double *a, const double *b)
{
    return fabs(b[0] - a[0]) >= fabs(b[1] - a[1]) ? 0 : 1;
}

/* 1 if w is strictly closer to b than cur along axis ax (or, with weak set, no
 * farther), and not beyond b. */
static int progresses(const double *cur, const double *w, const double *b, int ax, int weak,
                      const double *a)
{
    if (weak) {
        /* a rounded intersection may sit an ulp behind the previous one, or
         * an ulp beyond an end: any place within the segment's extent, widened
         * by 1e-9 of it plus 2^-40 of its coordinates (rounding happens at
         * their scale), will do; visit stamps keep the search finite */
        double lo = a[ax] < b[ax] ? a[ax] : b[ax], hi = a[ax] < b[ax] ? b[ax] : a[ax];
        double mag = fabs(a[0]) + fabs(a[1]) + fabs(b[0]) + fabs(b[1]);
        double eps = 1e-9 * (hi - lo) + 0x1p-40 * mag;
        return w[ax] >= lo - eps && w[ax] <= hi + eps;
    }
    if (cur[ax] < b[ax])
        return w[ax] > cur[ax] && w[ax] <= b[ax];
    return w[ax] < cur[ax] && w[ax] >= b[ax];
}

/* Is input segment k, vertices a-b, a union of mesh edges? Search (depth
 * first) for a path from a to b through vertices exactly on the segment, or
 * Steiner vertices within rounding distance of it (rounded intersections; two
 * of them may share a coordinate, so a Steiner step need not advance along the
 * major axis). With output segments given, only those edges are followed.
 * Each vertex is visited at most once per segment. */
static int check_segment(oracle *o, size_t k, cvm_index a, cvm_index b)
{
    const double *pa = P(o, a), *pb = P(o, b);
    int ax = axis_of(pa, pb);
    size_t nstack = 0, stamp = k + 1;
    cvm_index far = a, loose_a = -1, loose_b = -1;
    /* A rounded intersection lies within a few ulps of the segment: accept
     * Steiner vertices whose distance to it is at most 1e-9 of the larger of
     * the segment's length and its coordinates (|orient2d| = distance x length).
     * This bound only steers the search; the kernel's decisions are exact. */
    double len = fabs(pb[0] - pa[0]) + fabs(pb[1] - pa[1]);
    double mag = fabs(pa[0]) + fabs(pa[1]) + fabs(pb[0]) + fabs(pb[1]);
    double slack = 1e-9 * (len > mag ? len : mag) * len;
    if (pa[ax] == pb[ax])
        return ofail(o, "input segment %zu (vertices %ld-%ld) has zero length", k, (long)a,
                     (long)b);
    o->visit[a] = stamp;
    o->stack[nstack++] = a;
    while (nstack) {
        cvm_index cur = o->stack[--nstack];
        size_t i;
        if (cur == b)
            return 1;
        if (fabs(P(o, cur)[ax] - pa[ax]) > fabs(P(o, far)[ax] - pa[ax]))
            far = cur;
        for (i = o->adj_off[cur]; i < o->adj_off[cur + 1]; i++) {
            cvm_index w = o->adj[i];
            const double *pw = P(o, w);
            int steiner = (size_t)w >= o->n_orig;
            int on_line = w == b || cvm__orient2d(pa, pb, pw) == 0;
            int cur_on_line = cur == a || cvm__orient2d(pa, pb, P(o, cur)) == 0;
            /* a step off the exact line is a rounding case: an input vertex
             * an ulp from the segment's end may carry it (concurrent or
             * nearly coincident segments meet there), even an ulp beyond b;
             * so is a step back onto the line from a vertex within rounding of
             * it (two input points an ulp apart, one on the line: the chain
             * may step sideways between them) */
            int weak = steiner || (size_t)cur >= o->n_orig || !on_line || !cur_on_line;
            if (o->visit[w] == stamp ||
                (w != b && !progresses(P(o, cur), pw, pb, ax, weak, pa)))
                continue;
            /* an input vertex within rounding of the segment may carry it too:
             * a sub-segment from a rounded crossing can pass exactly through it
             * (then only along output segments) */
            if (!on_line && !((steiner || o->cons) && fabs(cvm__orient2d(pa, pb, pw)) <= slack))
                continue;
            if (o->cons && !is_constrained(o, cur, w)) {
                if (on_line && loose_a < 0) {
                    loose_a = cur;
                    loose_b = w;
                }
                continue;
            }
            o->visit[w] = stamp;
            o->stack[nstack++] = w;
        }
    }
    if (loose_a >= 0)
        return ofail(o, "input segment %zu (vertices %ld-%ld): mesh edge %ld-%ld on it is not "
                     "an output segment", k, (long)a, (long)b, (long)loose_a, (long)loose_b);
    return ofail(o, "input segment %zu (vertices %ld-%ld) is not a union of mesh edges: "
                 "no edge continues it from vertex %ld", k, (long)a, (long)b, (long)far);
}

/* With convex set: every vertex used and every boundary edge a hull edge. */
static int check_convex(oracle *o, const unsigned char *used)
{
    size_t i, v;
    for (v = 0; v < o->nv; v++)
        if (!used[v])
            return ofail(o, "vertex %zu is in no triangle of a convex-hull triangulation", v);
    for (i = 0; i < 3 * o->nt; i++) {
        const hedge *h = o->he + i;
        cvm_index a, b;
        if ((i > 0 && o->he[i - 1].lo == h->lo && o->he[i - 1].hi == h->hi) ||
            (i + 1 < 3 * o->nt && o->he[i + 1].lo == h->lo && o->he[i + 1].hi == h->hi))
            continue;
        a = h->fwd ? h->lo : h->hi;
        b = h->fwd ? h->hi : h->lo;
        for (v = 0; v < o->nv; v++)
            if (cvm__orient2d(P(o, a), P(o, b), P(o, (cvm_index)v)) < 0)
                return ofail(o, "boundary edge %ld-%ld is not a convex-hull edge: vertex %zu lies "
                            "outside it", (long)a, (long)b, v);
    }
    return 1;
}

static int run(oracle *o, const cvm_index *cons, size_t ncons, const cvm_index *input_map,
               size_t n_input, const cvmtest_expect *e)
{
    size_t i, n_edges = 0, n_boundary = 0, n_used = 0;
    unsigned char *used, *on_boundary;
    int ok = 1;

    for (i = 0; i < 2 * o->nv; i++)
        if (!isfinite(o->xy[i]))
            return ofail(o, "vertex %zu has a non-finite coordinate", i / 2);
    if (!check_triangles(o) || !build_edges(o, &n_edges, &n_boundary))
        return 0;

    if (cons && ncons) {
        o->cons = (cvm_index *)malloc(2 * ncons * sizeof(cvm_index));
        if (!o->cons)
            return ofail(o, "oracle: out of memory");
        for (i = 0; i < ncons; i++) {
            cvm_index a = cons[2 * i], b = cons[2 * i + 1];
            if (a < 0 || b < 0 || (size_t)a >= o->nv || (size_t)b >= o->nv || a == b)
                return ofail(o, "output segment %zu (%ld-%ld) is not a valid vertex pair", i,
                            (long)a, (long)b);
            o->cons[2 * i] = a < b ? a : b;
            o->cons[2 * i + 1] = a < b ? b : a;
            if (find_edge(o, a, b) < 0)
                return ofail(o, "output segment %zu (%ld-%ld) is not an edge of the mesh", i,
                            (long)a, (long)b);
        }
        qsort(o->cons, ncons, 2 * sizeof(cvm_index), cmp_pair);
        o->ncons = ncons;
    }

    used = (unsigned char *)calloc(o->nv + 1, 1);
    on_boundary = (unsigned char *)calloc(o->nv + 1, 1);
    if (!used || !on_boundary) {
        free(used);
        free(on_boundary);
        return ofail(o, "oracle: out of memory");
    }
    for (i = 0; i < 3 * o->nt; i++) {
        int paired = (i > 0 && o->he[i - 1].lo == o->he[i].lo && o->he[i - 1].hi == o->he[i].hi) ||
                     (i + 1 < 3 * o->nt && o->he[i + 1].lo == o->he[i].lo &&
                      o->he[i + 1].hi == o->he[i].hi);
        used[o->he[i].lo] = used[o->he[i].hi] = 1;
        if (!paired)
            on_boundary[o->he[i].lo] = on_boundary[o->he[i].hi] = 1;
    }
    for (i = 0; i < o->nv; i++)
        n_used += used[i];

    ok = check_winding(o, on_boundary, used);
    if (ok && (!e || e->delaunay))
        ok = check_delaunay(o);
    if (ok && e && e->convex == 1)
        ok = check_convex(o, used);
    if (ok && e && e->check_euler) {
        long chi = (long)n_used - (long)n_edges + (long)o->nt;
        if (chi != e->euler)
            ok = ofail(o, "Euler characteristic V - E + F = %zu - %zu + %zu = %ld, expected %ld",
                      n_used, n_edges, o->nt, chi, e->euler);
    }
    if (ok && e && e->check_area) {
        long double sum = 0;
        double tol = e->area_rel_tol > 0 ? e->area_rel_tol : 1e-12;
        for (i = 0; i < o->nt; i++) {
            const double *a = P(o, o->tri[3 * i]), *b = P(o, o->tri[3 * i + 1]),
                         *c = P(o, o->tri[3 * i + 2]);
            sum += 0.5L * (((long double)b[0] - a[0]) * ((long double)c[1] - a[1]) -
                           ((long double)b[1] - a[1]) * ((long double)c[0] - a[0]));
        }
        if (fabs((double)sum - e->area) > tol * fabs(e->area))
            ok = ofail(o, "total area %.17g differs from the expected %.17g (rel. tol %g)",
                      (double)sum, e->area, tol);
    }
    if (ok && e && e->segs && e->nseg) {
        ok = build_adjacency(o);
        for (i = 0; ok && i < e->nseg; i++) {
            cvm_index ia = e->segs[2 * i], ib = e->segs[2 * i + 1], a, b;
            if (ia < 0 || ib < 0 || (input_map && ((size_t)ia >= n_input || (size_t)ib >= n_input)) ||
                (!input_map && ((size_t)ia >= o->nv || (size_t)ib >= o->nv))) {
                ok = ofail(o, "input segment %zu names a point that does not exist", i);
                break;
            }
            a = input_map ? input_map[ia] : ia;
            b = input_map ? input_map[ib] : ib;
            if (a == b)
                continue; /* both ends merged as duplicates */
            ok = check_segment(o, i, a, b);
        }
    }
    free(used);
    free(on_boundary);
    return ok;
}

void cvmtest_expect_init(cvmtest_expect *e)
{
    memset(e, 0, sizeof *e);
    e->delaunay = 1;
    e->convex = -1;
}

int cvmtest_oracle(char *msg, size_t msglen, const double *xy, size_t nv, const cvm_index *tri,
                   size_t nt, const cvm_index *cons, size_t ncons, const cvm_index *input_map,
                   size_t n_input, const cvmtest_expect *e)
{
    oracle o;
    int ok;
    size_t i;
    memset(&o, 0, sizeof o);
    o.msg = msg;
    o.msglen = msglen;
    if (msg && msglen)
        msg[0] = '\0';
    o.xy = xy;
    o.nv = nv;
    o.tri = tri;
    o.nt = nt;
    o.n_orig = nv;
    if (input_map) {
        cvm_index mx = -1;
        for (i = 0; i < n_input; i++) {
            if (input_map[i] < 0 || (size_t)input_map[i] >= nv)
                return ofail(&o, "input map: point %zu maps to vertex %ld, outside [0, %zu)", i,
                            (long)input_map[i], nv);
            if (input_map[i] > mx)
                mx = input_map[i];
        }
        o.n_orig = (size_t)(mx + 1);
    }
    ok = run(&o, cons, ncons, input_map, n_input, e);
    free(o.he);
    free(o.cons);
    free(o.adj_off);
    free(o.adj);
    free(o.visit);
    free(o.stack);
    return ok;
}

/* Fetch an entity array through the public API into a malloc'd buffer. */
static int fetch_cells(char *msg, size_t msglen, cvm_mesh *m, cvm_entity kind, int per,
                       cvm_index **out, size_t *n_out)
{
    cvm_status s = cvm_mesh_count(n_out, m, kind);
    if (s != CVM_OK) {
        snprintf(msg, msglen, "cvm_mesh_count(%d): %s", (int)kind, cvm_status_str(s));
        return 0;
    }
    *out = (cvm_index *)malloc((per * *n_out + 1) * sizeof(cvm_index));
    if (!*out) {
        snprintf(msg, msglen, "oracle: out of memory");
        return 0;
    }
    if (kind == CVM_ENT_INPUT_POINT)
        s = cvm_mesh_copy_input_map(*out, *n_out, m);
    else
        s = cvm_mesh_copy_cells(*out, per * *n_out, m, kind);
    if (s != CVM_OK) {
        snprintf(msg, msglen, "copying entity %d: %s (%s)", (int)kind, cvm_status_str(s),
                 cvm_mesh_errmsg(m));
        return 0;
    }
    return 1;
}

int cvmtest_mesh_validate(char *msg, size_t msglen, cvm_mesh *m, const cvmtest_expect *e)
{
    cvmtest_expect def;
    size_t nv = 0, nt = 0, ns = 0, nin = 0, nseg_in = 0, nholes = 0;
    double *xy = NULL;
    cvm_index *tri = NULL, *seg = NULL, *map = NULL;
    int ok = 0;
    cvm_status s;

    if (!e) {
        cvmtest_expect_init(&def);
        e = &def;
    }
    if (e->convex == -1) {
        def = *e;
        def.convex = cvm_mesh_count(&nseg_in, m, CVM_ENT_INPUT_SEGMENT) == CVM_OK &&
                     cvm_mesh_count(&nholes, m, CVM_ENT_HOLE) == CVM_OK && nseg_in == 0 &&
                     nholes == 0;
        e = &def;
    }
    s = cvm_mesh_count(&nv, m, CVM_ENT_VERTEX);
    if (s != CVM_OK) {
        snprintf(msg, msglen, "cvm_mesh_count(vertices): %s", cvm_status_str(s));
        return 0;
    }
    xy = (double *)malloc((2 * nv + 1) * sizeof(double));
    if (!xy) {
        snprintf(msg, msglen, "oracle: out of memory");
        return 0;
    }
    s = cvm_mesh_copy_points(xy, 2 * nv, m);
    if (s != CVM_OK) {
        snprintf(msg, msglen, "cvm_mesh_copy_points: %s", cvm_status_str(s));
        goto done;
    }
    if (!fetch_cells(msg, msglen, m, CVM_ENT_TRIANGLE, 3, &tri, &nt) ||
        !fetch_cells(msg, msglen, m, CVM_ENT_SEGMENT, 2, &seg, &ns) ||
        !fetch_cells(msg, msglen, m, CVM_ENT_INPUT_POINT, 1, &map, &nin))
        goto done;
    ok = cvmtest_oracle(msg, msglen, xy, nv, tri, nt, seg, ns, map, nin, e);
done:
    free(xy);
    free(tri);
    free(seg);
    free(map);
    return ok;
}

#ifndef CVMTEST_NO_CHECK
void cvmtest_assert_valid_ex(cvm_mesh *m, const cvmtest_expect *e)
{
    char msg[512];
    cvm_status s;
    ck_assert_ptr_nonnull(m);
    s = cvm_mesh_check(m);
    ck_assert_msg(s == CVM_OK, "cvm_mesh_check: %s: %s", cvm_status_str(s), cvm_mesh_errmsg(m));
    ck_assert_msg(cvmtest_mesh_validate(msg, sizeof msg, m, e), "mesh oracle: %s", msg);
}

void cvmtest_assert_valid(cvm_mesh *m)
{
    cvmtest_assert_valid_ex(m, NULL);
}
#endif
