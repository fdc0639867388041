/* test_fv.c - the power dual as a finite-volume mesh: shared points, polygons of point ids, the
 * face table (lib/dual/cells.c through lib/api/dual_cells.c) and its .vtu file. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "dual/dual_tests.h"
#include "support/oom_sweep.h"

typedef struct fv {
    size_t nv, nt, ne, npt, ncorner, nface;
    double *xy, *pt, *cells, *flen, *area, *elen, *dvert;
    cvm_index *tri, *edge, *off, *poly, *face;
} fv;

static void *alloc(size_t n)
{
    void *p = malloc(n ? n : 1);
    ck_assert_ptr_nonnull(p);
    return p;
}

static void fv_get(cvm_mesh *m, fv *f)
{
    ck_assert_int_eq(cvm_mesh_count(&f->nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&f->nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&f->ne, m, CVM_ENT_EDGE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count_dual(&f->npt, &f->ncorner, &f->nface, m), CVM_OK);
    f->xy = alloc(2 * f->nv * sizeof *f->xy);
    f->tri = alloc(3 * f->nt * sizeof *f->tri);
    f->edge = alloc(2 * f->ne * sizeof *f->edge);
    f->pt = alloc(2 * f->npt * sizeof *f->pt);
    f->cells = alloc(2 * f->ncorner * sizeof *f->cells);
    f->off = alloc((f->nv + 1) * sizeof *f->off);
    f->poly = alloc(f->ncorner * sizeof *f->poly);
    f->face = alloc(6 * f->nface * sizeof *f->face);
    f->flen = alloc(2 * f->nface * sizeof *f->flen);
    f->area = alloc(f->nv * sizeof *f->area);
    f->elen = alloc(f->ne * sizeof *f->elen);
    f->dvert = alloc(2 * f->nt * sizeof *f->dvert);
    ck_assert_int_eq(cvm_mesh_copy_points(f->xy, 2 * f->nv, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(f->tri, 3 * f->nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(f->edge, 2 * f->ne, m, CVM_ENT_EDGE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_dual_points(f->pt, 2 * f->npt - 1, m), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_dual_points(f->pt, 2 * f->npt, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_dual_cells(f->cells, 2 * f->ncorner, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_dual_cell_offsets(f->off, f->nv + 1, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_dual_polygons(f->poly, f->ncorner - 1, m), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_dual_polygons(f->poly, f->ncorner, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_dual_faces(f->face, 6 * f->nface - 1, m), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_dual_faces(f->face, 6 * f->nface, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_dual_face_lengths(f->flen, 2 * f->nface - 1, m),
                     CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_dual_face_lengths(f->flen, 2 * f->nface, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_dual_areas(f->area, f->nv, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_dual_edge_lengths(f->elen, f->ne, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_dual_vertices(f->dvert, 2 * f->nt, m), CVM_OK);
}

static void fv_free(fv *f)
{
    free(f->xy);
    free(f->tri);
    free(f->edge);
    free(f->pt);
    free(f->cells);
    free(f->off);
    free(f->poly);
    free(f->face);
    free(f->flen);
    free(f->area);
    free(f->elen);
    free(f->dvert);
}

static int cmp_pair(const void *a, const void *b)
{
    const double *x = a, *y = b;
    if (x[0] != y[0])
        return x[0] < y[0] ? -1 : 1;
    return x[1] < y[1] ? -1 : x[1] > y[1];
}

/* Edge (a, b) of the triangles: how many triangles have it (1 boundary, 2 interior). */
static int edge_uses(const fv *f, cvm_index a, cvm_index b)
{
    size_t t;
    int j, n = 0;
    for (t = 0; t < f->nt; t++)
        for (j = 0; j < 3; j++) {
            cvm_index u = f->tri[3 * t + j], v = f->tri[3 * t + (j + 1) % 3];
            n += (u == a && v == b) || (u == b && v == a);
        }
    return n;
}

/* 1 when p -> q (or q -> p) are consecutive corners of cell c. */
static int cell_has_side(const fv *f, cvm_index c, cvm_index p, cvm_index q, int *forward)
{
    cvm_index a = f->off[c], b = f->off[c + 1], k;
    for (k = a; k < b; k++) {
        cvm_index u = f->poly[k], v = f->poly[k + 1 < b ? k + 1 : a];
        if (u == p && v == q) {
            *forward = 1;
            return 1;
        }
        if (u == q && v == p) {
            *forward = 0;
            return 1;
        }
    }
    return 0;
}

/* The facts every finite-volume dual must show; domain: its area. */
static void check_fv(const fv *f, double domain, int distinct_power_vertices)
{
    size_t k, nbe = 0, nbv = 0, sum = 0, n;
    double *sorted, tot = 0, *nsum;
    unsigned char *bv = calloc(f->nv + 1, 1), *used = calloc(f->npt + 1, 1);
    ck_assert(bv && used);
    /* points: the power vertices first (the same doubles), one foot per
     * boundary edge, the boundary vertices */
    ck_assert_mem_eq(f->pt, f->dvert, 2 * f->nt * sizeof *f->pt);
    for (k = 0; k < f->ne; k++)
        if (edge_uses(f, f->edge[2 * k], f->edge[2 * k + 1]) == 1) {
            nbe++;
            bv[f->edge[2 * k]] = bv[f->edge[2 * k + 1]] = 1;
        }
    for (k = 0; k < f->nv; k++)
        nbv += bv[k];
    ck_assert_uint_eq(f->npt, f->nt + nbe + nbv);
    ck_assert_uint_eq(f->nface, f->ne + 2 * nbe);
    /* the polygons name the points whose doubles the corners of cvm_mesh_copy_dual_cells() are */
    ck_assert_int_eq(f->off[f->nv], (cvm_index)f->ncorner);
    for (k = 0; k < f->ncorner; k++) {
        ck_assert(f->poly[k] >= 0 && (size_t)f->poly[k] < f->npt);
        ck_assert_mem_eq(f->pt + 2 * (size_t)f->poly[k], f->cells + 2 * k, 2 * sizeof *f->pt);
        used[f->poly[k]] = 1;
    }
    for (k = 0; k < f->npt; k++)
        ck_assert_msg(used[k], "point %lu is in no cell", (unsigned long)k);
    /* shared corners: no point repeats another's coordinates */
    sorted = alloc(2 * f->npt * sizeof *sorted);
    memcpy(sorted, f->pt, 2 * f->npt * sizeof *sorted);
    qsort(sorted, f->npt, 2 * sizeof *sorted, cmp_pair);
    for (k = 1, n = 1; k < f->npt; k++)
        n += cmp_pair(sorted + 2 * k, sorted + 2 * (k - 1)) != 0;
    if (distinct_power_vertices)
        ck_assert_uint_eq(n, f->npt);
    free(sorted);
    /* faces: the first ne cross the edges in edge order, each interior edge once */
    nsum = calloc(2 * f->nv + 1, sizeof *nsum);
    ck_assert_ptr_nonnull(nsum);
    for (k = 0; k < f->nface; k++) {
        const cvm_index *x = f->face + 6 * k;
        const double *a = f->xy + 2 * (size_t)x[2], *b = f->xy + 2 * (size_t)x[3];
        const double *p = f->pt + 2 * (size_t)x[4], *q = f->pt + 2 * (size_t)x[5];
        double nx = q[1] - p[1], ny = -(q[0] - p[0]); /* q - p turned clockwise */
        int fwd;
        ck_assert(fabs(f->flen[2 * k] - hypot(a[0] - b[0], a[1] - b[1])) <= 1e-15 * f->flen[2 * k]);
        ck_assert(fabs(f->flen[2 * k + 1] - hypot(p[0] - q[0], p[1] - q[1])) <= 1e-15 * f->flen[2 * k + 1]);
        if (k < f->ne) {
            ck_assert_int_eq(x[0], f->edge[2 * k]);
            ck_assert_int_eq(x[1], f->edge[2 * k + 1]);
            ck_assert_int_eq(x[2], x[0]);
            ck_assert_int_eq(x[3], x[1]);
            ck_assert(f->flen[2 * k + 1] == f->elen[k]);
            ck_assert(cell_has_side(f, x[1], x[4], x[5], &fwd) && !fwd); /* cell b: on its right */
        } else {
            ck_assert_int_eq(x[1], -1);
            ck_assert_int_eq(x[0], x[2]);
            ck_assert_int_eq(edge_uses(f, x[2], x[3]), 1);
        }
        ck_assert_msg(cell_has_side(f, x[0], x[4], x[5], &fwd) && fwd, "face %lu is no side of cell %d",
                      (unsigned long)k, x[0]);
        nsum[2 * x[0]] += nx;
        nsum[2 * x[0] + 1] += ny;
        if (x[1] >= 0) {
            nsum[2 * x[1]] -= nx;
            nsum[2 * x[1] + 1] -= ny;
        }
        sum += x[1] >= 0 ? 2 : 1;
    }
    /* every side of every cell is one face, and each cell is closed by its faces */
    ck_assert_uint_eq(sum, f->ncorner);
    for (k = 0; k < f->nv; k++) {
        double s = 0;
        cvm_index a = f->off[k], b = f->off[k + 1], j;
        ck_assert(fabs(nsum[2 * k]) <= 1e-12 && fabs(nsum[2 * k + 1]) <= 1e-12);
        for (j = a; j < b; j++) {
            const double *p = f->pt + 2 * (size_t)f->poly[j], *q = f->pt + 2 * (size_t)f->poly[j + 1 < b ? j + 1 : a];
            s += p[0] * q[1] - q[0] * p[1];
        }
        ck_assert_msg(fabs(0.5 * s - f->area[k]) <= 1e-12 * (1 + domain), "cell %lu: %.17g, area %.17g",
                      (unsigned long)k, 0.5 * s, f->area[k]);
        tot += 0.5 * s;
    }
    ck_assert_msg(fabs(tot - domain) <= 1e-12 * domain, "cells sum to %.17g, domain %.17g", tot, domain);
    free(nsum);
    free(bv);
    free(used);
}

/* Delaunay triangulation of random points in the unit square with its four sides. */
static cvm_mesh *random_square(int n, uint64_t seed)
{
    double *xy = alloc((size_t)(n + 4) * 2 * sizeof *xy);
    cvm_index seg[8] = {0, 1, 1, 2, 2, 3, 3, 0};
    cvm_mesh *m;
    int i;
    xy[0] = 0, xy[1] = 0, xy[2] = 1, xy[3] = 0, xy[4] = 1, xy[5] = 1, xy[6] = 0, xy[7] = 1;
    for (i = 0; i < n; i++) {
        xy[8 + 2 * i] = 0.01 + 0.98 * dtest_uniform(&seed);
        xy[9 + 2 * i] = 0.01 + 0.98 * dtest_uniform(&seed);
    }
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, (size_t)n + 4, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, seg, 4), CVM_OK);
    ck_assert_msg(cvm_mesh_triangulate(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    free(xy);
    return m;
}

START_TEST(fv_dual_of_random_points_shares_corners_and_closes_cells)
{
    cvm_mesh *m = random_square(300, 11);
    fv f;
    fv_get(m, &f);
    check_fv(&f, 1.0, 1);
    fv_free(&f);
    cvm_mesh_free(m);
}
END_TEST

/* A refined square (right and obtuse triangles, cocircular corners: equal
 * power vertices keep a point each), then weighted. */
START_TEST(fv_dual_of_refined_weighted_square_is_consistent)
{
    cvm_mesh *m = dtest_refined_square(0.08);
    uint64_t rng = 5;
    size_t nv, v;
    double *w;
    fv f;
    fv_get(m, &f);
    check_fv(&f, 1.0, 0);
    fv_free(&f);
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    w = alloc(nv * sizeof *w);
    for (v = 0; v < nv; v++)
        w[v] = 0.2 * 0.08 * 0.08 * dtest_uniform(&rng);
    ck_assert_int_eq(cvm_mesh_set_weights(m, w, nv), CVM_OK);
    fv_get(m, &f);
    check_fv(&f, 1.0, 0);
    fv_free(&f);
    free(w);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(fv_dual_arguments_and_states)
{
    static const double p3[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    cvm_mesh *m, *m3;
    size_t np = 9, nc = 9, nf = 9;
    double d;
    cvm_index i;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count_dual(&np, &nc, &nf, m), CVM_OK);
    ck_assert(np == 0 && nc == 0 && nf == 0);
    ck_assert_int_eq(cvm_mesh_copy_dual_points(NULL, 0, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_dual_faces(NULL, 0, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_dual_points(NULL, 2, m), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_count_dual(NULL, &nc, &nf, m), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_count_dual(&np, &nc, &nf, NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_dual_points(&d, 1, NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_dual_polygons(&i, 1, NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_dual_faces(&i, 1, NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_copy_dual_face_lengths(&d, 1, NULL), CVM_E_NULL_ARG);
    cvm_mesh_free(m);
    ck_assert_int_eq(cvm_mesh_create(&m3), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m3, p3, 4, 3), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count_dual(&np, &nc, &nf, m3), CVM_E_UNSUPPORTED);
    ck_assert_int_eq(cvm_mesh_copy_dual_faces(&i, 1, m3), CVM_E_UNSUPPORTED);
    cvm_mesh_free(m3);
}
END_TEST

/* The .vtu: the points of the finite-volume dual, each once, one polygon per
 * vertex, the face table as field data. */
START_TEST(fv_dual_vtu_has_shared_points_and_faces)
{
    char dir[] = "/tmp/cvm_fvXXXXXX", path[128], line[512];
    cvm_mesh *m = random_square(40, 3);
    size_t npt, nc, nf, nv, npoints = 0, ncell = 0, ntuples = 0;
    int fields = 0;
    FILE *f;
    ck_assert_ptr_nonnull(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/dual.vtu", dir);
    ck_assert_int_eq(cvm_mesh_write_dual(m, path), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count_dual(&npt, &nc, &nf, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    f = fopen(path, "r");
    ck_assert_ptr_nonnull(f);
    while (fgets(line, sizeof line, f)) {
        char *p;
        if ((p = strstr(line, "NumberOfPoints=\"")))
            npoints = strtoul(p + 16, NULL, 10);
        if ((p = strstr(line, "NumberOfCells=\"")))
            ncell = strtoul(p + 15, NULL, 10);
        if ((p = strstr(line, "NumberOfTuples=\""))) {
            ntuples = strtoul(p + 16, NULL, 10);
            ck_assert_uint_eq(ntuples, nf);
            fields++;
        }
    }
    fclose(f);
    ck_assert_uint_eq(npoints, npt);
    ck_assert_uint_eq(ncell, nv);
    ck_assert_int_eq(fields, 4);
    remove(path);
    ck_assert_int_eq(rmdir(dir), 0);
    cvm_mesh_free(m);
}
END_TEST

/* Out of memory at every allocation of the copies and of the dual's .vtu. */
static void oom_setup(cvm_mesh *m, void *arg)
{
    static const double xy[] = {0, 0, 1, 0, 1, 1, 0, 1, 0.3, 0.4, 0.7, 0.6, 0.55, 0.2, 0.2, 0.8};
    static const cvm_index seg[] = {0, 1, 1, 2, 2, 3, 3, 0};
    (void)arg;
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 8, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, seg, 4), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
}

static cvm_status oom_run(cvm_mesh *m, void *arg)
{
    const char *path = arg;
    size_t np, nc, nf;
    cvm_index ids[512];
    double x[512];
    cvm_status s;
    if ((s = cvm_mesh_count_dual(&np, &nc, &nf, m)))
        return s;
    ck_assert(2 * np <= 512 && nc <= 512 && 6 * nf <= 512);
    if ((s = cvm_mesh_copy_dual_points(x, 512, m)) || (s = cvm_mesh_copy_dual_polygons(ids, 512, m)) ||
        (s = cvm_mesh_copy_dual_faces(ids, 512, m)) || (s = cvm_mesh_copy_dual_face_lengths(x, 512, m)))
        return s;
    return cvm_mesh_write_dual(m, path);
}

START_TEST(fv_dual_out_of_memory_is_a_status)
{
    char dir[] = "/tmp/cvm_fvXXXXXX", path[128];
    ck_assert_ptr_nonnull(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/dual.vtu", dir);
    cvmtest_oom_sweep(oom_setup, oom_run, NULL, path);
    remove(path);
    ck_assert_int_eq(rmdir(dir), 0);
}
END_TEST

TCase *dual_fv_tcase(void)
{
    TCase *tc = tcase_create("fv");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, fv_dual_of_random_points_shares_corners_and_closes_cells);
    tcase_add_test(tc, fv_dual_of_refined_weighted_square_is_consistent);
    tcase_add_test(tc, fv_dual_arguments_and_states);
    tcase_add_test(tc, fv_dual_vtu_has_shared_points_and_faces);
    tcase_add_test(tc, fv_dual_out_of_memory_is_a_status);
    return tc;
}
