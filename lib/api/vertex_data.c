/* vertex_data.c - markers and attributes of the vertices the kernels add (Steiner points on segments, refinement vertices). */
#include "api_internal.h"

cvm_status cvm__grow_vertex_data(cvm_mesh *m)
{
    size_t nv = m->tri.nv, na = m->in.nattr;
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
    if (seg < 0 || (size_t)seg >= m->in.nseg)
        return 0;
    return m->in.smark ? m->in.smark[seg] : 1;
}

void cvm__segment_vertex_data(cvm_mesh *m, size_t v, int32_t seg)
{
    size_t na = m->in.nattr, i;
    const int32_t *s;
    const double *pa, *pb, *p = m->tri.xy + 2 * v;
    double len2, t;
    m->vmark[v] = cvm__segment_marker(m, seg);
    if (seg < 0 || (size_t)seg >= m->in.nseg)
        return; /* a convex-hull segment: marker 0, attributes as they are */
    s = m->in.seg + 2 * (size_t)seg;
    pa = m->in.xy + 2 * (size_t)s[0];
    pb = m->in.xy + 2 * (size_t)s[1];
    len2 = (pb[0] - pa[0]) * (pb[0] - pa[0]) + (pb[1] - pa[1]) * (pb[1] - pa[1]);
    t = len2 > 0 ? ((p[0] - pa[0]) * (pb[0] - pa[0]) + (p[1] - pa[1]) * (pb[1] - pa[1])) / len2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    for (i = 0; i < na; i++)
        m->vattr[v * na + i] =
            (1 - t) * m->in.pattr[(size_t)s[0] * na + i] + t * m->in.pattr[(size_t)s[1] * na + i];
}
