/* sizing_fields.c - the parts of a cvm_sizing that need the domain (the automatic length scale
 * and the boundary-spacing field), built from a mesh for one refinement or optimisation. */
#include <string.h>

#include "sizing_fields.h"

/* The automatic field of the domain of m; features are its boundary and
 * constrained edges and the input points on none of them. */
static cvm_status auto_field(cvm_mesh *m, const cvm_sizing *sizing, cvm__auto_field *F)
{
    uint8_t *is_input = cvm__malloc(&m->ctx, m->tri.nv + 1);
    size_t k;
    cvm_status s;
    if (!is_input)
        return cvm__nomem(&m->ctx);
    memset(is_input, 0, m->tri.nv + 1);
    for (k = 0; k < m->in.np; k++)
        if (m->input_map[k] >= 0)
            is_input[m->input_map[k]] = 1;
    s = cvm__auto_field_build(F, &m->tri, is_input, sizing->auto_R, sizing->auto_G, &m->ctx);
    cvm__free(&m->ctx, is_input);
    return s;
}

cvm_status cvm__sizing_fields_begin(cvm_mesh *m, const cvm_sizing *sizing, cvm__sizing_fields *F,
                                    const cvm_sizing **use)
{
    cvm_status s;
    memset(F, 0, sizeof *F);
    *use = sizing;
    if (!sizing || (!sizing->has_auto && !(sizing->bgrad > 0)))
        return CVM_OK;
    /* evaluated through a private copy of the handle: the caller's stays untouched */
    F->local = *sizing;
    if (sizing->has_auto) {
        if ((s = auto_field(m, sizing, &F->autof)) != CVM_OK)
            return s;
        F->local.autof = &F->autof;
    }
    if (sizing->bgrad > 0) {
        if ((s = cvm__spacing_field_build(&F->spacing, &m->tri, sizing->bgrad, &m->ctx)) != CVM_OK) {
            cvm__auto_field_free(&F->autof, &m->ctx);
            return s;
        }
        F->local.spacingf = &F->spacing;
    }
    *use = &F->local;
    return CVM_OK;
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

void cvm__sizing_fields_end(cvm_mesh *m, cvm__sizing_fields *F)
{
    cvm__auto_field_free(&F->autof, &m->ctx);
    cvm__auto_field_free(&F->spacing, &m->ctx);
}
