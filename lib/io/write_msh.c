/*
 * write_msh.c - writes a mesh as Gmsh MSH 4.1 ASCII.
 *
 * Layout: one surface entity (tag 1, physical group 2D tag 1 "domain") holds
 * every node and every triangle (element type 2). The constrained edges
 * (segments) become line elements (type 1), one curve entity per distinct
 * segment marker in increasing order; a curve whose marker m is positive
 * belongs to the physical group 1D tag m, named "marker_m". Gmsh physical
 * tags must be positive, so segments with a marker <= 0 keep their curve but
 * get no physical group. Node tags are vertex id + 1; element tags number the
 * lines first, then the triangles.
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

static int32_t seg_marker(const cvm__mesh_out *mo, size_t k)
{
    return mo->smark ? mo->smark[k] : 1;
}

static int cmp_i32(const void *a, const void *b)
{
    int32_t x = *(const int32_t *)a, y = *(const int32_t *)b;
    return (x > y) - (x < y);
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

static void curves_free(cvm__ctx *ctx, curves *c)
{
    cvm__free(ctx, c->marker);
    cvm__free(ctx, c->start);
    cvm__free(ctx, c->order);
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

static void physical_names(cvm__writer *w, const curves *c)
{
    size_t i, n = 1;
    for (i = 0; i < c->ncurve; i++)
        n += c->marker[i] > 0;
    cvm__writer_printf(w, "$PhysicalNames\n%lu\n", (unsigned long)n);
    for (i = 0; i < c->ncurve; i++)
        if (c->marker[i] > 0)
            cvm__writer_printf(w, "1 %ld \"marker_%ld\"\n", (long)c->marker[i], (long)c->marker[i]);
    cvm__writer_puts(w, "2 1 \"domain\"\n$EndPhysicalNames\n");
}

static void entities(cvm__writer *w, const cvm__mesh_out *mo, const curves *c)
{
    double lo[2] = {0, 0}, hi[2] = {0, 0};
    size_t i, j, v;
    cvm__writer_printf(w, "$Entities\n0 %lu 1 0\n", (unsigned long)c->ncurve);
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
    if (mo->nv) {
        lo[0] = hi[0] = mo->xy[0];
        lo[1] = hi[1] = mo->xy[1];
    }
    for (v = 0; v < mo->nv; v++)
        extend(lo, hi, mo->xy + 2 * v);
    cvm__writer_puts(w, "1 ");
    bbox(w, lo, hi);
    cvm__writer_printf(w, "1 1 %lu", (unsigned long)c->ncurve);
    for (i = 0; i < c->ncurve; i++)
        cvm__writer_printf(w, " %lu", (unsigned long)i + 1);
    cvm__writer_puts(w, "\n$EndEntities\n");
}

static void nodes(cvm__writer *w, const cvm__mesh_out *mo)
{
    size_t v, n = mo->nv;
    cvm__writer_printf(w, "$Nodes\n1 %lu %lu %lu\n2 1 0 %lu\n", (unsigned long)n,
                       (unsigned long)(n ? 1 : 0), (unsigned long)n, (unsigned long)n);
    for (v = 0; v < n; v++) {
        cvm__writer_ulong(w, v + 1);
        cvm__writer_putc(w, '\n');
    }
    for (v = 0; v < n; v++) {
        cvm__writer_double(w, mo->xy[2 * v]);
        cvm__writer_putc(w, ' ');
        cvm__writer_double(w, mo->xy[2 * v + 1]);
        cvm__writer_write(w, " 0\n", 3);
    }
    cvm__writer_puts(w, "$EndNodes\n");
}

static void elements(cvm__writer *w, const cvm__mesh_out *mo, const curves *c)
{
    size_t i, j, t, tag = 1, total = mo->nseg + mo->nt;
    cvm__writer_printf(w, "$Elements\n%lu %lu %lu %lu\n", (unsigned long)c->ncurve + 1,
                       (unsigned long)total, (unsigned long)(total ? 1 : 0), (unsigned long)total);
    for (i = 0; i < c->ncurve; i++) {
        cvm__writer_printf(w, "1 %lu 1 %lu\n", (unsigned long)i + 1,
                           (unsigned long)(c->start[i + 1] - c->start[i]));
        for (j = c->start[i]; j < c->start[i + 1]; j++) {
            const int32_t *s = mo->seg + 2 * c->order[j];
            cvm__writer_ulong(w, tag++);
            cvm__writer_putc(w, ' ');
            cvm__writer_long(w, (long long)s[0] + 1);
            cvm__writer_putc(w, ' ');
            cvm__writer_long(w, (long long)s[1] + 1);
            cvm__writer_putc(w, '\n');
        }
    }
    cvm__writer_printf(w, "2 1 2 %lu\n", (unsigned long)mo->nt);
    for (t = 0; t < mo->nt; t++) {
        const int32_t *v = mo->tri + 3 * t;
        cvm__writer_ulong(w, tag++);
        for (j = 0; j < 3; j++) {
            cvm__writer_putc(w, ' ');
            cvm__writer_long(w, (long long)v[j] + 1);
        }
        cvm__writer_putc(w, '\n');
    }
    cvm__writer_puts(w, "$EndElements\n");
}

cvm_status cvm__write_msh(cvm__writer *w, cvm__ctx *ctx, const cvm__mesh_out *mo)
{
    curves c;
    cvm_status s = curves_build(ctx, mo, &c);
    if (s)
        return s;
    cvm__writer_puts(w, "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n");
    physical_names(w, &c);
    entities(w, mo, &c);
    nodes(w, mo);
    elements(w, mo, &c);
    curves_free(ctx, &c);
    return CVM_OK;
}
