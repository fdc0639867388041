/* resample.h - the state of the boundary resampler shared by its two files: chain planning
 * (resample.c) and the rebuild of the triangulation (resample_rebuild.c). */
#ifndef CVM_BOUNDARY_RESAMPLE_H
#define CVM_BOUNDARY_RESAMPLE_H

#include "boundary_internal.h"

/* An inner vertex of a chain turns by less than this (degrees). */
#define RS_TURN_DEG 30.0
/* A new piece (a chord of the input polyline) replaces an arc turning by at
 * most this in total (degrees). */
#define RS_ARC_TURN_DEG 90.0
/* No other vertex may come closer to a chord than this times its length. */
#define RS_CLOSE 0.1
/* Passes that split chains at failed chords before the last one is taken. */
#define RS_MAX_PASSES 64

typedef struct rs_edge {
    int32_t a, b, seg;
} rs_edge;

typedef struct rs_xv {
    double x;
    int32_t v;
} rs_xv;

typedef struct rs_state {
    const cvm__resample_input *in;
    const cvm__tri2 *T;
    cvm__ctx *ctx;
    const cvm_sizing *sizing;
    size_t nv;
    rs_edge *e;                /* constrained edges with a domain side */
    size_t ne, cap_e;
    size_t *first;             /* nv + 1: start of each vertex's incident edges in inc */
    int32_t *inc;
    unsigned char *inner;      /* per vertex: may be an inner chain vertex */
    unsigned char *removed;    /* per vertex: inner vertex of a re-discretised chain */
    unsigned char *used;       /* per edge: walked into a chain */
    unsigned char *replaced;   /* per edge: part of a re-discretised chain */
    int32_t *stamp;            /* per vertex: chord serial that excludes it from the tests */
    int32_t *cmark;            /* per vertex: serial of the chain it is an inner vertex of */
    int32_t chain_serial;
    rs_xv *byx;                /* vertices sorted by x */
    /* the chain being processed: vertices pv[0..np-1], edges pe[0..np-2] */
    int32_t *pv, *pe;
    size_t np, cap_pv, cap_pe;
    double *cum, *tab, *pos;
    size_t cap_cum, cap_tab, cap_pos;
    double *poly;              /* region polygon scratch, 2 per corner */
    size_t cap_poly;
    /* new points: 2 coordinates; 4 ints: segment id, vertex ends of the edge it lies on, -; fraction */
    double *nxy, *nfrac;
    int32_t *ninfo;
    size_t nnew, cap_nxy, cap_nfrac, cap_ninfo;
    /* new pieces: 3 ints: ends (old vertex v >= 0, or new point k as -2 - k), segment */
    int32_t *pc;
    size_t npc, cap_pc;
    /* inner vertices to turn into corners before the next pass */
    int32_t *split;
    size_t nsplit, cap_split;
    int32_t serial;
} rs_state;

/* Build the triangulation of the re-discretised input (the kept edges and
 * the new pieces of S) into R->T and set R->newid and R->nkept. *fallback = 1
 * when the new pieces do not make a valid constrained triangulation (R then
 * holds nothing to use). CVM_OK, CVM_E_NOMEM or a stop status of the build. */
cvm_status cvm__resample_rebuild(const rs_state *S, cvm__resample_result *R, int *fallback);

#endif
