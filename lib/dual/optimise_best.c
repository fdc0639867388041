/* optimise_best.c - the best state of a dual optimisation run: the smallest angle, keeping the
 * best state (fewest non-compliant, then largest smallest angle) and returning to it. */
#include <math.h>
#include <string.h>

#include "optimise_run.h"
#include "geom/geom_internal.h"
#include "geom/measure.h"

/* Go back to the best state kept by keep_best when it beats the current one
 * and has the same vertices: its positions and weights, made regular again
 * (the regular triangulation of a weighted point set is unique, so this is
 * the triangulation it had). The flips since then may have made triangles that
 * the old positions turn over (around clusters of nearly coincident points);
 * flips cannot untangle that, so the run then keeps its current state. */
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
    return 1;
}
