/*
 * fuzz_refine.c - libFuzzer target: bytes -> a small PSLG (fuzz_pslg.h) and
 * refinement options -> triangulate -> refine. Required of every run that does
 * not fail (a failure needs a message and is allowed only before refinement):
 *   - it stops: at the Steiner budget at the latest (CVM_OPT_MAX_STEINER; the
 *     libFuzzer time-out catches a hang), with CVM_OK or
 *     CVM_INCOMPLETE_STEINER_LIMIT and no more Steiner points than the budget;
 *   - cvm_mesh_check() and the independent oracle accept the mesh;
 *   - the report is true, measured here from the coordinates: every triangle
 *     with an angle below the requested minimum, an area above CVM_OPT_MAX_AREA
 *     or a circumradius above the uniform size (0.707 x the size after
 *     CVM_ALGO_FRONTAL and CVM_ALGO_AFLR) is in the unmet list with that
 *     reason; every listed triangle has a reason that holds; the counts and
 *     CVM_MEASURE_REFINE_MET_ANGLE agree with the list; a triangle exempt as
 *     subtended by a small input angle has two corners on one shell (within
 *     0.2%) around an input point or a crossing of input segments, seen from
 *     there under less than 60 degrees;
 *   - with CVM_OK, what is promised: every unmet triangle is an exempt one,
 *     lies on a boundary edge that is not axis-parallel (the documented
 *     hull limitation), or has its three corners on one input segment (a
 *     rounded crossing or split point a few ulps off it, within a segment
 *     chain's tolerance 2^-40 (M + L): the documented rounding limitation);
 *   - a second run on a fresh handle gives identical points and triangles.
 *
 * Option bytes (then the PSLG of fuzz_pslg.h; missing bytes read as 0):
 *   byte 0  bits 0-1 algorithm (0, 1 Delaunay, 2 frontal, 3 AFLR); 2 diametral
 *           lens; 3 march segments; 4 KEEP_SEGMENT_VERTICES = 0 (with a size);
 *           5 keep the convex hull; 6 a uniform size; 7 a maximum area
 *   byte 1  minimum angle 20 + 13 b / 255 degrees
 *   byte 2  size 1 + (b & 31) / 4 (box units)
 *   byte 3  maximum area 0.5 + b / 16 (squared box units)
 *   byte 4  smooth sweeps (b & 7) - 1, smooth method (b >> 3) & 3, relax sweeps
 *           ((b >> 5) & 7) - 1
 *   byte 5  bit 0 swap; bits 1-2 AFLR smooth layers (AFLR only); bits 3-5 the
 *           Steiner budget (5000 for 0-3, else 20, 100, 400, 1500)
 *   byte 6  seed
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cvmesh.h"
#include "fuzz_pslg.h"
#include "fuzz_run.h"
#include "support/mesh_oracle.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define FUZZ_NAME "fuzz_refine"
#include "fuzz_require.h"

#define DEG (180.0 / 3.14159265358979323846)
/* Tolerances of the measured (not decided) quantities: angles in degrees, and
 * relative for areas and radii. */
#define ANGLE_TOL 1e-9
#define REL_TOL 1e-9

typedef struct options {
    cvm_algorithm algo;
    int lens, march, keep_seg, keep_hull, swap, aflr_layers;
    double min_angle, h, max_area; /* h, max_area: 0 = none; in mesh units */
    int smooth_sweeps, smooth_method, relax_sweeps;
    double max_steiner, seed;
} options;

typedef struct output {
    cvm_status tri_status, status;
    size_t nv0, nv, nt, nunmet;
    double *xy, *unmet;
    cvm_index *tri, *nb;
    double steiner, unmet_angle, unmet_size, small_angle, met_angle, requested;
} output;

static void decode(options *o, fuzz_pslg *g, const uint8_t *data, size_t size)
{
    static const double budget[8] = {5000, 5000, 5000, 5000, 20, 100, 400, 1500};
    fuzz_bytes b;
    uint8_t b0, b1, b2, b3, b4, b5, b6;
    b.data = data;
    b.size = size;
    b.pos = 0;
    b0 = fuzz_byte(&b);
    b1 = fuzz_byte(&b);
    b2 = fuzz_byte(&b);
    b3 = fuzz_byte(&b);
    b4 = fuzz_byte(&b);
    b5 = fuzz_byte(&b);
    b6 = fuzz_byte(&b);
    fuzz_pslg_decode(g, &b);
    memset(o, 0, sizeof *o);
    o->algo = (b0 & 3) == 2 ? CVM_ALGO_FRONTAL : (b0 & 3) == 3 ? CVM_ALGO_AFLR : CVM_ALGO_DELAUNAY;
    o->lens = (b0 >> 2) & 1;
    o->march = (b0 >> 3) & 1;
    o->keep_hull = (b0 >> 5) & 1;
    o->min_angle = 20.0 + 13.0 * b1 / 255.0;
    if (b0 & 64)
        o->h = g->scale * (1.0 + (b2 & 31) / 4.0);
    if (b0 & 128)
        o->max_area = g->scale * g->scale * (0.5 + b3 / 16.0);
    o->keep_seg = o->h > 0 && ((b0 >> 4) & 1);
    o->smooth_sweeps = (b4 & 7) - 1;
    o->smooth_method = (b4 >> 3) & 3;
    o->relax_sweeps = ((b4 >> 5) & 7) - 1;
    o->swap = b5 & 1;
    o->aflr_layers = o->algo == CVM_ALGO_AFLR ? (b5 >> 1) & 3 : 0;
    o->max_steiner = budget[(b5 >> 3) & 7];
    o->seed = b6;
}

static cvm_status set_options(cvm_mesh *m, const options *o)
{
    cvm_status s = CVM_OK;
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_KEEP_CONVEX_HULL, o->keep_hull);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_MIN_ANGLE_DEG, o->min_angle);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_MAX_AREA, o->max_area);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_ENCROACH_LENS, o->lens);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_MARCH_SEGMENTS, o->march);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_KEEP_SEGMENT_VERTICES, o->keep_seg ? 0 : 1);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_SWAP, o->swap);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_SMOOTH_SWEEPS, o->smooth_sweeps);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_SMOOTH_METHOD, o->smooth_method);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_RELAX_SWEEPS, o->relax_sweeps);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_AFLR_SMOOTH_LAYERS, o->aflr_layers);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_MAX_STEINER, o->max_steiner);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_SEED, o->seed);
    return s;
}

static void fetch(cvm_mesh *m, output *o)
{
    FUZZ_REQUIRE(cvm_mesh_count(&o->nv, m, CVM_ENT_VERTEX) == CVM_OK, "count");
    FUZZ_REQUIRE(cvm_mesh_count(&o->nt, m, CVM_ENT_TRIANGLE) == CVM_OK, "count");
    FUZZ_REQUIRE(cvm_mesh_count(&o->nunmet, m, CVM_ENT_REFINE_UNMET) == CVM_OK, "count");
    o->xy = (double *)fuzz_alloc(2 * o->nv * sizeof(double));
    o->tri = (cvm_index *)fuzz_alloc(3 * o->nt * sizeof(cvm_index));
    o->nb = (cvm_index *)fuzz_alloc(3 * o->nt * sizeof(cvm_index));
    o->unmet = (double *)fuzz_alloc(3 * o->nunmet * sizeof(double));
    FUZZ_REQUIRE(cvm_mesh_copy_points(o->xy, 2 * o->nv, m) == CVM_OK, "copy_points");
    FUZZ_REQUIRE(cvm_mesh_copy_cells(o->tri, 3 * o->nt, m, CVM_ENT_TRIANGLE) == CVM_OK, "cells");
    FUZZ_REQUIRE(cvm_mesh_copy_neighbors(o->nb, 3 * o->nt, m) == CVM_OK, "neighbors");
    FUZZ_REQUIRE(cvm_mesh_copy_refine_unmet(o->unmet, 3 * o->nunmet, m) == CVM_OK, "unmet");
    o->steiner = fuzz_measure(m, CVM_MEASURE_REFINE_STEINER);
    o->unmet_angle = fuzz_measure(m, CVM_MEASURE_REFINE_UNMET_ANGLE);
    o->unmet_size = fuzz_measure(m, CVM_MEASURE_REFINE_UNMET_SIZE);
    o->small_angle = fuzz_measure(m, CVM_MEASURE_REFINE_SMALL_INPUT_ANGLE);
    o->met_angle = fuzz_measure(m, CVM_MEASURE_REFINE_MET_ANGLE);
    o->requested = fuzz_measure(m, CVM_MEASURE_REFINE_REQUESTED_ANGLE);
}

static void release(output *o)
{
    free(o->xy);
    free(o->tri);
    free(o->nb);
    free(o->unmet);
}

static void validate(cvm_mesh *m, const fuzz_pslg *g, const options *op)
{
    cvmtest_expect e;
    if (op->keep_seg) {
        fuzz_validate(m, NULL); /* the oracle needs every input point in the mesh (the input map has -1) */
        return;
    }
    cvmtest_expect_init(&e);
    /* Input segments are walked only where no triangle along them can have
     * been carved away (holes, free segments reaching outside). */
    if (!g->nhole && (op->keep_hull || !g->ninner)) {
        e.segs = g->seg;
        e.nseg = g->nseg;
    }
    fuzz_validate(m, &e);
}

static int run(const fuzz_pslg *g, const options *op, output *o, int validate_it)
{
    cvm_mesh *m;
    cvm_sizing *sz = NULL;
    cvm_status s;
    memset(o, 0, sizeof *o);
    m = fuzz_pslg_mesh(g);
    s = set_options(m, op);
    FUZZ_REQUIRE(s == CVM_OK, "setting options: %s", cvm_mesh_errmsg(m));
    o->tri_status = fuzz_triangulate(m);
    if (o->tri_status != CVM_OK) {
        cvm_mesh_free(m);
        return 0;
    }
    FUZZ_REQUIRE(cvm_mesh_count(&o->nv0, m, CVM_ENT_VERTEX) == CVM_OK, "count");
    if (op->h > 0) {
        FUZZ_REQUIRE(cvm_sizing_create(&sz) == CVM_OK, "sizing");
        FUZZ_REQUIRE(cvm_sizing_set_uniform(sz, op->h) == CVM_OK, "uniform size");
    }
    o->status = cvm_mesh_refine(m, sz, op->algo);
    cvm_sizing_free(sz);
    FUZZ_REQUIRE(o->status == CVM_OK || o->status == CVM_INCOMPLETE_STEINER_LIMIT,
                 "refine returned %d (%s): %s", (int)o->status, cvm_status_str(o->status),
                 cvm_mesh_errmsg(m));
    if (validate_it)
        validate(m, g, op);
    fetch(m, o);
    cvm_mesh_free(m);
    return 1;
}

static double dist(const double *a, const double *b)
{
    return hypot(a[0] - b[0], a[1] - b[1]);
}

/* Where input segments i and j cross in both interiors (a floating-point
 * test: only used to find the centre of an exempt angle). */
static int crossing(const fuzz_pslg *g, size_t i, size_t j, double *x)
{
    const double *p = g->xy + 2 * g->seg[2 * i], *p2 = g->xy + 2 * g->seg[2 * i + 1];
    const double *q = g->xy + 2 * g->seg[2 * j], *q2 = g->xy + 2 * g->seg[2 * j + 1];
    double rx = p2[0] - p[0], ry = p2[1] - p[1], sx = q2[0] - q[0], sy = q2[1] - q[1];
    double den = rx * sy - ry * sx, t, u;
    if (den == 0)
        return 0;
    t = ((q[0] - p[0]) * sy - (q[1] - p[1]) * sx) / den;
    u = ((q[0] - p[0]) * ry - (q[1] - p[1]) * rx) / den;
    if (!(t > 0 && t < 1 && u > 0 && u < 1))
        return 0;
    x[0] = p[0] + t * rx;
    x[1] = p[1] + t * ry;
    return 1;
}

/* Two corners of the triangle at about the same distance from j and seen from
 * j under less than 60 degrees (the refiners' small-angle exemption). */
static int shell_pair(const double *j, const double *const *p)
{
    int a, b;
    for (a = 0; a < 3; a++)
        for (b = a + 1; b < 3; b++) {
            double da = dist(p[a], j), db = dist(p[b], j);
            double ux = p[a][0] - j[0], uy = p[a][1] - j[1], wx = p[b][0] - j[0], wy = p[b][1] - j[1];
            if (da > 0 && db > 0 && fabs(da - db) <= 0.002 * (da > db ? da : db) &&
                atan2(fabs(ux * wy - uy * wx), ux * wx + uy * wy) * DEG < 60.0 + 1e-6)
                return 1;
        }
    return 0;
}

static int exempt_plausible(const fuzz_pslg *g, const double *const *p)
{
    size_t i, j;
    double x[2];
    for (i = 0; i < g->np; i++)
        if (shell_pair(g->xy + 2 * i, p))
            return 1;
    for (i = 0; i < g->nseg; i++)
        for (j = i + 1; j < g->nseg; j++)
            if (crossing(g, i, j, x) && shell_pair(x, p))
                return 1;
    return 0;
}

/* Triangle t has an edge on the domain boundary that is not axis-parallel:
 * where the documented hull limitation can leave triangles unmet (a
 * floating-point hull test misjudges the slivers along nearly collinear hull
 * vertices, so any slanted boundary edge is taken). */
static int on_slanted_hull(const output *o, size_t t)
{
    int k;
    for (k = 0; k < 3; k++) {
        const double *a = o->xy + 2 * o->tri[3 * t + (size_t)(k + 1) % 3];
        const double *b = o->xy + 2 * o->tri[3 * t + (size_t)(k + 2) % 3];
        if (o->nb[3 * t + (size_t)k] < 0 && a[0] != b[0] && a[1] != b[1])
            return 1;
    }
    return 0;
}

/* 1 when the three corners of a triangle lie within 2^-40 (M + L) of one
 * input segment (M the largest coordinate, L its length; the tolerance of a
 * segment's chain, cvm_mesh_triangulate()): the triangle lies between a chain
 * and a rounded crossing or split point a few ulps off it, which no Steiner
 * point can remove (the documented rounding limitation). A looser tolerance
 * let any triangle tiny enough next to a segment pass as rounding. */
static int on_one_segment(const fuzz_pslg *g, const double *const *p)
{
    size_t i;
    int k;
    for (i = 0; i < g->nseg; i++) {
        const double *a = g->xy + 2 * g->seg[2 * i], *b = g->xy + 2 * g->seg[2 * i + 1];
        double dx = b[0] - a[0], dy = b[1] - a[1], L = hypot(dx, dy), M = 0, tol;
        int near = 1;
        for (k = 0; k < 2; k++)
            M = fmax(M, fmax(fabs(a[k]), fabs(b[k])));
        tol = 0x1p-40 * (M + L);
        for (k = 0; k < 3 && near; k++) {
            double t = ((p[k][0] - a[0]) * dx + (p[k][1] - a[1]) * dy) / (L * L);
            t = t < 0 ? 0 : t > 1 ? 1 : t;
            near = hypot(a[0] + t * dx - p[k][0], a[1] + t * dy - p[k][1]) <= tol;
        }
        if (near)
            return 1;
    }
    return 0;
}

/* 1 when some edge is shorter than 1e-9 x the coordinates around it: such
 * triangles are too small to tell apart by their centroids or to measure. */
static int has_ulp_cluster(const output *o)
{
    size_t t;
    int k;
    for (t = 0; t < o->nt; t++)
        for (k = 0; k < 3; k++) {
            const double *a = o->xy + 2 * o->tri[3 * t + (size_t)k];
            const double *b = o->xy + 2 * o->tri[3 * t + (size_t)(k + 1) % 3];
            if (dist(a, b) < 1e-9 * (fabs(a[0]) + fabs(a[1])))
                return 1;
        }
    return 0;
}

/* The report alone: its counts against its list. */
static void check_list_counts(const output *o)
{
    size_t u, n_angle = 0, n_size = 0, n_small = 0;
    for (u = 0; u < o->nunmet; u++) {
        int bits = (int)o->unmet[3 * u + 2];
        n_angle += (bits & CVM_UNMET_ANGLE) != 0;
        n_size += (bits & CVM_UNMET_SIZE) != 0;
        n_small += (bits & CVM_UNMET_SMALL_INPUT_ANGLE) != 0;
    }
    FUZZ_REQUIRE((double)n_angle == o->unmet_angle && (double)n_size == o->unmet_size &&
                 (double)n_small == o->small_angle,
                 "report counts angle/size/small %g/%g/%g, list %zu/%zu/%zu", o->unmet_angle,
                 o->unmet_size, o->small_angle, n_angle, n_size, n_small);
}

static void check_report(const fuzz_pslg *g, const options *op, const output *o)
{
    size_t t, u = 0, n_angle = 0, n_size = 0, n_small = 0;
    double met = 180.0;
    /* the circumradius bound: the size, 0.707 x the size after frontal and AFLR */
    double hb = op->algo == CVM_ALGO_FRONTAL || op->algo == CVM_ALGO_AFLR ? sqrt(0.5) * op->h : op->h;
    check_list_counts(o);
    FUZZ_REQUIRE(o->steiner <= op->max_steiner, "%g Steiner points over the budget %g", o->steiner,
                 op->max_steiner);
    FUZZ_REQUIRE(o->status != CVM_INCOMPLETE_STEINER_LIMIT || o->steiner >= op->max_steiner,
                 "stopped at the Steiner limit %g with %g points", op->max_steiner, o->steiner);
    if (!op->keep_seg)
        FUZZ_REQUIRE((double)o->nv == (double)o->nv0 + o->steiner,
                     "%zu vertices after refinement, %zu before plus %g Steiner points", o->nv,
                     o->nv0, o->steiner);
    FUZZ_REQUIRE(o->requested == op->min_angle, "requested angle %.17g, set %.17g", o->requested,
                 op->min_angle);
    if (has_ulp_cluster(o))
        return;
    for (t = 0; t < o->nt; t++) {
        const double *p[3];
        double ang, l0, l1, l2, area2, R, cx = 0, cy = 0;
        int k, listed = 0, bits = 0;
        for (k = 0; k < 3; k++)
            p[k] = o->xy + 2 * o->tri[3 * t + (size_t)k];
        /* the list is in triangle order, each entry at its triangle's centroid */
        for (k = 0; k < 3; k++) {
            cx += p[k][0] / 3;
            cy += p[k][1] / 3;
        }
        if (u < o->nunmet) {
            const double *e = o->unmet + 3 * u;
            /* the same sum, maybe in another vertex order: a few ulps apart */
            double tx = 1e-14 * (fabs(p[0][0]) + fabs(p[1][0]) + fabs(p[2][0]));
            double ty = 1e-14 * (fabs(p[0][1]) + fabs(p[1][1]) + fabs(p[2][1]));
            if (fabs(e[0] - cx) <= tx && fabs(e[1] - cy) <= ty) {
                listed = 1;
                bits = (int)e[2];
                u++;
            }
        }
        ang = cvmtest_tri_min_angle_deg(p[0], p[1], p[2]);
        l0 = dist(p[1], p[2]);
        l1 = dist(p[2], p[0]);
        l2 = dist(p[0], p[1]);
        area2 = (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]);
        R = l0 * l1 * l2 / (2 * area2);
        if (ang < op->min_angle - ANGLE_TOL)
            FUZZ_REQUIRE(bits & CVM_UNMET_ANGLE, "triangle %zu (%.17g, %.17g) has angle %.17g below %.17g "
                         "but is not listed (bits %d)", t, cx, cy, ang, op->min_angle, bits);
        if (bits & CVM_UNMET_ANGLE)
            FUZZ_REQUIRE(ang < op->min_angle + ANGLE_TOL, "triangle %zu (%.17g, %.17g) listed (bits %d, "
                         "status %d) with angle %.17g >= %.17g", t, cx, cy, bits, (int)o->status, ang,
                         op->min_angle);
        {
            /* too thin to measure in floating point (area2 <= 0): the refiner
             * classes it as the worst shape, the angle reason */
            int big = area2 > 0 && ((op->max_area > 0 && area2 / 2 > op->max_area * (1 + REL_TOL)) ||
                                    (op->h > 0 && R > hb * (1 + REL_TOL)));
            if (big)
                FUZZ_REQUIRE(bits & CVM_UNMET_SIZE, "triangle %zu (%.17g, %.17g): area %.17g (max %g), "
                             "circumradius %.17g (bound %g), not listed (bits %d)", t, cx, cy, area2 / 2,
                             op->max_area, R, hb, bits);
            if (bits & CVM_UNMET_SIZE)
                FUZZ_REQUIRE((op->max_area > 0 && area2 / 2 > op->max_area * (1 - REL_TOL)) ||
                             (op->h > 0 && R > hb * (1 - REL_TOL)),
                             "triangle %zu listed too big: area %.17g, circumradius %.17g", t, area2 / 2, R);
        }
        if (bits & CVM_UNMET_SMALL_INPUT_ANGLE) {
            FUZZ_REQUIRE(bits & CVM_UNMET_ANGLE, "triangle %zu exempt without the angle reason", t);
            FUZZ_REQUIRE(exempt_plausible(g, p), "triangle %zu (%.17g, %.17g) exempt, but no input point or "
                         "crossing sees two of its corners on one shell under < 60 degrees", t, cx, cy);
            n_small++;
        } else if (ang < met) {
            met = ang;
        }
        n_angle += (bits & CVM_UNMET_ANGLE) != 0;
        n_size += (bits & CVM_UNMET_SIZE) != 0;
        if (o->status == CVM_OK)
            FUZZ_REQUIRE(!listed || (bits & CVM_UNMET_SMALL_INPUT_ANGLE) || on_slanted_hull(o, t) ||
                         on_one_segment(g, p),
                         "refinement succeeded but left triangle %zu (%.17g, %.17g) unmet (bits %d, "
                         "angle %.17g, area %.17g, circumradius %.17g)", t, cx, cy, bits, ang, area2 / 2, R);
    }
    FUZZ_REQUIRE(u == o->nunmet, "%zu of %zu unmet entries matched no triangle in order", u, o->nunmet);
    FUZZ_REQUIRE((double)n_angle == o->unmet_angle && (double)n_size == o->unmet_size &&
                 (double)n_small == o->small_angle,
                 "report counts angle/size/small %g/%g/%g, list %zu/%zu/%zu", o->unmet_angle,
                 o->unmet_size, o->small_angle, n_angle, n_size, n_small);
    FUZZ_REQUIRE(fabs(met - o->met_angle) <= ANGLE_TOL, "met angle reported %.17g, measured %.17g",
                 o->met_angle, met);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_pslg g;
    options op;
    output a, b;
    decode(&op, &g, data, size);
    if (!run(&g, &op, &a, 1))
        return 0;
    check_report(&g, &op, &a);
    if (getenv("CVM_FUZZ_VERBOSE"))
        fprintf(stderr, "%s: algo %d, angle %.3g, size %g, area %g: status %d, %zu -> %zu vertices, %zu "
                "triangles, %zu unmet (%g small input angle), met angle %.4g\n", FUZZ_NAME, (int)op.algo,
                op.min_angle, op.h, op.max_area, (int)a.status, a.nv0, a.nv, a.nt, a.nunmet, a.small_angle,
                a.met_angle);
    FUZZ_REQUIRE(run(&g, &op, &b, 0), "second run failed to triangulate");
    FUZZ_REQUIRE(a.status == b.status, "second run gave status %d, first %d", (int)b.status, (int)a.status);
    FUZZ_REQUIRE(a.nv == b.nv && a.nt == b.nt, "second run: %zu/%zu vertices/triangles vs %zu/%zu", b.nv,
                 b.nt, a.nv, a.nt);
    FUZZ_REQUIRE(memcmp(a.xy, b.xy, 2 * a.nv * sizeof(double)) == 0, "points differ");
    FUZZ_REQUIRE(memcmp(a.tri, b.tri, 3 * a.nt * sizeof(cvm_index)) == 0, "triangles differ");
    release(&a);
    release(&b);
    return 0;
}
