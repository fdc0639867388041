/*
 * api_internal.h - the cvm_mesh handle behind include/cvmesh.h: the user's
 * input (copied on set), options, and the triangulation built from them.
 */
#ifndef CVM_API_INTERNAL_H
#define CVM_API_INTERNAL_H

#include "common/common_internal.h"
#include "delaunay/delaunay_internal.h"
#include "delaunay/domain.h"
#include "io/io_internal.h"

/* Options live in one table; index with cvm__option_slot(). */
#define CVM__NOPTIONS 96

#define CVM__NBIN_Q 20      /* the most bins of CVM_HIST_Q1 .. CVM_HIST_Q5 */
/* CVM_MEASURE_Q1_MEAN_DEG .. CVM_MEASURE_Q5_MIN_BOUNDARY */
#define CVM__NQ_MEASURES ((int)CVM_MEASURE_Q5_MIN_BOUNDARY - (int)CVM_MEASURE_Q1_MEAN_DEG + 1)

/* Whole-mesh summaries of the power dual (lib/api/dual_quality.c). */
typedef struct cvm__dual_summary {
    double q[CVM__NQ_MEASURES];    /* CVM_MEASURE_Q1_MEAN_DEG + k */
    double hist[5][CVM__NBIN_Q];   /* CVM_HIST_Q1 + k */
    double minima[3];              /* cvm__dual_edge_minima() */
} cvm__dual_summary;

/* Whole-mesh quality values, each group computed on its first request and
 * kept until the next call that may change the mesh (CVM__BEGIN forgets
 * them): a full report asks for about 30 measures and histograms, which
 * share a few passes over the mesh. Plain values: nothing to free. */
#define CVM__HAVE_TRI 1u
#define CVM__HAVE_DEGREE 2u
#define CVM__HAVE_DUAL 4u
#define CVM__HAVE_OUTSIDE 8u
typedef struct cvm__quality_cache {
    unsigned have;                 /* CVM__HAVE_* of the groups below that are valid */
    cvm__tri_quality tri;
    double degree_hist[CVM__NBIN_DEGREE];
    size_t n_interior;
    cvm__dual_summary dual;
    double pct_outside[2];         /* CVM_MEASURE_DUAL_OUTSIDE_PCT, _OUTSIDE_BOUNDARY_PCT */
} cvm__quality_cache;

/* The quad-dominant cells of the last cvm_mesh_quadmesh() (lib/api/quadmesh.c), in the layout
 * of cvm_mesh_copy_cells_mixed(): cell c has type types[c] and the vertex ids
 * conn[off[c] .. off[c+1]-1]; first[c] is its first triangle in CVM_ENT_TRIANGLE order. */
typedef struct cvm__quad_cells {
    size_t ncell, nconn;
    int32_t *off, *types, *conn, *first;
    double *quality; /* per cell: a quad's 1 - max|corner - 90| / 90 in the metric; 0 for a
                        triangle (.vtu cell data "quad_quality") */
} cvm__quad_cells;

#define CVM__NQUAD_REPORT 22 /* CVM_REPORT_QUAD_PCT .. CVM_REPORT_QUAD_BOUNDARY_SITES */

/* The 3D input and mesh of a handle given points of dimension 3 (lib/api/mesh3*.c). */
typedef struct cvm__mesh3 cvm__mesh3;

struct cvm_mesh {
    cvm__ctx ctx;
    double opt[CVM__NOPTIONS];

    /* NULL: a 2D handle (everything below). Else the handle is 3D: the 2D input
     * and output below stay empty, and the calls dispatch to lib/api/mesh3.h. */
    cvm__mesh3 *m3;

    /* input (owned copies) */
    cvm__pslg in;

    /* output */
    int triangulated;        /* 1 once cvm_mesh_triangulate() succeeded */
    cvm__tri2 tri;           /* vertices: input less duplicates, then Steiner points */
    int32_t *input_map;      /* in.np entries: input point -> vertex (-1: an inner vertex of a
                                chain re-discretised by CVM_OPT_KEEP_SEGMENT_VERTICES = 0) */
    size_t nv_triangulated;  /* tri.nv as cvm_mesh_triangulate() left it (0: not from it) */
    size_t n_dup;
    int32_t *vmark;          /* marker per vertex (tri.nv), grown with Steiner points */
    double *vattr;           /* nattr per vertex, or NULL */
    size_t cap_vmark, cap_vattr;
    /* regional attributes per triangle live in tri.ta (NULL without regions) */

    /* refinement (lib/api/refine.c) */
    double refine_report[6]; /* the last cvm_mesh_refine(): CVM_MEASURE_REFINE_* */
    double *refine_unmet;    /* 3 per triangle the last refinement left unmet: x, y, reasons */
    size_t n_refine_unmet;
    int32_t *front_marks;    /* cvm_mesh_set_front_markers() */
    size_t n_front_marks;

    /* dual optimisation (lib/api/optimise.c) */
    double dual_opt_report[10]; /* the last cvm_mesh_optimise_dual(): CVM_MEASURE_DUAL_OPT_* */
    double *tlayer;          /* AFLR layer index per triangle slot of tri, or NULL */
    size_t n_tlayer;         /* tri.nt when tlayer was made (stale when it differs) */

    /* the last cvm_mesh_read() of a mesh file: CVM_REPORT_READ_FLIPS */
    double read_flips;
    /* quad-dominant meshing (lib/api/quadmesh.c): NULL, or the cells of the last
     * cvm_mesh_quadmesh() on the current triangles (dropped with any change to them) */
    cvm__quad_cells *quad;
    double quad_report[CVM__NQUAD_REPORT];

    /* cvm_mesh_stage_write(): files written, waiting for cvm_mesh_commit_writes() */
    cvm__write_set staged;

    /* quality measures of the current mesh (lib/api/quality.c) */
    cvm__quality_cache quality;

    /* marker names (lib/api/marker_names.c), sorted by (dim, tag), tags unique per dim */
    cvm__phys_name *names;
    size_t nnames;
};

/* Slot of key in opt[], or -1 if the key is unknown. */
int cvm__option_slot(cvm_option key);
/* Fill opt[] with defaults. */
void cvm__options_default(double *opt);
/* Value of an option of m. */
double cvm__opt(const cvm_mesh *m, cvm_option key);

/* Begin a public call on m: clears the last error and forgets the cached
 * quality values, since the call may change the mesh. Every public function
 * that takes a non-const cvm_mesh * begins with it, except the two readers of
 * the cache (cvm_mesh_get_measure, cvm_mesh_copy_histogram), which begin
 * with CVM__BEGIN_READ. */
#define CVM__BEGIN(m) (cvm__clear_error(&(m)->ctx), (void)((m)->quality.have = 0))
#define CVM__BEGIN_READ(m) cvm__clear_error(&(m)->ctx)

/* The start of a setter taking count items at items: CVM_E_NULL_ARG without m; else
 * CVM__BEGIN(m), and CVM_E_NULL_ARG with the message "<name> is NULL" when items is NULL
 * but count is not 0; CVM_OK otherwise. */
cvm_status cvm__mesh_begin_set(cvm_mesh *m, const void *items, size_t count, const char *name);

/* The triangle holding point p (a hole or region seed), or -1 outside the triangulation. */
int32_t cvm__mesh_seed_triangle(cvm_mesh *m, const double *p);

/* Marker names (lib/api/marker_names.c): the physical names of the .msh at path
 * into *names_out, *n_out (sorted, a repeated (dim, tag) keeps its first
 * name); NULL and 0 for other formats. The reader's statuses. */
cvm_status cvm__mesh_read_names(cvm_mesh *m, const char *path, cvm__phys_name **names_out,
                                size_t *n_out);
/* Replace m's marker names by names (taken over; NULL with n 0: none). */
void cvm__mesh_set_names(cvm_mesh *m, cvm__phys_name *names, size_t n);

/* Forget the AFLR layer indices (the triangles they belong to are changing; mesh_state.c). */
void cvm__mesh_forget_layers(cvm_mesh *m);

/* Remove the exterior and the holes of the triangulation of m (its segments
 * recovered) and flood the regional attributes; lib/api/triangulate.c. */
cvm_status cvm__mesh_carve(cvm_mesh *m);

/* CVM_OPT_KEEP_SEGMENT_VERTICES = 0 (lib/api/resample.c, lib/boundary): re-discretise the
 * chains of segments of m that form smooth curves with sizing and rebuild the
 * triangulation; *n_chains receives how many chains were re-discretised.
 * CVM_OK (also when no chain could be: m unchanged), CVM_E_STATE (m is not as
 * cvm_mesh_triangulate() left it), CVM_E_NOMEM (m unchanged), the sizing's
 * errors, CVM_INCOMPLETE_* (m unchanged). Sets the message. */
cvm_status cvm__mesh_resample_boundary(cvm_mesh *m, const cvm_sizing *sizing, size_t *n_chains);

/* Input items in messages (lib/api/input_names.c). An item read by
 * cvm_mesh_read() is named in the file's terms: its number there, and
 * "FILE:LINE: " at the start of the message; an item set through the API by
 * its 0-based index and no prefix. cvm_mesh_error_item() stays 0-based.
 * cvm__src_where: the prefix for item k of src into buf ("" when none).
 * cvm__src_num: the number naming item k (for a point, also as an endpoint).
 * cvm__src_also: " (line L)" locating a further item k named in the same
 * message, " (FILE:L)" when it comes from another file than primary's. */
#define CVM__WHERE_LEN 320
const char *cvm__src_where(char *buf, size_t cap, const cvm__item_src *src, size_t k);
long long cvm__src_num(const cvm__item_src *src, size_t k);
const char *cvm__src_also(char *buf, size_t cap, const cvm__item_src *src, size_t k,
                          const cvm__item_src *primary);

/* The engine's input faults (cvm__cdt_build, cvm__cdt_carve) as messages
 * naming the items of in in the user's terms (lib/api/cdt_input.c): sets
 * the message for status s and returns s; a fault of kind NONE returns s
 * untouched (the engine set the message). */
cvm_status cvm__cdt_fault_message(cvm__ctx *ctx, const cvm__pslg *in, cvm_status s,
                                  const cvm__cdt_fault *f);

/* The input p with the options of m (seed, duplicates, crossings, convex
 * hull) as the engine's triangulation input (lib/api/cdt_input.c); out
 * borrows p's arrays. */
void cvm__mesh_cdt_input(cvm__cdt_input *out, const cvm_mesh *m, const cvm__pslg *p);
/* cvm__cdt_build() of in into m's store, the input map, duplicate count, vertex markers and
 * attributes it makes handed to m also on failure (lib/api/cdt_input.c). The engine's status;
 * its fault in *f, for cvm__cdt_fault_message(). */
cvm_status cvm__mesh_cdt_build(cvm_mesh *m, const cvm__cdt_input *in, cvm__cdt_fault *f);

/* Forget the quad cells and report of cvm_mesh_quadmesh() (quadmesh.c); a no-op without. */
void cvm__mesh_forget_quads(cvm_mesh *m);
/* Report which (CVM_REPORT_QUAD_PCT ..) of the last cvm_mesh_quadmesh(): CVM_OK, or
 * CVM_E_ARGUMENT (no message) for another value. */
cvm_status cvm__quad_report(double *out, const cvm_mesh *m, int which);

/* Forget the triangulation (input kept; mesh_state.c). */
void cvm__mesh_drop_output(cvm_mesh *m);

/* Gather the domain triangles (and edges, segments) of m into freshly
 * allocated arrays of mo (freed with cvm__mesh_out_free). */
cvm_status cvm__mesh_out_build(cvm_mesh *m, cvm__mesh_out *mo, int want_edges, int want_quality);
void cvm__mesh_out_free(cvm_mesh *m, cvm__mesh_out *mo);

/* The CVM_MEASURE_REFINE_* values of the last refinement (lib/api/refine.c):
 * CVM_OK, or CVM_E_ARGUMENT when which is not a refinement measure.
 * cvm_mesh_get_measure() hands these measures to it. */
cvm_status cvm__refine_measure(double *out, const cvm_mesh *m, cvm_measure which);

/* The dual measures CVM_MEASURE_DUAL_* .. CVM_MEASURE_VANISHED_VERTICES
 * (lib/api/dual.c); m has triangles. CVM_OK, CVM_E_ARGUMENT, CVM_E_NOMEM. */
cvm_status cvm__dual_measure(double *out, cvm_mesh *m, cvm_measure which);

/* The dual quality measures CVM_MEASURE_Q* and histograms CVM_HIST_Q*
 * (lib/api/dual_quality.c); m has triangles. Set the message on error. */
cvm_status cvm__dual_quality_measure(double *out, cvm_mesh *m, cvm_measure which);
cvm_status cvm__dual_quality_histogram(double *dst, size_t dst_len, cvm_mesh *m,
                                       cvm_histogram which);
/* From the same pass as the q measures (lib/api/dual_quality.c), over the
 * interior edges: out[0] CVM_MEASURE_MIN_DUAL_EDGE, out[1]
 * CVM_MEASURE_TIME_STEP_PROXY, out[2] CVM_MEASURE_MIN_DUAL_EDGE_RATIO; m has
 * triangles. CVM_OK or CVM_E_NOMEM (with its message). */
cvm_status cvm__dual_edge_minima(cvm_mesh *m, double *out);

/* cvm_mesh_read() of a .vtu file (lib/api/mesh_read_vtu.c): m ends up
 * triangulated, with weights, equal to the file's mesh; on error m is unchanged
 * and the message names the file and the offending line or item. */
cvm_status cvm__mesh_read_vtu(cvm_mesh *m, const char *path);

/* Grow m->vmark and m->vattr to the kernel's vertex count (new entries
 * uninitialised). CVM_OK or CVM_E_NOMEM (no message set). */
cvm_status cvm__grow_vertex_data(cvm_mesh *m);

/* Marker of input segment seg: its own, or 1 when the input has no segment
 * markers (Triangle's default boundary marker); 0 for seg < 0 or past the
 * input segments (a convex-hull edge). */
int32_t cvm__segment_marker(const cvm_mesh *m, int32_t seg);

/* Vertex v (coordinates in the store) lies on input segment seg: it takes the
 * segment's marker, and its attributes are interpolated linearly between the
 * segment's input ends (by the projection of v, clamped to the segment). For
 * a seg outside the input segments only the marker (0) is written. vmark and
 * vattr must have room for v (cvm__grow_vertex_data). */
void cvm__segment_vertex_data(cvm_mesh *m, size_t v, int32_t seg);
/* The merge and compliance measures CVM_MEASURE_DUAL_MERGED_PCT ..
 * CVM_MEASURE_DUAL_NONCOMPLIANT_BOUNDARY_PCT and the report
 * CVM_MEASURE_DUAL_OPT_* (lib/api/optimise.c); m has triangles for the former.
 * CVM_OK, CVM_E_NOMEM, or CVM_E_ARGUMENT (no message) when which is not one
 * of them. */
cvm_status cvm__optimise_measure(double *out, cvm_mesh *m, cvm_measure which);
/* 1 when which is one of the measures of cvm__optimise_measure that need triangles. */
int cvm__optimise_measure_needs_triangles(cvm_measure which);

/* With weights set: *out receives a fresh array of nattr + 1 values per
 * vertex, the weight first, then the point attributes (free with cvm__free);
 * without weights *out is NULL. CVM_OK or CVM_E_NOMEM (no message). */
cvm_status cvm__mesh_weight_attributes(cvm_mesh *m, double **out);

#endif
