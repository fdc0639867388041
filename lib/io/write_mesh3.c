/*
 * write_mesh3.c - writes a tetrahedral mesh: VTK XML UnstructuredGrid (.vtu,
 * VTK_TETRA cells, cell data "attribute" with regions, point data "weight"
 * when weighted; or merged cells as VTK_POLYHEDRON), Gmsh MSH 4.1 (.msh:
 * tetrahedra, type 4, in one volume per regional attribute; boundary
 * triangles, type 2, on one surface per face marker, physical group m
 * "marker_m" when m > 0), and TetGen's .node/.ele/.face (0-based; the weight
 * as the point attribute). All ASCII,
 * doubles in the shortest form that reads back exactly.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io_internal.h"

static void m3w_put_longs(cvm__writer *w, const int64_t *a, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        cvm__writer_long(w, (long long)a[i]);
        cvm__writer_putc(w, (i + 1) % 12 == 0 || i + 1 == n ? '\n' : ' ');
    }
}

/* The <Cells> and <CellData> of merged cells: VTK's polyhedron layout, with
 * "faceoffsets" -1 for the tetrahedra; cell data "tetrahedron" (the cell's
 * smallest tetrahedron) and "attribute" (its region). */
static void vtu_cells(cvm__writer *w, const cvm__mesh3_out *mo)
{
    const cvm__mesh3_cells *c = mo->cells;
    size_t i;
    cvm__writer_puts(w, "        <DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n");
    for (i = 0; i < (size_t)c->conn_off[c->ncell]; i++) {
        cvm__writer_long(w, c->conn[i]);
        cvm__writer_putc(w, (i + 1) % 12 == 0 || i + 1 == (size_t)c->conn_off[c->ncell] ? '\n' : ' ');
    }
    cvm__writer_puts(w, "        </DataArray>\n"
                        "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
    m3w_put_longs(w, c->conn_off + 1, c->ncell);
    cvm__writer_puts(w, "        </DataArray>\n"
                        "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
    for (i = 0; i < c->ncell; i++) {
        cvm__writer_ulong(w, c->type[i]);
        cvm__writer_putc(w, (i + 1) % 12 == 0 || i + 1 == c->ncell ? '\n' : ' ');
    }
    cvm__writer_puts(w, "        </DataArray>\n"
                        "        <DataArray type=\"Int64\" Name=\"faces\" format=\"ascii\">\n");
    m3w_put_longs(w, c->faces, (size_t)c->face_off[c->ncell]);
    cvm__writer_puts(w, "        </DataArray>\n"
                        "        <DataArray type=\"Int64\" Name=\"faceoffsets\" format=\"ascii\">\n");
    for (i = 0; i < c->ncell; i++) {
        cvm__writer_long(w, c->type[i] == 42 ? (long long)c->face_off[i + 1] : -1);
        cvm__writer_putc(w, (i + 1) % 12 == 0 || i + 1 == c->ncell ? '\n' : ' ');
    }
    cvm__writer_puts(w, "        </DataArray>\n      </Cells>\n"
                        "      <CellData Scalars=\"tetrahedron\">\n"
                        "        <DataArray type=\"Int32\" Name=\"tetrahedron\" format=\"ascii\">\n");
    for (i = 0; i < c->ncell; i++) {
        cvm__writer_long(w, c->tet[i]);
        cvm__writer_putc(w, (i + 1) % 12 == 0 || i + 1 == c->ncell ? '\n' : ' ');
    }
    cvm__writer_puts(w, "        </DataArray>\n");
    if (mo->tattr) {
        cvm__writer_puts(w, "        <DataArray type=\"Float64\" Name=\"attribute\" format=\"ascii\">\n");
        for (i = 0; i < c->ncell; i++) {
            cvm__writer_double(w, mo->tattr[c->tet[i]]);
            cvm__writer_putc(w, '\n');
        }
        cvm__writer_puts(w, "        </DataArray>\n");
    }
    cvm__writer_puts(w, "      </CellData>\n");
}

static void vtu(cvm__writer *w, const cvm__mesh3_out *mo)
{
    size_t i;
    cvm__writer_puts(w, "<?xml version=\"1.0\"?>\n"
                        "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                        "  <UnstructuredGrid>\n");
    cvm__writer_printf(w, "    <Piece NumberOfPoints=\"%lu\" NumberOfCells=\"%lu\">\n",
                       (unsigned long)mo->nv, (unsigned long)(mo->cells ? mo->cells->ncell : mo->ntet));
    if (mo->w) { /* the power weights: what the dual cells need besides the points */
        cvm__writer_puts(w, "      <PointData Scalars=\"weight\">\n"
                            "        <DataArray type=\"Float64\" Name=\"weight\" format=\"ascii\">\n");
        for (i = 0; i < mo->nv; i++) {
            cvm__writer_double(w, mo->w[i]);
            cvm__writer_putc(w, '\n');
        }
        cvm__writer_puts(w, "        </DataArray>\n      </PointData>\n");
    }
    cvm__writer_puts(w, "      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" "
                        "format=\"ascii\">\n");
    for (i = 0; i < mo->nv; i++) {
        cvm__writer_double(w, mo->xyz[3 * i]);
        cvm__writer_putc(w, ' ');
        cvm__writer_double(w, mo->xyz[3 * i + 1]);
        cvm__writer_putc(w, ' ');
        cvm__writer_double(w, mo->xyz[3 * i + 2]);
        cvm__writer_putc(w, '\n');
    }
    cvm__writer_puts(w, "        </DataArray>\n      </Points>\n      <Cells>\n");
    if (mo->cells) {
        vtu_cells(w, mo);
        cvm__writer_puts(w, "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
        return;
    }
    cvm__writer_puts(w, "        <DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n");
    for (i = 0; i < mo->ntet; i++) {
        const int32_t *t = mo->tet + 4 * i;
        cvm__writer_printf(w, "%ld %ld %ld %ld\n", (long)t[0], (long)t[1], (long)t[2], (long)t[3]);
    }
    cvm__writer_puts(w, "        </DataArray>\n"
                        "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
    for (i = 0; i < mo->ntet; i++) {
        cvm__writer_ulong(w, 4 * (i + 1));
        cvm__writer_putc(w, (i + 1) % 12 == 0 || i + 1 == mo->ntet ? '\n' : ' ');
    }
    cvm__writer_puts(w, "        </DataArray>\n"
                        "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
    for (i = 0; i < mo->ntet; i++)
        cvm__writer_puts(w, (i + 1) % 12 == 0 || i + 1 == mo->ntet ? "10\n" : "10 ");
    cvm__writer_puts(w, "        </DataArray>\n      </Cells>\n");
    if (mo->tattr) {
        cvm__writer_puts(w, "      <CellData Scalars=\"attribute\">\n"
                            "        <DataArray type=\"Float64\" Name=\"attribute\" format=\"ascii\">\n");
        for (i = 0; i < mo->ntet; i++) {
            cvm__writer_double(w, mo->tattr[i]);
            cvm__writer_putc(w, '\n');
        }
        cvm__writer_puts(w, "        </DataArray>\n      </CellData>\n");
    }
    cvm__writer_puts(w, "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
}

static int cmp_f64(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static int cmp_i32(const void *a, const void *b)
{
    int32_t x = *(const int32_t *)a, y = *(const int32_t *)b;
    return (x > y) - (x < y);
}

/* Distinct values of a (n), increasing, into *out (allocated); *nout. */
static cvm_status distinct_f64(cvm__ctx *ctx, const double *a, size_t n, double **out, size_t *nout)
{
    size_t i, k = 0;
    *out = cvm__malloc(ctx, (n ? n : 1) * sizeof **out);
    if (!*out)
        return cvm__nomem(ctx);
    memcpy(*out, a, n * sizeof **out);
    qsort(*out, n, sizeof **out, cmp_f64);
    for (i = 0; i < n; i++)
        if (k == 0 || (*out)[i] != (*out)[k - 1])
            (*out)[k++] = (*out)[i];
    *nout = k;
    return CVM_OK;
}

static cvm_status msh(cvm__writer *w, cvm__ctx *ctx, const cvm__mesh3_out *mo)
{
    double *vattr = NULL, lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    int32_t *marks = NULL;
    size_t nvol = 1, nsurf = 0, i, j, d, tag = 1, nblock;
    if (mo->tattr && mo->ntet && distinct_f64(ctx, mo->tattr, mo->ntet, &vattr, &nvol))
        return CVM_E_NOMEM;
    if (mo->nface) {
        marks = cvm__malloc(ctx, mo->nface * sizeof *marks);
        if (!marks) {
            cvm__free(ctx, vattr);
            return cvm__nomem(ctx);
        }
        for (i = 0; i < mo->nface; i++)
            marks[i] = mo->fmark ? mo->fmark[i] : 1;
        qsort(marks, mo->nface, sizeof *marks, cmp_i32);
        for (i = 0; i < mo->nface; i++)
            if (nsurf == 0 || marks[i] != marks[nsurf - 1])
                marks[nsurf++] = marks[i];
    }
    for (i = 0; i < mo->nv; i++)
        for (d = 0; d < 3; d++) {
            double x = mo->xyz[3 * i + d];
            if (i == 0 || x < lo[d])
                lo[d] = x;
            if (i == 0 || x > hi[d])
                hi[d] = x;
        }
    cvm__writer_puts(w, "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n");
    {
        size_t n = nvol;
        for (i = 0; i < nsurf; i++)
            n += marks[i] > 0;
        cvm__writer_printf(w, "%lu\n", (unsigned long)n);
    }
    for (i = 0; i < nsurf; i++)
        if (marks[i] > 0)
            cvm__writer_printf(w, "2 %ld \"marker_%ld\"\n", (long)marks[i], (long)marks[i]);
    for (i = 0; i < nvol; i++) {
        if (!vattr) {
            cvm__writer_puts(w, "3 1 \"domain\"\n");
        } else {
            cvm__writer_printf(w, "3 %lu \"region_", (unsigned long)i + 1);
            cvm__writer_double(w, vattr[i]);
            cvm__writer_puts(w, "\"\n");
        }
    }
    cvm__writer_puts(w, "$EndPhysicalNames\n$Entities\n");
    cvm__writer_printf(w, "0 0 %lu %lu\n", (unsigned long)nsurf, (unsigned long)nvol);
    for (j = 0; j < nsurf + nvol; j++) {
        cvm__writer_printf(w, "%lu", (unsigned long)(j < nsurf ? j + 1 : j - nsurf + 1));
        for (d = 0; d < 3; d++) {
            cvm__writer_putc(w, ' ');
            cvm__writer_double(w, lo[d]);
        }
        for (d = 0; d < 3; d++) {
            cvm__writer_putc(w, ' ');
            cvm__writer_double(w, hi[d]);
        }
        if (j < nsurf)
            cvm__writer_printf(w, marks[j] > 0 ? " 1 %ld 0\n" : " 0 0\n", (long)marks[j]);
        else
            cvm__writer_printf(w, " 1 %lu %lu", (unsigned long)(j - nsurf + 1), (unsigned long)nsurf);
        if (j >= nsurf) {
            for (i = 0; i < nsurf; i++)
                cvm__writer_printf(w, " %lu", (unsigned long)i + 1);
            cvm__writer_putc(w, '\n');
        }
    }
    cvm__writer_puts(w, "$EndEntities\n");
    /* every node in volume 1 */
    cvm__writer_printf(w, "$Nodes\n1 %lu %lu %lu\n3 1 0 %lu\n", (unsigned long)mo->nv,
                       (unsigned long)(mo->nv ? 1 : 0), (unsigned long)mo->nv, (unsigned long)mo->nv);
    for (i = 0; i < mo->nv; i++) {
        cvm__writer_ulong(w, i + 1);
        cvm__writer_putc(w, '\n');
    }
    for (i = 0; i < mo->nv; i++) {
        cvm__writer_double(w, mo->xyz[3 * i]);
        cvm__writer_putc(w, ' ');
        cvm__writer_double(w, mo->xyz[3 * i + 1]);
        cvm__writer_putc(w, ' ');
        cvm__writer_double(w, mo->xyz[3 * i + 2]);
        cvm__writer_putc(w, '\n');
    }
    cvm__writer_puts(w, "$EndNodes\n");
    nblock = nsurf + nvol;
    cvm__writer_printf(w, "$Elements\n%lu %lu %lu %lu\n", (unsigned long)nblock,
                       (unsigned long)(mo->nface + mo->ntet), (unsigned long)(mo->nface + mo->ntet ? 1 : 0),
                       (unsigned long)(mo->nface + mo->ntet));
    for (j = 0; j < nsurf; j++) {
        size_t n = 0;
        for (i = 0; i < mo->nface; i++)
            n += (mo->fmark ? mo->fmark[i] : 1) == marks[j];
        cvm__writer_printf(w, "2 %lu 2 %lu\n", (unsigned long)j + 1, (unsigned long)n);
        for (i = 0; i < mo->nface; i++) {
            const int32_t *f = mo->face + 3 * i;
            if ((mo->fmark ? mo->fmark[i] : 1) != marks[j])
                continue;
            cvm__writer_printf(w, "%lu %ld %ld %ld\n", (unsigned long)tag++, (long)f[0] + 1,
                               (long)f[1] + 1, (long)f[2] + 1);
        }
    }
    for (j = 0; j < nvol; j++) {
        size_t n = 0;
        for (i = 0; i < mo->ntet; i++)
            n += !vattr || mo->tattr[i] == vattr[j];
        cvm__writer_printf(w, "3 %lu 4 %lu\n", (unsigned long)j + 1, (unsigned long)n);
        for (i = 0; i < mo->ntet; i++) {
            const int32_t *t = mo->tet + 4 * i;
            if (vattr && mo->tattr[i] != vattr[j])
                continue;
            cvm__writer_printf(w, "%lu %ld %ld %ld %ld\n", (unsigned long)(mo->nface + i + 1),
                               (long)t[0] + 1, (long)t[1] + 1, (long)t[2] + 1, (long)t[3] + 1);
        }
    }
    cvm__writer_puts(w, "$EndElements\n");
    cvm__free(ctx, vattr);
    cvm__free(ctx, marks);
    return CVM_OK;
}

static void tet_node(cvm__writer *w, const cvm__mesh3_out *mo)
{
    size_t i;
    /* the weight as the one point attribute, where TetGen's -w reads it */
    cvm__writer_printf(w, "%lu 3 %d 0\n", (unsigned long)mo->nv, mo->w ? 1 : 0);
    for (i = 0; i < mo->nv; i++) {
        cvm__writer_printf(w, "%lu ", (unsigned long)i);
        cvm__writer_double(w, mo->xyz[3 * i]);
        cvm__writer_putc(w, ' ');
        cvm__writer_double(w, mo->xyz[3 * i + 1]);
        cvm__writer_putc(w, ' ');
        cvm__writer_double(w, mo->xyz[3 * i + 2]);
        if (mo->w) {
            cvm__writer_putc(w, ' ');
            cvm__writer_double(w, mo->w[i]);
        }
        cvm__writer_putc(w, '\n');
    }
}

static void tet_ele(cvm__writer *w, const cvm__mesh3_out *mo)
{
    size_t i;
    cvm__writer_printf(w, "%lu 4 %d\n", (unsigned long)mo->ntet, mo->tattr ? 1 : 0);
    for (i = 0; i < mo->ntet; i++) {
        const int32_t *t = mo->tet + 4 * i;
        cvm__writer_printf(w, "%lu %ld %ld %ld %ld", (unsigned long)i, (long)t[0], (long)t[1],
                           (long)t[2], (long)t[3]);
        if (mo->tattr) {
            cvm__writer_putc(w, ' ');
            cvm__writer_double(w, mo->tattr[i]);
        }
        cvm__writer_putc(w, '\n');
    }
}

static void tet_face(cvm__writer *w, const cvm__mesh3_out *mo)
{
    size_t i;
    cvm__writer_printf(w, "%lu 1\n", (unsigned long)mo->nface);
    for (i = 0; i < mo->nface; i++) {
        const int32_t *f = mo->face + 3 * i;
        cvm__writer_printf(w, "%lu %ld %ld %ld %ld\n", (unsigned long)i, (long)f[0], (long)f[1],
                           (long)f[2], (long)(mo->fmark ? mo->fmark[i] : 1));
    }
}

/* PREFIX.node, .ele and .face, each written and closed before any joins ws. */
static cvm_status write_tetgen(cvm__write_set *ws, const char *path, const cvm__mesh3_out *mo)
{
    static const char *const ext[3] = {".node", ".ele", ".face"};
    cvm__ctx *ctx = ws->ctx;
    size_t stem = strlen(path) - 5, i, n0 = ws->n;
    cvm__writer *w[3] = {NULL, NULL, NULL};
    char *name = cvm__malloc(ctx, stem + 6);
    cvm_status s = CVM_OK;
    if (!name)
        return cvm__nomem(ctx);
    memcpy(name, path, stem);
    for (i = 0; i < 3 && !s; i++) {
        memcpy(name + stem, ext[i], strlen(ext[i]) + 1);
        s = cvm__writer_open(&w[i], ctx, name);
    }
    cvm__free(ctx, name);
    if (!s) {
        tet_node(w[0], mo);
        if (!(s = cvm__writer_finish(w[0])))
            tet_ele(w[1], mo);
        if (!s && !(s = cvm__writer_finish(w[1]))) {
            tet_face(w[2], mo);
            s = cvm__writer_finish(w[2]);
        }
    }
    for (i = 0; i < 3; i++) {
        if (!s && w[i])
            s = cvm__write_set_add(ws, w[i]);
        else
            cvm__writer_discard(w[i]);
    }
    if (s)
        while (ws->n > n0)
            cvm__writer_discard(ws->w[--ws->n]);
    return s;
}

cvm_status cvm__write_file3_to_set(cvm__write_set *ws, const char *path, const cvm__mesh3_out *mo)
{
    cvm__format fmt = cvm__format_of(path);
    cvm__writer *w;
    cvm_status s;
    if (fmt == CVM__FMT_NODE)
        return write_tetgen(ws, path, mo);
    if (fmt != CVM__FMT_VTU && fmt != CVM__FMT_MSH)
        return cvm__error(ws->ctx, CVM_E_UNSUPPORTED, CVM_ENT_NONE, -1,
                          "cannot write the tetrahedral mesh to %s: expected .vtu, .msh or .node", path);
    if ((s = cvm__writer_open(&w, ws->ctx, path)))
        return s;
    cvm__writer_expect(w, 0, (uint64_t)mo->nv * 6 + (uint64_t)mo->ntet * 3);
    if (fmt == CVM__FMT_VTU)
        vtu(w, mo);
    else if ((s = msh(w, ws->ctx, mo)) != CVM_OK) {
        cvm__writer_discard(w);
        return s;
    }
    return cvm__write_set_add(ws, w);
}

/* The dimension field of a Triangle/TetGen .node or .poly file: the second
 * number of its first line that is neither empty nor a comment. */
int cvm__file_dimension(const char *path)
{
    char line[512];
    int dim = 2;
    FILE *f = fopen(path, "r");
    if (!f)
        return 2; /* the reader reports the open error */
    while (fgets(line, sizeof line, f)) {
        char *p = line, *end;
        long a, b;
        while (*p == ' ' || *p == '\t' || *p == '\r')
            p++;
        if (*p == '#' || *p == '\n' || *p == '\0')
            continue;
        a = strtol(p, &end, 10);
        (void)a;
        if (end == p)
            break;
        p = end;
        b = strtol(p, &end, 10);
        if (end != p && b == 3)
            dim = 3;
        break;
    }
    fclose(f);
    return dim;
}
