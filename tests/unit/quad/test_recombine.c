/* test_recombine.c - lib/quad/recombine.c: perfect squares from a right-triangle grid (also in a
 * stretched metric), convex counter-clockwise quads that tile a random Delaunay triangulation
 * exactly, constraints, bad input, out of memory. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "quad/quad_tests.h"
#include "quad/recombine.h"
#include "geom/geom_internal.h"
#include "support/fixtures.h"

typedef struct tmesh { size_t np, nt; double *xy; cvm_index *tri; } tmesh;

static void tmesh_free(tmesh *t)
{
    free(t->xy);
    free(t->tri);
}

/* n x n squares of size hx x hy, each cut by its diagonal (i,j)-(i+1,j+1). */
static void right_grid(tmesh *t, size_t n, double hx, double hy)
{
    size_t i, j, k = 0;
    t->np = (n + 1) * (n + 1);
    t->nt = 2 * n * n;
    t->xy = malloc(2 * t->np * sizeof *t->xy);
    t->tri = malloc(3 * t->nt * sizeof *t->tri);
    ck_assert(t->xy && t->tri);
    for (j = 0; j <= n; j++)
        for (i = 0; i <= n; i++) {
            t->xy[2 * (j * (n + 1) + i)] = (double)i * hx;
            t->xy[2 * (j * (n + 1) + i) + 1] = (double)j * hy;
        }
    for (j = 0; j < n; j++)
        for (i = 0; i < n; i++) {
            cvm_index a = (cvm_index)(j * (n + 1) + i), b = a + 1, c = a + (cvm_index)n + 2,
                      d = a + (cvm_index)n + 1;
            cvm_index tr[6] = {a, b, c, a, c, d};
            memcpy(t->tri + k, tr, sizeof tr);
            k += 6;
        }
}

static void delaunay_mesh(tmesh *t, size_t np, uint64_t seed)
{
    cvm_mesh *m = NULL;
    t->np = np;
    t->xy = malloc(2 * np * sizeof *t->xy);
    ck_assert_ptr_nonnull(t->xy);
    cvmtest_random_points(t->xy, np, seed);
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, t->xy, np, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&t->nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    t->tri = malloc(3 * t->nt * sizeof *t->tri);
    ck_assert_ptr_nonnull(t->tri);
    ck_assert_int_eq(cvm_mesh_copy_cells(t->tri, 3 * t->nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&np, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_uint_eq(np, t->np); /* random points: no duplicates */
    cvm_mesh_free(m);
}

static cvm__recombine_in input_of(const tmesh *t)
{
    cvm__recombine_in in;
    memset(&in, 0, sizeof in);
    in.npts = t->np;
    in.xy = t->xy;
    in.ntri = t->nt;
    in.tri = t->tri;
    in.min_quality = 0.5;
    return in;
}

static double area2(const double *xy, const cvm_index *p, int n)
{
    double s = 0;
    int k;
    for (k = 0; k < n; k++) {
        const double *a = xy + 2 * p[k], *b = xy + 2 * p[(k + 1) % n];
        s += a[0] * b[1] - a[1] * b[0];
    }
    return s;
}

/* Every input triangle lies in exactly one cell, whose points are the union of its sources;
 * quads strictly convex and counter-clockwise; areas add up. */
static void assert_tiling(const tmesh *t, const cvm__recombine_out *o, double qmin)
{
    unsigned char *used = calloc(t->nt + 1, 1);
    double at = 0, ac = 0;
    size_t c, k;
    ck_assert_ptr_nonnull(used);
    ck_assert_uint_eq(o->ncell, o->nquad + o->ntri);
    ck_assert_uint_eq(2 * o->nquad + o->ntri, t->nt);
    for (k = 0; k < t->nt; k++)
        at += area2(t->xy, t->tri + 3 * k, 3);
    for (c = 0; c < o->ncell; c++) {
        const cvm_index *p = o->conn + o->offsets[c];
        int n = o->offsets[c + 1] - o->offsets[c], j;
        ck_assert_int_eq(n, o->types[c] == CVM_CELL_QUAD ? 4 : 3);
        for (j = 0; j < 2; j++) {
            cvm_index s = o->source[2 * c + j];
            int i, l;
            if (s < 0) {
                ck_assert_int_eq(n, 3);
                continue;
            }
            ck_assert(!used[s]);
            used[s] = 1;
            for (i = 0; i < 3; i++) { /* each source corner is a cell corner */
                int found = 0;
                for (l = 0; l < n; l++)
                    found |= p[l] == t->tri[3 * s + i];
                ck_assert(found);
            }
        }
        if (n == 4) {
            for (j = 0; j < 4; j++)
                ck_assert(cvm__orient2d(t->xy + 2 * p[j], t->xy + 2 * p[(j + 1) % 4],
                                        t->xy + 2 * p[(j + 2) % 4]) > 0);
            ck_assert(o->quality[c] >= qmin && o->quality[c] <= 1);
        }
        ac += area2(t->xy, p, n);
    }
    for (k = 0; k < t->nt; k++)
        ck_assert(used[k]);
    ck_assert(fabs(ac - at) <= 1e-12 * fabs(at));
    free(used);
}

START_TEST(recombine_right_triangle_grid_gives_only_perfect_squares)
{
    tmesh t;
    cvm__recombine_in in;
    cvm__recombine_out o;
    cvm__ctx ctx;
    size_t c;
    int method;
    right_grid(&t, 12, 1.0, 1.0);
    cvm__ctx_init_default(&ctx);
    for (method = 0; method < 2; method++) {
        in = input_of(&t);
        in.method = (cvm__recombine_method)method;
        ck_assert_int_eq(cvm__recombine(&o, &ctx, &in), CVM_OK);
        assert_tiling(&t, &o, 0.5);
        ck_assert_uint_eq(o.nquad, 144);
        ck_assert_uint_eq(o.ntri, 0);
        for (c = 0; c < o.ncell; c++)
            ck_assert(o.quality[c] >= 1 - 1e-12);
        cvm__recombine_out_free(&ctx, &o);
    }
    tmesh_free(&t);
}
END_TEST

static int stretch_metric(double x, double y, double g[3], void *user)
{
    const double *h = user;
    (void)x;
    (void)y;
    g[0] = 1 / (h[0] * h[0]);
    g[1] = 0;
    g[2] = 1 / (h[1] * h[1]);
    return 0;
}

START_TEST(recombine_measures_corners_in_the_metric)
{
    /* cells 1 x 0.05: in the metric diag(1, 400) they are unit squares */
    static double h[2] = {1.0, 0.05};
    tmesh t;
    cvm__recombine_in in;
    cvm__recombine_out o;
    cvm__ctx ctx;
    double *g;
    size_t c, i;
    right_grid(&t, 8, h[0], h[1]);
    cvm__ctx_init_default(&ctx);
    in = input_of(&t);
    in.metric = stretch_metric;
    in.metric_user = h;
    ck_assert_int_eq(cvm__recombine(&o, &ctx, &in), CVM_OK);
    ck_assert_uint_eq(o.nquad, 64);
    for (c = 0; c < o.ncell; c++)
        ck_assert(o.quality[c] >= 1 - 1e-12);
    cvm__recombine_out_free(&ctx, &o);
    /* the same from per-point tensors */
    g = malloc(3 * t.np * sizeof *g);
    ck_assert_ptr_nonnull(g);
    for (i = 0; i < t.np; i++)
        stretch_metric(0, 0, g + 3 * i, h);
    in.metric = NULL;
    in.g = g;
    ck_assert_int_eq(cvm__recombine(&o, &ctx, &in), CVM_OK);
    ck_assert_uint_eq(o.nquad, 64);
    assert_tiling(&t, &o, 1 - 1e-12);
    cvm__recombine_out_free(&ctx, &o);
    /* Euclidean angles of these slivers' pairs are far from 90: fewer, worse quads */
    in.g = NULL;
    ck_assert_int_eq(cvm__recombine(&o, &ctx, &in), CVM_OK);
    for (c = 0; c < o.ncell; c++)
        if (o.types[c] == CVM_CELL_QUAD)
            ck_assert(o.quality[c] >= 0.5);
    cvm__recombine_out_free(&ctx, &o);
    free(g);
    tmesh_free(&t);
}
END_TEST

START_TEST(recombine_random_delaunay_tiles_with_convex_quads)
{
    tmesh t;
    cvm__recombine_in in;
    cvm__recombine_out ob, og, op;
    cvm__ctx ctx;
    delaunay_mesh(&t, 3000, 41);
    cvm__ctx_init_default(&ctx);
    in = input_of(&t);
    ck_assert_int_eq(cvm__recombine(&ob, &ctx, &in), CVM_OK);
    assert_tiling(&t, &ob, 0.5);
    in.method = CVM__RECOMBINE_GREEDY;
    ck_assert_int_eq(cvm__recombine(&og, &ctx, &in), CVM_OK);
    assert_tiling(&t, &og, 0.5);
    in.method = CVM__RECOMBINE_BLOSSOM;
    in.perfect = 1;
    ck_assert_int_eq(cvm__recombine(&op, &ctx, &in), CVM_OK);
    assert_tiling(&t, &op, 0.5);
    /* the optimum beats greedy (up to the 2^-20 rounding of each weight) */
    ck_assert(ob.total_quality >= og.total_quality - 1e-6 * (double)t.nt);
    ck_assert_uint_ge(op.nquad, ob.nquad);
    ck_assert(ob.total_quality >= op.total_quality - 1e-6 * (double)t.nt);
    ck_assert_uint_gt(2 * ob.nquad, t.nt / 2); /* most triangles pair up */
    cvm__recombine_out_free(&ctx, &ob);
    cvm__recombine_out_free(&ctx, &og);
    cvm__recombine_out_free(&ctx, &op);
    tmesh_free(&t);
}
END_TEST

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

/* All-quad output: every cell a counter-clockwise quad, every point used, areas
 * add up to the input's, and the cells conform: no directed edge twice, and the edges
 * without a reverse are exactly the halves of the input's boundary sides. */
static void assert_all_quad(const tmesh *t, const cvm__recombine_out *o)
{
    uint64_t *de = malloc((4 * o->ncell + 1) * sizeof *de);
    size_t c, k, lone = 0, boundary = 0;
    double at = 0, ac = 0;
    ck_assert_ptr_nonnull(de);
    ck_assert_uint_eq(o->ncell, 4 * o->nquad + 3 * o->ntri);
    for (k = 0; k < t->nt; k++)
        at += area2(t->xy, t->tri + 3 * k, 3);
    for (c = 0; c < o->ncell; c++) {
        const cvm_index *p = o->conn + o->offsets[c];
        ck_assert_int_eq(o->types[c], CVM_CELL_QUAD);
        ck_assert_int_eq(o->offsets[c + 1] - o->offsets[c], 4);
        ck_assert(area2(o->xy, p, 4) > 0);
        ac += area2(o->xy, p, 4);
        for (k = 0; k < 4; k++)
            de[4 * c + k] = (uint64_t)p[k] << 32 | (uint64_t)p[(k + 1) % 4];
    }
    { /* no point left unused */
        unsigned char *used = calloc(o->npts + 1, 1);
        ck_assert_ptr_nonnull(used);
        for (k = 0; k < 4 * o->ncell; k++)
            used[o->conn[k]] = 1;
        for (k = 0; k < o->npts; k++)
            ck_assert(used[k]);
        free(used);
    }
    qsort(de, 4 * o->ncell, sizeof *de, cmp_u64);
    for (k = 0; k < 4 * o->ncell; k++) {
        uint64_t rev = de[k] << 32 | de[k] >> 32;
        ck_assert(k == 0 || de[k] != de[k - 1]);
        lone += bsearch(&rev, de, 4 * o->ncell, sizeof *de, cmp_u64) == NULL;
    }
    for (k = 0; k < 3 * t->nt; k++) { /* boundary sides: no reverse among the triangles */
        cvm_index a = t->tri[k], b = t->tri[k - k % 3 + (k % 3 + 1) % 3];
        size_t j, found = 0;
        for (j = 0; j < 3 * t->nt && !found; j++)
            found = t->tri[j] == b && t->tri[j - j % 3 + (j % 3 + 1) % 3] == a;
        boundary += !found;
    }
    ck_assert_uint_eq(lone, 2 * boundary);
    ck_assert(fabs(ac - at) <= 1e-12 * fabs(at));
    free(de);
}

START_TEST(recombine_all_quad_splits_every_cell_conformingly)
{
    tmesh t;
    cvm__recombine_in in;
    cvm__recombine_out o;
    cvm__ctx ctx;
    size_t c;
    right_grid(&t, 6, 1.0, 1.0);
    cvm__ctx_init_default(&ctx);
    in = input_of(&t);
    in.all_quad = 1;
    ck_assert_int_eq(cvm__recombine(&o, &ctx, &in), CVM_OK);
    ck_assert_uint_eq(o.ncell, 144);
    ck_assert_uint_eq(o.npts, 49 + 36 + 84); /* points, centroids, grid-line midpoints */
    assert_all_quad(&t, &o);
    for (c = 0; c < o.ncell; c++)
        ck_assert(o.quality[c] >= 1 - 1e-12);
    cvm__recombine_out_free(&ctx, &o);
    tmesh_free(&t);
    delaunay_mesh(&t, 400, 17);
    in = input_of(&t);
    in.all_quad = 1;
    ck_assert_int_eq(cvm__recombine(&o, &ctx, &in), CVM_OK);
    ck_assert_uint_gt(o.ntri, 0); /* triangles were left, and split into 3 */
    assert_all_quad(&t, &o);
    cvm__recombine_out_free(&ctx, &o);
    tmesh_free(&t);
}
END_TEST

START_TEST(recombine_keeps_constrained_edges)
{
    tmesh t;
    cvm__recombine_in in;
    cvm__recombine_out o;
    cvm__ctx ctx;
    unsigned char *fixed;
    size_t s;
    right_grid(&t, 4, 1.0, 1.0);
    fixed = calloc(3 * t.nt, 1);
    ck_assert_ptr_nonnull(fixed);
    for (s = 0; s < 3 * t.nt; s++) /* every diagonal fixed: side 2 of the first triangle */
        fixed[s] = (s % 6) == 2;
    cvm__ctx_init_default(&ctx);
    in = input_of(&t);
    in.side_fixed = fixed;
    ck_assert_int_eq(cvm__recombine(&o, &ctx, &in), CVM_OK);
    assert_tiling(&t, &o, 0.5);
    for (s = 0; s < o.ncell; s++) /* what quads remain are parallelograms, q = 0.5 */
        if (o.types[s] == CVM_CELL_QUAD)
            ck_assert(o.quality[s] < 0.5 + 1e-9);
    cvm__recombine_out_free(&ctx, &o);
    free(fixed);
    tmesh_free(&t);
}
END_TEST

START_TEST(recombine_rejects_bad_input_naming_it)
{
    tmesh t;
    cvm__recombine_in in;
    cvm__recombine_out o;
    cvm__ctx ctx;
    double *g;
    right_grid(&t, 2, 1.0, 1.0);
    cvm__ctx_init_default(&ctx);
    in = input_of(&t);
    t.tri[3 * 5 + 1] = 99;
    ck_assert_int_eq(cvm__recombine(&o, &ctx, &in), CVM_E_INPUT_INDEX);
    ck_assert_ptr_nonnull(strstr(ctx.errmsg, "triangle 5"));
    t.tri[3 * 5 + 1] = t.tri[3 * 5 + 2];
    ck_assert_int_eq(cvm__recombine(&o, &ctx, &in), CVM_E_INPUT_DEGENERATE);
    ck_assert_ptr_nonnull(strstr(ctx.errmsg, "triangle 5"));
    tmesh_free(&t);
    right_grid(&t, 2, 1.0, 1.0);
    in = input_of(&t);
    g = calloc(3 * t.np, sizeof *g);
    ck_assert_ptr_nonnull(g);
    g[0] = g[2] = 1;
    in.g = g;
    ck_assert_int_eq(cvm__recombine(&o, &ctx, &in), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(ctx.errmsg, "positive definite"));
    in.g = NULL;
    in.min_quality = 1.5;
    ck_assert_int_eq(cvm__recombine(&o, &ctx, &in), CVM_E_ARGUMENT);
    free(g);
    tmesh_free(&t);
}
END_TEST

START_TEST(recombine_out_of_memory_at_every_allocation)
{
    tmesh t;
    long i;
    delaunay_mesh(&t, 200, 7);
    for (i = 1;; i++) {
        cvmtest_alloc a;
        cvm__ctx ctx;
        cvm__recombine_in in = input_of(&t);
        cvm__recombine_out o;
        cvm_status st;
        in.all_quad = 1;
        cvmtest_alloc_init(&a, i, 0);
        qtest_ctx(&ctx, &a);
        st = cvm__recombine(&o, &ctx, &in);
        if (st == CVM_OK) {
            assert_all_quad(&t, &o);
            cvm__recombine_out_free(&ctx, &o);
            ck_assert_int_eq(a.live_blocks, 0);
            ck_assert_int_gt(i, 10);
            break;
        }
        ck_assert_int_eq(st, CVM_E_NOMEM);
        ck_assert_int_eq(a.live_blocks, 0);
    }
    tmesh_free(&t);
}
END_TEST

TCase *quad_recombine_tcase(void)
{
    TCase *tc = tcase_create("recombine");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, recombine_right_triangle_grid_gives_only_perfect_squares);
    tcase_add_test(tc, recombine_measures_corners_in_the_metric);
    tcase_add_test(tc, recombine_random_delaunay_tiles_with_convex_quads);
    tcase_add_test(tc, recombine_all_quad_splits_every_cell_conformingly);
    tcase_add_test(tc, recombine_keeps_constrained_edges);
    tcase_add_test(tc, recombine_rejects_bad_input_naming_it);
    tcase_add_test(tc, recombine_out_of_memory_at_every_allocation);
    return tc;
}
