/*
 * io_internal.h - file readers and writers. They work on plain arrays (a
 * cvm__pslg read in, a cvm__mesh_out written out), so io depends on common
 * only. Readers go through a cvm__reader so tests can inject read faults;
 * writers go through a cvm__writer that writes PATH.tmp.XXXXXX and renames it
 * over PATH only when everything succeeded.
 */
#ifndef CVM_IO_INTERNAL_H
#define CVM_IO_INTERNAL_H

#include <stddef.h>
#include <stdint.h>
#include "common/common_internal.h"

/* ---- input: a planar straight-line graph, arrays allocated through ctx ---- */
typedef struct cvm__pslg {
    double *xy;          /* 2*np */
    size_t np;
    int32_t *pmark;      /* np or NULL */
    double *pattr;       /* np*nattr or NULL */
    size_t nattr;
    int32_t *seg;        /* 2*nseg, 0-based */
    size_t nseg;
    int32_t *smark;      /* nseg or NULL */
    double *holes;       /* 2*nholes */
    size_t nholes;
    double *regions;     /* 4*nregions: x, y, attribute, max area */
    size_t nregions;
} cvm__pslg;

/* Free every array of p through ctx and zero it. */
void cvm__pslg_free(cvm__ctx *ctx, cvm__pslg *p);

/* A byte source. read() returns bytes read (0 at end), or -1 on error. */
typedef struct cvm__reader {
    long (*read)(void *self, char *buf, size_t len);
    void *self;
} cvm__reader;

/* Parse Triangle .poly (is_poly = 1) or .node (is_poly = 0) text from r.
 * name is used in messages ("square.poly:12: ..."). On error p is left zeroed
 * and the message gives name:line. Returns CVM_OK, CVM_E_IO_READ,
 * CVM_E_IO_FORMAT, CVM_E_INPUT_NONFINITE, CVM_E_NOMEM, CVM_E_TOO_LARGE. */
cvm_status cvm__read_triangle_format(cvm__ctx *ctx, cvm__reader *r, const char *name,
                                     int is_poly, cvm__pslg *p);

/* Open path and parse it by extension (.poly, .node). A .poly with 0 points
 * reads the points from the .node of the same stem. */
cvm_status cvm__read_file(cvm__ctx *ctx, const char *path, cvm__pslg *p);

/* ---- output: a finished mesh, borrowed arrays ---- */
typedef struct cvm__mesh_out {
    const double *xy;    /* 2*nv */
    size_t nv;
    const int32_t *vmark;/* nv or NULL */
    const double *vattr; /* nv*nattr or NULL */
    size_t nattr;
    const int32_t *tri;  /* 3*nt, counter-clockwise */
    size_t nt;
    const double *tattr; /* nt or NULL (regional attribute) */
    const int32_t *edge; /* 2*ne or NULL: all edges (for .edge) */
    const int32_t *emark;/* ne or NULL: marker of each edge (0 interior) */
    size_t ne;
    const int32_t *seg;  /* 2*nseg: constrained edges */
    const int32_t *smark;/* nseg or NULL */
    size_t nseg;
    const double *tquality; /* nt or NULL: per-triangle value for SVG colouring (min angle, degrees) */
} cvm__mesh_out;

/* A byte sink with atomic commit. */
typedef struct cvm__writer cvm__writer;

/* Write the mesh to path in the format its extension names (.vtu, .msh,
 * .node -> PREFIX.node/.ele/.edge, .svg). Returns CVM_OK, CVM_E_UNSUPPORTED,
 * CVM_E_IO_OPEN, CVM_E_IO_WRITE, CVM_E_NOMEM; on error no file is left. */
cvm_status cvm__write_file(cvm__ctx *ctx, const char *path, const cvm__mesh_out *mo);

#endif
