/*
 * sizing_internal.h - the sizing engine: the cvm_sizing handle (uniform,
 * point, line, triangle, callback, automatic, background and boundary-grading
 * sources, in 2D or 3D: one dimension per handle) and its evaluation at a
 * point. Refinement, dual optimisation, the boundary resampler and 3D
 * generation read sizes through it; it knows nothing of them.
 *
 * Nothing here decides topology: a size only chooses which valid mesh a
 * meshing algorithm produces.
 */
#ifndef CVM_SIZING_INTERNAL_H
#define CVM_SIZING_INTERNAL_H

#include <stddef.h>
#include <stdint.h>
#include "common/common_internal.h"
#include "delaunay/delaunay_internal.h"

/* Positional sources; a 2D source has z = 0 (and is evaluated in the plane). */
typedef struct cvm__point_source {
    double x, y, h, growth;
    double z;
} cvm__point_source;

typedef struct cvm__line_source {
    double x0, y0, x1, y1, h, growth;
    double z0, z1;
} cvm__line_source;

typedef struct cvm__tri_source {
    double p[9]; /* the three corners, x y z each (z = 0 in 2D) */
    double h, growth;
} cvm__tri_source;

/* The layout of a uniform grid of square cells over a box (grid.c): origin,
 * cell side and counts only. Its users (the automatic and background sizing
 * fields) bucket static items into its cells themselves, in offset arrays
 * built once; compare cvm__vertex_grid, which stores a changing vertex set. */
typedef struct cvm__cell_grid {
    double x0, y0, cs;    /* origin and cell side */
    int nx, ny;
} cvm__cell_grid;

/* Fit about n cells (at least 1, at most 2048 a side) over the box
 * [xmin, xmax] x [ymin, ymax]; a flat or empty box still gets cells. */
void cvm__cell_grid_fit(cvm__cell_grid *g, double xmin, double ymin, double xmax, double ymax, size_t n);
/* Cell (i, j) of (x, y), clamped into the grid. */
void cvm__cell_grid_cell(const cvm__cell_grid *g, double x, double y, int *i, int *j);
/* The cells item k covers, for cvm__cell_grid_bucket(): (i, j) with i0 <= i <= i1,
 * j0 <= j <= j1. */
typedef void (*cvm__cell_range_fn)(const void *payload, size_t k, int *i0, int *j0, int *i1,
                                   int *j1);
/* Bucket items 0..n-1 into the cells of g as offsets: the items of cell
 * c = j nx + i are (*items)[(*start)[c] .. (*start)[c + 1] - 1], in increasing
 * k. *start and *items are set as soon as they are allocated, so the caller
 * frees them on any status. CVM_E_NOMEM, or CVM_E_TOO_LARGE when the
 * offsets pass INT32_MAX. */
cvm_status cvm__cell_grid_bucket(cvm__ctx *ctx, const cvm__cell_grid *g, size_t n,
                                 cvm__cell_range_fn range, const void *payload, int32_t **start,
                                 int32_t **items);

/* The automatic length scale (sizing_auto.c), built per refinement from the
 * domain: samples (x, y, LS) on the boundary in a uniform grid; the size at a
 * point is the least LS + distance / G over the samples. */
typedef struct cvm__auto_field {
    double *smp;          /* 3 per sample: x, y, LS */
    size_t ns;
    double G, ls_min;
    cvm__cell_grid g;
    int32_t *start;       /* g.nx * g.ny + 1 offsets into items */
    int32_t *items;       /* sample indices by cell */
    double *cmin;         /* least LS per cell */
} cvm__auto_field;

/* Sizes on a background triangulation (sizing_background.c), interpolated
 * linearly inside its triangles, no bound outside them. */
typedef struct cvm__background {
    double *xy, *h;       /* 2 and 1 per node */
    int32_t *tri;         /* 3 per triangle, counter-clockwise */
    size_t np, nt;
    cvm__cell_grid g;         /* grid of triangles by bounding box */
    int32_t *start, *items;
} cvm__background;

/* Parameters of a built-in metric field (lib/quad: cvm__metric_builtin_fn), kept in the
 * handle by cvm_sizing_set_metric_builtin() and cvm_sizing_set_metric_constant(). */
typedef struct cvm__metric_params {
    int kind;     /* a cvm__metric_kind of lib/quad */
    double scale;
    double g[3];  /* the constant tensor */
} cvm__metric_params;

struct cvm_sizing {
    cvm__ctx ctx;
    int has_uniform;
    double uniform;
    cvm__point_source *pts;
    size_t npts, cap_pts;
    cvm__line_source *lines;
    size_t nlines, cap_lines;
    cvm__tri_source *tris;
    size_t ntris, cap_tris;
    int dim;              /* 2 or 3: the dimension of the positional sources; 0: none yet */
    struct cvm__background3 *bg3; /* NULL, or cvm_sizing_set_background_nd() in 3D */
    cvm_sizing_fn fn;     /* the user function: at most one of fn, fn_nd, fn_batch */
    cvm_sizing_nd_fn fn_nd;
    cvm_sizing_batch_fn fn_batch;
    void *fn_payload;
    cvm_metric_fn metric; /* cvm_sizing_set_metric_fn(); no refiner reads it yet */
    void *metric_payload;
    int metric_has_dg;
    cvm__metric_params metric_own; /* the payload of a built-in metric the handle owns */
    int has_auto;         /* cvm_sizing_set_automatic() */
    double auto_R, auto_G;
    cvm__background *bg;  /* NULL, or cvm_sizing_set_background() */
    double bgrad;         /* > 0: cvm_sizing_set_boundary_grading() slope */
    /* set only on the private copy a refinement or optimisation evaluates: */
    const cvm__auto_field *autof;
    const cvm__auto_field *spacingf; /* the boundary-spacing field (bgrad) */
};

/* Build the automatic field of the domain triangles of T (features: domain
 * boundary and constrained edges, and the vertices flagged in is_input that
 * lie on none; is_input NULL: every vertex). CVM_OK or CVM_E_NOMEM (recorded
 * on ctx; F is then empty). */
cvm_status cvm__auto_field_build(cvm__auto_field *F, const cvm__tri2 *T, const uint8_t *is_input,
                                 double R, double G, cvm__ctx *ctx);
void cvm__auto_field_free(cvm__auto_field *F, cvm__ctx *ctx);
/* The boundary-spacing field of cvm_sizing_set_boundary_grading(): samples
 * on the domain boundary and constrained edges of T with LS = the local edge
 * length, slope g (> 0). CVM_OK or CVM_E_NOMEM (recorded on ctx; F empty). */
cvm_status cvm__spacing_field_build(cvm__auto_field *F, const cvm__tri2 *T, double g,
                                    cvm__ctx *ctx);
/* Size at (x, y) when it is below bound (else bound; bound without samples):
 * the search stops as soon as no sample can beat it, so a small bound makes it cheap. */
double cvm__auto_field_below(const cvm__auto_field *F, double x, double y, double bound);
/* Size of the background mesh at (x, y): the least linear interpolant over
 * the triangles containing it, +inf outside them. */
double cvm__background_at(const cvm__background *bg, double x, double y);
void cvm__background_free(cvm__background *bg, cvm__ctx *ctx);

/* 1 when s is NULL or has no source (no size bound). */
int cvm__sizing_is_empty(const cvm_sizing *s);

/* Add a positional source of dimension dim (2 or 3) to s, checked as the
 * public calls document (the message names the source); atomic (sizing.c). */
cvm_status cvm__sizing_add_point(cvm_sizing *s, const double *x, int dim, double h, double growth);
cvm_status cvm__sizing_add_line(cvm_sizing *s, const double *ends, int dim, double h,
                                double growth);
cvm_status cvm__sizing_add_tri(cvm_sizing *s, const double *corners, int dim, double h,
                               double growth);
/* Forget the dimension of s when it has no positional source left. */
void cvm__sizing_recount_dim(cvm_sizing *s);

/* Distance from p to the triangle t (9 doubles; a degenerate one is the
 * union of its edges), and from p to the segment a-b, in 3D (sizing.c). */
double cvm__dist_point_tri3(const double *p, const double *t);
double cvm__dist_point_seg3(const double *p, const double *a, const double *b);

/* Record on s an error when its positional sources are of a dimension other
 * than dim (CVM_E_ARGUMENT naming the first source), else CVM_OK. */
cvm_status cvm__sizing_check_dim(cvm_sizing *s, int dim, const char *call);

/* Size at the 3D point x into *h (+infinity without sources) from the
 * positional 3D sources, uniform size, 3D background and the _nd callback;
 * errors as cvm__sizing_at. The handle's sources must be 3D (or none) and
 * its callback, if any, the _nd one (cvm__sizing_check3 says so). */
cvm_status cvm__sizing_at3(const cvm_sizing *s, const double *x, double *h, cvm__ctx *err);
/* CVM_OK when s can be evaluated in 3D; else the status, with a message on
 * err naming what is 2D-only (a 2D source, a 2D callback; with meshing, also
 * the automatic field and a metric, which no 3D mesher reads). */
cvm_status cvm__sizing_check3(const cvm_sizing *s, cvm__ctx *err, const char *call, int meshing);
/* The least size the 3D sources can give (uniform, point, line, triangle and
 * background sizes), +infinity when none; a callback is not bounded. */
double cvm__sizing_min3(const cvm_sizing *s);
/* Boxes (6 doubles each: lo xyz, hi xyz) outside which no 3D source gives a
 * size <= a; an unbounded box (+-infinity) where a source can reach a anywhere
 * (a uniform size <= a, a zero growth, a callback). Writes them to box unless
 * it is NULL; returns their count, at most CVM__SIZING_MAX_BOXES3(s). */
#define CVM__SIZING_MAX_BOXES3(s) ((s)->npts + (s)->nlines + (s)->ntris + 2)
size_t cvm__sizing_boxes3(const cvm_sizing *s, double a, double *box);

/* Sizes at the nodes of a background tetrahedral mesh (sizing_background3.c). */
typedef struct cvm__background3 cvm__background3;
/* Check and install (replacing s->bg3) npoints nodes xyzh (x, y, z, h) and
 * ntet tetrahedra; errors name the node or tetrahedron, and leave s as it was. */
cvm_status cvm__background3_set(cvm_sizing *s, const double *xyzh, size_t npoints,
                                const cvm_index *tet, size_t ntet);
void cvm__background3_free(cvm__background3 *bg, cvm__ctx *ctx);
double cvm__background3_at(const cvm__background3 *bg, const double *x);
double cvm__background3_min(const cvm__background3 *bg);
void cvm__background3_box(const cvm__background3 *bg, double *lo, double *hi);

/* 1 when s has a metric source (sizing_nd.c). */
int cvm__sizing_has_metric(const cvm_sizing *s);

/* Size at (x, y) into *h (+infinity without sources). A bad callback value
 * records an error naming the callback and the position on err and returns
 * CVM_E_INPUT_NONFINITE or CVM_E_ARGUMENT. */
cvm_status cvm__sizing_at(const cvm_sizing *s, double x, double y, double *h, cvm__ctx *err);

/* Sizes at the n points xy (2n doubles) into h[0..n-1]: cvm__sizing_at point
 * by point, but a batch callback is asked for CVM__SIZING_BATCH points per
 * call. Same values and errors as n calls of cvm__sizing_at. */
#define CVM__SIZING_BATCH 1024
cvm_status cvm__sizing_at_many(const cvm_sizing *s, const double *xy, size_t n, double *h,
                               cvm__ctx *err);

/* A cvm_sizing's domain-dependent parts (automatic length scale, boundary
 * spacing), built from a triangulation for one refinement or optimisation
 * (sizing_fields.c). */
typedef struct cvm__sizing_fields {
    cvm__auto_field autof;   /* cvm_sizing_set_automatic() */
    cvm__auto_field spacing; /* cvm_sizing_set_boundary_grading() */
    cvm_sizing local;        /* the caller's handle with both fields attached */
} cvm__sizing_fields;

/* 1 when sizing asks for a field that needs the domain (automatic or
 * boundary grading). */
int cvm__sizing_needs_fields(const cvm_sizing *sizing);
/* Build the fields sizing asks for from the domain triangles of T (is_input
 * as for cvm__auto_field_build; read only for the automatic field); *use is
 * the handle to evaluate (sizing itself when it asks for none). On error
 * (CVM_E_NOMEM, recorded on ctx) nothing is left to free. Pair with
 * cvm__sizing_fields_free(). */
cvm_status cvm__sizing_fields_build(cvm__sizing_fields *F, const cvm_sizing **use,
                                    const cvm_sizing *sizing, const cvm__tri2 *T,
                                    const uint8_t *is_input, cvm__ctx *ctx);
void cvm__sizing_fields_free(cvm__sizing_fields *F, cvm__ctx *ctx);

#endif
