/*
 * test_octree.c - the octree free space (CVM_GEN3_FREESPACE_OCTREE): every
 * octree point is a leaf centroid strictly inside the domain and keeps its
 * rejection distance from every other point and from the surface; around a
 * point source the tetrahedra are well-centred once merged; the same bytes
 * every run; OOM at every allocation; option values and sizes give statuses.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "generate3/g3_util.h"
#include "generate3/generate3_tests.h"
#include "support/oom_sweep.h"
#include "support/skip.h"

static cvm_mesh *read_octree(const char *name)
{
    cvm_mesh *m;
    char path[1024];
    g3_data3d(path, sizeof path, name);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_msg(cvm_mesh_read(m, path) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_FREESPACE, CVM_GEN3_FREESPACE_OCTREE),
                     CVM_OK);
    return m;
}

static double report(const cvm_mesh *m, cvm_report which)
{
    double v;
    ck_assert_int_eq(cvm_mesh_get_report(&v, m, which), CVM_OK);
    return v;
}

/* The unit cube at uniform size 0.125: leaves of edge 1/8 (the first power of
 * two at most 2^(2/3) x 0.125), so every octree point is ((i, j, k) + 1/2) / 8
 * exactly, strictly inside, and at least 0.55 / 8 from every other vertex and
 * from the cube's faces. */
START_TEST(octree_points_are_centroids_inside_and_apart)
{
    cvm_mesh *m = read_octree(g3_with_tetgen() ? "cube.off" : "tetra.off");
    const double e = 0.125, dm = 0.55 * 0.125;
    double near_pts, oct_pts, leaves, lat;
    size_t first, i, j, np;
    g3_mesh g;
    if (!g3_with_tetgen()) {
        /* the tetrahedron (carve, no TetGen): the counts and the inside test only */
        ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_SIZE_FROM_SURFACE, 0), CVM_OK);
        ck_assert_msg(cvm_mesh_generate3(m, 0.25) == CVM_OK, "%s", cvm_mesh_errmsg(m));
        ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
        ck_assert_double_gt(report(m, CVM_REPORT_GEN3_OCTREE_POINTS), 0);
        cvm_mesh_free(m);
        CVMTEST_SKIP("the cube needs TetGen (a TETGEN=1 build)");
    }
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_SIZE_FROM_SURFACE, 0), CVM_OK);
    ck_assert_msg(cvm_mesh_generate3(m, 0.125) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    near_pts = report(m, CVM_REPORT_GEN3_NEAR_POINTS);
    oct_pts = report(m, CVM_REPORT_GEN3_OCTREE_POINTS);
    leaves = report(m, CVM_REPORT_GEN3_OCTREE_LEAVES);
    lat = report(m, CVM_REPORT_GEN3_LATTICE_POINTS);
    ck_assert_double_eq(leaves, 512);
    ck_assert_double_eq(lat, 0);
    /* the leaves of the outer layer lie within dm of the surface or the near field:
     * the 6 x 6 x 6 inner leaves stay */
    ck_assert_double_eq(oct_pts, 216);
    ck_assert_int_eq(cvm_mesh_count(&np, m, CVM_ENT_INPUT_POINT), CVM_OK);
    g3_mesh_get(&g, m);
    first = np + (size_t)near_pts;
    ck_assert_uint_eq(g.nv, first + (size_t)oct_pts);
    for (i = first; i < g.nv; i++) {
        const double *x = g.xyz + 3 * i;
        int ax;
        for (ax = 0; ax < 3; ax++) {
            double c = x[ax] / e - 0.5;
            ck_assert_double_eq(c, floor(c));
            ck_assert_double_ge(x[ax], dm);
            ck_assert_double_le(x[ax], 1 - dm);
        }
        for (j = 0; j < g.nv; j++) {
            const double *y = g.xyz + 3 * j;
            double d2 = (x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) +
                        (x[2] - y[2]) * (x[2] - y[2]);
            if (j != i)
                ck_assert_double_ge(d2, dm * dm);
        }
    }
    g3_mesh_free(&g);
    cvm_mesh_free(m);
}
END_TEST

/* The graded sphere in a box: every octree point strictly inside the box and
 * outside the ball of radius 0.5, apart from the surface by its rule. */
START_TEST(octree_graded_points_stay_inside)
{
    cvm_mesh *m = read_octree("sphere_in_box.poly");
    double near_pts, oct_pts;
    size_t np, i;
    g3_mesh g;
    cvm_status s = cvm_mesh_generate3(m, 0.5);
    if (!g3_with_tetgen()) {
        cvm_mesh_free(m);
        CVMTEST_SKIP("needs TetGen (a TETGEN=1 build)");
    }
    ck_assert_msg(s == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    near_pts = report(m, CVM_REPORT_GEN3_NEAR_POINTS);
    oct_pts = report(m, CVM_REPORT_GEN3_OCTREE_POINTS);
    ck_assert_double_gt(oct_pts, 1000);
    ck_assert_double_gt(report(m, CVM_REPORT_GEN3_OCTREE_LEAVES), oct_pts);
    ck_assert_int_eq(cvm_mesh_count(&np, m, CVM_ENT_INPUT_POINT), CVM_OK);
    g3_mesh_get(&g, m);
    ck_assert_uint_eq(g.nv, np + (size_t)(near_pts + oct_pts));
    ck_assert_int_eq(g3_euler(&g), 2);
    for (i = np + (size_t)near_pts; i < g.nv; i++) {
        const double *x = g.xyz + 3 * i;
        /* the polyhedral sphere lies within the ball; its smallest leaf centroid
         * distance from it is positive */
        ck_assert_double_gt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2], 0.25);
        ck_assert(fabs(x[0]) < 2 && fabs(x[1]) < 2 && fabs(x[2]) < 2);
    }
    g3_mesh_free(&g);
    cvm_mesh_free(m);
}
END_TEST

typedef struct face_ref {
    cvm_index v[3];
    size_t t;
    int f;
} face_ref;

static int cmp_face(const void *pa, const void *pb)
{
    const face_ref *a = pa, *b = pb;
    int k;
    for (k = 0; k < 3; k++)
        if (a->v[k] != b->v[k])
            return a->v[k] < b->v[k] ? -1 : 1;
    return 0;
}

static double det3(double a[3][3])
{
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

/* The barycentric coordinates of t's circumcentre (Cramer, plain doubles). */
static void circumcentre_bary(const g3_mesh *g, size_t t, double *lam)
{
    const double *p0 = g->xyz + 3 * g->tet[4 * t];
    double A[3][3], b[3], cc[3], M[3][3], d;
    int r, k, c;
    for (r = 0; r < 3; r++) {
        const double *p = g->xyz + 3 * g->tet[4 * t + r + 1];
        b[r] = 0;
        for (k = 0; k < 3; k++) {
            A[r][k] = p[k] - p0[k];
            b[r] += 0.5 * A[r][k] * A[r][k];
        }
    }
    d = det3(A);
    for (k = 0; k < 3; k++) {
        for (r = 0; r < 3; r++)
            for (c = 0; c < 3; c++)
                M[r][c] = c == k ? b[r] : A[r][c];
        cc[k] = det3(M) / d;
    }
    /* cc = sum_r lam[r+1] A[r]: the transposed system */
    for (k = 0; k < 3; k++) {
        for (r = 0; r < 3; r++)
            for (c = 0; c < 3; c++)
                M[r][c] = c == k ? cc[r] : A[c][r];
        lam[k + 1] = det3(M) / d;
    }
    lam[0] = 1 - lam[1] - lam[2] - lam[3];
}

/* A point source of size 0.02 (growth 0.2) near the centre of the unit cube
 * at size 0.25: the tetrahedra within 0.15 of it (several octree levels, no
 * boundary) are measured. A tetrahedron is compliant after merging when its
 * circumcentre lies inside it, or outside only beyond faces shared with a
 * tetrahedron of its own merged group (cvm_mesh_copy_dual3_merge_groups()).
 * Measured: 1,640 tetrahedra, all merged, none non-compliant: the paper's
 * 100 %; the lattice at the same sizes leaves 23 % (the octree without the
 * sources' boxes in its split rule, 0.31 %, at corners of 2:1 transitions).
 * With CVM_OPT_GEN3_OCTREE_SPLIT_HANGING: 1,870 tetrahedra, the same result. */
static void point_source_well_centred(int split_hanging)
{
    cvm_mesh *m = read_octree("cube.off");
    cvm_sizing *sz;
    const double c[3] = {0.5123, 0.4929, 0.5049};
    g3_mesh g;
    cvm_index *grp;
    face_ref *fr;
    int32_t *nb;
    size_t t, i, near = 0, bad = 0, merged = 0;
    cvm_status s;
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_SIZE_FROM_SURFACE, 0), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_OCTREE_SPLIT_HANGING, split_hanging),
                     CVM_OK);
    ck_assert_int_eq(cvm_sizing_create(&sz), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_point_source_nd(sz, c, 3, 0.02, 0.2), CVM_OK);
    s = cvm_mesh_generate3_sized(m, 0.25, sz);
    cvm_sizing_free(sz);
    if (!g3_with_tetgen()) {
        cvm_mesh_free(m);
        CVMTEST_SKIP("the cube needs TetGen (a TETGEN=1 build)");
    }
    ck_assert_msg(s == CVM_OK, "%s", cvm_mesh_errmsg(m));
    g3_mesh_get(&g, m);
    grp = malloc(g.nt * sizeof *grp);
    fr = malloc(4 * g.nt * sizeof *fr);
    nb = malloc(4 * g.nt * sizeof *nb);
    ck_assert(grp && fr && nb);
    ck_assert_int_eq(cvm_mesh_copy_dual3_merge_groups(grp, g.nt, m), CVM_OK);
    for (t = 0; t < g.nt; t++) {
        int f;
        for (f = 0; f < 4; f++) {
            face_ref *r = fr + 4 * t + f;
            cvm_index tmp;
            int a, n = 0;
            for (a = 0; a < 4; a++)
                if (a != f)
                    r->v[n++] = g.tet[4 * t + a];
            for (a = 0; a < 3; a++)
                for (n = 0; n < 2 - a; n++)
                    if (r->v[n] > r->v[n + 1]) {
                        tmp = r->v[n];
                        r->v[n] = r->v[n + 1];
                        r->v[n + 1] = tmp;
                    }
            r->t = t;
            r->f = f;
            nb[4 * t + f] = -1;
        }
    }
    qsort(fr, 4 * g.nt, sizeof *fr, cmp_face);
    for (i = 0; i + 1 < 4 * g.nt; i++)
        if (cmp_face(fr + i, fr + i + 1) == 0) {
            nb[4 * fr[i].t + (size_t)fr[i].f] = (int32_t)fr[i + 1].t;
            nb[4 * fr[i + 1].t + (size_t)fr[i + 1].f] = (int32_t)fr[i].t;
        }
    for (t = 0; t < g.nt; t++) {
        double lam[4];
        int q, ok = 1, joined = 0;
        for (q = 0; q < 4; q++) {
            const double *p = g.xyz + 3 * g.tet[4 * t + q];
            if ((p[0] - c[0]) * (p[0] - c[0]) + (p[1] - c[1]) * (p[1] - c[1]) +
                    (p[2] - c[2]) * (p[2] - c[2]) > 0.15 * 0.15)
                break;
        }
        if (q < 4)
            continue;
        near++;
        circumcentre_bary(&g, t, lam);
        for (q = 0; q < 4; q++) {
            int32_t u = nb[4 * t + (size_t)q];
            joined |= u >= 0 && grp[u] == grp[t];
            /* a quality threshold, not a decision: a circumcentre on a shared face
             * is inside up to rounding */
            if (lam[q] < -1e-9 && (u < 0 || grp[u] != grp[t]))
                ok = 0;
        }
        bad += !ok;
        merged += joined;
    }
    ck_assert_uint_ge(near, 1000);
    ck_assert_msg(100.0 * (double)merged / (double)near > 95, "merged %lu of %lu",
                  (unsigned long)merged, (unsigned long)near);
    ck_assert_msg(bad == 0, "%lu of %lu not compliant", (unsigned long)bad, (unsigned long)near);
    g3_mesh_free(&g);
    free(grp);
    free(fr);
    free(nb);
    cvm_mesh_free(m);
}

START_TEST(octree_point_source_is_well_centred_after_merging)
{
    point_source_well_centred(0);
}
END_TEST

START_TEST(octree_split_hanging_point_source_is_well_centred_after_merging)
{
    point_source_well_centred(1);
}
END_TEST

static void run_bytes(double seed, double threads, double **xyz, size_t *nv, cvm_index **tet,
                      size_t *nt)
{
    cvm_mesh *m = read_octree(g3_with_tetgen() ? "sphere_in_box.poly" : "tetra.off");
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_SEED, seed), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_THREADS, threads), CVM_OK);
    ck_assert_msg(cvm_mesh_generate3(m, g3_with_tetgen() ? 1.0 : 0.25) == CVM_OK, "%s",
                  cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_count(nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    *xyz = malloc(3 * *nv * sizeof **xyz);
    *tet = malloc(4 * *nt * sizeof **tet);
    ck_assert(*xyz && *tet);
    ck_assert_int_eq(cvm_mesh_copy_points_nd(*xyz, 3 * *nv, 3, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(*tet, 4 * *nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    cvm_mesh_free(m);
}

START_TEST(octree_same_bytes_for_every_run_seed_and_thread_count)
{
    double *x0, *x1;
    cvm_index *t0, *t1;
    size_t nv0, nt0, nv1, nt1;
    double runs[2][2] = {{1, 2}, {7, 0}};
    int r;
    run_bytes(1, 1, &x0, &nv0, &t0, &nt0);
    for (r = 0; r < 2; r++) {
        run_bytes(runs[r][0], runs[r][1], &x1, &nv1, &t1, &nt1);
        ck_assert_uint_eq(nv0, nv1);
        ck_assert_uint_eq(nt0, nt1);
        ck_assert(memcmp(x0, x1, 3 * nv0 * sizeof *x0) == 0);
        ck_assert(memcmp(t0, t1, 4 * nt0 * sizeof *t0) == 0);
        free(x1);
        free(t1);
    }
    free(x0);
    free(t0);
}
END_TEST

/* Option values and sizes give statuses. */
START_TEST(octree_options_and_sizes_give_statuses)
{
    cvm_mesh *m = read_octree("tetra.off");
    cvm_bounds b;
    double v;
    ck_assert_int_eq(cvm_option_bounds(&b, CVM_OPT_GEN3_FREESPACE), CVM_OK);
    ck_assert_double_eq(b.lo, 0);
    ck_assert_double_eq(b.hi, 2);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_FREESPACE, 3), CVM_E_OPTION_RANGE);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_FREESPACE, -1), CVM_E_OPTION_RANGE);
    ck_assert_int_eq(cvm_mesh_get_option(&v, m, CVM_OPT_GEN3_FREESPACE), CVM_OK);
    ck_assert_double_eq(v, CVM_GEN3_FREESPACE_OCTREE);
    /* (2 / 1e-3)^3 leaves at least: refused before the tree is built */
    ck_assert_int_eq(cvm_mesh_generate3(m, 1e-3), CVM_E_TOO_LARGE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "octree"));
    ck_assert_int_eq(cvm_mesh_generate3(m, 1e-300), CVM_E_TOO_LARGE);
    ck_assert_int_eq(cvm_mesh_generate3(m, 0), CVM_E_ARGUMENT);
    ck_assert_int_eq(cvm_mesh_generate3(m, NAN), CVM_E_INPUT_NONFINITE);
    /* a lattice run reports no octree */
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_FREESPACE, CVM_GEN3_FREESPACE_LATTICE),
                     CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_SIZE_FROM_SURFACE, 0), CVM_OK);
    ck_assert_msg(cvm_mesh_generate3(m, 0.5) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_double_eq(report(m, CVM_REPORT_GEN3_OCTREE_LEAVES), 0);
    ck_assert_double_eq(report(m, CVM_REPORT_GEN3_OCTREE_POINTS), 0);
    ck_assert_int_eq(cvm_mesh_get_measure(&v, m, CVM_MEASURE_GEN3_OCTREE_POINTS), CVM_OK);
    ck_assert_double_eq(v, 0);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_FREESPACE, CVM_GEN3_FREESPACE_OCTREE),
                     CVM_OK);
    ck_assert_msg(cvm_mesh_generate3(m, 0.5) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_double_gt(report(m, CVM_REPORT_GEN3_OCTREE_LEAVES), 0);
    ck_assert_int_eq(cvm_mesh_get_measure(&v, m, CVM_MEASURE_GEN3_OCTREE_LEAVES), CVM_OK);
    ck_assert_double_eq(v, report(m, CVM_REPORT_GEN3_OCTREE_LEAVES));
    cvm_mesh_free(m);
}
END_TEST

static double octree_radial(void *payload, const double *x, int dim)
{
    (void)payload;
    (void)dim;
    return 0.1 + 0.3 * sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
}

static double octree_negative(void *payload, const double *x, int dim)
{
    (void)payload;
    (void)dim;
    return x[0] > 0.2 ? -1.0 : 0.3;
}

/* A callback and a point source both reach the octree; a callback's bad value
 * is the call's status. */
START_TEST(octree_reads_the_sizing)
{
    cvm_mesh *m = read_octree("tetra.off");
    cvm_sizing *sz;
    const double c[3] = {0.1, -0.1, 0.05};
    double pts_cb, pts_src, pts_plain;
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_SIZE_FROM_SURFACE, 0), CVM_OK);
    ck_assert_msg(cvm_mesh_generate3(m, 0.6) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    pts_plain = report(m, CVM_REPORT_GEN3_OCTREE_POINTS);
    ck_assert_int_eq(cvm_sizing_create(&sz), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_callback_nd(sz, octree_radial, NULL), CVM_OK);
    ck_assert_msg(cvm_mesh_generate3_sized(m, 0.6, sz) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    pts_cb = report(m, CVM_REPORT_GEN3_OCTREE_POINTS);
    ck_assert_double_gt(pts_cb, pts_plain);
    cvm_sizing_free(sz);
    /* a source of size 0.02 smaller than the octant around it, growth 2: its
     * octant's centre misses it, its box does not */
    ck_assert_int_eq(cvm_sizing_create(&sz), CVM_OK);
    ck_assert_int_eq(cvm_sizing_add_point_source_nd(sz, c, 3, 0.02, 2.0), CVM_OK);
    ck_assert_msg(cvm_mesh_generate3_sized(m, 0.6, sz) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    pts_src = report(m, CVM_REPORT_GEN3_OCTREE_POINTS);
    ck_assert_double_gt(pts_src, pts_plain);
    cvm_sizing_free(sz);
    ck_assert_int_eq(cvm_sizing_create(&sz), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_callback_nd(sz, octree_negative, NULL), CVM_OK);
    ck_assert_int_eq(cvm_mesh_generate3_sized(m, 0.6, sz), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "callback"));
    cvm_sizing_free(sz);
    cvm_mesh_free(m);
}
END_TEST

static void oom_setup(cvm_mesh *m, void *arg)
{
    char path[1024];
    g3_data3d(path, sizeof path, (const char *)arg);
    ck_assert_int_eq(cvm_mesh_read(m, path), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_FREESPACE, CVM_GEN3_FREESPACE_OCTREE),
                     CVM_OK);
}

static cvm_status oom_run(cvm_mesh *m, void *arg)
{
    (void)arg;
    return cvm_mesh_generate3(m, 0.5);
}

START_TEST(octree_oom_at_every_allocation)
{
    cvmtest_oom_sweep(oom_setup, oom_run, NULL, (void *)"tetra.off");
}
END_TEST

static void oom_setup_split(cvm_mesh *m, void *arg)
{
    oom_setup(m, arg);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_OCTREE_SPLIT_HANGING, 1), CVM_OK);
}

/* The tetrahedron with a point source at its centre: a graded tree. */
static cvm_status generate_graded(cvm_mesh *m)
{
    const double c[3] = {0.05, -0.03, 0.02};
    cvm_sizing *sz;
    cvm_status s = cvm_sizing_create(&sz);
    if (s)
        return s;
    s = cvm_sizing_add_point_source_nd(sz, c, 3, 0.05, 0.3);
    if (!s)
        s = cvm_mesh_generate3_sized(m, 0.5, sz);
    cvm_sizing_free(sz);
    return s;
}

static cvm_status oom_run_split(cvm_mesh *m, void *arg)
{
    (void)arg;
    return generate_graded(m);
}

/* Splitting the leaves with hanging faces: more leaves and points than the
 * balanced tree alone, a valid mesh of the same volume, the option's bounds,
 * and OOM at every allocation of the split. */
START_TEST(octree_split_hanging_adds_leaves)
{
    cvm_mesh *m = read_octree("tetra.off");
    cvm_bounds b;
    double leaves0, pts0, vol0, vol1;
    ck_assert_int_eq(cvm_option_bounds(&b, CVM_OPT_GEN3_OCTREE_SPLIT_HANGING), CVM_OK);
    ck_assert_double_eq(b.lo, 0);
    ck_assert_double_eq(b.hi, 1);
    ck_assert_double_eq(b.def, 0);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_OCTREE_SPLIT_HANGING, 2),
                     CVM_E_OPTION_RANGE);
    ck_assert_msg(generate_graded(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    leaves0 = report(m, CVM_REPORT_GEN3_OCTREE_LEAVES);
    pts0 = report(m, CVM_REPORT_GEN3_OCTREE_POINTS);
    ck_assert_int_eq(cvm_mesh_get_measure(&vol0, m, CVM_MEASURE_VOLUME), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_option(m, CVM_OPT_GEN3_OCTREE_SPLIT_HANGING, 1), CVM_OK);
    ck_assert_msg(generate_graded(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_check(m), CVM_OK);
    ck_assert_double_gt(report(m, CVM_REPORT_GEN3_OCTREE_LEAVES), leaves0);
    ck_assert_double_gt(report(m, CVM_REPORT_GEN3_OCTREE_POINTS), pts0);
    ck_assert_int_eq(cvm_mesh_get_measure(&vol1, m, CVM_MEASURE_VOLUME), CVM_OK);
    ck_assert_double_eq_tol(vol1, vol0, 1e-12 * vol0);
    cvm_mesh_free(m);
    cvmtest_oom_sweep(oom_setup_split, oom_run_split, NULL, (void *)"tetra.off");
}
END_TEST

TCase *generate3_octree_tcase(void)
{
    TCase *tc = tcase_create("octree");
    tcase_set_timeout(tc, 300);
    tcase_add_test(tc, octree_points_are_centroids_inside_and_apart);
    tcase_add_test(tc, octree_graded_points_stay_inside);
    tcase_add_test(tc, octree_point_source_is_well_centred_after_merging);
    tcase_add_test(tc, octree_split_hanging_point_source_is_well_centred_after_merging);
    tcase_add_test(tc, octree_same_bytes_for_every_run_seed_and_thread_count);
    tcase_add_test(tc, octree_options_and_sizes_give_statuses);
    tcase_add_test(tc, octree_reads_the_sizing);
    tcase_add_test(tc, octree_oom_at_every_allocation);
    tcase_add_test(tc, octree_split_hanging_adds_leaves);
    return tc;
}
