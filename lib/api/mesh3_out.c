/*
 * mesh3_out.c - what a 3D handle gives back: counts, points and cells, files,
 * the exact check of its tetrahedralisation, and its quality measures.
 */
#include <math.h>
#include <string.h>

#include "api/mesh3_internal.h"
#include "api/store.h"
#include "geom/geom_internal.h"
#include "geom/measure3.h"

cvm_status cvm__mesh3_count(size_t *out, const cvm_mesh *m, cvm_entity kind)
{
    const cvm__mesh3 *g = m->m3;
    switch (kind) {
    case CVM_ENT_VERTEX: *out = cvm__store_nv(m); return CVM_OK;
    case CVM_ENT_TETRAHEDRON:
    case CVM_ENT_CELL: *out = cvm__store_nslots(m); return CVM_OK;
    case CVM_ENT_TRIANGLE: *out = g->have ? g->nface : 0; return CVM_OK;
    case CVM_ENT_INPUT_POINT: *out = g->in.np; return CVM_OK;
    case CVM_ENT_FACET: *out = g->in.nfacet; return CVM_OK;
    case CVM_ENT_HOLE: *out = g->in.nholes; return CVM_OK;
    case CVM_ENT_REGION: *out = g->in.nregions; return CVM_OK;
    case CVM_ENT_DUPLICATE: *out = g->have ? g->n_dup : 0; return CVM_OK;
    case CVM_ENT_EDGE:
    case CVM_ENT_SEGMENT:
    case CVM_ENT_INPUT_SEGMENT:
    case CVM_ENT_REFINE_UNMET:
    case CVM_ENT_QUAD: *out = 0; return CVM_OK;
    default: return CVM_E_ARGUMENT;
    }
}

const double *cvm__mesh3_points(const cvm_mesh *m, size_t *nv)
{
    const cvm__mesh3 *g = m->m3;
    if (g->have) {
        *nv = cvm__store_nv(m);
        return cvm__store_points(m);
    }
    *nv = g->in.np;
    return g->in.xyz;
}

cvm_status cvm__mesh3_copy_points(double *dst, size_t dst_len, const cvm_mesh *m)
{
    size_t nv;
    const double *p = cvm__mesh3_points(m, &nv);
    if (!dst && dst_len)
        return CVM_E_NULL_ARG;
    if (dst_len < 3 * nv)
        return CVM_E_BUFFER_TOO_SMALL;
    if (nv)
        memcpy(dst, p, 3 * nv * sizeof *dst);
    return CVM_OK;
}

cvm_status cvm__mesh3_copy_cells(cvm_index *dst, size_t dst_len, const cvm_mesh *m,
                                 cvm_entity kind)
{
    const cvm__mesh3 *g = m->m3;
    const int32_t *src;
    size_t n, per;
    if (kind == CVM_ENT_TETRAHEDRON || kind == CVM_ENT_CELL) {
        n = cvm__store_nslots(m);
        src = n ? cvm__store_cell(m, 0) : NULL;
        per = (size_t)cvm__store_cell_size(m);
    } else if (kind == CVM_ENT_TRIANGLE) {
        src = g->face;
        n = g->have ? g->nface : 0;
        per = 3;
    } else {
        return CVM_E_ARGUMENT;
    }
    if (!dst && dst_len)
        return CVM_E_NULL_ARG;
    if (dst_len < per * n)
        return CVM_E_BUFFER_TOO_SMALL;
    if (n)
        memcpy(dst, src, per * n * sizeof *dst);
    return CVM_OK;
}

cvm_status cvm__mesh3_write_to_set(cvm_mesh *m, const char *path, cvm__write_set *ws)
{
    const cvm__mesh3 *g = m->m3;
    cvm__mesh3_out mo;
    if (!g->have)
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "nothing to write: call cvm_mesh_triangulate() first");
    memset(&mo, 0, sizeof mo);
    mo.xyz = g->xyz;
    mo.nv = g->nv;
    mo.w = g->w;
    mo.tet = g->tet;
    mo.ntet = g->ntet;
    mo.tattr = g->tattr;
    mo.face = g->face;
    mo.fmark = g->fmark;
    mo.nface = g->nface;
    if (cvm__opt(m, CVM_OPT_VTU_MERGED_CELLS) != 0 && cvm__format_of(path) == CVM__FMT_VTU)
        return cvm__mesh3_write_merged_to_set(m, path, ws, &mo);
    return cvm__write_file3_to_set(ws, path, &mo);
}

cvm_status cvm__mesh3_check(cvm_mesh *m)
{
    cvm__mesh3 *g = m->m3;
    int32_t *nbr = NULL;
    cvm__face_key *index = NULL;
    size_t t, i, nbound = 0;
    cvm_status s = CVM_OK;
    if (!g->have)
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "nothing to check: call cvm_mesh_triangulate() first");
    for (t = 0; t < cvm__store_nslots(m); t++) {
        const int32_t *v = cvm__store_cell(m, t);
        for (i = 0; i < 4; i++)
            if (v[i] < 0 || (size_t)v[i] >= cvm__store_nv(m))
                return cvm__error(&m->ctx, CVM_E_INTERNAL, CVM_ENT_TETRAHEDRON, (int64_t)t,
                                  "check: tetrahedron %lu names vertex %ld of %lu",
                                  (unsigned long)t, (long)v[i], (unsigned long)g->nv);
        if (cvm__orient3d(cvm__store_point(m, (size_t)v[0]), cvm__store_point(m, (size_t)v[1]),
                          cvm__store_point(m, (size_t)v[2]), cvm__store_point(m, (size_t)v[3]))
            <= 0)
            return cvm__error(&m->ctx, CVM_E_INTERNAL, CVM_ENT_TETRAHEDRON, (int64_t)t,
                              "check: tetrahedron %lu (%ld, %ld, %ld, %ld) is not positively "
                              "oriented", (unsigned long)t, (long)v[0], (long)v[1], (long)v[2],
                              (long)v[3]);
    }
    if ((s = cvm__mesh3_adjacency(&m->ctx, g->tet, g->ntet, &nbr)))
        return s == CVM_E_INPUT_DEGENERATE ? cvm__error(&m->ctx, CVM_E_INTERNAL, CVM_ENT_NONE, -1,
                                                        "check: %s", cvm_mesh_errmsg(m))
                                           : s;
    for (i = 0; i < 4 * g->ntet && !s; i++) {
        int32_t f[3], o[3];
        if (nbr[i] < 0) {
            nbound++;
            continue;
        }
        cvm__mesh3_face_corners(g->tet + 4 * (i / 4), (int)(i % 4), f);
        cvm__mesh3_face_corners(g->tet + 4 * (nbr[i] / 4), nbr[i] % 4, o);
        if (!cvm__mesh3_faces_opposite(f, o)) {
            s = cvm__error(&m->ctx, CVM_E_INTERNAL, CVM_ENT_TETRAHEDRON, (int64_t)(i / 4),
                           "check: tetrahedra %lu and %ld see their shared face the same way",
                           (unsigned long)(i / 4), (long)(nbr[i] / 4));
            break;
        }
        if (g->delaunay && (int32_t)i < nbr[i]) { /* each interior face once */
            const int32_t *a = g->tet + 4 * (i / 4);
            int32_t e = g->tet[4 * (nbr[i] / 4) + nbr[i] % 4]; /* the far corner */
            const double *P = g->xyz;
            int in = g->w ? cvm__power3d_sos(P + 3 * a[0], P + 3 * a[1], P + 3 * a[2], P + 3 * a[3],
                                             P + 3 * e, g->w[a[0]], g->w[a[1]], g->w[a[2]],
                                             g->w[a[3]], g->w[e], a[0], a[1], a[2], a[3], e)
                          : cvm__insphere_sos(P + 3 * a[0], P + 3 * a[1], P + 3 * a[2],
                                              P + 3 * a[3], P + 3 * e, a[0], a[1], a[2], a[3], e);
            if (in > 0)
                s = cvm__error(&m->ctx, CVM_E_INTERNAL, CVM_ENT_TETRAHEDRON, (int64_t)(i / 4),
                               "check: vertex %ld lies inside the %s of tetrahedron %lu",
                               (long)e, g->w ? "orthosphere" : "circumsphere", (unsigned long)(i / 4));
        }
    }
    /* boundary: every boundary face of the tetrahedra is a listed face, and every listed face
     * is a face of the mesh */
    if (!s && nbound != g->nface && !(g->nface > nbound)) /* internal facets may add more */
        s = cvm__error(&m->ctx, CVM_E_INTERNAL, CVM_ENT_NONE, -1,
                       "check: %lu boundary faces, but %lu listed", (unsigned long)nbound,
                       (unsigned long)g->nface);
    if (!s && !(s = cvm__mesh3_face_index(&m->ctx, g->tet, g->ntet, &index)))
        for (i = 0; i < g->nface; i++)
            if (cvm__mesh3_find_face(index, 4 * g->ntet, g->face[3 * i], g->face[3 * i + 1],
                                     g->face[3 * i + 2]) < 0) {
                s = cvm__error(&m->ctx, CVM_E_INTERNAL, CVM_ENT_FACET, (int64_t)i,
                               "check: boundary face %lu (%ld, %ld, %ld) is not a face of the mesh",
                               (unsigned long)i, (long)g->face[3 * i], (long)g->face[3 * i + 1],
                               (long)g->face[3 * i + 2]);
                break;
            }
    cvm__free(&m->ctx, index);
    cvm__free(&m->ctx, nbr);
    return s;
}

cvm_status cvm__mesh3_measure(double *out, cvm_mesh *m, cvm_measure which)
{
    cvm__mesh3 *g = m->m3;
    int32_t *nbr = NULL;
    double vol = 0, dmin = 180, dmax = 0, remax = 0, emin = INFINITY, emax = 0;
    size_t t, nout = 0, nbt = 0, nbout = 0;
    cvm_status s;
    if (which == CVM_MEASURE_RECOVERY_STEINER) {
        *out = g->have ? (double)(g->n_steiner_boundary + g->n_steiner_interior) : 0;
        return CVM_OK;
    }
    if ((int)which >= (int)CVM_MEASURE_MIN_DUAL_EDGE_RATIO_3D &&
        (int)which <= (int)CVM_MEASURE_MIN_DUAL_EDGE_3D)
        return cvm__mesh3_quality(out, m, which);
    if ((int)which >= (int)CVM_MEASURE_DUAL3_MERGED_PCT &&
        (int)which <= (int)CVM_MEASURE_DUAL3_MERGE_DISSOLVED)
        return cvm__mesh3_merge_measure(out, m, which);
    if (cvm__mesh3_gen3_report(out, m, (int)which) == CVM_OK)
        return CVM_OK;
    if (which == CVM_MEASURE_VANISHED_VERTICES) {
        *out = g->have ? (double)g->n_redundant : 0;
        return CVM_OK;
    }
    if (which != CVM_MEASURE_VOLUME && which != CVM_MEASURE_MIN_DIHEDRAL_DEG &&
        which != CVM_MEASURE_MAX_DIHEDRAL_DEG && which != CVM_MEASURE_MAX_RADIUS_EDGE &&
        which != CVM_MEASURE_CIRCUMCENTRE_OUTSIDE_PCT &&
        which != CVM_MEASURE_CIRCUMCENTRE_OUTSIDE_BOUNDARY_PCT && which != CVM_MEASURE_MIN_EDGE &&
        which != CVM_MEASURE_MAX_EDGE)
        return cvm__error(&m->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "measure %d is not defined for a 3D mesh", (int)which);
    if (!g->have)
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "no mesh to measure: call cvm_mesh_triangulate() first");
    if ((which == CVM_MEASURE_CIRCUMCENTRE_OUTSIDE_BOUNDARY_PCT) &&
        (s = cvm__mesh3_adjacency(&m->ctx, g->tet, g->ntet, &nbr)))
        return s;
    for (t = 0; t < cvm__store_nslots(m); t++) {
        const int32_t *v = cvm__store_cell(m, t);
        const double *P[4], *wv = cvm__store_weights(m);
        double lo, hi, w4[4];
        int i, j, bnd = 0;
        for (i = 0; i < 4; i++) {
            P[i] = cvm__store_point(m, (size_t)v[i]);
            w4[i] = wv ? wv[v[i]] : 0;
            if (nbr && nbr[4 * t + i] < 0)
                bnd = 1;
        }
        vol += cvm__tet_volume(P[0], P[1], P[2], P[3]);
        cvm__tet_dihedral_range_deg(P[0], P[1], P[2], P[3], &lo, &hi);
        dmin = lo < dmin ? lo : dmin;
        dmax = hi > dmax ? hi : dmax;
        lo = cvm__tet_radius_edge(P[0], P[1], P[2], P[3]);
        remax = lo > remax ? lo : remax;
        for (i = 0; i < 4; i++)
            for (j = i + 1; j < 4; j++) {
                double e = sqrt(cvm__dist2_3(P[i], P[j]));
                emin = e < emin ? e : emin;
                emax = e > emax ? e : emax;
            }
        if (which == CVM_MEASURE_CIRCUMCENTRE_OUTSIDE_PCT ||
            which == CVM_MEASURE_CIRCUMCENTRE_OUTSIDE_BOUNDARY_PCT) {
            /* exact; on a face (edge, corner) counts as inside */
            int outside = cvm__tet_centre_inside(P[0], P[1], P[2], P[3], g->w ? w4 : NULL) < 0;
            nout += outside;
            nbt += bnd;
            nbout += bnd && outside;
        }
    }
    cvm__free(&m->ctx, nbr);
    switch (which) {
    case CVM_MEASURE_VOLUME: *out = vol; break;
    case CVM_MEASURE_MIN_DIHEDRAL_DEG: *out = g->ntet ? dmin : 0; break;
    case CVM_MEASURE_MAX_DIHEDRAL_DEG: *out = g->ntet ? dmax : 0; break;
    case CVM_MEASURE_MAX_RADIUS_EDGE: *out = remax; break;
    case CVM_MEASURE_MIN_EDGE: *out = g->ntet ? emin : 0; break;
    case CVM_MEASURE_MAX_EDGE: *out = emax; break;
    case CVM_MEASURE_CIRCUMCENTRE_OUTSIDE_PCT:
        *out = g->ntet ? 100.0 * (double)nout / (double)g->ntet : 0;
        break;
    default: *out = nbt ? 100.0 * (double)nbout / (double)nbt : 0; break;
    }
    return CVM_OK;
}
