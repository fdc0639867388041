/* spatial_sort.c - biased randomised insertion order (BRIO, Amenta, Choi, Rote 2003) with Hilbert-curve order inside each round. */
#include <string.h>

#include "delaunay_internal.h"
#include "spatial_sort.h"

/* Index of cell (x, y) along the Hilbert curve of order 16 (a 65536^2 grid). */
static uint32_t hilbert_d(uint32_t x, uint32_t y)
{
    uint32_t rx, ry, s, d = 0;
    for (s = 1u << 15; s > 0; s >>= 1) {
        rx = (x & s) > 0;
        ry = (y & s) > 0;
        d += s * s * ((3 * rx) ^ ry);
        if (ry == 0) {
            if (rx == 1) {
                x = s - 1 - x;
                y = s - 1 - y;
            }
            { uint32_t t = x; x = y; y = t; }
        }
    }
    return d;
}

/* Stable LSD radix sort of idx[lo..hi) by key, 16 bits per pass. */
static void radix_sort(uint32_t *key, int32_t *idx, uint32_t *ktmp, int32_t *itmp, size_t n,
                       size_t *count)
{
    int pass;
    size_t i;
    for (pass = 0; pass < 2; pass++) {
        int shift = 16 * pass;
        size_t sum = 0;
        memset(count, 0, 65536 * sizeof(size_t));
        for (i = 0; i < n; i++)
            count[(key[i] >> shift) & 0xFFFFu]++;
        for (i = 0; i < 65536; i++) {
            size_t c = count[i];
            count[i] = sum;
            sum += c;
        }
        for (i = 0; i < n; i++) {
            size_t dst = count[(key[i] >> shift) & 0xFFFFu]++;
            ktmp[dst] = key[i];
            itmp[dst] = idx[i];
        }
        memcpy(key, ktmp, n * sizeof *key);
        memcpy(idx, itmp, n * sizeof *idx);
    }
}

cvm_status cvm__brio_order(cvm__ctx *ctx, const double *xy, size_t n, uint64_t seed,
                           int32_t *order)
{
    double lo[2], hi[2], sc[2];
    size_t i, start, end;
    uint32_t *key, *ktmp;
    int32_t *itmp;
    size_t *count;
    cvm__rng rng;
    cvm_status s = CVM_OK;

    if (n == 0)
        return CVM_OK;
    key = cvm__malloc(ctx, n * sizeof *key);
    ktmp = cvm__malloc(ctx, n * sizeof *ktmp);
    itmp = cvm__malloc(ctx, n * sizeof *itmp);
    count = cvm__malloc(ctx, 65536 * sizeof *count);
    if (!key || !ktmp || !itmp || !count) {
        s = CVM_E_NOMEM;
        goto done;
    }
    lo[0] = hi[0] = xy[0];
    lo[1] = hi[1] = xy[1];
    for (i = 1; i < n; i++) {
        int k;
        for (k = 0; k < 2; k++) {
            double c = xy[2 * i + k];
            if (c < lo[k])
                lo[k] = c;
            if (c > hi[k])
                hi[k] = c;
        }
    }
    for (i = 0; i < 2; i++) {
        double ext = hi[i] - lo[i];
        /* scale in two steps so huge extents do not overflow */
        sc[i] = ext > 0 ? 65535.0 / ext : 0.0;
        if (!(sc[i] < 1e300))
            sc[i] = 0.0;
    }
    /* random permutation (Fisher-Yates) */
    cvm__rng_seed(&rng, seed);
    for (i = 0; i < n; i++)
        order[i] = (int32_t)i;
    for (i = n - 1; i > 0; i--) {
        size_t j = (size_t)cvm__rng_below(&rng, i + 1);
        int32_t t = order[i];
        order[i] = order[j];
        order[j] = t;
    }
    /* rounds: the last holds about half the points, the one before a quarter, ... */
    end = n;
    while (end > 0) {
        start = end / 2 < 256 ? 0 : end / 2;
        if (end - start > 1) {
            for (i = start; i < end; i++) {
                const double *p = xy + 2 * (size_t)order[i];
                double fx = (p[0] - lo[0]) * sc[0], fy = (p[1] - lo[1]) * sc[1];
                uint32_t x = fx > 65535.0 ? 65535u : fx > 0 ? (uint32_t)fx : 0u;
                uint32_t y = fy > 65535.0 ? 65535u : fy > 0 ? (uint32_t)fy : 0u;
                key[i] = hilbert_d(x, y);
            }
            radix_sort(key + start, order + start, ktmp, itmp, end - start, count);
        }
        end = start;
    }
done:
    cvm__free(ctx, key);
    cvm__free(ctx, ktmp);
    cvm__free(ctx, itmp);
    cvm__free(ctx, count);
    return s;
}
