/* util3.c - helpers of the delaunay3 suite: builders, generators, Euler characteristic. */
#include <stdlib.h>
#include <string.h>

#include "delaunay3/delaunay3_tests.h"

int32_t *d3test_build(cvm__tet3 *T, cvm__ctx *ctx, const double *xyz, const double *w, size_t n,
                      uint64_t seed, size_t *nt)
{
    int32_t *tets;
    cvm_status s;
    cvm__tet3_init(T, ctx);
    s = cvm__tet3_build(T, xyz, w, n, seed);
    ck_assert_msg(s == CVM_OK, "build: status %d: %s", (int)s, ctx->errmsg);
    s = cvm__tet3_check(T);
    ck_assert_msg(s == CVM_OK, "check: %s", ctx->errmsg);
    tets = malloc(4 * (T->n_finite + 1) * sizeof *tets);
    ck_assert_ptr_nonnull(tets);
    ck_assert_int_eq(cvm__tet3_copy_tets(T, tets), CVM_OK);
    *nt = T->n_finite;
    return tets;
}

void d3test_random(double *xyz, size_t n, uint64_t seed)
{
    size_t i;
    uint64_t s = seed * 2862933555777941757u + 3037000493u;
    for (i = 0; i < 3 * n; i++) {
        s = s * 6364136223846793005u + 1442695040888963407u;
        xyz[i] = (double)(s >> 11) * 0x1p-53;
    }
}

size_t d3test_bcc(double *xyz, int k)
{
    size_t m = 0;
    int x, y, z;
    for (x = 0; x < k; x++)
        for (y = 0; y < k; y++)
            for (z = 0; z < k; z++) {
                xyz[3 * m] = 2 * x, xyz[3 * m + 1] = 2 * y, xyz[3 * m + 2] = 2 * z, m++;
                if (x + 1 < k && y + 1 < k && z + 1 < k) {
                    xyz[3 * m] = 2 * x + 1, xyz[3 * m + 1] = 2 * y + 1;
                    xyz[3 * m + 2] = 2 * z + 1, m++;
                }
            }
    return m;
}

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return (x > y) - (x < y);
}

/* Distinct keys after sorting. */
static size_t count_distinct(uint64_t *k, size_t n)
{
    size_t i, d = 0;
    qsort(k, n, sizeof *k, cmp_u64);
    for (i = 0; i < n; i++)
        d += i == 0 || k[i] != k[i - 1];
    return d;
}

static void sort3(uint64_t *a, uint64_t *b, uint64_t *c)
{
    uint64_t t;
    if (*a > *b)
        t = *a, *a = *b, *b = t;
    if (*b > *c)
        t = *b, *b = *c, *c = t;
    if (*a > *b)
        t = *a, *a = *b, *b = t;
}

long d3test_euler(const int32_t *tets, size_t nt)
{
    uint64_t *k = malloc(6 * nt * sizeof *k + 8);
    size_t i, V, E, F;
    int a, b, c;
    ck_assert_ptr_nonnull(k);
    for (i = 0; i < 4 * nt; i++)
        k[i] = (uint64_t)tets[i];
    V = count_distinct(k, 4 * nt);
    for (i = 0; i < nt; i++)
        for (a = 0, c = 0; a < 4; a++)
            for (b = a + 1; b < 4; b++, c++) {
                uint64_t x = (uint64_t)tets[4 * i + a], y = (uint64_t)tets[4 * i + b];
                k[6 * i + c] = x < y ? (x << 32) | y : (y << 32) | x;
            }
    E = count_distinct(k, 6 * nt);
    for (i = 0; i < nt; i++)
        for (a = 0; a < 4; a++) {
            uint64_t v[3];
            int j, m = 0;
            for (j = 0; j < 4; j++)
                if (j != a)
                    v[m++] = (uint64_t)tets[4 * i + j];
            sort3(&v[0], &v[1], &v[2]);
            k[4 * i + a] = (v[0] << 42) | (v[1] << 21) | v[2]; /* ids < 2^21 here */
        }
    F = count_distinct(k, 4 * nt);
    free(k);
    return (long)V - (long)E + (long)F - (long)nt;
}
