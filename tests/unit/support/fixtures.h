/*
 * fixtures.h - small inputs shared by the unit tests: planar straight-line
 * graphs with known area and Euler characteristic, and a deterministic
 * point generator independent of the library's RNG.
 */
#ifndef CVMTEST_FIXTURES_H
#define CVMTEST_FIXTURES_H

#include <stddef.h>
#include <stdint.h>
#include "cvmesh.h"

typedef struct cvmtest_pslg {
    const char *name;
    const double *xy;      /* 2*np */
    size_t np;
    const cvm_index *seg;  /* 2*nseg */
    size_t nseg;
    const double *holes;   /* 2*nholes */
    size_t nholes;
    double area;           /* area of the domain */
    long euler;            /* V - E + F of any triangulation of the domain */
} cvmtest_pslg;

/* [0,3]^2 with the square hole [1,2]^2: 8 points, 8 segments, 1 hole; area 8, Euler 0. */
extern const cvmtest_pslg cvmtest_square_with_hole;
/* [0,1]^2 with its 4 sides as segments; area 1, Euler 1. */
extern const cvmtest_pslg cvmtest_unit_square;

/* The square [0,n]^2 with an n x n grid of square holes, hole (i, j) being
 * [i+1/4, i+3/4] x [j+1/4, j+3/4] with its hole point at the centre (as
 * tests/bench/hole_grid.py writes it): 4 + 4n^2 points, as many segments
 * (the outer square first), n^2 holes; area 3n^2/4, Euler 1 - n^2. Every
 * coordinate is exact. NULL when out of memory; free with cvmtest_pslg_free(). */
cvmtest_pslg *cvmtest_hole_grid(size_t n);
void cvmtest_pslg_free(cvmtest_pslg *p);

/* Set points, segments and holes of p on m; returns the first non-OK status. */
cvm_status cvmtest_pslg_set(cvm_mesh *m, const cvmtest_pslg *p);

/* n points uniform in [0,1)^2 from a splitmix64 stream seeded by seed. */
void cvmtest_random_points(double *xy, size_t n, uint64_t seed);

#endif
