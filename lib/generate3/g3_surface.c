/*
 * g3_surface.c - the planar facets of the surface re-meshed at the 3D size
 * field by the 2D frontal refiner, before the points are generated.
 *
 * Facets: triangles joined across edges of exactly two triangles when the
 * fourth point is coplanar (orient3d exactly 0) and the two triangles carry
 * the same key (the input facet marker). A facet of two or more triangles
 * whose boundary is one simple loop is re-meshed; any other triangle is a
 * facet of its own, kept as given.
 *
 * Shared edges: every facet boundary is made of input edges; each input edge
 * keeps one sorted list of parameters t in (0, 1) along it from its lower to
 * its higher point index, and its points a + t (b - a) are made once and
 * given to both facets, fixed in their 2D refinement. Edges between two
 * re-meshed facets start with ceil(length / size) equal pieces; when the
 * refiner splits a boundary segment anyway (encroachment), the split becomes
 * a parameter of that edge and every facet is meshed again (a few rounds),
 * so both sides always hold the same points. Only edges between two
 * re-meshed facets take points: a facet whose refiner splits an edge of a
 * kept triangle is demoted (its boundary loop triangulated, constrained
 * Delaunay, without new points) and the whole pass starts again; at most one
 * pass per facet. No convergence in G3S_MAX_ROUNDS rounds, or a facet whose
 * 2D triangulation fails on rounding: the surface is kept as given.
 *
 * 2D frame: the facet's plane projected along the axis of the largest normal
 * component (cyclic order of the two others, so orientation is kept when that
 * component is positive); new interior points are lifted back onto the plane
 * of the facet's first triangle (exactly, for axis-aligned planes).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "generate3/g3_surface.h"
#include "geom/geom_internal.h"
#include "delaunay/delaunay_internal.h"
#include "sizing/sizing_internal.h"
#include "refine/refine_internal.h"

#define G3S_MAX_ROUNDS 8

static int edge_cmp(const void *pa, const void *pb)
{
    const g3s_edge *a = pa, *b = pb;
    if (a->lo != b->lo)
        return a->lo < b->lo ? -1 : 1;
    return (a->hi > b->hi) - (a->hi < b->hi);
}

static int split_cmp(const void *pa, const void *pb)
{
    const g3s_split *a = pa, *b = pb;
    if (a->e != b->e)
        return a->e < b->e ? -1 : 1;
    return (a->t > b->t) - (a->t < b->t);
}

static const double *g3s_pt(const g3s_state *S, int32_t i)
{
    return S->s->xyz + 3 * (size_t)i;
}

/* The neighbour of every triangle edge (sorted half-edges). */
static void lift(const g3s_frame *fr, const double *uv, double *x)
{
    x[fr->u] = uv[0];
    x[fr->v] = uv[1];
    if (fr->n[fr->u] == 0 && fr->n[fr->v] == 0)
        x[fr->ax] = fr->a[fr->ax];
    else
        x[fr->ax] = fr->a[fr->ax] - (fr->n[fr->u] * (uv[0] - fr->a[fr->u]) +
                                     fr->n[fr->v] * (uv[1] - fr->a[fr->v])) / fr->n[fr->ax];
}

static double size_cb(void *payload, double x, double y)
{
    const g3s_size_payload *q = payload;
    double uv[2], p[3];
    uv[0] = x;
    uv[1] = y;
    lift(q->fr, uv, p);
    return cvm__g3_size_eval(q->z, p);
}

/* Group the triangles into facets; a facet of 2+ triangles is re-meshed when
 * its boundary is one simple loop, else its triangles become facets of one. */
static cvm_status push_point(g3s_state *S, const double *x)
{
    if (3 * (S->np + 1) > S->cap_xyz &&
        cvm__grow(S->ctx, (void **)&S->xyz, &S->cap_xyz, 3 * (S->np + 1), sizeof *S->xyz))
        return cvm__nomem(S->ctx);
    memcpy(S->xyz + 3 * S->np, x, 3 * sizeof *x);
    S->np++;
    return CVM_OK;
}

static cvm_status push_tri(g3s_state *S, int32_t a, int32_t b, int32_t c, int32_t src)
{
    if ((3 * (S->nt + 1) > S->cap_tri &&
         cvm__grow(S->ctx, (void **)&S->tri, &S->cap_tri, 3 * (S->nt + 1), sizeof *S->tri)) ||
        (S->nt + 1 > S->cap_tsrc &&
         cvm__grow(S->ctx, (void **)&S->tsrc, &S->cap_tsrc, S->nt + 1, sizeof *S->tsrc)))
        return cvm__nomem(S->ctx);
    S->tri[3 * S->nt] = a;
    S->tri[3 * S->nt + 1] = b;
    S->tri[3 * S->nt + 2] = c;
    S->tsrc[S->nt++] = src;
    return CVM_OK;
}

static cvm_status push_pending(g3s_state *S, int32_t e, double t)
{
    if (S->npend + 1 > S->cap_pend &&
        cvm__grow(S->ctx, (void **)&S->pend, &S->cap_pend, S->npend + 1, sizeof *S->pend))
        return cvm__nomem(S->ctx);
    S->pend[S->npend].e = e;
    S->pend[S->npend].t = t;
    S->npend++;
    return CVM_OK;
}

/* Point index of split k of edge e (points of the output: np0 input points,
 * then the splits in edge order). */
static int32_t split_point(const g3s_state *S, size_t np0, int32_t e, size_t k)
{
    return (int32_t)(np0 + S->edge[e].soff + k);
}

/* Mesh facet f: its loop (n directed edges in S->loop) with the splits of
 * its edges, refined when remesh; triangles appended to the output, or the
 * refiner's boundary splits appended to S->pend. */
static cvm_status mesh_facet(g3s_state *S, int32_t f, size_t n, int remesh, size_t np0,
                             cvm__tri2 *T, cvm__cdt_out *co)
{
    const cvm__g3_surface *s = S->s;
    g3s_frame fr;
    g3s_size_payload pay;
    cvm_sizing sz;
    cvm__cdt_input in;
    cvm__cdt_fault fault;
    cvm__refine_params rp;
    cvm__refine_report rr;
    size_t i, k, nb = 0, need = 0, t;
    cvm_status st;
    cvm__g3s_frame(S, S->fseed[f], &fr);
    for (i = 0; i < n; i++) {
        int32_t d = S->loop[i], tt = d / 3, j = d % 3;
        int32_t a = s->tri[3 * tt + (j + 1) % 3], b = s->tri[3 * tt + (j + 2) % 3];
        need += 1 + S->edge[cvm__g3s_find_edge(S, a, b)].ns;
    }
    if (need > S->cap_b) {
        size_t c = need;
        cvm__free(S->ctx, S->bxy);
        cvm__free(S->ctx, S->bid);
        cvm__free(S->ctx, S->bseg);
        cvm__free(S->ctx, S->bseg_e);
        cvm__free(S->ctx, S->bt0);
        cvm__free(S->ctx, S->bt1);
        S->bxy = cvm__malloc(S->ctx, 2 * c * sizeof *S->bxy);
        S->bid = cvm__malloc(S->ctx, c * sizeof *S->bid);
        S->bseg = cvm__malloc(S->ctx, 2 * c * sizeof *S->bseg);
        S->bseg_e = cvm__malloc(S->ctx, c * sizeof *S->bseg_e);
        S->bt0 = cvm__malloc(S->ctx, c * sizeof *S->bt0);
        S->bt1 = cvm__malloc(S->ctx, c * sizeof *S->bt1);
        S->cap_b = 0;
        if (!S->bxy || !S->bid || !S->bseg || !S->bseg_e || !S->bt0 || !S->bt1)
            return cvm__nomem(S->ctx);
        S->cap_b = c;
    }
    for (i = 0; i < n; i++) {
        int32_t d = S->loop[i], tt = d / 3, j = d % 3;
        int32_t a = s->tri[3 * tt + (j + 1) % 3], b = s->tri[3 * tt + (j + 2) % 3];
        int32_t e = cvm__g3s_find_edge(S, a, b);
        const g3s_edge *E = S->edge + e;
        int fwd = a == E->lo;
        double tprev = fwd ? 0 : 1;
        S->bid[nb] = a;
        for (k = 0; k <= E->ns; k++) {
            double tnext = k == E->ns ? (fwd ? 1 : 0) : S->sp[E->soff + (fwd ? k : E->ns - 1 - k)];
            if (k < E->ns)
                S->bid[nb + 1] = split_point(S, np0, e, fwd ? k : E->ns - 1 - k);
            S->bseg_e[nb] = e;
            S->bt0[nb] = tprev;
            S->bt1[nb] = tnext;
            tprev = tnext;
            nb++;
        }
    }
    for (i = 0; i < nb; i++) {
        const double *x = S->xyz + 3 * (size_t)S->bid[i];
        S->bxy[2 * i] = x[fr.u];
        S->bxy[2 * i + 1] = x[fr.v];
        S->bseg[2 * i] = (int32_t)i;
        S->bseg[2 * i + 1] = (int32_t)((i + 1) % nb);
    }
    memset(&in, 0, sizeof in);
    in.xy = S->bxy;
    in.np = nb;
    in.seg = S->bseg;
    in.nseg = nb;
    in.seed = 1;
    in.reject_duplicates = 1;
    memset(&fault, 0, sizeof fault);
    cvm__tri2_clear(T);
    st = cvm__cdt_build(T, &in, co, &fault);
    if (st == CVM_OK && (fault.kind != CVM__CDT_FAULT_NONE || T->nv != nb))
        st = CVM_E_INPUT_DEGENERATE;
    for (i = 0; i < nb && !st; i++)
        if (co->input_map[i] != (int32_t)i)
            st = CVM_E_INPUT_DEGENERATE;
    if (st)
        return st == CVM_E_NOMEM ? st : CVM_E_INPUT_DEGENERATE;
    if (remesh) {
        memset(&sz, 0, sizeof sz);
        pay.z = S->z;
        pay.fr = &fr;
        sz.fn = size_cb;
        sz.fn_payload = &pay;
        memset(&rp, 0, sizeof rp);
        memset(&rr, 0, sizeof rr);
        rp.algo = CVM_ALGO_FRONTAL;
        rp.min_angle_deg = 30;
        rp.march = 0;
        rp.sizing = &sz;
        rp.seg_ends = S->bseg;
        rp.nseg = nb;
        rp.swap = 1;
        rp.smooth_sweeps = CVM__FRONTAL_SMOOTH_SWEEPS;
        rp.relax_sweeps = CVM__FRONTAL_RELAX_SWEEPS;
        rp.restore_delaunay = 1;
        st = cvm__refine(T, &rp, &rr);
        cvm__free(T->ctx, rr.unmet);
        cvm__free(T->ctx, rr.cell_layer);
        if (cvm_status_is_error(st))
            return st;
        st = CVM_OK;
    }
    /* new vertices on a segment: splits for the next round */
    {
        size_t before = S->npend;
        for (t = 0; t < T->nt; t++) {
            int j;
            if (!cvm__tri2_in_domain(T, (int32_t)t))
                continue;
            for (j = 0; j < 3; j++) {
                int32_t sg = cvm__tri2_edge_seg(T, (int32_t)t, j), v;
                int c;
                if (sg < 0 || (size_t)sg >= nb)
                    continue;
                for (c = 1; c <= 2; c++) {
                    const double *p0 = S->bxy + 2 * (size_t)sg, *p1 = S->bxy + 2 * ((size_t)(sg + 1) % nb), *q;
                    double dx, dy, w;
                    v = T->tv[3 * t + (size_t)(j + c) % 3];
                    if ((size_t)v < nb)
                        continue;
                    q = T->xy + 2 * (size_t)v;
                    dx = p1[0] - p0[0];
                    dy = p1[1] - p0[1];
                    w = ((q[0] - p0[0]) * dx + (q[1] - p0[1]) * dy) / (dx * dx + dy * dy);
                    if (!(w > 0.01 && w < 0.99))
                        w = 0.5;
                    if (!S->edge[S->bseg_e[sg]].both) {
                        S->demote = f;
                        return CVM_OK;
                    }
                    if ((st = push_pending(S, S->bseg_e[sg],
                                           S->bt0[sg] + w * (S->bt1[sg] - S->bt0[sg]))))
                        return st;
                }
            }
        }
        if (S->npend > before)
            return CVM_OK;
    }
    /* the triangles, new interior points lifted onto the facet's plane */
    {
        size_t base = S->np;
        for (i = nb; i < T->nv; i++) {
            double x[3];
            lift(&fr, T->xy + 2 * i, x);
            if ((st = push_point(S, x)))
                return st;
        }
        for (t = 0; t < T->nt; t++) {
            const int32_t *tv = T->tv + 3 * t;
            int32_t g[3];
            int c;
            if (!cvm__tri2_in_domain(T, (int32_t)t))
                continue;
            for (c = 0; c < 3; c++)
                g[c] = (size_t)tv[c] < nb ? S->bid[tv[c]] : (int32_t)(base + (size_t)tv[c] - nb);
            if (fr.n[fr.ax] > 0)
                st = push_tri(S, g[0], g[1], g[2], S->fseed[f]);
            else
                st = push_tri(S, g[0], g[2], g[1], S->fseed[f]);
            if (st)
                return st;
        }
    }
    return CVM_OK;
}

/* Split parameters of the edges between two re-meshed facets: equal pieces
 * no longer than the size at the edge's ends and midpoint. */
static cvm_status initial_splits(g3s_state *S)
{
    size_t e;
    for (e = 0; e < S->ne; e++) {
        const double *a = g3s_pt(S, S->edge[e].lo), *b = g3s_pt(S, S->edge[e].hi);
        double m[3], len, h;
        size_t k, pieces;
        if (!S->edge[e].ns) /* ns carries the "both sides re-meshed" flag here */
            continue;
        S->edge[e].ns = 0;
        m[0] = 0.5 * (a[0] + b[0]);
        m[1] = 0.5 * (a[1] + b[1]);
        m[2] = 0.5 * (a[2] + b[2]);
        len = sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) +
                   (b[2] - a[2]) * (b[2] - a[2]));
        h = cvm__g3_size_eval(S->z, a);
        if (cvm__g3_size_eval(S->z, b) < h)
            h = cvm__g3_size_eval(S->z, b);
        if (cvm__g3_size_eval(S->z, m) < h)
            h = cvm__g3_size_eval(S->z, m);
        if (!(h > 0) || !(len / h < 1e6))
            continue;
        pieces = (size_t)ceil(len / h * (1 - 1e-12));
        for (k = 1; k < pieces; k++) {
            cvm_status st = push_pending(S, (int32_t)e, (double)k / (double)pieces);
            if (st)
                return st;
        }
    }
    return CVM_OK;
}

/* Merge the pending splits into the edges' lists (sorted, duplicates dropped). */
static cvm_status merge_pending(g3s_state *S)
{
    g3s_split *all;
    size_t e, i, n = S->nsp + S->npend, m = 0;
    if (!(all = cvm__malloc(S->ctx, (n ? n : 1) * sizeof *all)))
        return cvm__nomem(S->ctx);
    for (e = 0; e < S->ne; e++)
        for (i = 0; i < S->edge[e].ns; i++) {
            all[m].e = (int32_t)e;
            all[m++].t = S->sp[S->edge[e].soff + i];
        }
    if (S->npend)
        memcpy(all + m, S->pend, S->npend * sizeof *all);
    m += S->npend;
    S->npend = 0;
    qsort(all, m, sizeof *all, split_cmp);
    cvm__free(S->ctx, S->sp);
    if (!(S->sp = cvm__malloc(S->ctx, (m ? m : 1) * sizeof *S->sp))) {
        cvm__free(S->ctx, all);
        return cvm__nomem(S->ctx);
    }
    S->nsp = 0;
    for (e = 0; e < S->ne; e++)
        S->edge[e].ns = 0;
    for (i = 0; i < m; i++) {
        g3s_edge *E = S->edge + all[i].e;
        if (E->ns && S->sp[S->nsp - 1] == all[i].t)
            continue;
        if (!E->ns)
            E->soff = S->nsp;
        S->sp[S->nsp++] = all[i].t;
        E->ns++;
    }
    cvm__free(S->ctx, all);
    return CVM_OK;
}

static void state_free(g3s_state *S)
{
    cvm__ctx *c = S->ctx;
    cvm__free(c, S->nbr);
    cvm__free(c, S->fac);
    cvm__free(c, S->fseed);
    cvm__free(c, S->fcount);
    cvm__free(c, S->fremesh);
    cvm__free(c, S->edge);
    cvm__free(c, S->sp);
    cvm__free(c, S->pend);
    cvm__free(c, S->loop);
    cvm__free(c, S->bxy);
    cvm__free(c, S->bid);
    cvm__free(c, S->bseg);
    cvm__free(c, S->bseg_e);
    cvm__free(c, S->bt0);
    cvm__free(c, S->bt1);
    cvm__free(c, S->xyz);
    cvm__free(c, S->tri);
    cvm__free(c, S->tsrc);
}

void cvm__g3_remeshed_free(cvm__ctx *ctx, cvm__g3_remeshed *r)
{
    cvm__free(ctx, r->xyz);
    cvm__free(ctx, r->tri);
    cvm__free(ctx, r->tsrc);
    memset(r, 0, sizeof *r);
}

/* Facet membership lists: triangles sorted by facet (counting sort). */
cvm_status cvm__g3_remesh_planar(cvm__ctx *ctx, const cvm__g3_surface *s, const int32_t *key,
                                 const cvm__g3_params *p, cvm__g3_remeshed *out)
{
    g3s_state S;
    cvm__g3_size *z = NULL;
    int32_t *fstart = NULL, *fitems = NULL;
    cvm__tri2 T;
    cvm__cdt_out co;
    size_t i, t, f, nt = s->nt, round;
    int changed = 1;
    cvm_status st;
    memset(out, 0, sizeof *out);
    memset(&S, 0, sizeof S);
    memset(&co, 0, sizeof co);
    S.ctx = ctx;
    S.s = s;
    cvm__tri2_init(&T, ctx);
    out->tris_before = nt;
    if (nt == 0)
        return CVM_OK;
    if ((st = cvm__g3_size_create(&z, ctx, s, p)))
        return st;
    S.z = z;
    S.nbr = cvm__malloc(ctx, 3 * nt * sizeof *S.nbr);
    S.fac = cvm__malloc(ctx, nt * sizeof *S.fac);
    S.fseed = cvm__malloc(ctx, nt * sizeof *S.fseed);
    S.fcount = cvm__malloc(ctx, nt * sizeof *S.fcount);
    S.fremesh = cvm__calloc(ctx, nt, 1);
    S.loop = cvm__malloc(ctx, 3 * nt * sizeof *S.loop);
    S.edge = cvm__malloc(ctx, 3 * nt * sizeof *S.edge);
    if (!S.nbr || !S.fac || !S.fseed || !S.fcount || !S.fremesh || !S.loop || !S.edge) {
        st = cvm__nomem(ctx);
        goto done;
    }
    if ((st = cvm__g3s_neighbours(&S)) || (st = cvm__g3s_group(&S, key)))
        goto done;
    if ((st = cvm__g3s_members(&S, &fstart, &fitems)))
        goto done;
    /* which facets are re-meshed; the others fall apart into single triangles */
    for (f = 0; f < S.nf; f++) {
        size_t n;
        if (S.fcount[f] < 2)
            continue;
        if (cvm__g3s_loop(&S, (int32_t)f, fitems + fstart[f], (size_t)(fstart[f + 1] - fstart[f]), &n))
            S.fremesh[f] = 1;
    }
    {
        /* renumber: a re-meshed facet stays one facet, every other triangle becomes its own */
        int32_t *nfac = cvm__malloc(ctx, nt * sizeof *nfac);
        unsigned char *nrem = cvm__calloc(ctx, nt, 1);
        int32_t *nseed = cvm__malloc(ctx, nt * sizeof *nseed);
        size_t nf = 0;
        if (!nfac || !nrem || !nseed) {
            cvm__free(ctx, nfac);
            cvm__free(ctx, nrem);
            cvm__free(ctx, nseed);
            st = cvm__nomem(ctx);
            goto done;
        }
        for (f = 0; f < S.nf; f++) {
            int32_t k;
            if (S.fremesh[f]) {
                for (k = fstart[f]; k < fstart[f + 1]; k++)
                    nfac[fitems[k]] = (int32_t)nf;
                nrem[nf] = 1;
                nseed[nf++] = S.fseed[f];
            } else {
                for (k = fstart[f]; k < fstart[f + 1]; k++) {
                    nfac[fitems[k]] = (int32_t)nf;
                    nseed[nf++] = fitems[k];
                }
            }
        }
        cvm__free(ctx, S.fac);
        cvm__free(ctx, S.fremesh);
        cvm__free(ctx, S.fseed);
        S.fac = nfac;
        S.fremesh = nrem;
        S.fseed = nseed;
        S.nf = nf;
        cvm__free(ctx, fstart);
        cvm__free(ctx, fitems);
        fstart = fitems = NULL;
        if ((st = cvm__g3s_members(&S, &fstart, &fitems)))
            goto done;
    }
    for (f = 0; f < S.nf; f++)
        out->facets_remeshed += S.fremesh[f];
    if (!out->facets_remeshed)
        goto done; /* nothing planar to re-mesh: the surface stays as given */
again:
    /* the boundary edges of every facet; ns = 1 marks an edge between two re-meshed facets */
    S.ne = 0;
    S.nsp = 0;
    S.npend = 0;
    S.demote = -1;
    changed = 1;
    for (t = 0; t < nt; t++) {
        int j;
        for (j = 0; j < 3; j++) {
            int32_t w = S.nbr[3 * t + (size_t)j];
            int32_t a = s->tri[3 * t + (size_t)(j + 1) % 3], b = s->tri[3 * t + (size_t)(j + 2) % 3];
            if (w >= 0 && S.fac[w] == S.fac[t])
                continue;
            if (w >= 0 && a > b)
                continue; /* the neighbour lists it */
            S.edge[S.ne].lo = a < b ? a : b;
            S.edge[S.ne].hi = a < b ? b : a;
            S.edge[S.ne].soff = 0;
            S.edge[S.ne].ns = w >= 0 && S.fremesh[S.fac[t]] && S.fremesh[S.fac[w]];
            S.edge[S.ne].both = (int)S.edge[S.ne].ns;
            S.ne++;
        }
    }
    if (S.ne > 1)
        qsort(S.edge, S.ne, sizeof *S.edge, edge_cmp);
    {
        /* an edge of 3+ triangles is listed by each: keep one, split by no one */
        size_t m = 0;
        for (i = 0; i < S.ne; i++) {
            if (m && !edge_cmp(&S.edge[m - 1], &S.edge[i])) {
                S.edge[m - 1].ns = 0;
                S.edge[m - 1].both = 0;
                continue;
            }
            S.edge[m++] = S.edge[i];
        }
        S.ne = m;
    }
    if ((st = initial_splits(&S)) || (st = merge_pending(&S)))
        goto done;
    for (round = 0; changed && round < G3S_MAX_ROUNDS; round++) {
        size_t e, k;
        changed = 0;
        S.np = 0;
        S.nt = 0;
        for (i = 0; i < s->np && !st; i++)
            st = push_point(&S, s->xyz + 3 * i);
        for (e = 0; e < S.ne && !st; e++) {
            const double *a = g3s_pt(&S, S.edge[e].lo), *b = g3s_pt(&S, S.edge[e].hi);
            for (k = 0; k < S.edge[e].ns && !st; k++) {
                double tt = S.sp[S.edge[e].soff + k], x[3];
                int c;
                for (c = 0; c < 3; c++)
                    x[c] = a[c] == b[c] ? a[c] : a[c] + tt * (b[c] - a[c]);
                st = push_point(&S, x);
            }
        }
        for (f = 0; f < S.nf && !st; f++) {
            size_t n;
            if (!cvm__g3s_loop(&S, (int32_t)f, fitems + fstart[f], (size_t)(fstart[f + 1] - fstart[f]), &n)) {
                st = CVM_E_INPUT_DEGENERATE;
                break;
            }
            st = mesh_facet(&S, (int32_t)f, n, S.fremesh[f], s->np, &T, &co);
            if (!st && S.demote >= 0)
                break;
        }
        if (st)
            break;
        if (S.demote >= 0) {
            S.fremesh[S.demote] = 0;
            goto again;
        }
        if (S.npend) {
            changed = 1;
            if ((st = merge_pending(&S)))
                break;
        }
    }
    if (!st && changed)
        st = CVM_E_INPUT_DEGENERATE;
    out->rounds = round;
    out->facets_remeshed = 0;
    for (f = 0; f < S.nf; f++)
        out->facets_remeshed += S.fremesh[f];
    if (st == CVM_E_INPUT_DEGENERATE) {
        /* a facet the 2D path cannot take (rounding, or no convergence): keep the surface as given */
        out->facets_remeshed = 0;
        st = CVM_OK;
        goto done;
    }
    if (st || !out->facets_remeshed)
        goto done; /* an error, or every facet demoted: the surface stays as given */
    /* compact: drop input points no triangle uses any more */
    {
        int32_t *map = cvm__malloc(ctx, (S.np ? S.np : 1) * sizeof *map);
        size_t m = 0;
        if (!map) {
            st = cvm__nomem(ctx);
            goto done;
        }
        for (i = 0; i < S.np; i++)
            map[i] = -1;
        for (i = 0; i < 3 * S.nt; i++)
            map[S.tri[i]] = 0;
        for (i = 0; i < S.np; i++)
            if (map[i] == 0) {
                memmove(S.xyz + 3 * m, S.xyz + 3 * i, 3 * sizeof *S.xyz);
                map[i] = (int32_t)m++;
            }
        for (i = 0; i < 3 * S.nt; i++)
            S.tri[i] = map[S.tri[i]];
        cvm__free(ctx, map);
        S.np = m;
    }
    out->xyz = S.xyz;
    out->np = S.np;
    out->tri = S.tri;
    out->tsrc = S.tsrc;
    out->nt = S.nt;
    S.xyz = NULL;
    S.tri = S.tsrc = NULL;
done:
    out->tris_after = out->tri ? out->nt : nt;
    cvm__free(ctx, co.input_map);
    cvm__free(ctx, co.vmark);
    cvm__free(ctx, co.vattr);
    cvm__tri2_destroy(&T);
    cvm__free(ctx, fstart);
    cvm__free(ctx, fitems);
    state_free(&S);
    cvm__g3_size_free(z);
    if (st) {
        cvm__g3_remeshed_free(ctx, out);
        return st;
    }
    return CVM_OK;
}
