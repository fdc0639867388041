/*
 * d3_internal.h - shared between the files of lib/dual3 (see dual3.h).
 */
#ifndef CVM_DUAL3_INTERNAL_H
#define CVM_DUAL3_INTERNAL_H

#include "dual3/dual3.h"

typedef struct cvm__d3_work {
    const cvm__d3_mesh *M;
    const cvm__d3_params *p;
    int32_t *voff;   /* nv + 1: CSR offsets of each vertex's tetrahedra */
    int32_t *vtet;   /* 4 ntet: tetrahedron indices */
    uint8_t *fixpos; /* nv: 1 when the vertex lies on a constrained face */
    uint8_t *out;    /* ntet: 1 when the power vertex lies strictly outside (exact) */
    uint8_t *bnd;    /* ntet: 1 when a face has no neighbour */
    double *lv;      /* nv: mean length of the vertex's edges (counted per tetrahedron) */
    uint8_t *slide;  /* nv: for a vertex on a constrained face, the axes it may move along */
    uint8_t *stuck;  /* nv: 1 when the last search from v failed and nothing near v moved since */
    size_t nout;     /* sum of out */
} cvm__d3_work;

/* The penalty of one tetrahedron (dual3.h); HUGE_VAL when it is flat or
 * inverted in floating point. dist_out (may be NULL): |centroid - power vertex|. */
double cvm__d3_tet_penalty(const double *const P[4], const double W[4], double margin,
                           double *dist_out);
/* The summed penalty of v's star with v at (x, wv); the sum is cut short once it
 * reaches stop (HUGE_VAL: the full sum). */
double cvm__d3_star_penalty(const cvm__d3_work *K, int32_t v, const double *x, double wv,
                            double stop);
/* The cosine of the smallest dihedral angle of v's star with v at x (2 when a
 * tetrahedron is flat). */
double cvm__d3_star_max_cos(const cvm__d3_work *K, int32_t v, const double *x);
/* 1 when v may move to (x, wv): the exact checks of dual3.h (orientation,
 * local regularity, non-compliant count of the star). */
int cvm__d3_star_valid(const cvm__d3_work *K, int32_t v, const double *x, double wv);
/* 1 when face f of tetrahedron t is locally regular or constrained (exact). */
int cvm__d3_face_regular(const cvm__d3_mesh *M, size_t t, int f);

#endif
