/* vertex_data.c - markers and attributes of the vertices the kernels add (Steiner points on segments, refinement vertices). */
#include "api_internal.h"
#include "store.h"

cvm_status cvm__grow_vertex_data(cvm_mesh *m)
{
    size_t nv = cvm__store_nv(m), na = m->in.nattr;
    if (nv > m->cap_vmark &&
        cvm__grow(&m->ctx, (void **)&m->vmark, &m->cap_vmark, nv, sizeof(int32_t)))
        return CVM_E_NOMEM;
    if (na && nv * na > m->cap_vattr &&
        cvm__grow(&m->ctx, (void **)&m->vattr, &m->cap_vattr, nv * na, sizeof(double)))
        return CVM_E_NOMEM;
    return CVM_OK;
}

int32_t cvm__segment_marker(const cvm_mesh *m, int32_t seg)
{
    return cvm__cdt_segment_marker(m->in.smark, m->in.nseg, seg);
}

void cvm__segment_vertex_data(cvm_mesh *m, size_t v, int32_t seg)
{
    cvm__cdt_input in;
    size_t na = m->in.nattr;
    cvm__mesh_cdt_input(&in, m, &m->in);
    cvm__cdt_segment_point(&in, cvm__store_point(m, v), seg, m->vmark + v, na ? m->vattr + v * na : NULL);
}
