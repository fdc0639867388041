/* hilbert3.c - 3D insertion order: biased randomised rounds (BRIO) sorted along a Hilbert curve inside each round. */
#include <string.h>

#include "delaunay3/delaunay3_internal.h"

#define HILBERT_BITS 10 /* per axis: a 1024^3 grid over the bounding box */

/* The HILBERT_BITS bits of v spread to every third bit (bit k -> bit 3 k). */
static uint32_t spread3(uint32_t v)
{
    v &= (1u << HILBERT_BITS) - 1;
    v = (v | (v << 16)) & 0x030000ffu;
    v = (v | (v << 8)) & 0x0300f00fu;
    v = (v | (v << 4)) & 0x030c30c3u;
    v = (v | (v << 2)) & 0x09249249u;
    return v;
}

/* Index of cell (x0, x1, x2) along the 3D Hilbert curve, after Skilling's
 * "Programming the Hilbert curve" (2004): undo the excess work of the
 * transpose form, Gray-encode, then interleave the bits (x0 most
 * significant). Without branches (the bits of random points are random):
 * each "if bit q is set: invert, else: exchange" goes through masks. */
static uint32_t hilbert3(uint32_t x0, uint32_t x1, uint32_t x2)
{
    uint32_t q, t, set;
    for (q = 1u << (HILBERT_BITS - 1); q > 1; q >>= 1) {
        uint32_t p = q - 1;
        x0 ^= p & (0u - (uint32_t)((x0 & q) != 0)); /* exchanging x0 with itself does nothing */
        set = 0u - (uint32_t)((x1 & q) != 0);
        t = (x0 ^ x1) & p & ~set;
        x0 ^= (p & set) | t;
        x1 ^= t;
        set = 0u - (uint32_t)((x2 & q) != 0);
        t = (x0 ^ x2) & p & ~set;
        x0 ^= (p & set) | t;
        x2 ^= t;
    }
    x1 ^= x0;
    x2 ^= x1;
    t = 0;
    for (q = 1u << (HILBERT_BITS - 1); q > 1; q >>= 1)
        t ^= (q - 1) & (0u - (uint32_t)((x2 & q) != 0));
    x0 ^= t, x1 ^= t, x2 ^= t;
    return (spread3(x0) << 2) | (spread3(x1) << 1) | spread3(x2);
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
    return cvm__tet3_brio_keys(ctx, xyz, n, seed, order, NULL);
}

cvm_status cvm__tet3_brio_keys(cvm__ctx *ctx, const double *xyz, size_t n, uint64_t seed,
                               int32_t *order, uint64_t *keep)
{
    double lo[3], sc[3];
    uint64_t *key;
    cvm__brio b;
    size_t i;
    cvm_status s;

    if (n == 0)
        return CVM_OK;
    key = cvm__malloc(ctx, n * sizeof *key);
    if (!key)
        return CVM_E_NOMEM;
    cvm__bbox_scale(xyz, n, 3, (double)(1u << HILBERT_BITS), lo, sc);
    cvm__brio_init(&b, n, 1024, seed);
    for (i = 0; i < n; i++) {
        const double *p = xyz + 3 * i;
        key[i] = ((uint64_t)cvm__brio_next_round(&b) << CVM__T3_HBITS)
                 | hilbert3(cell(p[0], lo[0], sc[0]), cell(p[1], lo[1], sc[1]),
                            cell(p[2], lo[2], sc[2]));
    }
    s = cvm__sort_by_key(ctx, key, order, n, 36);
    if (s == CVM_OK && keep)
        memcpy(keep, key, n * sizeof *key);
    cvm__free(ctx, key);
    return s;
}
