/* hilbert3.c - 3D insertion order: biased randomised rounds (BRIO) sorted along a Hilbert curve inside each round. */
#include <string.h>

#include "delaunay3/delaunay3_internal.h"

#define HILBERT_BITS 10 /* per axis: a 1024^3 grid over the bounding box */

/* Index of cell x[0..2] along the 3D Hilbert curve, after Skilling's
 * "Programming the Hilbert curve" (2004): undo the excess work of the
 * transpose form, Gray-encode, then interleave the bits (x[0] most significant). */
static uint32_t hilbert3(uint32_t x0, uint32_t x1, uint32_t x2)
{
    uint32_t x[3], m = 1u << (HILBERT_BITS - 1), q, p, t, key = 0;
    int i, b;
    x[0] = x0, x[1] = x1, x[2] = x2;
    for (q = m; q > 1; q >>= 1) {
        p = q - 1;
        for (i = 0; i < 3; i++) {
            if (x[i] & q) {
                x[0] ^= p;
            } else {
                t = (x[0] ^ x[i]) & p;
                x[0] ^= t;
                x[i] ^= t;
            }
        }
    }
    for (i = 1; i < 3; i++)
        x[i] ^= x[i - 1];
    t = 0;
    for (q = m; q > 1; q >>= 1)
        if (x[2] & q)
            t ^= q - 1;
    for (i = 0; i < 3; i++)
        x[i] ^= t;
    for (b = HILBERT_BITS - 1; b >= 0; b--)
        for (i = 0; i < 3; i++)
            key = (key << 1) | ((x[i] >> b) & 1u);
    return key;
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

/* Grid cell of coordinate c: the scaled offset clamped to the grid. */
static uint32_t cell(double c, double lo, double sc)
{
    double f = (c - lo) * sc;
    const double top = (double)((1u << HILBERT_BITS) - 1);
    return f > top ? (uint32_t)top : f > 0 ? (uint32_t)f : 0u;
}

cvm_status cvm__tet3_brio_order(cvm__ctx *ctx, const double *xyz, size_t n, uint64_t seed,
                                int32_t *order)
{
    double lo[3], hi[3], sc[3];
    size_t i;
    int k, rounds = 0;
    uint64_t *key, *ktmp;
    int32_t *itmp;
    size_t *count;
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
    for (k = 0; k < 3; k++)
        lo[k] = hi[k] = xyz[k];
    for (i = 1; i < n; i++)
        for (k = 0; k < 3; k++) {
            double c = xyz[3 * i + k];
            lo[k] = c < lo[k] ? c : lo[k];
            hi[k] = c > hi[k] ? c : hi[k];
        }
    for (k = 0; k < 3; k++) {
        double ext = hi[k] - lo[k];
        sc[k] = ext > 0 ? (double)(1u << HILBERT_BITS) / ext : 0.0;
        if (!(sc[k] < 1e300))
            sc[k] = 0.0;
    }
    /* BRIO: round r = rounds - (trailing zero bits of a random word), so the
     * last round holds about half the points, the one before a quarter, ... */
    while ((n >> rounds) > 1024 && rounds < 15)
        rounds++;
    cvm__rng_seed(&rng, seed);
    for (i = 0; i < n; i++) {
        const double *p = xyz + 3 * i;
        uint64_t rnd = cvm__rng_next(&rng);
        int tz = 0;
        while (tz < rounds && !(rnd & 1)) {
            rnd >>= 1;
            tz++;
        }
        key[i] = ((uint64_t)(rounds - tz) << 30)
                 | hilbert3(cell(p[0], lo[0], sc[0]), cell(p[1], lo[1], sc[1]),
                            cell(p[2], lo[2], sc[2]));
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
