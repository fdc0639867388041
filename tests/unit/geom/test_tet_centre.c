/* test_tet_centre.c - the exact side of each face on which a tetrahedron's circumcentre (power vertex) lies. */
#include <math.h>
#include <stdint.h>

#include "geom/geom_internal.h"
#include "geom/geom_tests.h"

/* The four signs in int64 for small-integer input, by a formula of its own:
 * with d at the origin, u = a - d, v = b - d, t = c - d, the power vertex x
 * solves 2 [u; v; t] x = r (r_p = |p - d|^2 - (w_p - w_d)); its barycentric
 * coordinates (alpha, beta, gamma) in the basis u, v, t solve 2 G g = r with
 * G the Gram matrix, so by Cramer each is det(G with a column replaced by
 * r) / (2 det G) and the coordinate of d is 1 minus their sum. */
static int ref_signs(double (*p)[3], const double *w, int s[4])
{
    int64_t u[3][3], g[3][3], r[3], det, num[3];
    int i, j, k;
    for (i = 0; i < 3; i++) {
        for (k = 0; k < 3; k++)
            u[i][k] = (int64_t)p[i][k] - (int64_t)p[3][k];
        r[i] = u[i][0] * u[i][0] + u[i][1] * u[i][1] + u[i][2] * u[i][2] -
               (w ? (int64_t)w[i] - (int64_t)w[3] : 0);
    }
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            g[i][j] = u[i][0] * u[j][0] + u[i][1] * u[j][1] + u[i][2] * u[j][2];
#define DET3(m) ((m)[0][0] * ((m)[1][1] * (m)[2][2] - (m)[1][2] * (m)[2][1]) - \
                 (m)[0][1] * ((m)[1][0] * (m)[2][2] - (m)[1][2] * (m)[2][0]) + \
                 (m)[0][2] * ((m)[1][0] * (m)[2][1] - (m)[1][1] * (m)[2][0]))
    det = DET3(g);
    if (det == 0)
        return -1;
    for (j = 0; j < 3; j++) {
        int64_t h[3][3];
        for (i = 0; i < 3; i++)
            for (k = 0; k < 3; k++)
                h[i][k] = k == j ? r[i] : g[i][k];
        num[j] = DET3(h);
        s[j] = geomtest_sign64(num[j]);
    }
#undef DET3
    s[3] = geomtest_sign64(2 * det - num[0] - num[1] - num[2]);
    return 0;
}

static int got_signs(double (*p)[3], const double *w, int s[4])
{
    return cvm__tet_centre_side(p[0], p[1], p[2], p[3], w, s);
}

START_TEST(tet_centre_agrees_with_int64_on_small_integers)
{
    geomtest_rng r = { 1701 };
    int i, j, k, zeros = 0, flat = 0, neg = 0;
    for (i = 0; i < 40000; i++) {
        int lim = (i % 2) ? 1 : 8, weighted = (i % 3) == 0;
        double p[4][3], w[4];
        int want[4], got[4], rw, rg;
        for (j = 0; j < 4; j++) {
            for (k = 0; k < 3; k++)
                p[j][k] = geomtest_int(&r, -lim, lim);
            w[j] = geomtest_int(&r, -lim, lim);
        }
        rw = ref_signs(p, weighted ? w : NULL, want);
        rg = got_signs(p, weighted ? w : NULL, got);
        ck_assert_int_eq(rg, rw);
        if (rw) {
            flat++;
            continue;
        }
        for (j = 0; j < 4; j++) {
            ck_assert_int_eq(got[j], want[j]);
            zeros += want[j] == 0;
            neg += want[j] < 0;
        }
    }
    ck_assert_int_gt(zeros, 1000); /* the degenerate cases are exercised */
    ck_assert_int_gt(neg, 1000);
    ck_assert_int_gt(flat, 100);
}
END_TEST

/* Scaling by 2^k (weights by 2^2k) and translating by a large integer keep
 * every sign: the filter fails on most of these and the rescaled exact stage decides. */
START_TEST(tet_centre_is_scale_and_translation_invariant)
{
    static const int ks[] = { -500, -300, -64, 64, 300, 450 }; /* weights stay normal */
    geomtest_rng r = { 1702 };
    int i, j, k, e;
    for (i = 0; i < 6000; i++) {
        double p[4][3], w[4], q[4][3], v[4];
        int want[4], got[4];
        for (j = 0; j < 4; j++) {
            for (k = 0; k < 3; k++)
                p[j][k] = geomtest_int(&r, -2, 2);
            w[j] = geomtest_int(&r, -2, 2);
        }
        if (ref_signs(p, w, want))
            continue;
        for (e = 0; e < 7; e++) {
            for (j = 0; j < 4; j++) {
                for (k = 0; k < 3; k++)
                    q[j][k] = e < 6 ? ldexp(p[j][k], ks[e]) : p[j][k] + 0x1p40;
                v[j] = e < 6 ? ldexp(w[j], 2 * ks[e]) : w[j];
            }
            ck_assert_int_eq(got_signs(q, v, got), 0);
            for (j = 0; j < 4; j++)
                ck_assert_msg(got[j] == want[j], "case %d scale %d corner %d: %d, want %d", i, e,
                              j, got[j], want[j]);
        }
    }
}
END_TEST

static void expect(double (*p)[3], const double *w, int s0, int s1, int s2, int s3)
{
    int s[4];
    ck_assert_int_eq(got_signs(p, w, s), 0);
    ck_assert_int_eq(s[0], s0);
    ck_assert_int_eq(s[1], s1);
    ck_assert_int_eq(s[2], s2);
    ck_assert_int_eq(s[3], s3);
}

START_TEST(tet_centre_degenerate_cube_and_lattice_tetrahedra)
{
    /* a Kuhn (path) tetrahedron of the unit cube: the centre is the middle of
     * its long diagonal, so two coordinates are exactly 0 */
    double kuhn[4][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 1, 1, 1 } };
    /* the right-angled corner of a cube: the centre (1/2, 1/2, 1/2) is beyond
     * the face opposite the corner */
    double corner[4][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
    /* the regular tetrahedron of alternate cube corners: inside */
    double regular[4][3] = { { 0, 0, 0 }, { 1, 1, 0 }, { 1, 0, 1 }, { 0, 1, 1 } };
    /* three points on a great circle of the sphere of radius 5: the centre
     * (the origin) is inside the face abc, on its plane */
    double face[4][3] = { { 5, 0, 0 }, { -3, 4, 0 }, { -3, -4, 0 }, { 0, 0, 5 } };
    /* a BCC lattice (Sommerville) tetrahedron: inside */
    double bcc[4][3] = { { 0, 0, 0 }, { 2, 0, 0 }, { 1, 1, 1 }, { 1, 1, -1 } };
    /* the face case with equal weights is the same; weights moving the power
     * vertex to z = -1 (w_d = 10: beyond the face) or z = 1 (w_d = -10: inside) */
    double w_eq[4] = { 3, 3, 3, 3 }, w_up[4] = { 0, 0, 0, 10 };
    double w_dn[4] = { 0, 0, 0, -10 };
    expect(kuhn, NULL, 1, 0, 0, 1);
    expect(corner, NULL, -1, 1, 1, 1);
    expect(regular, NULL, 1, 1, 1, 1);
    expect(face, NULL, 1, 1, 1, 0);
    expect(face, w_eq, 1, 1, 1, 0);
    expect(face, w_up, 1, 1, 1, -1);
    expect(face, w_dn, 1, 1, 1, 1);
    expect(bcc, NULL, 1, 1, 1, 1);
    ck_assert_int_eq(cvm__tet_centre_inside(kuhn[0], kuhn[1], kuhn[2], kuhn[3], NULL), 0);
    ck_assert_int_eq(cvm__tet_centre_inside(corner[0], corner[1], corner[2], corner[3], NULL), -1);
    ck_assert_int_eq(cvm__tet_centre_inside(bcc[0], bcc[1], bcc[2], bcc[3], NULL), 1);
    ck_assert_int_eq(cvm__tet_centre_inside(face[0], face[1], face[2], face[3], NULL), 0);
    /* the orientation does not matter */
    expect((double (*)[3])(double[4][3]){ { 1, 0, 0 }, { 0, 0, 0 }, { 1, 1, 0 }, { 1, 1, 1 } },
           NULL, 0, 1, 0, 1);
    /* flat */
    ck_assert_int_eq(cvm__tet_centre_inside(face[0], face[1], face[2],
                                            (double[3]){ 1, 1, 0 }, NULL), -2);
}
END_TEST

/* Exact ties at non-integer coordinates: the face case scaled by 0.1 is not
 * exactly a tie in doubles, yet every sign must match a power-of-two scaled
 * copy (exact), and the unscaled tie stays 0 after a 2^-3 scaling. */
START_TEST(tet_centre_ties_survive_binary_scaling)
{
    double face[4][3] = { { 5, 0, 0 }, { -3, 4, 0 }, { -3, -4, 0 }, { 0, 0, 5 } };
    double q[4][3], q2[4][3];
    int s[4], t[4], j, k;
    for (j = 0; j < 4; j++)
        for (k = 0; k < 3; k++) {
            q[j][k] = face[j][k] * 0.1;
            q2[j][k] = q[j][k] * 0x1p-3;
            face[j][k] *= 0x1p-3;
        }
    expect(face, NULL, 1, 1, 1, 0);
    ck_assert_int_eq(got_signs(q, NULL, s), 0);
    ck_assert_int_eq(got_signs(q2, NULL, t), 0);
    for (j = 0; j < 4; j++)
        ck_assert_int_eq(s[j], t[j]);
}
END_TEST

TCase *geom_tet_centre_tcase(void)
{
    TCase *tc = tcase_create("tet_centre");
    tcase_add_test(tc, tet_centre_agrees_with_int64_on_small_integers);
    tcase_add_test(tc, tet_centre_is_scale_and_translation_invariant);
    tcase_add_test(tc, tet_centre_degenerate_cube_and_lattice_tetrahedra);
    tcase_add_test(tc, tet_centre_ties_survive_binary_scaling);
    return tc;
}
