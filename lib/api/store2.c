/* store2.c - the 2D store behind a cvm_mesh (store.h): its operations on the kernel's
 * triangulation (lib/delaunay). */
#include <string.h>

#include "store.h"

void cvm__store_init(cvm_mesh *m)
{
    cvm__tri2_init(&m->tri, &m->ctx);
}

void cvm__store_destroy(cvm_mesh *m)
{
    cvm__tri2_destroy(&m->tri);
}

void cvm__store_clear(cvm_mesh *m)
{
    cvm__tri2_clear(&m->tri);
}

void cvm__store_exchange_tri2(cvm_mesh *m, cvm__tri2 *T)
{
    cvm__tri2 old = m->tri;
    m->tri = *T;
    *T = old;
}

void cvm__store_adopt_tri2(cvm_mesh *m, cvm__tri2 *T)
{
    cvm__ctx *ctx = T->ctx;
    cvm__tri2_destroy(&m->tri);
    m->tri = *T;
    m->tri.ctx = &m->ctx;
    cvm__tri2_init(T, ctx);
}

int32_t cvm__store_locate(cvm_mesh *m, const double *p)
{
    int32_t t;
    int j;
    cvm__loc loc = cvm__tri2_locate(&m->tri, p, -1, &t, &j);
    if (loc == CVM__LOC_OUTSIDE || t < 0)
        return -1;
    return t;
}

cvm_status cvm__store_add_vertex(cvm_mesh *m, const double *p, int32_t *v_out)
{
    return cvm__tri2_add_vertex(&m->tri, p, v_out);
}

void cvm__store_drop_last_vertex(cvm_mesh *m)
{
    m->tri.nv--;
}

cvm_status cvm__store_insert_vertex(cvm_mesh *m, int32_t v, double min_dist, int *inserted)
{
    cvm__ins res;
    int32_t other;
    cvm_status s = cvm__tri2_insert_vertex(&m->tri, v, m->tri.last, CVM__INSF_DOMAIN_ONLY, min_dist,
                                           &res, &other);
    *inserted = !s && res == CVM__INS_DONE;
    return s;
}

cvm_status cvm__store_set_weights(cvm_mesh *m, const double *w)
{
    cvm__tri2 *T = &m->tri;
    double *old = T->w, *nw;
    cvm_status s;
    /* keep the old weights until the flips succeeded */
    nw = w ? cvm__malloc(&m->ctx, (T->cap_v ? T->cap_v : 1) * sizeof *nw) : NULL;
    if (w && !nw)
        return CVM_E_NOMEM;
    if (nw)
        memcpy(nw, w, T->nv * sizeof *nw);
    T->w = nw;
    if ((s = cvm__tri2_make_regular(T, NULL))) {
        T->w = old;
        cvm__free(&m->ctx, nw);
        return s;
    }
    cvm__free(&m->ctx, old);
    return CVM_OK;
}

size_t cvm__store_count_vanished(cvm_mesh *m, uint8_t *mark)
{
    return cvm__tri2_count_unregular(&m->tri, mark);
}

cvm_status cvm__store_flood_attribute(cvm_mesh *m, int32_t t, double value)
{
    return cvm__tri2_flood_attribute(&m->tri, t, value);
}

cvm_status cvm__store_check(cvm_mesh *m)
{
    cvm_status s;
    if ((s = cvm__tri2_check(&m->tri)))
        return s;
    return cvm__cdt_check_chains(&m->tri, m->in.seg, m->in.nseg, m->input_map);
}

void cvm__store_remap_segments(cvm_mesh *m, const int32_t *map, size_t n)
{
    size_t k;
    for (k = 0; m->tri.te && k < 3 * m->tri.nt; k++)
        if (m->tri.te[k] >= 0 && (size_t)m->tri.te[k] < n)
            m->tri.te[k] = map[m->tri.te[k]];
}
