/*
 * rebuild.h - a triangulation rebuilt from given cells: the triangles (and
 * line cells, weights, attributes) of a mesh file, made into the kernel's
 * constrained regular triangulation of the same points (rebuild.c), after
 * the checks that the cells can be one (rebuild_cells.c).
 *
 * Points become vertices; line cells and boundary edges of the triangles
 * become segments (no line cells: first tried as the Delaunay triangulation
 * of the points). The PSLG is triangulated as cvm__cdt_build() does, regions
 * without a given triangle get hole points, weights are set; when that gives
 * exactly the given triangles, slots are reordered to the cells' order, so
 * writing the result reproduces the file. Otherwise every edge of the cells
 * is constrained, which reproduces them exactly when they are a conforming
 * triangulation (else an error names a triangle); the inner edges but region
 * borders are then released and Lawson flips (cvm__tri2_make_regular) make
 * the mesh constrained Delaunay, or regular with weights.
 */
#ifndef CVM_DELAUNAY_REBUILD_H
#define CVM_DELAUNAY_REBUILD_H

#include "delaunay_internal.h"

/* The cells to rebuild, borrowed for the call. Indices are in range (the
 * reader checked them). */
typedef struct cvm__rebuild_input {
    cvm__cdt_input cdt;    /* the points (markers, attributes) and the options of the
                              triangulation; its segments, holes, regions and keep_hull
                              are not read */
    const int32_t *tri;    /* 3 point indices per triangle */
    size_t nt;
    const int32_t *lines;  /* 2 point indices per line cell */
    const int32_t *lmark;  /* a marker per line cell, or NULL: marker 1 */
    size_t nlines;
    int has_lines;         /* the file has line cells */
    const double *w;       /* a weight per point, or NULL */
    const double *tattr;   /* a regional attribute per triangle, or NULL */
} cvm__rebuild_input;

/* The rebuilt mesh and what the handle needs beside it. Arrays are
 * allocated through ctx and owned here until a caller takes them (and sets
 * the pointer to NULL); cvm__rebuild_free() frees the rest. */
typedef struct cvm__rebuild {
    cvm__ctx *ctx;          /* allocator, message; no progress callback, no time limit */
    cvm__tri2 tri;          /* the triangulation, slots in the cells' order */
    cvm__cdt_out out;       /* input map, markers and attributes of the vertices */
    int32_t *seg, *smark;   /* the segments (seg may hold more than nseg: scratch) */
    int32_t *segtri;        /* scratch: a file triangle on each segment, -1 for a line */
    size_t nseg;            /* segments of the result (0: the Delaunay triangulation of
                               the points, without segments) */
    double *holes;          /* the hole points found, 2 each */
    size_t nholes;
    size_t nflips;          /* flips inside the domain that made the cells (constrained)
                               Delaunay, or regular with weights: 0 when the result holds
                               exactly the file's triangles */
    cvm__cdt_fault fault;   /* an input fault of the triangulation: the message is the
                               caller's (items are segments of seg, points) */
    int rebuilding;         /* 1 when an error arose in the triangulation itself (its
                               message reads "rebuilding the mesh: ..."), 0 in the checks
                               of the cells */
    size_t keep_ids;        /* the forced rebuild: segments below this id (the file's lines
                               and boundary) keep their ids on edges that temporary
                               constraints share with them; 0 otherwise */
} cvm__rebuild;

/* Empty rb, allocating through ctx. */
void cvm__rebuild_init(cvm__rebuild *rb, cvm__ctx *ctx);
/* Free what rb still owns. */
void cvm__rebuild_free(cvm__rebuild *rb);

/* Rebuild the cells of in into rb. CVM_OK; CVM_E_INPUT_EMPTY (no triangle);
 * CVM_E_INPUT_DEGENERATE with a message naming the triangle, line cell, edge
 * or point in the file's numbering (a triangle repeats a point, has two
 * corners at one position or all on a line, a line cell has zero length, a
 * point inside the mesh is no triangle's corner, an edge has three
 * triangles, a triangle is inverted or overlaps another); the errors of
 * cvm__cdt_build() (rb->rebuilding = 1; an input fault in rb->fault, without
 * a message; crossing edges of two triangles are named as an overlap of
 * those triangles instead); CVM_E_NOMEM. */
cvm_status cvm__rebuild_cells(cvm__rebuild *rb, const cvm__rebuild_input *in);

/* ---- between rebuild.c and rebuild_cells.c ---- */

/* A triangle (or edge: v[2] = INT32_MAX) as its sorted vertex ids, and where it comes from. */
typedef struct cvm__rb_key {
    int32_t v[3];
    int32_t src;
} cvm__rb_key;

void cvm__rb_make_key(cvm__rb_key *k, int32_t a, int32_t b, int32_t c, int32_t src);
/* qsort order: vertex ids, then src. */
int cvm__rb_cmp_key(const void *pa, const void *pb);
/* src of an entry of keys (n, sorted) with the vertex ids of key, or -1. */
int32_t cvm__rb_find(const cvm__rb_key *keys, size_t n, const cvm__rb_key *key);

/* The edges of the cells: the file's checks of its triangles and line
 * cells, then the segments to rebuild with (rb->seg, rb->smark, and
 * rb->segtri a triangle on each, -1 for a line cell): the line cells, the
 * boundary edges that are no line cell (the first *nreal of rb->seg), the
 * edges between triangles of different attributes that are no line cell
 * (marker 0; the first *nkeep), then the other inner edges that are no line
 * cell (temporary constraints, marker 0; *nall in all). Errors as
 * cvm__rebuild_cells(). */
cvm_status cvm__rb_cells(cvm__rebuild *rb, const cvm__rebuild_input *in, size_t *nreal,
                         size_t *nkeep, size_t *nall);

#endif
