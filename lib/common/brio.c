/* brio.c - the insertion order shared by the 2D and 3D kernels: BRIO rounds, bounding-box scaling, a stable radix sort by key. */
#include <string.h>

#include "common/common_internal.h"

void cvm__brio_init(cvm__brio *b, size_t n, size_t first_round_max, uint64_t seed)
{
    b->rounds = 0;
    while ((n >> b->rounds) > first_round_max && b->rounds < 15)
        b->rounds++;
    cvm__rng_seed(&b->rng, seed);
}

int cvm__brio_next_round(cvm__brio *b)
{
    uint64_t rnd = cvm__rng_next(&b->rng);
    int tz = 0;
    while (tz < b->rounds && !(rnd & 1)) {
        rnd >>= 1;
        tz++;
    }
    return b->rounds - tz;
}

void cvm__bbox_scale(const double *x, size_t n, int dim, double cells, double *lo, double *sc)
{
    double hi[3];
    size_t i;
    int k;
    for (k = 0; k < dim; k++)
        lo[k] = hi[k] = x[k];
    for (i = 1; i < n; i++)
        for (k = 0; k < dim; k++) {
            double c = x[(size_t)dim * i + (size_t)k];
            if (c < lo[k])
                lo[k] = c;
            if (c > hi[k])
                hi[k] = c;
        }
    for (k = 0; k < dim; k++) {
        double ext = hi[k] - lo[k];
        sc[k] = ext > 0 ? cells / ext : 0.0;
        if (!(sc[k] < 1e300))
            sc[k] = 0.0;
    }
}

cvm_status cvm__sort_by_key(cvm__ctx *ctx, uint64_t *key, int32_t *order, size_t n, int bits)
{
    uint64_t *ktmp = cvm__malloc(ctx, n * sizeof *ktmp + 1);
    int32_t *itmp = cvm__malloc(ctx, n * sizeof *itmp + 1);
    size_t *count = cvm__malloc(ctx, 4096 * sizeof *count);
    cvm_status s = CVM_OK;
    size_t i;
    int shift;
    if (!ktmp || !itmp || !count) {
        s = CVM_E_NOMEM;
        goto done;
    }
    for (i = 0; i < n; i++)
        order[i] = (int32_t)i;
    for (shift = 0; shift < bits; shift += 12) {
        size_t sum = 0;
        memset(count, 0, 4096 * sizeof *count);
        for (i = 0; i < n; i++)
            count[(key[i] >> shift) & 0xFFFu]++;
        for (i = 0; i < 4096; i++) {
            size_t c = count[i];
            count[i] = sum;
            sum += c;
        }
        for (i = 0; i < n; i++) {
            size_t dst = count[(key[i] >> shift) & 0xFFFu]++;
            ktmp[dst] = key[i];
            itmp[dst] = order[i];
        }
        memcpy(key, ktmp, n * sizeof *key);
        memcpy(order, itmp, n * sizeof *order);
    }
done:
    cvm__free(ctx, ktmp);
    cvm__free(ctx, itmp);
    cvm__free(ctx, count);
    return s;
}
