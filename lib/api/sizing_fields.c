/* sizing_fields.c - a cvm_sizing's domain fields built from a mesh handle (lib/sizing builds
 * them; this file supplies the handle's triangulation and input points). */
#include <string.h>

#include "sizing_fields.h"
#include "store.h"

cvm_status cvm__sizing_fields_begin(cvm_mesh *m, const cvm_sizing *sizing, cvm__sizing_fields *F,
                                    const cvm_sizing **use)
{
    uint8_t *is_input = NULL;
    size_t k;
    cvm_status s;
    memset(F, 0, sizeof *F);
    *use = sizing;
    if (!cvm__sizing_needs_fields(sizing))
        return CVM_OK;
    if (sizing->has_auto) {
        /* the automatic field's features: boundary and constrained edges, and the input
         * points on none of them */
        if (!(is_input = cvm__malloc(&m->ctx, cvm__store_nv(m) + 1)))
            return cvm__nomem(&m->ctx);
        memset(is_input, 0, cvm__store_nv(m) + 1);
        for (k = 0; k < m->in.np; k++)
            if (m->input_map[k] >= 0)
                is_input[m->input_map[k]] = 1;
    }
    s = cvm__sizing_fields_build(F, use, sizing, cvm__store_tri2_const(m), is_input, &m->ctx);
    cvm__free(&m->ctx, is_input);
    return s;
}

cvm_status cvm__sizing_refuse_metric(cvm_mesh *m, const cvm_sizing *sizing, const char *call)
{
    if (!cvm__sizing_has_metric(sizing))
        return CVM_OK;
    return cvm__error(&m->ctx, CVM_E_UNSUPPORTED, CVM_ENT_NONE, -1,
                      "%s does not mesh to a metric (tensor) source yet: remove it with "
                      "cvm_sizing_set_metric_fn(s, NULL, 0, NULL) or use a sizing without one",
                      call);
}

cvm_status cvm__sizing_refuse_3d(cvm_mesh *m, const cvm_sizing *sizing, const char *call)
{
    if (!sizing || sizing->dim != 3)
        return CVM_OK;
    return cvm__error(&m->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                      "%s meshes in 2D, and the sizing holds 3D sources (added with dim 3)",
                      call);
}

void cvm__sizing_fields_end(cvm_mesh *m, cvm__sizing_fields *F)
{
    cvm__sizing_fields_free(F, &m->ctx);
}
