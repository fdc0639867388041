/* hilbert3.c - 3D insertion order: biased randomised rounds (BRIO) sorted along a Hilbert curve inside each round. */
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
        key[i] = ((uint64_t)cvm__brio_next_round(&b) << 30)
                 | hilbert3(cell(p[0], lo[0], sc[0]), cell(p[1], lo[1], sc[1]),
                            cell(p[2], lo[2], sc[2]));
    }
    s = cvm__sort_by_key(ctx, key, order, n, 36);
    cvm__free(ctx, key);
    return s;
}
