/*
 * g3_remesh.h - the state shared by g3_remesh.c (the half-edge store and its
 * passes) and g3_remesh_field.c (features, patches, target sizes and the
 * projection onto the input), private to lib/generate3.
 */
#ifndef CVM_G3_REMESH_H
#define CVM_G3_REMESH_H

#include <math.h>

#include "generate3/generate3.h"

/* Radians of normal turn per target edge length. */
#define G3R_TURN 0.5

/* Vertex classes. */
enum { G3R_FREE = 0, G3R_LINE = 1, G3R_FIXED = 2 };

typedef struct g3r_state {
    cvm__ctx *ctx;
    int ok;              /* 0: the input is no closed oriented 2-manifold; kept as given */
    /* the current surface */
    double *x;           /* 3 nv */
    double *L;           /* nv target edge lengths */
    unsigned char *vflag; /* G3R_* */
    int32_t *vpatch;     /* smooth patch of a free vertex, else -1 */
    int32_t *vhe;        /* a half-edge leaving each vertex; -1 for a removed vertex */
    size_t nv, cap_v, cap_x;
    int32_t *tv;         /* 3 nt; tv[3 t] = -1 for a removed triangle */
    int32_t *opp;        /* 3 nt twin half-edges */
    unsigned char *feat; /* 3 nt: 1 on feature edges (both halves) */
    int32_t *tsrc;       /* nt: the input triangle each one comes from */
    size_t nt, cap_t, cap_h;
    int32_t *ring;       /* scratch: half-edges around a vertex */
    size_t cap_ring;
    /* the input, for projections */
    const cvm__g3_surface *in;
    int32_t *ipatch;     /* per input triangle: its smooth patch */
    int32_t *iopp;       /* the input's twin half-edges */
    unsigned char *ifeat; /* the input's feature half-edges */
    double *iL;          /* per input vertex: target size */
    /* projection grid over the input triangles: (cell key, triangle) sorted by key */
    uint64_t *gkey;
    int32_t *gtri;
    size_t ng;
    double glo[3], gcell;
    int gdim[3];
    /* counters */
    size_t splits, collapses, flips, moves;
} g3r_state;

/* ---- geometry and store accessors ---- */
static inline double g3r_dist(const double *a, const double *b)
{
    double d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

static inline void g3r_normal(const double *a, const double *b, const double *c, double *n)
{
    double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    n[0] = u[1] * v[2] - u[2] * v[1];
    n[1] = u[2] * v[0] - u[0] * v[2];
    n[2] = u[0] * v[1] - u[1] * v[0];
}

static inline double g3r_unit(double *n)
{
    double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (l > 0) {
        n[0] /= l;
        n[1] /= l;
        n[2] /= l;
    }
    return l;
}

/* ---- the half-edge store ---- */
#define G3R_T(h) ((h) / 3)
#define G3R_NEXT(h) (3 * ((h) / 3) + ((h) % 3 + 1) % 3)
#define G3R_PREV(h) (3 * ((h) / 3) + ((h) % 3 + 2) % 3)

/* Half-edge h = 3 t + k of triangle t goes from corner k+1 to corner k+2. */
static inline int32_t g3r_org(const g3r_state *R, int32_t h) { return R->tv[G3R_NEXT(h)]; }
static inline int32_t g3r_dst(const g3r_state *R, int32_t h) { return R->tv[G3R_PREV(h)]; }
static inline int32_t g3r_apex(const g3r_state *R, int32_t h) { return R->tv[h]; }

static inline const double *g3r_x(const g3r_state *R, int32_t v) { return R->x + 3 * (size_t)v; }


/* ---- g3_remesh_store.c ---- */
/* Room for nv vertices and nt triangles (CVM_E_NOMEM). */
cvm_status cvm__g3r_room(g3r_state *R, size_t nv, size_t nt);
/* Make half-edges a and b twins. */
void cvm__g3r_link(g3r_state *R, int32_t a, int32_t b);
/* Triangle t = (p0, p1, p2) from input triangle src: its half-edges 0, 1, 2 go
 * p1->p2, p2->p0, p0->p1; each vertex's half-edge is set to one of t's. */
void cvm__g3r_set(g3r_state *R, int32_t t, int32_t p0, int32_t p1, int32_t p2, int32_t src);
/* The feature flag of half-edge h and its twin. */
void cvm__g3r_setf(g3r_state *R, int32_t h, unsigned char f);
/* The half-edges leaving v, in turning order, into R->ring (*n); 0 when they
 * do not fit in R->cap_ring. */
int cvm__g3r_ring(g3r_state *R, int32_t v, size_t *n);
/* The store from the input surface: triangles, twins, feature edges. R->ok = 0
 * when an edge is not shared by exactly two oppositely oriented triangles. */
cvm_status cvm__g3r_build(g3r_state *R, const cvm__g3_surface *s, const int32_t *key);
/* Sort n pairs by their non-negative key, ties in their order (stable); CVM_E_NOMEM
 * (recorded on ctx) leaves them in an unspecified order. */
cvm_status cvm__g3r_sort_pairs(cvm__ctx *ctx, int64_t *key, int32_t *val, size_t n);

/* ---- g3_remesh_field.c ---- */
/* Vertex classes, smooth patches, the target sizes of the input's vertices
 * (R->iL, copied into R->L) and the projection grid. CVM_E_NOMEM, or a user
 * sizing's status. */
cvm_status cvm__g3r_field(g3r_state *R, const cvm__g3_params *p);
/* The point of patch `patch` of the input nearest to x within radius r into
 * y, with the target size there into *L; 0 when none lies within r. */
int cvm__g3r_project(const g3r_state *R, int32_t patch, const double *x, double r, double *y,
                     double *L);
void cvm__g3r_free(g3r_state *R);

#endif
