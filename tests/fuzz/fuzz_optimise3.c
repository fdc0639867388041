/*
 * fuzz_optimise3.c - libFuzzer target: bytes -> a 3D point set (on a coarse
 * grid, so that ties, cospherical and coplanar points are common), optional
 * weights, its Delaunay / regular tetrahedralisation, and the options of
 * cvm_mesh_optimise_dual3(). Required:
 *   - the optimiser returns CVM_OK (no other status for a valid mesh);
 *   - cvm_mesh_check() accepts the result: conforming, positively oriented and
 *     regular by the exact perturbed power test (the handle holds a point set's
 *     tetrahedralisation, which the check verifies face by face);
 *   - the vertices and boundary faces are the same as before, and so are the
 *     tetrahedra without flips (with flips every vertex is still used), the
 *     volume the same (to 1e-9 relative; 10 % with slide 2), and the outside
 *     count did not grow;
 *   - a second run on a fresh handle gives identical points, weights and
 *     tetrahedra;
 *   - the merged dual cells of the result (cvm_mesh_copy_dual3_merge_groups(),
 *     tol from byte 2): each group id is a tetrahedron of the group and its
 *     smallest, the tetrahedra of a group are connected across faces shared by
 *     two of them (so never across a boundary face), a second copy is the same,
 *     merged % in [0, 100], non-compliant % <= outside % (all and boundary),
 *     and tol 0 merges nothing and leaves non-compliant = outside.
 *
 * Bytes (missing ones read as 0):
 *   0      points: 5 + b % 40
 *   1      bits 0-1 sweeps 1 + b % 4; bit 2 slide (1, or 2 when byte 3 / 126 is odd);
 *          bit 3 weights; bits 4-7 budget 1 + 4 (b >> 4)
 *   2      min dihedral (b % 61) degrees, merge tol (b / 61 % 5) / 4
 *   3      margin (b % 21) / 100, flips (b / 21 % 2), solver 1 + b / 42 % 3 (cuckoo budget 60)
 *   4..    per point: 3 coordinates (b % 8) / 4 (a grid), then, with weights, (b % 16) / 64
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "cvmesh.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define FUZZ_NAME "fuzz_optimise3"
#include "fuzz_require.h"

static uint8_t byte_at(const uint8_t *data, size_t size, size_t i)
{
    return i < size ? data[i] : 0;
}

typedef struct o3_state {
    size_t nv, nt, nf;
    double *xyz, *w;
    cvm_index *tet, *face;
} o3_state;

static void state_get(o3_state *st, const cvm_mesh *m)
{
    FUZZ_REQUIRE(cvm_mesh_count(&st->nv, m, CVM_ENT_VERTEX) == CVM_OK, "count");
    FUZZ_REQUIRE(cvm_mesh_count(&st->nt, m, CVM_ENT_TETRAHEDRON) == CVM_OK, "count");
    FUZZ_REQUIRE(cvm_mesh_count(&st->nf, m, CVM_ENT_TRIANGLE) == CVM_OK, "count");
    st->xyz = malloc(3 * st->nv * sizeof *st->xyz + 1);
    st->w = malloc(st->nv * sizeof *st->w + 1);
    st->tet = malloc(4 * st->nt * sizeof *st->tet + 1);
    st->face = malloc(3 * st->nf * sizeof *st->face + 1);
    FUZZ_REQUIRE(st->xyz && st->w && st->tet && st->face, "malloc");
    FUZZ_REQUIRE(cvm_mesh_copy_points_nd(st->xyz, 3 * st->nv, 3, m) == CVM_OK, "points");
    FUZZ_REQUIRE(cvm_mesh_copy_weights(st->w, st->nv, m) == CVM_OK, "weights");
    FUZZ_REQUIRE(cvm_mesh_copy_cells(st->tet, 4 * st->nt, m, CVM_ENT_TETRAHEDRON) == CVM_OK, "tets");
    FUZZ_REQUIRE(cvm_mesh_copy_cells(st->face, 3 * st->nf, m, CVM_ENT_TRIANGLE) == CVM_OK, "faces");
}

static void state_free(o3_state *st)
{
    free(st->xyz);
    free(st->w);
    free(st->tet);
    free(st->face);
}

static int32_t o3_find(int32_t *g, int32_t x)
{
    while (g[x] != x)
        x = g[x] = g[g[x]];
    return x;
}

static double o3_measure(cvm_mesh *m, cvm_measure which)
{
    double v = -1;
    FUZZ_REQUIRE(cvm_mesh_get_measure(&v, m, which) == CVM_OK, "measure %d: %s", (int)which,
                 cvm_mesh_errmsg(m));
    return v;
}

/* The merge invariants of the header comment on m (tetrahedra st->tet). */
static void check_merge(cvm_mesh *m, const o3_state *st, double tol)
{
    size_t nt = st->nt, t, i, j;
    cvm_index *g = malloc(nt * sizeof *g + 1), *g2 = malloc(nt * sizeof *g2 + 1);
    int32_t *uf = malloc(nt * sizeof *uf + 1);
    FUZZ_REQUIRE(g && g2 && uf, "malloc");
    FUZZ_REQUIRE(cvm_mesh_set_option(m, CVM_OPT_DUAL3_MERGE_TOL, tol) == CVM_OK, "option");
    FUZZ_REQUIRE(cvm_mesh_copy_dual3_merge_groups(g, nt, m) == CVM_OK, "merge groups");
    FUZZ_REQUIRE(cvm_mesh_copy_dual3_merge_groups(g2, nt, m) == CVM_OK, "merge groups");
    FUZZ_REQUIRE(memcmp(g, g2, nt * sizeof *g) == 0, "merge groups: a second copy differs");
    for (t = 0; t < nt; t++) {
        FUZZ_REQUIRE(g[t] >= 0 && (size_t)g[t] <= t && g[g[t]] == g[t],
                     "tet %lu: group %ld is not its group's smallest", (unsigned long)t, (long)g[t]);
        FUZZ_REQUIRE(tol > 0 || g[t] == (cvm_index)t, "tol 0 merged tet %lu", (unsigned long)t);
        uf[t] = (int32_t)t;
    }
    /* join members that share a face (3 common corners); each group is one component */
    for (t = 0; t < nt; t++)
        for (i = t + 1; i < nt; i++) {
            int common = 0, a, b;
            if (g[t] != g[i])
                continue;
            for (a = 0; a < 4; a++)
                for (b = 0; b < 4; b++)
                    common += st->tet[4 * t + (size_t)a] == st->tet[4 * i + (size_t)b];
            if (common == 3) {
                int32_t ra = o3_find(uf, (int32_t)t), rb = o3_find(uf, (int32_t)i);
                uf[ra > rb ? ra : rb] = ra < rb ? ra : rb;
            }
        }
    for (j = 0; j < nt; j++)
        FUZZ_REQUIRE(o3_find(uf, (int32_t)j) == o3_find(uf, g[j]),
                     "tet %lu is not face-connected to its group %ld", (unsigned long)j, (long)g[j]);
    {
        double mp = o3_measure(m, CVM_MEASURE_DUAL3_MERGED_PCT);
        double nc = o3_measure(m, CVM_MEASURE_DUAL3_NONCOMPLIANT_PCT);
        double ncb = o3_measure(m, CVM_MEASURE_DUAL3_NONCOMPLIANT_BOUNDARY_PCT);
        double out = o3_measure(m, CVM_MEASURE_CIRCUMCENTRE_OUTSIDE_PCT);
        double outb = o3_measure(m, CVM_MEASURE_CIRCUMCENTRE_OUTSIDE_BOUNDARY_PCT);
        FUZZ_REQUIRE(mp >= 0 && mp <= 100, "merged %g %%", mp);
        FUZZ_REQUIRE(nc <= out && ncb <= outb, "non-compliant %g %% / %g %%, outside %g %% / %g %%",
                     nc, ncb, out, outb);
        FUZZ_REQUIRE(tol > 0 || (mp == 0 && nc == out && ncb == outb), "tol 0: merged %g %%", mp);
    }
    free(g);
    free(g2);
    free(uf);
}

/* A mesh of the points, optimised; NULL when the points have no tetrahedralisation. */
static cvm_mesh *run(const double *xyz, const double *w, size_t n, const double opt[7],
                     o3_state *before)
{
    cvm_mesh *m;
    cvm_status s;
    double vol0, vol1, out0, out1;
    size_t nt0, nt1;
    FUZZ_REQUIRE(cvm_mesh_create(&m) == CVM_OK, "create");
    FUZZ_REQUIRE(cvm_mesh_set_points(m, xyz, n, 3) == CVM_OK, "set_points");
    s = cvm_mesh_triangulate(m);
    if (s != CVM_OK) { /* flat or too few distinct points */
        FUZZ_REQUIRE(s == CVM_E_INPUT_DEGENERATE, "triangulate: %s", cvm_mesh_errmsg(m));
        cvm_mesh_free(m);
        return NULL;
    }
    if (w) {
        size_t nv;
        FUZZ_REQUIRE(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX) == CVM_OK, "count");
        s = cvm_mesh_set_weights(m, w, nv);
        FUZZ_REQUIRE(s == CVM_OK, "set_weights: %s", cvm_mesh_errmsg(m));
    }
    FUZZ_REQUIRE(cvm_mesh_set_option(m, CVM_OPT_DUAL3_MAX_SWEEPS, opt[0]) == CVM_OK, "option");
    FUZZ_REQUIRE(cvm_mesh_set_option(m, CVM_OPT_DUAL3_SLIDE_BOUNDARY, opt[1]) == CVM_OK, "option");
    FUZZ_REQUIRE(cvm_mesh_set_option(m, CVM_OPT_DUAL3_BUDGET, opt[2]) == CVM_OK, "option");
    FUZZ_REQUIRE(cvm_mesh_set_option(m, CVM_OPT_DUAL3_MIN_DIHEDRAL_DEG, opt[3]) == CVM_OK, "option");
    FUZZ_REQUIRE(cvm_mesh_set_option(m, CVM_OPT_DUAL3_MARGIN, opt[4]) == CVM_OK, "option");
    FUZZ_REQUIRE(cvm_mesh_set_option(m, CVM_OPT_DUAL3_FLIPS, opt[5]) == CVM_OK, "option");
    FUZZ_REQUIRE(cvm_mesh_set_option(m, CVM_OPT_DUAL3_SOLVER, opt[6]) == CVM_OK, "option");
    FUZZ_REQUIRE(cvm_mesh_set_option(m, CVM_OPT_DUAL3_CUCKOO_BUDGET, 60) == CVM_OK, "option");
    FUZZ_REQUIRE(cvm_mesh_count(&nt0, m, CVM_ENT_TETRAHEDRON) == CVM_OK, "count");
    FUZZ_REQUIRE(cvm_mesh_get_measure(&vol0, m, CVM_MEASURE_VOLUME) == CVM_OK, "volume");
    FUZZ_REQUIRE(cvm_mesh_get_measure(&out0, m, CVM_MEASURE_CIRCUMCENTRE_OUTSIDE_PCT) == CVM_OK,
                 "outside");
    if (before)
        state_get(before, m);
    s = cvm_mesh_optimise_dual3(m);
    FUZZ_REQUIRE(s == CVM_OK, "optimise_dual3 status %d: %s", (int)s, cvm_mesh_errmsg(m));
    FUZZ_REQUIRE(cvm_mesh_check(m) == CVM_OK, "check: %s", cvm_mesh_errmsg(m));
    FUZZ_REQUIRE(cvm_mesh_get_measure(&vol1, m, CVM_MEASURE_VOLUME) == CVM_OK, "volume");
    /* slide 2 moves vertices of bent hull patches on the hull as it was: the chords
       between them change the volume a little */
    FUZZ_REQUIRE(fabs(vol1 - vol0) <= (opt[1] == 2 ? 0.1 : 1e-9) * vol0, "volume %.17g -> %.17g",
                 vol0, vol1);
    FUZZ_REQUIRE(cvm_mesh_get_measure(&out1, m, CVM_MEASURE_CIRCUMCENTRE_OUTSIDE_PCT) == CVM_OK,
                 "outside");
    FUZZ_REQUIRE(cvm_mesh_count(&nt1, m, CVM_ENT_TETRAHEDRON) == CVM_OK, "count");
    /* counts (flips change the number of tetrahedra): round the percentages back */
    FUZZ_REQUIRE(floor(out1 * (double)nt1 / 100 + 0.5) <= floor(out0 * (double)nt0 / 100 + 0.5),
                 "outside %g %% of %lu -> %g %% of %lu", out0, (unsigned long)nt0, out1,
                 (unsigned long)nt1);
    return m;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    size_t n = 5 + byte_at(data, size, 0) % 40, i, pos = 4;
    uint8_t b1 = byte_at(data, size, 1);
    int weighted = (b1 >> 3) & 1;
    double opt[7], *xyz, *w;
    cvm_mesh *m1, *m2;
    o3_state a, b, c;
    opt[0] = 1 + (b1 & 3);
    opt[1] = (b1 >> 2) & 1 ? 1 + byte_at(data, size, 3) / 126 % 2 : 0;
    opt[2] = 1 + 4 * (b1 >> 4);
    opt[3] = byte_at(data, size, 2) % 61;
    opt[4] = (byte_at(data, size, 3) % 21) / 100.0;
    opt[5] = byte_at(data, size, 3) / 21 % 2;
    opt[6] = 1 + byte_at(data, size, 3) / 42 % 3;
    xyz = malloc(3 * n * sizeof *xyz);
    w = malloc(n * sizeof *w);
    FUZZ_REQUIRE(xyz && w, "malloc");
    for (i = 0; i < n; i++) {
        int k;
        for (k = 0; k < 3; k++)
            xyz[3 * i + (size_t)k] = (byte_at(data, size, pos++) % 8) / 4.0;
        w[i] = weighted ? (byte_at(data, size, pos++) % 16) / 64.0 : 0;
    }
    m1 = run(xyz, weighted ? w : NULL, n, opt, &a);
    if (!m1) {
        free(xyz);
        free(w);
        return 0;
    }
    state_get(&b, m1);
    FUZZ_REQUIRE(a.nv == b.nv && a.nf == b.nf, "counts changed");
    if (opt[5] == 0)
        FUZZ_REQUIRE(a.nt == b.nt && memcmp(a.tet, b.tet, 4 * a.nt * sizeof *a.tet) == 0,
                     "tetrahedra changed");
    FUZZ_REQUIRE(memcmp(a.face, b.face, 3 * a.nf * sizeof *a.face) == 0, "faces changed");
    {
        /* no vertex lost: each one of a tetrahedron before is in one after */
        unsigned char *used = calloc(b.nv + 1, 1);
        size_t k;
        FUZZ_REQUIRE(used != NULL, "malloc");
        for (k = 0; k < 4 * a.nt; k++)
            used[a.tet[k]] = 1;
        for (k = 0; k < 4 * b.nt; k++)
            used[b.tet[k]] = 0;
        for (k = 0; k < b.nv; k++)
            FUZZ_REQUIRE(!used[k], "vertex %lu lost", (unsigned long)k);
        free(used);
    }
    check_merge(m1, &b, (byte_at(data, size, 2) / 61 % 5) / 4.0);
    check_merge(m1, &b, 0);
    m2 = run(xyz, weighted ? w : NULL, n, opt, NULL);
    FUZZ_REQUIRE(m2 != NULL, "the second run failed");
    state_get(&c, m2);
    FUZZ_REQUIRE(c.nv == b.nv && memcmp(b.xyz, c.xyz, 3 * b.nv * sizeof *b.xyz) == 0 &&
                     memcmp(b.w, c.w, b.nv * sizeof *b.w) == 0 && c.nt == b.nt &&
                     memcmp(b.tet, c.tet, 4 * b.nt * sizeof *b.tet) == 0,
                 "second run: other points, weights or tetrahedra");
    state_free(&a);
    state_free(&b);
    state_free(&c);
    cvm_mesh_free(m1);
    cvm_mesh_free(m2);
    free(xyz);
    free(w);
    return 0;
}
