/* sizing_dim.c - the dimension of a cvm_sizing's positional sources: one per handle, checked
 * when a source is added. */
#include <stdio.h>

#include "sizing_internal.h"

/* The first positional source of s, for messages. */
static void first_source(const cvm_sizing *s, char *buf, size_t n)
{
    if (s->npts)
        snprintf(buf, n, "point source 0");
    else if (s->nlines)
        snprintf(buf, n, "line source 0");
    else if (s->ntris)
        snprintf(buf, n, "triangle source 0");
    else
        snprintf(buf, n, "the background mesh");
}

void cvm__sizing_recount_dim(cvm_sizing *s)
{
    if (!s->npts && !s->nlines && !s->ntris && !s->bg && !s->bg3)
        s->dim = 0;
}

cvm_status cvm__sizing_check_dim(cvm_sizing *s, int dim, const char *call)
{
    char first[64];
    if (s->dim == 0 || s->dim == dim)
        return CVM_OK;
    first_source(s, first, sizeof first);
    return cvm__error(&s->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                      "%s: a sizing holds sources of one dimension, and this one holds %dD "
                      "sources (%s); use another handle for %dD",
                      call, s->dim, first, dim);
}
