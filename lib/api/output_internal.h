/*
 * output_internal.h - the domain of a triangulated mesh in output order,
 * shared by the output and measure files of lib/api (the enumeration itself
 * is lib/delaunay/domain.h).
 */
#ifndef CVM_OUTPUT_INTERNAL_H
#define CVM_OUTPUT_INTERNAL_H

#include "api_internal.h"
#include "delaunay/domain.h"
#include "dual/dual_internal.h"

/* Number of domain triangles of m: 0 when it is not triangulated. */
size_t cvm__mesh_n_triangles(const cvm_mesh *m);

/* Whether an output buffer dst of dst_len entries holds need entries:
 * CVM_E_NULL_ARG when dst is NULL with dst_len > 0, CVM_E_BUFFER_TOO_SMALL when
 * dst_len < need, else CVM_OK (no message set). */
cvm_status cvm__room(const void *dst, size_t dst_len, size_t need);

/* Writes of the files of path into a write set (the staged one or a fresh one). */
typedef cvm_status (*cvm__mesh_write_fn)(cvm_mesh *m, const char *path, cvm__write_set *ws);

/* A cvm_mesh_write*() call: CVM_E_NULL_ARG without m; else CVM__BEGIN(m), write(m, path)
 * into a fresh write set, then commit it, or discard it when write fails. Returns the
 * first failing status. */
cvm_status cvm__mesh_write_now(cvm_mesh *m, const char *path, cvm__mesh_write_fn write);

/* The end of a cvm_mesh_stage_write*() call that returns s: on an error or
 * cancellation every staged write of m is discarded. Returns s. */
cvm_status cvm__mesh_stage_settle(cvm_mesh *m, cvm_status s);

#endif
