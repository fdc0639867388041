/*
 * optimise_cuckoo.c - the stochastic local solver of the dual optimiser:
 * Modified Cuckoo Search (S. Walton, O. Hassan, K. Morgan, M. R. Brown,
 * "Modified cuckoo search: a new gradient free optimisation algorithm",
 * Chaos, Solitons & Fractals 44 (2011) 710-718), from its description.
 *
 * Population 10 x the degrees of freedom. Each generation G sorts the nests;
 * the worst 75% are abandoned and replaced by a Levy flight from themselves
 * with step A / sqrt(G); each of the best 25% (the elite) picks another elite
 * nest at random: if it picked itself it lays an egg by a Levy flight of step
 * A / G^2, else the egg lies on the line between the two, 1/phi of the way
 * from the worse to the better (phi the golden ratio); the egg replaces a
 * random nest only when it is better, so an elite nest is replaced only on
 * improvement. Levy steps come from Mantegna's algorithm (beta = 1.5).
 * Randomness comes only from the stream r, so a run is reproducible.
 */
#include <math.h>
#include <string.h>

#include "optimise.h"

#define NEST_MAX (10 * CVM__DOPT_MAXDOF)
#define A_POS 0.2     /* initial spread and step scale, units of the local size */
#define A_W 0.1       /* the same for the weight, units of its square */
#define PHI 1.6180339887498949

typedef struct nest {
    double x[CVM__DOPT_MAXDOF];
    double f;
} nest;

static void levy_from(cvm__dopt_local *L, cvm__rng *r, const nest *from, double a, const double *scale,
                      nest *out)
{
    int d;
    for (d = 0; d < L->ndof; d++)
        out->x[d] = from->x[d] + a * scale[d] * cvm__rng_levy(r);
    out->f = cvm__dopt_eval(L, out->x);
}

void cvm__dopt_cuckoo(cvm__dopt_local *L, int budget, cvm__rng *r, double f0, double *u, double *f)
{
    nest ns[NEST_MAX];
    int order[NEST_MAX], n = 10 * L->ndof, ntop = (n + 2) / 4, i, d, best = 0;
    double scale[CVM__DOPT_MAXDOF];
    size_t start = L->evals;
    long G = 1;
    for (d = 0; d < L->ndof; d++)
        scale[d] = d == L->ndof - 1 ? A_W : A_POS;
    memset(ns, 0, sizeof ns);
    ns[0].f = f0;
    for (i = 1; i < n; i++) {
        for (d = 0; d < L->ndof; d++)
            ns[i].x[d] = scale[d] * (2.0 * cvm__rng_uniform(r) - 1.0);
        ns[i].f = cvm__dopt_eval(L, ns[i].x);
    }
    while (L->evals - start < (size_t)budget) {
        cvm__order_small(&ns[0].f, sizeof ns[0], order, n);
        for (i = ntop; i < n && L->evals - start < (size_t)budget; i++) {
            nest egg;
            levy_from(L, r, &ns[order[i]], 1.0 / sqrt((double)G), scale, &egg);
            ns[order[i]] = egg;
        }
        for (i = 0; i < ntop && L->evals - start < (size_t)budget; i++) {
            int j = (int)cvm__rng_below(r, (uint64_t)ntop), l;
            nest egg;
            const nest *ni = &ns[order[i]], *nj = &ns[order[j]];
            if (j == i) {
                levy_from(L, r, ni, 1.0 / ((double)G * (double)G), scale, &egg);
            } else {
                const nest *worse = ni->f > nj->f ? ni : nj, *better = ni->f > nj->f ? nj : ni;
                for (d = 0; d < L->ndof; d++)
                    egg.x[d] = worse->x[d] + (better->x[d] - worse->x[d]) / PHI;
                egg.f = cvm__dopt_eval(L, egg.x);
            }
            l = (int)cvm__rng_below(r, (uint64_t)n);
            if (egg.f < ns[l].f)
                ns[l] = egg;
        }
        G++;
    }
    for (i = 1; i < n; i++)
        if (ns[i].f < ns[best].f)
            best = i;
    memcpy(u, ns[best].x, (size_t)L->ndof * sizeof *u);
    *f = ns[best].f;
}
