/* sizing_fields.c - the parts of a cvm_sizing that need the domain (the automatic length scale
 * and the boundary-spacing field), built from a triangulation for one refinement or optimisation. */
#include <string.h>

#include "sizing_internal.h"

int cvm__sizing_needs_fields(const cvm_sizing *sizing)
{
    return sizing && (sizing->has_auto || sizing->bgrad > 0);
}

cvm_status cvm__sizing_fields_build(cvm__sizing_fields *F, const cvm_sizing **use,
                                    const cvm_sizing *sizing, const cvm__tri2 *T,
                                    const uint8_t *is_input, cvm__ctx *ctx)
{
    cvm_status s;
    memset(F, 0, sizeof *F);
    *use = sizing;
    if (!cvm__sizing_needs_fields(sizing))
        return CVM_OK;
    /* evaluated through a private copy of the handle: the caller's stays untouched */
    F->local = *sizing;
    if (sizing->has_auto) {
        s = cvm__auto_field_build(&F->autof, T, is_input, sizing->auto_R, sizing->auto_G, ctx);
        if (s != CVM_OK)
            return s;
        F->local.autof = &F->autof;
    }
    if (sizing->bgrad > 0) {
        if ((s = cvm__spacing_field_build(&F->spacing, T, sizing->bgrad, ctx)) != CVM_OK) {
            cvm__auto_field_free(&F->autof, ctx);
            return s;
        }
        F->local.spacingf = &F->spacing;
    }
    *use = &F->local;
    return CVM_OK;
}

void cvm__sizing_fields_free(cvm__sizing_fields *F, cvm__ctx *ctx)
{
    cvm__auto_field_free(&F->autof, ctx);
    cvm__auto_field_free(&F->spacing, ctx);
}
