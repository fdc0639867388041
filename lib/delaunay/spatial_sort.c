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

/* Stable LSD radix sort of (key, idx) by the low `bits` bits of key, 12 bits per pass. */
static void radix_sort(uint64_t *key, int32_t *idx, uint64_t *ktmp, int32_t *itmp, size_t n,
                       size_t *count, int bits)
{
    int shift;
    size_t i;
    for (shift = 0; shift < bits; shift += 12) {
        size_t sum = 0;
        memset(count, 0, 4096 * sizeof(size_t));
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
    size_t i;
    uint64_t *key, *ktmp;
    int32_t *itmp;
    size_t *count;
    int rounds = 0;
    cvm__rng rng;
    cvm_status s = CVM_OK;

    if (n == 0)
        return CVM_OK;
    key = cvm__malloc(ctx, n * sizeof *key);
    ktmp = cvm__malloc(ctx, n * sizeof *ktmp);
    itmp = cvm__malloc(ctx, n * sizeof *itmp);
    count = cvm__malloc(ctx, 4096 * sizeof *count);
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
        sc[i] = ext > 0 ? 65535.0 / ext : 0.0;
        if (!(sc[i] < 1e300))
            sc[i] = 0.0;
    }
    /* BRIO: round r = rounds - (number of trailing zero bits of a random word),
     * so the last round holds about half the points, the one before a quarter... */
    while ((n >> rounds) > 256 && rounds < 15)
        rounds++;
    cvm__rng_seed(&rng, seed);
    for (i = 0; i < n; i++) {
        const double *p = xy + 2 * i;
        double fx = (p[0] - lo[0]) * sc[0], fy = (p[1] - lo[1]) * sc[1];
        uint32_t x = fx > 65535.0 ? 65535u : fx > 0 ? (uint32_t)fx : 0u;
        uint32_t y = fy > 65535.0 ? 65535u : fy > 0 ? (uint32_t)fy : 0u;
        uint64_t rnd = cvm__rng_next(&rng);
        int tz = 0, r;
        while (tz < rounds && !(rnd & 1)) {
            rnd >>= 1;
            tz++;
        }
        r = rounds - tz;
        key[i] = ((uint64_t)r << 32) | hilbert_d(x, y);
        order[i] = (int32_t)i;
    }
    radix_sort(key, order, ktmp, itmp, n, count, 36);
done:
    cvm__free(ctx, key);
    cvm__free(ctx, ktmp);
    cvm__free(ctx, itmp);
    cvm__free(ctx, count);
    return s;
}
