/* test_aflr.c - advancing-front local reconnection (lib/refine/aflr.c) through cvm_mesh_refine. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "refine/refine_tests.h"
#include "support/failing_alloc.h"
#include "support/oom_sweep.h"
#include "support/mesh_oracle.h"

#define PI 3.14159265358979323846

void rtest_small_angle_terminates(cvm_algorithm algo, double angle, double h);
void rtest_jagged_star(cvm_algorithm algo, unsigned long seed);

START_TEST(square_meets_angle_and_size)
{
    rtest_shared_geometry("square.poly", 0.03, 1, CVM_ALGO_AFLR);
}
END_TEST

START_TEST(channel_meets_angle_and_size)
{
    rtest_shared_geometry("channel.poly", 0.05, 1, CVM_ALGO_AFLR);
}
END_TEST

START_TEST(annulus_meets_angle_and_size)
{
    rtest_shared_geometry("annulus.poly", 0.2, 0, CVM_ALGO_AFLR);
}
END_TEST

START_TEST(cylinder_meets_angle_and_size)
{
    rtest_shared_geometry("cylinder.poly", 0.5, 0, CVM_ALGO_AFLR);
}
END_TEST

START_TEST(naca0012_meets_angle_and_size)
{
    rtest_shared_geometry("naca0012.poly", 0.5, 0, CVM_ALGO_AFLR);
}
END_TEST

/* No size and 34 degrees on the cylinder and the NACA 0012: nothing but the
 * shortest input edge bounded the AFLR pass, whose points cascaded to that
 * scale (5.9 million on the cylinder, and a run past its time limit). Now
 * it finishes (CVM_OK) within a Steiner budget a few times what Delaunay
 * refinement needs (557 and 1582 points), valid and at 34 degrees. */
static void sizeless_34(const char *name)
{
    char path[1024];
    cvm_mesh *m;
    cvm_index *segs;
    size_t nseg;
    rtest_quality q;
    double steiner;
    cvm_status s;
    cvmtest_expect e;
    rtest_data_path(path, sizeof path, name);
    segs = rtest_poly_segments(path, &nseg);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_msg(cvm_mesh_read(m, path) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_MIN_ANGLE_DEG, 34), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_MAX_STEINER, 100000), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    s = cvm_mesh_refine(m, NULL, CVM_ALGO_AFLR);
    ck_assert_msg(s == CVM_OK, "%s: %s: %s", name, cvm_status_str(s), cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_get_measure(&steiner, m, CVM_MEASURE_REFINE_STEINER), CVM_OK);
    ck_assert_msg(steiner <= 10000, "%s: %g Steiner points", name, steiner);
    cvmtest_expect_init(&e);
    e.segs = segs;
    e.nseg = nseg;
    cvmtest_assert_valid_ex(m, &e);
    rtest_measure(m, &q);
    ck_assert_msg(q.min_angle >= 34.0 - 1e-9, "%s: min angle %.17g", name, q.min_angle);
    free(segs);
    cvm_mesh_free(m);
}

START_TEST(sizeless_34_degrees_terminates)
{
    sizeless_34("cylinder.poly");
    sizeless_34("naca0012.poly");
}
END_TEST

START_TEST(three_degree_wedge_terminates)
{
    rtest_small_angle_terminates(CVM_ALGO_AFLR, 3.0, 0.01);
}
END_TEST

START_TEST(jagged_star_terminates)
{
    rtest_jagged_star(CVM_ALGO_AFLR, 7);
    rtest_jagged_star(CVM_ALGO_AFLR, 8);
}
END_TEST

/* Points and triangles of m (caller frees). */
static void af_fetch(cvm_mesh *m, double **xy, size_t *nv, cvm_index **tri, size_t *nt)
{
    ck_assert_int_eq(cvm_mesh_count(nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    *xy = malloc((2 * *nv + 1) * sizeof **xy);
    *tri = malloc((3 * *nt + 1) * sizeof **tri);
    ck_assert_int_eq(cvm_mesh_copy_points(*xy, 2 * *nv, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(*tri, 3 * *nt, m, CVM_ENT_TRIANGLE), CVM_OK);
}

/* A random polygon with two holes: an outer ring of 48 points at radius
 * 0.75..0.95 and two rings of 14 points at radius 0.1..0.14 around
 * (-0.35, 0) and (0.35, 0.05); every input angle is far above 60 degrees.
 * The input segments (2 per segment) go to segs. */
static size_t af_holed_polygon(cvm_mesh *m, unsigned long seed, cvm_index *segs)
{
    static const double cx[3] = {0, -0.35, 0.35}, cy[3] = {0, 0, 0.05};
    static const double r0[3] = {0.75, 0.1, 0.1}, r1[3] = {0.95, 0.14, 0.14};
    static const size_t n[3] = {48, 14, 14};
    double xy[2 * 76], holes[4] = {-0.35, 0, 0.35, 0.05};
    size_t k = 0, ring, i;
    for (ring = 0; ring < 3; ring++) {
        size_t first = k;
        for (i = 0; i < n[ring]; i++, k++) {
            double t = 2 * PI * (double)i / (double)n[ring], r;
            seed = seed * 6364136223846793005ul + 1442695040888963407ul;
            r = r0[ring] + (r1[ring] - r0[ring]) * (double)(seed >> 11) / 9007199254740992.0;
            xy[2 * k] = cx[ring] + r * cos(t);
            xy[2 * k + 1] = cy[ring] + r * sin(t);
            segs[2 * k] = (cvm_index)k;
            segs[2 * k + 1] = (cvm_index)(i + 1 < n[ring] ? k + 1 : first);
        }
    }
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, k, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, segs, k), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_holes(m, holes, 2), CVM_OK);
    return k;
}

/* A random polygon with two holes (seed), refined by AFLR at 0.04 with
 * CVM_OPT_AFLR_SMOOTH_LAYERS nsm; its segments into segs, their number returned. */
static size_t af_holed_refined(cvm_mesh **m, unsigned long seed, int nsm, cvm_index *segs)
{
    size_t nseg;
    ck_assert_int_eq(cvm_mesh_create(m), CVM_OK);
    nseg = af_holed_polygon(*m, seed, segs);
    ck_assert_int_eq(cvm_mesh_set_option(*m, CVM_OPT_AFLR_SMOOTH_LAYERS, nsm), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(*m), CVM_OK);
    ck_assert_int_eq(rtest_refine_uniform(*m, 0.04, CVM_ALGO_AFLR), CVM_OK);
    return nseg;
}

START_TEST(random_polygon_with_holes_meets_bounds)
{
    unsigned long seed;
    for (seed = 1; seed <= 3; seed++) {
        cvm_mesh *m[2];
        cvm_index segs[2 * 76];
        size_t nseg = af_holed_refined(&m[0], seed, 0, segs);
        rtest_quality q;
        char what[64];
        af_holed_refined(&m[1], seed, 0, segs);
        snprintf(what, sizeof what, "seed %lu", seed);
        /* conforming, every segment kept, two holes, angle and size bounds */
        rtest_assert_refined(m[0], what, segs, nseg, 0, 1 - 2, 0.04, &q);
        rtest_assert_identical(m[0], m[1]);
        cvm_mesh_free(m[0]);
        cvm_mesh_free(m[1]);
    }
}
END_TEST

/* The unit square refined at uniform size h with algo. */
static cvm_mesh *af_square(double h, cvm_algorithm algo)
{
    static const double sq[] = {0, 0, 1, 0, 1, 1, 0, 1};
    static const cvm_index seg[] = {0, 1, 1, 2, 2, 3, 3, 0};
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, sq, 4, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, seg, 4), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(rtest_refine_uniform(m, h, algo), CVM_OK);
    return m;
}

/* Distance of a point of the unit square to its boundary. */
static double af_wall(const double *p)
{
    double d = p[0];
    d = p[1] < d ? p[1] : d;
    d = 1 - p[0] < d ? 1 - p[0] : d;
    return 1 - p[1] < d ? 1 - p[1] : d;
}

/* Layer facts on the square: every triangle on the boundary has an edge of
 * layer 0 (so its index max + 0.1 x min is a whole number), at most 3, and
 * two thirds or more are in the first layer; the mean index grows with the
 * distance from the wall over the first layers (0, 2 and 4 h);
 * no triangle is left without a layer. */
START_TEST(layer_index_grows_from_the_boundary)
{
    const double h = 0.03;
    cvm_mesh *m = af_square(h, CVM_ALGO_AFLR);
    double *xy, *layer, sum[6] = {0}, cnt[6] = {0};
    cvm_index *tri;
    size_t nv, nt, t, nbnd = 0, nfirst = 0;
    int b;
    af_fetch(m, &xy, &nv, &tri, &nt);
    layer = malloc(nt * sizeof *layer);
    ck_assert_int_eq(cvm_mesh_copy_layer_index(layer, nt, m), CVM_OK);
    for (t = 0; t < nt; t++) {
        const double *p[3];
        double c[2], d;
        int k, on_wall = 0;
        for (k = 0; k < 3; k++)
            p[k] = xy + 2 * tri[3 * t + k];
        for (k = 0; k < 3; k++) {
            const double *a = p[k], *q = p[(k + 1) % 3];
            /* an edge on the boundary: both ends on the same side of the square */
            if ((a[0] == 0 && q[0] == 0) || (a[1] == 0 && q[1] == 0) || (a[0] == 1 && q[0] == 1) ||
                (a[1] == 1 && q[1] == 1))
                on_wall = 1;
        }
        ck_assert_msg(layer[t] >= 0, "triangle %lu has no layer", (unsigned long)t);
        if (on_wall) {
            nbnd++;
            ck_assert_msg(layer[t] == floor(layer[t]), "boundary triangle %lu: layer %g", (unsigned long)t,
                          layer[t]);
            nfirst += layer[t] <= 1.0;
            ck_assert_msg(layer[t] <= 3.0, "boundary triangle %lu: layer %g", (unsigned long)t, layer[t]);
        }
        c[0] = (p[0][0] + p[1][0] + p[2][0]) / 3;
        c[1] = (p[0][1] + p[1][1] + p[2][1]) / 3;
        d = af_wall(c) / h;
        for (b = 0; b < 6; b++)
            if (d >= 2.0 * b && d < 2.0 * b + 1) {
                sum[b] += layer[t];
                cnt[b]++;
            }
    }
    ck_assert_uint_gt(nbnd, 100);
    ck_assert_msg(3 * nfirst >= 2 * nbnd, "%lu of %lu boundary triangles in layer 1", (unsigned long)nfirst,
                  (unsigned long)nbnd);
    for (b = 1; b < 3; b++) {
        ck_assert(cnt[b] > 0 && cnt[b - 1] > 0);
        ck_assert_msg(sum[b] / cnt[b] > sum[b - 1] / cnt[b - 1],
                      "mean layer %g at %d h from the wall, %g at %d h", sum[b] / cnt[b], 2 * b,
                      sum[b - 1] / cnt[b - 1], 2 * b - 2);
    }
    free(layer);
    free(xy);
    free(tri);
    cvm_mesh_free(m);
}
END_TEST

/* Without AFLR every layer is -1; a marker that no segment has starts no
 * front, and the clean-up still meets the bounds. Buffer rules. */
START_TEST(layer_index_without_fronts)
{
    cvm_mesh *m = af_square(0.05, CVM_ALGO_DELAUNAY);
    int32_t nomark = 99;
    rtest_quality q;
    double *layer;
    size_t nt, t;
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    layer = malloc((nt + 1) * sizeof *layer);
    ck_assert_int_eq(cvm_mesh_copy_layer_index(layer, nt, m), CVM_OK);
    for (t = 0; t < nt; t++)
        ck_assert_double_eq(layer[t], -1);
    ck_assert_int_eq(cvm_mesh_copy_layer_index(layer, nt - 1, m), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_layer_index(NULL, 3, m), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_layer_index(layer, nt, NULL), CVM_E_NULL_ARG);
    free(layer);
    cvm_mesh_free(m);

    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    {
        static const double sq[] = {0, 0, 1, 0, 1, 1, 0, 1};
        static const cvm_index seg[] = {0, 1, 1, 2, 2, 3, 3, 0};
        ck_assert_int_eq(cvm_mesh_set_points(m, sq, 4, 2), CVM_OK);
        ck_assert_int_eq(cvm_mesh_set_segments(m, seg, 4), CVM_OK);
    }
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_front_markers(m, &nomark, 1), CVM_OK);
    ck_assert_int_eq(rtest_refine_uniform(m, 0.05, CVM_ALGO_AFLR), CVM_OK);
    cvmtest_assert_valid(m);
    rtest_measure(m, &q);
    ck_assert(q.min_angle >= 30.0 - 1e-9);
    ck_assert(q.max_circumradius <= 0.05 * (1 + 1e-9));
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    layer = malloc(nt * sizeof *layer);
    ck_assert_int_eq(cvm_mesh_copy_layer_index(layer, nt, m), CVM_OK);
    for (t = 0; t < nt; t++)
        ck_assert_double_eq(layer[t], -1);
    free(layer);
    cvm_mesh_free(m);
}
END_TEST

/* AFLR on the square is far more regular than Delaunay refinement, measured here. */
START_TEST(aflr_is_regular_on_the_square)
{
    cvm_mesh *m = af_square(0.03, CVM_ALGO_AFLR);
    double *xy;
    cvm_index *tri;
    size_t nv, nt, t, reg = 0;
    af_fetch(m, &xy, &nv, &tri, &nt);
    for (t = 0; t < nt; t++) {
        int k;
        for (k = 0; k < 3; k++) {
            const double *o = xy + 2 * tri[3 * t + k], *u = xy + 2 * tri[3 * t + (k + 1) % 3];
            const double *w = xy + 2 * tri[3 * t + (k + 2) % 3];
            double ux = u[0] - o[0], uy = u[1] - o[1], wx = w[0] - o[0], wy = w[1] - o[1];
            double a = atan2(fabs(ux * wy - uy * wx), ux * wx + uy * wy) * 180 / PI;
            reg += a >= 55 && a <= 65;
        }
    }
    ck_assert_msg(reg >= 0.9 * 3 * (double)nt, "%lu of %lu angles in [55, 65]", (unsigned long)reg,
                  (unsigned long)(3 * nt));
    free(xy);
    free(tri);
    cvm_mesh_free(m);
}
END_TEST

/* ---- manufactured solution: -lap u = f on the unit square, u = 0 on the wall ---- */

static double af_u(const double *p)
{
    return sin(PI * p[0]) * sin(PI * p[1]);
}

/* y = K x with the P1 stiffness matrix, applied triangle by triangle; fixed
 * (boundary) rows and columns are left out (y = 0 there). */
static void af_stiffness(const double *xy, const cvm_index *tri, size_t nt, const char *fixed,
                         const double *x, double *y, size_t nv)
{
    size_t t, i;
    for (i = 0; i < nv; i++)
        y[i] = 0;
    for (t = 0; t < nt; t++) {
        const cvm_index *v = tri + 3 * t;
        double g[3][2], area;
        int a, b;
        for (a = 0; a < 3; a++) {
            const double *p = xy + 2 * v[(a + 1) % 3], *q = xy + 2 * v[(a + 2) % 3];
            g[a][0] = p[1] - q[1]; /* gradient of the hat function x 2 area */
            g[a][1] = q[0] - p[0];
        }
        {
            const double *a0 = xy + 2 * v[0], *a1 = xy + 2 * v[1], *a2 = xy + 2 * v[2];
            area = 0.5 * fabs((a1[0] - a0[0]) * (a2[1] - a0[1]) - (a1[1] - a0[1]) * (a2[0] - a0[0]));
        }
        for (a = 0; a < 3; a++) {
            if (fixed[v[a]])
                continue;
            for (b = 0; b < 3; b++)
                if (!fixed[v[b]])
                    y[v[a]] += (g[a][0] * g[b][0] + g[a][1] * g[b][1]) / (4 * area) * x[v[b]];
        }
    }
}

/* Max nodal error of the P1 finite-element solution (consistent load, conjugate gradients). */
static double af_poisson_error(cvm_mesh *m)
{
    double *xy, *b, *x, *r, *p, *q, rr, err = 0;
    cvm_index *tri;
    char *fixed;
    size_t nv, nt, t, i, it;
    af_fetch(m, &xy, &nv, &tri, &nt);
    b = calloc(nv, sizeof *b);
    x = calloc(nv, sizeof *x);
    r = calloc(nv, sizeof *r);
    p = calloc(nv, sizeof *p);
    q = calloc(nv, sizeof *q);
    fixed = calloc(nv, 1);
    for (i = 0; i < nv; i++)
        fixed[i] = af_wall(xy + 2 * i) == 0;
    for (t = 0; t < nt; t++) {
        const cvm_index *v = tri + 3 * t;
        const double *a = xy + 2 * v[0], *c = xy + 2 * v[1], *d = xy + 2 * v[2];
        double area = 0.5 * fabs((c[0] - a[0]) * (d[1] - a[1]) - (c[1] - a[1]) * (d[0] - a[0]));
        double f[3];
        int k;
        for (k = 0; k < 3; k++)
            f[k] = 2 * PI * PI * af_u(xy + 2 * v[k]);
        for (k = 0; k < 3; k++)
            if (!fixed[v[k]])
                b[v[k]] += area / 12 * (2 * f[k] + f[(k + 1) % 3] + f[(k + 2) % 3]);
    }
    for (i = 0; i < nv; i++)
        r[i] = p[i] = b[i];
    for (rr = 0, i = 0; i < nv; i++)
        rr += r[i] * r[i];
    for (it = 0; it < 10 * nv && rr > 1e-28; it++) {
        double pq = 0, alpha, rr2 = 0;
        af_stiffness(xy, tri, nt, fixed, p, q, nv);
        for (i = 0; i < nv; i++)
            pq += p[i] * q[i];
        alpha = rr / pq;
        for (i = 0; i < nv; i++) {
            x[i] += alpha * p[i];
            r[i] -= alpha * q[i];
            rr2 += r[i] * r[i];
        }
        for (i = 0; i < nv; i++)
            p[i] = r[i] + rr2 / rr * p[i];
        rr = rr2;
    }
    for (i = 0; i < nv; i++)
        if (fabs(x[i] - af_u(xy + 2 * i)) > err)
            err = fabs(x[i] - af_u(xy + 2 * i));
    free(xy);
    free(tri);
    free(b);
    free(x);
    free(r);
    free(p);
    free(q);
    free(fixed);
    return err;
}

/* The manufactured-solution check of issue 4: at the same sizing the AFLR
 * mesh gives a lower maximum nodal error than the Delaunay-refinement mesh,
 * and still does against a Delaunay mesh refined to h / 1.4, which has more
 * vertices than the AFLR mesh (counted here). */
START_TEST(poisson_error_lower_on_aflr_than_delaunay)
{
    static const double hs[3] = {0.05, 0.05, 0.05 / 1.4};
    static const cvm_algorithm algo[3] = {CVM_ALGO_AFLR, CVM_ALGO_DELAUNAY, CVM_ALGO_DELAUNAY};
    double e[3];
    size_t nv[3];
    int k;
    for (k = 0; k < 3; k++) {
        cvm_mesh *m = af_square(hs[k], algo[k]);
        e[k] = af_poisson_error(m);
        ck_assert_int_eq(cvm_mesh_count(&nv[k], m, CVM_ENT_VERTEX), CVM_OK);
        cvm_mesh_free(m);
    }
    ck_assert_msg(e[0] > 0 && e[0] < e[1], "max nodal error: AFLR %g, Delaunay %g", e[0], e[1]);
    ck_assert_msg(nv[2] > nv[0], "Delaunay at h / 1.4: %lu vertices, AFLR %lu", (unsigned long)nv[2],
                  (unsigned long)nv[0]);
    ck_assert_msg(e[0] < e[2], "max nodal error: AFLR %g (%lu vertices), Delaunay %g (%lu vertices)",
                  e[0], (unsigned long)nv[0], e[2], (unsigned long)nv[2]);
}
END_TEST

/* Out of memory at every allocation of an AFLR refinement (transient and
 * persistent): CVM_OK or CVM_E_NOMEM, nothing leaks, and the mesh, when kept,
 * is a valid constrained Delaunay triangulation whose layer copy works. */
static void oom_setup(cvm_mesh *m, void *arg)
{
    (void)arg;
    rtest_set_unit_square(m);
}

static cvm_status oom_run(cvm_mesh *m, void *arg)
{
    (void)arg;
    return rtest_refine_uniform(m, 0.1, CVM_ALGO_AFLR);
}

/* the layer copy works on every mesh the run leaves */
static void oom_check(cvm_mesh *m, void *arg)
{
    size_t nt;
    double *layer;
    (void)arg;
    cvmtest_assert_valid(m);
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    layer = malloc((nt + 1) * sizeof *layer);
    ck_assert_int_eq(cvm_mesh_copy_layer_index(layer, nt, m), CVM_OK);
    free(layer);
}

START_TEST(out_of_memory_keeps_a_valid_mesh)
{
    cvmtest_oom_sweep(oom_setup, oom_run, oom_check, NULL);
}
END_TEST

/* ---- smoothing interleaved with the layers (CVM_OPT_AFLR_SMOOTH_LAYERS) ---- */

/* 1 when a and b have different points or triangles. */
static int af_differ(cvm_mesh *a, cvm_mesh *b)
{
    double *xa, *xb;
    cvm_index *ta, *tb;
    size_t nva, nta, nvb, ntb;
    int d;
    af_fetch(a, &xa, &nva, &ta, &nta);
    af_fetch(b, &xb, &nvb, &tb, &ntb);
    d = nva != nvb || nta != ntb || memcmp(xa, xb, 2 * nva * sizeof *xa) != 0 ||
        memcmp(ta, tb, 3 * nta * sizeof *ta) != 0;
    free(xa);
    free(xb);
    free(ta);
    free(tb);
    return d;
}

/* A shared geometry read, triangulated and refined by AFLR at size h with
 * CVM_OPT_AFLR_SMOOTH_LAYERS = nsm. */
static cvm_mesh *af_shared_layers(const char *path, double h, int nsm)
{
    cvm_mesh *m;
    cvm_status s;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_msg(cvm_mesh_read(m, path) == CVM_OK, "%s: %s", path, cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_AFLR_SMOOTH_LAYERS, nsm), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    s = rtest_refine_uniform(m, h, CVM_ALGO_AFLR);
    ck_assert_msg(s == CVM_OK, "%s: %s", path, cvm_mesh_errmsg(m));
    return m;
}

/* With the option on (N = 1 and 2): valid, every segment kept, every angle >=
 * 30 degrees and every circumradius <= h by the test's own measure, a second
 * run bit-identical, and a mesh that differs from the one without it. */
static void af_layers_geometry(const char *name, double h, long euler)
{
    char path[1024];
    size_t nseg;
    cvm_index *segs;
    cvm_mesh *off;
    int nsm;
    rtest_data_path(path, sizeof path, name);
    segs = rtest_poly_segments(path, &nseg);
    off = af_shared_layers(path, h, 0);
    for (nsm = 1; nsm <= 2; nsm++) {
        cvm_mesh *m = af_shared_layers(path, h, nsm), *m2 = af_shared_layers(path, h, nsm);
        rtest_quality q;
        char what[160];
        snprintf(what, sizeof what, "%s, N %d", name, nsm);
        rtest_assert_refined(m, what, segs, nseg, 0, euler, h, &q);
        rtest_assert_identical(m, m2);
        ck_assert_msg(af_differ(m, off), "%s, N %d: same mesh as without the option", name, nsm);
        cvm_mesh_free(m);
        cvm_mesh_free(m2);
    }
    cvm_mesh_free(off);
    free(segs);
}

START_TEST(smooth_layers_square)
{
    af_layers_geometry("square.poly", 0.03, 1);
}
END_TEST

START_TEST(smooth_layers_naca0012)
{
    af_layers_geometry("naca0012.poly", 0.5, 0);
}
END_TEST

START_TEST(smooth_layers_random_polygon_with_holes)
{
    unsigned long seed;
    for (seed = 1; seed <= 3; seed++) {
        cvm_mesh *m[3];
        cvm_index segs[2 * 76];
        size_t nseg = af_holed_refined(&m[0], seed, 1, segs);
        rtest_quality q;
        char what[64];
        int r;
        af_holed_refined(&m[1], seed, 1, segs);
        af_holed_refined(&m[2], seed, 0, segs);
        snprintf(what, sizeof what, "seed %lu, N 1", seed);
        rtest_assert_refined(m[0], what, segs, nseg, 0, 1 - 2, 0.04, &q);
        rtest_assert_identical(m[0], m[1]);
        ck_assert_msg(af_differ(m[0], m[2]), "seed %lu: same mesh as without the option", seed);
        for (r = 0; r < 3; r++)
            cvm_mesh_free(m[r]);
    }
}
END_TEST

/* Frontal and Delaunay refinement have no layers: a non-zero value is refused
 * with CVM_E_UNSUPPORTED naming the option, and the mesh is left as it was. */
START_TEST(smooth_layers_refused_without_aflr)
{
    static const cvm_algorithm algos[2] = {CVM_ALGO_FRONTAL, CVM_ALGO_DELAUNAY};
    int a;
    for (a = 0; a < 2; a++) {
        cvm_mesh *m;
        size_t nv0, nv1;
        cvm_entity kind = CVM_ENT_NONE;
        int64_t index = -1;
        ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
        rtest_set_unit_square(m);
        ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_AFLR_SMOOTH_LAYERS, 2), CVM_OK);
        ck_assert_int_eq(cvm_mesh_count(&nv0, m, CVM_ENT_VERTEX), CVM_OK);
        ck_assert_int_eq(rtest_refine_uniform(m, 0.1, algos[a]), CVM_E_UNSUPPORTED);
        ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "CVM_OPT_AFLR_SMOOTH_LAYERS"));
        ck_assert_int_eq(cvm_mesh_error_item(&kind, &index, m), CVM_OK);
        ck_assert_int_eq(kind, CVM_ENT_OPTION);
        ck_assert_int_eq(index, CVM_OPT_AFLR_SMOOTH_LAYERS);
        ck_assert_int_eq(cvm_mesh_count(&nv1, m, CVM_ENT_VERTEX), CVM_OK);
        ck_assert_uint_eq(nv0, nv1);
        /* 0 is accepted */
        ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_AFLR_SMOOTH_LAYERS, 0), CVM_OK);
        ck_assert_int_eq(rtest_refine_uniform(m, 0.1, algos[a]), CVM_OK);
        cvm_mesh_free(m);
    }
}
END_TEST

static cvm_status oom_run_layers(cvm_mesh *m, void *arg)
{
    (void)arg;
    if (cvm_mesh_set_option(m, CVM_OPT_AFLR_SMOOTH_LAYERS, 1) != CVM_OK)
        return CVM_E_INTERNAL;
    return rtest_refine_uniform(m, 0.1, CVM_ALGO_AFLR);
}

START_TEST(smooth_layers_out_of_memory_keeps_a_valid_mesh)
{
    cvmtest_oom_sweep(oom_setup, oom_run_layers, oom_check, NULL);
}
END_TEST

TCase *refine_aflr_tcase(void)
{
    TCase *tc = tcase_create("aflr");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, square_meets_angle_and_size);
    tcase_add_test(tc, channel_meets_angle_and_size);
    tcase_add_test(tc, annulus_meets_angle_and_size);
    tcase_add_test(tc, cylinder_meets_angle_and_size);
    tcase_add_test(tc, sizeless_34_degrees_terminates);
    tcase_add_test(tc, naca0012_meets_angle_and_size);
    tcase_add_test(tc, three_degree_wedge_terminates);
    tcase_add_test(tc, jagged_star_terminates);
    tcase_add_test(tc, random_polygon_with_holes_meets_bounds);
    tcase_add_test(tc, layer_index_grows_from_the_boundary);
    tcase_add_test(tc, layer_index_without_fronts);
    tcase_add_test(tc, aflr_is_regular_on_the_square);
    tcase_add_test(tc, poisson_error_lower_on_aflr_than_delaunay);
    tcase_add_test(tc, out_of_memory_keeps_a_valid_mesh);
    tcase_add_test(tc, smooth_layers_square);
    tcase_add_test(tc, smooth_layers_naca0012);
    tcase_add_test(tc, smooth_layers_random_polygon_with_holes);
    tcase_add_test(tc, smooth_layers_refused_without_aflr);
    tcase_add_test(tc, smooth_layers_out_of_memory_keeps_a_valid_mesh);
    return tc;
}
