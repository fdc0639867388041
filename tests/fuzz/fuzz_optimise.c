/*
 * fuzz_optimise.c - libFuzzer target: bytes -> a small PSLG (fuzz_pslg.h) ->
 * triangulate -> refine (uniform size, Steiner budget 1500) -> optional start
 * weights -> cvm_mesh_optimise_dual() with fuzzed solver and options. Required:
 *   - the optimisation returns CVM_OK, cvm_mesh_check() and the oracle accept
 *     the mesh, and no vertex is left with an empty power cell;
 *   - input points are never removed, and keep their place with
 *     CVM_OPT_DUAL_KEEP_INPUT_POINTS; without vertex removal or insertion
 *     (CVM_OPT_DUAL_TOPOLOGY 0) the vertex count is unchanged and the run ends
 *     no worse than it started (CVM_MEASURE_DUAL_OPT_NONCOMPLIANT_*);
 *   - the library's containment (cvm_mesh_copy_dual_inside() and
 *     CVM_MEASURE_DUAL_OUTSIDE_PCT, _OUTSIDE_BOUNDARY_PCT) equals an exact
 *     recomputation here from the points, weights and triangles (the sign of
 *     |B|^2 (|C|^2 + wa - wc) - (B.C)(|B|^2 + wa - wb) in expansion arithmetic);
 *     the merge measures (CVM_MEASURE_DUAL_MERGED_PCT, _NONCOMPLIANT_PCT,
 *     _NONCOMPLIANT_BOUNDARY_PCT) equal a recomputation of the merge rule of
 *     CVM_OPT_DUAL_MERGE_TOL, up to the triangles whose merge distance lies
 *     within 1e-6 of its threshold (constructions: plain doubles);
 *     CVM_MEASURE_DUAL_OPT_NONCOMPLIANT_AFTER_PCT equals the measure;
 *   - a second run on a fresh handle gives identical points, triangles, weights.
 *
 * Option bytes (then the PSLG of fuzz_pslg.h; missing bytes read as 0):
 *   byte 0  bits 0-1 refiner (0, 1 Delaunay, 2 frontal, 3 AFLR); bit 2 cuckoo
 *           solver; 3 keep input points; 4-5 topology b % 3; 6 pre-pass (with
 *           topology); 7 start weights (-3..3) x 0.01 x size^2 by vertex
 *   byte 1  refinement minimum angle 20 + 13 b / 255 degrees
 *   byte 2  size 1.5 + (b & 15) / 4 (box units); merge tolerance 0.1 x
 *           ((b >> 4) & 3); margin 0.15, 0, 0.1, 0.25 (bits 6-7)
 *   byte 3  sweeps b & 15; max-min rounds 0, 1, 2, 5 (bits 4-5); removal trials
 *           bits 6-7 (with topology and rounds)
 *   byte 4  dual minimum angle 3 (b & 15) degrees, target angle 4 (b >> 4)
 *   byte 5  pattern budget 5 + 2 (b & 31), cuckoo budget 30 + 10 (b >> 5)
 *   byte 6  seed
 *   byte 7  layer priority 0.5 (b & 7); bit 7 the sizing is passed to the optimiser
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cvmesh.h"
#include "fuzz_pslg.h"
#include "fuzz_run.h"
#include "geom/expansion.h"
#include "support/mesh_oracle.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define FUZZ_NAME "fuzz_optimise"
#include "fuzz_require.h"

/* Tolerance of percentages computed from counts (reporting numbers). */
#define PCT_TOL 1e-9

typedef struct options {
    cvm_algorithm algo;
    double min_angle, h, merge_tol, margin, dual_min_angle, target_angle, layer_priority, seed;
    int solver, keep_input, topology, prepass, weights, sweeps, rounds, trials;
    int pattern_budget, cuckoo_budget, pass_sizing;
} options;

typedef struct output {
    cvm_status status;
    size_t nv, nt, nseg;
    double *xy, *w;
    cvm_index *tri, *nb, *seg, *map;
    int32_t *inside;
    double before, after, outside, outside_bnd, merged, noncompliant, noncompliant_bnd, vanished;
} output;

static void decode(options *o, fuzz_pslg *g, const uint8_t *data, size_t size)
{
    static const double margin[4] = {0.15, 0.0, 0.1, 0.25};
    static const int rounds[4] = {0, 1, 2, 5};
    fuzz_bytes b;
    uint8_t x[8];
    size_t i;
    b.data = data;
    b.size = size;
    b.pos = 0;
    for (i = 0; i < 8; i++)
        x[i] = fuzz_byte(&b);
    fuzz_pslg_decode(g, &b);
    memset(o, 0, sizeof *o);
    o->algo = (x[0] & 3) == 2 ? CVM_ALGO_FRONTAL : (x[0] & 3) == 3 ? CVM_ALGO_AFLR : CVM_ALGO_DELAUNAY;
    o->solver = (x[0] & 4) ? 2 : 1;
    o->keep_input = (x[0] >> 3) & 1;
    o->topology = ((x[0] >> 4) & 3) % 3;
    o->prepass = o->topology ? (x[0] >> 6) & 1 : 0;
    o->weights = (x[0] >> 7) & 1;
    o->min_angle = 20.0 + 13.0 * x[1] / 255.0;
    o->h = g->scale * (1.5 + (x[2] & 15) / 4.0);
    o->merge_tol = 0.1 * ((x[2] >> 4) & 3);
    o->margin = margin[x[2] >> 6];
    o->sweeps = x[3] & 15;
    o->rounds = rounds[(x[3] >> 4) & 3];
    o->trials = o->topology && o->rounds ? x[3] >> 6 : 0;
    o->dual_min_angle = 3.0 * (x[4] & 15);
    o->target_angle = 4.0 * (x[4] >> 4);
    o->pattern_budget = 5 + 2 * (x[5] & 31);
    o->cuckoo_budget = 30 + 10 * (x[5] >> 5);
    o->seed = x[6];
    o->layer_priority = 0.5 * (x[7] & 7);
    o->pass_sizing = x[7] >> 7;
}

static cvm_status set_options(cvm_mesh *m, const options *o)
{
    cvm_status s = CVM_OK;
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_MIN_ANGLE_DEG, o->min_angle);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_MAX_STEINER, 1500);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_SEED, o->seed);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_DUAL_SOLVER, o->solver);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_DUAL_KEEP_INPUT_POINTS, o->keep_input);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_DUAL_TOPOLOGY, o->topology);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_DUAL_PREPASS, o->prepass);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_DUAL_MERGE_TOL, o->merge_tol);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_DUAL_MARGIN, o->margin);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_DUAL_MAX_SWEEPS, o->sweeps);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_DUAL_MAXMIN_ROUNDS, o->rounds);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_DUAL_MAXMIN_TRIALS, o->trials);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_DUAL_MIN_ANGLE_DEG, o->dual_min_angle);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_DUAL_TARGET_ANGLE_DEG, o->target_angle);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_DUAL_PATTERN_BUDGET, o->pattern_budget);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_DUAL_CUCKOO_BUDGET, o->cuckoo_budget);
    if (!s) s = cvm_mesh_set_option(m, CVM_OPT_DUAL_LAYER_PRIORITY, o->layer_priority);
    return s;
}

static void fetch(cvm_mesh *m, output *o, size_t n_input)
{
    FUZZ_REQUIRE(cvm_mesh_count(&o->nv, m, CVM_ENT_VERTEX) == CVM_OK, "count");
    FUZZ_REQUIRE(cvm_mesh_count(&o->nt, m, CVM_ENT_TRIANGLE) == CVM_OK, "count");
    FUZZ_REQUIRE(cvm_mesh_count(&o->nseg, m, CVM_ENT_SEGMENT) == CVM_OK, "count");
    o->xy = (double *)fuzz_alloc(2 * o->nv * sizeof(double));
    o->w = (double *)fuzz_alloc(o->nv * sizeof(double));
    o->tri = (cvm_index *)fuzz_alloc(3 * o->nt * sizeof(cvm_index));
    o->nb = (cvm_index *)fuzz_alloc(3 * o->nt * sizeof(cvm_index));
    o->seg = (cvm_index *)fuzz_alloc(2 * o->nseg * sizeof(cvm_index));
    o->map = (cvm_index *)fuzz_alloc(n_input * sizeof(cvm_index));
    o->inside = (int32_t *)fuzz_alloc(o->nt * sizeof(int32_t));
    FUZZ_REQUIRE(cvm_mesh_copy_points(o->xy, 2 * o->nv, m) == CVM_OK, "copy_points");
    FUZZ_REQUIRE(cvm_mesh_copy_weights(o->w, o->nv, m) == CVM_OK, "copy_weights");
    FUZZ_REQUIRE(cvm_mesh_copy_cells(o->tri, 3 * o->nt, m, CVM_ENT_TRIANGLE) == CVM_OK, "cells");
    FUZZ_REQUIRE(cvm_mesh_copy_neighbors(o->nb, 3 * o->nt, m) == CVM_OK, "neighbors");
    FUZZ_REQUIRE(cvm_mesh_copy_cells(o->seg, 2 * o->nseg, m, CVM_ENT_SEGMENT) == CVM_OK, "segments");
    FUZZ_REQUIRE(cvm_mesh_copy_input_map(o->map, n_input, m) == CVM_OK, "input map");
    FUZZ_REQUIRE(cvm_mesh_copy_dual_inside(o->inside, o->nt, m) == CVM_OK, "dual inside");
    o->before = fuzz_measure(m, CVM_MEASURE_DUAL_OPT_NONCOMPLIANT_BEFORE_PCT);
    o->after = fuzz_measure(m, CVM_MEASURE_DUAL_OPT_NONCOMPLIANT_AFTER_PCT);
    o->outside = fuzz_measure(m, CVM_MEASURE_DUAL_OUTSIDE_PCT);
    o->outside_bnd = fuzz_measure(m, CVM_MEASURE_DUAL_OUTSIDE_BOUNDARY_PCT);
    o->merged = fuzz_measure(m, CVM_MEASURE_DUAL_MERGED_PCT);
    o->noncompliant = fuzz_measure(m, CVM_MEASURE_DUAL_NONCOMPLIANT_PCT);
    o->noncompliant_bnd = fuzz_measure(m, CVM_MEASURE_DUAL_NONCOMPLIANT_BOUNDARY_PCT);
    o->vanished = fuzz_measure(m, CVM_MEASURE_VANISHED_VERTICES);
}

static void release(output *o)
{
    free(o->xy);
    free(o->w);
    free(o->tri);
    free(o->nb);
    free(o->seg);
    free(o->map);
    free(o->inside);
}

static void validate(cvm_mesh *m, const fuzz_pslg *g)
{
    cvmtest_expect e;
    cvmtest_expect_init(&e);
    e.delaunay = 0; /* regular, not Delaunay: cvm_mesh_check() tests the power property */
    /* segments are walked only where no triangle along them can have been
     * carved away (holes, free segments reaching outside) */
    if (!g->nhole && !g->ninner) {
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
    if (fuzz_triangulate(m) != CVM_OK) {
        cvm_mesh_free(m);
        return 0;
    }
    FUZZ_REQUIRE(cvm_sizing_create(&sz) == CVM_OK, "sizing");
    FUZZ_REQUIRE(cvm_sizing_set_uniform(sz, op->h) == CVM_OK, "uniform size");
    s = cvm_mesh_refine(m, sz, op->algo);
    FUZZ_REQUIRE(s == CVM_OK || s == CVM_INCOMPLETE_STEINER_LIMIT, "refine returned %d: %s", (int)s,
                 cvm_mesh_errmsg(m));
    if (op->weights) {
        size_t nv, v;
        double *w;
        FUZZ_REQUIRE(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX) == CVM_OK, "count");
        w = (double *)fuzz_alloc(nv * sizeof(double));
        for (v = 0; v < nv; v++)
            w[v] = 0.01 * op->h * op->h * (double)((int)((v * 37 + (size_t)op->seed) % 7) - 3);
        s = cvm_mesh_set_weights(m, w, nv);
        free(w);
        FUZZ_REQUIRE(s == CVM_OK, "set_weights: %s", cvm_mesh_errmsg(m));
    }
    o->status = cvm_mesh_optimise_dual(m, op->pass_sizing ? sz : NULL);
    cvm_sizing_free(sz);
    FUZZ_REQUIRE(o->status == CVM_OK, "optimise_dual returned %d (%s): %s", (int)o->status,
                 cvm_status_str(o->status), cvm_mesh_errmsg(m));
    if (validate_it)
        validate(m, g);
    fetch(m, o, g->np);
    cvm_mesh_free(m);
    return 1;
}

/* ---- exact side of the power vertex -------------------------------------- */

/* Expansions here have at most EXP_MAX components (products of the 2- and
 * 4-term differences below stay far under it). */
#define EXP_MAX 2048

typedef struct expn {
    int n;
    double c[EXP_MAX];
} expn;

static void exp_diff(expn *r, double a, double b)
{
    cvm__two_diff(a, b, &r->c[1], &r->c[0]);
    r->n = 2;
}

static void exp_add(expn *r, const expn *a, const expn *b)
{
    FUZZ_REQUIRE(a->n + b->n <= EXP_MAX, "expansion too long");
    r->n = cvm__fast_expansion_sum_zeroelim(a->n, a->c, b->n, b->c, r->c);
}

static void exp_mul(expn *r, const expn *a, const expn *b)
{
    static expn acc, part, tmp; /* scratch; the fuzz target is single-threaded */
    int i;
    FUZZ_REQUIRE(2 * a->n * b->n <= EXP_MAX, "expansion too long");
    acc.n = 1;
    acc.c[0] = 0.0;
    for (i = 0; i < b->n; i++) {
        part.n = cvm__scale_expansion_zeroelim(a->n, a->c, b->c[i], part.c);
        exp_add(&tmp, &acc, &part);
        acc = tmp;
    }
    *r = acc;
}

static int exp_sign(const expn *a)
{
    double top = a->c[a->n - 1];
    return top > 0 ? 1 : top < 0 ? -1 : 0;
}

/* Sign of |B|^2 (|C|^2 + wa - wc) - (B.C)(|B|^2 + wa - wb), B = b - a,
 * C = c - a: >= 0 iff the power vertex of (a, b, c) lies on c's side of ab or
 * on it (the contract of cvm_mesh_copy_dual_inside()). */
static int power_side(const double *a, const double *b, const double *c, double wa, double wb,
                      double wc)
{
    static expn bx, by, cx, cy, wab, wac, t1, t2, bb, cc, bc, betab, betac, l, r;
    exp_diff(&bx, b[0], a[0]);
    exp_diff(&by, b[1], a[1]);
    exp_diff(&cx, c[0], a[0]);
    exp_diff(&cy, c[1], a[1]);
    exp_diff(&wab, wa, wb);
    exp_diff(&wac, wa, wc);
    exp_mul(&t1, &bx, &bx);
    exp_mul(&t2, &by, &by);
    exp_add(&bb, &t1, &t2);
    exp_mul(&t1, &cx, &cx);
    exp_mul(&t2, &cy, &cy);
    exp_add(&cc, &t1, &t2);
    exp_mul(&t1, &bx, &cx);
    exp_mul(&t2, &by, &cy);
    exp_add(&bc, &t1, &t2);
    exp_add(&betab, &bb, &wab);
    exp_add(&betac, &cc, &wac);
    exp_mul(&l, &bb, &betac);
    exp_mul(&r, &bc, &betab);
    for (t1.n = 0; t1.n < r.n; t1.n++)
        t1.c[t1.n] = -r.c[t1.n];
    exp_add(&t2, &l, &t1);
    return exp_sign(&t2);
}

/* ---- the recomputation ----------------------------------------------------- */

static int is_segment(const output *o, cvm_index a, cvm_index b)
{
    size_t k;
    for (k = 0; k < o->nseg; k++)
        if ((o->seg[2 * k] == a && o->seg[2 * k + 1] == b) || (o->seg[2 * k] == b && o->seg[2 * k + 1] == a))
            return 1;
    return 0;
}

static void power_vertex(const output *o, size_t t, double *V)
{
    const cvm_index *v = o->tri + 3 * t;
    const double *a = o->xy + 2 * v[0], *b = o->xy + 2 * v[1], *c = o->xy + 2 * v[2];
    double bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
    double d = 2.0 * (bx * cy - by * cx);
    double betab = bx * bx + by * by + (o->w[v[0]] - o->w[v[1]]);
    double betac = cx * cx + cy * cy + (o->w[v[0]] - o->w[v[2]]);
    V[0] = a[0] + (cy * betab - by * betac) / d;
    V[1] = a[1] + (bx * betac - cx * betab) / d;
}

static double pct(size_t k, size_t n)
{
    return n ? 100.0 * (double)k / (double)n : 0.0;
}

static void check_dual(const fuzz_pslg *g, const options *op, const output *o)
{
    size_t t, v, n_bnd = 0, n_out = 0, n_out_bnd = 0, n_nc = 0, n_nc_bnd = 0, n_merged = 0, n_amb = 0;
    size_t n_amb_bnd = 0, n_amb_merged = 0;
    double *vsum = (double *)fuzz_alloc(o->nv * sizeof(double)), *vcnt = (double *)fuzz_alloc(o->nv * sizeof(double));
    double *V = (double *)fuzz_alloc(2 * o->nt * sizeof(double));
    int8_t *mergeable = (int8_t *)fuzz_alloc(3 * o->nt); /* 1 yes, 0 no, -1 too close to call */
    uint8_t *bnd = (uint8_t *)fuzz_alloc(o->nv);
    FUZZ_REQUIRE(o->vanished == 0, "%g vertices with an empty power cell", o->vanished);
    /* input points stay (a duplicate maps to its first occurrence's vertex) */
    for (v = 0; v < g->np; v++) {
        cvm_index k = o->map[v];
        FUZZ_REQUIRE(k >= 0 && (size_t)k < o->nv, "input point %zu maps to %ld of %zu vertices", v, (long)k,
                     o->nv);
        if (op->keep_input)
            FUZZ_REQUIRE(o->xy[2 * k] == g->xy[2 * v] && o->xy[2 * k + 1] == g->xy[2 * v + 1],
                         "input point %zu moved to (%.17g, %.17g) with KEEP_INPUT_POINTS", v, o->xy[2 * k],
                         o->xy[2 * k + 1]);
    }
    /* a percentage of the triangles: comparable only while no vertex goes */
    if (op->topology == 0)
        FUZZ_REQUIRE(o->after <= o->before + PCT_TOL, "non-compliant %.17g%% after, %.17g%% before", o->after,
                     o->before);
    FUZZ_REQUIRE(fabs(o->after - o->noncompliant) <= PCT_TOL, "report says %.17g%% non-compliant after, "
                 "the measure %.17g%%", o->after, o->noncompliant);
    /* boundary vertices and the mean length of each vertex's domain edges */
    memset(bnd, 0, o->nv);
    for (v = 0; v < o->nv; v++)
        vsum[v] = vcnt[v] = 0.0;
    for (t = 0; t < o->nt; t++) {
        int j;
        for (j = 0; j < 3; j++) {
            cvm_index a = o->tri[3 * t + (size_t)(j + 1) % 3], b = o->tri[3 * t + (size_t)(j + 2) % 3];
            cvm_index u = o->nb[3 * t + (size_t)j];
            double len = hypot(o->xy[2 * a] - o->xy[2 * b], o->xy[2 * a + 1] - o->xy[2 * b + 1]);
            if (u < 0)
                bnd[a] = bnd[b] = 1;
            if (u >= 0 && (size_t)u < t)
                continue; /* each edge once */
            vsum[a] += len;
            vsum[b] += len;
            vcnt[a] += 1;
            vcnt[b] += 1;
        }
        power_vertex(o, t, V + 2 * t);
    }
    for (v = 0; v < o->nv; v++)
        vsum[v] = vcnt[v] > 0 ? vsum[v] / vcnt[v] : 0.0;
    for (t = 0; t < o->nt; t++) {
        int j;
        for (j = 0; j < 3; j++) {
            cvm_index a = o->tri[3 * t + (size_t)(j + 1) % 3], b = o->tri[3 * t + (size_t)(j + 2) % 3];
            cvm_index u = o->nb[3 * t + (size_t)j];
            double l, d, thr;
            int8_t *mk = mergeable + 3 * t + j;
            if (op->merge_tol <= 0 || u < 0 || is_segment(o, a, b)) {
                *mk = 0;
                continue;
            }
            l = 0.5 * (vsum[a] + vsum[b]);
            thr = op->merge_tol * l / sqrt(3.0);
            d = hypot(V[2 * t] - V[2 * (size_t)u], V[2 * t + 1] - V[2 * (size_t)u + 1]);
            *mk = fabs(d - thr) <= 1e-6 * l ? -1 : d < thr;
        }
    }
    for (t = 0; t < o->nt; t++) {
        const cvm_index *tv = o->tri + 3 * t;
        int k, out = 0, nc = 0, amb = 0, merged = 0, amb_merged = 0;
        int on_bnd = bnd[tv[0]] || bnd[tv[1]] || bnd[tv[2]];
        for (k = 0; k < 3; k++) {
            cvm_index a = tv[(k + 1) % 3], b = tv[(k + 2) % 3], c = tv[k];
            int8_t mk = mergeable[3 * t + (size_t)k];
            merged |= mk == 1;
            amb_merged |= mk == -1;
            if (power_side(o->xy + 2 * a, o->xy + 2 * b, o->xy + 2 * c, o->w[a], o->w[b], o->w[c]) >= 0)
                continue;
            out = 1;
            if (mk == 0)
                nc = 1;
            else if (mk == -1)
                amb = 1;
        }
        FUZZ_REQUIRE(o->inside[t] == !out, "triangle %zu: the library says inside %d, the exact test %d", t,
                     (int)o->inside[t], !out);
        n_bnd += on_bnd;
        n_out += out;
        n_out_bnd += out && on_bnd;
        n_nc += nc;
        n_amb += !nc && amb;
        n_nc_bnd += nc && on_bnd;
        n_amb_bnd += !nc && amb && on_bnd;
        n_merged += merged;
        n_amb_merged += !merged && amb_merged;
    }
    FUZZ_REQUIRE(fabs(o->outside - pct(n_out, o->nt)) <= PCT_TOL, "outside %.17g%%, recomputed %.17g%%",
                 o->outside, pct(n_out, o->nt));
    FUZZ_REQUIRE(fabs(o->outside_bnd - pct(n_out_bnd, n_bnd)) <= PCT_TOL,
                 "outside at the boundary %.17g%%, recomputed %.17g%%", o->outside_bnd, pct(n_out_bnd, n_bnd));
    FUZZ_REQUIRE(o->noncompliant >= pct(n_nc, o->nt) - PCT_TOL &&
                 o->noncompliant <= pct(n_nc + n_amb, o->nt) + PCT_TOL,
                 "non-compliant %.17g%%, recomputed %zu + %zu undecided of %zu", o->noncompliant, n_nc, n_amb,
                 o->nt);
    FUZZ_REQUIRE(o->noncompliant_bnd >= pct(n_nc_bnd, n_bnd) - PCT_TOL &&
                 o->noncompliant_bnd <= pct(n_nc_bnd + n_amb_bnd, n_bnd) + PCT_TOL,
                 "non-compliant at the boundary %.17g%%, recomputed %zu + %zu undecided of %zu",
                 o->noncompliant_bnd, n_nc_bnd, n_amb_bnd, n_bnd);
    FUZZ_REQUIRE(o->merged >= pct(n_merged, o->nt) - PCT_TOL &&
                 o->merged <= pct(n_merged + n_amb_merged, o->nt) + PCT_TOL,
                 "merged %.17g%%, recomputed %zu + %zu undecided of %zu", o->merged, n_merged, n_amb_merged,
                 o->nt);
    free(vsum);
    free(vcnt);
    free(V);
    free(mergeable);
    free(bnd);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_pslg g;
    options op;
    output a, b;
    decode(&op, &g, data, size);
    if (!run(&g, &op, &a, 1))
        return 0;
    check_dual(&g, &op, &a);
    if (getenv("CVM_FUZZ_VERBOSE"))
        fprintf(stderr, "%s: solver %d, topology %d: %zu vertices, %zu triangles, non-compliant %.3g%% -> "
                "%.3g%%, outside %.3g%%, merged %.3g%%\n", FUZZ_NAME, op.solver, op.topology, a.nv, a.nt,
                a.before, a.after, a.outside, a.merged);
    FUZZ_REQUIRE(run(&g, &op, &b, 0), "second run failed to triangulate");
    FUZZ_REQUIRE(a.nv == b.nv && a.nt == b.nt, "second run: %zu/%zu vertices/triangles vs %zu/%zu", b.nv,
                 b.nt, a.nv, a.nt);
    FUZZ_REQUIRE(memcmp(a.xy, b.xy, 2 * a.nv * sizeof(double)) == 0, "points differ");
    FUZZ_REQUIRE(memcmp(a.w, b.w, a.nv * sizeof(double)) == 0, "weights differ");
    FUZZ_REQUIRE(memcmp(a.tri, b.tri, 3 * a.nt * sizeof(cvm_index)) == 0, "triangles differ");
    release(&a);
    release(&b);
    return 0;
}
