/*
 * g3_surface.h - the state shared by g3_facets.c (coplanar facets and their
 * boundary loops) and g3_surface.c (their re-meshing), private to lib/generate3.
 */
#ifndef CVM_G3_SURFACE_H
#define CVM_G3_SURFACE_H

#include "generate3/generate3.h"


/* An input edge on a facet boundary: its points (lo < hi) and its split
 * parameters sp[soff .. soff + ns - 1] (ascending). */
typedef struct g3s_edge {
    int32_t lo, hi;
    size_t soff, ns;
    int both;      /* both sides re-meshed: the only edges that may take points */
} g3s_edge;

/* A split parameter waiting for the next round. */
typedef struct g3s_split {
    int32_t e;
    double t;
} g3s_split;

typedef struct g3s_frame {
    int ax, u, v;
    double n[3];
    const double *a;
} g3s_frame;

typedef struct g3s_size_payload {
    const cvm__g3_size *z;
    const g3s_frame *fr;
} g3s_size_payload;

typedef struct g3s_state {
    cvm__ctx *ctx;
    const cvm__g3_surface *s;
    const cvm__g3_size *z;
    int32_t *nbr;      /* 3 nt: triangle across edge j (from corner j+1 to j+2), -1 if not 2-manifold */
    int32_t *fac;      /* nt: facet of each triangle */
    int32_t *fseed;    /* nf: first triangle */
    int32_t *fcount;   /* nf */
    unsigned char *fremesh;
    size_t nf;
    g3s_edge *edge;    /* sorted by (lo, hi) */
    size_t ne;
    double *sp;        /* split parameters */
    size_t nsp;
    int32_t demote;    /* a re-meshed facet whose refiner split an edge of a kept
                          triangle: it is meshed again without refinement */
    g3s_split *pend;
    size_t npend, cap_pend;
    int32_t *loop;     /* scratch: a facet's boundary as directed edges (3 t + j) */
    size_t cap_loop;
    double *bxy;       /* scratch: 2D points of the loop */
    int32_t *bid, *bseg_e; /* point of each loop point; input edge of each loop segment */
    double *bt0, *bt1; /* parameters (canonical) at a segment's ends; -1 at corners */
    int32_t *bseg;
    size_t cap_b;
    /* output */
    double *xyz;
    size_t np, cap_xyz;
    int32_t *tri, *tsrc;
    size_t nt, cap_tri, cap_tsrc;
} g3s_state;

/* ---- g3_facets.c ---- */
int32_t cvm__g3s_find_edge(const g3s_state *S, int32_t a, int32_t b);
/* The triangle across every edge (S->nbr; -1 unless the edge has exactly two). */
cvm_status cvm__g3s_neighbours(g3s_state *S);
/* The projection frame of triangle t's plane. */
void cvm__g3s_frame(const g3s_state *S, int32_t t, g3s_frame *fr);
/* Facets of coplanar triangles of equal key (S->fac, fseed, fcount, nf). */
cvm_status cvm__g3s_group(g3s_state *S, const int32_t *key);
/* Facet f's boundary as directed edges in loop order into S->loop (*n of
 * them); 0 when it is not one simple loop or a triangle of it is degenerate
 * in the facet's projection. */
int cvm__g3s_loop(g3s_state *S, int32_t f, const int32_t *members, size_t nm, size_t *n);
/* Triangles sorted by facet: facet f owns items[start[f] .. start[f+1]-1]. */
cvm_status cvm__g3s_members(g3s_state *S, int32_t **start_out, int32_t **items_out);

#endif
