/* test_resample.c - CVM_OPT_KEEP_SEGMENT_VERTICES = 0: smooth chains of segments re-discretised with the sizing. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "refine/refine_tests.h"
#include "support/failing_alloc.h"
#include "support/oom_sweep.h"
#include "support/mesh_oracle.h"

#define PI 3.14159265358979323846
#define N_IN 64   /* inner circle r = 1: spacing 0.098 */
#define N_OUT 128 /* outer circle r = 4: spacing 0.196 */

/* The thesis annulus as the test builds it: input points, segments (loops
 * inner then outer) and the hole. */
static void annulus_input(double *xy, cvm_index *seg, int32_t *smark)
{
    int k;
    for (k = 0; k < N_IN; k++) {
        xy[2 * k] = cos(2 * PI * k / N_IN);
        xy[2 * k + 1] = sin(2 * PI * k / N_IN);
        seg[2 * k] = k;
        seg[2 * k + 1] = (k + 1) % N_IN;
        smark[k] = 1;
    }
    for (k = 0; k < N_OUT; k++) {
        xy[2 * (N_IN + k)] = 4 * cos(2 * PI * k / N_OUT);
        xy[2 * (N_IN + k) + 1] = 4 * sin(2 * PI * k / N_OUT);
        seg[2 * (N_IN + k)] = N_IN + k;
        seg[2 * (N_IN + k) + 1] = N_IN + (k + 1) % N_OUT;
        smark[N_IN + k] = 2;
    }
}

static void set_annulus(cvm_mesh *m)
{
    static const double hole[2] = {0, 0};
    double xy[2 * (N_IN + N_OUT)];
    cvm_index seg[2 * (N_IN + N_OUT)];
    int32_t smark[N_IN + N_OUT];
    annulus_input(xy, seg, smark);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, N_IN + N_OUT, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, seg, N_IN + N_OUT), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segment_markers(m, smark, N_IN + N_OUT), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_holes(m, hole, 1), CVM_OK);
}

static double graded_size(void *payload, double x, double y)
{
    (void)payload;
    return 0.4 + (sqrt(x * x + y * y) - 1) / 2.5;
}

/* The size the test asks for: uniform h, or graded when h < 0. */
static double size_at(double h, double x, double y)
{
    return h > 0 ? h : graded_size(NULL, x, y);
}

static cvm_status refine_with(cvm_mesh *m, double h, cvm_algorithm algo)
{
    cvm_sizing *s;
    cvm_status st;
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    if (h > 0)
        ck_assert_int_eq(cvm_sizing_set_uniform(s, h), CVM_OK);
    else
        ck_assert_int_eq(cvm_sizing_set_callback(s, graded_size, NULL), CVM_OK);
    st = cvm_mesh_refine(m, s, algo);
    cvm_sizing_free(s);
    return st;
}

static int cmp_edge(const void *pa, const void *pb)
{
    const cvm_index *a = pa, *b = pb;
    cvm_index a0 = a[0] < a[1] ? a[0] : a[1], a1 = a[0] < a[1] ? a[1] : a[0];
    cvm_index b0 = b[0] < b[1] ? b[0] : b[1], b1 = b[0] < b[1] ? b[1] : b[0];
    if (a0 != b0)
        return a0 < b0 ? -1 : 1;
    return (a1 > b1) - (a1 < b1);
}

/* Boundary edges of the triangles (in one triangle only), oriented as in it;
 * caller frees. */
static cvm_index *boundary_edges(const cvm_index *tri, size_t nt, size_t *nb)
{
    cvm_index *e = malloc((6 * nt + 2) * sizeof *e), *out = malloc((6 * nt + 2) * sizeof *out);
    size_t k, n = 0;
    ck_assert(e && out);
    for (k = 0; k < 3 * nt; k++) {
        e[2 * k] = tri[k];
        e[2 * k + 1] = tri[k - k % 3 + (k + 1) % 3];
    }
    qsort(e, 3 * nt, 2 * sizeof *e, cmp_edge);
    for (k = 0; k < 3 * nt; k++) {
        if ((k > 0 && !cmp_edge(e + 2 * k, e + 2 * k - 2)) ||
            (k + 1 < 3 * nt && !cmp_edge(e + 2 * k, e + 2 * k + 2)))
            continue;
        out[2 * n] = e[2 * k];
        out[2 * n + 1] = e[2 * k + 1];
        n++;
    }
    free(e);
    *nb = n;
    return out;
}

static double seg_dist(const double *a, const double *b, const double *p)
{
    double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy, t;
    t = l2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return hypot(a[0] + t * dx - p[0], a[1] + t * dy - p[1]);
}

/* Distance from p to the input polyline (in_xy points, in_seg segments). */
static double polyline_dist(const double *in_xy, const cvm_index *in_seg, size_t nseg, const double *p)
{
    size_t k;
    double d = HUGE_VAL;
    for (k = 0; k < nseg; k++) {
        double dk = seg_dist(in_xy + 2 * (size_t)in_seg[2 * k], in_xy + 2 * (size_t)in_seg[2 * k + 1], p);
        d = dk < d ? dk : d;
    }
    return d;
}

/* What the test measures on a re-discretised mesh. */
typedef struct rs_meas {
    double min_ratio, max_ratio; /* boundary piece / size at its midpoint */
    double max_off;              /* largest distance from the input polyline of a boundary vertex
                                    where the boundary turns (the ends of the new pieces) */
    size_t n_chord_splits;       /* boundary vertices on the straight line of their neighbours
                                    (refinement split a new piece there) */
    double area, boundary_area;  /* sum of triangle areas; area enclosed by the boundary edges */
    double max_removed_dist;     /* largest distance of an input point to the output boundary */
    double perimeter;
    size_t nb;
} rs_meas;

static void measure(cvm_mesh *m, double h, const double *in_xy, size_t nin, const cvm_index *in_seg,
                    size_t nseg, rs_meas *r)
{
    double *xy;
    cvm_index *tri, *be, *out;
    size_t nv, nt, k;
    memset(r, 0, sizeof *r);
    rtest_fetch(m, &xy, &nv, &tri, &nt);
    be = boundary_edges(tri, nt, &r->nb);
    r->min_ratio = HUGE_VAL;
    for (k = 0; k < nt; k++) {
        const double *a = xy + 2 * (size_t)tri[3 * k], *b = xy + 2 * (size_t)tri[3 * k + 1],
                     *c = xy + 2 * (size_t)tri[3 * k + 2];
        r->area += 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
    }
    out = malloc((nv + 1) * sizeof *out);
    ck_assert_ptr_nonnull(out);
    for (k = 0; k < nv; k++)
        out[k] = -1;
    for (k = 0; k < r->nb; k++)
        out[be[2 * k]] = be[2 * k + 1];
    for (k = 0; k < r->nb; k++) {
        const double *a = xy + 2 * (size_t)be[2 * k], *b = xy + 2 * (size_t)be[2 * k + 1], *c;
        double len = hypot(b[0] - a[0], b[1] - a[1]);
        double ratio = len / size_at(h, 0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]));
        ck_assert_int_ge(out[be[2 * k + 1]], 0);
        c = xy + 2 * (size_t)out[be[2 * k + 1]];
        r->min_ratio = ratio < r->min_ratio ? ratio : r->min_ratio;
        r->max_ratio = ratio > r->max_ratio ? ratio : r->max_ratio;
        if (seg_dist(a, c, b) <= 1e-12 * 8.0) {
            r->n_chord_splits++;
        } else {
            double off = polyline_dist(in_xy, in_seg, nseg, b);
            r->max_off = off > r->max_off ? off : r->max_off;
        }
        r->boundary_area += 0.5 * (a[0] * b[1] - a[1] * b[0]);
        r->perimeter += len;
    }
    for (k = 0; k < nin; k++) {
        size_t j;
        double d = HUGE_VAL;
        for (j = 0; j < r->nb; j++) {
            double dj = seg_dist(xy + 2 * (size_t)be[2 * j], xy + 2 * (size_t)be[2 * j + 1], in_xy + 2 * k);
            d = dj < d ? dj : d;
        }
        r->max_removed_dist = d > r->max_removed_dist ? d : r->max_removed_dist;
    }
    free(be);
    free(out);
    free(xy);
    free(tri);
}

/* The oracle on the output (its input map is not used: inner chain vertices
 * have none), with the annulus's Euler characteristic and the measured area. */
static void assert_valid_resampled(cvm_mesh *m, long euler, double area)
{
    char msg[512];
    cvmtest_expect e;
    double *xy;
    cvm_index *tri, *seg;
    size_t nv, nt, ns;
    cvm_status s = cvm_mesh_check(m);
    ck_assert_msg(s == CVM_OK, "cvm_mesh_check: %s: %s", cvm_status_str(s), cvm_mesh_errmsg(m));
    rtest_fetch(m, &xy, &nv, &tri, &nt);
    ck_assert_int_eq(cvm_mesh_count(&ns, m, CVM_ENT_SEGMENT), CVM_OK);
    seg = malloc((2 * ns + 1) * sizeof *seg);
    ck_assert_ptr_nonnull(seg);
    ck_assert_int_eq(cvm_mesh_copy_cells(seg, 2 * ns, m, CVM_ENT_SEGMENT), CVM_OK);
    cvmtest_expect_init(&e);
    e.convex = 0;
    e.check_euler = 1;
    e.euler = euler;
    e.check_area = 1;
    e.area = area;
    ck_assert_msg(cvmtest_oracle(msg, sizeof msg, xy, nv, tri, nt, seg, ns, NULL, 0, &e),
                  "mesh oracle: %s", msg);
    free(xy);
    free(tri);
    free(seg);
}

static cvm_mesh *resampled_annulus(double h, cvm_algorithm algo)
{
    cvm_mesh *m;
    cvm_status st;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    set_annulus(m);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_KEEP_SEGMENT_VERTICES, 0), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    st = refine_with(m, h, algo);
    ck_assert_msg(st == CVM_OK, "refine: %s: %s", cvm_status_str(st), cvm_mesh_errmsg(m));
    return m;
}

/* The annulus at size h (< 0: graded) with each algorithm: the boundary
 * follows the size, lies on the input polyline, the area is that of the
 * re-discretised polygon and within the sagitta bound of the input's, the
 * mesh is valid, Delaunay, meets 30 degrees, and reruns are identical. */
static void check_annulus(double h, double lo, double hi)
{
    static const cvm_algorithm algos[] = {CVM_ALGO_DELAUNAY, CVM_ALGO_FRONTAL, CVM_ALGO_AFLR};
    double in_xy[2 * (N_IN + N_OUT)], in_area = 0;
    cvm_index in_seg[2 * (N_IN + N_OUT)];
    int32_t smark[N_IN + N_OUT];
    size_t a, k;
    annulus_input(in_xy, in_seg, smark);
    for (k = 0; k < N_IN + N_OUT; k++) {
        const double *p = in_xy + 2 * (size_t)in_seg[2 * k], *q = in_xy + 2 * (size_t)in_seg[2 * k + 1];
        /* inner loop counter-clockwise bounds the hole: subtract it */
        in_area += (k < N_IN ? -0.5 : 0.5) * (p[0] * q[1] - p[1] * q[0]);
    }
    for (a = 0; a < 3; a++) {
        cvm_mesh *m = resampled_annulus(h, algos[a]), *m2;
        rtest_quality q;
        rs_meas r;
        measure(m, h, in_xy, N_IN + N_OUT, in_seg, N_IN + N_OUT, &r);
        assert_valid_resampled(m, 0, r.boundary_area);
        ck_assert_double_le(r.max_off, 1e-12 * 8.0);
        ck_assert_double_eq_tol(r.area, r.boundary_area, 1e-12 * r.area);
        ck_assert_double_le(fabs(r.area - in_area), r.perimeter * r.max_removed_dist);
        ck_assert_double_lt(r.area, in_area); /* chords cut the outer circle, widen the hole */
        ck_assert_double_ge(r.min_ratio, lo);
        ck_assert_uint_lt(r.nb, N_IN + N_OUT); /* fewer pieces than input segments */
        ck_assert_double_le(r.max_ratio, hi);
        rtest_measure(m, &q);
        ck_assert_double_ge(q.min_angle, 30.0 - 1e-9);
        m2 = resampled_annulus(h, algos[a]);
        rtest_assert_identical(m, m2);
        cvm_mesh_free(m2);
        cvm_mesh_free(m);
    }
}

START_TEST(annulus_uniform_follows_size)
{
    check_annulus(0.3, 0.45, 1.05);
}
END_TEST

START_TEST(annulus_graded_follows_size)
{
    check_annulus(-1.0, 0.45, 1.05);
}
END_TEST

/* A shared geometry with its input points (as triangulated: no duplicates
 * there) and segments; caller frees. */
static void shared_input(const char *name, double **xy, size_t *np, cvm_index **seg, size_t *ns)
{
    char path[1024];
    cvm_mesh *m;
    rtest_data_path(path, sizeof path, name);
    *seg = rtest_poly_segments(path, ns);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_read(m, path), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(np, m, CVM_ENT_INPUT_POINT), CVM_OK);
    *xy = malloc((2 * *np + 1) * sizeof **xy);
    ck_assert_ptr_nonnull(*xy);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    {
        size_t nv, k;
        double *v;
        cvm_index *map = malloc((*np + 1) * sizeof *map);
        ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
        v = malloc((2 * nv + 1) * sizeof *v);
        ck_assert(map && v);
        ck_assert_int_eq(cvm_mesh_copy_points(v, 2 * nv, m), CVM_OK);
        ck_assert_int_eq(cvm_mesh_copy_input_map(map, *np, m), CVM_OK);
        for (k = 0; k < *np; k++) {
            (*xy)[2 * k] = v[2 * (size_t)map[k]];
            (*xy)[2 * k + 1] = v[2 * (size_t)map[k] + 1];
        }
        free(map);
        free(v);
    }
    cvm_mesh_free(m);
}

/* 1 when the point (x, y) is a vertex of m. */
static int has_point(cvm_mesh *m, double x, double y)
{
    double *xy;
    cvm_index *tri;
    size_t nv, nt, k;
    int found = 0;
    rtest_fetch(m, &xy, &nv, &tri, &nt);
    for (k = 0; k < nv && !found; k++)
        found = xy[2 * k] == x && xy[2 * k + 1] == y;
    free(xy);
    free(tri);
    return found;
}

/* The shared geometry re-discretised at size h: valid, its corners kept
 * (given as input point ids), boundary turning points on the input polyline,
 * boundary pieces no shorter than min_ratio x the size. */
static void check_shared(const char *name, double h, long euler, const size_t *corner, size_t ncorner,
                         double min_ratio)
{
    static const cvm_algorithm algos[] = {CVM_ALGO_DELAUNAY, CVM_ALGO_FRONTAL, CVM_ALGO_AFLR};
    char path[1024];
    double *in_xy, diam = 0;
    cvm_index *in_seg;
    size_t np, ns, a, k;
    shared_input(name, &in_xy, &np, &in_seg, &ns);
    for (k = 0; k < np; k++) {
        double d = hypot(in_xy[2 * k] - in_xy[0], in_xy[2 * k + 1] - in_xy[1]);
        diam = d > diam ? d : diam;
    }
    rtest_data_path(path, sizeof path, name);
    for (a = 0; a < 3; a++) {
        cvm_mesh *m, *keep;
        rs_meas r, rk;
        rtest_quality q;
        cvm_status st;
        ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
        ck_assert_int_eq(cvm_mesh_read(m, path), CVM_OK);
        ck_assert_int_eq(cvm_mesh_create(&keep), CVM_OK);
        ck_assert_int_eq(cvm_mesh_read(keep, path), CVM_OK);
        ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_KEEP_SEGMENT_VERTICES, 0), CVM_OK);
        ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
        ck_assert_int_eq(cvm_mesh_triangulate(keep), CVM_OK);
        st = refine_with(m, h, algos[a]);
        ck_assert_msg(st == CVM_OK, "%s: %s", cvm_status_str(st), cvm_mesh_errmsg(m));
        ck_assert_int_eq(refine_with(keep, h, algos[a]), CVM_OK);
        measure(m, h, in_xy, 0, in_seg, ns, &r);
        measure(keep, h, in_xy, 0, in_seg, ns, &rk);
        assert_valid_resampled(m, euler, r.boundary_area);
        ck_assert_double_le(r.max_off, 1e-12 * diam);
        ck_assert_double_eq_tol(r.area, r.boundary_area, 1e-12 * r.area);
        for (k = 0; k < ncorner; k++)
            ck_assert_msg(has_point(m, in_xy[2 * corner[k]], in_xy[2 * corner[k] + 1]),
                          "%s: corner %lu (%g, %g) is gone", name, (unsigned long)corner[k],
                          in_xy[2 * corner[k]], in_xy[2 * corner[k] + 1]);
        rtest_measure(m, &q);
        ck_assert_double_ge(q.min_angle, 30.0 - 1e-9);
        /* the pieces follow the size no worse than the input vertices do */
        ck_assert_double_ge(r.min_ratio, min_ratio);
        ck_assert_uint_gt(r.nb, 0);
        ck_assert_uint_gt(rk.nb, 0);
        cvm_mesh_free(m);
        cvm_mesh_free(keep);
    }
    free(in_xy);
    free(in_seg);
}

/* The input point of largest x with |y| <= ymax and x <= xmax (a trailing edge). */
static size_t rightmost(const double *xy, size_t np, double xmax, double ymax)
{
    size_t k, best = 0;
    double bx = -HUGE_VAL;
    for (k = 0; k < np; k++)
        if (fabs(xy[2 * k + 1]) <= ymax && xy[2 * k] <= xmax && xy[2 * k] > bx) {
            bx = xy[2 * k];
            best = k;
        }
    return best;
}

START_TEST(naca_trailing_edge_is_kept)
{
    double *xy;
    cvm_index *seg;
    size_t np, ns, te;
    shared_input("naca0012.poly", &xy, &np, &seg, &ns);
    te = rightmost(xy, np, 1.5, 0.1);
    ck_assert_double_gt(xy[2 * te], 0.99);
    free(xy);
    free(seg);
    /* at the uniform size 0.2 a chord across the leading edge (radius 0.016)
       would replace an arc turning by more than 90 degrees: the profile is
       split there and keeps its short input pieces around it */
    check_shared("naca0012.poly", 0.2, 0, &te, 1, 0.0);
}
END_TEST

START_TEST(channel_and_cylinder_corners_are_kept)
{
    /* the box corners are the first four points of both files */
    static const size_t corners[] = {0, 1, 2, 3};
    check_shared("channel.poly", 0.1, 1, corners, 4, 0.45);
    check_shared("cylinder.poly", 0.2, 0, corners, 4, 0.45);
}
END_TEST

/* Without a sizing the option changes nothing; out-of-range values, a mesh
 * that was refined or had points inserted, are refused with clear statuses. */
START_TEST(option_and_state_errors)
{
    static const double extra[2] = {2.0, 0.5};
    cvm_mesh *m, *m2;
    cvm_index id;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    set_annulus(m);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_KEEP_SEGMENT_VERTICES, 2), CVM_E_OPTION_RANGE);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_KEEP_SEGMENT_VERTICES, -1), CVM_E_OPTION_RANGE);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_KEEP_SEGMENT_VERTICES, 0.5), CVM_E_OPTION_RANGE);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_KEEP_SEGMENT_VERTICES, 0), CVM_OK);
    /* no sizing (NULL or empty): nothing to re-discretise with, refused with
     * the option as the error item, the mesh as triangulated */
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_create(&m2), CVM_OK);
    set_annulus(m2);
    ck_assert_int_eq(cvm_mesh_triangulate(m2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_refine(m, NULL, CVM_ALGO_DELAUNAY), CVM_E_UNSUPPORTED);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "KEEP_SEGMENT_VERTICES"));
    {
        cvm_entity kind = CVM_ENT_NONE;
        int64_t item = -1;
        cvm_sizing *empty;
        ck_assert_int_eq(cvm_mesh_error_item(&kind, &item, m), CVM_OK);
        ck_assert_int_eq(kind, CVM_ENT_OPTION);
        ck_assert_int_eq(item, (int64_t)CVM_OPT_KEEP_SEGMENT_VERTICES);
        ck_assert_int_eq(cvm_sizing_create(&empty), CVM_OK);
        ck_assert_int_eq(cvm_mesh_refine(m, empty, CVM_ALGO_FRONTAL), CVM_E_UNSUPPORTED);
        cvm_sizing_free(empty);
    }
    rtest_assert_identical(m, m2);
    cvm_mesh_free(m2);
    /* with the input vertices kept, refinement without a sizing works */
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_KEEP_SEGMENT_VERTICES, 1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_refine(m, NULL, CVM_ALGO_DELAUNAY), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_KEEP_SEGMENT_VERTICES, 0), CVM_OK);
    /* refined already: refused, mesh unchanged and valid */
    ck_assert_int_eq(refine_with(m, 0.3, CVM_ALGO_FRONTAL), CVM_E_STATE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "KEEP_SEGMENT_VERTICES"));
    cvmtest_assert_valid(m);
    /* points inserted after triangulating: refused too */
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_insert_points(&id, m, extra, 1, 0.0), CVM_OK);
    ck_assert_int_eq(refine_with(m, 0.3, CVM_ALGO_DELAUNAY), CVM_E_STATE);
    /* triangulated again: accepted */
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(refine_with(m, 0.3, CVM_ALGO_DELAUNAY), CVM_OK);
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    cvm_mesh_free(m);
}
END_TEST

/* Markers and attributes follow the chains: with the attribute of each input
 * point set to its x, every boundary vertex of the re-discretised annulus
 * (uniform 0.3: no piece is split later) carries its own x, and the marker
 * of its circle (1 inner, 2 outer), segment markers too. */
START_TEST(markers_and_attributes_follow_the_chain)
{
    double attr[N_IN + N_OUT], xy_in[2 * (N_IN + N_OUT)], *xy, *va;
    cvm_index seg[2 * (N_IN + N_OUT)], *tri, *be;
    int32_t smark[N_IN + N_OUT], *vm, *sm;
    size_t nv, nt, nb, na, ns, k;
    cvm_mesh *m;
    annulus_input(xy_in, seg, smark);
    for (k = 0; k < N_IN + N_OUT; k++)
        attr[k] = xy_in[2 * k];
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    set_annulus(m);
    ck_assert_int_eq(cvm_mesh_set_point_attributes(m, attr, N_IN + N_OUT, 1), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_KEEP_SEGMENT_VERTICES, 0), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(refine_with(m, 0.3, CVM_ALGO_FRONTAL), CVM_OK);
    rtest_fetch(m, &xy, &nv, &tri, &nt);
    be = boundary_edges(tri, nt, &nb);
    va = malloc((nv + 1) * sizeof *va);
    vm = malloc((nv + 1) * sizeof *vm);
    ck_assert(va && vm);
    ck_assert_int_eq(cvm_mesh_copy_point_attributes(va, nv, &na, m), CVM_OK);
    ck_assert_uint_eq(na, 1);
    ck_assert_int_eq(cvm_mesh_copy_markers(vm, nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_uint_eq(nb, 105);
    for (k = 0; k < 2 * nb; k++) {
        cvm_index v = be[k];
        double r = hypot(xy[2 * (size_t)v], xy[2 * (size_t)v + 1]);
        ck_assert_double_eq_tol(va[v], xy[2 * (size_t)v], 1e-12);
        ck_assert_int_eq(vm[v], r < 2 ? 1 : 2);
    }
    ck_assert_int_eq(cvm_mesh_count(&ns, m, CVM_ENT_SEGMENT), CVM_OK);
    ck_assert_uint_eq(ns, 105);
    sm = malloc((ns + 1) * sizeof *sm);
    ck_assert_ptr_nonnull(sm);
    ck_assert_int_eq(cvm_mesh_copy_markers(sm, ns, m, CVM_ENT_SEGMENT), CVM_OK);
    for (k = 0; k < ns; k++)
        ck_assert(sm[k] == 1 || sm[k] == 2);
    free(sm);
    free(va);
    free(vm);
    free(be);
    free(xy);
    free(tri);
    cvm_mesh_free(m);
}
END_TEST

static double bad_size(void *payload, double x, double y)
{
    (void)payload;
    return x > 3.5 && y > 0 ? -1.0 : 0.3;
}

/* A sizing callback that fails during the re-discretisation: its status, and
 * the mesh as triangulated (valid). */
START_TEST(sizing_error_during_resampling)
{
    cvm_mesh *m;
    cvm_sizing *s;
    size_t nv0, nv1;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    set_annulus(m);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_KEEP_SEGMENT_VERTICES, 0), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nv0, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_callback(s, bad_size, NULL), CVM_OK);
    ck_assert_int_eq(cvm_mesh_refine(m, s, CVM_ALGO_DELAUNAY), CVM_E_ARGUMENT);
    cvm_sizing_free(s);
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nv1, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_uint_eq(nv1, nv0);
    cvm_mesh_free(m);
}
END_TEST

/* A flat rhombus (-1, 0), (0, -0.25), (1, 0), (0, 0.25): the vertices at
 * +-0.25 turn by 28 degrees, so each side pair is a chain between the corners
 * (+-1, 0). At size 10 each chain alone would become the chord between the
 * corners, and both would collapse onto one edge: the re-discretisation must
 * fall back and keep the rhombus (its area). */
START_TEST(collapsing_chains_fall_back)
{
    static const double xy[] = {-1, 0, 0, -0.25, 1, 0, 0, 0.25};
    static const cvm_index seg[] = {0, 1, 1, 2, 2, 3, 3, 0};
    cvm_mesh *m;
    double a2;
    size_t nv;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 4, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, seg, 4), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_KEEP_SEGMENT_VERTICES, 0), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(refine_with(m, 10.0, CVM_ALGO_FRONTAL), CVM_OK);
    assert_valid_resampled(m, 1, 0.5);
    ck_assert_int_eq(cvm_mesh_get_measure(&a2, m, CVM_MEASURE_AREA), CVM_OK);
    ck_assert_double_eq_tol(a2, 0.5, 1e-15);
    ck_assert(has_point(m, 0, 0.25) && has_point(m, 0, -0.25));
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_uint_ge(nv, 4);
    cvm_mesh_free(m);
}
END_TEST

/* A 16-gon of radius 2 on a 1/8 grid is one smooth chain: re-discretised, its
 * inner input vertices are gone, so their input segments have no ends left.
 * The small-input-angle test of a skinny triangle between two pieces must
 * skip such segments (it read the coordinates of vertex -1 before) and find
 * no small input angle in a convex polygon. */
START_TEST(removed_chain_ends_are_no_small_input_angle)
{
    double xy[2 * 16], v;
    cvm_index seg[2 * 16];
    cvm_mesh *m;
    int k;
    for (k = 0; k < 16; k++) {
        xy[2 * k] = floor((8 + 2 * cos(2 * PI * k / 16)) * 8 + 0.5) / 8;
        xy[2 * k + 1] = floor((8 + 2 * sin(2 * PI * k / 16)) * 8 + 0.5) / 8;
        seg[2 * k] = k;
        seg[2 * k + 1] = (k + 1) % 16;
    }
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 16, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, seg, 16), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_KEEP_SEGMENT_VERTICES, 0), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_MIN_ANGLE_DEG, 20 + 13 * 157 / 255.0), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(refine_with(m, 1.0, CVM_ALGO_FRONTAL), CVM_OK);
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_get_measure(&v, m, CVM_MEASURE_REFINE_SMALL_INPUT_ANGLE), CVM_OK);
    ck_assert_double_eq(v, 0);
    ck_assert_int_eq(cvm_mesh_get_measure(&v, m, CVM_MEASURE_REFINE_UNMET_ANGLE), CVM_OK);
    ck_assert_double_eq(v, 0);
    cvm_mesh_free(m);
}
END_TEST

/* Segments outside the domain: a free segment in a square hole of a 16-gon
 * (a smooth chain) and a triangle beyond it (its own hole seed). The
 * re-discretisation rebuilt the triangulation from the constrained edges with
 * a domain side only, so these lost their edges (cvm_mesh_check: "input
 * segment ... is not joined end to end"). They must stay, and the 16-gon is
 * still re-discretised (its inner input vertices gone). */
START_TEST(segments_outside_the_domain_are_kept)
{
    double xy[2 * 25], holes[4] = {8, 8, 12.4, 8.2}, a16 = 0, area;
    cvm_index seg[2 * 25];
    cvm_mesh *m;
    size_t k, gone;
    static const double sq[] = {7.5, 7.5, 8.5, 7.5, 8.5, 8.5, 7.5, 8.5, 7.75, 8, 8.25, 8,
                                12, 8, 13, 8, 12.5, 8.5};
    for (k = 0; k < 16; k++) {
        xy[2 * k] = floor((8 + 2 * cos(2 * PI * (double)k / 16)) * 8 + 0.5) / 8;
        xy[2 * k + 1] = floor((8 + 2 * sin(2 * PI * (double)k / 16)) * 8 + 0.5) / 8;
        seg[2 * k] = (cvm_index)k;
        seg[2 * k + 1] = (cvm_index)((k + 1) % 16);
    }
    for (k = 0; k < 16; k++)
        a16 += (xy[2 * k] * xy[2 * ((k + 1) % 16) + 1] - xy[2 * ((k + 1) % 16)] * xy[2 * k + 1]) / 2;
    memcpy(xy + 32, sq, sizeof sq);
    for (k = 0; k < 4; k++) { /* the square hole: points 16..19 */
        seg[2 * (16 + k)] = (cvm_index)(16 + k);
        seg[2 * (16 + k) + 1] = (cvm_index)(16 + (k + 1) % 4);
    }
    seg[40] = 20; /* the free segment in the hole */
    seg[41] = 21;
    for (k = 0; k < 3; k++) { /* the triangle beyond the 16-gon: points 22..24 */
        seg[2 * (21 + k)] = (cvm_index)(22 + k);
        seg[2 * (21 + k) + 1] = (cvm_index)(22 + (k + 1) % 3);
    }
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 25, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, seg, 24), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_holes(m, holes, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_KEEP_SEGMENT_VERTICES, 0), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(refine_with(m, 0.5, CVM_ALGO_DELAUNAY), CVM_OK);
    /* the chords cut the 16-gon: less area than the input, by less than 2 % */
    ck_assert_int_eq(cvm_mesh_get_measure(&area, m, CVM_MEASURE_AREA), CVM_OK);
    ck_assert_double_lt(area, a16 - 1.0);
    ck_assert_double_gt(area, 0.98 * (a16 - 1.0));
    assert_valid_resampled(m, 0, area);
    for (k = 1, gone = 0; k < 16; k++)
        gone += !has_point(m, xy[2 * k], xy[2 * k + 1]);
    ck_assert_uint_gt(gone, 0);
    ck_assert(has_point(m, 7.75, 8) && has_point(m, 8.25, 8) && has_point(m, 13, 8));
    cvm_mesh_free(m);
}
END_TEST

/* Out of memory at every allocation of a re-discretising refinement: a
 * status, no leak, and a valid mesh (the rebuilt one or the old one). */
static void oom_setup(cvm_mesh *m, void *arg)
{
    (void)arg;
    set_annulus(m);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_KEEP_SEGMENT_VERTICES, 0), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
}

static cvm_status oom_run(cvm_mesh *m, void *arg)
{
    (void)arg;
    return refine_with(m, 1.0, CVM_ALGO_DELAUNAY);
}

START_TEST(out_of_memory_is_a_status)
{
    cvmtest_oom_sweep(oom_setup, oom_run, NULL, NULL);
}
END_TEST

TCase *refine_resample_tcase(void)
{
    TCase *tc = tcase_create("resample");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, annulus_uniform_follows_size);
    tcase_add_test(tc, annulus_graded_follows_size);
    tcase_add_test(tc, naca_trailing_edge_is_kept);
    tcase_add_test(tc, channel_and_cylinder_corners_are_kept);
    tcase_add_test(tc, option_and_state_errors);
    tcase_add_test(tc, collapsing_chains_fall_back);
    tcase_add_test(tc, removed_chain_ends_are_no_small_input_angle);
    tcase_add_test(tc, segments_outside_the_domain_are_kept);
    tcase_add_test(tc, markers_and_attributes_follow_the_chain);
    tcase_add_test(tc, sizing_error_during_resampling);
    tcase_add_test(tc, out_of_memory_is_a_status);
    return tc;
}
