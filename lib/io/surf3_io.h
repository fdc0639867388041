/*
 * surf3_io.h - readers of closed 3D surfaces into a cvm__surf3 (common/surf3.h):
 * Object File Format .off, STL (ASCII and binary) and TetGen's .poly and
 * .smesh. They read through a cvm__reader, so tests inject short reads and read
 * errors, and allocate through the ctx, so out of memory is a status.
 *
 * Every reader leaves *out empty on error, and its message names the file and
 * line (the byte offset for binary STL) and the offending item in the file's
 * own numbering. Statuses: CVM_OK, CVM_E_IO_READ, CVM_E_IO_FORMAT (malformed,
 * bad count, index out of range), CVM_E_INPUT_NONFINITE (NaN or infinite
 * coordinate), CVM_E_TOO_LARGE (a count above CVM__SURF3_MAX_COUNT),
 * CVM_E_NOMEM, CVM_INCOMPLETE_CANCELLED (ctx's progress callback, stage
 * CVM_STAGE_READ, asked every 64 KiB).
 */
#ifndef CVM_IO_SURF3_IO_H
#define CVM_IO_SURF3_IO_H

#include "common/surf3.h"
#include "io_text.h"

/* .off: "OFF", then "<#points> <#faces> <#edges>", points "x y z", faces
 * "<n> <i1> ... <in>" (0-based; up to 4 colour fields after them are
 * ignored). Each face becomes one facet of one polygon with marker 1;
 * messages name "face k" (0-based, as the file numbers them). */
cvm_status cvm__read_off(cvm__ctx *ctx, cvm__reader *r, const char *name, cvm__surf3 *out);

/* .stl, ASCII or binary (binary when the size is exactly 84 + 50 * count, or
 * when the text does not start with "solid"). ASCII: each solid's triangles get
 * the solid's ordinal (1, 2, ...) as marker; binary: marker 1. Vertices with
 * exactly equal coordinates are merged (-0 equals +0), numbered in order of
 * first appearance. Each triangle is one facet; messages name "facet k"
 * counted from 1 through the whole file. */
cvm_status cvm__read_stl(cvm__ctx *ctx, cvm__reader *r, const char *name, cvm__surf3 *out);

/* TetGen .poly (is_smesh 0) or .smesh (1), 3D: points, facets (polygons,
 * facet holes, markers), hole points, optional regions (x y z attribute
 * [max volume]). Numbered from 0 or 1, as the first point says. A file with 0
 * points gets them from ext (np points of a .node numbered from base), or,
 * when ext is NULL, is refused with CVM_E_IO_FORMAT. */
typedef struct cvm__surf3_ext_points {
    const double *xyz;
    size_t np;
    int base;
} cvm__surf3_ext_points;
cvm_status cvm__read_tetpoly(cvm__ctx *ctx, cvm__reader *r, const char *name, int is_smesh,
                             const cvm__surf3_ext_points *ext, cvm__surf3 *out);
/* TetGen .node, 3D (the point section of a .poly alone). */
cvm_status cvm__read_tetnode(cvm__ctx *ctx, cvm__reader *r, const char *name, cvm__surf3 *out);

/* TetGen .ele (read_tetele.c): the tetrahedra of a mesh on the np points of a
 * .node numbered from base. tet: 4 nt corners, 0-based; attr: the first
 * attribute of each tetrahedron, or NULL when the file has none; first: the
 * file's number of tetrahedron 0 (for messages). Corners are only checked to
 * name points; CVM_E_UNSUPPORTED for quadratic (10-node) tetrahedra. */
typedef struct cvm__tetele {
    int32_t *tet;
    double *attr;
    size_t nt;
    long long first;
} cvm__tetele;
cvm_status cvm__read_tetele(cvm__ctx *ctx, cvm__reader *r, const char *name, long long base,
                            size_t np, cvm__tetele *out);
void cvm__tetele_free(cvm__ctx *ctx, cvm__tetele *t);

/* Open path and read it by extension (.off, .stl, .poly, .smesh; a .poly or
 * .smesh with 0 points reads them from STEM.node). CVM_E_IO_OPEN when it cannot
 * be opened, CVM_E_UNSUPPORTED for another extension. */
cvm_status cvm__read_surface3_file(cvm__ctx *ctx, const char *path, cvm__surf3 *out);

/* ---- field helpers of the text readers (surf3_fields.c) ---- */

/* Next line with content; at end of file CVM_E_IO_FORMAT "unexpected end of
 * file: expected <expected>". */
cvm_status cvm__s3_need_line(cvm__scan *sc, const char *expected);
/* Fail unless the current line has between lo and hi fields. */
cvm_status cvm__s3_want_fields(cvm__scan *sc, size_t lo, size_t hi, const char *what,
                               const char *layout);
/* The next field as an integer in [lo, hi]. */
cvm_status cvm__s3_int(cvm__scan *sc, const char *what, long long lo, long long hi,
                       long long *out);
/* The next field as a count in [0, CVM__SURF3_MAX_COUNT] (else CVM_E_TOO_LARGE). */
cvm_status cvm__s3_count(cvm__scan *sc, const char *what, long long *out);
/* The next field as a finite number; what and number name the item
 * ("point 7"); CVM_E_INPUT_NONFINITE for NaN or infinity. */
cvm_status cvm__s3_real(cvm__scan *sc, const char *what, long long number, double *out);
/* Fail unless the file has no more content. */
cvm_status cvm__s3_expect_end(cvm__scan *sc, const char *after);

#endif
