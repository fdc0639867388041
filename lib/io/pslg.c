/* pslg.c - releases the arrays of a cvm__pslg and keeps the file origin of its items. */
#include <string.h>

#include "io_internal.h"

void cvm__item_src_free(cvm__ctx *ctx, cvm__item_src *s)
{
    cvm__free(ctx, s->file);
    cvm__free(ctx, s->run);
    memset(s, 0, sizeof *s);
}

cvm_status cvm__item_src_add(cvm__ctx *ctx, cvm__item_src *s, const char *file, int64_t num,
                             int64_t line)
{
    if (!s->file) {
        size_t n = strlen(file) + 1;
        if (!(s->file = cvm__malloc(ctx, n)))
            return CVM_E_NOMEM;
        memcpy(s->file, file, n);
    }
    if (s->n == 0 || num != s->last_num + 1 || line != s->last_line + 1) {
        if (cvm__grow(ctx, (void **)&s->run, &s->cap, 3 * (s->nrun + 1), sizeof *s->run))
            return CVM_E_NOMEM;
        s->run[3 * s->nrun] = (int64_t)s->n;
        s->run[3 * s->nrun + 1] = num;
        s->run[3 * s->nrun + 2] = line;
        s->nrun++;
    }
    s->n++;
    s->last_num = num;
    s->last_line = line;
    return CVM_OK;
}

int cvm__item_src_get(const cvm__item_src *s, size_t k, int64_t *num, int64_t *line)
{
    size_t lo = 0, hi;
    const int64_t *r;
    *num = (int64_t)k;
    *line = 0;
    if (!s->file || s->nrun == 0)
        return 0;
    if (k >= s->n) {
        *num = (int64_t)k + s->run[1];
        return 0;
    }
    hi = s->nrun; /* the last run whose first item is <= k: runs are sorted, run 0 starts at 0 */
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        if (s->run[3 * mid] <= (int64_t)k)
            lo = mid;
        else
            hi = mid;
    }
    r = s->run + 3 * lo;
    *num = r[1] + ((int64_t)k - r[0]);
    *line = r[2] + ((int64_t)k - r[0]);
    return 1;
}

void cvm__pslg_free(cvm__ctx *ctx, cvm__pslg *p)
{
    cvm__free(ctx, p->xy);
    cvm__free(ctx, p->pmark);
    cvm__free(ctx, p->pattr);
    cvm__free(ctx, p->seg);
    cvm__free(ctx, p->smark);
    cvm__free(ctx, p->holes);
    cvm__free(ctx, p->regions);
    cvm__item_src_free(ctx, &p->src_point);
    cvm__item_src_free(ctx, &p->src_segment);
    cvm__item_src_free(ctx, &p->src_hole);
    cvm__item_src_free(ctx, &p->src_region);
    memset(p, 0, sizeof *p);
}
