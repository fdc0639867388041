/*
 * mesh3.h - the 3D side of the cvm_mesh handle (lib/api/mesh3*.c): a handle
 * given points of dimension 3 keeps its input and its tetrahedral mesh here
 * (m->m3), and the public calls that have a 3D meaning dispatch to these.
 * The engines: lib/delaunay3 (Delaunay / regular tetrahedralisation),
 * lib/surface3 (surface validation), lib/tetgen (boundary recovery, optional).
 */
#ifndef CVM_API_MESH3_H
#define CVM_API_MESH3_H

#include "api_internal.h"

/* Free m->m3 (NULL afterwards): the handle is 2D again. */
void cvm__mesh3_free(cvm_mesh *m);
/* The calls below set the message on error. */
cvm_status cvm__mesh3_set_points(cvm_mesh *m, const double *xyz, size_t n);
cvm_status cvm__mesh3_set_holes(cvm_mesh *m, const double *xyz, size_t n);
cvm_status cvm__mesh3_set_regions(cvm_mesh *m, const double *r, size_t n); /* 5 per region */
/* .off, .stl, .smesh, and .poly / .node of dimension 3. */
cvm_status cvm__mesh3_read(cvm_mesh *m, const char *path);
cvm_status cvm__mesh3_triangulate(cvm_mesh *m);
cvm_status cvm__mesh3_check(cvm_mesh *m);
/* cvm_mesh_insert_points_nd() with dim 3 (mesh3_insert.c); xyz: 3 per point. */
cvm_status cvm__mesh3_insert_points(cvm_index *ids_out, cvm_mesh *m, const double *xyz,
                                    size_t count, double min_dist);
cvm_status cvm__mesh3_set_weights(cvm_mesh *m, const double *w, size_t n);
cvm_status cvm__mesh3_write_to_set(cvm_mesh *m, const char *path, cvm__write_set *ws);
cvm_status cvm__mesh3_measure(double *out, cvm_mesh *m, cvm_measure which);
/* Measures 720-724 and the 3D histograms (mesh3_quality.c). */
cvm_status cvm__mesh3_quality(double *out, cvm_mesh *m, cvm_measure which);
/* Measures 725-728, merged dual cells (mesh3_merge.c). */
cvm_status cvm__mesh3_merge_measure(double *out, cvm_mesh *m, cvm_measure which);
/* Write mo (the handle's mesh) to path with the merged cells of
 * CVM_OPT_VTU_MERGED_CELLS: as cvm__write_file3_to_set(), message set. */
struct cvm__mesh3_out;
cvm_status cvm__mesh3_write_merged_to_set(cvm_mesh *m, const char *path, cvm__write_set *ws,
                                          struct cvm__mesh3_out *mo);
cvm_status cvm__mesh3_histogram(double *dst, size_t dst_len, cvm_mesh *m, cvm_histogram which);
/* Const readers: statuses only, no message. */
cvm_status cvm__mesh3_count(size_t *out, const cvm_mesh *m, cvm_entity kind);
cvm_status cvm__mesh3_copy_points(double *dst, size_t dst_len, const cvm_mesh *m);
const double *cvm__mesh3_points(const cvm_mesh *m, size_t *nv);
cvm_status cvm__mesh3_copy_cells(cvm_index *dst, size_t dst_len, const cvm_mesh *m,
                                 cvm_entity kind);
/* The weight of each vertex, 0 when none were set (optimise3.c). */
cvm_status cvm__mesh3_copy_weights(double *dst, size_t dst_len, const cvm_mesh *m);
/* The power vertex of each tetrahedron (3 per tetrahedron; mesh3_dual_out.c). */
cvm_status cvm__mesh3_copy_dual_vertices(double *dst, size_t dst_len, const cvm_mesh *m);
/* The bounded dual cells as a .vtu of polyhedra into ws (message set on error). */
cvm_status cvm__mesh3_write_dual_to_set(cvm_mesh *m, const char *path, cvm__write_set *ws);
/* The report of the last cvm_mesh_generate3() (lib/api/generate3.c): CVM_OK, or
 * CVM_E_ARGUMENT when which is not a CVM_REPORT_GEN3_* value. No message. */
cvm_status cvm__mesh3_gen3_report(double *out, const cvm_mesh *m, int which);
/* The message of a 2D-only call made on a 3D handle: CVM_E_UNSUPPORTED. */
cvm_status cvm__mesh3_unsupported(cvm_mesh *m, const char *call);

#endif
