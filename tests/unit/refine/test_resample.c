/* test_resample.c - CVM_OPT_KEEP_SEGMENT_VERTICES = 0: smooth chains of segments re-discretised with the sizing. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "refine/refine_tests.h"
#include "support/failing_alloc.h"
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
        fprintf(stderr, "h %g algo %d: nb %lu ratio [%g, %g] off %g area %.15g boundary %.15g input %.15g removed %g perim %g splits %lu\n",
                h, (int)algos[a], (unsigned long)r.nb, r.min_ratio, r.max_ratio, r.max_off, r.area,
                r.boundary_area, in_area, r.max_removed_dist, r.perimeter,
                (unsigned long)r.n_chord_splits);
        assert_valid_resampled(m, 0, r.boundary_area);
        ck_assert_double_le(r.max_off, 1e-12 * 8.0);
        ck_assert_double_eq_tol(r.area, r.boundary_area, 1e-12 * r.area);
        ck_assert_double_le(fabs(r.area - in_area), r.perimeter * r.max_removed_dist);
        ck_assert_double_lt(r.area, in_area); /* chords cut the outer circle, widen the hole */
        ck_assert_double_ge(r.min_ratio, lo);
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

TCase *refine_resample_tcase(void)
{
    TCase *tc = tcase_create("resample");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, annulus_uniform_follows_size);
    tcase_add_test(tc, annulus_graded_follows_size);
    return tc;
}
