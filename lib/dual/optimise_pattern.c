/* optimise_pattern.c - the deterministic local solver of the dual optimiser: compass (pattern) search. */
#include <string.h>

#include "optimise.h"

/* Initial and final step, in units of the local size (positions) and of its
 * square (weights). */
#define STEP0_POS 0.1
#define STEP0_W 0.05
#define STEP_MIN 1e-3

void cvm__dopt_pattern(cvm__dopt_local *L, int budget, double f0, double *u, double *f)
{
    double x[CVM__DOPT_MAXDOF] = {0}, scale[CVM__DOPT_MAXDOF], fx = f0, step = 1.0;
    size_t start = L->evals;
    int d, n = L->ndof;
    for (d = 0; d < n; d++)
        scale[d] = d == n - 1 ? STEP0_W : STEP0_POS; /* the weight is the last degree of freedom */
    while (L->evals - start < (size_t)budget && step > STEP_MIN) {
        int improved = 0;
        for (d = 0; d < n && L->evals - start < (size_t)budget; d++) {
            int sgn;
            for (sgn = 1; sgn >= -1; sgn -= 2) {
                double y[CVM__DOPT_MAXDOF], fy;
                memcpy(y, x, sizeof y);
                y[d] += sgn * step * scale[d];
                fy = cvm__dopt_eval_below(L, y, fx); /* only "below fx?" matters */
                if (fy < fx) {
                    memcpy(x, y, sizeof x);
                    fx = fy;
                    improved = 1;
                    break;
                }
            }
        }
        step = improved ? (step * 1.5 > 2.0 ? 2.0 : step * 1.5) : step * 0.5;
    }
    memcpy(u, x, (size_t)n * sizeof *u);
    *f = fx;
}
