/* optimise_sweep.c - one sweep of the dual optimiser: the visiting order, batches of
 * independent vertices solved in parallel and applied in order, the restore of the regular
 * triangulation afterwards (weight raises, vertex removal, compaction) and degree repair. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "optimise_run.h"
#include "geom/geom_internal.h"
#include "geom/measure.h"


/* Solve the local problem of job J (reads the mesh, writes only J): the
 * parallel part of a batch. */
static void solve_job(const dopt *D, job *J, uint64_t sweep)
{
    const cvm__tri2 *T = D->T;
    const int32_t *star = D->star + J->star0;
    cvm__dopt_local L;
    double u[CVM__DOPT_MAXDOF] = {0}, f0, f;
    int32_t v = J->v;
    J->moved = 0;
    memset(&L, 0, sizeof L);
    if (!J->nstar || !(D->vsize[v] > 0))
        return;
    L.ndof = cvm__dopt_vertex_mode(D, v, star, J->nstar, L.dir);
    if (!L.ndof)
        return;
    L.T = T;
    L.v = v;
    L.p0[0] = T->xy[2 * (size_t)v];
    L.p0[1] = T->xy[2 * (size_t)v + 1];
    L.w0 = T->w[v];
    L.h = D->vsize[v];
    L.star = star;
    L.nstar = J->nstar;
    L.vbnd = D->vbnd;
    L.margin = D->p->margin;
    L.sin2_target = D->sin2_target;
    L.sin2_bound = cvm__dopt_star_min_sin2(&L);
    if (L.sin2_bound > D->sin2_min)
        L.sin2_bound = D->sin2_min;
    if (D->mm) {
        double m0[2];
        cvm__dopt_maxmin_cache(&L);
        if (cvm__dopt_eval_maxmin(&L, u, m0) == HUGE_VAL)
            return; /* not regular or too large a star: leave it */
        L.slack_bound = m0[0] < MM_SLACK_F * D->p->margin ? m0[0] : MM_SLACK_F * D->p->margin;
        L.dual_bound = m0[1] < MM_DUAL_F * D->p->margin ? m0[1] : MM_DUAL_F * D->p->margin;
        L.maxmin = 1;
        L.mm_m0 = cvm__dopt_star_min_sin2(&L);
    }
    f0 = cvm__dopt_eval(&L, u);
    if (D->mm) {
        /* the active-set ascent of the position, then the compass search over
         * every degree of freedom from where it ended */
        double ua[CVM__DOPT_MAXDOF], fa;
        cvm__dopt_maxmin_active(&L, f0, ua, &fa);
        if (fa < f0) {
            double w;
            cvm__dopt_point(&L, ua, L.p0, &w);
            L.w0 = w;
        }
        cvm__dopt_pattern(&L, D->p->pattern_budget < MM_PATTERN_BUDGET ? D->p->pattern_budget : MM_PATTERN_BUDGET,
                          fa, u, &f);
        if (!(f < f0))
            return;
        cvm__dopt_point(&L, u, J->p, &J->w);
        J->moved = 1;
        return;
    }
    if (D->p->solver == CVM__DUAL_SOLVER_CUCKOO) {
        cvm__rng r;
        cvm__rng_seed(&r, cvm__dopt_stream_key(D->p->seed, sweep, (uint64_t)v));
        cvm__dopt_cuckoo(&L, D->p->cuckoo_budget, &r, f0, u, &f);
    } else {
        cvm__dopt_pattern(&L, D->p->pattern_budget, f0, u, &f);
    }
    if (!(f < f0))
        return;
    cvm__dopt_point(&L, u, J->p, &J->w);
    J->moved = 1;
}

static void rescore_star(dopt *D, const int32_t *star, size_t nstar);

/* Apply a solved job: move the vertex, re-score its star and the triangles
 * across its outer edges; in the max-min phase, undo a move that made a
 * triangle non-compliant (then J->moved is 0). Serial, in batch order. */
static void apply_job(dopt *D, job *J)
{
    cvm__tri2 *T = D->T;
    const int32_t *star = D->star + J->star0;
    size_t nc0 = D->nc;
    double old[3];
    if (!J->moved)
        return;
    old[0] = T->xy[2 * (size_t)J->v];
    old[1] = T->xy[2 * (size_t)J->v + 1];
    old[2] = T->w[J->v];
    T->xy[2 * (size_t)J->v] = J->p[0];
    T->xy[2 * (size_t)J->v + 1] = J->p[1];
    T->w[J->v] = J->w;
    rescore_star(D, star, J->nstar);
    if (D->mm && D->nc > nc0) {
        /* the max-min phase keeps every triangle compliant (exact test) */
        T->xy[2 * (size_t)J->v] = old[0];
        T->xy[2 * (size_t)J->v + 1] = old[1];
        T->w[J->v] = old[2];
        rescore_star(D, star, J->nstar);
        J->moved = 0;
    }
}

/* Power vertices and scores of the triangles of a star and of those across its outer edges. */
static void rescore_star(dopt *D, const int32_t *star, size_t nstar)
{
    cvm__tri2 *T = D->T;
    size_t k;
    int j;
    for (k = 0; k < nstar; k++)
        if (cvm__tri2_in_domain(T, star[k]))
            cvm__dual_tri_vertex(T, star[k], D->V + 2 * (size_t)star[k]);
    for (k = 0; k < nstar; k++) {
        int32_t t = star[k];
        if (!cvm__tri2_in_domain(T, t))
            continue;
        cvm__dopt_rescore(D, t);
        for (j = 0; j < 3; j++) {
            int32_t u2 = T->tn[3 * (size_t)t + (size_t)j] / 3;
            if (cvm__tri2_in_domain(T, u2))
                cvm__dopt_rescore(D, u2);
        }
    }
}

/* Drop the removed vertices (gone) from T's vertex arrays, renumbering the
 * rest in order; carry vsize, vbnd and the caller's map along. */
void cvm__dopt_compact(dopt *D)
{
    cvm__tri2 *T = D->T;
    size_t v, nv = T->nv;
    for (v = 0; v < nv; v++)
        D->dup[v] = D->gone[v] ? 0 : -1; /* vertex 0 is an input point: never gone */
    cvm__tri2_compact(T, D->dup, D->map2);
    for (v = 0; v < nv; v++) {
        int32_t n = D->map2[v];
        if (D->gone[v]) {
            D->map2[v] = -1;
            continue;
        }
        D->vsize[n] = D->vsize[v]; /* n <= v: in place */
        D->msize[n] = D->msize[v];
        D->vbnd[n] = D->vbnd[v];
    }
    memset(D->gone, 0, nv);
    for (v = 0; v < D->nv0; v++)
        if (D->p->vmap[v] >= 0)
            D->p->vmap[v] = D->map2[D->p->vmap[v]];
}

/* Average angle, in degrees, of vertex v over its domain triangles (each
 * corner's angle, plain doubles) into *avg; their number is returned. */
static size_t corner_angles(const dopt *D, int32_t v, double *avg)
{
    const cvm__tri2 *T = D->T;
    int32_t t0 = T->vtri[v], t = t0;
    size_t n = 0, k = 0;
    double sum = 0;
    if (t0 < 0)
        return 0;
    do {
        const int32_t *tv = T->tv + 3 * (size_t)t;
        int i = tv[0] == v ? 0 : tv[1] == v ? 1 : 2;
        if (cvm__tri2_in_domain(T, t)) {
            const double *p = T->xy + 2 * (size_t)v, *a = T->xy + 2 * (size_t)tv[(i + 1) % 3];
            const double *b = T->xy + 2 * (size_t)tv[(i + 2) % 3];
            sum += cvm__corner_angle(p, a, b);
            n++;
        }
        t = T->tn[3 * (size_t)t + (size_t)(i + 1) % 3] / 3;
    } while (t != t0 && ++k < T->nt);
    *avg = n ? sum / (double)n * (180.0 / CVM__PI) : 0.0;
    return n;
}

/* 1 when a domain triangle around v has an angle below the target. */
static int star_weak(const dopt *D, int32_t v)
{
    const cvm__tri2 *T = D->T;
    int32_t t0 = T->vtri[v], t = t0;
    size_t k = 0;
    if (t0 < 0)
        return 0;
    do {
        if (cvm__tri2_in_domain(T, t) && D->weak[t])
            return 1;
        t = cvm__tri2_around(T, t, v);
    } while (t != t0 && ++k < T->nt);
    return 0;
}

/* Degree repair (see the file comment): a vertex whose corners average less
 * than DEG_HIGH_DEG degrees (degree 8 and more inside) and that touches a weak
 * triangle loses its removable Steiner neighbour of least degree; an interior
 * removable Steiner vertex of degree 4 or less is removed. One operation per
 * neighbourhood and pass (stamps); vertices in index order. The number
 * removed; T is then valid but maybe not regular (cvm__dopt_restore() follows). */
size_t cvm__dopt_repair_degrees(dopt *D)
{
    cvm__tri2 *T = D->T;
    size_t v, nrem = 0;
    D->cur_stamp++;
    for (v = 0; v < T->nv; v++) {
        int32_t t0 = T->vtri[v], t, best = -1;
        size_t deg, bdeg = 0, k = 0;
        double avg;
        if (t0 < 0 || D->gone[v] || D->stamp[v] == D->cur_stamp)
            continue;
        if (v >= D->p->n_input && cvm__dual_removable(T, (int32_t)v, &deg) && deg <= 4) {
            best = (int32_t)v;
        } else if (corner_angles(D, (int32_t)v, &avg) && avg < DEG_HIGH_DEG && star_weak(D, (int32_t)v)) {
            t = t0;
            do {
                const int32_t *tv = T->tv + 3 * (size_t)t;
                int i = tv[0] == (int32_t)v ? 0 : tv[1] == (int32_t)v ? 1 : 2;
                int32_t x = tv[(i + 2) % 3];
                size_t dx;
                if (x >= 0 && (size_t)x >= D->p->n_input && D->stamp[x] != D->cur_stamp &&
                    cvm__dual_removable(T, x, &dx) && (best < 0 || dx < bdeg)) {
                    best = x;
                    bdeg = dx;
                }
                t = T->tn[3 * (size_t)t + (size_t)(i + 1) % 3] / 3;
            } while (t != t0 && ++k < T->nt);
        }
        if (best < 0)
            continue;
        {
            /* stamp the neighbourhood of best before it goes */
            int32_t s0 = T->vtri[best], s = s0;
            k = 0;
            do {
                int i = cvm__tri2_corner(T, s, best);
                D->stamp[T->tv[3 * (size_t)s + (size_t)(i + 1) % 3]] = D->cur_stamp;
                s = T->tn[3 * (size_t)s + (size_t)(i + 1) % 3] / 3;
            } while (s != s0 && ++k < T->nt);
            D->stamp[v] = D->cur_stamp;
            if (cvm__dual_remove_vertex(T, best, best == (int32_t)v ? -1 : (int32_t)v)) {
                D->gone[best] = 1;
                nrem++;
            }
        }
    }
    return nrem;
}

/* Make T regular again with no vanished vertex (see the file comment). */
cvm_status cvm__dopt_restore(dopt *D)
{
    cvm__tri2 *T = D->T;
    size_t nfl, v;
    int round;
    cvm_status s;
    if ((s = cvm__tri2_make_regular(T, &nfl)))
        return s;
    D->rep->flips += nfl;
    for (round = 0; D->topo && round < FIX_ROUNDS; round++) {
        size_t nrem = 0;
        if (!cvm__tri2_count_unregular(T, D->mark))
            return CVM_OK;
        for (v = D->p->n_input; v < T->nv; v++)
            if (D->mark[v] && cvm__dual_remove_vertex(T, (int32_t)v, -1)) {
                D->gone[v] = 1;
                nrem++;
            }
        if (!nrem)
            break;
        D->rep->removed_vanished += nrem;
        cvm__dopt_compact(D);
        if ((s = cvm__tri2_make_regular(T, &nfl)))
            return s;
        D->rep->flips += nfl;
    }
    for (round = 0; round < FIX_ROUNDS; round++) {
        if (!cvm__tri2_count_unregular(T, D->mark))
            return CVM_OK;
        for (v = 0; v < T->nv; v++)
            if (D->mark[v]) {
                double h = D->vsize[v] > 0 ? D->vsize[v] : 1.0;
                T->w[v] += 0.1 * h * h * (double)(1 << round);
                D->rep->weight_fixes++;
            }
        if ((s = cvm__tri2_make_regular(T, &nfl)))
            return s;
        D->rep->flips += nfl;
    }
    if (!cvm__tri2_count_unregular(T, D->mark))
        return CVM_OK;
    memset(T->w, 0, T->nv * sizeof *T->w);
    D->rep->weight_fixes += T->nv;
    if ((s = cvm__tri2_make_regular(T, &nfl)))
        return s;
    D->rep->flips += nfl;
    return CVM_OK;
}

static int by_score(const void *a, const void *b, const double *F, const uint8_t *st)
{
    int32_t x = *(const int32_t *)a, y = *(const int32_t *)b;
    if ((st[x] == CVM__DUAL_NONCOMPLIANT) != (st[y] == CVM__DUAL_NONCOMPLIANT))
        return st[x] == CVM__DUAL_NONCOMPLIANT ? -1 : 1;
    if (F[x] != F[y])
        return F[x] > F[y] ? -1 : 1;
    return x < y ? -1 : x > y;
}

/* Sort list[0..n) by (F descending, slot ascending): insertion into runs
 * merged bottom-up would be faster; a plain merge sort keeps it total. */
static void sort_list(int32_t *a, int32_t *tmp, size_t n, const double *F, const uint8_t *st)
{
    size_t width, i;
    for (width = 1; width < n; width *= 2) {
        for (i = 0; i < n; i += 2 * width) {
            size_t lo = i, mid = i + width < n ? i + width : n, hi = i + 2 * width < n ? i + 2 * width : n;
            size_t x = lo, y = mid, k = lo;
            while (x < mid && y < hi)
                tmp[k++] = by_score(&a[x], &a[y], F, st) <= 0 ? a[x++] : a[y++];
            while (x < mid)
                tmp[k++] = a[x++];
            while (y < hi)
                tmp[k++] = a[y++];
        }
        memcpy(a, tmp, n * sizeof *a);
    }
}

/* Order of one sweep into D->list; returns its length. */
static size_t sweep_order(dopt *D, uint64_t sweep)
{
    cvm__tri2 *T = D->T;
    size_t t, n = 0, nb, b;
    cvm__rng r;
    for (t = 0; t < T->nt; t++)
        if (D->st[t] == CVM__DUAL_NONCOMPLIANT || (D->weak[t] && !D->nc_only))
            D->list[n++] = (int32_t)t;
    sort_list(D->list, D->star, n, D->F, D->st);
    nb = n / 25 < 20 ? n / 25 : 20;
    if (nb < 1)
        nb = 1;
    cvm__rng_seed(&r, cvm__dopt_stream_key(D->p->seed, sweep, UINT64_MAX - 1));
    for (b = 0; b < nb; b++) {
        size_t lo = b * n / nb, hi = (b + 1) * n / nb, i;
        for (i = hi; i > lo + 1; i--) {
            size_t k = lo + (size_t)cvm__rng_below(&r, i - lo);
            int32_t x = D->list[i - 1];
            D->list[i - 1] = D->list[k];
            D->list[k] = x;
        }
    }
    return n;
}

/* Smallest sin^2 of an angle of triangle t (plain doubles), at most 1. */
double cvm__dopt_tri_min_sin2(const cvm__tri2 *T, int32_t t)
{
    const int32_t *v = T->tv + 3 * (size_t)t;
    double m = cvm__min_sin2_corners(T->xy + 2 * (size_t)v[0], T->xy + 2 * (size_t)v[1],
                                     T->xy + 2 * (size_t)v[2]);
    return m < 1.0 ? m : 1.0;
}

/* Order of a max-min round into D->list: the domain triangles whose smallest
 * angle is below the smallest over the mesh + MM_BAND_DEG (that smallest, in
 * degrees, into D->mm_min), smallest first (ties by slot; the key is kept in
 * D->F, which the phase does not otherwise read). Returns the length. */
static size_t mm_order(dopt *D)
{
    cvm__tri2 *T = D->T;
    size_t t, n = 0;
    double m = 1.0, g;
    for (t = 0; t < T->nt; t++) {
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        D->F[t] = cvm__dopt_tri_min_sin2(T, (int32_t)t);
        m = D->F[t] < m ? D->F[t] : m;
    }
    D->mm_min = asin(sqrt(m)) * (180.0 / CVM__PI);
    g = D->mm_min + MM_BAND_DEG < 90.0 ? sin((D->mm_min + MM_BAND_DEG) * CVM__PI / 180.0) : 1.0;
    g *= g;
    for (t = 0; t < T->nt; t++) {
        const int32_t *tv = T->tv + 3 * t;
        if (!cvm__tri2_in_domain(T, (int32_t)t) || !(D->F[t] < g) ||
            (D->region_on && !D->region[tv[0]] && !D->region[tv[1]] && !D->region[tv[2]]))
            continue;
        D->F[t] = -D->F[t];
        D->list[n++] = (int32_t)t;
    }
    sort_list(D->list, D->star, n, D->F, D->st);
    return n;
}

void cvm__dopt_save_state(dopt *D)
{
    cvm__tri2 *T = D->T;
    size_t v;
    for (v = 0; v < T->nv; v++) {
        D->save[3 * v] = T->xy[2 * v];
        D->save[3 * v + 1] = T->xy[2 * v + 1];
        D->save[3 * v + 2] = T->w[v];
    }
}

void cvm__dopt_load_state(dopt *D)
{
    cvm__tri2 *T = D->T;
    size_t v;
    for (v = 0; v < T->nv; v++) {
        T->xy[2 * v] = D->save[3 * v];
        T->xy[2 * v + 1] = D->save[3 * v + 1];
        T->w[v] = D->save[3 * v + 2];
    }
}

static double progress(const dopt *D)
{
    return D->nc0 ? 1.0 - (double)D->nc / (double)D->nc0 : 1.0;
}

/* The report's non-compliant %, as CVM_MEASURE_DUAL_NONCOMPLIANT_PCT measures
 * it: D->nc of the last cvm__dopt_score_all() (the mesh's own sizes). */
double cvm__dopt_pct(dopt *D)
{
    size_t t, n = 0;
    for (t = 0; t < D->T->nt; t++)
        n += cvm__tri2_in_domain(D->T, (int32_t)t) != 0;
    return n ? 100.0 * (double)D->nc / (double)n : 0.0;
}

/* Add v to the batch being formed when no vertex of the batch is v or one of
 * its neighbours (so the batch's local problems share no vertex that moves):
 * gather its star into the pool and stamp its star's vertices. 0: blocked. */
static int batch_add(dopt *D, int32_t v, size_t *nb, size_t *used)
{
    const cvm__tri2 *T = D->T;
    job *J = D->jobs + *nb;
    size_t k;
    if (D->stamp[v] == D->cur_stamp)
        return 0;
    J->v = v;
    J->star0 = *used;
    J->nstar = cvm__dopt_gather_star(D, v, D->star + *used);
    for (k = 0; k < J->nstar; k++) {
        const int32_t *tv = T->tv + 3 * (size_t)D->star[*used + k];
        int c;
        for (c = 0; c < 3; c++)
            if (tv[c] != CVM__GHOST && D->stamp[tv[c]] == D->cur_stamp) {
                J->nstar = 0; /* a neighbour is in the batch: v waits */
                return 0;
            }
    }
    for (k = 0; k < J->nstar; k++) {
        const int32_t *tv = T->tv + 3 * (size_t)D->star[*used + k];
        int c;
        for (c = 0; c < 3; c++)
            if (tv[c] != CVM__GHOST)
                D->stamp[tv[c]] = D->cur_stamp;
    }
    D->stamp[v] = D->cur_stamp;
    *used += J->nstar;
    ++*nb;
    return 1;
}

/* One sweep; *moved_out receives the number of accepted moves. The visiting
 * order is cut into batches of at most BATCH vertices, no two of them equal or
 * adjacent, taken in order from the sorted list (a vertex that would join a
 * batch holding one of its neighbours closes the batch). The local problems of
 * a batch are independent, so they are solved in parallel; the moves are
 * then applied and re-scored in batch order. Batches depend only on the mesh
 * and the order, never on the thread count, so the result does not either. */
cvm_status cvm__dopt_sweep(dopt *D, uint64_t k, size_t *moved_out)
{
    cvm__tri2 *T = D->T;
    size_t n = D->mm ? mm_order(D) : sweep_order(D, k), i = 0, moved = 0;
    cvm_status s = CVM_OK;
    memset(D->mark, 0, T->nv);
    while (i < n && !s) {
        size_t nb = 0, used = 0, b;
        int closed = 0;
        D->cur_stamp++;
        while (i < n && nb < BATCH && !closed) {
            int32_t t = D->list[i];
            int j;
            if ((!D->mm && D->st[t] != CVM__DUAL_NONCOMPLIANT && !D->weak[t]) ||
                !cvm__tri2_in_domain(T, t)) {
                i++;
                continue;
            }
            for (j = 0; j < 3 && !closed; j++) {
                int32_t v = T->tv[3 * (size_t)t + (size_t)j];
                if (D->mark[v])
                    continue;
                if (nb == BATCH || !batch_add(D, v, &nb, &used))
                    closed = 1;
                else
                    D->mark[v] = 1;
            }
            if (!closed)
                i++;
        }
        {
            long kk, nbl = (long)nb;
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 8) num_threads(D->nthreads) if (nb > 16)
#endif
            for (kk = 0; kk < nbl; kk++)
                solve_job(D, D->jobs + kk, k);
        }
        for (b = 0; b < nb && !s; b++) {
            apply_job(D, D->jobs + b);
            moved += (size_t)D->jobs[b].moved;
            s = cvm__tick(T->ctx, 1, CVM_STAGE_OPTIMISE_DUAL, progress(D));
        }
    }
    *moved_out = moved;
    return s;
}
