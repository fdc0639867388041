/* test_lpcvt_optimise.c - the boundary at unit metric length, the initial sites, and the L-BFGS
 * optimisation of the Lp-CVT energy (lattice recovery, bad metrics, out of memory). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "quad/quad_tests.h"
#include "quad/quad_internal.h"
#include "support/failing_alloc.h"

/* The stretch metric diag(1, 1 + 4y^2): the metric length of x = const from y0 to y1 is
 * F(y1) - F(y0), F(y) = y sqrt(1 + 4y^2) / 2 + asinh(2y) / 4; Gauss-Kronrod gets it to 1e-12,
 * and the pieces of an edge have equal metric length. */
START_TEST(boundary_pieces_have_equal_metric_length)
{
    cvm__metric_builtin b = {CVM__METRIC_STRETCH, 9, {0, 0, 0}};
    double corners[8] = {0, 0, 5, 0, 5, 1.3, 0, 1.3}, *xy, want, got, a[2] = {5, 0}, c[2] = {5, 1.3};
    size_t n, k;
    cvm_sizing *s;
    cvm__ctx ctx;
    cvm__metric mt;
    cvm__ctx_init_default(&ctx);
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    cvm_sizing_set_metric_fn(s, cvm__metric_builtin_fn, 1, &b);
    mt.s = s;
    mt.bnd = corners;
    mt.nbnd = 4;
    want = 3 * (1.3 * sqrt(1 + 4 * 1.3 * 1.3) / 2 + asinh(2 * 1.3) / 4);
    ck_assert_int_eq(cvm__metric_length(&got, &mt, a, c, 0, 1, &ctx), CVM_OK);
    ck_assert_msg(fabs(got - want) <= 1e-12 * want, "length %.17g, exact %.17g", got, want);
    ck_assert_int_eq(cvm__boundary_discretise(&xy, &n, &mt, corners, 4, &ctx), CVM_OK);
    /* bottom and top: 15 pieces (length 3 * 5); sides: round(want) */
    ck_assert_uint_eq(n, 30 + 2 * (size_t)floor(want + 0.5));
    for (k = 0; k < n; k++) {
        const double *p = xy + 2 * k, *q = xy + 2 * ((k + 1) % n);
        double l, e[2] = {0, 0};
        ck_assert_int_eq(cvm__metric_length(&l, &mt, p, q, 0, 1, &ctx), CVM_OK);
        e[0] = k < 15 ? 1.0 : k < 15 + (n - 30) / 2 ? want / ((double)(n - 30) / 2) : 1.0;
        if (k >= 15 + (n - 30) / 2 && k < 30 + (n - 30) / 2)
            e[0] = 1.0;
        else if (k >= 30 + (n - 30) / 2)
            e[0] = want / ((double)(n - 30) / 2);
        ck_assert_msg(fabs(l - e[0]) <= 1e-10, "piece %lu has metric length %.15g, want %.15g",
                      (unsigned long)k, l, e[0]);
    }
    /* the same edges elsewhere (the metric does not depend on x) get the same points, bit for bit */
    {
        double moved[8] = {10, 0, 15, 0, 15, 1.3, 10, 1.3}, *xy2;
        size_t n2;
        mt.bnd = moved;
        ck_assert_int_eq(cvm__boundary_discretise(&xy2, &n2, &mt, moved, 4, &ctx), CVM_OK);
        ck_assert_uint_eq(n2, n);
        for (k = 0; k < n; k++) {
            ck_assert(xy2[2 * k + 1] == xy[2 * k + 1]);
            ck_assert(fabs(xy2[2 * k] - 10 - xy[2 * k]) <= 1e-14);
        }
        cvm__free(&ctx, xy2);
    }
    cvm__free(&ctx, xy);
    cvm_sizing_free(s);
}
END_TEST

/* The lattice of paper Table 1 is recovered from random starts: 9 sites uniform in
 * [0.2, 3.8]^2, L-BFGS with relocations, every site within 1e-6 of a lattice point (so every
 * lattice edge has metric length 1 +- 2e-6), for at least 95 of 100 seeds. */
START_TEST(lpcvt_recovers_the_lattice_from_random_starts)
{
    cvm__metric_builtin b = {CVM__METRIC_IDENTITY, 1, {0, 0, 0}};
    double corners[8] = {0, 0, 4, 0, 4, 4, 0, 4}, *bxy;
    size_t nb;
    cvm_sizing *s;
    cvm__ctx ctx;
    cvm__metric mt;
    int seed, ok = 0;
    cvm__ctx_init_default(&ctx);
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    cvm_sizing_set_metric_fn(s, cvm__metric_builtin_fn, 1, &b);
    mt.s = s;
    mt.bnd = corners;
    mt.nbnd = 4;
    ck_assert_int_eq(cvm__boundary_discretise(&bxy, &nb, &mt, corners, 4, &ctx), CVM_OK);
    ck_assert_uint_eq(nb, 16);
    for (seed = 0; seed < 100; seed++) {
        unsigned long long st = (unsigned long long)seed * 7919 + 1;
        cvm__lpcvt L;
        cvm__lbfgs_opts o;
        cvm__lbfgs_result res;
        double xi[18], err = 0;
        int i, j, found;
        for (i = 0; i < 18; i++)
            xi[i] = 0.2 + 3.6 * qtest_uniform(&st);
        ck_assert_int_eq(cvm__lpcvt_init(&L, &ctx, s, bxy, nb, 9, 6, 0), CVM_OK);
        cvm__lbfgs_defaults(&o);
        ck_assert_int_eq(cvm__lpcvt_optimise(&L, xi, &o, &res), CVM_OK);
        ck_assert_int_eq(res.outside, 0);
        for (i = 0; i < 9; i++) { /* the nearest lattice point of each site, each taken once */
            double px = 1 + i % 3, py = 1 + i / 3, best = INFINITY;
            for (found = 0, j = 0; j < 9; j++)
                best = fmin(best, fmax(fabs(xi[2 * j] - px), fabs(xi[2 * j + 1] - py)));
            err = fmax(err, best);
        }
        ok += err <= 1e-6;
        (void)found;
        cvm__lpcvt_free(&L);
    }
    ck_assert_msg(ok >= 95, "lattice recovered from %d of 100 seeds", ok);
    cvm__free(&ctx, bxy);
    cvm_sizing_free(s);
}
END_TEST

/* The initial sites: the interior count of a unit grid (9 in [0,4]^2 under g = I), strictly
 * inside, the same for the same seed. */
START_TEST(lpcvt_initial_sites_follow_the_metric_area)
{
    cvm__metric_builtin b = {CVM__METRIC_IDENTITY, 1, {0, 0, 0}};
    double corners[8] = {0, 0, 4, 0, 4, 4, 0, 4}, *bxy, *x1, *x2;
    size_t nb, n1, n2, k;
    cvm_sizing *s;
    cvm__ctx ctx;
    cvm__metric mt;
    cvm__lpcvt L;
    cvm__ctx_init_default(&ctx);
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    cvm_sizing_set_metric_fn(s, cvm__metric_builtin_fn, 1, &b);
    mt.s = s;
    mt.bnd = corners;
    mt.nbnd = 4;
    ck_assert_int_eq(cvm__boundary_discretise(&bxy, &nb, &mt, corners, 4, &ctx), CVM_OK);
    ck_assert_int_eq(cvm__lpcvt_initial_sites(&x1, &n1, &mt, bxy, nb, 42, &ctx), CVM_OK);
    ck_assert_int_eq(cvm__lpcvt_initial_sites(&x2, &n2, &mt, bxy, nb, 42, &ctx), CVM_OK);
    ck_assert_uint_eq(n1, 9);
    ck_assert_uint_eq(n2, 9);
    ck_assert(memcmp(x1, x2, 18 * sizeof *x1) == 0);
    ck_assert_int_eq(cvm__lpcvt_init(&L, &ctx, s, bxy, nb, n1, 6, 0), CVM_OK);
    for (k = 0; k < n1; k++)
        ck_assert(cvm__lpcvt_inside(&L, x1 + 2 * k));
    cvm__lpcvt_free(&L);
    cvm__free(&ctx, x1);
    cvm__free(&ctx, x2);
    cvm__free(&ctx, bxy);
    cvm_sizing_free(s);
}
END_TEST

/* The frontal start reproduces the lattice of metric squares where one exists: the 3 x 3
 * interior of [0,4]^2 under g = I, and under the constant metric of unit steps 1/2 along
 * (cos 30, sin 30) and 1/4 across it (a rotated rectangle lattice clipped to a rotated
 * square); sites strictly inside, the same twice. */
START_TEST(lpcvt_frontal_sites_reproduce_a_lattice)
{
    cvm__metric_builtin b = {CVM__METRIC_IDENTITY, 1, {0, 0, 0}};
    double corners[8] = {0, 0, 4, 0, 4, 4, 0, 4}, *bxy, *x1, *x2, err = 0;
    size_t nb, n1, n2, k;
    cvm_sizing *s;
    cvm__ctx ctx;
    cvm__metric mt;
    qtest_metric(&s, &mt, &ctx, &b, corners, 4);
    ck_assert_int_eq(cvm__boundary_discretise(&bxy, &nb, &mt, corners, 4, &ctx), CVM_OK);
    ck_assert_int_eq(cvm__lpcvt_frontal_sites(&x1, &n1, &mt, bxy, nb, corners, 4, 1000, &ctx),
                     CVM_OK);
    ck_assert_int_eq(cvm__lpcvt_frontal_sites(&x2, &n2, &mt, bxy, nb, corners, 4, 1000, &ctx),
                     CVM_OK);
    ck_assert_uint_eq(n1, 9);
    ck_assert_uint_eq(n2, 9);
    ck_assert(memcmp(x1, x2, 18 * sizeof *x1) == 0);
    for (k = 0; k < n1; k++) {
        err = fmax(err, fabs(x1[2 * k] - floor(x1[2 * k] + 0.5)));
        err = fmax(err, fabs(x1[2 * k + 1] - floor(x1[2 * k + 1] + 0.5)));
        ck_assert(x1[2 * k] > 0.5 && x1[2 * k] < 3.5 && x1[2 * k + 1] > 0.5 && x1[2 * k + 1] < 3.5);
    }
    ck_assert_msg(err < 1e-12, "off the lattice by %g", err);
    cvm__free(&ctx, x1);
    cvm__free(&ctx, x2);
    cvm__free(&ctx, bxy);
    {
        /* g = Q diag(4, 16) Q^T, Q the rotation by 30 degrees; the domain a square of side 3
         * with the same axes, so the boundary sites lie on the lattice */
        double c = sqrt(3.0) / 2, sn = 0.5, rc[8], lat[2][2];
        size_t bad = 0;
        b.kind = CVM__METRIC_CONSTANT;
        b.g[0] = 4 * c * c + 16 * sn * sn;
        b.g[1] = (4 - 16) * c * sn;
        b.g[2] = 4 * sn * sn + 16 * c * c;
        rc[0] = 0, rc[1] = 0;
        rc[2] = 3 * c, rc[3] = 3 * sn;
        rc[4] = 3 * c - 3 * sn, rc[5] = 3 * sn + 3 * c;
        rc[6] = -3 * sn, rc[7] = 3 * c;
        mt.bnd = rc;
        lat[0][0] = 0.5 * c, lat[0][1] = 0.5 * sn;    /* unit metric step along Q e1 */
        lat[1][0] = -0.25 * sn, lat[1][1] = 0.25 * c; /* and along Q e2 */
        ck_assert_int_eq(cvm__boundary_discretise(&bxy, &nb, &mt, rc, 4, &ctx), CVM_OK);
        ck_assert_int_eq(cvm__lpcvt_frontal_sites(&x1, &n1, &mt, bxy, nb, rc, 4, 1000, &ctx),
                         CVM_OK);
        ck_assert_uint_eq(n1, 5 * 11); /* (6 - 1) x (12 - 1) interior lattice points */
        for (k = 0; k < n1; k++) {
            /* lattice coordinates: x = i lat0 + j lat1 */
            double i = (x1[2 * k] * lat[0][0] + x1[2 * k + 1] * lat[0][1]) / 0.25;
            double j = (x1[2 * k] * lat[1][0] + x1[2 * k + 1] * lat[1][1]) / 0.0625;
            bad += fabs(i - floor(i + 0.5)) > 1e-9 || fabs(j - floor(j + 0.5)) > 1e-9;
        }
        ck_assert_msg(bad == 0, "%zu of %zu sites off the lattice", bad, n1);
        cvm__free(&ctx, x1);
        cvm__free(&ctx, bxy);
        /* the same metric in the axis-aligned [0,4]^2: no boundary site follows the frame, the
         * front still fills the domain (about the metric area's count of sites) */
        mt.bnd = corners;
        {
            double A, rmax;
            ck_assert_int_eq(cvm__boundary_discretise(&bxy, &nb, &mt, corners, 4, &ctx), CVM_OK);
            ck_assert_int_eq(cvm__metric_area(&A, &rmax, &mt, corners, 4, &ctx), CVM_OK);
            ck_assert_int_eq(cvm__lpcvt_frontal_sites(&x1, &n1, &mt, bxy, nb, corners, 4, 10000,
                                                      &ctx), CVM_OK);
            A = A - 0.5 * (double)nb + 1;
            ck_assert_msg(fabs((double)n1 - A) <= 0.15 * A, "%zu sites, the area asks for %g", n1, A);
            for (k = 0; k < n1; k++)
                ck_assert(x1[2 * k] > 0 && x1[2 * k] < 4 && x1[2 * k + 1] > 0 && x1[2 * k + 1] < 4);
            cvm__free(&ctx, x1);
            cvm__free(&ctx, bxy);
        }
    }
    cvm_sizing_free(s);
}
END_TEST

static int identity_metric(double x, double y, double g[3], void *user)
{
    (void)x;
    (void)y;
    (void)user;
    g[0] = g[2] = 1;
    g[1] = 0;
    return 0;
}

/* A 7 x 7 grid of unit squares whose interior columns zig-zag by +-0.2 in y: parallelogram
 * smoothing straightens it back to the lattice (the boundary is fixed), every cell stays
 * convex, and the lattice itself does not move. The grid is stored with its 32 boundary
 * points first. */
static void zigzag_grid(double *xy, int32_t *off, int32_t *types, int32_t *conn, int32_t *id,
                        double amp)
{
    int i, j, nb = 0, ni = 32, c = 0;
    for (j = 0; j <= 8; j++)
        for (i = 0; i <= 8; i++) {
            int b = i == 0 || j == 0 || i == 8 || j == 8;
            int v = b ? nb++ : ni++;
            id[j * 9 + i] = v;
            xy[2 * v] = i;
            xy[2 * v + 1] = j + (b ? 0 : (i % 2 ? amp : -amp));
        }
    for (j = 0; j < 8; j++)
        for (i = 0; i < 8; i++, c++) {
            off[c] = 4 * c;
            types[c] = CVM_CELL_QUAD;
            conn[4 * c] = id[j * 9 + i];
            conn[4 * c + 1] = id[j * 9 + i + 1];
            conn[4 * c + 2] = id[(j + 1) * 9 + i + 1];
            conn[4 * c + 3] = id[(j + 1) * 9 + i];
        }
    off[c] = 4 * c;
}

START_TEST(quad_smoothing_straightens_a_zigzag_grid)
{
    double xy[162], q[64], err = 0;
    int32_t off[65], types[64], conn[256], id[81];
    cvm__quad_smooth_in in;
    cvm__ctx ctx;
    size_t moves, k;
    cvm__ctx_init_default(&ctx);
    zigzag_grid(xy, off, types, conn, id, 0.2);
    memset(&in, 0, sizeof in);
    in.nv = 81;
    in.first_free = 32;
    in.ncell = 64;
    in.off = off;
    in.types = types;
    in.conn = conn;
    in.metric = identity_metric;
    in.sweeps = 1000;
    in.quality = q;
    ck_assert_int_eq(cvm__quad_smooth(&ctx, xy, &in, &moves), CVM_OK);
    ck_assert(moves > 0);
    for (k = 0; k < 81; k++) {
        err = fmax(err, fabs(xy[2 * k] - floor(xy[2 * k] + 0.5)));
        err = fmax(err, fabs(xy[2 * k + 1] - floor(xy[2 * k + 1] + 0.5)));
    }
    ck_assert_msg(err < 1e-3, "%g off the lattice after %zu moves", err, moves);
    for (k = 0; k < 64; k++)
        ck_assert_msg(q[k] > 0.99, "quad %zu quality %g", k, q[k]);
    /* the lattice is a fixed point */
    zigzag_grid(xy, off, types, conn, id, 0);
    ck_assert_int_eq(cvm__quad_smooth(&ctx, xy, &in, &moves), CVM_OK);
    ck_assert_uint_eq(moves, 0);
    /* every allocation may fail: CVM_E_NOMEM and the points unchanged */
    {
        cvmtest_alloc a;
        double before[162];
        long n;
        for (n = 1; n <= 2; n++) {
            zigzag_grid(xy, off, types, conn, id, 0.2);
            memcpy(before, xy, sizeof before);
            cvmtest_alloc_init(&a, n, 0);
            ctx.alloc_fn = cvmtest_malloc;
            ctx.realloc_fn = cvmtest_realloc;
            ctx.free_fn = cvmtest_free;
            ctx.payload = &a;
            ck_assert_int_eq(cvm__quad_smooth(&ctx, xy, &in, &moves), CVM_E_NOMEM);
            ck_assert(memcmp(before, xy, sizeof before) == 0);
            ck_assert_int_eq(a.live_blocks, 0);
        }
    }
}
END_TEST

/* One insertion/removal cycle on [0,4]^2 under g = I: four sites at (1|3, 1|3) leave quad sides
 * of length 2 (a site goes to each midpoint), and a tenth site 0.2 from the centre of the 3 x 3
 * lattice gives one side of 0.2 (one of the two ends goes); the lattice itself is left as it is. */
START_TEST(lpcvt_cycle_inserts_and_removes_sites)
{
    cvm__metric_builtin b = {CVM__METRIC_IDENTITY, 1, {0, 0, 0}};
    double bxy[32], four[8] = {1, 1, 3, 1, 1, 3, 3, 3}, ten[20], *xo, pct;
    size_t no, nins, nrem, k, mids = 0;
    cvm_sizing *s;
    cvm__ctx ctx;
    cvm__lpcvt L;
    cvm__ctx_init_default(&ctx);
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    cvm_sizing_set_metric_fn(s, cvm__metric_builtin_fn, 1, &b);
    qtest_box(bxy, 0, 0, 4, 4, 4);
    ck_assert_int_eq(cvm__lpcvt_init(&L, &ctx, s, bxy, 16, 4, 6, 0), CVM_OK);
    ck_assert_int_eq(cvm__lpcvt_adapt_sites(&L, four, &xo, &no, &nins, &nrem, &pct), CVM_OK);
    ck_assert_ptr_nonnull(xo);
    ck_assert(pct < 95);
    ck_assert_uint_eq(nrem, 0);
    ck_assert_uint_eq(no, 4 + nins);
    for (k = 4; k < no; k++) /* (2, 1), (1, 2), (3, 2), (2, 3) among the new sites */
        mids += (xo[2 * k] == 2 && (xo[2 * k + 1] == 1 || xo[2 * k + 1] == 3)) ||
                (xo[2 * k + 1] == 2 && (xo[2 * k] == 1 || xo[2 * k] == 3));
    ck_assert_uint_eq(mids, 4);
    cvm__free(&ctx, xo);
    cvm__lpcvt_free(&L);
    for (k = 0; k < 9; k++) {
        ten[2 * k] = 1 + (double)(k % 3);
        ten[2 * k + 1] = 1 + (double)(k / 3);
    }
    ck_assert_int_eq(cvm__lpcvt_init(&L, &ctx, s, bxy, 16, 9, 6, 0), CVM_OK);
    ck_assert_int_eq(cvm__lpcvt_adapt_sites(&L, ten, &xo, &no, &nins, &nrem, &pct), CVM_OK);
    ck_assert_ptr_null(xo); /* the lattice: every side has length 1 */
    ck_assert_double_eq(pct, 100);
    cvm__lpcvt_free(&L);
    ten[18] = 2;
    ten[19] = 2.2;
    ck_assert_int_eq(cvm__lpcvt_init(&L, &ctx, s, bxy, 16, 10, 6, 0), CVM_OK);
    ck_assert_int_eq(cvm__lpcvt_adapt_sites(&L, ten, &xo, &no, &nins, &nrem, &pct), CVM_OK);
    ck_assert_ptr_nonnull(xo);
    ck_assert_uint_eq(nrem, 1);
    ck_assert_uint_eq(no, 9 + nins);
    cvm__free(&ctx, xo);
    cvm__lpcvt_free(&L);
    cvm_sizing_free(s);
}
END_TEST

static int nan_inside(void *payload, const double *x, int dim, double *g, double *dg)
{
    (void)payload;
    (void)dim;
    g[0] = x[0] > 1.5 && x[0] < 2.5 ? NAN : 1;
    g[1] = 0;
    g[2] = x[1] > 2.9 && x[1] < 3.1 ? -1 : 1;
    if (dg)
        memset(dg, 0, 6 * sizeof *dg);
    return 0;
}

/* A metric that is NaN or indefinite somewhere in the domain stops the energy with
 * CVM_E_ARGUMENT naming the point. */
START_TEST(lpcvt_bad_metric_is_an_argument_error)
{
    double bxy[32], xi[18], E, grad[18];
    cvm_sizing *s;
    cvm__ctx ctx;
    cvm__lpcvt L;
    int i;
    cvm__ctx_init_default(&ctx);
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    cvm_sizing_set_metric_fn(s, nan_inside, 1, NULL);
    qtest_box(bxy, 0, 0, 4, 4, 4);
    for (i = 0; i < 9; i++) {
        xi[2 * i] = 1 + i % 3;
        xi[2 * i + 1] = 1 + i / 3;
    }
    /* the boundary sites at x = 2 meet the NaN when their ghosts are made */
    ck_assert_int_eq(cvm__lpcvt_init(&L, &ctx, s, bxy, 16, 9, 6, 0), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(ctx.errmsg, "non-finite"));
    cvm__lpcvt_free(&L);
    ck_assert_int_eq(cvm__lpcvt_init(&L, &ctx, s, bxy, 16, 9, 6, 1), CVM_OK);
    ck_assert_int_eq(cvm__lpcvt_eval(&L, xi, &E, grad), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(ctx.errmsg, "the metric at ("));
    cvm__lpcvt_free(&L);
    cvm_sizing_free(s);
}
END_TEST

/* Every allocation of boundary, initial sites, energy and optimisation may fail: CVM_E_NOMEM,
 * nothing leaked, and a run that passes the last allocation succeeds. */
START_TEST(lpcvt_out_of_memory_sweep)
{
    cvm__metric_builtin b = {CVM__METRIC_SADDLE, 4, {0, 0, 0}};
    double corners[8] = {-1.3, -1.3, 1.3, -1.3, 1.3, 1.3, -1.3, 1.3};
    cvm_sizing *s;
    long k;
    int done = 0;
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    cvm_sizing_set_metric_fn(s, cvm__metric_builtin_fn, 1, &b);
    for (k = 1; k < 100000 && !done; k++) {
        cvmtest_alloc a;
        cvm__ctx ctx;
        cvm__metric mt;
        cvm__lpcvt L;
        cvm__lbfgs_opts o;
        cvm__lbfgs_result res;
        double *bxy = NULL, *xi = NULL;
        size_t nb = 0, ni = 0;
        cvm_status st;
        cvmtest_alloc_init(&a, k, 0);
        cvm__ctx_init_default(&ctx);
        ctx.alloc_fn = cvmtest_malloc;
        ctx.realloc_fn = cvmtest_realloc;
        ctx.free_fn = cvmtest_free;
        ctx.payload = &a;
        mt.s = s;
        mt.bnd = corners;
        mt.nbnd = 4;
        memset(&L, 0, sizeof L);
        st = cvm__boundary_discretise(&bxy, &nb, &mt, corners, 4, &ctx);
        if (!st) /* both starts: the frontal one is the default */
            st = cvm__lpcvt_initial_sites(&xi, &ni, &mt, bxy, nb, 7, &ctx);
        if (!st) {
            cvm__free(&ctx, xi);
            xi = NULL;
            st = cvm__lpcvt_frontal_sites(&xi, &ni, &mt, bxy, nb, corners, 4, 100000, &ctx);
        }
        if (!st)
            st = cvm__lpcvt_init(&L, &ctx, s, bxy, nb, ni, 4, 0);
        if (!st) {
            cvm__lbfgs_defaults(&o);
            o.max_iter = 20;
            o.relocations = 1;
            st = cvm__lpcvt_optimise(&L, xi, &o, &res);
        }
        if (!st) { /* and one insertion/removal cycle */
            double *xo = NULL, pct;
            size_t no, nins, nrem;
            st = cvm__lpcvt_adapt_sites(&L, xi, &xo, &no, &nins, &nrem, &pct);
            cvm__free(&ctx, xo);
        }
        ck_assert_msg(st == CVM_OK || st == CVM_E_NOMEM, "allocation %ld: status %d (%s)", k,
                      (int)st, ctx.errmsg);
        done = st == CVM_OK && a.n_failed == 0;
        cvm__lpcvt_free(&L);
        cvm__free(&ctx, bxy);
        cvm__free(&ctx, xi);
        ck_assert_msg(a.live_blocks == 0, "allocation %ld: %ld blocks leaked", k, a.live_blocks);
    }
    ck_assert(done);
    cvm_sizing_free(s);
}
END_TEST

TCase *quad_lpcvt_optimise_tcase(void)
{
    TCase *tc = tcase_create("lpcvt_optimise");
    tcase_set_timeout(tc, 300);
    tcase_add_test(tc, boundary_pieces_have_equal_metric_length);
    tcase_add_test(tc, lpcvt_initial_sites_follow_the_metric_area);
    tcase_add_test(tc, lpcvt_frontal_sites_reproduce_a_lattice);
    tcase_add_test(tc, quad_smoothing_straightens_a_zigzag_grid);
    tcase_add_test(tc, lpcvt_cycle_inserts_and_removes_sites);
    tcase_add_test(tc, lpcvt_bad_metric_is_an_argument_error);
    tcase_add_test(tc, lpcvt_recovers_the_lattice_from_random_starts);
    tcase_add_test(tc, lpcvt_out_of_memory_sweep);
    return tc;
}
