/* domain.c - the domain triangle count of a mesh handle and the caller-buffer check shared by
 * the copy functions. */
#include "output_internal.h"
#include "store.h"

size_t cvm__mesh_n_triangles(const cvm_mesh *m)
{
    return m->triangulated ? cvm__domain_triangles(cvm__store_tri2_const(m)) : 0;
}

cvm_status cvm__room(const void *dst, size_t dst_len, size_t need)
{
    if (!dst && dst_len)
        return CVM_E_NULL_ARG;
    return dst_len < need ? CVM_E_BUFFER_TOO_SMALL : CVM_OK;
}
