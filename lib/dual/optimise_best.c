/* optimise_best.c - the best state of a dual optimisation run: the smallest angle, keeping the
 * best state (fewest non-compliant, then largest smallest angle) and returning to it. */
#include <math.h>
#include <string.h>

#include "optimise_run.h"
#include "geom/geom_internal.h"
#include "geom/measure.h"

/* Go back to the best state kept by keep_best when it beats the current one
 * and has the same vertices: its positions, weights and triangulation (the
 * flips since then may have made triangles that the old positions turn over,
 * around clusters of nearly coincident points, which flips cannot untangle;
 * so the triangulation is copied back, not re-derived). When that
 * triangulation was not kept, the old positions are made regular by flips,
 * and where they turn a triangle over the run keeps its current state. */
cvm_status cvm__dopt_end_at_best(dopt *D, size_t best_nc, double best_min)
{
    size_t v;
    if (D->best_nv != D->T->nv || D->best_removed != D->rep->removed_vanished + D->rep->removed_degree + D->rep->removed_maxmin)
        return CVM_OK;
    if (!(best_nc < D->nc ||
          (best_nc == D->nc && best_min > cvm__dopt_min_angle(D) + BEST_EPS_DEG)))
        return CVM_OK;
    cvm__dopt_save_state(D);
    for (v = 0; v < D->T->nv; v++) {
        D->T->xy[2 * v] = D->best[3 * v];
        D->T->xy[2 * v + 1] = D->best[3 * v + 1];
        D->T->w[v] = D->best[3 * v + 2];
    }
    if (D->best_nt && D->best_nt == D->T->nt) {
        cvm__tri2 *T = D->T;
        size_t nt = T->nt;
        memcpy(T->tv, D->best_tv, 3 * nt * sizeof *T->tv);
        memcpy(T->tn, D->best_tn, 3 * nt * sizeof *T->tn);
        memcpy(T->tf, D->best_tf, nt);
        if (T->te)
            memcpy(T->te, D->best_te, 3 * nt * sizeof *T->te);
        if (T->ta)
            memcpy(T->ta, D->best_ta, nt * sizeof *T->ta);
        memcpy(T->vtri, D->best_vtri, T->nv * sizeof *T->vtri);
        T->last = D->best_last;
    }
    if (!cvm__tri2_all_ccw(D->T)) {
        cvm__dopt_load_state(D);
        return CVM_OK;
    }
    return cvm__dopt_restore(D);
}

/* Smallest angle over the domain triangles, degrees (a measure). */
double cvm__dopt_min_angle(const dopt *D)
{
    const cvm__tri2 *T = D->T;
    size_t t;
    double best = 180.0;
    for (t = 0; t < T->nt; t++) {
        const int32_t *v = T->tv + 3 * t;
        double a;
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        a = cvm__tri_min_angle_deg(T->xy + 2 * (size_t)v[0], T->xy + 2 * (size_t)v[1],
                                   T->xy + 2 * (size_t)v[2]);
        if (a < best)
            best = a;
    }
    return best;
}

/* The best state so far (see run): fewest non-compliant, then largest
 * smallest angle. 1 when the current state is better (and is now the best). */
int cvm__dopt_keep_best(dopt *D, size_t *best_nc, double *best_min)
{
    double mn = cvm__dopt_min_angle(D);
    size_t v;
    if (!(D->nc < *best_nc || (D->nc == *best_nc && mn > *best_min + BEST_EPS_DEG)))
        return 0;
    *best_nc = D->nc;
    *best_min = mn;
    for (v = 0; v < D->T->nv; v++) {
        D->best[3 * v] = D->T->xy[2 * v];
        D->best[3 * v + 1] = D->T->xy[2 * v + 1];
        D->best[3 * v + 2] = D->T->w[v];
    }
    D->best_nv = D->T->nv;
    D->best_removed = D->rep->removed_vanished + D->rep->removed_degree + D->rep->removed_maxmin;
    D->best_nt = 0;
    if (D->best_tv && D->T->nt <= D->best_cap) {
        const cvm__tri2 *T = D->T;
        size_t nt = T->nt;
        memcpy(D->best_tv, T->tv, 3 * nt * sizeof *T->tv);
        memcpy(D->best_tn, T->tn, 3 * nt * sizeof *T->tn);
        memcpy(D->best_tf, T->tf, nt);
        if (T->te)
            memcpy(D->best_te, T->te, 3 * nt * sizeof *T->te);
        if (T->ta)
            memcpy(D->best_ta, T->ta, nt * sizeof *T->ta);
        memcpy(D->best_vtri, T->vtri, T->nv * sizeof *T->vtri);
        D->best_last = T->last;
        D->best_nt = nt;
    }
    return 1;
}
