/* util.c - helpers shared by the delaunay tests. */
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay_tests.h"

cvm_index *dtest_triangles(cvm_mesh *m, size_t *nt)
{
    cvm_index *t;
    ck_assert_int_eq(cvm_mesh_count(nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    t = malloc(3 * (*nt + 1) * sizeof *t);
    ck_assert_ptr_nonnull(t);
    ck_assert_int_eq(cvm_mesh_copy_cells(t, 3 * *nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    return t;
}

static int cmp3(const void *a, const void *b)
{
    const cvm_index *x = a, *y = b;
    int k;
    for (k = 0; k < 3; k++)
        if (x[k] != y[k])
            return x[k] < y[k] ? -1 : 1;
    return 0;
}

void dtest_canonical(cvm_index *tri, size_t nt)
{
    size_t i;
    for (i = 0; i < nt; i++) {
        cvm_index *t = tri + 3 * i;
        while (t[0] > t[1] || t[0] > t[2]) {
            cvm_index x = t[0];
            t[0] = t[1];
            t[1] = t[2];
            t[2] = x;
        }
    }
    qsort(tri, nt, 3 * sizeof *tri, cmp3);
}

void dtest_random_points(double *xy, size_t n, unsigned long seed)
{
    unsigned long long s = seed * 6364136223846793005ull + 1442695040888963407ull;
    size_t i;
    for (i = 0; i < 2 * n; i++) {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        xy[i] = (double)(s >> 11) / 9007199254740992.0;
    }
}
