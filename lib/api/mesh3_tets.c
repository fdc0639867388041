/*
 * mesh3_tets.c - a tetrahedral mesh made elsewhere (TetGen, Gmsh, ...) checked
 * and built as a handle's mesh, for cvm_mesh_set_tetrahedra() and the .ele
 * reading of cvm_mesh_read() (mesh3.c). Every check that decides validity is
 * exact (orient3d); the boundary is then validated as a closed surface by
 * lib/surface3.
 */
#include <math.h>
#include <string.h>

#include "api/mesh3_internal.h"
#include "geom/geom_internal.h"
#include "surface3/surface3_internal.h"

/* The tetrahedra one by one: corners in range and distinct, not flat (exact),
 * positively oriented (two corners swapped otherwise), attributes finite; every
 * point used. Writes out->tet, out->tattr. */
static cvm_status m3t_cells(cvm__ctx *ctx, const double *xyz, size_t np, const int32_t *tets,
                            const double *attr, size_t nt, long long tbase, long long pbase,
                            cvm__mesh3 *out, uint8_t *used)
{
    size_t t, i;
    int a, b;
    for (t = 0; t < nt; t++) {
        int32_t *v = out->tet + 4 * t;
        double o;
        for (a = 0; a < 4; a++) {
            v[a] = tets[4 * t + (size_t)a];
            if (v[a] < 0 || (size_t)v[a] >= np)
                return cvm__error(ctx, CVM_E_INPUT_INDEX, CVM_ENT_TETRAHEDRON, (int64_t)t,
                                  "tetrahedron %lld names point %lld, but points are numbered "
                                  "%lld..%lld", (long long)t + tbase, (long long)v[a] + pbase,
                                  pbase, (long long)np - 1 + pbase);
            for (b = 0; b < a; b++)
                if (v[b] == v[a])
                    return cvm__error(ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_TETRAHEDRON,
                                      (int64_t)t, "tetrahedron %lld names point %lld twice",
                                      (long long)t + tbase, (long long)v[a] + pbase);
        }
        o = cvm__orient3d(xyz + 3 * (size_t)v[0], xyz + 3 * (size_t)v[1], xyz + 3 * (size_t)v[2],
                          xyz + 3 * (size_t)v[3]);
        if (o == 0)
            return cvm__error(ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_TETRAHEDRON, (int64_t)t,
                              "tetrahedron %lld (points %lld %lld %lld %lld) is flat: its corners "
                              "are coplanar", (long long)t + tbase, (long long)v[0] + pbase,
                              (long long)v[1] + pbase, (long long)v[2] + pbase,
                              (long long)v[3] + pbase);
        if (o < 0) {
            int32_t s = v[2];
            v[2] = v[3];
            v[3] = s;
        }
        if (attr) {
            if (!isfinite(attr[t]))
                return cvm__error(ctx, CVM_E_INPUT_NONFINITE, CVM_ENT_TETRAHEDRON, (int64_t)t,
                                  "tetrahedron %lld has a non-finite attribute",
                                  (long long)t + tbase);
            out->tattr[t] = attr[t];
        }
        for (a = 0; a < 4; a++)
            used[v[a]] = 1;
    }
    for (i = 0; i < np; i++)
        if (!used[i])
            return cvm__error(ctx, CVM_E_INPUT_DEGENERATE, CVM_ENT_INPUT_POINT, (int64_t)i,
                              "point %lld is in no tetrahedron (every point must be a vertex of "
                              "the mesh)", (long long)i + pbase);
    return CVM_OK;
}

/* The faces: each shared by at most two tetrahedra, from opposite sides; the
 * boundary (faces of one tetrahedron, outwards) and, with attributes, the faces
 * between tetrahedra of different attributes become out->face. */
static cvm_status m3t_faces(cvm__ctx *ctx, cvm__mesh3 *out, long long tbase)
{
    int32_t *nbr = NULL;
    size_t i, n = 0;
    cvm_status s;
    if ((s = cvm__mesh3_adjacency(ctx, out->tet, out->ntet, &nbr)))
        return s;
    for (i = 0; i < 4 * out->ntet; i++) {
        int32_t f[3], o[3];
        if (nbr[i] < 0) {
            n++;
            continue;
        }
        cvm__mesh3_face_corners(out->tet + 4 * (i / 4), (int)(i % 4), f);
        cvm__mesh3_face_corners(out->tet + 4 * (size_t)(nbr[i] / 4), nbr[i] % 4, o);
        if (!cvm__mesh3_faces_opposite(f, o)) {
            s = cvm__error(ctx, CVM_E_INPUT_INTERSECTING, CVM_ENT_TETRAHEDRON, (int64_t)(i / 4),
                           "tetrahedra %lld and %lld overlap: they lie on the same side of their "
                           "shared face (points %ld %ld %ld, 0-based)",
                           (long long)(i / 4) + tbase, (long long)(nbr[i] / 4) + tbase, (long)f[0],
                           (long)f[1], (long)f[2]);
            break;
        }
        if (out->tattr && (int32_t)i < nbr[i] &&
            out->tattr[i / 4] != out->tattr[(size_t)nbr[i] / 4])
            n++;
    }
    if (!s && !(out->face = cvm__malloc(ctx, (n ? 3 * n : 1) * sizeof *out->face)))
        s = cvm__nomem(ctx);
    for (i = 0; i < 4 * out->ntet && !s; i++)
        if (nbr[i] < 0 || (out->tattr && (int32_t)i < nbr[i] &&
                           out->tattr[i / 4] != out->tattr[(size_t)nbr[i] / 4]))
            cvm__mesh3_face_corners(out->tet + 4 * (i / 4), (int)(i % 4),
                                    out->face + 3 * out->nface++);
    cvm__free(ctx, nbr);
    return s;
}

/* The faces of out as a surface: closed, manifold, consistently oriented and
 * free of intersections (lib/surface3, exact). */
static cvm_status m3t_surface(cvm__ctx *ctx, const cvm__mesh3 *out)
{
    cvm__surf3 sf;
    cvm__surf3_tris tris;
    size_t i;
    cvm_status s;
    cvm__surf3_init(&sf);
    memset(&tris, 0, sizeof tris);
    s = cvm__surf3_add_facet(ctx, &sf, 0);
    for (i = 0; i < out->nv && !s; i++)
        s = cvm__surf3_add_point(ctx, &sf, out->xyz[3 * i], out->xyz[3 * i + 1],
                                 out->xyz[3 * i + 2]);
    for (i = 0; i < out->nface && !s; i++)
        s = cvm__surf3_add_polygon(ctx, &sf, out->face + 3 * i, 3);
    if (!s) {
        sf.facet_word = "boundary face";
        s = cvm__surf3_validate(ctx, &sf, out->tattr ? CVM__SURF3_ALLOW_INTERNAL : 0, &tris);
        if (s && s != CVM_E_NOMEM) {
            char why[CVM__ERRMSG_LEN];
            memcpy(why, ctx->errmsg, sizeof why);
            why[sizeof why - 1] = '\0';
            s = cvm__error(ctx, s, ctx->err_kind, ctx->err_index,
                           "the boundary of the tetrahedra is not a valid closed surface: %s", why);
        }
    }
    cvm__surf3_tris_free(ctx, &tris);
    cvm__surf3_free(ctx, &sf);
    return s;
}

void cvm__mesh3_tets_free(cvm__ctx *ctx, cvm__mesh3 *out)
{
    cvm__free(ctx, out->xyz);
    cvm__free(ctx, out->tet);
    cvm__free(ctx, out->tattr);
    cvm__free(ctx, out->face);
    cvm__free(ctx, out->input_map);
    memset(out, 0, sizeof *out);
}

cvm_status cvm__mesh3_tets_build(cvm__ctx *ctx, const double *xyz, size_t np, const int32_t *tets,
                                 const double *attr, size_t nt, long long tbase, long long pbase,
                                 cvm__mesh3 *out)
{
    uint8_t *used;
    size_t i;
    cvm_status s;
    memset(out, 0, sizeof *out);
    if (nt == 0)
        return cvm__error(ctx, CVM_E_INPUT_EMPTY, CVM_ENT_NONE, -1, "no tetrahedra");
    if (nt > (size_t)INT32_MAX / 4)
        return cvm__error(ctx, CVM_E_TOO_LARGE, CVM_ENT_NONE, -1,
                          "%lu tetrahedra exceed the limit of %ld", (unsigned long)nt,
                          (long)(INT32_MAX / 4));
    out->xyz = cvm__malloc(ctx, 3 * np * sizeof *out->xyz);
    out->input_map = cvm__malloc(ctx, np * sizeof *out->input_map);
    out->tet = cvm__malloc(ctx, 4 * nt * sizeof *out->tet);
    out->tattr = attr ? cvm__malloc(ctx, nt * sizeof *out->tattr) : NULL;
    used = cvm__calloc(ctx, np, 1);
    if (!out->xyz || !out->input_map || !out->tet || (attr && !out->tattr) || !used) {
        s = cvm__nomem(ctx);
        goto done;
    }
    memcpy(out->xyz, xyz, 3 * np * sizeof *xyz);
    for (i = 0; i < np; i++)
        out->input_map[i] = (int32_t)i;
    out->nv = np;
    out->ntet = nt;
    s = m3t_cells(ctx, xyz, np, tets, attr, nt, tbase, pbase, out, used);
    if (!s)
        s = m3t_faces(ctx, out, tbase);
    if (!s)
        s = m3t_surface(ctx, out);
done:
    cvm__free(ctx, used);
    if (s)
        cvm__mesh3_tets_free(ctx, out);
    else
        out->have = 1;
    return s;
}
