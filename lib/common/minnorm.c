/* minnorm.c - the search direction of max-min angle optimisation (Freitag and Ollivier): the smallest-norm point of the convex hull of the active gradients, shared by the refiners' smoothing and the dual optimiser. */
#include <math.h>

#include "common_internal.h"

int cvm__minnorm_hull(const double *g, int nd, const size_t *act, size_t na, double *d)
{
    size_t i, j, l;
    double best = HUGE_VAL;
    int found = 0, q;
    for (i = 0; i < na; i++)
        for (j = i; j < na; j++) {
            const double *gi = g + (size_t)nd * act[i], *gj = g + (size_t)nd * act[j];
            double e[2] = {0, 0}, c[2] = {0, 0}, ee = 0, t = 0, cc = 0;
            int ok = 1;
            for (q = 0; q < nd; q++) {
                e[q] = gj[q] - gi[q];
                ee += e[q] * e[q];
            }
            if (j > i) {
                double ge = 0;
                if (!(ee > 0))
                    continue; /* the same point as vertex i */
                for (q = 0; q < nd; q++)
                    ge += gi[q] * e[q];
                t = -ge / ee;
                if (!(t > 0 && t < 1))
                    continue; /* the vertices are candidates of their own */
            }
            for (q = 0; q < nd; q++) {
                c[q] = gi[q] + t * e[q];
                cc += c[q] * c[q];
            }
            if (!(cc < best) || !(cc > 0))
                continue;
            for (l = 0; l < na && ok; l++) {
                const double *gl = g + (size_t)nd * act[l];
                double dot = 0;
                for (q = 0; q < nd; q++)
                    dot += gl[q] * c[q];
                ok = dot >= cc * (1 - 1e-9);
            }
            if (!ok)
                continue;
            best = cc;
            for (q = 0; q < nd; q++)
                d[q] = c[q];
            found = 1;
        }
    return found;
}
