/*
 * test_sized.c - cvm_mesh_generate3_sized(): a point source (or a callback)
 * makes edges shorter near its point and the mesh stays valid; no sizing gives
 * cvm_mesh_generate3()'s bytes; the sizing's boundary grading is the surface
 * field; 2D or unsupported sizings are refused with a message; OOM at every
 * allocation.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "generate3/g3_util.h"
#include "generate3/generate3_tests.h"
#include "support/oom_sweep.h"

static cvm_mesh *read3(const char *name)
{
    cvm_mesh *m;
    char path[1024];
    g3_data3d(path, sizeof path, name);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_msg(cvm_mesh_read(m, path) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    return m;
}

/* Mean length of the edges whose midpoint lies within r of c (inside = 1) or
 * farther than r (inside = 0); *n receives their count. */
static double mean_edge(const g3_mesh *g, const double *c, double r, int inside, size_t *n)
{
    double sum = 0;
    size_t e;
    *n = 0;
    for (e = 0; e < g->ne; e++) {
        int64_t a = g->edge[e] / (int64_t)g->nv, b = g->edge[e] % (int64_t)g->nv;
        const double *p = g->xyz + 3 * a, *q = g->xyz + 3 * b;
        double mid[3], d = 0, len = 0;
        int k;
        for (k = 0; k < 3; k++) {
            mid[k] = 0.5 * (p[k] + q[k]) - c[k];
            d += mid[k] * mid[k];
            len += (p[k] - q[k]) * (p[k] - q[k]);
        }
        if ((sqrt(d) <= r) == inside) {
            sum += sqrt(len);
            (*n)++;
        }
    }
    return *n ? sum / (double)*n : 0;
}

static void copy_mesh(const cvm_mesh *m, double **xyz, size_t *nv, cvm_index **tet, size_t *nt)
{
    ck_assert_int_eq(cvm_mesh_count(nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    *xyz = malloc(3 * *nv * sizeof **xyz + 1);
    *tet = malloc(4 * *nt * sizeof **tet + 1);
    ck_assert_int_eq(cvm_mesh_copy_points_nd(*xyz, 3 * *nv, 3, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(*tet, 4 * *nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
}

static void assert_same_mesh(const cvm_mesh *a, const cvm_mesh *b)
{
    double *x0, *x1;
    cvm_index *t0, *t1;
    size_t nv0, nt0, nv1, nt1;
    copy_mesh(a, &x0, &nv0, &t0, &nt0);
    copy_mesh(b, &x1, &nv1, &t1, &nt1);
    ck_assert_uint_eq(nv0, nv1);
    ck_assert_uint_eq(nt0, nt1);
    ck_assert(memcmp(x0, x1, 3 * nv0 * sizeof *x0) == 0);
    ck_assert(memcmp(t0, t1, 4 * nt0 * sizeof *t0) == 0);
    free(x0);
    free(x1);
    free(t0);
    free(t1);
}

/* The tetrahedron (vertices (+-1, +-1, +-1), inradius 0.577) at uniform size 0.5,
 * with sizing s (NULL: cvm_mesh_generate3()). */
static cvm_mesh *tetra_mesh(const cvm_sizing *s)
{
    cvm_mesh *m = read3("tetra.off");
    cvm_status st;
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_SIZE_FROM_SURFACE, 0), CVM_OK);
    st = s ? cvm_mesh_generate3_sized(m, 0.5, s) : cvm_mesh_generate3(m, 0.5);
    ck_assert_msg(st == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    return m;
}

/* Edges near the source against edges far from it, and against the same ball
 * without the source; the volume is the tetrahedron's. */
static void assert_refined_at_origin(cvm_mesh *sized, const cvm_mesh *plain)
{
    static const double c[3] = {0, 0, 0};
    g3_mesh g, h;
    size_t n_near, n_far, n_plain;
    double near, far, near_plain, v, levels;
    g3_mesh_get(&g, sized);
    g3_mesh_get(&h, plain);
    near = mean_edge(&g, c, 0.25, 1, &n_near);
    far = mean_edge(&g, c, 0.45, 0, &n_far);
    near_plain = mean_edge(&h, c, 0.25, 1, &n_plain);
    ck_assert_uint_gt(n_near, 20);
    ck_assert_uint_gt(n_far, 20);
    ck_assert_msg(near < 0.6 * far, "near %g, far %g", near, far);
    ck_assert_msg(near < 0.6 * near_plain, "near %g, without the source %g", near, near_plain);
    ck_assert_uint_gt(g.nv, h.nv);
    ck_assert_uint_eq(g.nbnd, 4);
    ck_assert_int_eq(g3_euler(&g), 1);
    ck_assert_int_eq(cvm_mesh_get_measure(&v, sized, CVM_MEASURE_VOLUME), CVM_OK);
    ck_assert_double_eq_tol(v, 8.0 / 3.0, 1e-12);
    ck_assert_int_eq(cvm_mesh_get_report(&levels, sized, CVM_REPORT_GEN3_LATTICE_LEVELS),
                     CVM_OK);
    ck_assert_double_ge(levels, 3);
    g3_mesh_free(&g);
    g3_mesh_free(&h);
}

START_TEST(point_source_refines_near_its_point)
{
    static const double c[3] = {0, 0, 0};
    cvm_sizing *s;
    cvm_mesh *m, *plain = tetra_mesh(NULL);
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_point_source_nd(s, c, 3, 0.08, 0.3), CVM_OK);
    m = tetra_mesh(s);
    assert_refined_at_origin(m, plain);
    cvm_mesh_free(m);
    cvm_mesh_free(plain);
    cvm_sizing_free(s);
}
END_TEST

static double radial(void *payload, const double *x, int dim)
{
    int *bad_dim = payload;
    *bad_dim += dim != 3;
    return 0.08 + 0.3 * sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
}

/* The same field as a callback: no least size is known, the levels go on while
 * a level meets smaller sizes; the same mesh as the point source. */
START_TEST(callback_refines_as_the_point_source_does)
{
    static const double c[3] = {0, 0, 0};
    cvm_sizing *s, *p;
    cvm_mesh *m, *mp, *plain = tetra_mesh(NULL);
    int bad_dim = 0;
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_callback_nd(s, radial, &bad_dim), CVM_OK);
    m = tetra_mesh(s);
    ck_assert_int_eq(bad_dim, 0);
    assert_refined_at_origin(m, plain);
    ck_assert_int_eq(cvm_sizing_create(&p), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_point_source_nd(p, c, 3, 0.08, 0.3), CVM_OK);
    mp = tetra_mesh(p);
    assert_same_mesh(m, mp);
    cvm_mesh_free(m);
    cvm_mesh_free(mp);
    cvm_mesh_free(plain);
    cvm_sizing_free(s);
    cvm_sizing_free(p);
}
END_TEST

START_TEST(no_sizing_gives_the_generate3_bytes)
{
    static const double far[3] = {50, 50, 50};
    cvm_sizing *s;
    cvm_mesh *a = tetra_mesh(NULL), *b;
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    b = tetra_mesh(s); /* empty */
    assert_same_mesh(a, b);
    cvm_mesh_free(b);
    /* a source that never reaches the size cap changes nothing either */
    ck_assert_int_eq(cvm_sizing_add_point_source_nd(s, far, 3, 0.6, 0.1), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_uniform(s, 0.75), CVM_OK);
    b = tetra_mesh(s);
    assert_same_mesh(a, b);
    cvm_mesh_free(b);
    cvm_mesh_free(a);
    cvm_sizing_free(s);
}
END_TEST

/* The sizing's boundary grading g is the surface-following field of slope g. */
START_TEST(boundary_grading_is_the_surface_field)
{
    const char *name = g3_with_tetgen() ? "cube.off" : "tetra.off";
    double h = g3_with_tetgen() ? 0.25 : 0.5;
    cvm_sizing *s;
    cvm_mesh *a = read3(name), *b = read3(name);
    ck_assert_int_eq(cvm_mesh_set_option(a, CVM_OPT_GEN3_GRADING, 0.5), CVM_OK);
    ck_assert_msg(cvm_mesh_generate3(a, h) == CVM_OK, "%s", cvm_mesh_errmsg(a));
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_boundary_grading(s, 0.5), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(b, CVM_OPT_GEN3_SIZE_FROM_SURFACE, 0), CVM_OK);
    ck_assert_msg(cvm_mesh_generate3_sized(b, h, s) == CVM_OK, "%s", cvm_mesh_errmsg(b));
    assert_same_mesh(a, b);
    /* with the option on too, the smaller slope holds */
    ck_assert_int_eq(cvm_mesh_set_option(b, CVM_OPT_GEN3_SIZE_FROM_SURFACE, 1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(b, CVM_OPT_GEN3_GRADING, 2), CVM_OK);
    ck_assert_msg(cvm_mesh_generate3_sized(b, h, s) == CVM_OK, "%s", cvm_mesh_errmsg(b));
    assert_same_mesh(a, b);
    cvm_mesh_free(a);
    cvm_mesh_free(b);
    cvm_sizing_free(s);
}
END_TEST

static double negative(void *payload, const double *x, int dim)
{
    (void)payload;
    (void)dim;
    return x[0] > 0.2 ? -1 : 0.4;
}

static double size_xy(void *payload, double x, double y)
{
    (void)payload;
    (void)x;
    (void)y;
    return 0.3;
}

START_TEST(unusable_sizings_are_refused)
{
    cvm_mesh *m = read3("tetra.off");
    cvm_sizing *s;
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_mesh_generate3_sized(NULL, 0.5, s), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_generate3_sized(m, -1, s), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_sizing_add_point_source(s, 0, 0, 0.1, 0.2), CVM_OK); /* 2D */
    ck_assert_int_eq(cvm_mesh_generate3_sized(m, 0.5, s), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "2D sources"));
    cvm_sizing_free(s);
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_callback(s, size_xy, NULL), CVM_OK);
    ck_assert_int_eq(cvm_mesh_generate3_sized(m, 0.5, s), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "cvm_sizing_set_callback_nd"));
    ck_assert_int_eq(cvm_sizing_set_callback(s, NULL, NULL), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_automatic(s, 2, 4), CVM_OK);
    ck_assert_int_eq(cvm_mesh_generate3_sized(m, 0.5, s), CVM_E_UNSUPPORTED);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "automatic"));
    ck_assert_int_eq(cvm_sizing_set_automatic(s, 0, 0), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_metric_builtin(s, CVM_METRIC_IDENTITY, 1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_generate3_sized(m, 0.5, s), CVM_E_UNSUPPORTED);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "metric"));
    ck_assert_int_eq(cvm_sizing_set_metric_fn(s, NULL, 0, NULL), CVM_OK);
    /* a callback's bad size stops the run, naming the callback and the point */
    ck_assert_int_eq(cvm_sizing_set_callback_nd(s, negative, NULL), CVM_OK);
    ck_assert_int_eq(cvm_mesh_generate3_sized(m, 0.5, s), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "sizing callback"));
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "size -1"));
    /* the handle still meshes afterwards */
    ck_assert_int_eq(cvm_sizing_set_callback_nd(s, NULL, NULL), CVM_OK);
    ck_assert_msg(cvm_mesh_generate3_sized(m, 0.5, s) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    cvm_sizing_free(s);
    cvm_mesh_free(m);
}
END_TEST

static void oom_setup(cvm_mesh *m, void *arg)
{
    char path[1024];
    (void)arg;
    g3_data3d(path, sizeof path, "tetra.off");
    ck_assert_int_eq(cvm_mesh_read(m, path), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_SIZE_FROM_SURFACE, 0), CVM_OK);
}

static cvm_status oom_run(cvm_mesh *m, void *arg)
{
    return cvm_mesh_generate3_sized(m, 0.5, (const cvm_sizing *)arg);
}

START_TEST(oom_at_every_allocation_with_a_sizing)
{
    static const double c[3] = {0, 0, 0};
    cvm_sizing *s;
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_point_source_nd(s, c, 3, 0.15, 0.4), CVM_OK);
    cvmtest_oom_sweep(oom_setup, oom_run, NULL, s);
    cvm_sizing_free(s);
}
END_TEST

TCase *generate3_sized_tcase(void)
{
    TCase *tc = tcase_create("sized");
    tcase_set_timeout(tc, 300);
    tcase_add_test(tc, point_source_refines_near_its_point);
    tcase_add_test(tc, callback_refines_as_the_point_source_does);
    tcase_add_test(tc, no_sizing_gives_the_generate3_bytes);
    tcase_add_test(tc, boundary_grading_is_the_surface_field);
    tcase_add_test(tc, unusable_sizings_are_refused);
    tcase_add_test(tc, oom_at_every_allocation_with_a_sizing);
    return tc;
}
