/* pslg.c - releases the arrays of a cvm__pslg. */
#include <string.h>

#include "io_internal.h"

void cvm__pslg_free(cvm__ctx *ctx, cvm__pslg *p)
{
    cvm__free(ctx, p->xy);
    cvm__free(ctx, p->pmark);
    cvm__free(ctx, p->pattr);
    cvm__free(ctx, p->seg);
    cvm__free(ctx, p->smark);
    cvm__free(ctx, p->holes);
    cvm__free(ctx, p->regions);
    memset(p, 0, sizeof *p);
}
