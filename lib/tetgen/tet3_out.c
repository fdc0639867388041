/* tet3_out.c - release of a cvm__tet3_out, and the recovery entry point of a build without TetGen. */
#include <string.h>

#include "tetgen_shim.h"

void cvm__tet3_out_free(cvm__ctx *ctx, cvm__tet3_out *out)
{
    cvm__free(ctx, out->xyz);
    cvm__free(ctx, out->tet);
    cvm__free(ctx, out->tattr);
    cvm__free(ctx, out->face);
    cvm__free(ctx, out->fmark);
    memset(out, 0, sizeof *out);
}

#ifndef CVM_WITH_TETGEN
int cvm__tetgen_available(void)
{
    return 0;
}

cvm_status cvm__tetgen_recover(cvm__ctx *ctx, const cvm__surf3 *s, cvm__tet3_out *out)
{
    (void)s;
    memset(out, 0, sizeof *out);
    return cvm__error(ctx, CVM_E_UNSUPPORTED, CVM_ENT_NONE, -1,
                      "boundary recovery needs TetGen, and this build of cvmesh has none "
                      "(built with TETGEN=0: BSD-only)");
}
#endif
