/*
 * d3_cuckoo.c - the stochastic per-vertex search of the 3D power-dual
 * optimiser: Modified Cuckoo Search (Walton, Hassan, Morgan, Brown, Chaos,
 * Solitons & Fractals 44 (2011) 710-718), from its description, over the
 * degrees of freedom of one vertex (its free coordinates and its weight).
 *
 * Population 10 x the degrees of freedom (40 for an interior vertex). Each
 * generation G sorts the nests by fitness (the fixed star's penalty; HUGE_VAL
 * when a tetrahedron is flat or inverted in floating point or a dihedral angle
 * drops below the floor); the worst 75 % are replaced by a Levy flight from
 * themselves of step A / sqrt(G); each of the best 25 % picks another at random
 * and lays an egg 1/phi of the way from the worse to the better (a Levy flight
 * of step A / G^2 when it picked itself), which replaces a random nest only
 * when better. Levy steps by Mantegna's algorithm (beta 1.5). The stream is
 * keyed by (seed, sweep, vertex): the result depends only on the mesh and
 * the parameters. The caller applies the best nests through the exact checks.
 */
#include <math.h>
#include <string.h>

#include "dual3/d3_internal.h"

#define D3C_A_POS 0.2 /* initial spread and step scale, x the mean edge at v */
#define D3C_A_W 0.1   /* the same for the weight, x its square */
#define D3C_PHI 1.6180339887498949

typedef struct d3c_ctx {
    const cvm__d3_work *K;
    int32_t v;
    const double *x0; /* v's current (x, y, z, w) */
    int ndof, axis[4]; /* axis[d]: 0-2 a coordinate, 3 the weight */
    double scale[4];
    double cfloor;
    size_t evals;
} d3c_ctx;

static void d3c_point(const d3c_ctx *C, const double *u, double *cand)
{
    int d;
    memcpy(cand, C->x0, 4 * sizeof *cand);
    for (d = 0; d < C->ndof; d++)
        cand[C->axis[d]] += u[d];
}

static double d3c_eval(d3c_ctx *C, const double *u)
{
    double cand[4], f;
    C->evals++;
    d3c_point(C, u, cand);
    f = cvm__d3_star_penalty(C->K, C->v, cand, cand[3], HUGE_VAL);
    if (f < HUGE_VAL && C->ndof > 1 && cvm__d3_star_max_cos(C->K, C->v, cand) > C->cfloor)
        return HUGE_VAL;
    return f;
}

static void d3c_levy_from(d3c_ctx *C, cvm__rng *r, const cvm__d3_nest *from, double a,
                          cvm__d3_nest *out)
{
    int d;
    for (d = 0; d < C->ndof; d++)
        out->u[d] = from->u[d] + a * C->scale[d] * cvm__rng_levy(r);
    out->f = d3c_eval(C, out->u);
}

int cvm__d3_cuckoo(const cvm__d3_work *K, int32_t v, const double *cur, double cfloor,
                   int budget, uint64_t key, cvm__d3_nest *ns, int *order)
{
    d3c_ctx C;
    cvm__rng r;
    int n, ntop, i, d, a;
    long G = 1;
    memset(&C, 0, sizeof C);
    C.K = K, C.v = v, C.x0 = cur, C.cfloor = cfloor;
    for (a = 0; a < 3; a++)
        if (!K->fixpos[v] || (K->slide[v] >> a & 1))
            C.axis[C.ndof] = a, C.scale[C.ndof++] = D3C_A_POS * K->lv[v];
    C.axis[C.ndof] = 3, C.scale[C.ndof++] = D3C_A_W * K->lv[v] * K->lv[v];
    n = 10 * C.ndof;
    ntop = (n + 2) / 4;
    cvm__rng_seed(&r, key);
    memset(ns, 0, (size_t)n * sizeof *ns);
    ns[0].f = cvm__d3_star_penalty(K, v, cur, cur[3], HUGE_VAL);
    for (i = 1; i < n; i++) {
        for (d = 0; d < C.ndof; d++)
            ns[i].u[d] = C.scale[d] * (2.0 * cvm__rng_uniform(&r) - 1.0);
        ns[i].f = d3c_eval(&C, ns[i].u);
    }
    while (C.evals < (size_t)budget) {
        cvm__order_small(&ns[0].f, sizeof ns[0], order, n);
        for (i = ntop; i < n && C.evals < (size_t)budget; i++) {
            cvm__d3_nest egg;
            d3c_levy_from(&C, &r, &ns[order[i]], 1.0 / sqrt((double)G), &egg);
            ns[order[i]] = egg;
        }
        for (i = 0; i < ntop && C.evals < (size_t)budget; i++) {
            int j = (int)cvm__rng_below(&r, (uint64_t)ntop), l;
            cvm__d3_nest egg;
            const cvm__d3_nest *ni = &ns[order[i]], *nj = &ns[order[j]];
            if (j == i) {
                d3c_levy_from(&C, &r, ni, 1.0 / ((double)G * (double)G), &egg);
            } else {
                const cvm__d3_nest *worse = ni->f > nj->f ? ni : nj;
                const cvm__d3_nest *better = ni->f > nj->f ? nj : ni;
                for (d = 0; d < C.ndof; d++)
                    egg.u[d] = worse->u[d] + (better->u[d] - worse->u[d]) / D3C_PHI;
                egg.f = d3c_eval(&C, egg.u);
            }
            l = (int)cvm__rng_below(&r, (uint64_t)n);
            if (egg.f < ns[l].f)
                ns[l] = egg;
        }
        G++;
    }
    cvm__order_small(&ns[0].f, sizeof ns[0], order, n);
    for (i = 0; i < n; i++) /* the nests as points, best first */
        d3c_point(&C, ns[i].u, ns[i].x);
    return n;
}
