/* test_cells.c - dual cell polygons and their .vtu file (lib/dual/cells.c through lib/api/dual_cells.c). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "dual/dual_tests.h"

/* Shoelace area of corners xy[2*a .. 2*b). */
static double shoelace(const double *xy, int a, int b)
{
    double s = 0;
    int k;
    for (k = a; k < b; k++) {
        int n = k + 1 < b ? k + 1 : a;
        s += xy[2 * k] * xy[2 * n + 1] - xy[2 * n] * xy[2 * k + 1];
    }
    return 0.5 * s;
}

typedef struct cells {
    size_t nv;
    cvm_index *off;
    double *xy, *area;
} cells;

static void get_cells(cvm_mesh *m, cells *c)
{
    cvm_index dummy;
    ck_assert_int_eq(cvm_mesh_count(&c->nv, m, CVM_ENT_VERTEX), CVM_OK);
    c->off = malloc((c->nv + 1) * sizeof *c->off);
    c->area = malloc(c->nv * sizeof *c->area);
    ck_assert(c->off && c->area);
    ck_assert_int_eq(cvm_mesh_copy_dual_cell_offsets(&dummy, 1, m), CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_dual_cell_offsets(c->off, c->nv + 1, m), CVM_OK);
    ck_assert_int_eq(c->off[0], 0);
    c->xy = malloc((2 * (size_t)c->off[c->nv] + 1) * sizeof *c->xy);
    ck_assert_ptr_nonnull(c->xy);
    ck_assert_int_eq(cvm_mesh_copy_dual_cells(c->xy, 2 * (size_t)c->off[c->nv] - 1, m),
                     CVM_E_BUFFER_TOO_SMALL);
    ck_assert_int_eq(cvm_mesh_copy_dual_cells(c->xy, 2 * (size_t)c->off[c->nv], m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_dual_areas(c->area, c->nv, m), CVM_OK);
}

static void free_cells(cells *c)
{
    free(c->off);
    free(c->xy);
    free(c->area);
}

/* Every cell's shoelace area equals its co-volume area; the cells sum to the domain. */
static void check_areas(cvm_mesh *m, const cells *c, double domain)
{
    double sum = 0;
    size_t v;
    for (v = 0; v < c->nv; v++) {
        double a = shoelace(c->xy, c->off[v], c->off[v + 1]);
        ck_assert_msg(fabs(a - c->area[v]) <= 1e-12 * (1 + domain), "vertex %lu: polygon %.17g, dual area %.17g",
                      (unsigned long)v, a, c->area[v]);
        ck_assert(c->off[v + 1] - c->off[v] >= 3);
        sum += a;
    }
    ck_assert_msg(fabs(sum - domain) <= 1e-12 * domain, "cells sum to %.17g, domain %.17g", sum, domain);
    (void)m;
}

/* A triangular lattice clipped to [0,1] x [0, ny*s]: only acute and right triangles. */
static cvm_mesh *lattice(int nx, int ny, double *domain)
{
    double h = 1.0 / nx, s = h * sqrt(3.0) / 2, *xy = malloc((size_t)(nx + 3) * (ny + 1) * 2 * sizeof *xy);
    cvm_index seg[8] = {0, 1, 1, 2, 2, 3, 3, 0};
    size_t n = 4;
    int i, j;
    cvm_mesh *m;
    ck_assert_ptr_nonnull(xy);
    xy[0] = 0; xy[1] = 0; xy[2] = 1; xy[3] = 0; xy[4] = 1; xy[5] = ny * s; xy[6] = 0; xy[7] = ny * s;
    for (j = 0; j <= ny; j++) {
        for (i = 0; i <= nx; i++) {
            double x = i * h + (j % 2 ? 0.5 * h : 0);
            if (x > 1 || ((j == 0 || j == ny) && (i == 0 || i == nx)))
                continue; /* corners already in */
            xy[2 * n] = x;
            xy[2 * n + 1] = j * s;
            n++;
        }
        if (j % 2) { /* the odd rows start half a step in: add their ends on the sides */
            xy[2 * n] = 0;
            xy[2 * n + 1] = j * s;
            xy[2 * n + 2] = 1;
            xy[2 * n + 3] = j * s;
            n += 2;
        }
    }
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, n, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, seg, 4), CVM_OK);
    ck_assert_msg(cvm_mesh_triangulate(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    free(xy);
    *domain = ny * s;
    return m;
}

/* Acute/right triangles: every triangle holds its power vertex, cell areas
 * match the co-volume areas and every cell polygon is convex and CCW. */
START_TEST(cells_of_acute_delaunay_mesh_are_convex_and_tile)
{
    double domain, pct;
    cvm_mesh *m = lattice(12, 10, &domain);
    cells c;
    size_t v;
    int k;
    ck_assert_int_eq(cvm_mesh_get_measure(&pct, m, CVM_MEASURE_DUAL_OUTSIDE_PCT), CVM_OK);
    ck_assert(pct == 0);
    get_cells(m, &c);
    check_areas(m, &c, domain);
    for (v = 0; v < c.nv; v++) {
        int a = c.off[v], b = c.off[v + 1], n = b - a;
        for (k = 0; k < n; k++) {
            const double *p = c.xy + 2 * (a + k), *q = c.xy + 2 * (a + (k + 1) % n),
                         *r = c.xy + 2 * (a + (k + 2) % n);
            double cross = (q[0] - p[0]) * (r[1] - q[1]) - (q[1] - p[1]) * (r[0] - q[0]);
            ck_assert_msg(cross >= -1e-12, "cell of vertex %lu turns clockwise at corner %d (%g)",
                          (unsigned long)v, (k + 1) % n, cross);
        }
    }
    free_cells(&c);
    cvm_mesh_free(m);
}
END_TEST

/* Weighted, refined square (some power vertices outside their triangles):
 * signed polygon areas still equal the co-volume areas and sum to 1. */
START_TEST(cells_of_weighted_mesh_sum_to_domain)
{
    cvm_mesh *m = dtest_refined_square(0.08);
    uint64_t rng = 3;
    size_t nv, v;
    double *w;
    cells c;
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    w = malloc(nv * sizeof *w);
    ck_assert_ptr_nonnull(w);
    for (v = 0; v < nv; v++)
        w[v] = 0.2 * 0.08 * 0.08 * dtest_uniform(&rng);
    ck_assert_int_eq(cvm_mesh_set_weights(m, w, nv), CVM_OK);
    get_cells(m, &c);
    check_areas(m, &c, 1.0);
    free_cells(&c);
    free(w);
    cvm_mesh_free(m);
}
END_TEST

/* The .vtu of the dual: one polygon per vertex with vertex, area and weight data. */
START_TEST(write_dual_writes_polygons)
{
    char dir[] = "/tmp/cvm_dualXXXXXX", path[128], line[512];
    double domain;
    cvm_mesh *m = lattice(4, 4, &domain), *empty;
    size_t nv, ncell = 0, npoly = 0;
    int seen_area = 0, seen_weight = 0, seen_vertex = 0;
    FILE *f;
    ck_assert_ptr_nonnull(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/dual.vtu", dir);
    ck_assert_int_eq(cvm_mesh_write_dual(m, path), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&nv, m, CVM_ENT_VERTEX), CVM_OK);
    f = fopen(path, "r");
    ck_assert_ptr_nonnull(f);
    while (fgets(line, sizeof line, f)) {
        char *p = strstr(line, "NumberOfCells=\"");
        if (p)
            ncell = strtoul(p + 15, NULL, 10);
        seen_area |= strstr(line, "Name=\"area\"") != NULL;
        seen_weight |= strstr(line, "Name=\"weight\"") != NULL;
        seen_vertex |= strstr(line, "Name=\"vertex\"") != NULL;
        if (strstr(line, "Name=\"types\"")) {
            while (fgets(line, sizeof line, f) && !strstr(line, "</DataArray>"))
                for (p = strtok(line, " \n"); p; p = strtok(NULL, " \n"))
                    npoly += strcmp(p, "7") == 0;
        }
    }
    fclose(f);
    ck_assert_uint_eq(ncell, nv);
    ck_assert_uint_eq(npoly, nv);
    ck_assert(seen_area && seen_weight && seen_vertex);
    remove(path);
    snprintf(path, sizeof path, "%s/dual.svg", dir);
    ck_assert_int_eq(cvm_mesh_write_dual(m, path), CVM_E_UNSUPPORTED);
    ck_assert_int_eq(access(path, F_OK), -1);
    ck_assert_int_eq(cvm_mesh_write_dual(m, NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_write_dual(NULL, path), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_create(&empty), CVM_OK);
    ck_assert_int_eq(cvm_mesh_write_dual(empty, path), CVM_E_STATE);
    cvm_mesh_free(empty);
    snprintf(path, sizeof path, "%s/no/such/dir/dual.vtu", dir);
    ck_assert_int_eq(cvm_mesh_write_dual(m, path), CVM_E_IO_OPEN);
    ck_assert_int_eq(rmdir(dir), 0);
    cvm_mesh_free(m);
}
END_TEST

TCase *dual_cells_tcase(void)
{
    TCase *tc = tcase_create("cells");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, cells_of_acute_delaunay_mesh_are_convex_and_tile);
    tcase_add_test(tc, cells_of_weighted_mesh_sum_to_domain);
    tcase_add_test(tc, write_dual_writes_polygons);
    return tc;
}
