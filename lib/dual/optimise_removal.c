/* optimise_removal.c - the max-min-angle phase of the dual optimiser: rounds of max-min solves
 * that keep every triangle compliant, and removal trials on a snapshot of the triangulation. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "optimise_run.h"
#include "geom/geom_internal.h"
#include "geom/measure.h"


/* The max-min-angle phase, once every triangle is compliant: rounds over the
 * vertices of the triangles whose smallest angle is below the current
 * smallest + MM_BAND_DEG, smallest first, each solving max over its degrees
 * of freedom of its star's smallest angle with every star triangle kept
 * compliant with a slack and dual edges kept long
 * (cvm__dopt_eval_maxmin), the star regular (so no flip follows a move;
 * cvm__dopt_restore() still runs as a safety net) and a move that made a triangle
 * non-compliant (exact test) undone. The smallest angle never drops; the
 * phase ends after p->maxmin_rounds rounds, a round that moves nothing, or
 * MM_PATIENCE rounds without MM_PROGRESS_DEG gain. */
/* The whole triangulation (and the caller's vertex map) before a removal
 * trial: vertices are only removed and triangles only killed or flipped
 * during a trial, so the arrays keep their capacity and copying back
 * restores it exactly. */
typedef struct snap {
    double *xy, *w, *ta;
    int32_t *vtri, *tv, *tn, *te, *vmap;
    uint8_t *tf;
    size_t nv, nt, n_dead, cap_nv, cap_nt;
    int32_t free_head, last;
    cvm__dual_opt_report rep;
} snap;

void cvm__dopt_snap_free(cvm__ctx *ctx, snap *S)
{
    if (!S)
        return;
    cvm__free(ctx, S->xy);
    cvm__free(ctx, S->w);
    cvm__free(ctx, S->ta);
    cvm__free(ctx, S->vtri);
    cvm__free(ctx, S->tv);
    cvm__free(ctx, S->tn);
    cvm__free(ctx, S->te);
    cvm__free(ctx, S->vmap);
    cvm__free(ctx, S->tf);
    cvm__free(ctx, S);
}

/* Copy the arrays of the triangulation (and the vertex map) into the
 * snapshot, or back from it (back = 1), for the snapshot's counts. */
static void snap_copy(dopt *D, int back)
{
    cvm__tri2 *T = D->T;
    snap *S = D->snap;
    size_t nt = S->nt, nv = S->nv;
#define SNAP_COPY(t, s, bytes) ((back) ? memcpy((t), (s), (bytes)) : memcpy((s), (t), (bytes)))
    SNAP_COPY(T->xy, S->xy, 2 * nv * sizeof *S->xy);
    SNAP_COPY(T->w, S->w, nv * sizeof *S->w);
    SNAP_COPY(T->vtri, S->vtri, nv * sizeof *S->vtri);
    SNAP_COPY(T->tv, S->tv, 3 * nt * sizeof *S->tv);
    SNAP_COPY(T->tn, S->tn, 3 * nt * sizeof *S->tn);
    SNAP_COPY(T->tf, S->tf, nt);
    if (T->te)
        SNAP_COPY(T->te, S->te, 3 * nt * sizeof *S->te);
    if (T->ta)
        SNAP_COPY(T->ta, S->ta, nt * sizeof *S->ta);
    if (D->topo)
        SNAP_COPY(D->p->vmap, S->vmap, D->nv0 * sizeof *S->vmap);
#undef SNAP_COPY
}

static cvm_status snap_take(dopt *D)
{
    cvm__tri2 *T = D->T;
    cvm__ctx *ctx = T->ctx;
    snap *S = D->snap;
    size_t nv = T->nv, nt = T->nt;
    if (S && (S->cap_nv < nv || S->cap_nt < nt)) {
        cvm__dopt_snap_free(ctx, S);
        D->snap = S = NULL;
    }
    if (!S) {
        S = cvm__calloc(ctx, 1, sizeof *S);
        if (!S)
            return CVM_E_NOMEM;
        D->snap = S; /* S->nv 0: nothing to go back to yet */
        S->cap_nv = nv;
        S->cap_nt = nt;
        S->xy = cvm__malloc(ctx, (2 * nv + 1) * sizeof *S->xy);
        S->w = cvm__malloc(ctx, (nv + 1) * sizeof *S->w);
        S->vtri = cvm__malloc(ctx, (nv + 1) * sizeof *S->vtri);
        S->tv = cvm__malloc(ctx, (3 * nt + 1) * sizeof *S->tv);
        S->tn = cvm__malloc(ctx, (3 * nt + 1) * sizeof *S->tn);
        S->tf = cvm__malloc(ctx, nt + 1);
        S->te = T->te ? cvm__malloc(ctx, (3 * nt + 1) * sizeof *S->te) : NULL;
        S->ta = T->ta ? cvm__malloc(ctx, (nt + 1) * sizeof *S->ta) : NULL;
        S->vmap = D->topo ? cvm__malloc(ctx, (D->nv0 + 1) * sizeof *S->vmap) : NULL;
        if (!S->xy || !S->w || !S->vtri || !S->tv || !S->tn || !S->tf || (T->te && !S->te) ||
            (T->ta && !S->ta) || (D->topo && !S->vmap))
            return CVM_E_NOMEM; /* D->snap is freed by the caller */
    }
    S->nv = nv;
    S->nt = nt;
    S->n_dead = T->n_dead;
    S->free_head = T->free_head;
    S->last = T->last;
    S->rep = *D->rep;
    snap_copy(D, 0);
    return CVM_OK;
}

static void snap_back(dopt *D)
{
    cvm__tri2 *T = D->T;
    const snap *S = D->snap;
    double seconds = D->rep->seconds;
    T->nv = S->nv;
    T->nt = S->nt;
    T->n_dead = S->n_dead;
    T->free_head = S->free_head;
    T->last = S->last;
    *D->rep = S->rep;
    D->rep->seconds = seconds;
    snap_copy(D, 1);
}

static cvm_status mm_rounds(dopt *D, uint64_t k0, int rounds, size_t *best_nc, double *best_min,
                                int *stalled);

/* Mark in D->region the n vertices seed[] and RM_RINGS rings of neighbours
 * around them (breadth first; D->list is the queue, D->star scratch). */
static void mark_region(dopt *D, const int32_t *seed, size_t n)
{
    cvm__tri2 *T = D->T;
    size_t head = 0, tail = 0, ring_end, i;
    int ring;
    memset(D->region, 0, T->nv);
    for (i = 0; i < n; i++)
        if (seed[i] >= 0 && !D->region[seed[i]]) {
            D->region[seed[i]] = 1;
            D->list[tail++] = seed[i];
        }
    for (ring = 0; ring < RM_RINGS; ring++) {
        ring_end = tail;
        while (head < ring_end) {
            int32_t v = D->list[head++];
            size_t ns = cvm__dopt_gather_star(D, v, D->star), k;
            for (k = 0; k < ns; k++) {
                const int32_t *tv = T->tv + 3 * (size_t)D->star[k];
                int c;
                for (c = 0; c < 3; c++)
                    if (tv[c] != CVM__GHOST && !D->region[tv[c]]) {
                        D->region[tv[c]] = 1;
                        D->list[tail++] = tv[c];
                    }
            }
        }
    }
}

/* Number of domain triangles with an angle below deg degrees (plain doubles). */
static size_t count_below(const dopt *D, double deg)
{
    const cvm__tri2 *T = D->T;
    double g = sin(deg * CVM__PI / 180.0);
    size_t t, n = 0;
    g *= g;
    for (t = 0; t < T->nt; t++)
        n += cvm__tri2_in_domain(T, (int32_t)t) && cvm__dopt_tri_min_sin2(T, (int32_t)t) < g;
    return n;
}

/* Removal trials of the max-min phase (with p->topology and its vertex map):
 * for the triangles within RM_BAND_DEG of the smallest angle, up to RM_TRIES
 * removable Steiner vertices (cvm__dual_removable) - first the least-degree
 * neighbour of each hub (see below), then the triangles' corners, highest
 * degree first, lower index on ties; none at a position whose trial failed
 * before (D->failed) - are removed one at a time; up to RM_SWEEPS sweeps over
 * the non-compliant triangles make every triangle compliant again and up to
 * RM_ROUNDS max-min rounds over RM_RINGS rings around the vertex follow. The
 * result is kept when every triangle is compliant and the smallest angle
 * rose by MM_PROGRESS_DEG, or did not drop and fewer triangles lie within
 * MM_PROGRESS_DEG of it; else the triangulation goes back to its snapshot.
 * Stops at the first kept trial (*kept_out 1). Deterministic: the order and
 * the sweeps depend only on the mesh. */
static cvm_status removal_trials(dopt *D, uint64_t k0, size_t *best_nc, double *best_min, int *kept_out)
{
    cvm__tri2 *T = D->T;
    int32_t cand[RM_TRIES], nb[RM_MAXNB];
    size_t n, i, nc = 0, t, cdeg[RM_TRIES], nnb = 0, nlow0;
    double g, gmin = cvm__dopt_min_angle(D), target = D->sin2_target;
    cvm_status s = CVM_OK;
    *kept_out = 0;
    if (!D->topo)
        return CVM_OK;
    g = sin((gmin + RM_BAND_DEG) * CVM__PI / 180.0);
    g *= g;
    /* candidates: the removable Steiner neighbour of least degree of each hub
     * (an interior vertex of RM_HUB_DEG or more triangles at the smallest
     * angle of a worst triangle: it caps that angle at 360 / its degree),
     * mark 2; the removable Steiner corners of the worst triangles, mark 1 */
    memset(D->mark, 0, T->nv);
    for (t = 0; t < T->nt; t++) {
        const int32_t *tv = T->tv + 3 * t;
        double l2[3];
        int j, c = 0;
        size_t ns;
        if (!cvm__tri2_in_domain(T, (int32_t)t) || !(cvm__dopt_tri_min_sin2(T, (int32_t)t) < g))
            continue;
        for (j = 0; j < 3; j++) {
            const double *p = T->xy + 2 * (size_t)tv[(j + 1) % 3], *q = T->xy + 2 * (size_t)tv[(j + 2) % 3];
            l2[j] = cvm__dopt_sq(p[0] - q[0]) + cvm__dopt_sq(p[1] - q[1]);
            c = l2[j] < l2[c] ? j : c; /* the smallest angle is opposite the shortest edge */
            if (D->mark[tv[j]] < 1)
                D->mark[tv[j]] = 1;
        }
        if (D->vbnd[tv[c]] || (ns = cvm__dopt_gather_star(D, tv[c], D->star)) < RM_HUB_DEG)
            continue;
        {
            int32_t best = -1;
            size_t bdeg = 0, q;
            for (q = 0; q < ns; q++) {
                const int32_t *sv = T->tv + 3 * (size_t)D->star[q];
                int e;
                for (e = 0; e < 3; e++) {
                    int32_t x = sv[e];
                    size_t dx;
                    if (x == CVM__GHOST || x == tv[c] || (size_t)x < D->p->n_input ||
                        !cvm__dual_removable(T, x, &dx))
                        continue;
                    if (best < 0 || dx < bdeg || (dx == bdeg && x < best)) {
                        best = x;
                        bdeg = dx;
                    }
                }
            }
            if (best >= 0)
                D->mark[best] = 2;
        }
    }
    for (i = D->p->n_input; i < T->nv; i++) {
        size_t deg, q, f;
        if (!D->mark[i] || !cvm__dual_removable(T, (int32_t)i, &deg))
            continue;
        for (f = 0; f < D->nfailed; f++)
            if (D->failed[2 * f] == T->xy[2 * i] && D->failed[2 * f + 1] == T->xy[2 * i + 1])
                break;
        if (f < D->nfailed)
            continue; /* tried at this very position before, and failed */
        /* keep the RM_TRIES best: mark 2 before 1, then the higher degree, then
         * the lower index (earlier in this loop) */
        for (q = nc; q > 0 && (D->mark[cand[q - 1]] < D->mark[i] ||
                               (D->mark[cand[q - 1]] == D->mark[i] && cdeg[q - 1] < deg)); q--)
            if (q < RM_TRIES) {
                cand[q] = cand[q - 1];
                cdeg[q] = cdeg[q - 1];
            }
        if (q < RM_TRIES) {
            cand[q] = (int32_t)i;
            cdeg[q] = deg;
            nc += nc < RM_TRIES;
        }
    }
    nlow0 = count_below(D, gmin + MM_PROGRESS_DEG);
    /* trials aim at the target the caller set, not at a raised one */
    D->sin2_target = sin(D->p->target_angle_deg * CVM__PI / 180.0);
    D->sin2_target *= D->sin2_target;
    for (n = 0; n < nc && !s; n++) {
        size_t k, moved;
        int stalled;
        double mn;
        if ((s = snap_take(D)))
            break;
        {
            /* its neighbours, to seed the region of the trial's rounds */
            size_t ns = cvm__dopt_gather_star(D, cand[n], D->star), q;
            nnb = 0;
            for (q = 0; q < ns && nnb < RM_MAXNB; q++) {
                const int32_t *tv = T->tv + 3 * (size_t)D->star[q];
                int c;
                for (c = 0; c < 3; c++)
                    if (tv[c] != CVM__GHOST && tv[c] != cand[n] && nnb < RM_MAXNB)
                        nb[nnb++] = tv[c];
            }
        }
        if (!cvm__dual_remove_vertex(T, cand[n], -1))
            continue;
        D->gone[cand[n]] = 1;
        D->rep->removed_maxmin++;
        cvm__dopt_compact(D);
        for (i = 0; i < nnb; i++)
            nb[i] = D->map2[nb[i]];
        if ((s = cvm__dopt_restore(D)))
            break;
        for (k = 0; k < RM_SWEEPS && !s; k++) {
            if ((s = cvm__dopt_sizes(D)))
                break;
            cvm__dopt_boundary_flags(D);
            cvm__dual_layers(T, D->vbnd, D->layer, D->list);
            cvm__dopt_score_all(D);
            if (!D->nc)
                break;
            D->nc_only = 1;
            s = cvm__dopt_sweep(D, k0 + 1000 * (n + 1) + k, &moved);
            D->nc_only = 0;
            if (s || (s = cvm__dopt_restore(D)))
                break;
        }
        if (s)
            break;
        cvm__dopt_score_all(D);
        if (!D->nc) {
            mark_region(D, nb, nnb);
            D->region_on = 1;
            s = mm_rounds(D, k0 + 1000 * (n + 1) + 100, RM_ROUNDS, NULL, NULL, &stalled);
            D->region_on = 0;
            if (s)
                break;
            cvm__dopt_score_all(D);
        }
        mn = D->nc ? -1.0 : cvm__dopt_min_angle(D);
        if (mn > gmin + MM_PROGRESS_DEG || (mn >= gmin && count_below(D, gmin + MM_PROGRESS_DEG) < nlow0)) {
            *best_nc = (size_t)-1; /* the old best had other vertices */
            cvm__dopt_keep_best(D, best_nc, best_min);
            *kept_out = 1;
            break;
        }
        snap_back(D);
        if (D->nfailed < RM_FAILED) {
            D->failed[2 * D->nfailed] = T->xy[2 * (size_t)cand[n]];
            D->failed[2 * D->nfailed + 1] = T->xy[2 * (size_t)cand[n] + 1];
            D->nfailed++;
        }
        if ((s = cvm__dopt_sizes(D)))
            break;
        cvm__dopt_boundary_flags(D);
        cvm__dopt_score_all(D);
    }
    if (s && n < nc && D->snap && D->snap->nv) {
        /* out of memory or stopped inside a trial: back to its regular start */
        snap_back(D);
        cvm__dopt_score_all(D);
    }
    D->sin2_target = target;
    return s;
}

/* Up to rounds max-min rounds (see maxmin_phase); with best_nc, keep_best
 * follows the last. Moves keep every triangle compliant and the
 * triangulation regular, and no star's smallest angle drops, so the
 * per-triangle state is kept up to date by the moves alone and one cvm__dopt_restore()
 * at the end is only a safety net. *stalled: 1 when the rounds ended because
 * a round moved nothing or MM_PATIENCE rounds gained less than
 * MM_PROGRESS_DEG. Needs sizes, boundary flags and scores up to date. */
static cvm_status mm_rounds(dopt *D, uint64_t k0, int rounds, size_t *best_nc, double *best_min,
                                int *stalled)
{
    cvm_status s = CVM_OK;
    int r, stall = 0;
    double last = -1.0;
    *stalled = 0;
    for (r = 0; r < rounds && !D->nc; r++) {
        size_t moved = 0;
        D->mm = 1;
        s = cvm__dopt_sweep(D, k0 + (uint64_t)r, &moved); /* its order (mm_order) sets D->mm_min */
        D->mm = 0;
        D->rep->moves += moved;
        D->rep->maxmin_rounds++;
        if (s)
            break;
        if (D->mm_min > last + MM_PROGRESS_DEG) {
            last = D->mm_min;
            stall = 0;
        } else if (++stall >= MM_PATIENCE) {
            *stalled = 1;
            break;
        }
        if (!moved) {
            *stalled = 1;
            break;
        }
    }
    D->mm = 0;
    if (!s && !(s = cvm__dopt_restore(D))) {
        cvm__dopt_score_all(D);
        if (best_nc)
            cvm__dopt_keep_best(D, best_nc, best_min);
    }
    return s;
}

cvm_status cvm__dopt_maxmin_phase(dopt *D, uint64_t k0, size_t *best_nc, double *best_min)
{
    cvm_status s;
    int calls, stalled = 0, kept = 1;
    if ((s = cvm__dopt_sizes(D)))
        return s;
    cvm__dopt_boundary_flags(D);
    cvm__dopt_score_all(D);
    if (D->nc)
        return CVM_OK;
    if ((s = mm_rounds(D, k0, D->p->maxmin_rounds, best_nc, best_min, &stalled)) || D->p->maxmin_trials <= 0)
        return s;
    /* the trials follow the rounds when asked for, stalled or not (at the
     * default 10 rounds the shared meshes end by the count); a kept trial's
     * rounds ran to a stall around it, so the next trials follow at once */
    for (calls = 0; calls < D->p->maxmin_trials && kept && !s; calls++)
        s = removal_trials(D, k0 + (uint64_t)D->p->maxmin_rounds + 100000 * (uint64_t)calls, best_nc,
                           best_min, &kept);
    return s;
}
