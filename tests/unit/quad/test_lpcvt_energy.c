/* test_lpcvt_energy.c - the Lp-CVT energy: the paper's lattice is critical (Table 1), and the
 * exact gradient equals central differences and the complex step of the same source. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "quad/quad_tests.h"
#include "quad/quad_internal.h"

/* The 3x3 lattice in [0,4]^2 with 16 boundary sites at unit spacing, g = I, p = 6. */
static double lattice_gradient(int clip, double *E)
{
    cvm__metric_builtin b = {CVM__METRIC_IDENTITY, 1, {0, 0, 0}};
    cvm_sizing *s;
    cvm__ctx ctx;
    cvm__lpcvt L;
    double bxy[32], xi[18], grad[18], gmax = 0;
    int i, j;
    cvm__ctx_init_default(&ctx);
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    cvm_sizing_set_metric_fn(s, cvm__metric_builtin_fn, 1, &b);
    qtest_box(bxy, 0, 0, 4, 4, 4);
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            xi[2 * (3 * i + j)] = 1 + j;
            xi[2 * (3 * i + j) + 1] = 1 + i;
        }
    ck_assert_int_eq(cvm__lpcvt_init(&L, &ctx, s, bxy, 16, 9, 6, clip), CVM_OK);
    ck_assert_int_eq(cvm__lpcvt_eval(&L, xi, E, grad), CVM_OK);
    ck_assert(L.valid);
    for (i = 0; i < 18; i++)
        gmax = fmax(gmax, fabs(grad[i]));
    cvm__lpcvt_free(&L);
    cvm_sizing_free(s);
    return gmax;
}

START_TEST(lpcvt_lattice_is_critical_table1)
{
    double E, g = lattice_gradient(0, &E);
    /* 25 unit cells of |y|_6^6 over [-1/2, 1/2]^2: 2 * (1/7) (1/2)^6 each */
    ck_assert_msg(fabs(E - 25 * 2.0 / (7 * 64)) < 1e-14, "E = %.17g", E);
    ck_assert_msg(g <= 1e-13, "reconstruction: |grad E| = %g", g);
    g = lattice_gradient(1, &E);
    ck_assert_msg(g <= 1e-7, "clipping: |grad E| = %g", g);
}
END_TEST

typedef struct gcase {
    cvm__metric_kind kind;
    double scale, x0, y0, x1, y1;
    int n, ni;
} gcase;

/* Random configurations of ni moving sites at least 0.4 box/n apart, for every built-in metric,
 * both boundary treatments and both metric samplings: the gradient agrees with central
 * differences and with the complex step to 1e-7 relative. */
START_TEST(lpcvt_gradient_matches_differences_and_complex_step)
{
    static const gcase cases[] = {
        {CVM__METRIC_IDENTITY, 1, 0, 0, 4, 4, 4, 9},
        {CVM__METRIC_STRETCH, 1, 0, 0, 5, 1.3, 5, 12},
        {CVM__METRIC_SADDLE, 4, -1.3, -1.3, 1.3, 1.3, 5, 14},
        {CVM__METRIC_SSHOCK, 0.05, -1, -1, 1, 1, 6, 20},
    };
    unsigned long long st = 2024;
    size_t c;
    for (c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        const gcase *k = cases + c;
        cvm__metric_builtin b = {k->kind, k->scale, {0, 0, 0}};
        int trial, clip;
        for (trial = 0; trial < 6; trial++) {
            for (clip = 0; clip < 2; clip++) {
                cvm_sizing *s;
                cvm__ctx ctx;
                cvm__lpcvt L;
                int nb = 4 * k->n, i, j, p = clip ? 4 : 6 + 2 * (trial % 3);
                double *bxy = malloc(2 * (size_t)nb * sizeof *bxy), xi[64], grad[64], xyz[1024];
                double E, Ez[2], gmax = 0, w = k->x1 - k->x0, hgt = k->y1 - k->y0;
                double sep = 0.4 * fmin(w, hgt) / k->n, h = 1e-6 * fmax(w, hgt);
                cvm__ctx_init_default(&ctx);
                ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
                cvm_sizing_set_metric_fn(s, cvm__metric_builtin_fn, 1, &b);
                qtest_box(bxy, k->x0, k->y0, k->x1, k->y1, k->n);
                for (i = 0; i < k->ni; i++) {
                    int ok;
                    do {
                        xi[2 * i] = k->x0 + w * (0.1 + 0.8 * qtest_uniform(&st));
                        xi[2 * i + 1] = k->y0 + hgt * (0.1 + 0.8 * qtest_uniform(&st));
                        for (ok = 1, j = 0; j < i; j++)
                            ok &= hypot(xi[2 * i] - xi[2 * j], xi[2 * i + 1] - xi[2 * j + 1]) > sep;
                    } while (!ok);
                }
                ck_assert_int_eq(cvm__lpcvt_init(&L, &ctx, s, bxy, (size_t)nb, (size_t)k->ni, p, clip),
                                 CVM_OK);
                L.cellwise = trial >= 3; /* M(y) per quadrature point, then M(x_i) per cell */
                ck_assert_int_eq(cvm__lpcvt_eval(&L, xi, &E, grad), CVM_OK);
                ck_assert(L.valid);
                for (i = 0; i < 2 * k->ni; i++)
                    gmax = fmax(gmax, fabs(grad[i]));
                for (i = 0; i < 2 * k->ni; i++) {
                    double Ep, Em, fd, cs;
                    /* complex step, on the topology of xi (the last one evaluated) */
                    ck_assert_int_eq(cvm__lpcvt_eval(&L, xi, &E, NULL), CVM_OK);
                    for (j = 0; j < 2 * (int)L.nall; j++) {
                        xyz[2 * j] = L.xy[j];
                        xyz[2 * j + 1] = 0;
                    }
                    xyz[2 * (2 * nb + i) + 1] = 1e-30;
                    ck_assert_int_eq(cvm__lpcvt_energy_complex(&L, xyz, Ez), CVM_OK);
                    ck_assert(fabs(Ez[0] - E) <= 1e-14 * E);
                    cs = Ez[1] / 1e-30;
                    xi[i] += h;
                    ck_assert_int_eq(cvm__lpcvt_eval(&L, xi, &Ep, NULL), CVM_OK);
                    xi[i] -= 2 * h;
                    ck_assert_int_eq(cvm__lpcvt_eval(&L, xi, &Em, NULL), CVM_OK);
                    xi[i] += h;
                    fd = (Ep - Em) / (2 * h);
                    ck_assert_msg(fabs(cs - grad[i]) <= 1e-7 * gmax,
                                  "metric %d p %d clip %d trial %d: dE/dx%d = %.12g, complex step "
                                  "%.12g (max %.3g)", (int)k->kind, p, clip, trial, i, grad[i], cs, gmax);
                    ck_assert_msg(fabs(fd - grad[i]) <= 1e-7 * gmax,
                                  "metric %d p %d clip %d trial %d: dE/dx%d = %.12g, differences "
                                  "%.12g (max %.3g)", (int)k->kind, p, clip, trial, i, grad[i], fd, gmax);
                }
                cvm__lpcvt_free(&L);
                cvm_sizing_free(s);
                free(bxy);
            }
        }
    }
}
END_TEST


/* The energy and its gradient are the same bits with 1 and 2 threads (cells summed in order). */
START_TEST(lpcvt_energy_is_identical_for_any_thread_count)
{
    cvm__metric_builtin b = {CVM__METRIC_SADDLE, 64, {0, 0, 0}};
    double corners[8] = {-1.3, -1.3, 1.3, -1.3, 1.3, 1.3, -1.3, 1.3}, *bxy, *xi, *g1, *g2, E1, E2;
    size_t nb, ni;
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
    ck_assert_int_eq(cvm__lpcvt_initial_sites(&xi, &ni, &mt, bxy, nb, 3, &ctx), CVM_OK);
    ck_assert(ni > 300);
    g1 = malloc(2 * ni * sizeof *g1);
    g2 = malloc(2 * ni * sizeof *g2);
    ck_assert_int_eq(cvm__lpcvt_init(&L, &ctx, s, bxy, nb, ni, 6, 0), CVM_OK);
    ck_assert_int_eq(cvm__lpcvt_eval(&L, xi, &E1, g1), CVM_OK);
    L.threads = 2;
    ck_assert_int_eq(cvm__lpcvt_eval(&L, xi, &E2, g2), CVM_OK);
    ck_assert(memcmp(&E1, &E2, sizeof E1) == 0);
    ck_assert(memcmp(g1, g2, 2 * ni * sizeof *g1) == 0);
    cvm__lpcvt_free(&L);
    free(g1);
    free(g2);
    cvm__free(&ctx, xi);
    cvm__free(&ctx, bxy);
    cvm_sizing_free(s);
}
END_TEST

TCase *quad_lpcvt_energy_tcase(void)
{
    TCase *tc = tcase_create("lpcvt_energy");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, lpcvt_lattice_is_critical_table1);
    tcase_add_test(tc, lpcvt_gradient_matches_differences_and_complex_step);
    tcase_add_test(tc, lpcvt_energy_is_identical_for_any_thread_count);
    return tc;
}
