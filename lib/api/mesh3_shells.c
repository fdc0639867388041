/* mesh3_shells.c - holes told by the surface's orientation: without hole or region points, a
 * tetrahedron on the side a surface triangle faces is outside the domain (the convention of
 * .off and .stl: normals point out of the domain), and so is everything it reaches without
 * crossing the surface. */
#include <string.h>

#include "api/mesh3_internal.h"

/* Is (a, b, c) an even permutation of (x, y, z)? (The same triple is assumed.) */
static int same_turn(const int32_t *abc, const int32_t *xyz)
{
    int k;
    for (k = 0; k < 3; k++)
        if (abc[0] == xyz[k])
            return abc[1] == xyz[(k + 1) % 3];
    return 0;
}

/* Drop the tetrahedra of g in gone (ntet flags), then the vertices no tetrahedron uses
 * (Steiner points the recovery put inside a hole; input points stay on the surface). */
static cvm_status compact(cvm__ctx *ctx, cvm__mesh3 *g, const uint8_t *gone)
{
    size_t i, k, nkeep = 0, nv = 0;
    int32_t *vmap = cvm__malloc(ctx, (g->nv ? g->nv : 1) * sizeof *vmap);
    if (!vmap)
        return cvm__nomem(ctx);
    for (i = 0; i < g->ntet; i++)
        if (!gone[i]) {
            memmove(g->tet + 4 * nkeep, g->tet + 4 * i, 4 * sizeof *g->tet);
            if (g->tattr)
                g->tattr[nkeep] = g->tattr[i];
            nkeep++;
        }
    g->ntet = nkeep;
    for (i = 0; i < g->nv; i++)
        vmap[i] = -1;
    for (i = 0; i < 4 * g->ntet; i++)
        vmap[g->tet[i]] = 0;
    for (i = 0; i < g->nv; i++)
        if (vmap[i] == 0) {
            memmove(g->xyz + 3 * nv, g->xyz + 3 * i, 3 * sizeof *g->xyz);
            vmap[i] = (int32_t)nv++;
        }
    if (nv < g->nv) {
        size_t dropped = g->nv - nv;
        for (i = 0; i < 4 * g->ntet; i++)
            g->tet[i] = vmap[g->tet[i]];
        for (i = 0; i < 3 * g->nface; i++)
            g->face[i] = vmap[g->face[i]];
        for (k = 0; k < g->in.np; k++)
            if (g->input_map[k] >= 0)
                g->input_map[k] = vmap[g->input_map[k]];
        g->n_steiner_interior -= dropped < g->n_steiner_interior ? dropped : g->n_steiner_interior;
        g->nv = nv;
    }
    cvm__free(ctx, vmap);
    return CVM_OK;
}

cvm_status cvm__mesh3_carve_by_orientation(cvm__ctx *ctx, cvm__mesh3 *g, const int32_t *tri,
                                           size_t nt, size_t *removed)
{
    int32_t *nbr = NULL, *stack = NULL;
    uint8_t *wall = NULL, *side = NULL; /* side: 1 outside seed / reached, 2 inside seed */
    cvm__face_key *index = NULL;
    size_t i, k, nst = 0, ngone = 0;
    int clash = 0;
    cvm_status s;
    *removed = 0;
    if (g->in.nholes || g->in.nregions || g->ntet == 0)
        return CVM_OK;
    if ((s = cvm__mesh3_adjacency(ctx, g->tet, g->ntet, &nbr)) ||
        (s = cvm__mesh3_face_index(ctx, g->tet, g->ntet, &index)))
        goto done;
    wall = cvm__calloc(ctx, 4 * g->ntet, 1);
    side = cvm__calloc(ctx, g->ntet, 1);
    stack = cvm__malloc(ctx, g->ntet * sizeof *stack);
    if (!wall || !side || !stack) {
        s = cvm__nomem(ctx);
        goto done;
    }
    for (k = 0; k < nt; k++) {
        int32_t v[3], f[3], slot, t, across;
        v[0] = g->input_map[tri[3 * k]];
        v[1] = g->input_map[tri[3 * k + 1]];
        v[2] = g->input_map[tri[3 * k + 2]];
        slot = cvm__mesh3_find_face(index, 4 * g->ntet, v[0], v[1], v[2]);
        if (slot < 0)
            goto done; /* not a face (cannot happen after recovery): leave the mesh as it is */
        t = slot / 4;
        across = nbr[slot];
        wall[slot] = 1;
        if (across >= 0)
            wall[across] = 1;
        cvm__mesh3_face_corners(g->tet + 4 * (size_t)t, slot % 4, f);
        /* the triangle turns as t's outward face: it faces away from t, towards across */
        if (same_turn(v, f)) {
            side[t] |= 2;
            if (across >= 0)
                side[across / 4] |= 1;
        } else {
            side[t] |= 1;
            if (across >= 0)
                side[across / 4] |= 2;
        }
    }
    for (i = 0; i < g->ntet; i++)
        if (side[i] & 1)
            stack[nst++] = (int32_t)i;
    while (nst) {
        int32_t t = stack[--nst];
        int f;
        if (side[t] & 2)
            clash = 1;
        ngone++;
        for (f = 0; f < 4; f++) {
            int32_t o = nbr[4 * t + f];
            if (o >= 0 && !wall[4 * t + f] && !(side[o / 4] & 1)) {
                side[o / 4] |= 1;
                stack[nst++] = o / 4;
            }
        }
    }
    /* A tetrahedron both behind and in front of the surface: internal facets, or shells
     * oriented some other way. Orientation tells nothing then; keep every tetrahedron. */
    if (clash || ngone == 0 || ngone == g->ntet)
        goto done;
    for (i = 0; i < g->ntet; i++)
        side[i] &= 1;
    if ((s = compact(ctx, g, side)))
        goto done;
    *removed = ngone;
done:
    cvm__free(ctx, nbr);
    cvm__free(ctx, index);
    cvm__free(ctx, wall);
    cvm__free(ctx, side);
    cvm__free(ctx, stack);
    return s;
}
