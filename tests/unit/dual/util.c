/* util.c - helpers of the dual suite: a refined square, a mesh's arrays, an independent power test. */
#include <stdlib.h>
#include <string.h>

#include "dual/dual_tests.h"
#include "geom/geom_internal.h"

cvm_mesh *dtest_refined_square(double h)
{
    static const double sq[] = {0, 0, 1, 0, 1, 1, 0, 1};
    static const cvm_index seg[] = {0, 1, 1, 2, 2, 3, 3, 0};
    cvm_mesh *m;
    cvm_sizing *s;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, sq, 4, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, seg, 4), CVM_OK);
    ck_assert_msg(cvm_mesh_triangulate(m) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_uniform(s, h), CVM_OK);
    ck_assert_msg(cvm_mesh_refine(m, s, CVM_ALGO_FRONTAL) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    cvm_sizing_free(s);
    return m;
}

void dtest_get(cvm_mesh *m, dtest_mesh *d)
{
    ck_assert_int_eq(cvm_mesh_count(&d->nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&d->nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&d->ne, m, CVM_ENT_EDGE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&d->nseg, m, CVM_ENT_SEGMENT), CVM_OK);
    d->xy = malloc((2 * d->nv + 1) * sizeof *d->xy);
    d->tri = malloc((3 * d->nt + 1) * sizeof *d->tri);
    d->nbr = malloc((3 * d->nt + 1) * sizeof *d->nbr);
    d->edge = malloc((2 * d->ne + 1) * sizeof *d->edge);
    d->seg = malloc((2 * d->nseg + 1) * sizeof *d->seg);
    d->w = malloc((d->nv + 1) * sizeof *d->w);
    ck_assert(d->xy && d->tri && d->nbr && d->edge && d->seg && d->w);
    ck_assert_int_eq(cvm_mesh_copy_points(d->xy, 2 * d->nv, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(d->tri, 3 * d->nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_neighbors(d->nbr, 3 * d->nt, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(d->edge, 2 * d->ne, m, CVM_ENT_EDGE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(d->seg, 2 * d->nseg, m, CVM_ENT_SEGMENT), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_weights(d->w, d->nv, m), CVM_OK);
}

void dtest_free(dtest_mesh *d)
{
    free(d->xy);
    free(d->tri);
    free(d->nbr);
    free(d->edge);
    free(d->seg);
    free(d->w);
}

void dtest_assert_identical(const dtest_mesh *a, const dtest_mesh *b)
{
    ck_assert_uint_eq(a->nv, b->nv);
    ck_assert_uint_eq(a->nt, b->nt);
    ck_assert_int_eq(memcmp(a->xy, b->xy, 2 * a->nv * sizeof *a->xy), 0);
    ck_assert_int_eq(memcmp(a->w, b->w, a->nv * sizeof *a->w), 0);
    ck_assert_int_eq(memcmp(a->tri, b->tri, 3 * a->nt * sizeof *a->tri), 0);
}

int dtest_is_segment(const dtest_mesh *d, cvm_index a, cvm_index b)
{
    size_t k;
    cvm_index lo = a < b ? a : b, hi = a < b ? b : a;
    for (k = 0; k < d->nseg; k++)
        if (d->seg[2 * k] == lo && d->seg[2 * k + 1] == hi)
            return 1;
    return 0;
}

size_t dtest_power_violations(const dtest_mesh *d, const double *w)
{
    size_t t, bad = 0;
    int j, k;
    for (t = 0; t < d->nt; t++) {
        const cvm_index *v = d->tri + 3 * t;
        for (j = 0; j < 3; j++) {
            cvm_index u = d->nbr[3 * t + (size_t)j], a = v[(j + 1) % 3], b = v[(j + 2) % 3], o = -1;
            if (u < 0 || dtest_is_segment(d, a, b))
                continue;
            for (k = 0; k < 3; k++) {
                cvm_index x = d->tri[3 * (size_t)u + (size_t)k];
                if (x != a && x != b)
                    o = x;
            }
            ck_assert_int_ge(o, 0);
            if (cvm__power2d(d->xy + 2 * (size_t)v[0], d->xy + 2 * (size_t)v[1], d->xy + 2 * (size_t)v[2],
                             d->xy + 2 * (size_t)o, w[v[0]], w[v[1]], w[v[2]], w[o]) > 0)
                bad++;
        }
    }
    return bad;
}

double dtest_uniform(uint64_t *state)
{
    uint64_t z = (*state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return (double)(z >> 11) * 0x1p-53;
}
