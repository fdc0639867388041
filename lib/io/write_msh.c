/*
 * write_msh.c - writes a mesh as Gmsh MSH 4.1 ASCII.
 *
 * Entities: one surface per regional attribute (increasing; a mesh without
 * attributes has one surface, physical group 2D tag 1 "domain"; otherwise
 * surface s is physical group s named "region_A" for its attribute A). The
 * constrained edges (segments) are line elements (type 1) on one curve per
 * distinct segment marker in increasing order; a curve whose marker m is
 * positive belongs to the physical group 1D tag m, named "marker_m" (Gmsh's
 * physical tags are positive, so a marker <= 0 gets no group). A name in
 * mo->names replaces these: (1, m) names curve group m, (2, A) the surface of
 * integer attribute A, (2, 1) the one surface of a mesh without attributes.
 * Nodes are classified as Gmsh does: a segment vertex where curves meet or a chain ends
 * is a point entity, a vertex inside one curve belongs to that curve, and the
 * others to the surface of their lowest-numbered triangle. Node tags are vertex
 * id + 1; element tags number the lines first (curve by curve), then the
 * triangles in id order.
 */
#include <stdlib.h>
#include <string.h>

#include "formats.h"

typedef struct curves {
    int32_t *marker;   /* ncurve distinct markers, increasing */
    size_t ncurve;
    size_t *start;     /* ncurve + 1 offsets into order */
    size_t *order;     /* segment ids grouped by curve, in id order within a curve */
} curves;

/* Surfaces, node classification and the node blocks. */
typedef struct layout {
    double *sattr;     /* nsurf distinct attributes, increasing; NULL: one surface */
    size_t nsurf;
    size_t *tsurf;     /* surface of each triangle */
    size_t npoint;     /* point entities (corner nodes), tags in node order */
    size_t nblock;     /* npoint + ncurve + nsurf node blocks, some empty */
    size_t *block;     /* block of each node */
    size_t *bstart;    /* nblock + 1 offsets into border */
    size_t *border;    /* node ids grouped by block, in id order */
    size_t *bound;     /* (surface, curve) pairs bounding surfaces, 2 per pair */
    size_t nbound;
} layout;

static int32_t seg_marker(const cvm__mesh_out *mo, size_t k)
{
    return mo->smark ? mo->smark[k] : 1;
}

static int cmp_i32(const void *a, const void *b)
{
    int32_t x = *(const int32_t *)a, y = *(const int32_t *)b;
    return (x > y) - (x < y);
}

static int cmp_f64(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static int cmp_pair(const void *a, const void *b)
{
    const size_t *x = (const size_t *)a, *y = (const size_t *)b;
    if (x[0] != y[0])
        return (x[0] > y[0]) - (x[0] < y[0]);
    return (x[1] > y[1]) - (x[1] < y[1]);
}

/* The vertex ids of cell t and their number (triangles, or the mixed cells of mo->coff). */
static const int32_t *cell_of(const cvm__mesh_out *mo, size_t t, size_t *n)
{
    if (!mo->coff) {
        *n = 3;
        return mo->tri + 3 * t;
    }
    *n = (size_t)(mo->coff[t + 1] - mo->coff[t]);
    return mo->tri + mo->coff[t];
}

/* (min, max, curve) of a segment, for looking edges up. */
typedef struct seg_key {
    int32_t a, b;
    size_t curve;
} seg_key;

static int cmp_seg_key(const void *p, const void *q)
{
    const seg_key *x = (const seg_key *)p, *y = (const seg_key *)q;
    if (x->a != y->a)
        return (x->a > y->a) - (x->a < y->a);
    return (x->b > y->b) - (x->b < y->b);
}

static size_t curve_of(const curves *c, int32_t m)
{
    size_t lo = 0, hi = c->ncurve;
    while (hi - lo > 1) {
        size_t mid = (lo + hi) / 2;
        if (c->marker[mid] <= m)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

static size_t surface_of(const layout *l, double a)
{
    size_t lo = 0, hi = l->nsurf;
    while (hi - lo > 1) {
        size_t mid = (lo + hi) / 2;
        if (l->sattr[mid] <= a)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

static void curves_free(cvm__ctx *ctx, curves *c)
{
    cvm__free(ctx, c->marker);
    cvm__free(ctx, c->start);
    cvm__free(ctx, c->order);
}

static void layout_free(cvm__ctx *ctx, layout *l)
{
    cvm__free(ctx, l->sattr);
    cvm__free(ctx, l->tsurf);
    cvm__free(ctx, l->block);
    cvm__free(ctx, l->bstart);
    cvm__free(ctx, l->border);
    cvm__free(ctx, l->bound);
}

/* Group the segments by marker (a counting sort, so ties keep id order). */
static cvm_status curves_build(cvm__ctx *ctx, const cvm__mesh_out *mo, curves *c)
{
    size_t k, n = mo->nseg;
    memset(c, 0, sizeof *c);
    if (n == 0)
        return CVM_OK;
    c->marker = cvm__malloc(ctx, n * sizeof *c->marker);
    c->start = cvm__calloc(ctx, n + 1, sizeof *c->start);
    c->order = cvm__malloc(ctx, n * sizeof *c->order);
    if (!c->marker || !c->start || !c->order) {
        curves_free(ctx, c);
        return cvm__nomem(ctx);
    }
    for (k = 0; k < n; k++)
        c->marker[k] = seg_marker(mo, k);
    qsort(c->marker, n, sizeof *c->marker, cmp_i32);
    c->ncurve = 1;
    for (k = 1; k < n; k++)
        if (c->marker[k] != c->marker[c->ncurve - 1])
            c->marker[c->ncurve++] = c->marker[k];
    for (k = 0; k < n; k++)
        c->start[curve_of(c, seg_marker(mo, k)) + 1]++;
    for (k = 0; k < c->ncurve; k++)
        c->start[k + 1] += c->start[k];
    for (k = 0; k < n; k++) {
        size_t i = curve_of(c, seg_marker(mo, k));
        c->order[c->start[i]++] = k;
    }
    for (k = c->ncurve; k > 0; k--)
        c->start[k] = c->start[k - 1];
    c->start[0] = 0;
    return CVM_OK;
}

/* The surfaces: distinct attributes, and each triangle's. */
static cvm_status surfaces_build(cvm__ctx *ctx, const cvm__mesh_out *mo, layout *l)
{
    size_t t;
    l->nsurf = 1;
    l->tsurf = cvm__calloc(ctx, mo->nt ? mo->nt : 1, sizeof *l->tsurf);
    if (!l->tsurf)
        return cvm__nomem(ctx);
    if (!mo->tattr || mo->nt == 0)
        return CVM_OK;
    l->sattr = cvm__malloc(ctx, mo->nt * sizeof *l->sattr);
    if (!l->sattr)
        return cvm__nomem(ctx);
    memcpy(l->sattr, mo->tattr, mo->nt * sizeof *l->sattr);
    qsort(l->sattr, mo->nt, sizeof *l->sattr, cmp_f64);
    for (t = 1; t < mo->nt; t++)
        if (l->sattr[t] != l->sattr[l->nsurf - 1])
            l->sattr[l->nsurf++] = l->sattr[t];
    for (t = 0; t < mo->nt; t++)
        l->tsurf[t] = surface_of(l, mo->tattr[t]);
    return CVM_OK;
}

/* Classify the nodes (point, curve or surface) and group them into blocks;
 * collect the curves bounding each surface. */
static cvm_status nodes_build(cvm__ctx *ctx, const cvm__mesh_out *mo, const curves *c, layout *l)
{
    size_t nv = mo->nv, k, t, j, i, *ptag = NULL;
    int32_t *nseg = NULL, *curve = NULL;
    seg_key *keys = NULL;
    cvm_status s = CVM_OK;
    nseg = cvm__calloc(ctx, nv ? nv : 1, sizeof *nseg);
    curve = cvm__malloc(ctx, (nv ? nv : 1) * sizeof *curve);
    ptag = cvm__calloc(ctx, nv ? nv : 1, sizeof *ptag);
    l->block = cvm__malloc(ctx, (nv ? nv : 1) * sizeof *l->block);
    l->border = cvm__malloc(ctx, (nv ? nv : 1) * sizeof *l->border);
    keys = cvm__malloc(ctx, (mo->nseg ? mo->nseg : 1) * sizeof *keys);
    l->bound = cvm__malloc(ctx, 2 * ((mo->coff ? (size_t)mo->coff[mo->nt] : 3 * mo->nt) + 1) *
                                    sizeof *l->bound);
    if (!nseg || !curve || !ptag || !l->block || !l->border || !keys || !l->bound) {
        s = cvm__nomem(ctx);
        goto done;
    }
    for (k = 0; k < nv; k++)
        curve[k] = -1;
    /* a vertex on two curves, or not inside a chain, is a corner (-2) */
    for (i = 0; i < c->ncurve; i++)
        for (j = c->start[i]; j < c->start[i + 1]; j++) {
            const int32_t *sg = mo->seg + 2 * c->order[j];
            int e;
            keys[j].a = sg[0] < sg[1] ? sg[0] : sg[1];
            keys[j].b = sg[0] < sg[1] ? sg[1] : sg[0];
            keys[j].curve = i;
            for (e = 0; e < 2; e++) {
                int32_t v = sg[e];
                nseg[v]++;
                if (curve[v] == -1)
                    curve[v] = (int32_t)i;
                else if (curve[v] != (int32_t)i)
                    curve[v] = -2;
            }
        }
    qsort(keys, mo->nseg, sizeof *keys, cmp_seg_key);
    l->npoint = 0;
    for (k = 0; k < nv; k++)
        if (nseg[k] && (curve[k] == -2 || nseg[k] != 2))
            ptag[k] = ++l->npoint;
    l->nblock = l->npoint + c->ncurve + l->nsurf;
    l->bstart = cvm__calloc(ctx, l->nblock + 1, sizeof *l->bstart);
    if (!l->bstart) {
        s = cvm__nomem(ctx);
        goto done;
    }
    for (k = 0; k < nv; k++)
        l->block[k] = SIZE_MAX;
    for (t = mo->nt; t-- > 0;) { /* the lowest triangle last: it wins */
        size_t n;
        const int32_t *cv = cell_of(mo, t, &n);
        for (j = 0; j < n; j++)
            l->block[cv[j]] = l->npoint + c->ncurve + l->tsurf[t];
    }
    for (k = 0; k < nv; k++) {
        if (ptag[k])
            l->block[k] = ptag[k] - 1;
        else if (nseg[k])
            l->block[k] = l->npoint + (size_t)curve[k];
        else if (l->block[k] == SIZE_MAX)
            l->block[k] = l->npoint + c->ncurve; /* in no triangle: the first surface */
        l->bstart[l->block[k] + 1]++;
    }
    for (k = 0; k < l->nblock; k++)
        l->bstart[k + 1] += l->bstart[k];
    for (k = 0; k < nv; k++)
        l->border[l->bstart[l->block[k]]++] = k;
    for (k = l->nblock; k > 0; k--)
        l->bstart[k] = l->bstart[k - 1];
    l->bstart[0] = 0;
    /* curves bounding each surface: the segments among its triangles' edges */
    l->nbound = 0;
    for (t = 0; t < mo->nt && mo->nseg; t++) {
        size_t n;
        const int32_t *cv = cell_of(mo, t, &n);
        for (j = 0; j < n; j++) {
            int32_t a = cv[j], b = cv[(j + 1) % n];
            seg_key key, *hit;
            key.a = a < b ? a : b;
            key.b = a < b ? b : a;
            hit = bsearch(&key, keys, mo->nseg, sizeof *keys, cmp_seg_key);
            if (hit) {
                l->bound[2 * l->nbound] = l->tsurf[t];
                l->bound[2 * l->nbound + 1] = hit->curve;
                l->nbound++;
            }
        }
    }
    qsort(l->bound, l->nbound, 2 * sizeof *l->bound, cmp_pair);
    for (k = 0, j = 0; k < l->nbound; k++)
        if (j == 0 || cmp_pair(l->bound + 2 * k, l->bound + 2 * (j - 1)) != 0) {
            l->bound[2 * j] = l->bound[2 * k];
            l->bound[2 * j + 1] = l->bound[2 * k + 1];
            j++;
        }
    l->nbound = j;
done:
    cvm__free(ctx, nseg);
    cvm__free(ctx, curve);
    cvm__free(ctx, ptag);
    cvm__free(ctx, keys);
    return s;
}

static void bbox(cvm__writer *w, const double *lo, const double *hi)
{
    cvm__writer_double(w, lo[0]);
    cvm__writer_puts(w, " ");
    cvm__writer_double(w, lo[1]);
    cvm__writer_puts(w, " 0 ");
    cvm__writer_double(w, hi[0]);
    cvm__writer_puts(w, " ");
    cvm__writer_double(w, hi[1]);
    cvm__writer_puts(w, " 0 ");
}

static void extend(double *lo, double *hi, const double *p)
{
    int d;
    for (d = 0; d < 2; d++) {
        if (p[d] < lo[d])
            lo[d] = p[d];
        if (p[d] > hi[d])
            hi[d] = p[d];
    }
}

/* The name of physical group (dim, tag) in mo's table, or NULL. */
static const char *name_of(const cvm__mesh_out *mo, int32_t dim, int32_t tag)
{
    size_t k;
    for (k = 0; k < mo->nnames; k++)
        if (mo->names[k].dim == dim && mo->names[k].tag == tag)
            return mo->names[k].name;
    return NULL;
}

/* The table's name for region attribute a (an integer), or NULL. */
static const char *region_name(const cvm__mesh_out *mo, double a)
{
    if (!(a >= INT32_MIN && a <= INT32_MAX) || a != (double)(int32_t)a)
        return NULL;
    return name_of(mo, 2, (int32_t)a);
}

static void physical_names(cvm__writer *w, const cvm__mesh_out *mo, const curves *c,
                           const layout *l)
{
    size_t i, n = l->nsurf;
    const char *name;
    for (i = 0; i < c->ncurve; i++)
        n += c->marker[i] > 0;
    cvm__writer_printf(w, "$PhysicalNames\n%lu\n", (unsigned long)n);
    for (i = 0; i < c->ncurve; i++) {
        if (c->marker[i] <= 0)
            continue;
        if ((name = name_of(mo, 1, c->marker[i])))
            cvm__writer_printf(w, "1 %ld \"%s\"\n", (long)c->marker[i], name);
        else
            cvm__writer_printf(w, "1 %ld \"marker_%ld\"\n", (long)c->marker[i], (long)c->marker[i]);
    }
    if (!l->sattr) {
        name = name_of(mo, 2, 1);
        cvm__writer_printf(w, "2 1 \"%s\"\n", name ? name : "domain");
    } else {
        for (i = 0; i < l->nsurf; i++) {
            if ((name = region_name(mo, l->sattr[i]))) {
                cvm__writer_printf(w, "2 %lu \"%s\"\n", (unsigned long)i + 1, name);
                continue;
            }
            cvm__writer_printf(w, "2 %lu \"region_", (unsigned long)i + 1);
            cvm__writer_double(w, l->sattr[i]);
            cvm__writer_puts(w, "\"\n");
        }
    }
    cvm__writer_puts(w, "$EndPhysicalNames\n");
}

static void entities(cvm__writer *w, const cvm__mesh_out *mo, const curves *c, const layout *l)
{
    double lo[2] = {0, 0}, hi[2] = {0, 0};
    size_t i, j, k, b;
    cvm__writer_printf(w, "$Entities\n%lu %lu %lu 0\n", (unsigned long)l->npoint,
                       (unsigned long)c->ncurve, (unsigned long)l->nsurf);
    for (i = 0; i < l->npoint; i++) {
        const double *p = mo->xy + 2 * l->border[l->bstart[i]];
        cvm__writer_printf(w, "%lu ", (unsigned long)i + 1);
        cvm__writer_double(w, p[0]);
        cvm__writer_putc(w, ' ');
        cvm__writer_double(w, p[1]);
        cvm__writer_puts(w, " 0 0\n");
    }
    for (i = 0; i < c->ncurve; i++) {
        const int32_t *s = mo->seg + 2 * c->order[c->start[i]];
        lo[0] = hi[0] = mo->xy[2 * (size_t)s[0]];
        lo[1] = hi[1] = mo->xy[2 * (size_t)s[0] + 1];
        for (j = c->start[i]; j < c->start[i + 1]; j++) {
            s = mo->seg + 2 * c->order[j];
            extend(lo, hi, mo->xy + 2 * (size_t)s[0]);
            extend(lo, hi, mo->xy + 2 * (size_t)s[1]);
        }
        cvm__writer_printf(w, "%lu ", (unsigned long)i + 1);
        bbox(w, lo, hi);
        if (c->marker[i] > 0)
            cvm__writer_printf(w, "1 %ld 0\n", (long)c->marker[i]);
        else
            cvm__writer_puts(w, "0 0\n");
    }
    for (i = 0, b = 0; i < l->nsurf; i++) {
        size_t t, n = 0, first = 1;
        lo[0] = lo[1] = hi[0] = hi[1] = 0;
        for (t = 0; t < mo->nt; t++) {
            if (l->tsurf[t] != i)
                continue;
            size_t nc;
            const int32_t *cv = cell_of(mo, t, &nc);
            for (k = 0; k < nc; k++) {
                const double *p = mo->xy + 2 * (size_t)cv[k];
                if (first) {
                    lo[0] = hi[0] = p[0];
                    lo[1] = hi[1] = p[1];
                    first = 0;
                }
                extend(lo, hi, p);
            }
        }
        if (mo->nt == 0)
            for (k = 0; k < mo->nv; k++) {
                if (k == 0) {
                    lo[0] = hi[0] = mo->xy[0];
                    lo[1] = hi[1] = mo->xy[1];
                }
                extend(lo, hi, mo->xy + 2 * k);
            }
        cvm__writer_printf(w, "%lu ", (unsigned long)i + 1);
        bbox(w, lo, hi);
        while (b + n < l->nbound && l->bound[2 * (b + n)] == i)
            n++;
        /* one surface bounded by every curve, as a mesh without regions always was */
        if (l->nsurf == 1)
            n = c->ncurve;
        cvm__writer_printf(w, "1 %lu %lu", (unsigned long)i + 1, (unsigned long)n);
        for (k = 0; k < n; k++)
            cvm__writer_printf(w, " %lu", (unsigned long)(l->nsurf == 1 ? k : l->bound[2 * (b + k) + 1]) + 1);
        if (l->nsurf > 1)
            b += n;
        cvm__writer_putc(w, '\n');
    }
    cvm__writer_puts(w, "$EndEntities\n");
}

static void nodes(cvm__writer *w, const cvm__mesh_out *mo, const curves *c, const layout *l)
{
    size_t b, j, nb = 0, n = mo->nv;
    for (b = 0; b < l->nblock; b++)
        nb += l->bstart[b + 1] > l->bstart[b];
    cvm__writer_printf(w, "$Nodes\n%lu %lu %lu %lu\n", (unsigned long)nb, (unsigned long)n,
                       (unsigned long)(n ? 1 : 0), (unsigned long)n);
    for (b = 0; b < l->nblock; b++) {
        size_t first = l->bstart[b], last = l->bstart[b + 1];
        int dim = b < l->npoint ? 0 : b < l->npoint + c->ncurve ? 1 : 2;
        size_t tag = dim == 0 ? b + 1 : dim == 1 ? b - l->npoint + 1 : b - l->npoint - c->ncurve + 1;
        if (first == last)
            continue;
        cvm__writer_printf(w, "%d %lu 0 %lu\n", dim, (unsigned long)tag,
                           (unsigned long)(last - first));
        for (j = first; j < last; j++) {
            cvm__writer_ulong(w, l->border[j] + 1);
            cvm__writer_putc(w, '\n');
        }
        for (j = first; j < last; j++) {
            const double *p = mo->xy + 2 * l->border[j];
            cvm__writer_double(w, p[0]);
            cvm__writer_putc(w, ' ');
            cvm__writer_double(w, p[1]);
            cvm__writer_write(w, " 0\n", 3);
        }
    }
    cvm__writer_puts(w, "$EndNodes\n");
}

/* The Gmsh type of cell t: 2 triangle, 3 quadrangle. */
static int gmsh_type(const cvm__mesh_out *mo, size_t t)
{
    return mo->coff && mo->coff[t + 1] - mo->coff[t] == 4 ? 3 : 2;
}

static void elements(cvm__writer *w, const cvm__mesh_out *mo, const curves *c, const layout *l)
{
    size_t i, j, t, s, tag = 1, total = mo->nseg + mo->nt, nsb = 0;
    int type;
    /* one block per surface and cell type present (triangles, then quadrangles); a mesh without
     * cells keeps one empty triangle block */
    for (s = 0; s < l->nsurf; s++)
        for (type = 2; type <= 3; type++) {
            for (t = 0; t < mo->nt && (l->tsurf[t] != s || gmsh_type(mo, t) != type); t++)
                ;
            nsb += t < mo->nt || (s == 0 && type == 2 && mo->nt == 0);
        }
    cvm__writer_printf(w, "$Elements\n%lu %lu %lu %lu\n", (unsigned long)(c->ncurve + nsb),
                       (unsigned long)total, (unsigned long)(total ? 1 : 0), (unsigned long)total);
    for (i = 0; i < c->ncurve; i++) {
        cvm__writer_printf(w, "1 %lu 1 %lu\n", (unsigned long)i + 1,
                           (unsigned long)(c->start[i + 1] - c->start[i]));
        for (j = c->start[i]; j < c->start[i + 1]; j++) {
            const int32_t *sg = mo->seg + 2 * c->order[j];
            cvm__writer_ulong(w, tag++);
            cvm__writer_putc(w, ' ');
            cvm__writer_long(w, (long long)sg[0] + 1);
            cvm__writer_putc(w, ' ');
            cvm__writer_long(w, (long long)sg[1] + 1);
            cvm__writer_putc(w, '\n');
        }
    }
    for (s = 0; s < l->nsurf; s++)
        for (type = 2; type <= 3; type++) {
            size_t n = 0;
            for (t = 0; t < mo->nt; t++)
                n += l->tsurf[t] == s && gmsh_type(mo, t) == type;
            if (n == 0 && !(s == 0 && type == 2 && mo->nt == 0))
                continue;
            cvm__writer_printf(w, "2 %lu %d %lu\n", (unsigned long)s + 1, type, (unsigned long)n);
            for (t = 0; t < mo->nt; t++) {
                size_t nc;
                const int32_t *v = cell_of(mo, t, &nc);
                if (l->tsurf[t] != s || gmsh_type(mo, t) != type)
                    continue;
                cvm__writer_ulong(w, mo->nseg + t + 1);
                for (j = 0; j < nc; j++) {
                    cvm__writer_putc(w, ' ');
                    cvm__writer_long(w, (long long)v[j] + 1);
                }
                cvm__writer_putc(w, '\n');
            }
        }
    (void)tag;
    cvm__writer_puts(w, "$EndElements\n");
}

cvm_status cvm__write_msh(cvm__writer *w, cvm__ctx *ctx, const cvm__mesh_out *mo)
{
    curves c;
    layout l;
    cvm_status s;
    memset(&l, 0, sizeof l);
    if ((s = curves_build(ctx, mo, &c)) != CVM_OK)
        return s;
    if ((s = surfaces_build(ctx, mo, &l)) == CVM_OK && (s = nodes_build(ctx, mo, &c, &l)) == CVM_OK) {
        cvm__writer_puts(w, "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n");
        physical_names(w, mo, &c, &l);
        entities(w, mo, &c, &l);
        nodes(w, mo, &c, &l);
        elements(w, mo, &c, &l);
    }
    layout_free(ctx, &l);
    curves_free(ctx, &c);
    return s;
}
