/*
 * d3_run.c - the sweeps of the 3D power-dual optimiser (dual3.h): the
 * vertex stars, the sweep order, the compass search per vertex (and the
 * cuckoo search's use, d3_cuckoo.c).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "dual3/d3_internal.h"
#include "geom/geom_internal.h"
#include "geom/measure.h"
#include "geom/measure3.h"

typedef struct d3_rank {
    double score;
    int32_t v;
} d3_rank;

static int rank_cmp(const void *pa, const void *pb)
{
    const d3_rank *a = pa, *b = pb;
    if (a->score != b->score)
        return a->score > b->score ? -1 : 1;
    return (a->v > b->v) - (a->v < b->v);
}

static void work_free(cvm__ctx *ctx, cvm__d3_work *K)
{
    cvm__d3_topo_free(ctx, K);
    cvm__free(ctx, K->fixpos);
    cvm__free(ctx, K->lv);
    cvm__free(ctx, K->stuck);
    cvm__free(ctx, K->slide);
    cvm__d3_slide_free(ctx, K);
    memset(K, 0, sizeof *K);
}

static cvm_status work_init(cvm__ctx *ctx, cvm__d3_work *K, const cvm__d3_mesh *M)
{
    size_t t, i, nv = M->nv;
    double *cnt;
    cvm_status s;
    if ((s = cvm__d3_topo_init(ctx, K, M)))
        return s;
    K->fixpos = cvm__calloc(ctx, nv + 1, 1);
    K->lv = cvm__calloc(ctx, 2 * nv + 1, sizeof *K->lv);
    K->stuck = cvm__calloc(ctx, nv + 1, 1);
    K->slide = cvm__malloc(ctx, nv + 1);
    if (!K->fixpos || !K->lv || !K->stuck || !K->slide) {
        work_free(ctx, K);
        return cvm__nomem(ctx);
    }
    cnt = K->lv + nv;
    memset(K->slide, 7, nv + 1);
    for (t = 0; t < M->ntet; t++) {
        int a, b;
        for (a = 0; a < 4; a++) {
            int32_t q = M->tet[4 * t + (size_t)a];
            if (M->nbr[4 * t + (size_t)a] < 0)
                K->bnd[t] = 1;
            if (M->cface[4 * t + (size_t)a]) {
                const double *X[3];
                int j = 0, ax, same = 0;
                for (b = 0; b < 4; b++)
                    if (b != a)
                        X[j++] = M->xyz + 3 * (size_t)M->tet[4 * t + (size_t)b];
                for (ax = 0; ax < 3; ax++) /* the face lies in the plane x_ax = const */
                    if (X[0][ax] == X[1][ax] && X[0][ax] == X[2][ax])
                        same |= 1 << ax;
                for (b = 0; b < 4; b++)
                    if (b != a) {
                        K->fixpos[M->tet[4 * t + (size_t)b]] = 1;
                        K->slide[M->tet[4 * t + (size_t)b]] &= (uint8_t)same;
                    }
            }
            for (b = 0; b < 4; b++)
                if (b != a) {
                    int32_t r = M->tet[4 * t + (size_t)b];
                    K->lv[q] += sqrt(cvm__dist2_3(M->xyz + 3 * (size_t)q, M->xyz + 3 * (size_t)r));
                    cnt[q] += 1;
                }
        }
        K->out[t] = (uint8_t)cvm__d3_outside(M, t);
    }
    for (i = 0; i < nv; i++) {
        K->lv[i] = cnt[i] > 0 ? K->lv[i] / cnt[i] : 0;
        /* every constrained face at i in one plane x_a = const: i may move in the other two
         * coordinates (exactly in the plane); else (an edge, a corner, a curved surface) not */
        K->slide[i] = K->p->slide && (K->slide[i] == 1 || K->slide[i] == 2 || K->slide[i] == 4)
                          ? (uint8_t)(~K->slide[i] & 7) : 0;
    }
    if (K->p->slide == 2 && cvm__d3_slide_init(ctx, K, M) != CVM_OK) {
        work_free(ctx, K);
        return CVM_E_NOMEM;
    }
    return CVM_OK;
}

/* Penalty (L_k-weighted), outside counts and largest dihedral cosine of the
 * tetrahedra list[0..n) with v at (x, wv); full 0: the penalty only. */
typedef struct d3_region {
    double pen, cmax;
    size_t nout, bout;
} d3_region;

static void d3_region_eval(const cvm__d3_work *K, const int32_t *list, size_t n, int32_t v,
                           const double *x, double wv, int full, d3_region *R)
{
    size_t i;
    if (!full)
        memset(R, 0, sizeof *R);
    R->cmax = -1;
    for (i = 0; i < n; i++) {
        size_t t = (size_t)list[i];
        const double *P[4];
        double W[4], f, c;
        cvm__d3_corners(K->M, t, v, x, wv, P, W);
        if (!full) {
            f = cvm__d3_tet_penalty(P, W, K->p->margin, NULL);
            R->pen += K->bnd[t] ? 2 * f : f;
            continue;
        }
        c = cvm__d3_tet_max_cos(K->M, t, v, x);
        R->cmax = c > R->cmax ? c : R->cmax;
        if (cvm__tet_centre_inside(P[0], P[1], P[2], P[3], W) < 0) {
            R->nout++;
            R->bout += K->bnd[t];
        }
    }
}

static int d3_tet_has(const int32_t *c, int32_t v)
{
    return c[0] == v || c[1] == v || c[2] == v || c[3] == v;
}

/* Clear the stuck flag of the corners of t and of the vertices across its faces. */
static void d3_unstick(cvm__d3_work *K, size_t t)
{
    int k;
    for (k = 0; k < 4; k++) {
        int32_t nb = K->nbr[4 * t + (size_t)k];
        K->stuck[K->tet[4 * t + (size_t)k]] = 0;
        if (nb >= 0)
            K->stuck[K->tet[nb]] = 0;
    }
}

/* Move v from (x0, w0) to cand (its star in K->star) and repair the faces that are
 * no longer locally regular by flips. Kept when the repair succeeds and, over the
 * tetrahedra the move and the flips replaced against those that replace them, the
 * penalty drops, the outside counts do not grow and no dihedral angle falls below
 * min(floor, the smallest before); else everything is undone. 1 when kept (v's new
 * star in K->star). */
static int d3_flip_move(cvm__d3_work *K, int32_t v, const double *cand, double cfloor)
{
    cvm__d3_mesh *M = &K->W;
    double x0[3], w0 = M->w[v];
    size_t ntet0, i, nold, nnew;
    int32_t *oldr = K->queue, *newr; /* the queue is free again once the repair is done */
    d3_region Ro, Rn;
    int ok;
    memcpy(x0, M->xyz + 3 * (size_t)v, sizeof x0);
    if (K->ntet + 4 * CVM__D3_MAX_FLIPS > K->cap) {
        /* compacting renumbers the tetrahedra in order: v's star follows */
        cvm__d3_compact(K);
        for (i = 0; i < K->nstar; i++)
            K->star[i] = K->remap[K->star[i]];
        if (K->ntet + 4 * CVM__D3_MAX_FLIPS > K->cap)
            return 0;
    }
    ntet0 = K->ntet;
    memcpy(K->star0, K->star, K->nstar * sizeof *K->star);
    K->nstar0 = K->nstar;
    K->logging = 1;
    K->nlog = 0;
    memcpy(M->xyz + 3 * (size_t)v, cand, 3 * sizeof *cand);
    M->w[v] = cand[3];
    ok = cvm__d3_restore(K, v, x0, w0, ntet0);
    if (ok) {
        /* old side: the star before and every older tetrahedron killed; new side: the
           star now and every appended tetrahedron alive outside it */
        nold = 0;
        for (i = 0; i < K->nstar0; i++)
            oldr[nold++] = K->star0[i];
        for (i = 0; i < K->nlog; i++)
            if (K->log[i].kind == 1 && (size_t)K->log[i].idx < ntet0 &&
                !d3_tet_has(K->tet + 4 * (size_t)K->log[i].idx, v))
                oldr[nold++] = K->log[i].idx;
        newr = oldr + nold;
        nnew = 0;
        for (i = 0; i < K->nstar; i++)
            newr[nnew++] = K->star[i];
        for (i = ntet0; i < K->ntet; i++)
            if (!K->dead[i] && !d3_tet_has(K->tet + 4 * i, v))
                newr[nnew++] = (int32_t)i;
        /* the penalty first: most repaired trials end there, before the exact counts */
        d3_region_eval(K, oldr, nold, v, x0, w0, 0, &Ro);
        d3_region_eval(K, newr, nnew, v, cand, cand[3], 0, &Rn);
        ok = Rn.pen < Ro.pen;
        if (ok) {
            d3_region_eval(K, oldr, nold, v, x0, w0, 1, &Ro);
            d3_region_eval(K, newr, nnew, v, cand, cand[3], 1, &Rn);
            cfloor = Ro.cmax > cfloor ? Ro.cmax : cfloor;
            ok = Rn.nout <= Ro.nout && Rn.bout <= Ro.bout && Rn.cmax <= cfloor;
        }
    }
    if (!ok) {
        cvm__d3_undo_all(K, ntet0);
        memcpy(M->xyz + 3 * (size_t)v, x0, sizeof x0);
        M->w[v] = w0;
        memcpy(K->star, K->star0, K->nstar0 * sizeof *K->star);
        K->nstar = K->nstar0;
        K->logging = 0;
        return 0;
    }
    for (i = 0; i < K->nlog; i++)
        if (K->log[i].kind == 1) {
            size_t t = (size_t)K->log[i].idx;
            if (t < ntet0)
                K->nout -= K->out[t];
            K->out[t] = 0;
        }
    for (i = 0; i < nnew; i++) {
        size_t t = (size_t)newr[i];
        if (t < ntet0)
            K->nout -= K->out[t];
        K->out[t] = (uint8_t)cvm__d3_outside(M, t);
        K->nout += K->out[t];
        d3_unstick(K, t);
    }
    K->flips += K->mflips;
    K->logging = 0;
    K->nlog = 0;
    return 1;
}

/* The state of one vertex's search: its current point, the penalty there, the
 * dihedral floor (cosines: larger is worse) and the speculative repairs left. */
typedef struct d3_search {
    double cur[4], best, cfloor, cmin;
    int spec;
} d3_search;

/* Try v at cand, whose fixed-star penalty is f: kept when the exact checks pass on
 * the fixed star, or (with flips) on the star the repair makes. 1 when kept (S
 * then describes cand). */
static int d3_try(cvm__d3_work *K, int32_t v, const double *cand, double f, int posmove,
                  d3_search *S)
{
    int st = -1;
    if (f < S->best && (!posmove || cvm__d3_star_max_cos(K, v, cand) <= S->cfloor))
        st = cvm__d3_star_check(K, v, cand, cand[3], 1);
    else if (K->p->flips && S->spec++ < CVM__D3_SPECULATIVE &&
             cvm__d3_star_check(K, v, cand, cand[3], 0) == 1)
        st = 1; /* the fixed star's penalty and angles say nothing about the flipped
                   one: d3_flip_move judges it */
    if (st == 0) { /* v itself moves at the end */
        memcpy(S->cur, cand, sizeof S->cur);
        S->best = f;
        return 1;
    }
    if (st == 1 && K->p->flips && d3_flip_move(K, v, cand, S->cmin)) {
        /* a new star: its penalty and smallest angle are the new reference */
        double cmax0;
        memcpy(S->cur, cand, sizeof S->cur);
        S->best = cvm__d3_star_penalty(K, v, S->cur, S->cur[3], HUGE_VAL);
        cmax0 = cvm__d3_star_max_cos(K, v, S->cur);
        S->cfloor = cmax0 > S->cmin ? cmax0 : S->cmin;
        return 1;
    }
    return 0;
}

/* Compass search over the directions dirs[0..nd) (2a, 2a + 1: +-axis a; 6, 7: +-w;
 * 8 + 2a, 9 + 2a: +-tangent a of a vertex sliding on its ring, then put on the ring)
 * from steps 0.08 l_v and 0.16 l_v^2, halved when no direction helps. 1 when v moved. */
static int d3_compass(cvm__d3_work *K, int32_t v, const int *dirs, int nd, d3_search *S)
{
    double cand[4], hs = 0.08 * K->lv[v], hw = 0.16 * K->lv[v] * K->lv[v];
    int evals = 0, first = 0, moved = 0;
    while (evals < K->budget && hs > 1e-3 * K->lv[v]) {
        int improved = 0, k;
        for (k = 0; k < nd && evals < K->budget; k++) {
            int dir = dirs[(first + k) % nd];
            double f;
            memcpy(cand, S->cur, sizeof cand);
            if (dir >= 8) {
                const double *t = K->tan + 6 * (size_t)v + 3 * (size_t)((dir - 8) >> 1);
                double h = (dir & 1) ? -hs : hs;
                cand[0] += h * t[0], cand[1] += h * t[1], cand[2] += h * t[2];
                cvm__d3_slide_project(K, v, cand);
            } else if (dir >= 6) {
                cand[3] += (dir & 1) ? -hw : hw;
            } else {
                cand[dir >> 1] += (dir & 1) ? -hs : hs;
            }
            f = cvm__d3_star_penalty(K, v, cand, cand[3], S->best);
            evals++;
            if (!d3_try(K, v, cand, f, dir < 6 || dir >= 8, S))
                continue;
            first = (first + k) % nd;
            improved = moved = 1;
            break;
        }
        if (!improved)
            hs *= 0.5, hw *= 0.5;
    }
    return moved;
}

/* Cuckoo search from S->cur, then its best nests (better than the current point)
 * tried in order until one is kept. 1 when v moved. */
static int d3_cuckoo_move(cvm__d3_work *K, int32_t v, d3_search *S)
{
    cvm__d3_nest ns[CVM__D3_NESTS];
    int order[CVM__D3_NESTS], n, i, tried = 0;
    uint64_t key = K->p->seed ^ (0x9e3779b97f4a7c15ULL * (uint64_t)(K->sweep + 1)) ^
                   (0xbf58476d1ce4e5b9ULL * (uint64_t)((uint32_t)v + 1));
    n = cvm__d3_cuckoo(K, v, S->cur, S->cfloor, K->p->cuckoo_budget, key, ns, order);
    for (i = 0; i < n && tried < 8; i++) {
        if (!(ns[i].f < S->best))
            break;
        tried++;
        if (d3_try(K, v, ns[i].x, ns[i].f, 1, S))
            return 1;
    }
    return 0;
}

/* The search for v over (x, y, z, w): the coordinates its position may change in
 * (all for an interior vertex, the two in-plane ones for one inside an
 * axis-aligned planar facet with slide on, none otherwise) and w, by the solver
 * of K->p; v ends at the best valid point found. 1 when v moved. */
static int solve_vertex(cvm__d3_work *K, int32_t v)
{
    cvm__d3_mesh *M = &K->W;
    double *x0 = M->xyz + 3 * (size_t)v, cmax0;
    int nd = 0, moved = 0, a, dirs[12];
    d3_search S;
    if (K->lv[v] <= 0 || K->stuck[v] || cvm__d3_gather_star(K, v))
        return 0;
    for (a = 0; a < 3; a++)
        if (!K->fixpos[v] || (K->slide[v] >> a & 1))
            dirs[nd++] = 2 * a, dirs[nd++] = 2 * a + 1;
    if (K->curved && K->curved[v])
        dirs[nd++] = 8, dirs[nd++] = 9, dirs[nd++] = 10, dirs[nd++] = 11;
    dirs[nd++] = 6, dirs[nd++] = 7;
    S.cur[0] = x0[0], S.cur[1] = x0[1], S.cur[2] = x0[2], S.cur[3] = M->w[v];
    S.best = cvm__d3_star_penalty(K, v, S.cur, S.cur[3], HUGE_VAL);
    if (S.best == HUGE_VAL)
        return 0;
    /* no angle below min(the floor, the smallest now): cosines, larger is worse */
    cmax0 = cvm__d3_star_max_cos(K, v, S.cur);
    S.cmin = cos(K->p->min_dihedral_deg * (CVM__PI / 180));
    S.cfloor = cmax0 > S.cmin ? cmax0 : S.cmin;
    S.spec = 0;
    if (K->p->solver != 2)
        moved = d3_compass(K, v, dirs, nd, &S);
    if (K->p->solver >= 2 && !moved)
        moved = d3_cuckoo_move(K, v, &S);
    if (moved) {
        size_t s;
        x0[0] = S.cur[0], x0[1] = S.cur[1], x0[2] = S.cur[2];
        M->w[v] = S.cur[3];
        for (s = 0; s < K->nstar; s++) {
            int32_t t = K->star[s];
            K->nout -= K->out[t];
            K->out[t] = (uint8_t)cvm__d3_outside(M, (size_t)t);
            K->nout += K->out[t];
            /* these vertices see a new star, and so do those across its faces (whose
               link faces these are) */
            d3_unstick(K, (size_t)t);
        }
    } else {
        K->stuck[v] = 1; /* the same search would fail again until a neighbour moves */
    }
    return moved;
}

static size_t count_out(const cvm__d3_work *K, size_t *bout, size_t *nbnd)
{
    size_t t, n = 0;
    *bout = *nbnd = 0;
    for (t = 0; t < K->ntet; t++) {
        if (K->dead[t])
            continue;
        n += K->out[t];
        *bout += K->out[t] && K->bnd[t];
        *nbnd += K->bnd[t];
    }
    return n;
}

/* The vertices of the non-compliant tetrahedra, worst score first, bins shuffled. */
static size_t sweep_order(const cvm__d3_work *K, d3_rank *rk, double *vs, uint64_t seed,
                          size_t sweep)
{
    const cvm__d3_mesh *M = K->M;
    size_t t, i, n = 0, nbin, b;
    cvm__rng rng;
    for (i = 0; i < M->nv; i++)
        vs[i] = 0;
    for (t = 0; t < M->ntet; t++) {
        const double *P[4];
        double W[4], d = 0, F;
        int k;
        if (!K->out[t])
            continue;
        for (k = 0; k < 4; k++) {
            int32_t q = M->tet[4 * t + (size_t)k];
            P[k] = M->xyz + 3 * (size_t)q;
            W[k] = M->w[q];
        }
        cvm__d3_tet_penalty(P, W, K->p->margin, &d);
        F = (K->bnd[t] ? 2.0 : 1.0) * (d > 0 ? d : 0) + 1e-300;
        for (k = 0; k < 4; k++) {
            int32_t q = M->tet[4 * t + (size_t)k];
            vs[q] = F > vs[q] ? F : vs[q];
        }
    }
    for (i = 0; i < M->nv; i++)
        if (vs[i] > 0) {
            rk[n].score = vs[i];
            rk[n].v = (int32_t)i;
            n++;
        }
    qsort(rk, n, sizeof *rk, rank_cmp);
    nbin = n / 25 + 1 < 20 ? n / 25 + 1 : 20;
    cvm__rng_seed(&rng, seed ^ (0x9e3779b97f4a7c15ULL * (uint64_t)(sweep + 1)));
    for (b = 0; b < nbin; b++) {
        size_t lo = n * b / nbin, hi = n * (b + 1) / nbin;
        for (i = hi; i > lo + 1; i--) {
            size_t j = lo + (size_t)cvm__rng_below(&rng, (uint64_t)(i - lo));
            d3_rank tmp = rk[i - 1];
            rk[i - 1] = rk[j];
            rk[j] = tmp;
        }
    }
    return n;
}

cvm_status cvm__d3_optimise(cvm__ctx *ctx, cvm__d3_mesh *M, const cvm__d3_params *p,
                            cvm__d3_report *r, cvm__d3_topo *topo)
{
    cvm__d3_work K;
    d3_rank *rk;
    double *vs;
    size_t sweep, i, low, stall = 0;
    cvm_status s = CVM_OK;
    memset(r, 0, sizeof *r);
    memset(&K, 0, sizeof K);
    r->ntet = M->ntet;
    K.p = p;
    K.budget = p->budget;
    if ((s = work_init(ctx, &K, M)))
        return s;
    rk = cvm__malloc(ctx, (M->nv + 1) * sizeof *rk);
    vs = cvm__malloc(ctx, (M->nv + 1) * sizeof *vs);
    if (!rk || !vs) {
        cvm__free(ctx, rk);
        cvm__free(ctx, vs);
        work_free(ctx, &K);
        return cvm__nomem(ctx);
    }
    /* nothing is allocated from here on: a stop leaves the mesh as it is */
    r->out_before = K.nout = count_out(&K, &r->bout_before, &r->nbnd);
    if (p->flips && p->max_sweeps > 0) {
        /* a constrained Delaunay mesh can start with faces that are not locally regular */
        r->flips_start = cvm__d3_regularise(&K, cos(p->min_dihedral_deg * (CVM__PI / 180)));
        K.flips = r->flips_start;
        if (r->flips_start) {
            cvm__d3_compact(&K);
            for (i = 0; i < K.ntet; i++) {
                int f;
                K.out[i] = (uint8_t)cvm__d3_outside(K.M, i);
                K.bnd[i] = 0;
                for (f = 0; f < 4; f++)
                    K.bnd[i] |= K.nbr[4 * i + (size_t)f] < 0;
            }
        }
    }
    r->out_after = K.nout = count_out(&K, &r->bout_after, &r->nbnd_after);
    low = r->out_after;
    for (sweep = 0; sweep < (size_t)p->max_sweeps && r->out_after > 0 && !s; sweep++) {
        size_t n = sweep_order(&K, rk, vs, p->seed, sweep), moved = 0;
        K.sweep = sweep;
        for (i = 0; i < n && !s; i++) {
            moved += (size_t)solve_vertex(&K, rk[i].v);
            s = cvm__tick(ctx, 1, CVM_STAGE_OPTIMISE_DUAL,
                          1.0 - (double)K.nout / (double)(r->out_before ? r->out_before : 1));
        }
        if (p->flips)
            cvm__d3_compact(&K);
        r->moves += moved;
        r->sweeps++;
        r->out_after = count_out(&K, &r->bout_after, &r->nbnd_after);
        if (r->out_after < low)
            low = r->out_after, stall = 0;
        else
            stall++;
        if (stall >= 3 || !moved) {
            if (p->escalate <= 1 || K.budget >= p->escalate * p->budget)
                break;
            K.budget *= 2;
            stall = 0;
            memset(K.stuck, 0, M->nv);
        }
    }
    if (p->flips)
        cvm__d3_compact(&K);
    r->out_after = count_out(&K, &r->bout_after, &r->nbnd_after);
    r->ntet_after = K.ntet;
    r->flips = K.flips;
    if (p->flips) { /* hand the connectivity over: no allocation, so no failure here */
        topo->tet = K.tet;
        topo->attr = K.attr;
        topo->ntet = K.ntet;
        K.tet = NULL;
        K.attr = NULL;
    }
    cvm__free(ctx, rk);
    cvm__free(ctx, vs);
    work_free(ctx, &K);
    return s;
}
