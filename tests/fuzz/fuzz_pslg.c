/* fuzz_pslg.c - bytes -> a small PSLG for the refinement and dual fuzz targets (see fuzz_pslg.h). */
#include <math.h>
#include <string.h>

#include "fuzz_pslg.h"

#define FUZZ_PI 3.14159265358979323846

uint8_t fuzz_byte(fuzz_bytes *b)
{
    uint8_t v = b->pos < b->size ? b->data[b->pos] : 0;
    b->pos++;
    return v;
}

/* Round to a multiple of 1/8 (exact in binary). */
static double round8(double x)
{
    return floor(x * 8.0 + 0.5) / 8.0;
}

static double map(const fuzz_pslg *g, double x)
{
    return g->scale * x + g->offset;
}

static size_t add_point(fuzz_pslg *g, double x, double y)
{
    size_t i = g->np++;
    g->xy[2 * i] = map(g, round8(x));
    g->xy[2 * i + 1] = map(g, round8(y));
    return i;
}

static void add_segment(fuzz_pslg *g, size_t a, size_t b)
{
    if (g->nseg >= FUZZ_PSLG_MAXS)
        return;
    if (g->xy[2 * a] == g->xy[2 * b] && g->xy[2 * a + 1] == g->xy[2 * b + 1])
        return;
    g->seg[2 * g->nseg] = (cvm_index)a;
    g->seg[2 * g->nseg + 1] = (cvm_index)b;
    g->nseg++;
}

/* A closed star-shaped polygon of n vertices around (cx, cy); radius
 * r0 + dr (b & 15) per vertex, x radius times ex. */
static void add_loop(fuzz_pslg *g, fuzz_bytes *b, size_t n, double cx, double cy, double r0,
                     double dr, double ex)
{
    size_t first = g->np, k;
    for (k = 0; k < n; k++) {
        uint8_t v = fuzz_byte(b);
        double r = r0 + dr * (v & 15);
        double jit = ((double)(v >> 4) - 8.0) / 16.0;
        double th = 2.0 * FUZZ_PI * ((double)k + 0.5 + jit) / (double)n;
        add_point(g, cx + ex * r * cos(th), cy + r * sin(th));
    }
    for (k = 0; k < n; k++)
        add_segment(g, first + k, first + (k + 1) % n);
}

void fuzz_pslg_decode(fuzz_pslg *g, fuzz_bytes *b)
{
    static const double stretch[4] = {1.0, 1.5, 2.0, 1.0};
    uint8_t b0 = fuzz_byte(b), b1 = fuzz_byte(b);
    size_t nout = 3 + (b0 & 15), nholes = (size_t)(b0 >> 6) % 3, ninner = (b1 >> 2) & 7, h, k;
    double sx;
    memset(g, 0, sizeof *g);
    g->stretch = sx = stretch[(b0 >> 4) & 3];
    switch (b1 & 3) {
    case 0: g->scale = 1.0; break;
    case 1: g->scale = 1e-3; break;
    case 2: g->scale = 1e3; break;
    default: g->scale = 1.0; g->offset = 1e3; break;
    }
    if (nout > 16)
        nout = 16;
    if (ninner > 6)
        ninner = 6;
    add_loop(g, b, nout, 8.0 * sx, 8.0, 2.0, 0.4, sx);
    for (h = 0; h < nholes; h++) {
        uint8_t hb = fuzz_byte(b), cb = fuzz_byte(b);
        size_t n = 3 + (hb & 7);
        double ex = 1.0 + ((hb >> 3) & 3);
        double cx = round8(8.0 * sx + sx * ((double)(cb & 15) - 8.0) / 2.0);
        double cy = round8(8.0 + ((double)(cb >> 4) - 8.0) / 2.0);
        add_loop(g, b, n, cx, cy, 0.5, 0.1, ex);
        g->hole[2 * h] = map(g, cx);
        g->hole[2 * h + 1] = map(g, cy);
        g->nhole++;
    }
    for (k = 0; k < ninner; k++) {
        uint8_t e0 = fuzz_byte(b), e1 = fuzz_byte(b);
        size_t a = add_point(g, sx * (e0 & 15) + 0.5, (e0 >> 4) + 0.5);
        size_t c = add_point(g, sx * (e1 & 15) + 0.5, (e1 >> 4) + 0.5), n = g->nseg;
        add_segment(g, a, c);
        g->ninner += g->nseg - n;
    }
}

cvm_status fuzz_pslg_set(cvm_mesh *m, const fuzz_pslg *g)
{
    cvm_status s = cvm_mesh_set_points(m, g->xy, g->np, 2);
    if (s == CVM_OK)
        s = cvm_mesh_set_segments(m, g->seg, g->nseg);
    if (s == CVM_OK && g->nhole)
        s = cvm_mesh_set_holes(m, g->hole, g->nhole);
    return s;
}
