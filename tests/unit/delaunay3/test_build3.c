/* test_build3.c - 3D Delaunay on random, lattice and spherical input: exact validity, Euler, volume, determinism. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay3/delaunay3_tests.h"
#include "geom/geom_internal.h"

/* Sum of 6 x volume of the tetrahedra: exact for small-integer coordinates. */
static double six_volume(const double *xyz, const int32_t *tets, size_t nt)
{
    double sum = 0.0;
    size_t i;
    for (i = 0; i < nt; i++) {
        const int32_t *t = tets + 4 * i;
        sum += cvm__orient3d(xyz + 3 * t[0], xyz + 3 * t[1], xyz + 3 * t[2], xyz + 3 * t[3]);
    }
    return sum;
}

START_TEST(random_1e5_is_delaunay_with_ball_euler)
{
    size_t n = 100000, nt;
    double *xyz = malloc(3 * n * sizeof *xyz);
    cvm__ctx ctx;
    cvm__tet3 T;
    int32_t *tets;
    cvm__ctx_init_default(&ctx);
    d3test_random(xyz, n, 1);
    tets = d3test_build(&T, &ctx, xyz, NULL, n, 1, &nt);
    ck_assert_uint_eq(T.n_dup, 0);
    ck_assert_uint_gt(nt, 6 * n);
    ck_assert_int_eq(d3test_euler(tets, nt), 1);
    cvm__tet3_free(&T);
    free(tets);
    free(xyz);
}
END_TEST

/* Every point of the BCC lattice is on many common spheres: every decision
 * beyond the filter is a tie the symbolic perturbation must break. */
START_TEST(exact_bcc_lattice_1e5_is_delaunay_and_fills_the_cube)
{
    int k = 37;
    size_t n, nt;
    double *xyz = malloc(3 * 2 * (size_t)k * k * k * sizeof *xyz), side = 2.0 * (k - 1);
    cvm__ctx ctx;
    cvm__tet3 T;
    int32_t *tets;
    cvm__ctx_init_default(&ctx);
    n = d3test_bcc(xyz, k);
    ck_assert_uint_gt(n, 97000);
    tets = d3test_build(&T, &ctx, xyz, NULL, n, 3, &nt);
    ck_assert_uint_eq(T.n_dup, 0);
    ck_assert(six_volume(xyz, tets, nt) == 6.0 * side * side * side);
    ck_assert_int_eq(d3test_euler(tets, nt), 1);
    cvm__tet3_free(&T);
    free(tets);
    free(xyz);
}
END_TEST

START_TEST(perturbed_bcc_lattice_is_delaunay)
{
    int k = 20;
    size_t n, nt, i;
    double *xyz = malloc(3 * 2 * (size_t)k * k * k * sizeof *xyz), *jit;
    cvm__ctx ctx;
    cvm__tet3 T;
    int32_t *tets;
    cvm__ctx_init_default(&ctx);
    n = d3test_bcc(xyz, k);
    jit = malloc(3 * n * sizeof *jit);
    d3test_random(jit, n, 5);
    for (i = 0; i < 3 * n; i++)
        xyz[i] += 1e-9 * (jit[i] - 0.5);
    tets = d3test_build(&T, &ctx, xyz, NULL, n, 5, &nt);
    ck_assert_int_eq(d3test_euler(tets, nt), 1);
    cvm__tet3_free(&T);
    free(tets);
    free(jit);
    free(xyz);
}
END_TEST

/* An n^3 grid in [0, n-1]^3: cospherical everywhere, coplanar hull faces;
 * the tetrahedra fill the cube exactly. */
START_TEST(integer_grid_volume_is_exact)
{
    int g = 14, x, y, z;
    size_t n = 0, nt;
    double *xyz = malloc(3 * (size_t)g * g * g * sizeof *xyz), side = g - 1;
    cvm__ctx ctx;
    cvm__tet3 T;
    int32_t *tets;
    cvm__ctx_init_default(&ctx);
    for (x = 0; x < g; x++)
        for (y = 0; y < g; y++)
            for (z = 0; z < g; z++)
                xyz[3 * n] = x, xyz[3 * n + 1] = y, xyz[3 * n + 2] = z, n++;
    tets = d3test_build(&T, &ctx, xyz, NULL, n, 9, &nt);
    ck_assert(six_volume(xyz, tets, nt) == 6.0 * side * side * side);
    ck_assert_int_eq(d3test_euler(tets, nt), 1);
    cvm__tet3_free(&T);
    free(tets);
    free(xyz);
}
END_TEST

/* All integer points on the sphere x^2 + y^2 + z^2 = 1105 (exactly
 * cospherical), then the same directions rounded onto the unit sphere. */
START_TEST(points_on_a_sphere)
{
    double *xyz = malloc(3 * 4000 * sizeof *xyz);
    size_t n = 0, nt, i;
    int x, y, z;
    cvm__ctx ctx;
    cvm__tet3 T;
    int32_t *tets;
    cvm__ctx_init_default(&ctx);
    for (x = -34; x <= 34; x++)
        for (y = -34; y <= 34; y++)
            for (z = -34; z <= 34; z++)
                if (x * x + y * y + z * z == 1105)
                    xyz[3 * n] = x, xyz[3 * n + 1] = y, xyz[3 * n + 2] = z, n++;
    ck_assert_uint_gt(n, 150);
    tets = d3test_build(&T, &ctx, xyz, NULL, n, 2, &nt);
    ck_assert_int_eq(d3test_euler(tets, nt), 1);
    cvm__tet3_free(&T);
    free(tets);
    for (i = 0; i < n; i++) {
        double *p = xyz + 3 * i, r = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        p[0] /= r, p[1] /= r, p[2] /= r;
    }
    tets = d3test_build(&T, &ctx, xyz, NULL, n, 2, &nt);
    ck_assert_int_eq(d3test_euler(tets, nt), 1);
    cvm__tet3_free(&T);
    free(tets);
    free(xyz);
}
END_TEST

/* Point 0 at the centre of 600 points on a sphere: inserted late, its
 * cavity is the whole ball (a boundary of 600 vertices, linked through the
 * hash table), and all its tetrahedra share the first vertex 0 (the sort's
 * long-run path). Every seed gives the same bytes. */
START_TEST(centre_of_a_sphere_has_the_whole_ball_as_cavity)
{
    size_t n = 601, i, nt, nt0 = 0, big = 0;
    double *xyz = malloc(3 * n * sizeof *xyz);
    int32_t *first = NULL, *tets;
    uint64_t seed;
    cvm__ctx ctx;
    cvm__tet3 T;
    cvm__ctx_init_default(&ctx);
    d3test_random(xyz, n, 61);
    xyz[0] = xyz[1] = xyz[2] = 0.0;
    for (i = 1; i < n; i++) {
        double *p = xyz + 3 * i, r;
        p[0] -= 0.5, p[1] -= 0.5, p[2] -= 0.5;
        r = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        p[0] /= r, p[1] /= r, p[2] /= r;
    }
    for (seed = 1; seed <= 8; seed++) {
        tets = d3test_build(&T, &ctx, xyz, NULL, n, seed, &nt);
        big += T.n_big_cavities;
        for (i = 0; i < nt; i++)
            ck_assert_int_eq(tets[4 * i], 0); /* every tetrahedron is a cone from the centre */
        if (!first) {
            first = tets, nt0 = nt;
        } else {
            ck_assert_uint_eq(nt, nt0);
            ck_assert(memcmp(first, tets, 4 * nt * sizeof *tets) == 0);
            free(tets);
        }
        cvm__tet3_free(&T);
    }
    ck_assert_uint_gt(big, 0);
    ck_assert_int_eq(d3test_euler(first, nt0), 1);
    free(first);
    free(xyz);
}
END_TEST

/* Different seeds insert in different orders; the canonical output is the
 * same bytes (the perturbed tetrahedralisation is unique), on random input
 * and on the fully degenerate lattice. Scaling by 2^-900 or 2^900 changes nothing either. */
START_TEST(same_bytes_for_any_seed_and_scale)
{
    int lattice, e;
    for (lattice = 0; lattice < 2; lattice++) {
        double *xyz = malloc(3 * 20000 * sizeof *xyz), *sc = malloc(3 * 20000 * sizeof *sc);
        size_t n = lattice ? d3test_bcc(xyz, 12) : 5000, nt1, nt2, i;
        cvm__ctx ctx;
        cvm__tet3 T;
        int32_t *a, *b;
        static const int scales[] = { -900, 0, 900 };
        cvm__ctx_init_default(&ctx);
        if (!lattice)
            d3test_random(xyz, n, 11);
        a = d3test_build(&T, &ctx, xyz, NULL, n, 1, &nt1);
        cvm__tet3_free(&T);
        for (e = 0; e < 3; e++) {
            for (i = 0; i < 3 * n; i++)
                sc[i] = ldexp(xyz[i], scales[e]);
            b = d3test_build(&T, &ctx, sc, NULL, n, 77 + (uint64_t)e, &nt2);
            cvm__tet3_free(&T);
            ck_assert_uint_eq(nt1, nt2);
            ck_assert(memcmp(a, b, 4 * nt1 * sizeof *a) == 0);
            free(b);
        }
        free(a);
        free(sc);
        free(xyz);
    }
}
END_TEST

/* Exact duplicates, shuffled among a degenerate (co-spherical) grid: the first of a group to be
 * inserted depends on the seed, yet the output is the same bytes for every seed, unweighted and
 * weighted (each group's vertex takes the group's lowest input index in the perturbation). */
START_TEST(duplicates_give_the_same_bytes_for_any_seed)
{
    size_t ng = 12 * 12 * 12, nd = 300, n = ng + nd, i, nt0 = 0, nt;
    double *xyz = malloc(3 * n * sizeof *xyz), *w = malloc(n * sizeof *w);
    uint64_t r = 12345;
    static const uint64_t seeds[] = {1, 3, 99, 4242};
    int weighted, k;
    for (i = 0; i < ng; i++) {
        xyz[3 * i] = 0.3 * (double)(i % 12);
        xyz[3 * i + 1] = 0.7 * (double)((i / 12) % 12);
        xyz[3 * i + 2] = 1.1 * (double)(i / 144);
        w[i] = 0.01 * (double)(i % 3);
    }
    for (i = ng; i < n; i++) { /* copies of grid points, weight included */
        size_t j;
        r ^= r << 13, r ^= r >> 7, r ^= r << 17;
        j = (size_t)(r % ng);
        memcpy(xyz + 3 * i, xyz + 3 * j, 3 * sizeof *xyz);
        w[i] = w[j];
    }
    for (i = n - 1; i > 0; i--) { /* shuffle, so copies come before their originals too */
        size_t j;
        double t[3], tw;
        r ^= r << 13, r ^= r >> 7, r ^= r << 17;
        j = (size_t)(r % (i + 1));
        memcpy(t, xyz + 3 * i, sizeof t);
        memcpy(xyz + 3 * i, xyz + 3 * j, sizeof t);
        memcpy(xyz + 3 * j, t, sizeof t);
        tw = w[i], w[i] = w[j], w[j] = tw;
    }
    for (weighted = 0; weighted < 2; weighted++) {
        int32_t *first = NULL;
        for (k = 0; k < 4; k++) {
            cvm__ctx ctx;
            cvm__tet3 T;
            int32_t *t;
            cvm__ctx_init_default(&ctx);
            t = d3test_build(&T, &ctx, xyz, weighted ? w : NULL, n, seeds[k], &nt);
            ck_assert_uint_eq(T.n_dup, nd);
            cvm__tet3_free(&T);
            if (k == 0) {
                first = t;
                nt0 = nt;
                continue;
            }
            ck_assert_msg(nt == nt0, "seed %lu: %zu tetrahedra, seed 1: %zu",
                          (unsigned long)seeds[k], nt, nt0);
            ck_assert_msg(memcmp(first, t, 4 * nt * sizeof *t) == 0, "seed %lu: other tetrahedra",
                          (unsigned long)seeds[k]);
            free(t);
        }
        free(first);
    }
    free(xyz);
    free(w);
}
END_TEST

TCase *delaunay3_build_tcase(void)
{
    TCase *tc = tcase_create("build3");
    tcase_set_timeout(tc, 600);
    tcase_add_test(tc, random_1e5_is_delaunay_with_ball_euler);
    tcase_add_test(tc, exact_bcc_lattice_1e5_is_delaunay_and_fills_the_cube);
    tcase_add_test(tc, perturbed_bcc_lattice_is_delaunay);
    tcase_add_test(tc, integer_grid_volume_is_exact);
    tcase_add_test(tc, points_on_a_sphere);
    tcase_add_test(tc, centre_of_a_sphere_has_the_whole_ball_as_cavity);
    tcase_add_test(tc, same_bytes_for_any_seed_and_scale);
    tcase_add_test(tc, duplicates_give_the_same_bytes_for_any_seed);
    return tc;
}
