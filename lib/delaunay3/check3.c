/* check3.c - exact re-verification of a tetrahedral store: adjacency, orientation, local Delaunay/regular property, convex hull, vertex coverage. */
#include <stdio.h>

#include "delaunay3/delaunay3_internal.h"
#include "geom/geom_internal.h"

#define PT(T, v) ((T)->xyz + 3 * (size_t)(v))

static int vname(const cvm__tet3 *T, int32_t v)
{
    return v == CVM__T3_GHOST ? -1 : (int)T->outid[v];
}

static cvm_status bad_tet(cvm__tet3 *T, size_t t, const char *what)
{
    const int32_t *v = T->tt + 8 * t;
    return cvm__error(T->ctx, CVM_E_INTERNAL, CVM_ENT_TETRAHEDRON, (int64_t)t,
                      "3D check: tetrahedron %zu (vertices %d %d %d %d, -1 = ghost) %s", t,
                      vname(T, v[0]), vname(T, v[1]), vname(T, v[2]), vname(T, v[3]), what);
}

/* Does the other tetrahedron's face g carry the same three vertices as face f of t? */
static int same_face(const int32_t *a, int f, const int32_t *b, int g)
{
    int i, j, found;
    for (i = 0; i < 4; i++) {
        if (i == f)
            continue;
        for (j = 0, found = 0; j < 4; j++)
            found |= j != g && b[j] == a[i];
        if (!found)
            return 0;
    }
    return 1;
}

/* Exact, perturbed: is q in conflict with the finite tetrahedron v? */
static int conflicts(const cvm__tet3 *T, const int32_t *v, int32_t q)
{
    const int32_t *o = T->orig;
    if (!T->w)
        return cvm__insphere_sos(PT(T, v[0]), PT(T, v[1]), PT(T, v[2]), PT(T, v[3]), PT(T, q),
                                 o[v[0]], o[v[1]], o[v[2]], o[v[3]], o[q])
               > 0;
    return cvm__power3d_sos(PT(T, v[0]), PT(T, v[1]), PT(T, v[2]), PT(T, v[3]), PT(T, q),
                            T->w[v[0]], T->w[v[1]], T->w[v[2]], T->w[v[3]], T->w[q], o[v[0]],
                            o[v[1]], o[v[2]], o[v[3]], o[q])
           > 0;
}

static cvm_status check_vertices(cvm__tet3 *T, size_t t)
{
    const int32_t *v = T->tt + 8 * t;
    int k;
    for (k = 0; k < 4; k++) {
        if (v[k] == CVM__T3_GHOST) {
            if (k != 3)
                return bad_tet(T, t, "has the ghost vertex away from position 3");
            continue;
        }
        if (v[k] < 0 || (size_t)v[k] >= T->np)
            return bad_tet(T, t, "names a vertex that does not exist");
        if (T->fate[v[k]] != CVM__T3_VERTEX)
            return bad_tet(T, t, "uses a point that was merged, left out or never inserted");
    }
    if (v[3] != CVM__T3_GHOST
        && !(cvm__orient3d(PT(T, v[0]), PT(T, v[1]), PT(T, v[2]), PT(T, v[3])) > 0.0))
        return bad_tet(T, t, "is not positively oriented (exact orient3d)");
    return CVM_OK;
}

static cvm_status check_face(cvm__tet3 *T, size_t t, int f)
{
    const int32_t *v = T->tt + 8 * t;
    int32_t s = CVM__T3_TN(T, 4 * t + f), g = s & 3;
    size_t u = (size_t)(s >> 2);
    const int32_t *w;
    char what[96];
    if (s < 0 || u >= T->nslot || T->tt[8 * u] == CVM__T3_DEAD) {
        snprintf(what, sizeof what, "has face %d pointing to no live tetrahedron", f);
        return bad_tet(T, t, what);
    }
    w = T->tt + 8 * u;
    if (CVM__T3_TN(T, s) != (int32_t)(4 * t) + f || !same_face(v, f, w, g)) {
        snprintf(what, sizeof what, "has face %d not shared back by tetrahedron %zu", f, u);
        return bad_tet(T, t, what);
    }
    if (v[3] != CVM__T3_GHOST && w[3] != CVM__T3_GHOST && conflicts(T, v, w[g])) {
        snprintf(what, sizeof what,
                 "has face %d not locally %s: vertex %d of tetrahedron %zu is inside", f,
                 T->w ? "regular" : "Delaunay", vname(T, w[g]), u);
        return bad_tet(T, t, what);
    }
    if (v[3] == CVM__T3_GHOST && f < 3) {
        if (w[3] != CVM__T3_GHOST)
            return bad_tet(T, t, "is a ghost with a finite neighbour across a ghost face");
        if (cvm__orient3d(PT(T, v[0]), PT(T, v[1]), PT(T, v[2]), PT(T, w[g])) > 0.0) {
            snprintf(what, sizeof what, "has a hull face seeing hull vertex %d outside: not convex",
                     vname(T, w[g]));
            return bad_tet(T, t, what);
        }
    }
    return CVM_OK;
}

cvm_status cvm__tet3_check(cvm__tet3 *T)
{
    size_t t, i;
    uint8_t *seen;
    cvm_status s = CVM_OK;
    seen = cvm__calloc(T->ctx, T->np + 1, 1);
    if (!seen)
        return cvm__nomem(T->ctx);
    for (t = 0; t < T->nslot && s == CVM_OK; t++) {
        const int32_t *v = T->tt + 8 * t;
        int f;
        if (v[0] == CVM__T3_DEAD)
            continue;
        s = check_vertices(T, t);
        for (f = 0; f < 4 && s == CVM_OK; f++)
            s = check_face(T, t, f);
        for (f = 0; f < 4 && s == CVM_OK; f++)
            if (v[f] >= 0)
                seen[v[f]] = 1;
    }
    for (i = 0; i < T->np && s == CVM_OK; i++)
        if (T->fate[i] == CVM__T3_VERTEX && !seen[i])
            s = cvm__error(T->ctx, CVM_E_INTERNAL, CVM_ENT_VERTEX, T->outid[i],
                           "3D check: vertex %d is in no tetrahedron", (int)T->outid[i]);
    cvm__free(T->ctx, seen);
    return s;
}
