/*
 * formats.h - the body of each output format, written to an open
 * cvm__writer (write_file.c opens, commits or discards). Each writes text
 * only and never fails by itself: output errors are sticky in the writer,
 * except CVM_E_NOMEM for the formats that need scratch memory.
 */
#ifndef CVM_IO_FORMATS_H
#define CVM_IO_FORMATS_H

#include "io_internal.h"

/* VTK XML UnstructuredGrid, ASCII, or binary as mo->vtu_encoding says (write_vtu.c). */
cvm_status cvm__write_vtu(cvm__writer *w, cvm__ctx *ctx, const cvm__mesh_out *mo);
/* The same arrays in one raw <AppendedData> block, zlib-compressed when zlib
 * (write_vtu_binary.c); CVM_E_NOMEM is its only failure. */
cvm_status cvm__write_vtu_binary(cvm__writer *w, cvm__ctx *ctx, const cvm__mesh_out *mo, int zlib);
/* The power cells as VTK polygons (write_vtu.c). */
void cvm__write_dual_vtu(cvm__writer *w, const cvm__dual_out *d);
/* Gmsh MSH 4.1, ASCII (write_msh.c). */
cvm_status cvm__write_msh(cvm__writer *w, cvm__ctx *ctx, const cvm__mesh_out *mo);
/* Triangle .node, .ele and .edge, 0-based (write_triangle.c). */
void cvm__write_node(cvm__writer *w, const cvm__mesh_out *mo);
void cvm__write_ele(cvm__writer *w, const cvm__mesh_out *mo);
void cvm__write_edge(cvm__writer *w, const cvm__mesh_out *mo);
/* An SVG picture (write_svg.c). */
cvm_status cvm__write_svg(cvm__writer *w, cvm__ctx *ctx, const cvm__mesh_out *mo);

#endif
