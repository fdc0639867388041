/* mesh3_faces.c - face adjacency of a tetrahedron list, by sorting the faces' corner triples;
 * the constrained faces of a 3D handle's mesh. */
#include <stdlib.h>
#include <string.h>

#include "api/mesh3_internal.h"

typedef cvm__face_key fkey;

static void sort3(int32_t *c)
{
    int a, b;
    for (a = 0; a < 3; a++)
        for (b = a + 1; b < 3; b++)
            if (c[b] < c[a]) {
                int32_t t = c[a];
                c[a] = c[b];
                c[b] = t;
            }
}

static int cmp_fkey(const void *a, const void *b)
{
    const fkey *x = (const fkey *)a, *y = (const fkey *)b;
    int k;
    for (k = 0; k < 3; k++)
        if (x->v[k] != y->v[k])
            return (x->v[k] > y->v[k]) - (x->v[k] < y->v[k]);
    return (x->slot > y->slot) - (x->slot < y->slot);
}

void cvm__mesh3_face_corners(const int32_t *t, int f, int32_t out[3])
{
    /* (a, b, c, d) positive: face 0 = (b, d, c), 1 = (a, c, d), 2 = (a, d, b), 3 = (a, b, c) */
    static const int k_face[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};
    int k;
    for (k = 0; k < 3; k++)
        out[k] = t[k_face[f][k]];
}

cvm_status cvm__mesh3_face_index(cvm__ctx *ctx, const int32_t *tet, size_t ntet, fkey **out)
{
    size_t n = 4 * ntet, i;
    fkey *keys = cvm__malloc(ctx, (n ? n : 1) * sizeof *keys);
    *out = NULL;
    if (!keys)
        return cvm__nomem(ctx);
    for (i = 0; i < n; i++) {
        cvm__mesh3_face_corners(tet + 4 * (i / 4), (int)(i % 4), keys[i].v);
        sort3(keys[i].v);
        keys[i].slot = (int32_t)i;
    }
    qsort(keys, n, sizeof *keys, cmp_fkey);
    *out = keys;
    return CVM_OK;
}

int32_t cvm__mesh3_find_face(const fkey *index, size_t n, int32_t a, int32_t b, int32_t c)
{
    fkey key;
    size_t lo = 0, hi = n;
    key.v[0] = a;
    key.v[1] = b;
    key.v[2] = c;
    key.slot = -1; /* below every slot: the first face with these corners */
    sort3(key.v);
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (cmp_fkey(&index[mid], &key) < 0)
            lo = mid + 1;
        else
            hi = mid;
    }
    if (lo < n && memcmp(index[lo].v, key.v, sizeof key.v) == 0)
        return index[lo].slot;
    return -1;
}

cvm_status cvm__mesh3_adjacency(cvm__ctx *ctx, const int32_t *tet, size_t ntet, int32_t **nbr_out)
{
    size_t n = 4 * ntet, i;
    fkey *keys;
    int32_t *nbr;
    cvm_status s;
    *nbr_out = NULL;
    if ((s = cvm__mesh3_face_index(ctx, tet, ntet, &keys)))
        return s;
    nbr = cvm__malloc(ctx, (n ? n : 1) * sizeof *nbr);
    if (!nbr) {
        cvm__free(ctx, keys);
        return cvm__nomem(ctx);
    }
    for (i = 0; i < n; i++)
        nbr[i] = -1;
    for (i = 0; i < n;) {
        size_t j = i + 1;
        while (j < n && memcmp(keys[j].v, keys[i].v, sizeof keys[i].v) == 0)
            j++;
        if (j - i > 2) {
            cvm_status s = cvm__error(ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_TETRAHEDRON,
                                      keys[i].slot / 4,
                                      "the face (%ld, %ld, %ld) is shared by %lu tetrahedra",
                                      (long)keys[i].v[0], (long)keys[i].v[1], (long)keys[i].v[2],
                                      (unsigned long)(j - i));
            cvm__free(ctx, keys);
            cvm__free(ctx, nbr);
            return s;
        }
        if (j - i == 2) {
            nbr[keys[i].slot] = keys[i + 1].slot;
            nbr[keys[i + 1].slot] = keys[i].slot;
        }
        i = j;
    }
    cvm__free(ctx, keys);
    *nbr_out = nbr;
    return CVM_OK;
}

cvm_status cvm__mesh3_constrained_faces(cvm__ctx *ctx, const cvm__mesh3 *g, const int32_t *nbr,
                                        uint8_t **out)
{
    uint8_t *cf = cvm__calloc(ctx, 4 * g->ntet + 1, 1);
    cvm__face_key *keys = NULL;
    size_t i;
    cvm_status s;
    if (!cf)
        return cvm__nomem(ctx);
    for (i = 0; i < 4 * g->ntet; i++)
        cf[i] = nbr[i] < 0;
    if (g->nface) {
        if ((s = cvm__mesh3_face_index(ctx, g->tet, g->ntet, &keys))) {
            cvm__free(ctx, cf);
            return s;
        }
        for (i = 0; i < g->nface; i++) {
            const int32_t *f = g->face + 3 * i;
            int32_t slot = cvm__mesh3_find_face(keys, 4 * g->ntet, f[0], f[1], f[2]);
            if (slot < 0)
                continue;
            cf[slot] = 1;
            if (nbr[slot] >= 0)
                cf[nbr[slot]] = 1;
        }
        cvm__free(ctx, keys);
    }
    *out = cf;
    return CVM_OK;
}

int cvm__mesh3_faces_opposite(const int32_t *f, const int32_t *o)
{
    int k;
    for (k = 0; k < 3; k++)
        if (f[0] == o[k])
            return f[1] == o[(k + 2) % 3] && f[2] == o[(k + 1) % 3];
    return 0;
}
