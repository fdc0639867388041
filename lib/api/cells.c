/* cells.c - cells of several types (offsets + type codes + vertex ids), their neighbours and
 * attributes, for any cell kind of the mesh; in this version every cell is a triangle. */
#include "api_internal.h"
#include "api/mesh3.h"

/* Check dst against need entries (the rule of output.c). */
static cvm_status room(const void *dst, size_t dst_len, size_t need)
{
    if (!dst && dst_len)
        return CVM_E_NULL_ARG;
    return dst_len < need ? CVM_E_BUFFER_TOO_SMALL : CVM_OK;
}

cvm_status cvm_mesh_count_cells_mixed(size_t *ncells_out, size_t *nconn_out, const cvm_mesh *m,
                                      cvm_entity kind)
{
    size_t nt = 0;
    cvm_status s;
    if (!ncells_out || !nconn_out || !m)
        return CVM_E_NULL_ARG;
    *ncells_out = *nconn_out = 0;
    if (kind != CVM_ENT_CELL)
        return CVM_E_ARGUMENT;
    if ((s = cvm_mesh_count(&nt, m, m->m3 ? CVM_ENT_CELL : CVM_ENT_TRIANGLE)))
        return s;
    if (nt > (size_t)INT32_MAX / (m->m3 ? 4 : 3)) /* offsets are cvm_index */
        return CVM_E_TOO_LARGE;
    *ncells_out = nt;
    *nconn_out = (m->m3 ? 4 : 3) * nt;
    return CVM_OK;
}

cvm_status cvm_mesh_copy_cells_mixed(cvm_index *offsets, size_t offsets_len, int32_t *types,
                                     size_t types_len, cvm_index *conn, size_t conn_len,
                                     const cvm_mesh *m, cvm_entity kind)
{
    size_t nc, nconn, c;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    if ((s = cvm_mesh_count_cells_mixed(&nc, &nconn, m, kind)))
        return s;
    /* every array is checked before any is written */
    if ((s = room(offsets, offsets_len, nc + 1)) || (s = room(types, types_len, nc)) ||
        (s = room(conn, conn_len, nconn)))
        return s;
    if ((s = cvm_mesh_copy_cells(conn, conn_len, m, m->m3 ? CVM_ENT_TETRAHEDRON : CVM_ENT_TRIANGLE)))
        return s;
    for (c = 0; c <= nc; c++)
        offsets[c] = (cvm_index)((m->m3 ? 4 : 3) * c);
    for (c = 0; c < nc; c++)
        types[c] = m->m3 ? CVM_CELL_TETRAHEDRON : CVM_CELL_TRIANGLE;
    return CVM_OK;
}

cvm_status cvm_mesh_copy_cell_neighbors(cvm_index *dst, size_t dst_len, const cvm_mesh *m,
                                        cvm_entity kind)
{
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    if (!m)
        return CVM_E_NULL_ARG;
    if (kind == CVM_ENT_TETRAHEDRON)
        return CVM_E_UNSUPPORTED;
    if (kind != CVM_ENT_TRIANGLE && kind != CVM_ENT_CELL)
        return CVM_E_ARGUMENT;
    /* cells are the triangles, in that order, face k opposite vertex k: the same array */
    return cvm_mesh_copy_neighbors(dst, dst_len, m);
}

cvm_status cvm_mesh_copy_cell_attributes(double *dst, size_t dst_len, const cvm_mesh *m,
                                         cvm_entity kind)
{
    if (m && m->m3)
        return CVM_E_UNSUPPORTED; /* a 2D call on a 3D mesh */
    if (!m)
        return CVM_E_NULL_ARG;
    if (kind != CVM_ENT_TRIANGLE && kind != CVM_ENT_CELL)
        return CVM_E_ARGUMENT;
    return cvm_mesh_copy_triangle_attributes(dst, dst_len, m);
}
