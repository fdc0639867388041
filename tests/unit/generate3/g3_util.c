/* g3_util.c - see g3_util.h. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "generate3/g3_util.h"

static int cmp_i64(const void *a, const void *b)
{
    int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

static void sort3(cvm_index *v)
{
    cvm_index t;
    if (v[0] > v[1]) { t = v[0]; v[0] = v[1]; v[1] = t; }
    if (v[1] > v[2]) { t = v[1]; v[1] = v[2]; v[2] = t; }
    if (v[0] > v[1]) { t = v[0]; v[0] = v[1]; v[1] = t; }
}

int64_t g3_face_key(const g3_mesh *g, cvm_index a, cvm_index b, cvm_index c)
{
    cvm_index v[3] = {a, b, c};
    int64_t n = (int64_t)g->nv;
    sort3(v);
    return ((int64_t)v[0] * n + v[1]) * n + v[2];
}

void g3_mesh_get(g3_mesh *g, const cvm_mesh *m)
{
    size_t t, i, k;
    int64_t *all;
    memset(g, 0, sizeof *g);
    ck_assert_int_eq(cvm_mesh_count(&g->nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&g->nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&g->nf, m, CVM_ENT_TRIANGLE), CVM_OK);
    g->xyz = malloc(3 * g->nv * sizeof *g->xyz);
    g->tet = malloc(4 * g->nt * sizeof *g->tet);
    g->face = malloc((3 * g->nf + 1) * sizeof *g->face);
    g->valence = calloc(g->nv, sizeof *g->valence);
    ck_assert(g->xyz && g->tet && g->face && g->valence);
    ck_assert_int_eq(cvm_mesh_copy_points_nd(g->xyz, 3 * g->nv, 3, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(g->tet, 4 * g->nt, m, CVM_ENT_TETRAHEDRON), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(g->face, 3 * g->nf, m, CVM_ENT_TRIANGLE), CVM_OK);
    /* edges */
    all = malloc((6 * g->nt + 1) * sizeof *all);
    ck_assert_ptr_nonnull(all);
    for (t = 0, k = 0; t < g->nt; t++) {
        int a, b;
        for (a = 0; a < 4; a++)
            for (b = a + 1; b < 4; b++) {
                int64_t p = g->tet[4 * t + a], q = g->tet[4 * t + b];
                all[k++] = p < q ? p * (int64_t)g->nv + q : q * (int64_t)g->nv + p;
            }
    }
    qsort(all, k, sizeof *all, cmp_i64);
    for (i = 0, g->ne = 0; i < k; i++)
        if (i == 0 || all[i] != all[i - 1])
            all[g->ne++] = all[i];
    g->edge = all;
    for (i = 0; i < g->ne; i++) {
        g->valence[all[i] / (int64_t)g->nv]++;
        g->valence[all[i] % (int64_t)g->nv]++;
    }
    /* faces */
    all = malloc((4 * g->nt + 1) * sizeof *all);
    ck_assert_ptr_nonnull(all);
    for (t = 0, k = 0; t < g->nt; t++) {
        const cvm_index *v = g->tet + 4 * t;
        all[k++] = g3_face_key(g, v[1], v[2], v[3]);
        all[k++] = g3_face_key(g, v[0], v[2], v[3]);
        all[k++] = g3_face_key(g, v[0], v[1], v[3]);
        all[k++] = g3_face_key(g, v[0], v[1], v[2]);
    }
    qsort(all, k, sizeof *all, cmp_i64);
    g->tface = all;
    g->ntf = k; /* with repeats: g3_face_on_boundary counts them */
    for (i = 0, g->nbnd = 0; i < k;) {
        size_t j = i;
        while (j < k && all[j] == all[i])
            j++;
        ck_assert_msg(j - i <= 2, "a face of three or more tetrahedra");
        g->nbnd += j - i == 1;
        i = j;
    }
}

int g3_face_on_boundary(const g3_mesh *g, cvm_index a, cvm_index b, cvm_index c)
{
    int64_t key = g3_face_key(g, a, b, c);
    const int64_t *p = bsearch(&key, g->tface, g->ntf, sizeof *g->tface, cmp_i64);
    size_t i, n = 0;
    if (!p)
        return 0;
    i = (size_t)(p - g->tface);
    while (i > 0 && g->tface[i - 1] == key)
        i--;
    while (i + n < g->ntf && g->tface[i + n] == key)
        n++;
    return n == 1;
}

int64_t g3_euler(const g3_mesh *g)
{
    size_t i, nf = 0;
    for (i = 0; i < g->ntf; i++)
        nf += i == 0 || g->tface[i] != g->tface[i - 1];
    return (int64_t)g->nv - (int64_t)g->ne + (int64_t)nf - (int64_t)g->nt;
}

void g3_mesh_free(g3_mesh *g)
{
    free(g->xyz);
    free(g->tet);
    free(g->face);
    free(g->edge);
    free(g->tface);
    free(g->valence);
    memset(g, 0, sizeof *g);
}

void g3_data3d(char *buf, size_t len, const char *name)
{
    const char *d = getenv("CVM_DATA3D_DIR");
    snprintf(buf, len, "%s/%s", d && *d ? d : "examples/data3d", name);
}

int g3_with_tetgen(void)
{
    return strstr(cvm_build_string(), "TetGen 1.5") != NULL;
}

double g3_tet_volume(const g3_mesh *g)
{
    double v = 0;
    size_t t;
    for (t = 0; t < g->nt; t++) {
        const double *a = g->xyz + 3 * g->tet[4 * t], *b = g->xyz + 3 * g->tet[4 * t + 1],
                     *c = g->xyz + 3 * g->tet[4 * t + 2], *d = g->xyz + 3 * g->tet[4 * t + 3];
        double u[3], w[3], x[3];
        int k;
        for (k = 0; k < 3; k++)
            u[k] = b[k] - a[k], w[k] = c[k] - a[k], x[k] = d[k] - a[k];
        v += fabs(u[0] * (w[1] * x[2] - w[2] * x[1]) - u[1] * (w[0] * x[2] - w[2] * x[0]) +
                  u[2] * (w[0] * x[1] - w[1] * x[0])) / 6;
    }
    return v;
}

static int g3u_cmp_i64(const void *a, const void *b)
{
    int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

void g3_assert_closed_oriented(const g3_mesh *g)
{
    int64_t *e = malloc(3 * g->nf * sizeof *e);
    size_t f, i;
    int k;
    ck_assert_ptr_nonnull(e);
    for (f = 0; f < g->nf; f++)
        for (k = 0; k < 3; k++)
            e[3 * f + (size_t)k] = (int64_t)g->face[3 * f + (size_t)k] * (int64_t)g->nv +
                                   g->face[3 * f + (size_t)(k + 1) % 3];
    qsort(e, 3 * g->nf, sizeof *e, g3u_cmp_i64);
    for (i = 0; i < 3 * g->nf; i++) {
        int64_t a = e[i] / (int64_t)g->nv, b = e[i] % (int64_t)g->nv, rev = b * (int64_t)g->nv + a;
        ck_assert_msg(i == 0 || e[i] != e[i - 1], "directed edge %lld-%lld twice", (long long)a,
                      (long long)b);
        ck_assert_msg(bsearch(&rev, e, 3 * g->nf, sizeof *e, g3u_cmp_i64) != NULL,
                      "edge %lld-%lld has no twin", (long long)a, (long long)b);
    }
    free(e);
}
