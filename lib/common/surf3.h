/*
 * surf3.h - a 3D piecewise linear boundary as plain arrays: points, polygons
 * grouped into facets with boundary markers, facet holes, volume hole points
 * and region points. The readers of lib/io fill it, lib/surface3 validates it
 * and lib/tetgen recovers it; every array is allocated through a cvm__ctx.
 */
#ifndef CVM_COMMON_SURF3_H
#define CVM_COMMON_SURF3_H

#include <stddef.h>
#include <stdint.h>
#include "common/common_internal.h"

/* Largest item count the readers accept (points, polygons, corners, ...), so
 * that every index and offset fits an int32_t. */
#define CVM__SURF3_MAX_COUNT ((size_t)INT32_MAX / 4)

typedef struct cvm__surf3 {
    double *xyz;         /* 3*np coordinates, all finite */
    size_t np;
    int32_t *poff;       /* npoly+1: polygon k has the corners pidx[poff[k] .. poff[k+1]-1] */
    int32_t *pidx;       /* 0-based point indices */
    int32_t *pfacet;     /* npoly: the facet of each polygon (nondecreasing) */
    size_t npoly;
    int32_t *fmark;      /* nfacet: boundary marker of each facet */
    int32_t *fhole_off;  /* nfacet+1: facet f has the hole points fhole[3*fhole_off[f] ..
                            3*fhole_off[f+1]-1] (points in the facet's plane) */
    double *fhole;
    size_t nfacet;
    double *holes;       /* 3*nholes: points inside volumes that are not meshed */
    size_t nholes;
    double *regions;     /* 5*nregions: x, y, z, attribute, max volume (<= 0: none) */
    size_t nregions;
    /* How messages name items, in the file's own numbering. */
    char *file;              /* owned copy of the file name; NULL when not read from a file */
    const char *facet_word;  /* static: "face" (.off), "facet" (.stl, .poly, .smesh) */
    int32_t point_base;      /* the file's number of point 0 (0 or 1) */
    int32_t facet_base;      /* the file's number of facet 0 */
    int points_numbered;     /* 0 when the file has no point numbers (.stl: merged vertices) */
    /* capacities of the growing arrays */
    size_t cap_xyz, cap_poff, cap_pidx, cap_pfacet, cap_fmark, cap_fhole_off, cap_fhole,
           cap_holes, cap_regions;
} cvm__surf3;

/* An empty surface (all zero; facet_word "facet", numbering from 0). */
void cvm__surf3_init(cvm__surf3 *s);
/* Free every array of s through ctx and make it empty again. */
void cvm__surf3_free(cvm__ctx *ctx, cvm__surf3 *s);

/* Builders. Each returns CVM_OK or CVM_E_NOMEM (with the standard message)
 * and leaves s consistent either way. */
cvm_status cvm__surf3_add_point(cvm__ctx *ctx, cvm__surf3 *s, double x, double y, double z);
/* Start facet nfacet with marker; later polygons and facet holes join it. */
cvm_status cvm__surf3_add_facet(cvm__ctx *ctx, cvm__surf3 *s, int32_t marker);
/* A polygon of n corners (0-based, not checked here) in the last facet. */
cvm_status cvm__surf3_add_polygon(cvm__ctx *ctx, cvm__surf3 *s, const int32_t *idx, size_t n);
cvm_status cvm__surf3_add_facet_hole(cvm__ctx *ctx, cvm__surf3 *s, const double *xyz);
cvm_status cvm__surf3_add_hole(cvm__ctx *ctx, cvm__surf3 *s, const double *xyz);
/* r: x, y, z, attribute, max volume. */
cvm_status cvm__surf3_add_region(cvm__ctx *ctx, cvm__surf3 *s, const double *r);
/* Keep a copy of the file name for messages. */
cvm_status cvm__surf3_set_file(cvm__ctx *ctx, cvm__surf3 *s, const char *file);

#endif
