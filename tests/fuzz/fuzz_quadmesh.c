/*
 * fuzz_quadmesh.c - libFuzzer target: bytes -> a small convex polygon and a constant metric ->
 * cvm_mesh_quadmesh(). Required:
 *   - the call returns CVM_OK, or an error with a message (a polygon the harness builds is
 *     convex, so only metric and size refusals: CVM_E_ARGUMENT, CVM_E_TOO_LARGE,
 *     CVM_E_UNSUPPORTED for collinear input, CVM_E_INPUT_*);
 *   - on CVM_OK: cvm_mesh_check() accepts the triangles; every mixed cell is a quad or a
 *     triangle, strictly convex and counter-clockwise (exact orient2d at every corner);
 *     each face without a neighbour lies on an edge of the polygon (within 1e-12 of its
 *     length: the boundary points are constructions), each other face is shared reversed by its neighbour; the cells' areas sum to
 *     the polygon's (to 1e-9 relative: plain doubles); the quad count matches the report;
 *   - a second run on a fresh handle gives identical points and cells.
 *
 * Bytes (missing bytes read as 0):
 *   byte 0      number of candidate points 3 + b % 8
 *   byte 1      metric g11 = 0.5 + (b & 15) / 4, g22 = 0.5 + (b >> 4) / 4
 *   byte 2      g12 = 0.9 (b / 127.5 - 1) sqrt(g11 g22)
 *   byte 3      bits 0-2: p = 2 + 2 (b % 6); bits 3-4: recombination b % 3; bit 5 clipping;
 *               bit 6 cellwise metric
 *   byte 4      seed
 *   bytes 5...  the candidate points, one byte each: (b & 15, b >> 4) / 4
 * The domain is the convex hull of the candidates (exact integer arithmetic).
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>

#include "cvmesh.h"
#include "geom/geom_internal.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define FUZZ_NAME "fuzz_quadmesh"
#include "fuzz_require.h"

typedef struct out {
    cvm_status st;
    size_t np, nc, nconn;
    double *xy;
    cvm_index *off, *conn, *nb;
    int32_t *types;
} out;

static uint8_t byte_at(const uint8_t *d, size_t n, size_t k)
{
    return k < n ? d[k] : 0;
}

static long cross_i(const int *o, const int *a, const int *b)
{
    return (long)(a[0] - o[0]) * (b[1] - o[1]) - (long)(a[1] - o[1]) * (b[0] - o[0]);
}

static int cmp_pt(const void *a, const void *b)
{
    const int *p = (const int *)a, *q = (const int *)b;
    return p[0] != q[0] ? p[0] - q[0] : p[1] - q[1];
}

/* The strictly convex hull (no collinear vertices) of the n points pt, counter-clockwise, into
 * hull; returns its size (monotone chain, exact on small integers). */
static int convex_hull(int (*pt)[2], int n, int (*hull)[2])
{
    int k = 0, i, t;
    qsort(pt, (size_t)n, sizeof pt[0], cmp_pt);
    for (i = 0; i < n; i++) {
        while (k >= 2 && cross_i(hull[k - 2], hull[k - 1], pt[i]) <= 0)
            k--;
        hull[k][0] = pt[i][0];
        hull[k][1] = pt[i][1];
        k++;
    }
    for (i = n - 2, t = k + 1; i >= 0; i--) {
        while (k >= t && cross_i(hull[k - 2], hull[k - 1], pt[i]) <= 0)
            k--;
        hull[k][0] = pt[i][0];
        hull[k][1] = pt[i][1];
        k++;
    }
    return k - 1;
}

static void run(out *o, const double *poly, int nh, const uint8_t *data, size_t size)
{
    cvm_mesh *m;
    cvm_sizing *s;
    cvm_index seg[32];
    double g11 = 0.5 + (byte_at(data, size, 1) & 15) / 4.0, g22 = 0.5 + (byte_at(data, size, 1) >> 4) / 4.0;
    double g12 = 0.9 * (byte_at(data, size, 2) / 127.5 - 1) * sqrt(g11 * g22);
    uint8_t b3 = byte_at(data, size, 3);
    int k;
    memset(o, 0, sizeof *o);
    FUZZ_REQUIRE(cvm_mesh_create(&m) == CVM_OK && cvm_sizing_create(&s) == CVM_OK, "create");
    FUZZ_REQUIRE(cvm_sizing_set_metric_constant(s, g11, g12, g22) == CVM_OK, "metric");
    for (k = 0; k < nh; k++) {
        seg[2 * k] = k;
        seg[2 * k + 1] = (k + 1) % nh;
    }
    FUZZ_REQUIRE(cvm_mesh_set_points(m, poly, (size_t)nh, 2) == CVM_OK, "points");
    FUZZ_REQUIRE(cvm_mesh_set_segments(m, seg, (size_t)nh) == CVM_OK, "segments");
    cvm_mesh_set_option(m, CVM_OPT_QUAD_P, 2 + 2 * ((b3 & 7) % 6));
    cvm_mesh_set_option(m, CVM_OPT_QUAD_RECOMBINE, ((b3 >> 3) & 3) % 3);
    cvm_mesh_set_option(m, CVM_OPT_QUAD_CLIP, (b3 >> 5) & 1);
    cvm_mesh_set_option(m, CVM_OPT_QUAD_CELLWISE_METRIC, (b3 >> 6) & 1);
    cvm_mesh_set_option(m, CVM_OPT_QUAD_MEAN_METRIC_VORONOI, (b3 >> 7) & 1 ? 0 : 2);
    cvm_mesh_set_option(m, CVM_OPT_SEED, byte_at(data, size, 4));
    cvm_mesh_set_option(m, CVM_OPT_QUAD_MAX_ITERATIONS, 300);
    cvm_mesh_set_option(m, CVM_OPT_QUAD_RELOCATIONS, 1);
    /* the seed's high bits: the start and the smoothing (both starts, with and without) */
    cvm_mesh_set_option(m, CVM_OPT_QUAD_INITIAL_SITES, (byte_at(data, size, 4) >> 7) & 1);
    cvm_mesh_set_option(m, CVM_OPT_QUAD_SMOOTH, (byte_at(data, size, 4) >> 6) & 1 ? 0 : 200);
    cvm_mesh_set_option(m, CVM_OPT_QUAD_ALL_QUAD, (byte_at(data, size, 4) >> 5) & 1);
    o->st = cvm_mesh_quadmesh(m, s);
    if (o->st != CVM_OK) {
        FUZZ_REQUIRE(cvm_status_is_error(o->st) && cvm_mesh_errmsg(m)[0] != '\0',
                     "status %d without a message", (int)o->st);
        FUZZ_REQUIRE(o->st != CVM_E_INTERNAL && o->st != CVM_E_NOMEM, "status %d: %s",
                     (int)o->st, cvm_mesh_errmsg(m));
    } else {
        double q = -1;
        size_t nquad = 0, c;
        FUZZ_REQUIRE(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
        FUZZ_REQUIRE(cvm_mesh_count(&o->np, m, CVM_ENT_VERTEX) == CVM_OK, "count");
        FUZZ_REQUIRE(cvm_mesh_count_cells_mixed(&o->nc, &o->nconn, m, CVM_ENT_CELL) == CVM_OK, "cells");
        o->xy = malloc(2 * o->np * sizeof *o->xy + 1);
        o->off = malloc((o->nc + 1) * sizeof *o->off);
        o->types = malloc(o->nc * sizeof *o->types + 1);
        o->conn = malloc(o->nconn * sizeof *o->conn + 1);
        o->nb = malloc(o->nconn * sizeof *o->nb + 1);
        FUZZ_REQUIRE(o->xy && o->off && o->types && o->conn && o->nb, "malloc");
        FUZZ_REQUIRE(cvm_mesh_copy_points(o->xy, 2 * o->np, m) == CVM_OK, "points");
        FUZZ_REQUIRE(cvm_mesh_copy_cells_mixed(o->off, o->nc + 1, o->types, o->nc, o->conn,
                                               o->nconn, m, CVM_ENT_CELL) == CVM_OK, "cells");
        FUZZ_REQUIRE(cvm_mesh_copy_cell_neighbors(o->nb, o->nconn, m, CVM_ENT_CELL) == CVM_OK,
                     "neighbours");
        FUZZ_REQUIRE(cvm_mesh_get_report(&q, m, CVM_REPORT_QUAD_QUADS) == CVM_OK, "report");
        for (c = 0; c < o->nc; c++)
            nquad += o->types[c] == CVM_CELL_QUAD;
        FUZZ_REQUIRE(q == (double)nquad, "report %g quads, cells %lu", q, (unsigned long)nquad);
    }
    cvm_sizing_free(s);
    cvm_mesh_free(m);
}

static void free_out(out *o)
{
    free(o->xy);
    free(o->off);
    free(o->types);
    free(o->conn);
    free(o->nb);
}

/* A face p->q without a neighbour lies on an edge of the polygon: the boundary points are
 * constructed in doubles (a + s (b - a)), so within 1e-12 of the edge's length from its line. */
static int near_line(const double *a, const double *b, const double *p)
{
    double ex = b[0] - a[0], ey = b[1] - a[1], l2 = ex * ex + ey * ey;
    double c = ex * (p[1] - a[1]) - ey * (p[0] - a[0]);
    return fabs(c) <= 1e-12 * l2;
}

static int on_polygon(const double *poly, int nh, const double *p, const double *q)
{
    int k;
    for (k = 0; k < nh; k++) {
        const double *a = poly + 2 * k, *b = poly + 2 * ((k + 1) % nh);
        if (near_line(a, b, p) && near_line(a, b, q))
            return 1;
    }
    return 0;
}

static void check_cells(const out *o, const double *poly, int nh, double area_want)
{
    size_t c;
    double area = 0;
    for (c = 0; c < o->nc; c++) {
        int n = o->off[c + 1] - o->off[c], j;
        const cvm_index *p = o->conn + o->off[c];
        FUZZ_REQUIRE((o->types[c] == CVM_CELL_QUAD && n == 4) ||
                     (o->types[c] == CVM_CELL_TRIANGLE && n == 3), "cell %lu type %d size %d",
                     (unsigned long)c, (int)o->types[c], n);
        for (j = 0; j < n; j++) {
            const double *a = o->xy + 2 * p[j], *b = o->xy + 2 * p[(j + 1) % n];
            const double *d = o->xy + 2 * p[(j + 2) % n];
            cvm_index nb = o->nb[o->off[c] + j];
            FUZZ_REQUIRE(cvm__orient2d(a, b, d) > 0, "cell %lu not strictly convex at %d",
                         (unsigned long)c, j);
            area += 0.5 * (a[0] * b[1] - a[1] * b[0]);
            if (nb < 0) {
                FUZZ_REQUIRE(on_polygon(poly, nh, a, b), "cell %lu face %d: no neighbour inside",
                             (unsigned long)c, j);
            } else {
                int no = o->off[nb + 1] - o->off[nb], i, found = 0;
                for (i = 0; i < no; i++)
                    found |= o->conn[o->off[nb] + i] == p[(j + 1) % n] &&
                             o->conn[o->off[nb] + (i + 1) % no] == p[j];
                FUZZ_REQUIRE(found, "cells %lu and %ld share no face", (unsigned long)c, (long)nb);
            }
        }
    }
    FUZZ_REQUIRE(fabs(area - area_want) <= 1e-9 * area_want, "area %.17g, polygon %.17g", area,
                 area_want);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    int pt[16][2], hull[34][2], n = 3 + byte_at(data, size, 0) % 8, nh, k;
    double poly[68], area = 0;
    out a, b;
    for (k = 0; k < n; k++) {
        uint8_t v = byte_at(data, size, 5 + (size_t)k);
        pt[k][0] = v & 15;
        pt[k][1] = v >> 4;
    }
    nh = convex_hull(pt, n, hull);
    if (nh < 3)
        return 0; /* collinear candidates: no polygon */
    for (k = 0; k < nh; k++) {
        poly[2 * k] = hull[k][0] / 4.0;
        poly[2 * k + 1] = hull[k][1] / 4.0;
    }
    for (k = 0; k < nh; k++)
        area += 0.5 * (poly[2 * k] * poly[2 * ((k + 1) % nh) + 1] -
                       poly[2 * k + 1] * poly[2 * ((k + 1) % nh)]);
    run(&a, poly, nh, data, size);
    if (a.st == CVM_OK)
        check_cells(&a, poly, nh, area);
    run(&b, poly, nh, data, size);
    FUZZ_REQUIRE(a.st == b.st, "second run: status %d, first %d", (int)b.st, (int)a.st);
    if (a.st == CVM_OK)
        FUZZ_REQUIRE(a.np == b.np && a.nc == b.nc && a.nconn == b.nconn &&
                         !memcmp(a.xy, b.xy, 2 * a.np * sizeof *a.xy) &&
                         !memcmp(a.off, b.off, (a.nc + 1) * sizeof *a.off) &&
                         !memcmp(a.conn, b.conn, a.nconn * sizeof *a.conn),
                     "second run differs");
    free_out(&a);
    free_out(&b);
    return 0;
}
