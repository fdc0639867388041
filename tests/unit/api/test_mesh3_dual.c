/*
 * test_mesh3_dual.c - the 3D power dual and quality measures of a 3D handle
 * (lib/api/mesh3_dual*.c, mesh3_quality.c, lib/io/write_dual3.c): exact
 * circumcentre containment on lattices, valence, dual edges, dual cell
 * volumes of BCC and cubic lattices, histograms, the polyhedron .vtu, OOM.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api/api_tests.h"
#include "io/io_tests.h"
#include "support/failing_alloc.h"

/* The BCC lattice on [0, k]^3 (corners and cube centres), or the cubic one. */
static double *lattice(int k, int centres, size_t *n)
{
    double *p = malloc(3 * (size_t)(2 * (k + 1) * (k + 1) * (k + 1)) * sizeof *p);
    int x, y, z;
    *n = 0;
    for (x = 0; x <= k; x++)
        for (y = 0; y <= k; y++)
            for (z = 0; z <= k; z++) {
                p[3 * *n] = x, p[3 * *n + 1] = y, p[3 * *n + 2] = z;
                ++*n;
                if (centres && x < k && y < k && z < k) {
                    p[3 * *n] = x + 0.5, p[3 * *n + 1] = y + 0.5, p[3 * *n + 2] = z + 0.5;
                    ++*n;
                }
            }
    return p;
}

static cvm_mesh *mesh_of(const double *p, size_t n)
{
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, p, n, 3), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    return m;
}

typedef struct mesh_copy {
    size_t nv, nt;
    double *p;
    cvm_index *t;
} mesh_copy;

static mesh_copy copy_of(const cvm_mesh *m)
{
    mesh_copy c;
    ck_assert_int_eq(cvm_mesh_count(&c.nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&c.nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    c.p = malloc(3 * c.nv * sizeof *c.p);
    c.t = malloc(4 * c.nt * sizeof *c.t);
    ck_assert_int_eq(cvm_mesh_copy_points_nd(c.p, 3 * c.nv, 3, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(c.t, 4 * c.nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    return c;
}

static void copy_free(mesh_copy *c)
{
    free(c->p);
    free(c->t);
}

/* The signs of the circumcentre's barycentric coordinates of a tetrahedron
 * with coordinates in half-integers, exactly in int64 (coordinates doubled):
 * Gram-matrix Cramer, as in tests/unit/geom/test_tet_centre.c. Returns -1
 * (outside), 0 (on the boundary), 1 (inside). */
static int centre_class(const double *P, const cvm_index *t)
{
    int64_t u[3][3], g[3][3], r[3], det, num[3], lam[4];
    int i, j, k, on = 0;
    for (i = 0; i < 3; i++) {
        for (k = 0; k < 3; k++)
            u[i][k] = (int64_t)(2 * P[3 * t[i] + k]) - (int64_t)(2 * P[3 * t[3] + k]);
        r[i] = u[i][0] * u[i][0] + u[i][1] * u[i][1] + u[i][2] * u[i][2];
    }
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            g[i][j] = u[i][0] * u[j][0] + u[i][1] * u[j][1] + u[i][2] * u[j][2];
#define DET3(m) ((m)[0][0] * ((m)[1][1] * (m)[2][2] - (m)[1][2] * (m)[2][1]) - \
                 (m)[0][1] * ((m)[1][0] * (m)[2][2] - (m)[1][2] * (m)[2][0]) + \
                 (m)[0][2] * ((m)[1][0] * (m)[2][1] - (m)[1][1] * (m)[2][0]))
    det = DET3(g);
    for (j = 0; j < 3; j++) {
        int64_t h[3][3];
        for (i = 0; i < 3; i++)
            for (k = 0; k < 3; k++)
                h[i][k] = k == j ? r[i] : g[i][k];
        num[j] = DET3(h);
        lam[j] = num[j];
    }
#undef DET3
    lam[3] = 2 * det - num[0] - num[1] - num[2];
    for (i = 0; i < 4; i++) {
        if (lam[i] < 0)
            return -1;
        on += lam[i] == 0;
    }
    return on ? 0 : 1;
}

/* Circumcentre (floating point, by its own Cramer rule). */
static void circumcentre(const double *P, const cvm_index *t, double *o)
{
    double A[3][3], b[3], det;
    int i, k;
    for (i = 0; i < 3; i++) {
        b[i] = 0;
        for (k = 0; k < 3; k++) {
            A[i][k] = 2 * (P[3 * t[i + 1] + k] - P[3 * t[0] + k]);
            b[i] += P[3 * t[i + 1] + k] * P[3 * t[i + 1] + k] - P[3 * t[0] + k] * P[3 * t[0] + k];
        }
    }
    det = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) -
          A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
          A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
    for (k = 0; k < 3; k++) {
        double M[3][3];
        int r, c;
        for (r = 0; r < 3; r++)
            for (c = 0; c < 3; c++)
                M[r][c] = c == k ? b[r] : A[r][c];
        o[k] = (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) -
                M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0])) / det;
    }
}

typedef struct face_rec {
    cvm_index v[3];
    size_t t;
} face_rec;

static int cmp_face(const void *a, const void *b)
{
    const face_rec *x = a, *y = b;
    int k;
    for (k = 0; k < 3; k++)
        if (x->v[k] != y->v[k])
            return (x->v[k] > y->v[k]) - (x->v[k] < y->v[k]);
    return (x->t > y->t) - (x->t < y->t);
}

static int cmp_i64_dual(const void *a, const void *b)
{
    int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

static int cmp_idx(const void *a, const void *b)
{
    cvm_index x = *(const cvm_index *)a, y = *(const cvm_index *)b;
    return (x > y) - (x < y);
}

/* All faces sorted (corners sorted): pairs of equal ones are interior. */
static face_rec *faces_of(const mesh_copy *c)
{
    face_rec *f = malloc(4 * c->nt * sizeof *f);
    size_t t;
    int i, j, k;
    for (t = 0; t < c->nt; t++)
        for (i = 0; i < 4; i++) {
            face_rec *r = f + 4 * t + i;
            for (j = 0, k = 0; j < 4; j++)
                if (j != i)
                    r->v[k++] = c->t[4 * t + j];
            qsort(r->v, 3, sizeof r->v[0], cmp_idx);
            r->t = t;
        }
    qsort(f, 4 * c->nt, sizeof *f, cmp_face);
    return f;
}

/* BCC k = 5: the exact containment count agrees with the int64 classes, the
 * interior tetrahedra (the lattice's disphenoids) all contain their centres,
 * and the measures of valence, dual edges and radius-edge agree with the
 * test's own computation. */
START_TEST(bcc_measures_agree_with_an_independent_computation)
{
    size_t n, i, t, nout = 0, non = 0, nint = 0, n14 = 0;
    double *p = lattice(5, 1, &n), got, dmin = INFINITY, rmin = INFINITY, pmin = INFINITY;
    double sum_re = 0, *cc, hist[32], dh[18], hsum = 0;
    cvm_mesh *m = mesh_of(p, n);
    mesh_copy c = copy_of(m);
    face_rec *f = faces_of(&c);
    unsigned char *bnd = calloc(c.nv, 1);
    cvm_index *pairs = malloc(12 * c.nt * sizeof *pairs);
    size_t *deg = calloc(c.nv, sizeof *deg);
    for (t = 0; t < c.nt; t++) {
        int k = centre_class(c.p, c.t + 4 * t);
        nout += k < 0;
        non += k == 0;
    }
    ck_assert_int_eq(cvm_mesh_get_measure(&got, m, CVM_MEASURE_CIRCUMCENTRE_OUTSIDE_PCT), CVM_OK);
    ck_assert_double_eq_tol(got, 100.0 * (double)nout / (double)c.nt, 1e-12);
    ck_assert_uint_gt(nout, 0); /* pyramids on the hull squares have their centre beyond */
    /* boundary faces: the unpaired ones */
    for (i = 0; i < 4 * c.nt;) {
        if (i + 1 < 4 * c.nt && !memcmp(f[i].v, f[i + 1].v, sizeof f[i].v)) {
            double a[3], b[3], len, e[3], mean = 0, emin = INFINITY;
            int k, q;
            circumcentre(c.p, c.t + 4 * f[i].t, a);
            circumcentre(c.p, c.t + 4 * f[i + 1].t, b);
            len = sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                       (a[2] - b[2]) * (a[2] - b[2]));
            for (k = 0; k < 3; k++) {
                const double *x = c.p + 3 * f[i].v[k], *y = c.p + 3 * f[i].v[(k + 1) % 3];
                for (q = 0; q < 3; q++)
                    e[q] = x[q] - y[q];
                e[0] = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
                mean += e[0] / 3;
                emin = e[0] < emin ? e[0] : emin;
            }
            if (len > 1e-9) { /* ties (cospherical neighbours) have no dual edge */
                dmin = len < dmin ? len : dmin;
                rmin = len / mean < rmin ? len / mean : rmin;
                emin = len < emin ? len : emin;
                pmin = emin < pmin ? emin : pmin;
            }
            i += 2;
        } else {
            bnd[f[i].v[0]] = bnd[f[i].v[1]] = bnd[f[i].v[2]] = 1;
            i++;
        }
    }
    ck_assert_int_eq(cvm_mesh_get_measure(&got, m, CVM_MEASURE_MIN_DUAL_EDGE_3D), CVM_OK);
    ck_assert_double_eq_tol(got, dmin, 1e-12);
    ck_assert_int_eq(cvm_mesh_get_measure(&got, m, CVM_MEASURE_MIN_DUAL_EDGE_RATIO_3D), CVM_OK);
    ck_assert_double_eq_tol(got, rmin, 1e-12);
    ck_assert_int_eq(cvm_mesh_get_measure(&got, m, CVM_MEASURE_TIME_STEP_PROXY_3D), CVM_OK);
    ck_assert_double_eq_tol(got, pmin, 1e-12);
    /* valence: distinct edges per vertex */
    for (t = 0; t < c.nt; t++) {
        int a, b, k = 0;
        for (a = 0; a < 4; a++)
            for (b = a + 1; b < 4; b++) {
                cvm_index x = c.t[4 * t + a], y = c.t[4 * t + b];
                pairs[2 * (6 * t + k)] = x < y ? x : y;
                pairs[2 * (6 * t + k) + 1] = x < y ? y : x;
                k++;
            }
    }
    {
        int64_t *key = malloc(6 * c.nt * sizeof *key);
        for (i = 0; i < 6 * c.nt; i++)
            key[i] = (int64_t)pairs[2 * i] * (int64_t)c.nv + pairs[2 * i + 1];
        qsort(key, 6 * c.nt, sizeof *key, cmp_i64_dual);
        for (i = 0; i < 6 * c.nt; i++)
            if (i == 0 || key[i] != key[i - 1]) {
                deg[key[i] / (int64_t)c.nv]++;
                deg[key[i] % (int64_t)c.nv]++;
            }
        free(key);
    }
    for (i = 0; i < c.nv; i++)
        if (!bnd[i]) {
            nint++;
            n14 += deg[i] == 14;
        }
    ck_assert_int_eq(cvm_mesh_get_measure(&got, m, CVM_MEASURE_VALENCE14_PCT), CVM_OK);
    ck_assert_double_eq_tol(got, 100.0 * (double)n14 / (double)nint, 1e-12);
    ck_assert_uint_eq(n14, 4 * 4 * 4 + 3 * 3 * 3); /* exactly those with all 14 lattice neighbours */
    ck_assert_int_eq(cvm_mesh_copy_histogram(hist, 32, m, CVM_HIST_VALENCE_3D), CVM_OK);
    ck_assert_double_eq(hist[14], (double)n14);
    for (i = 0; i < 32; i++)
        hsum += hist[i];
    ck_assert_double_eq(hsum, (double)nint);
    ck_assert_int_eq(cvm_mesh_copy_histogram(hist, 31, m, CVM_HIST_VALENCE_3D),
                     CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_histogram(dh, 18, m, CVM_HIST_DIHEDRAL_DEG), CVM_OK);
    for (i = 0, hsum = 0; i < 18; i++)
        hsum += dh[i];
    ck_assert_double_eq(hsum, 6.0 * (double)c.nt);
    /* the disphenoid's dihedral angles are 60 and 90 degrees */
    ck_assert_double_gt(dh[5] + dh[6] + dh[8] + dh[9], 0.5 * hsum);
    ck_assert_int_eq(cvm_mesh_copy_histogram(dh, 18, m, CVM_HIST_ANGLE_DEG), CVM_E_ARGUMENT);
    /* mean radius-edge */
    cc = malloc(3 * c.nt * sizeof *cc);
    ck_assert_int_eq(cvm_mesh_copy_dual_vertices_nd(cc, 3 * c.nt, 3, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_dual_vertices_nd(cc, 3 * c.nt - 1, 3, m), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_dual_vertices_nd(cc, 3 * c.nt, 2, m), CVM_E_ARGUMENT);
    for (t = 0; t < c.nt; t++) {
        double o[3], r, lmin = INFINITY;
        int a, b, k;
        circumcentre(c.p, c.t + 4 * t, o);
        for (k = 0; k < 3; k++)
            ck_assert_double_eq_tol(cc[3 * t + k], o[k], 1e-12);
        r = sqrt((o[0] - c.p[3 * c.t[4 * t]]) * (o[0] - c.p[3 * c.t[4 * t]]) +
                 (o[1] - c.p[3 * c.t[4 * t] + 1]) * (o[1] - c.p[3 * c.t[4 * t] + 1]) +
                 (o[2] - c.p[3 * c.t[4 * t] + 2]) * (o[2] - c.p[3 * c.t[4 * t] + 2]));
        for (a = 0; a < 4; a++)
            for (b = a + 1; b < 4; b++) {
                const double *x = c.p + 3 * c.t[4 * t + a], *y = c.p + 3 * c.t[4 * t + b];
                double l = sqrt((x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) +
                                (x[2] - y[2]) * (x[2] - y[2]));
                lmin = l < lmin ? l : lmin;
            }
        sum_re += r / lmin;
    }
    ck_assert_int_eq(cvm_mesh_get_measure(&got, m, CVM_MEASURE_MEAN_RADIUS_EDGE), CVM_OK);
    ck_assert_double_eq_tol(got, sum_re / (double)c.nt, 1e-12);
    free(cc);
    free(deg);
    free(pairs);
    free(bnd);
    free(f);
    copy_free(&c);
    cvm_mesh_free(m);
    free(p);
    (void)non;
}
END_TEST

/* Every cell of a vertex whose 14 BCC neighbours are all present is the
 * truncated octahedron of volume 1/2, with 8 hexagons of area 3 sqrt(3)/16
 * and 6 squares of area 1/8; on the cubic lattice (all ties) every interior
 * vertex has the unit cube, and the interior cells fill (k-1)^3. */
START_TEST(dual_cells_of_lattices_have_the_exact_volumes)
{
    int cubic;
    for (cubic = 0; cubic < 2; cubic++) {
        int k = cubic ? 6 : 5;
        size_t n, i, ne, nf, nfull = 0;
        double *p = lattice(k, !cubic, &n), *vol, *area, *len, sum = 0;
        cvm_mesh *m = mesh_of(p, n);
        cvm_index *edges, *faces;
        ck_assert_int_eq(cvm_mesh_count_dual3(&ne, &nf, m), CVM_OK);
        vol = malloc(n * sizeof *vol);
        area = malloc(ne * sizeof *area);
        len = malloc(nf * sizeof *len);
        edges = malloc(2 * ne * sizeof *edges);
        faces = malloc(3 * nf * sizeof *faces);
        ck_assert_int_eq(cvm_mesh_copy_dual3_volumes(vol, n - 1, m), CVM_E_BUFFER_TOO_SMALL);
        ck_assert_int_eq(cvm_mesh_copy_dual3_volumes(vol, n, m), CVM_OK);
        ck_assert_int_eq(cvm_mesh_copy_dual3_face_areas(edges, 2 * ne, area, ne, m), CVM_OK);
        ck_assert_int_eq(cvm_mesh_copy_dual3_edge_lengths(faces, 3 * nf, len, nf, m), CVM_OK);
        for (i = 0; i < n; i++) {
            const double *x = p + 3 * i;
            int full = cubic ? (x[0] >= 1 && x[0] <= k - 1 && x[1] >= 1 && x[1] <= k - 1 &&
                                x[2] >= 1 && x[2] <= k - 1)
                             : (x[0] >= 1 && x[0] <= k - 1 && x[1] >= 1 && x[1] <= k - 1 &&
                                x[2] >= 1 && x[2] <= k - 1);
            if (vol[i] >= 0)
                sum += vol[i];
            if (!full)
                continue;
            nfull++;
            ck_assert_msg(fabs(vol[i] - (cubic ? 1.0 : 0.5)) < 1e-12, "vertex %lu: volume %.17g",
                          (unsigned long)i, vol[i]);
        }
        ck_assert_uint_gt(nfull, 20);
        if (cubic) {
            /* interior vertices are exactly those of [1, k-1]^3 */
            ck_assert_double_eq_tol(sum, (double)((k - 1) * (k - 1) * (k - 1)), 1e-9);
            for (i = 0; i < nf; i++) /* a dual edge is 0 (a tie) or a unit step */
                ck_assert(len[i] == 0 || fabs(len[i] - 1) < 1e-12);
        }
        for (i = 0; i < ne; i++) {
            const double *a = p + 3 * edges[2 * i], *b = p + 3 * edges[2 * i + 1];
            double l2 = (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                        (a[2] - b[2]) * (a[2] - b[2]);
            int inner = a[0] >= 1 && a[0] <= k - 1 && a[1] >= 1 && a[1] <= k - 1 &&
                        a[2] >= 1 && a[2] <= k - 1;
            ck_assert_int_lt(edges[2 * i], edges[2 * i + 1]);
            if (!inner)
                continue;
            if (cubic)
                ck_assert(fabs(area[i] - (l2 == 1 ? 1.0 : 0.0)) < 1e-12);
            else
                ck_assert(fabs(area[i] - (l2 == 1 ? 0.125 : 3 * sqrt(3.0) / 16)) < 1e-12);
        }
        free(vol);
        free(area);
        free(len);
        free(edges);
        free(faces);
        cvm_mesh_free(m);
        free(p);
    }
}
END_TEST

/* The polyhedron .vtu: shared points (one per dual vertex), one VTK_POLYHEDRON
 * per interior vertex, staged and committed like the other writes. */
START_TEST(dual_cells_are_written_as_polyhedra)
{
    size_t n, nv, nt;
    double *p = lattice(3, 1, &n);
    char *dir = iotest_tmpdir(), path[4096], *text;
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, p, n, 3), CVM_OK);
    snprintf(path, sizeof path, "%s/d.vtu", dir);
    ck_assert_int_eq(cvm_mesh_write_dual(m, path), CVM_E_STATE);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_write_dual(m, path), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    text = iotest_slurp(path, NULL);
    ck_assert_ptr_nonnull(text);
    /* BCC k = 3: interior vertices: 2^3 corners and 3^3 centres, minus none */
    ck_assert_ptr_nonnull(strstr(text, "NumberOfCells=\"35\""));
    ck_assert_ptr_nonnull(strstr(text, "Name=\"faceoffsets\""));
    ck_assert_ptr_nonnull(strstr(text, "42 42 42"));
    ck_assert_ptr_nonnull(strstr(text, "Name=\"dual_face_area\""));
    free(text);
    snprintf(path, sizeof path, "%s/d.svg", dir);
    ck_assert_int_eq(cvm_mesh_write_dual(m, path), CVM_E_UNSUPPORTED);
    snprintf(path, sizeof path, "%s/s.vtu", dir);
    ck_assert_int_eq(cvm_mesh_stage_write_dual(m, path), CVM_OK);
    ck_assert_int_eq(cvm_mesh_commit_writes(m), CVM_OK);
    text = iotest_slurp(path, NULL);
    ck_assert_ptr_nonnull(text);
    free(text);
    cvm_mesh_free(m);
    iotest_rmdir(dir);
    free(dir);
    free(p);
}
END_TEST

START_TEST(dual_calls_fail_cleanly_at_every_allocation)
{
    size_t n, k;
    double *p = lattice(2, 1, &n), got, hist[32], *vol = malloc(n * sizeof *vol);
    char *dir = iotest_tmpdir(), path[4096];
    cvmtest_alloc a;
    cvm_mesh *m;
    int step;
    snprintf(path, sizeof path, "%s/o.vtu", dir);
    cvmtest_alloc_init(&a, 0, 0);
    ck_assert_int_eq(cvmtest_mesh_create(&m, &a), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, p, n, 3), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    for (step = 0; step < 4; step++)
        for (k = 1;; k++) {
            cvm_status s;
            cvmtest_alloc_arm(&a, (long)k, 0);
            s = step == 0   ? cvm_mesh_write_dual(m, path)
                : step == 1 ? cvm_mesh_get_measure(&got, m, CVM_MEASURE_MIN_DUAL_EDGE_RATIO_3D)
                : step == 2 ? cvm_mesh_copy_histogram(hist, 32, m, CVM_HIST_VALENCE_3D)
                            : cvm_mesh_copy_dual3_volumes(vol, n, m);
            cvmtest_alloc_arm(&a, 0, 0);
            if (s == CVM_OK)
                break;
            ck_assert_msg(s == CVM_E_NOMEM, "step %d k=%lu: %d %s", step, (unsigned long)k, (int)s,
                          cvm_mesh_errmsg(m));
            ck_assert_uint_lt(k, 1000);
        }
    cvm_mesh_free(m);
    ck_assert_int_eq((int)a.live_blocks, 0);
    iotest_rmdir(dir);
    free(dir);
    free(vol);
    free(p);
}
END_TEST

START_TEST(dual3_calls_refuse_a_2d_mesh_and_bad_arguments)
{
    double xy[8] = {0, 0, 1, 0, 0, 1, 1, 1}, v[4];
    size_t ne, nf;
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 4, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count_dual3(&ne, &nf, m), CVM_E_UNSUPPORTED);
    ck_assert_int_eq(cvm_mesh_copy_dual3_volumes(v, 4, m), CVM_E_UNSUPPORTED);
    ck_assert_int_eq(cvm_mesh_count_dual3(NULL, &nf, m), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_dual3_volumes(v, 4, NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_histogram(v, 4, m, CVM_HIST_DIHEDRAL_DEG), CVM_E_ARGUMENT);
    cvm_mesh_free(m);
}
END_TEST

/* Weights on the BCC corners (the regular tetrahedralisation keeps the BCC
 * connectivity for a small weight): the power bisectors move towards the
 * centres, a corner's cell grows and a centre's shrinks, and one of each still
 * fills the unit cube's volume. Equal weights everywhere change nothing. */
START_TEST(weighted_bcc_cells_share_the_unit_volume)
{
    size_t n, nv, i;
    double *p = lattice(5, 1, &n), *w, *vol, *vol0, corner = -1, centre = -1;
    cvm_mesh *m = mesh_of(p, n);
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    w = malloc(nv * sizeof *w);
    vol = malloc(nv * sizeof *vol);
    vol0 = malloc(nv * sizeof *vol0);
    ck_assert_int_eq(cvm_mesh_copy_dual3_volumes(vol0, nv, m), CVM_OK);
    for (i = 0; i < nv; i++)
        w[i] = 0.25;
    ck_assert_int_eq(cvm_mesh_set_weights(m, w, nv), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_dual3_volumes(vol, nv, m), CVM_OK);
    for (i = 0; i < nv; i++)
        ck_assert(fabs(vol[i] - vol0[i]) < 1e-12);
    for (i = 0; i < nv; i++)
        w[i] = p[3 * i] == floor(p[3 * i]) ? 0.05 : 0.0;
    ck_assert_int_eq(cvm_mesh_set_weights(m, w, nv), CVM_OK);
    ck_assert_msg(cvm_mesh_check(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_copy_dual3_volumes(vol, nv, m), CVM_OK);
    for (i = 0; i < nv; i++) {
        const double *x = p + 3 * i;
        if (!(x[0] >= 1 && x[0] <= 4 && x[1] >= 1 && x[1] <= 4 && x[2] >= 1 && x[2] <= 4))
            continue;
        if (x[0] == floor(x[0])) {
            if (corner >= 0)
                ck_assert(fabs(vol[i] - corner) < 1e-12);
            corner = vol[i];
        } else {
            if (centre >= 0)
                ck_assert(fabs(vol[i] - centre) < 1e-12);
            centre = vol[i];
        }
    }
    ck_assert_double_gt(corner, 0.5);
    ck_assert_double_lt(centre, 0.5);
    ck_assert_double_eq_tol(corner + centre, 1.0, 1e-12);
    free(w);
    free(vol);
    free(vol0);
    cvm_mesh_free(m);
    free(p);
}
END_TEST

TCase *api_mesh3_dual_tcase(void)
{
    TCase *tc = tcase_create("mesh3_dual");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, bcc_measures_agree_with_an_independent_computation);
    tcase_add_test(tc, dual_cells_of_lattices_have_the_exact_volumes);
    tcase_add_test(tc, dual_cells_are_written_as_polyhedra);
    tcase_add_test(tc, weighted_bcc_cells_share_the_unit_volume);
    tcase_add_test(tc, dual_calls_fail_cleanly_at_every_allocation);
    tcase_add_test(tc, dual3_calls_refuse_a_2d_mesh_and_bad_arguments);
    return tc;
}
