/* test_metric.c - the metric field: built-in fields and their exact derivatives, the factor
 * M = Lambda^(1/2) Q^T, |Hessian| clamping, and the checks of every evaluation. */
#include <math.h>
#include <string.h>
#include "quad/quad_tests.h"
#include "quad/quad_internal.h"

static const cvm__metric_kind kinds[] = {CVM__METRIC_IDENTITY, CVM__METRIC_STRETCH,
                                          CVM__METRIC_SADDLE, CVM__METRIC_SSHOCK};

/* The derivatives each built-in field returns agree with central differences of its values. */
START_TEST(metric_builtin_derivatives_match_differences)
{
    unsigned long long st = 11;
    size_t kk;
    for (kk = 0; kk < sizeof kinds / sizeof kinds[0]; kk++) {
        cvm__metric_builtin b = {kinds[kk], 2.5, {0, 0, 0}};
        int trial;
        for (trial = 0; trial < 200; trial++) {
            double x[2], g[3], dg[6], gp[3], gm[3], h = 1e-6;
            int m, k;
            x[0] = 2 * qtest_uniform(&st) - 1;
            x[1] = 2 * qtest_uniform(&st) - 1;
            ck_assert_int_eq(cvm__metric_builtin_fn(&b, x, 2, g, dg), 0);
            for (m = 0; m < 2; m++) {
                double xp[2] = {x[0], x[1]}, xm[2] = {x[0], x[1]};
                xp[m] += h;
                xm[m] -= h;
                cvm__metric_builtin_fn(&b, xp, 2, gp, NULL);
                cvm__metric_builtin_fn(&b, xm, 2, gm, NULL);
                for (k = 0; k < 3; k++) {
                    double fd = (gp[k] - gm[k]) / (2 * h);
                    double scale = fabs(g[0]) + fabs(g[2]);
                    ck_assert_msg(fabs(fd - dg[3 * m + k]) <= 1e-6 * scale * (1 + fabs(fd) / scale),
                                  "kind %d at (%g, %g): d g%d / d x%d = %.10g, differences %.10g",
                                  (int)b.kind, x[0], x[1], k, m, dg[3 * m + k], fd);
                }
            }
        }
    }
}
END_TEST

/* M^T M = g, and dM agrees with differences of the factor along the field. */
START_TEST(metric_factor_reproduces_g_and_its_derivative)
{
    unsigned long long st = 5;
    size_t kk;
    for (kk = 0; kk < sizeof kinds / sizeof kinds[0]; kk++) {
        cvm__metric_builtin b = {kinds[kk], 1, {0, 0, 0}};
        int trial;
        for (trial = 0; trial < 200; trial++) {
            double x[2], g[3], dg[6], M[4], dM[8], Mp[4], Mm[4], gq[3], h = 1e-6;
            int m, k;
            x[0] = 2.6 * qtest_uniform(&st) - 1.3;
            x[1] = 2.6 * qtest_uniform(&st) - 1.3;
            cvm__metric_builtin_fn(&b, x, 2, g, dg);
            cvm__metric_factor(M, dM, g, dg);
            ck_assert(fabs(M[0] * M[0] + M[2] * M[2] - g[0]) <= 1e-12 * g[0]);
            ck_assert(fabs(M[0] * M[1] + M[2] * M[3] - g[1]) <= 1e-12 * (g[0] + g[2]));
            ck_assert(fabs(M[1] * M[1] + M[3] * M[3] - g[2]) <= 1e-12 * g[2]);
            for (m = 0; m < 2; m++) {
                double xp[2] = {x[0], x[1]}, xm[2] = {x[0], x[1]};
                xp[m] += h;
                xm[m] -= h;
                cvm__metric_builtin_fn(&b, xp, 2, gq, NULL);
                cvm__metric_factor(Mp, NULL, gq, NULL);
                cvm__metric_builtin_fn(&b, xm, 2, gq, NULL);
                cvm__metric_factor(Mm, NULL, gq, NULL);
                for (k = 0; k < 4; k++) {
                    double fd = (Mp[k] - Mm[k]) / (2 * h), sc = sqrt(g[0] + g[2]);
                    if (fabs(Mp[k] - Mm[k]) > 0.1 * sc) /* an eigenvector swap between x-h and x+h */
                        continue;
                    ck_assert_msg(fabs(fd - dM[4 * m + k]) <= 1e-5 * sc * (1 + fabs(fd) / sc),
                                  "kind %d at (%g, %g): dM%d/dx%d = %.10g, differences %.10g",
                                  (int)b.kind, x[0], x[1], k, m, dM[4 * m + k], fd);
                }
            }
        }
    }
}
END_TEST

/* The energy's batch of M and dM for the built-in fields (each kind has its own path): M^T M = g,
 * d(M^T M) = dg, and dM agrees with differences of the batch's own M. */
START_TEST(metric_batch_factor_matches_the_field)
{
    unsigned long long st = 23;
    size_t kk;
    cvm__ctx ctx;
    cvm__ctx_init_default(&ctx);
    for (kk = 1; kk < sizeof kinds / sizeof kinds[0]; kk++) {
        cvm__metric_builtin b = {kinds[kk], 2.5, {0, 0, 0}};
        cvm_sizing *s;
        cvm__metric mt;
        int trial;
        ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
        cvm_sizing_set_metric_fn(s, cvm__metric_builtin_fn, 1, &b);
        mt.s = s;
        mt.bnd = NULL;
        mt.nbnd = 0;
        for (trial = 0; trial < 40; trial++) {
            double y[2 * 12], M[4 * 12], dM[8 * 12], yq[2 * 3], Mq[4 * 3], dMq[8 * 3], h = 1e-6;
            int q, m, k;
            for (q = 0; q < 12; q++) {
                y[2 * q] = 2.6 * qtest_uniform(&st) - 1.3;
                y[2 * q + 1] = 2.6 * qtest_uniform(&st) - 1.3;
            }
            ck_assert_int_eq(cvm__metric_eval_M_batch(&mt, y, 12, M, dM, &ctx), CVM_OK);
            for (q = 0; q < 12; q++) {
                const double *P = M + 4 * q, *dP = dM + 8 * q;
                double g[3], dg[6], sc;
                ck_assert_int_eq(cvm__metric_eval(&mt, y + 2 * q, g, dg, &ctx), CVM_OK);
                sc = g[0] + g[2];
                ck_assert(fabs(P[0] * P[0] + P[2] * P[2] - g[0]) <= 1e-12 * sc);
                ck_assert(fabs(P[0] * P[1] + P[2] * P[3] - g[1]) <= 1e-12 * sc);
                ck_assert(fabs(P[1] * P[1] + P[3] * P[3] - g[2]) <= 1e-12 * sc);
                for (m = 0; m < 2; m++) {
                    const double *D = dP + 4 * m;
                    double d0 = 2 * (D[0] * P[0] + D[2] * P[2]);
                    double d1 = D[0] * P[1] + P[0] * D[1] + D[2] * P[3] + P[2] * D[3];
                    double d2 = 2 * (D[1] * P[1] + D[3] * P[3]);
                    double ds = 1e-9 * (sc + fabs(dg[3 * m]) + fabs(dg[3 * m + 2]));
                    ck_assert_msg(fabs(d0 - dg[3 * m]) <= ds && fabs(d1 - dg[3 * m + 1]) <= ds &&
                                      fabs(d2 - dg[3 * m + 2]) <= ds,
                                  "kind %d at (%g, %g): d(M^T M)/dx%d differs from dg",
                                  (int)b.kind, y[2 * q], y[2 * q + 1], m);
                    /* x - h, x + h and x itself in one batch */
                    yq[0] = yq[2] = yq[4] = y[2 * q];
                    yq[1] = yq[3] = yq[5] = y[2 * q + 1];
                    yq[m] -= h;
                    yq[2 + m] += h;
                    ck_assert_int_eq(cvm__metric_eval_M_batch(&mt, yq, 3, Mq, dMq, &ctx), CVM_OK);
                    for (k = 0; k < 4; k++) {
                        double fd = (Mq[4 + k] - Mq[k]) / (2 * h), r = sqrt(sc);
                        if (fabs(Mq[4 + k] - Mq[k]) > 0.1 * r) /* an eigenvector swap */
                            continue;
                        ck_assert_msg(fabs(fd - D[k]) <= 1e-5 * r * (1 + fabs(fd) / r),
                                      "kind %d at (%g, %g): dM%d/dx%d = %.10g, differences %.10g",
                                      (int)b.kind, y[2 * q], y[2 * q + 1], k, m, D[k], fd);
                    }
                }
            }
        }
        cvm_sizing_free(s);
    }
}
END_TEST

/* The S-shock sizes stay in [0.005, 0.2] with aspect ratio <= 50. */
START_TEST(metric_hessian_sizes_are_clamped)
{
    cvm__metric_builtin b = {CVM__METRIC_SSHOCK, 1, {0, 0, 0}};
    unsigned long long st = 3;
    int trial, clamped_min = 0;
    for (trial = 0; trial < 5000; trial++) {
        double x[2], g[3];
        cvm__eig2 e;
        x[0] = 2 * qtest_uniform(&st) - 1;
        x[1] = 2 * qtest_uniform(&st) - 1;
        cvm__metric_builtin_fn(&b, x, 2, g, NULL);
        cvm__eig2_of(&e, g, NULL);
        ck_assert(e.lam[0] <= 1 / (0.005 * 0.005) * (1 + 1e-12));
        ck_assert(e.lam[1] >= 1 / (0.2 * 0.2) * (1 - 1e-12));
        ck_assert(e.lam[0] <= 2500 * e.lam[1] * (1 + 1e-12));
        clamped_min += e.lam[1] <= 25 * (1 + 1e-12);
    }
    ck_assert(clamped_min > 0);
}
END_TEST

static int nan_metric(void *payload, const double *x, int dim, double *g, double *dg)
{
    (void)payload;
    (void)dim;
    g[0] = x[0] > 0.5 ? NAN : 1;
    g[1] = 0;
    g[2] = 1;
    if (dg)
        memset(dg, 0, 6 * sizeof *dg);
    return 0;
}

static int indefinite_metric(void *payload, const double *x, int dim, double *g, double *dg)
{
    (void)payload;
    (void)dim;
    (void)x;
    g[0] = 1;
    g[1] = 2; /* eigenvalues 3 and -1 */
    g[2] = 1;
    if (dg)
        memset(dg, 0, 6 * sizeof *dg);
    return 0;
}

/* NaN, an indefinite tensor, and a callback without derivatives: CVM_E_ARGUMENT naming the point. */
START_TEST(metric_bad_values_are_refused_naming_the_point)
{
    cvm_sizing *s;
    cvm__ctx ctx;
    cvm__metric mt = {NULL, NULL, 0};
    double y[2] = {0.75, 0.25}, g[3], dg[6];
    cvm__ctx_init_default(&ctx);
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    mt.s = s;
    ck_assert_int_eq(cvm__metric_eval(&mt, y, g, dg, &ctx), CVM_E_ARGUMENT); /* no metric */
    cvm_sizing_set_metric_fn(s, nan_metric, 1, NULL);
    ck_assert_int_eq(cvm__metric_eval(&mt, y, g, dg, &ctx), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(ctx.errmsg, "(0.75, 0.25)"));
    ck_assert_ptr_nonnull(strstr(ctx.errmsg, "non-finite"));
    y[0] = 0.25;
    ck_assert_int_eq(cvm__metric_eval(&mt, y, g, dg, &ctx), CVM_OK);
    cvm_sizing_set_metric_fn(s, indefinite_metric, 1, NULL);
    ck_assert_int_eq(cvm__metric_eval(&mt, y, g, dg, &ctx), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(ctx.errmsg, "(0.25, 0.25)"));
    ck_assert_ptr_nonnull(strstr(ctx.errmsg, "not positive definite"));
    cvm_sizing_set_metric_fn(s, nan_metric, 0, NULL);
    ck_assert_int_eq(cvm__metric_eval(&mt, y, g, dg, &ctx), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(ctx.errmsg, "derivatives"));
    cvm_sizing_free(s);
}
END_TEST


/* Log-Euclidean interpolation: the node tensors at the nodes, the geometric mean half-way
 * (sqrt(1 * 4) = 2 between I and 4I), SPD everywhere, exact derivatives, refused outside. */
START_TEST(metric_background_is_log_euclidean)
{
    static const double xy[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    static const int32_t tri[6] = {0, 1, 2, 0, 2, 3};
    static const double gn[12] = {1, 0, 1, 4, 0, 4, 9, 2, 1, 2, -1, 3};
    cvm__metric_bg bg;
    cvm__ctx ctx;
    double x[2], g[3], dg[6], gp[3], gm[3], bad[12];
    unsigned long long st = 9;
    int k, trial, m;
    cvm__ctx_init_default(&ctx);
    ck_assert_int_eq(cvm__metric_bg_build(&bg, &ctx, xy, 4, tri, 2, gn), CVM_OK);
    for (k = 0; k < 4; k++) {
        ck_assert_int_eq(cvm__metric_bg_fn(&bg, xy + 2 * k, 2, g, NULL), 0);
        for (m = 0; m < 3; m++)
            ck_assert(fabs(g[m] - gn[3 * k + m]) <= 1e-12 * (1 + fabs(gn[3 * k + m])));
    }
    x[0] = 0.5;
    x[1] = 0;
    ck_assert_int_eq(cvm__metric_bg_fn(&bg, x, 2, g, NULL), 0);
    ck_assert(fabs(g[0] - 2) <= 1e-14 && fabs(g[1]) <= 1e-14 && fabs(g[2] - 2) <= 1e-14);
    for (trial = 0; trial < 300; trial++) {
        double h = 1e-6;
        x[0] = 0.01 + 0.98 * qtest_uniform(&st);
        x[1] = 0.01 + 0.98 * qtest_uniform(&st);
        if (fabs(x[0] - x[1]) < 2e-6) /* the shared edge: the derivative jumps there */
            continue;
        ck_assert_int_eq(cvm__metric_bg_fn(&bg, x, 2, g, dg), 0);
        ck_assert(g[0] > 0 && g[0] * g[2] - g[1] * g[1] > 0);
        for (m = 0; m < 2; m++) {
            double xp[2] = {x[0], x[1]}, xm[2] = {x[0], x[1]};
            xp[m] += h;
            xm[m] -= h;
            cvm__metric_bg_fn(&bg, xp, 2, gp, NULL);
            cvm__metric_bg_fn(&bg, xm, 2, gm, NULL);
            for (k = 0; k < 3; k++)
                ck_assert_msg(fabs((gp[k] - gm[k]) / (2 * h) - dg[3 * m + k]) <= 1e-6 * (1 + fabs(dg[3 * m + k])),
                              "at (%g, %g): dg%d/dx%d %.10g vs %.10g", x[0], x[1], k, m,
                              dg[3 * m + k], (gp[k] - gm[k]) / (2 * h));
        }
    }
    x[0] = 1.5;
    ck_assert_int_eq(cvm__metric_bg_fn(&bg, x, 2, g, dg), 1);
    cvm__metric_bg_free(&bg);
    memcpy(bad, gn, sizeof bad);
    bad[10] = 5; /* node 3: g12 = 5 > sqrt(g11 g22) */
    ck_assert_int_eq(cvm__metric_bg_build(&bg, &ctx, xy, 4, tri, 2, bad), CVM_E_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(ctx.errmsg, "background node 3"));
    cvm__metric_bg_free(&bg);
}
END_TEST

TCase *quad_metric_tcase(void)
{
    TCase *tc = tcase_create("metric");
    tcase_add_test(tc, metric_builtin_derivatives_match_differences);
    tcase_add_test(tc, metric_factor_reproduces_g_and_its_derivative);
    tcase_add_test(tc, metric_batch_factor_matches_the_field);
    tcase_add_test(tc, metric_hessian_sizes_are_clamped);
    tcase_add_test(tc, metric_bad_values_are_refused_naming_the_point);
    tcase_add_test(tc, metric_background_is_log_euclidean);
    return tc;
}
