/* resample.c - CVM_OPT_KEEP_SEGMENT_VERTICES = 0: chains of segments forming a smooth curve re-discretised as one curve with the sizing, before refinement (the triangulation is rebuilt by resample_rebuild.c). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "resample.h"
#include "geom/geom_internal.h"
#include "geom/measure.h"

static void rs_free(rs_state *S)
{
    cvm__ctx *c = S->ctx;
    cvm__free(c, S->e);
    cvm__free(c, S->first);
    cvm__free(c, S->inc);
    cvm__free(c, S->inner);
    cvm__free(c, S->removed);
    cvm__free(c, S->used);
    cvm__free(c, S->replaced);
    cvm__free(c, S->stamp);
    cvm__free(c, S->cmark);
    cvm__free(c, S->byx);
    cvm__free(c, S->pv);
    cvm__free(c, S->pe);
    cvm__free(c, S->cum);
    cvm__free(c, S->tab);
    cvm__free(c, S->pos);
    cvm__free(c, S->poly);
    cvm__free(c, S->nxy);
    cvm__free(c, S->nfrac);
    cvm__free(c, S->ninfo);
    cvm__free(c, S->pc);
    cvm__free(c, S->split);
}

static const double *rs_pt(const rs_state *S, int32_t v)
{
    return S->T->xy + 2 * (size_t)v;
}

static int cmp_xv(const void *pa, const void *pb)
{
    const rs_xv *a = pa, *b = pb;
    if (a->x != b->x)
        return a->x < b->x ? -1 : 1;
    return (a->v > b->v) - (a->v < b->v);
}

/* The other end of edge k from v. */
static int32_t rs_other(const rs_state *S, size_t k, int32_t v)
{
    return S->e[k].a == v ? S->e[k].b : S->e[k].a;
}

/* Turning angle (degrees) at b of the path a-b-c. */
static double rs_turn(const double *a, const double *b, const double *c)
{
    return cvm__turn_angle(a, b, c) * 180.0 / CVM__PI;
}

/* Every constrained edge (those outside the domain too, which the rebuild
 * keeps), incidences, and which vertices may be inner chain vertices: exactly
 * two such edges, both with a domain side, of segments with the same marker,
 * turning by less than RS_TURN_DEG. A vertex with an edge outside the domain,
 * or on the kept convex hull, is never inner (a new point on a hull edge rounds
 * a few ulps off it, and the rebuilt hull would span slivers over the reflex
 * ones; the march splits hull edges on the mesh, where the hull just turns). */
static cvm_status rs_graph(rs_state *S)
{
    const cvm__tri2 *T = S->T;
    size_t t, k, v;
    int j, keep_hull = S->in->keep_hull;
    unsigned char *outside = cvm__calloc(S->ctx, S->nv + 1, 1);
    if (!outside)
        return CVM_E_NOMEM;
    for (t = 0; t < T->nt && T->te; t++) {
        int in = cvm__tri2_in_domain(T, (int32_t)t);
        if (!in && (!cvm__tri2_is_live(T, (int32_t)t) || cvm__tri2_is_ghost(T, (int32_t)t)))
            continue;
        for (j = 0; j < 3; j++) {
            size_t h = 3 * t + (size_t)j;
            int32_t a = T->tv[3 * t + (size_t)(j + 1) % 3], b = T->tv[3 * t + (size_t)(j + 2) % 3];
            int32_t nb = T->tn[h] / 3;
            int nb_in = cvm__tri2_in_domain(T, nb);
            if (T->te[h] < 0)
                continue;
            /* once per edge: from a domain side (the lower a when both are),
             * else from the live side (the lower a when both are live) */
            if (in ? nb_in && a > b
                   : nb_in || (!cvm__tri2_is_ghost(T, nb) && a > b))
                continue;
            if (cvm__grow(S->ctx, (void **)&S->e, &S->cap_e, S->ne + 1, sizeof *S->e)) {
                cvm__free(S->ctx, outside);
                return CVM_E_NOMEM;
            }
            S->e[S->ne].a = a;
            S->e[S->ne].b = b;
            S->e[S->ne].seg = T->te[h];
            S->ne++;
            if ((!in && !nb_in) || (keep_hull && cvm__tri2_is_ghost(T, nb)))
                outside[a] = outside[b] = 1;
        }
    }
    S->first = cvm__calloc(S->ctx, S->nv + 2, sizeof *S->first);
    S->inc = cvm__malloc(S->ctx, (2 * S->ne + 1) * sizeof *S->inc);
    S->inner = cvm__calloc(S->ctx, S->nv + 1, 1);
    S->removed = cvm__calloc(S->ctx, S->nv + 1, 1);
    S->used = cvm__calloc(S->ctx, S->ne + 1, 1);
    S->replaced = cvm__calloc(S->ctx, S->ne + 1, 1);
    S->stamp = cvm__malloc(S->ctx, (S->nv + 1) * sizeof *S->stamp);
    S->cmark = cvm__malloc(S->ctx, (S->nv + 1) * sizeof *S->cmark);
    S->byx = cvm__malloc(S->ctx, (S->nv + 1) * sizeof *S->byx);
    if (!S->first || !S->inc || !S->inner || !S->removed || !S->used || !S->replaced || !S->stamp ||
        !S->cmark || !S->byx) {
        cvm__free(S->ctx, outside);
        return CVM_E_NOMEM;
    }
    for (k = 0; k < S->ne; k++) {
        S->first[S->e[k].a + 2]++;
        S->first[S->e[k].b + 2]++;
    }
    for (v = 2; v < S->nv + 2; v++)
        S->first[v] += S->first[v - 1];
    for (k = 0; k < S->ne; k++) {
        S->inc[S->first[S->e[k].a + 1]++] = (int32_t)k;
        S->inc[S->first[S->e[k].b + 1]++] = (int32_t)k;
    }
    for (v = 0; v < S->nv; v++) {
        S->stamp[v] = -1;
        S->cmark[v] = -1;
        S->byx[v].x = T->xy[2 * v];
        S->byx[v].v = (int32_t)v;
        if (S->first[v + 1] - S->first[v] == 2 && !outside[v]) {
            size_t k0 = (size_t)S->inc[S->first[v]], k1 = (size_t)S->inc[S->first[v] + 1];
            int32_t u = rs_other(S, k0, (int32_t)v), w = rs_other(S, k1, (int32_t)v);
            S->inner[v] = cvm__cdt_segment_marker(S->in->smark, S->in->nseg, S->e[k0].seg) ==
                              cvm__cdt_segment_marker(S->in->smark, S->in->nseg, S->e[k1].seg) &&
                          rs_turn(rs_pt(S, u), rs_pt(S, (int32_t)v), rs_pt(S, w)) < RS_TURN_DEG;
        }
    }
    cvm__free(S->ctx, outside);
    qsort(S->byx, S->nv, sizeof *S->byx, cmp_xv);
    return CVM_OK;
}

/* Walk the chain that leaves v along edge k into pv/pe, until a vertex that
 * is not inner (or v again, for a closed loop). */
static cvm_status rs_walk(rs_state *S, int32_t v, size_t k)
{
    int32_t cur = v;
    S->np = 0;
    for (;;) {
        int32_t nxt;
        if (cvm__grow(S->ctx, (void **)&S->pv, &S->cap_pv, S->np + 2, sizeof *S->pv) ||
            cvm__grow(S->ctx, (void **)&S->pe, &S->cap_pe, S->np + 1, sizeof *S->pe))
            return CVM_E_NOMEM;
        S->pv[S->np] = cur;
        S->pe[S->np] = (int32_t)k;
        S->np++;
        S->used[k] = 1;
        nxt = rs_other(S, k, cur);
        if (nxt == v || !S->inner[nxt]) {
            S->pv[S->np++] = nxt;
            return CVM_OK;
        }
        k = (size_t)(S->inc[S->first[nxt]] == (int32_t)k ? S->inc[S->first[nxt] + 1]
                                                           : S->inc[S->first[nxt]]);
        cur = nxt;
    }
}

/* Point at arc length s of the chain: *i the edge index (searched from its value). */
static void rs_at(const rs_state *S, double s, size_t *i, double *xy, double *frac)
{
    const double *a, *b;
    double len, f;
    while (*i + 2 < S->np && S->cum[*i + 1] < s)
        (*i)++;
    a = rs_pt(S, S->pv[*i]);
    b = rs_pt(S, S->pv[*i + 1]);
    len = S->cum[*i + 1] - S->cum[*i];
    f = len > 0 ? (s - S->cum[*i]) / len : 0.0;
    f = f < 0 ? 0 : f > 1 ? 1 : f;
    xy[0] = a[0] + f * (b[0] - a[0]);
    xy[1] = a[1] + f * (b[1] - a[1]);
    *frac = f;
}

/* Tabulate the integral of ds / h along the chain (midpoint rule, steps of
 * h/8, as the march does) into tab (pairs s, I); *ns pairs. */
static cvm_status rs_integrate(rs_state *S, size_t *ns)
{
    double total = 0, L = S->cum[S->np - 1], sofar = 0;
    size_t i = 0, n = 0;
    cvm_status s;
    while (sofar < L && total <= 1e7) {
        double p[2], f, h, ds;
        rs_at(S, sofar, &i, p, &f);
        if ((s = cvm__sizing_at(S->sizing, p[0], p[1], &h, S->ctx)))
            return s;
        ds = h / 8 < L - sofar ? h / 8 : L - sofar;
        rs_at(S, sofar + ds / 2, &i, p, &f);
        if ((s = cvm__sizing_at(S->sizing, p[0], p[1], &h, S->ctx)))
            return s;
        total += ds / h;
        sofar += ds;
        if (cvm__grow(S->ctx, (void **)&S->tab, &S->cap_tab, 2 * n + 2, sizeof *S->tab))
            return CVM_E_NOMEM;
        S->tab[2 * n] = sofar;
        S->tab[2 * n + 1] = total;
        n++;
    }
    *ns = n;
    return CVM_OK;
}

/* 1 when p lies inside or on the closed polygon (n corners), by the exact
 * orientation test (winding number). */
static int rs_in_polygon(const double *poly, size_t n, const double *p)
{
    size_t i;
    int wn = 0;
    for (i = 0; i < n; i++) {
        const double *a = poly + 2 * i, *b = poly + 2 * ((i + 1) % n);
        double o = cvm__orient2d(a, b, p);
        if (o == 0 && p[0] >= fmin(a[0], b[0]) && p[0] <= fmax(a[0], b[0]) &&
            p[1] >= fmin(a[1], b[1]) && p[1] <= fmax(a[1], b[1]))
            return 1;
        if (a[1] <= p[1]) {
            if (b[1] > p[1] && o > 0)
                wn++;
        } else if (b[1] <= p[1] && o < 0) {
            wn--;
        }
    }
    return wn != 0;
}

/* Distance from p to the segment a-b. */
static double rs_dist(const double *a, const double *b, const double *p)
{
    double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy, t;
    t = l2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return hypot(a[0] + t * dx - p[0], a[1] + t * dy - p[1]);
}

/* 1 when x lies in the closed wedge at c between the rays to u and to w
 * (an angle below 180 degrees; exact). */
static int rs_in_wedge(const double *c, const double *u, const double *w, const double *x)
{
    double o = cvm__orient2d(c, u, w), a, b;
    if (o == 0)
        return 0;
    a = cvm__orient2d(c, u, x);
    b = cvm__orient2d(c, x, w);
    return o > 0 ? a >= 0 && b >= 0 : a <= 0 && b <= 0;
}

/* Whether the chord q0-q1 of the chain, replacing the arc between arc
 * lengths s0 and s1 (its inner vertices), is safe: the arc turns by at most
 * RS_ARC_TURN_DEG, no other vertex (or hole or region seed) lies in the
 * closed region between the chord and the arc or within RS_CLOSE x its
 * length of the chord, and no other constrained edge at a chain end enters
 * the region there. */
static cvm_status rs_chord_ok(rs_state *S, const double *q0, const double *q1, double s0, double s1,
                              int at_start, int at_end, int *ok)
{
    const cvm__resample_input *in = S->in;
    size_t i, n = 0, lo, hi, k;
    double turn = 0, bb[4], len = hypot(q1[0] - q0[0], q1[1] - q0[1]), pad;
    size_t first_in = 0, last_in = 0;
    *ok = 0;
    if (!(len > 0))
        return CVM_OK;
    S->serial++;
    if (cvm__grow(S->ctx, (void **)&S->poly, &S->cap_poly, 2 * (S->np + 2), sizeof *S->poly))
        return CVM_E_NOMEM;
    S->poly[n * 2] = q0[0];
    S->poly[n * 2 + 1] = q0[1];
    n++;
    for (i = 1; i + 1 < S->np; i++) {
        if (S->cum[i] < s0 || S->cum[i] > s1)
            continue;
        if (!first_in)
            first_in = i;
        last_in = i;
        turn += rs_turn(rs_pt(S, S->pv[i - 1]), rs_pt(S, S->pv[i]), rs_pt(S, S->pv[i + 1]));
        S->stamp[S->pv[i]] = S->serial;
        S->poly[n * 2] = rs_pt(S, S->pv[i])[0];
        S->poly[n * 2 + 1] = rs_pt(S, S->pv[i])[1];
        n++;
    }
    if (turn > RS_ARC_TURN_DEG)
        return CVM_OK;
    S->poly[n * 2] = q1[0];
    S->poly[n * 2 + 1] = q1[1];
    n++;
    if (at_start)
        S->stamp[S->pv[0]] = S->serial;
    if (at_end)
        S->stamp[S->pv[S->np - 1]] = S->serial;
    pad = RS_CLOSE * len;
    bb[0] = bb[2] = q0[0];
    bb[1] = bb[3] = q0[1];
    for (i = 0; i < n; i++) {
        bb[0] = fmin(bb[0], S->poly[2 * i]);
        bb[1] = fmin(bb[1], S->poly[2 * i + 1]);
        bb[2] = fmax(bb[2], S->poly[2 * i]);
        bb[3] = fmax(bb[3], S->poly[2 * i + 1]);
    }
    bb[0] -= pad;
    bb[1] -= pad;
    bb[2] += pad;
    bb[3] += pad;
    /* the vertices with x in [bb0, bb2]: binary search in byx */
    lo = 0;
    hi = S->nv;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (S->byx[mid].x < bb[0])
            lo = mid + 1;
        else
            hi = mid;
    }
    for (k = lo; k < S->nv && S->byx[k].x <= bb[2]; k++) {
        int32_t y = S->byx[k].v;
        const double *p = rs_pt(S, y);
        if (S->stamp[y] == S->serial || p[1] < bb[1] || p[1] > bb[3] || S->T->vtri[y] < 0)
            continue;
        if (rs_in_polygon(S->poly, n, p))
            return CVM_OK;
        /* the chain's own inner vertices go: only the region matters for them */
        if (S->cmark[y] != S->chain_serial && rs_dist(q0, q1, p) < pad)
            return CVM_OK;
    }
    for (k = 0; k < in->nholes; k++)
        if (rs_in_polygon(S->poly, n, in->holes + 2 * k))
            return CVM_OK;
    for (k = 0; k < in->nregions; k++)
        if (rs_in_polygon(S->poly, n, in->regions + 4 * k))
            return CVM_OK;
    /* other constrained edges at a chain end must not point into the region */
    for (i = 0; i < 2 && first_in; i++) {
        int32_t c = i == 0 ? S->pv[0] : S->pv[S->np - 1];
        size_t own = (size_t)S->pe[0], own2 = (size_t)S->pe[S->np - 2];
        const double *u = i == 0 ? q1 : q0;
        const double *w = rs_pt(S, S->pv[i == 0 ? first_in : last_in]);
        if (!(i == 0 ? at_start : at_end))
            continue;
        for (k = S->first[c]; k < S->first[c + 1]; k++) {
            size_t ek = (size_t)S->inc[k];
            if (ek != own && ek != own2 && rs_in_wedge(rs_pt(S, c), u, w, rs_pt(S, rs_other(S, ek, c))))
                return CVM_OK;
        }
    }
    *ok = 1;
    return CVM_OK;
}

/* Append a piece between ends a and b (old vertex ids, or -2 - k for new point k). */
static cvm_status rs_piece(rs_state *S, int32_t a, int32_t b, int32_t seg)
{
    if (cvm__grow(S->ctx, (void **)&S->pc, &S->cap_pc, 3 * S->npc + 3, sizeof *S->pc))
        return CVM_E_NOMEM;
    S->pc[3 * S->npc] = a;
    S->pc[3 * S->npc + 1] = b;
    S->pc[3 * S->npc + 2] = seg;
    S->npc++;
    return CVM_OK;
}

/* A chord over the arc s0..s1 failed: ask to make the inner vertex of the
 * arc that turns most (the first on ties) a corner, so that the next pass
 * re-discretises the chain in two parts. Nothing when the arc has no inner
 * vertex (the chain then keeps its vertices). */
static cvm_status rs_request_split(rs_state *S, double s0, double s1)
{
    size_t i, best = 0;
    double turn = -1;
    for (i = 1; i + 1 < S->np; i++) {
        double t;
        if (S->cum[i] < s0 || S->cum[i] > s1 || !S->inner[S->pv[i]])
            continue;
        t = rs_turn(rs_pt(S, S->pv[i - 1]), rs_pt(S, S->pv[i]), rs_pt(S, S->pv[i + 1]));
        if (t > turn) {
            turn = t;
            best = i;
        }
    }
    if (!best)
        return CVM_OK;
    if (cvm__grow(S->ctx, (void **)&S->split, &S->cap_split, S->nsplit + 1, sizeof *S->split))
        return CVM_E_NOMEM;
    S->split[S->nsplit++] = S->pv[best];
    return CVM_OK;
}

/* Re-discretise the chain in pv/pe (closed: pv[0] == pv[np-1]) when it has
 * inner vertices and every chord is safe; otherwise leave it. */
static cvm_status rs_chain(rs_state *S, int closed)
{
    size_t ns, i, k, e;
    long n;
    double total;
    cvm_status s;
    int ok = 1;
    if (S->np < 3)
        return CVM_OK; /* a single edge: the march handles it */
    if (cvm__grow(S->ctx, (void **)&S->cum, &S->cap_cum, S->np, sizeof *S->cum))
        return CVM_E_NOMEM;
    S->chain_serial++;
    for (i = 1; i + 1 < S->np; i++)
        S->cmark[S->pv[i]] = S->chain_serial;
    S->cum[0] = 0;
    for (i = 1; i < S->np; i++) {
        const double *a = rs_pt(S, S->pv[i - 1]), *b = rs_pt(S, S->pv[i]);
        S->cum[i] = S->cum[i - 1] + hypot(b[0] - a[0], b[1] - a[1]);
    }
    if ((s = rs_integrate(S, &ns)) || ns == 0)
        return s;
    total = S->tab[2 * ns - 1];
    if (total > 1e7)
        return CVM_OK;
    n = (long)floor(total + 0.5);
    if (n < 1)
        n = 1;
    if ((closed || S->pv[0] == S->pv[S->np - 1]) && n < 3)
        return CVM_OK; /* a loop needs 3 pieces to keep an area */
    /* positions: arc lengths of the n - 1 new points, and their coordinates */
    if (cvm__grow(S->ctx, (void **)&S->pos, &S->cap_pos, 3 * (size_t)n + 3, sizeof *S->pos))
        return CVM_E_NOMEM;
    {
        size_t j = 0;
        S->pos[0] = 0;
        for (k = 1; k < (size_t)n; k++) {
            double target = total * (double)k / (double)n, s0, i0, f;
            while (j + 1 < ns && S->tab[2 * j + 1] < target)
                j++;
            s0 = j ? S->tab[2 * j - 2] : 0.0;
            i0 = j ? S->tab[2 * j - 1] : 0.0;
            f = S->tab[2 * j + 1] > i0 ? (target - i0) / (S->tab[2 * j + 1] - i0) : 0.0;
            S->pos[k] = s0 + f * (S->tab[2 * j] - s0);
        }
        S->pos[n] = S->cum[S->np - 1];
    }
    /* coordinates into pos[n+1 ..]: 2 per point k (k = 0..n), chain ends exact */
    {
        double *xy = S->pos + n + 1;
        size_t ei = 0;
        for (k = 0; k <= (size_t)n; k++) {
            double f;
            if (k == 0 || k == (size_t)n) {
                const double *p = rs_pt(S, S->pv[k == 0 ? 0 : S->np - 1]);
                xy[2 * k] = p[0];
                xy[2 * k + 1] = p[1];
                continue;
            }
            rs_at(S, S->pos[k], &ei, xy + 2 * k, &f);
            if ((xy[2 * k] == xy[2 * k - 2] && xy[2 * k + 1] == xy[2 * k - 1]) || !(S->pos[k] > S->pos[k - 1]))
                return CVM_OK;
        }
        if (xy[2 * n] == xy[2 * n - 2] && xy[2 * n + 1] == xy[2 * n - 1])
            return CVM_OK;
        for (k = 0; k < (size_t)n; k++) {
            int ok_k;
            if ((s = rs_chord_ok(S, xy + 2 * k, xy + 2 * k + 2, S->pos[k], S->pos[k + 1], k == 0,
                                 k + 1 == (size_t)n, &ok_k)))
                return s;
            if (!ok_k && (s = rs_request_split(S, S->pos[k], S->pos[k + 1])))
                return s;
            ok &= ok_k;
        }
        if (!ok)
            return CVM_OK;
        /* accepted: new points, pieces, removed vertices and edges */
        ei = 0;
        for (k = 1; k < (size_t)n; k++) {
            double p[2], f;
            size_t q = S->nnew;
            rs_at(S, S->pos[k], &ei, p, &f);
            if (cvm__grow(S->ctx, (void **)&S->nxy, &S->cap_nxy, 2 * q + 2, sizeof *S->nxy) ||
                cvm__grow(S->ctx, (void **)&S->nfrac, &S->cap_nfrac, q + 1, sizeof *S->nfrac) ||
                cvm__grow(S->ctx, (void **)&S->ninfo, &S->cap_ninfo, 3 * q + 3, sizeof *S->ninfo))
                return CVM_E_NOMEM;
            S->nxy[2 * q] = p[0];
            S->nxy[2 * q + 1] = p[1];
            S->nfrac[q] = f;
            S->ninfo[3 * q] = S->e[S->pe[ei]].seg;
            S->ninfo[3 * q + 1] = S->pv[ei];
            S->ninfo[3 * q + 2] = S->pv[ei + 1];
            S->nnew++;
        }
        for (k = 0; k < (size_t)n; k++) {
            int32_t a = k == 0 ? S->pv[0] : -2 - (int32_t)(S->nnew - (size_t)n + k);
            int32_t b = k + 1 == (size_t)n ? S->pv[S->np - 1]
                                           : -2 - (int32_t)(S->nnew - (size_t)n + k + 1);
            size_t mid;
            int32_t seg;
            if (k == 0)
                seg = S->e[S->pe[0]].seg;
            else if (k + 1 == (size_t)n)
                seg = S->e[S->pe[S->np - 2]].seg;
            else {
                double sm = 0.5 * (S->pos[k] + S->pos[k + 1]);
                for (mid = 0; mid + 2 < S->np && S->cum[mid + 1] < sm; mid++)
                    ;
                seg = S->e[S->pe[mid]].seg;
            }
            if ((s = rs_piece(S, a, b, seg)))
                return s;
        }
        for (e = 0; e + 1 < S->np; e++)
            S->replaced[S->pe[e]] = 1;
        for (i = 1; i + 1 < S->np; i++)
            S->removed[S->pv[i]] = 1;
    }
    return CVM_OK;
}

/* One pass over every chain: open chains from each end (a vertex that is not
 * inner) in vertex order, then closed loops of inner vertices anchored at
 * their lowest vertex. */
static cvm_status rs_pass(rs_state *S, size_t *n_chains)
{
    size_t v, k;
    cvm_status s = CVM_OK;
    *n_chains = 0;
    for (v = 0; v < S->nv && !s; v++) {
        if (S->inner[v])
            continue;
        for (k = S->first[v]; k < S->first[v + 1] && !s; k++) {
            size_t ek = (size_t)S->inc[k];
            size_t before = S->npc;
            if (S->used[ek])
                continue;
            if (!(s = rs_walk(S, (int32_t)v, ek)))
                s = rs_chain(S, 0);
            *n_chains += S->npc > before;
        }
    }
    for (v = 0; v < S->nv && !s; v++) {
        size_t before = S->npc;
        if (!S->inner[v] || S->used[S->inc[S->first[v]]])
            continue;
        if (!(s = rs_walk(S, (int32_t)v, (size_t)S->inc[S->first[v]])))
            s = rs_chain(S, 1);
        if (!s && S->npc > before)
            S->removed[v] = 0; /* the anchor stays */
        *n_chains += S->npc > before;
    }
    return s;
}

void cvm__resample_result_free(cvm__resample_result *R, cvm__ctx *ctx)
{
    cvm__tri2_destroy(&R->T);
    cvm__free(ctx, R->newid);
    cvm__free(ctx, R->ninfo);
    cvm__free(ctx, R->nfrac);
    R->newid = R->ninfo = NULL;
    R->nfrac = NULL;
    R->n_chains = R->nkept = R->nnew = 0;
}

cvm_status cvm__resample_boundary(cvm__resample_result *R, const cvm__resample_input *in,
                                  cvm__ctx *ctx)
{
    rs_state S;
    size_t k, pass, n_chains = 0;
    cvm_status s = CVM_OK;
    int fallback = 0;
    memset(R, 0, sizeof *R);
    cvm__tri2_init(&R->T, ctx);
    memset(&S, 0, sizeof S);
    S.in = in;
    S.T = in->T;
    S.ctx = ctx;
    S.sizing = in->sizing;
    S.nv = in->T->nv;
    if ((s = rs_graph(&S)))
        goto done;
    for (pass = 0;; pass++) {
        if ((s = rs_pass(&S, &n_chains)) || S.nsplit == 0 || pass == RS_MAX_PASSES)
            break;
        /* failed chords: their chains are split at the vertex turning most
           under each, and every chain is planned again */
        for (k = 0; k < S.nsplit; k++)
            S.inner[S.split[k]] = 0;
        memset(S.used, 0, S.ne);
        memset(S.removed, 0, S.nv);
        memset(S.replaced, 0, S.ne);
        S.nnew = S.npc = S.nsplit = 0;
    }
    if (!s && S.npc)
        s = cvm__resample_rebuild(&S, R, &fallback);
    if (!s && S.npc && !fallback) {
        R->n_chains = n_chains;
        R->nnew = S.nnew;
        R->ninfo = S.ninfo;
        R->nfrac = S.nfrac;
        S.ninfo = NULL;
        S.nfrac = NULL;
    }
done:
    rs_free(&S);
    if (!R->n_chains) {
        /* nothing to use: keep R empty */
        cvm__resample_result_free(R, ctx);
        cvm__tri2_init(&R->T, ctx);
    }
    return s;
}
