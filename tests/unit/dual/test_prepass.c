/* test_prepass.c - the topology pre-pass of the dual optimiser (lib/dual/prepass.c, CVM_OPT_DUAL_PREPASS). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "dual/dual_tests.h"
#include "support/oom_sweep.h"
#include "support/failing_alloc.h"

/* The unit square with a slanted interior segment, Delaunay-refined at size h
 * (Delaunay refinement leaves triangles below 35 degrees for the re-seeding). */
static cvm_mesh *refined(double h)
{
    static const double pts[] = {0, 0, 1, 0, 1, 1, 0, 1, 0.2, 0.3, 0.7, 0.8};
    static const cvm_index seg[] = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5};
    cvm_mesh *m;
    cvm_sizing *s;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, pts, 6, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, seg, 5), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_uniform(s, h), CVM_OK);
    ck_assert_int_eq(cvm_mesh_refine(m, s, CVM_ALGO_DELAUNAY), CVM_OK);
    cvm_sizing_free(s);
    return m;
}

/* Segment edges as sorted coordinate quadruples (ids change with renumbering). */
static int cmp4(const void *a, const void *b)
{
    const double *x = a, *y = b;
    int i;
    for (i = 0; i < 4; i++)
        if (x[i] != y[i])
            return x[i] < y[i] ? -1 : 1;
    return 0;
}

static double *segment_coords(const dtest_mesh *d)
{
    double *c = malloc((4 * d->nseg + 1) * sizeof *c);
    size_t k;
    ck_assert_ptr_nonnull(c);
    for (k = 0; k < d->nseg; k++) {
        const double *p = d->xy + 2 * d->seg[2 * k], *q = d->xy + 2 * d->seg[2 * k + 1];
        int swap = p[0] > q[0] || (p[0] == q[0] && p[1] > q[1]);
        const double *a = swap ? q : p, *b = swap ? p : q;
        c[4 * k] = a[0];
        c[4 * k + 1] = a[1];
        c[4 * k + 2] = b[0];
        c[4 * k + 3] = b[1];
    }
    qsort(c, d->nseg, 4 * sizeof *c, cmp4);
    return c;
}

/* Smallest angle over the triangles of d, degrees (own computation). */
static double min_angle(const dtest_mesh *d)
{
    double best = 180;
    size_t t;
    int i;
    for (t = 0; t < d->nt; t++)
        for (i = 0; i < 3; i++) {
            const double *a = d->xy + 2 * d->tri[3 * t + i], *b = d->xy + 2 * d->tri[3 * t + (i + 1) % 3],
                         *c = d->xy + 2 * d->tri[3 * t + (i + 2) % 3];
            double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - a[0], vy = c[1] - a[1];
            double ang = atan2(fabs(ux * vy - uy * vx), ux * vx + uy * vy) * 180 / 3.14159265358979323846;
            if (ang < best)
                best = ang;
        }
    return best;
}

/* Share of the edges of d whose length lies in [0.5 h, 1.5 h]: the band the
 * pre-pass collapses and splits towards (PRE_SHORT, PRE_LONG in prepass.c). */
static double share_sized(const dtest_mesh *d, double h)
{
    size_t k, n = 0;
    for (k = 0; k < d->ne; k++) {
        const double *a = d->xy + 2 * d->edge[2 * k], *b = d->xy + 2 * d->edge[2 * k + 1];
        double len = hypot(b[0] - a[0], b[1] - a[1]);
        n += len >= 0.5 * h && len <= 1.5 * h;
    }
    return d->ne ? (double)n / (double)d->ne : 0;
}

/* What the pre-pass did to the mesh: smallest angle and share of edges in
 * the size band, before and after. */
typedef struct prepass_effect {
    size_t nv0, nv;
    double ang0, ang1, share0, share1;
} prepass_effect;

/* Pre-pass only (no sweep) with a uniform sizing hs on a mesh refined at 0.1:
 * checks what must hold whatever the pre-pass did; fills *e. */
static void prepass_only(double hs, prepass_effect *e)
{
    cvm_mesh *m = refined(0.1);
    cvm_sizing *s;
    dtest_mesh d0, d;
    double *c0, *c1;
    size_t k, nin, nmark0 = 0, nmark1 = 0;
    int32_t *mk;
    ck_assert_int_eq(cvm_mesh_count(&nin, m, CVM_ENT_INPUT_POINT), CVM_OK);
    dtest_get(m, &d0);
    mk = malloc((d0.nv + 1) * sizeof *mk);
    ck_assert_int_eq(cvm_mesh_copy_markers(mk, d0.nv, m, CVM_ENT_VERTEX), CVM_OK);
    for (k = 0; k < d0.nv; k++)
        nmark0 += mk[k] != 0;
    free(mk);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL_PREPASS, 1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL_MAX_SWEEPS, 0), CVM_OK);
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_uniform(s, hs), CVM_OK);
    ck_assert_msg(cvm_mesh_optimise_dual(m, s) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    cvm_sizing_free(s);
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    dtest_get(m, &d);
    /* input points kept, in place, first */
    for (k = 0; k < nin; k++)
        ck_assert(d.xy[2 * k] == d0.xy[2 * k] && d.xy[2 * k + 1] == d0.xy[2 * k + 1]);
    /* segments intact: the same constrained edges, by coordinates */
    ck_assert_uint_eq(d.nseg, d0.nseg);
    c0 = segment_coords(&d0);
    c1 = segment_coords(&d);
    ck_assert_int_eq(memcmp(c0, c1, 4 * d.nseg * sizeof *c0), 0);
    /* regular (here Delaunay) by the test's own power test */
    ck_assert_uint_eq(dtest_power_violations(&d, d.w), 0);
    /* markers follow: the marked (segment) vertices are the same number, new ones 0 */
    mk = malloc((d.nv + 1) * sizeof *mk);
    ck_assert_int_eq(cvm_mesh_copy_markers(mk, d.nv, m, CVM_ENT_VERTEX), CVM_OK);
    for (k = 0; k < d.nv; k++)
        nmark1 += mk[k] != 0;
    free(mk);
    ck_assert_uint_eq(nmark1, nmark0);
    e->nv0 = d0.nv;
    e->nv = d.nv;
    e->ang0 = min_angle(&d0);
    e->ang1 = min_angle(&d);
    e->share0 = share_sized(&d0, hs);
    e->share1 = share_sized(&d, hs);
    free(c0);
    free(c1);
    dtest_free(&d0);
    dtest_free(&d);
    cvm_mesh_free(m);
}

/* The pre-pass alone (no sweep) may lower the smallest angle, since the
 * sweeps are what raise it, but it must not make slivers: at most a halving
 * (measured: 31.1 degrees before, 19.2 after splits, 22.1 after collapses). */
START_TEST(prepass_splits_long_edges_and_keeps_input_and_segments)
{
    prepass_effect e;
    prepass_only(0.05, &e); /* every edge ~2x the size: splits */
    ck_assert_uint_gt(e.nv, e.nv0 + e.nv0 / 4);
    /* no edge was in the band before; measured 91% after */
    ck_assert_double_eq(e.share0, 0);
    ck_assert_double_gt(e.share1, 0.8);
    ck_assert_double_ge(e.ang1, 0.5 * e.ang0);
}
END_TEST

START_TEST(prepass_collapses_short_edges_and_keeps_input_and_segments)
{
    prepass_effect e;
    prepass_only(0.25, &e); /* every edge ~0.4x the size: removals */
    ck_assert_uint_lt(e.nv, e.nv0);
    /* more edges in the band: measured 45% before, 54% after */
    ck_assert_double_gt(e.share1, e.share0 + 0.05);
    ck_assert_double_ge(e.ang1, 0.5 * e.ang0);
}
END_TEST

START_TEST(prepass_reseeds_steiner_vertices_of_small_angles)
{
    cvm_mesh *m = refined(0.1);
    dtest_mesh d0, d;
    double a0;
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL_PREPASS, 1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL_MAX_SWEEPS, 0), CVM_OK);
    dtest_get(m, &d0);
    a0 = min_angle(&d0);
    ck_assert_double_lt(a0, 35.0); /* the premise: something to re-seed */
    ck_assert_msg(cvm_mesh_optimise_dual(m, NULL) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    dtest_get(m, &d);
    /* something changed: a vertex not at any former position */
    {
        size_t k, j, moved = 0;
        for (k = 0; k < d.nv && !moved; k++) {
            int found = 0;
            for (j = 0; j < d0.nv && !found; j++)
                found = d.xy[2 * k] == d0.xy[2 * j] && d.xy[2 * k + 1] == d0.xy[2 * j + 1];
            moved += !found;
        }
        ck_assert_uint_gt(moved, 0);
    }
    ck_assert_uint_eq(dtest_power_violations(&d, d.w), 0);
    dtest_free(&d0);
    dtest_free(&d);
    cvm_mesh_free(m);
}
END_TEST

/* Start weights that empty no power cell, where a split or re-seed point
 * inserted among them can: weighted Bowyer-Watson drops every vertex inside
 * the point's cavity, and where the triangulation is not regular the cavity
 * need not even be a disc. The pre-pass refuses such points, so every vertex
 * stays a corner, input points stay in place and the mesh stays regular.
 * Before the fix (fuzz finding regression_prepass_insertion_swallows_vertices)
 * scale 0.05 left a vertex without a triangle (seeds 2 and 4) and scale 0.1
 * turned a triangle over (seed 0). */
START_TEST(prepass_insertions_drop_no_weighted_vertex)
{
    static const double scale[2] = {0.05, 0.1};
    int i, seed;
    for (i = 0; i < 2; i++)
        for (seed = 0; seed < 7; seed++) {
            cvm_mesh *m = refined(0.1);
            cvm_sizing *s;
            dtest_mesh d0, d;
            size_t nin, nv0, k, t;
            double *w, van = -1;
            unsigned char *corner;
            ck_assert_int_eq(cvm_mesh_count(&nin, m, CVM_ENT_INPUT_POINT), CVM_OK);
            ck_assert_int_eq(cvm_mesh_count(&nv0, m, CVM_ENT_VERTEX), CVM_OK);
            w = malloc(nv0 * sizeof *w);
            ck_assert_ptr_nonnull(w);
            for (k = 0; k < nv0; k++)
                w[k] = scale[i] * 0.01 * (double)((int)((k * 37 + (size_t)seed) % 7) - 3);
            ck_assert_int_eq(cvm_mesh_set_weights(m, w, nv0), CVM_OK);
            free(w);
            /* the premise: the start keeps every vertex */
            ck_assert_int_eq(cvm_mesh_get_measure(&van, m, CVM_MEASURE_VANISHED_VERTICES), CVM_OK);
            ck_assert(van == 0);
            dtest_get(m, &d0);
            ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL_PREPASS, 1), CVM_OK);
            ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL_MAX_SWEEPS, 0), CVM_OK);
            ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
            ck_assert_int_eq(cvm_sizing_set_uniform(s, 0.05), CVM_OK); /* every edge ~2x: splits */
            ck_assert_msg(cvm_mesh_optimise_dual(m, s) == CVM_OK, "%s", cvm_mesh_errmsg(m));
            cvm_sizing_free(s);
            ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "scale %g seed %d: %s", scale[i], seed,
                          cvm_mesh_errmsg(m));
            ck_assert_int_eq(cvm_mesh_get_measure(&van, m, CVM_MEASURE_VANISHED_VERTICES), CVM_OK);
            ck_assert_msg(van == 0, "scale %g seed %d: %g vanished", scale[i], seed, van);
            dtest_get(m, &d);
            ck_assert_uint_gt(d.nv, d0.nv); /* the premise: points were inserted */
            corner = calloc(d.nv + 1, 1);
            ck_assert_ptr_nonnull(corner);
            for (t = 0; t < 3 * d.nt; t++)
                corner[d.tri[t]] = 1;
            for (k = 0; k < d.nv; k++)
                ck_assert_msg(corner[k], "scale %g seed %d: vertex %zu is in no triangle", scale[i], seed, k);
            free(corner);
            for (k = 0; k < nin; k++)
                ck_assert(d.xy[2 * k] == d0.xy[2 * k] && d.xy[2 * k + 1] == d0.xy[2 * k + 1]);
            ck_assert_uint_eq(dtest_power_violations(&d, d.w), 0);
            dtest_free(&d0);
            dtest_free(&d);
            cvm_mesh_free(m);
        }
}
END_TEST

static void run_threads(int threads, dtest_mesh *d)
{
    cvm_mesh *m = refined(0.1);
    cvm_sizing *s;
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_SEED, 777), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_THREADS, threads), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL_PREPASS, 1), CVM_OK);
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_uniform(s, 0.07), CVM_OK);
    ck_assert_msg(cvm_mesh_optimise_dual(m, s) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    cvm_sizing_free(s);
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    dtest_get(m, d);
    cvm_mesh_free(m);
}

START_TEST(prepass_same_bytes_for_1_2_4_threads)
{
    dtest_mesh a, b;
    int threads[] = {2, 4}, i;
    run_threads(1, &a);
    ck_assert_uint_eq(dtest_power_violations(&a, a.w), 0);
    for (i = 0; i < 2; i++) {
        run_threads(threads[i], &b);
        dtest_assert_identical(&a, &b);
        dtest_free(&b);
    }
    dtest_free(&a);
}
END_TEST

/* Allocation k fails (transient and persistent): CVM_OK or CVM_E_NOMEM, the
 * mesh valid, nothing leaked. */
/* the sizings of the refinement (0.25) and of the optimisation (0.12) */
typedef struct oom_sizes {
    cvm_sizing *refine, *optimise;
} oom_sizes;

static void oom_setup(cvm_mesh *m, void *arg)
{
    static const double pts[] = {0, 0, 1, 0, 1, 1, 0, 1};
    static const cvm_index seg[] = {0, 1, 1, 2, 2, 3, 3, 0};
    const oom_sizes *z = (const oom_sizes *)arg;
    ck_assert_int_eq(cvm_mesh_set_points(m, pts, 4, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, seg, 4), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_refine(m, z->refine, CVM_ALGO_DELAUNAY), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL_PREPASS, 1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_DUAL_MAX_SWEEPS, 2), CVM_OK);
}

static cvm_status oom_run(cvm_mesh *m, void *arg)
{
    return cvm_mesh_optimise_dual(m, ((const oom_sizes *)arg)->optimise);
}

START_TEST(prepass_out_of_memory_leaves_a_valid_mesh)
{
    oom_sizes z;
    ck_assert_int_eq(cvm_sizing_create(&z.refine), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_uniform(z.refine, 0.25), CVM_OK);
    ck_assert_int_eq(cvm_sizing_create(&z.optimise), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_uniform(z.optimise, 0.12), CVM_OK);
    cvmtest_oom_sweep(oom_setup, oom_run, NULL, &z);
    cvm_sizing_free(z.refine);
    cvm_sizing_free(z.optimise);
}
END_TEST

TCase *dual_prepass_tcase(void)
{
    TCase *tc = tcase_create("prepass");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, prepass_splits_long_edges_and_keeps_input_and_segments);
    tcase_add_test(tc, prepass_collapses_short_edges_and_keeps_input_and_segments);
    tcase_add_test(tc, prepass_reseeds_steiner_vertices_of_small_angles);
    tcase_add_test(tc, prepass_insertions_drop_no_weighted_vertex);
    tcase_add_test(tc, prepass_same_bytes_for_1_2_4_threads);
    tcase_add_test(tc, prepass_out_of_memory_leaves_a_valid_mesh);
    return tc;
}
