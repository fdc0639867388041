/*
 * write_dual3.c - the bounded power cells of a tetrahedral mesh as a VTK XML
 * UnstructuredGrid (.vtu, ASCII): one VTK_POLYHEDRON (42) per cell, its
 * corners shared points (the dual vertices, each once), with the "faces" and
 * "faceoffsets" arrays of VTK's polyhedron layout; point data "tetrahedron",
 * cell data "vertex", "volume", "weight", and field data with the dual face
 * area of each interior edge and the dual edge length of each interior face.
 */
#include "io_internal.h"

static void open_array(cvm__writer *w, const char *type, const char *name, int ncomp)
{
    cvm__writer_printf(w, "        <DataArray type=\"%s\" Name=\"%s\"", type, name);
    if (ncomp > 1)
        cvm__writer_printf(w, " NumberOfComponents=\"%d\"", ncomp);
    cvm__writer_puts(w, " format=\"ascii\">\n");
}

static void close_array(cvm__writer *w)
{
    cvm__writer_puts(w, "        </DataArray>\n");
}

static void ints(cvm__writer *w, const int32_t *a, size_t n, size_t per_line)
{
    size_t i;
    for (i = 0; i < n; i++) {
        cvm__writer_long(w, a[i]);
        cvm__writer_putc(w, (i + 1) % per_line == 0 || i + 1 == n ? '\n' : ' ');
    }
}

static void longs(cvm__writer *w, const int64_t *a, size_t n, size_t per_line)
{
    size_t i;
    for (i = 0; i < n; i++) {
        cvm__writer_long(w, (long long)a[i]);
        cvm__writer_putc(w, (i + 1) % per_line == 0 || i + 1 == n ? '\n' : ' ');
    }
}

static void doubles(cvm__writer *w, const double *a, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        cvm__writer_double(w, a[i]);
        cvm__writer_putc(w, '\n');
    }
}

static void vtu(cvm__writer *w, const cvm__dual3_out *d)
{
    size_t i;
    cvm__writer_puts(w, "<?xml version=\"1.0\"?>\n"
                        "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                        "  <UnstructuredGrid>\n");
    if (d->nedge || d->nface) {
        cvm__writer_puts(w, "    <FieldData>\n");
        cvm__writer_printf(w, "        <DataArray type=\"Int32\" Name=\"edge\" NumberOfComponents=\"2\" "
                              "NumberOfTuples=\"%lu\" format=\"ascii\">\n", (unsigned long)d->nedge);
        ints(w, d->edge, 2 * d->nedge, 2);
        close_array(w);
        cvm__writer_printf(w, "        <DataArray type=\"Float64\" Name=\"dual_face_area\" "
                              "NumberOfTuples=\"%lu\" format=\"ascii\">\n", (unsigned long)d->nedge);
        doubles(w, d->edge_area, d->nedge);
        close_array(w);
        cvm__writer_printf(w, "        <DataArray type=\"Int32\" Name=\"face\" NumberOfComponents=\"3\" "
                              "NumberOfTuples=\"%lu\" format=\"ascii\">\n", (unsigned long)d->nface);
        ints(w, d->face, 3 * d->nface, 3);
        close_array(w);
        cvm__writer_printf(w, "        <DataArray type=\"Float64\" Name=\"dual_edge_length\" "
                              "NumberOfTuples=\"%lu\" format=\"ascii\">\n", (unsigned long)d->nface);
        doubles(w, d->face_len, d->nface);
        close_array(w);
        cvm__writer_puts(w, "    </FieldData>\n");
    }
    cvm__writer_printf(w, "    <Piece NumberOfPoints=\"%lu\" NumberOfCells=\"%lu\">\n",
                       (unsigned long)d->npts, (unsigned long)d->ncell);
    cvm__writer_puts(w, "      <PointData>\n");
    open_array(w, "Int32", "tetrahedron", 1);
    ints(w, d->pt_tet, d->npts, 12);
    close_array(w);
    cvm__writer_puts(w, "      </PointData>\n      <CellData Scalars=\"volume\">\n");
    open_array(w, "Int32", "vertex", 1);
    ints(w, d->vertex, d->ncell, 12);
    close_array(w);
    open_array(w, "Float64", "volume", 1);
    doubles(w, d->volume, d->ncell);
    close_array(w);
    open_array(w, "Float64", "weight", 1);
    doubles(w, d->weight, d->ncell);
    close_array(w);
    cvm__writer_puts(w, "      </CellData>\n      <Points>\n");
    open_array(w, "Float64", "Points", 3);
    for (i = 0; i < d->npts; i++) {
        cvm__writer_double(w, d->pts[3 * i]);
        cvm__writer_putc(w, ' ');
        cvm__writer_double(w, d->pts[3 * i + 1]);
        cvm__writer_putc(w, ' ');
        cvm__writer_double(w, d->pts[3 * i + 2]);
        cvm__writer_putc(w, '\n');
    }
    close_array(w);
    cvm__writer_puts(w, "      </Points>\n      <Cells>\n");
    open_array(w, "Int32", "connectivity", 1);
    ints(w, d->conn, (size_t)d->conn_off[d->ncell], 12);
    close_array(w);
    open_array(w, "Int64", "offsets", 1);
    longs(w, d->conn_off + 1, d->ncell, 12);
    close_array(w);
    open_array(w, "UInt8", "types", 1);
    for (i = 0; i < d->ncell; i++)
        cvm__writer_puts(w, (i + 1) % 12 == 0 || i + 1 == d->ncell ? "42\n" : "42 ");
    close_array(w);
    open_array(w, "Int64", "faces", 1);
    longs(w, d->faces, (size_t)d->face_off[d->ncell], 12);
    close_array(w);
    open_array(w, "Int64", "faceoffsets", 1);
    longs(w, d->face_off + 1, d->ncell, 12);
    close_array(w);
    cvm__writer_puts(w, "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
}

cvm_status cvm__write_dual3_file_to_set(cvm__write_set *ws, const char *path,
                                        const cvm__dual3_out *d)
{
    cvm__writer *w;
    cvm_status s;
    if ((s = cvm__writer_open(&w, ws->ctx, path)))
        return s;
    cvm__writer_expect(w, 0, (uint64_t)d->npts * 4 + (uint64_t)d->face_off[d->ncell] +
                                 (uint64_t)d->nedge + (uint64_t)d->nface);
    vtu(w, d);
    return cvm__write_set_add(ws, w);
}
