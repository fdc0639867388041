/* spatial_sort.c - biased randomised insertion order (BRIO, Amenta, Choi, Rote 2003) with Hilbert-curve order inside each round. */
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

cvm_status cvm__brio_order(cvm__ctx *ctx, const double *xy, size_t n, uint64_t seed,
                           int32_t *order)
{
    double lo[2], sc[2];
    uint64_t *key;
    cvm__brio b;
    size_t i;
    cvm_status s;

    if (n == 0)
        return CVM_OK;
    key = cvm__malloc(ctx, n * sizeof *key);
    if (!key)
        return CVM_E_NOMEM;
    cvm__bbox_scale(xy, n, 2, 65535.0, lo, sc);
    cvm__brio_init(&b, n, 256, seed);
    for (i = 0; i < n; i++) {
        const double *p = xy + 2 * i;
        double fx = (p[0] - lo[0]) * sc[0], fy = (p[1] - lo[1]) * sc[1];
        uint32_t x = fx > 65535.0 ? 65535u : fx > 0 ? (uint32_t)fx : 0u;
        uint32_t y = fy > 65535.0 ? 65535u : fy > 0 ? (uint32_t)fy : 0u;
        key[i] = ((uint64_t)cvm__brio_next_round(&b) << 32) | hilbert_d(x, y);
    }
    s = cvm__sort_by_key(ctx, key, order, n, 36);
    cvm__free(ctx, key);
    return s;
}
