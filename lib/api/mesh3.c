/*
 * mesh3.c - the 3D input of a cvm_mesh and its tetrahedralisation: the
 * Delaunay (or regular) tetrahedralisation of a point set by lib/delaunay3,
 * or the mesh of the inside of a closed surface, recovered by TetGen when the
 * build has it, else carved from the Delaunay tetrahedralisation when every
 * surface triangle is one of its faces.
 */
#include <math.h>
#include <string.h>

#include "api/mesh3_internal.h"
#include "geom/geom_internal.h"
#include "io/surf3_io.h"
#include "surface3/surface3_internal.h"
#include "tetgen/tetgen_shim.h"

static void drop_output(cvm__ctx *ctx, cvm__mesh3 *g)
{
    cvm__free(ctx, g->xyz);
    cvm__free(ctx, g->tet);
    cvm__free(ctx, g->tattr);
    cvm__free(ctx, g->face);
    cvm__free(ctx, g->fmark);
    cvm__free(ctx, g->input_map);
    cvm__free(ctx, g->w);
    g->xyz = g->tattr = g->w = NULL;
    g->tet = g->face = g->fmark = g->input_map = NULL;
    g->nv = g->ntet = g->nface = 0;
    g->have = g->delaunay = 0;
    g->n_dup = g->n_redundant = g->n_steiner_boundary = g->n_steiner_interior = 0;
}

void cvm__mesh3_free(cvm_mesh *m)
{
    if (!m->m3)
        return;
    drop_output(&m->ctx, m->m3);
    cvm__surf3_free(&m->ctx, &m->m3->in);
    cvm__free(&m->ctx, m->m3);
    m->m3 = NULL;
}

cvm_status cvm__mesh3_unsupported(cvm_mesh *m, const char *call)
{
    return cvm__error(&m->ctx, CVM_E_UNSUPPORTED, CVM_ENT_NONE, -1,
                      "%s: the mesh is 3D, and this call is for 2D meshes only in this version",
                      call);
}

/* A new, empty m->m3 (the 2D state of m is forgotten). */
static cvm_status ensure(cvm_mesh *m)
{
    if (m->m3)
        return CVM_OK;
    m->m3 = cvm__calloc(&m->ctx, 1, sizeof *m->m3);
    if (!m->m3)
        return cvm__nomem(&m->ctx);
    cvm__surf3_init(&m->m3->in);
    cvm__mesh_drop_output(m);
    return CVM_OK;
}

static cvm_status check_finite(cvm_mesh *m, const double *x, size_t n, size_t k, cvm_entity kind,
                               const char *what)
{
    size_t i;
    for (i = 0; i < n * k; i++)
        if (!isfinite(x[i]))
            return cvm__error(&m->ctx, CVM_E_INPUT_NONFINITE, kind, (int64_t)(i / k),
                              "%s %lu has a non-finite value", what, (unsigned long)(i / k));
    return CVM_OK;
}

cvm_status cvm__mesh3_set_points(cvm_mesh *m, const double *xyz, size_t n)
{
    cvm__surf3 in;
    size_t i;
    cvm_status s;
    if (n > CVM__T3_MAX_POINTS)
        return cvm__error(&m->ctx, CVM_E_TOO_LARGE, CVM_ENT_INPUT_POINT, -1,
                          "%lu points exceed the 3D limit of %lu", (unsigned long)n,
                          (unsigned long)CVM__T3_MAX_POINTS);
    if ((s = check_finite(m, xyz, n, 3, CVM_ENT_INPUT_POINT, "point")))
        return s;
    cvm__surf3_init(&in);
    for (i = 0; i < n && !s; i++)
        s = cvm__surf3_add_point(&m->ctx, &in, xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    if (!s)
        s = ensure(m);
    if (s) {
        cvm__surf3_free(&m->ctx, &in);
        return s;
    }
    /* holes and regions stay, as in 2D; facets name the old points: gone */
    in.holes = m->m3->in.holes;
    in.nholes = m->m3->in.nholes;
    in.cap_holes = m->m3->in.cap_holes;
    in.regions = m->m3->in.regions;
    in.nregions = m->m3->in.nregions;
    in.cap_regions = m->m3->in.cap_regions;
    m->m3->in.holes = m->m3->in.regions = NULL;
    m->m3->in.nholes = m->m3->in.nregions = 0;
    cvm__surf3_free(&m->ctx, &m->m3->in);
    m->m3->in = in;
    drop_output(&m->ctx, m->m3);
    return CVM_OK;
}

/* Replace the holes (k = 3) or regions (k = 5: x, y, z, attribute, max
 * volume) of the 3D input by a copy of the n items at src: all or nothing. */
static cvm_status replace_seeds(cvm_mesh *m, const double *src, size_t n, size_t k)
{
    cvm__surf3 *in;
    double *p = NULL;
    cvm_status s;
    if ((s = check_finite(m, src, n, k, k == 3 ? CVM_ENT_HOLE : CVM_ENT_REGION,
                          k == 3 ? "hole" : "region")) ||
        (s = ensure(m)))
        return s;
    if (n && !(p = cvm__malloc(&m->ctx, n * k * sizeof *p)))
        return cvm__nomem(&m->ctx);
    if (n)
        memcpy(p, src, n * k * sizeof *p);
    in = &m->m3->in;
    if (k == 3) {
        cvm__free(&m->ctx, in->holes);
        in->holes = p;
        in->nholes = n;
        in->cap_holes = 3 * n; /* in doubles, as cvm__surf3_add_hole() counts */
    } else {
        cvm__free(&m->ctx, in->regions);
        in->regions = p;
        in->nregions = n;
        in->cap_regions = 5 * n;
    }
    drop_output(&m->ctx, m->m3);
    return CVM_OK;
}

cvm_status cvm__mesh3_set_holes(cvm_mesh *m, const double *xyz, size_t n)
{
    return replace_seeds(m, xyz, n, 3);
}

cvm_status cvm__mesh3_set_regions(cvm_mesh *m, const double *r, size_t n)
{
    return replace_seeds(m, r, n, 5);
}

void cvm__mesh3_take_tets(cvm_mesh *m, cvm__mesh3 *b)
{
    cvm__mesh3 *g = m->m3;
    drop_output(&m->ctx, g);
    g->xyz = b->xyz;
    g->nv = b->nv;
    g->tet = b->tet;
    g->ntet = b->ntet;
    g->tattr = b->tattr;
    g->face = b->face;
    g->nface = b->nface;
    g->input_map = b->input_map;
    g->have = 1;
    memset(b, 0, sizeof *b);
}

cvm_status cvm_mesh_set_tetrahedra(cvm_mesh *m, const cvm_index *tets, size_t count,
                                   const double *tet_attr)
{
    cvm__mesh3 *g, b;
    cvm_status s;
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    if (!tets && count)
        return cvm__error(&m->ctx, CVM_E_NULL_ARG, CVM_ENT_NONE, -1, "tets is NULL");
    g = m->m3;
    if (!g || g->in.np == 0)
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "cvm_mesh_set_tetrahedra() needs the 3D points first: "
                          "cvm_mesh_set_points(m, xyz, n, 3) or cvm_mesh_read() of a .node");
    if ((s = cvm__mesh3_tets_build(&m->ctx, g->in.xyz, g->in.np, tets, tet_attr, count, 0, 0,
                                   &b)))
        return s;
    cvm__mesh3_take_tets(m, &b);
    return CVM_OK;
}

/* STEM.ele with the points of STEM.node: both read, the mesh built, then (only
 * then) the handle's input and mesh replaced. */
static cvm_status read_ele(cvm_mesh *m, const char *path)
{
    size_t stem = strlen(path) - 4;
    char *node = cvm__malloc(&m->ctx, stem + 6);
    cvm__surf3 in;
    cvm__tetele te;
    cvm__mesh3 b;
    cvm__reader r;
    cvm_status s;
    cvm__surf3_init(&in);
    memset(&te, 0, sizeof te);
    memset(&b, 0, sizeof b);
    if (!node)
        return cvm__nomem(&m->ctx);
    memcpy(node, path, stem);
    memcpy(node + stem, ".node", 6);
    if (!(s = cvm__file_reader_open(&m->ctx, &r, node))) {
        s = cvm__read_tetnode(&m->ctx, &r, node, &in);
        cvm__file_reader_close(&r);
    }
    if (!s && !(s = cvm__file_reader_open(&m->ctx, &r, path))) {
        s = cvm__read_tetele(&m->ctx, &r, path, in.point_base, in.np, &te);
        cvm__file_reader_close(&r);
    }
    if (!s)
        s = cvm__mesh3_tets_build(&m->ctx, in.xyz, in.np, te.tet, te.attr, te.nt, te.first,
                                  in.point_base, &b);
    if (!s)
        s = ensure(m);
    cvm__tetele_free(&m->ctx, &te);
    cvm__free(&m->ctx, node);
    if (s) {
        cvm__mesh3_tets_free(&m->ctx, &b);
        cvm__surf3_free(&m->ctx, &in);
        return s;
    }
    cvm__surf3_free(&m->ctx, &m->m3->in);
    m->m3->in = in;
    cvm__mesh3_take_tets(m, &b);
    return CVM_OK;
}

cvm_status cvm__mesh3_read(cvm_mesh *m, const char *path)
{
    cvm__surf3 in;
    cvm_status s;
    if (cvm__path_has_ext(path, ".ele"))
        return read_ele(m, path);
    if (cvm__path_has_ext(path, ".node")) {
        cvm__reader r;
        cvm__surf3_init(&in);
        if ((s = cvm__file_reader_open(&m->ctx, &r, path)))
            return s;
        s = cvm__read_tetnode(&m->ctx, &r, path, &in);
        cvm__file_reader_close(&r);
    } else {
        s = cvm__read_surface3_file(&m->ctx, path, &in);
    }
    if (!s)
        s = ensure(m);
    if (s) {
        cvm__surf3_free(&m->ctx, &in);
        return s;
    }
    cvm__surf3_free(&m->ctx, &m->m3->in);
    m->m3->in = in;
    drop_output(&m->ctx, m->m3);
    return CVM_OK;
}

/* The faces of the tets without a neighbour, oriented outwards, marker 0. */
static cvm_status hull_faces(cvm__ctx *ctx, cvm__mesh3 *g, const int32_t *nbr)
{
    size_t i, n = 0;
    for (i = 0; i < 4 * g->ntet; i++)
        n += nbr[i] < 0;
    g->face = cvm__malloc(ctx, (n ? 3 * n : 1) * sizeof *g->face);
    if (!g->face)
        return cvm__nomem(ctx);
    g->nface = 0;
    for (i = 0; i < 4 * g->ntet; i++)
        if (nbr[i] < 0)
            cvm__mesh3_face_corners(g->tet + 4 * (i / 4), (int)(i % 4), g->face + 3 * g->nface++);
    return CVM_OK;
}

/* Delaunay (w NULL) or regular tetrahedralisation of the n points xyz into g:
 * vertices are the points less duplicates, in input order. */
static cvm_status tetrahedralise_points(cvm_mesh *m, const double *xyz, const double *w, size_t n, int32_t **nbr_out)
{
    cvm__mesh3 *g = m->m3;
    cvm__tet3 T;
    uint8_t *fate = NULL;
    int32_t *into = NULL, *nbr = NULL;
    size_t i, k;
    cvm_status s;
    cvm__tet3_init(&T, &m->ctx);
    T.threads = (int)cvm__opt(m, CVM_OPT_THREADS); /* parallel insertion, same output */
    s = cvm__tet3_build(&T, xyz, w, n, (uint64_t)cvm__opt(m, CVM_OPT_SEED));
    if (!s && T.n_dup && cvm__opt(m, CVM_OPT_REJECT_DUPLICATES) != 0)
        s = cvm__error(&m->ctx, CVM_E_INPUT_DUPLICATE, CVM_ENT_INPUT_POINT, T.dup_first[1],
                       "point %lld duplicates point %lld", (long long)T.dup_first[1],
                       (long long)T.dup_first[0]);
    if (!s) {
        fate = cvm__malloc(&m->ctx, n * sizeof *fate);
        into = cvm__malloc(&m->ctx, n * sizeof *into);
        g->input_map = cvm__malloc(&m->ctx, n * sizeof *g->input_map);
        g->xyz = cvm__malloc(&m->ctx, 3 * n * sizeof *g->xyz);
        g->tet = cvm__malloc(&m->ctx, (T.n_finite ? 4 * T.n_finite : 1) * sizeof *g->tet);
        if (w)
            g->w = cvm__malloc(&m->ctx, n * sizeof *g->w);
        if (!fate || !into || !g->input_map || !g->xyz || !g->tet || (w && !g->w))
            s = cvm__nomem(&m->ctx);
    }
    if (!s)
        s = cvm__tet3_copy_tets(&T, g->tet);
    if (!s) {
        cvm__tet3_point_fates(&T, fate, into);
        for (i = 0, k = 0; i < n; i++) {
            if (fate[i] == CVM__T3_DUPLICATE)
                continue;
            g->input_map[i] = (int32_t)k;
            memcpy(g->xyz + 3 * k, xyz + 3 * i, 3 * sizeof *xyz);
            if (w)
                g->w[k] = w[i];
            k++;
        }
        for (i = 0; i < n; i++)
            if (fate[i] == CVM__T3_DUPLICATE)
                g->input_map[i] = g->input_map[into[i]];
        g->nv = k;
        g->ntet = T.n_finite;
        for (i = 0; i < 4 * g->ntet; i++)
            g->tet[i] = g->input_map[g->tet[i]];
        g->n_dup = T.n_dup;
        g->n_redundant = T.n_redundant;
        s = cvm__mesh3_adjacency(&m->ctx, g->tet, g->ntet, &nbr);
    }
    cvm__free(&m->ctx, fate);
    cvm__free(&m->ctx, into);
    cvm__tet3_free(&T);
    if (!s && nbr_out)
        *nbr_out = nbr;
    else
        cvm__free(&m->ctx, nbr);
    return s;
}

/* Exactly inside or on tet t (positively oriented). */
static int in_tet(const cvm__mesh3 *g, size_t t, const double *p)
{
    const int32_t *v = g->tet + 4 * t;
    const double *a = g->xyz + 3 * v[0], *b = g->xyz + 3 * v[1], *c = g->xyz + 3 * v[2],
                 *d = g->xyz + 3 * v[3];
    return cvm__orient3d(p, b, c, d) >= 0 && cvm__orient3d(a, p, c, d) >= 0 &&
           cvm__orient3d(a, b, p, d) >= 0 && cvm__orient3d(a, b, c, p) >= 0;
}

/* Without TetGen: the surface's triangles must all be faces of the Delaunay
 * tetrahedralisation; then flood from the hull and the hole points without
 * crossing them, and give the regions their attributes. */
static cvm_status carve_delaunay(cvm_mesh *m, const cvm__surf3_tris *st)
{
    cvm__mesh3 *g = m->m3;
    cvm__surf3 *in = &g->in;
    int32_t *nbr = NULL, *stack = NULL;
    uint8_t *wall = NULL, *gone = NULL;
    double *attr = NULL;
    cvm__face_key *index = NULL;
    size_t i, nst = 0, k, nkeep;
    cvm_status s = tetrahedralise_points(m, in->xyz, NULL, in->np, &nbr);
    if (s)
        return s;
    wall = cvm__calloc(&m->ctx, 4 * g->ntet + 1, 1);
    gone = cvm__calloc(&m->ctx, g->ntet + 1, 1);
    stack = cvm__malloc(&m->ctx, (g->ntet + 1) * sizeof *stack);
    if (!wall || !gone || !stack) {
        s = cvm__nomem(&m->ctx);
        goto done;
    }
    if ((s = cvm__mesh3_face_index(&m->ctx, g->tet, g->ntet, &index)))
        goto done;
    for (k = 0; k < st->nt; k++) {
        int32_t slot = cvm__mesh3_find_face(index, 4 * g->ntet, g->input_map[st->tri[3 * k]],
                                            g->input_map[st->tri[3 * k + 1]],
                                            g->input_map[st->tri[3 * k + 2]]);
        if (slot >= 0) {
            wall[slot] = 1;
            if (nbr[slot] >= 0)
                wall[nbr[slot]] = 1;
        } else {
            s = cvm__error(&m->ctx, CVM_E_UNSUPPORTED, CVM_ENT_FACET, (int64_t)st->tpoly[k],
                           "%s %ld of %s is not a face of the Delaunay tetrahedralisation of its "
                           "points, and this build has no boundary recovery (build with TETGEN=1)",
                           in->facet_word, (long)(st->tpoly[k] + in->facet_base),
                           in->file ? in->file : "the input");
            goto done;
        }
    }
    /* flood the outside from every tet on the hull, then from each hole point */
    for (i = 0; i < 4 * g->ntet; i++)
        if (nbr[i] < 0 && !wall[i] && !gone[i / 4]) {
            gone[i / 4] = 1;
            stack[nst++] = (int32_t)(i / 4);
        }
    for (k = 0; k <= in->nholes; k++) {
        while (nst) {
            int32_t t = stack[--nst];
            int f;
            for (f = 0; f < 4; f++) {
                int32_t o = nbr[4 * t + f];
                if (o >= 0 && !wall[4 * t + f] && !gone[o / 4]) {
                    gone[o / 4] = 1;
                    stack[nst++] = o / 4;
                }
            }
        }
        if (k < in->nholes)
            for (i = 0; i < g->ntet; i++)
                if (!gone[i] && in_tet(g, i, in->holes + 3 * k)) {
                    gone[i] = 1;
                    stack[nst++] = (int32_t)i;
                    break;
                }
    }
    if (in->nregions) {
        attr = cvm__calloc(&m->ctx, g->ntet + 1, sizeof *attr);
        if (!attr) {
            s = cvm__nomem(&m->ctx);
            goto done;
        }
        for (k = 0; k < in->nregions; k++) {
            uint8_t *seen = wall; /* reuse: bit 2 marks a tet reached by this region */
            for (i = 0; i < g->ntet; i++)
                if (!gone[i] && in_tet(g, i, in->regions + 5 * k))
                    break;
            if (i == g->ntet)
                continue;
            nst = 0;
            stack[nst++] = (int32_t)i;
            seen[4 * i] |= 2;
            while (nst) {
                int32_t t = stack[--nst];
                int f;
                attr[t] = in->regions[5 * k + 3];
                for (f = 0; f < 4; f++) {
                    int32_t o = nbr[4 * t + f];
                    if (o >= 0 && !(wall[4 * t + f] & 1) && !gone[o / 4] && !(seen[o & ~3] & 2)) {
                        seen[o & ~3] |= 2;
                        stack[nst++] = o / 4;
                    }
                }
            }
        }
    }
    /* keep the tets inside; boundary faces: the surface's triangles */
    for (i = 0, nkeep = 0; i < g->ntet; i++)
        if (!gone[i]) {
            memmove(g->tet + 4 * nkeep, g->tet + 4 * i, 4 * sizeof *g->tet);
            if (attr)
                attr[nkeep] = attr[i];
            nkeep++;
        }
    if (nkeep == 0) {
        s = cvm__error(&m->ctx, CVM_E_INPUT_EMPTY, CVM_ENT_NONE, -1,
                       "nothing is left inside the surface (the holes cover the domain)");
        goto done;
    }
    g->ntet = nkeep;
    g->tattr = attr;
    attr = NULL;
    g->face = cvm__malloc(&m->ctx, 3 * st->nt * sizeof *g->face);
    g->fmark = cvm__malloc(&m->ctx, st->nt * sizeof *g->fmark);
    if (!g->face || !g->fmark) {
        s = cvm__nomem(&m->ctx);
        goto done;
    }
    for (k = 0; k < st->nt; k++) {
        int j;
        for (j = 0; j < 3; j++)
            g->face[3 * k + j] = g->input_map[st->tri[3 * k + j]];
        g->fmark[k] = in->fmark[in->pfacet[st->tpoly[k]]];
    }
    g->nface = st->nt;
    g->delaunay = 0;
done:
    cvm__free(&m->ctx, index);
    cvm__free(&m->ctx, nbr);
    cvm__free(&m->ctx, stack);
    cvm__free(&m->ctx, wall);
    cvm__free(&m->ctx, gone);
    cvm__free(&m->ctx, attr);
    return s;
}

static cvm_status recover_with_tetgen(cvm_mesh *m)
{
    cvm__mesh3 *g = m->m3;
    cvm__tet3_out out;
    size_t i;
    cvm_status s;
    memset(&out, 0, sizeof out);
    if ((s = cvm__tetgen_recover(&m->ctx, &g->in, &out)))
        return s;
    g->xyz = out.xyz;
    g->nv = out.np;
    g->tet = out.tet;
    g->ntet = out.ntet;
    g->tattr = out.tattr;
    g->face = out.face;
    g->fmark = out.fmark;
    g->nface = out.nface;
    g->n_steiner_boundary = out.n_steiner_boundary;
    g->n_steiner_interior = out.n_steiner_interior;
    g->input_map = cvm__malloc(&m->ctx, (g->in.np ? g->in.np : 1) * sizeof *g->input_map);
    if (!g->input_map)
        return cvm__nomem(&m->ctx);
    for (i = 0; i < g->in.np; i++)
        g->input_map[i] = (int32_t)i;
    return CVM_OK;
}

static cvm_status recover(cvm_mesh *m)
{
    cvm__mesh3 *g = m->m3;
    cvm__surf3_tris st;
    size_t removed;
    cvm_status s;
    memset(&st, 0, sizeof st);
    if ((s = cvm__surf3_validate(&m->ctx, &g->in, CVM__SURF3_ALLOW_INTERNAL, &st)))
        return s;
    s = cvm__tetgen_available() ? recover_with_tetgen(m) : carve_delaunay(m, &st);
    /* without hole points, a shell whose triangles face into it bounds a hole */
    if (!s)
        s = cvm__mesh3_carve_by_orientation(&m->ctx, g, st.tri, st.nt, &removed);
    cvm__surf3_tris_free(&m->ctx, &st);
    return s;
}

cvm_status cvm__mesh3_triangulate(cvm_mesh *m)
{
    cvm__mesh3 *g = m->m3;
    int32_t *nbr = NULL;
    cvm_status s;
    drop_output(&m->ctx, g);
    cvm__run_begin(&m->ctx, cvm__opt(m, CVM_OPT_TIME_LIMIT_S));
    if (g->in.npoly) {
        s = recover(m);
    } else {
        s = tetrahedralise_points(m, g->in.xyz, NULL, g->in.np, &nbr);
        if (!s) {
            g->delaunay = 1;
            s = hull_faces(&m->ctx, g, nbr);
        }
        cvm__free(&m->ctx, nbr);
    }
    if (s) {
        drop_output(&m->ctx, g);
        return s;
    }
    g->have = 1;
    return CVM_OK;
}

cvm_status cvm__mesh3_set_weights(cvm_mesh *m, const double *w, size_t n)
{
    cvm__mesh3 *g = m->m3;
    double *xyz;
    int32_t *nbr = NULL;
    size_t nv = g->nv;
    cvm_status s;
    if (!g->have)
        return cvm__error(&m->ctx, CVM_E_STATE, CVM_ENT_NONE, -1,
                          "weights are set on the vertices of a mesh: call cvm_mesh_triangulate() first");
    if (!g->delaunay)
        return cvm__error(&m->ctx, CVM_E_UNSUPPORTED, CVM_ENT_NONE, -1,
                          "weights on a tetrahedralised surface (constrained) are not supported in "
                          "this version: only on a point set's Delaunay tetrahedralisation");
    if (n != nv)
        return cvm__error(&m->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "%lu weights for %lu vertices", (unsigned long)n, (unsigned long)nv);
    if ((s = check_finite(m, w, n, 1, CVM_ENT_VERTEX, "weight of vertex")))
        return s;
    {
        /* the vertices are distinct points: the rebuild keeps their ids, and the
         * input points keep their map */
        int32_t *map = g->input_map;
        xyz = g->xyz;
        g->xyz = NULL;
        g->input_map = NULL;
        drop_output(&m->ctx, g);
        s = tetrahedralise_points(m, xyz, w, nv, &nbr);
        if (!s) {
            cvm__free(&m->ctx, g->input_map);
            g->input_map = map;
            map = NULL;
            g->delaunay = 1;
            s = hull_faces(&m->ctx, g, nbr);
        }
        cvm__free(&m->ctx, map);
        cvm__free(&m->ctx, xyz);
    }
    cvm__free(&m->ctx, nbr);
    if (s) {
        drop_output(&m->ctx, g);
        return s;
    }
    g->have = 1;
    return CVM_OK;
}
