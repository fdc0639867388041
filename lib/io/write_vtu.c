/*
 * write_vtu.c - writes a mesh as a VTK XML UnstructuredGrid (.vtu, ASCII),
 * readable by ParaView and meshio (and by read_vtu.c): points (z = 0),
 * triangles (VTK type 5) and then the segments as lines (VTK type 3); point
 * data "marker", "weight" (when weights are set) and "attribute" (the point
 * attributes, when there are any); cell data "marker" (the segment marker of
 * a line, 0 on a triangle), "attribute" (regional attribute), "min_angle_deg"
 * and "layer_index" (AFLR) when given (0 on a line).
 * Also the power cells of a mesh as VTK polygons (type 7) on shared points,
 * with their face table as field data.
 */
#include "formats.h"

#define PER_LINE 12

static void begin_array(cvm__writer *w, const char *type, const char *name, size_t ncomp)
{
    cvm__writer_printf(w, "        <DataArray type=\"%s\"", type);
    if (name)
        cvm__writer_printf(w, " Name=\"%s\"", name);
    if (ncomp > 1)
        cvm__writer_printf(w, " NumberOfComponents=\"%lu\"", (unsigned long)ncomp);
    cvm__writer_puts(w, " format=\"ascii\">\n");
}

static void end_array(cvm__writer *w)
{
    cvm__writer_puts(w, "        </DataArray>\n");
}

/* n doubles, ncomp per line. */
static void doubles(cvm__writer *w, const double *x, size_t n, size_t ncomp)
{
    size_t i;
    for (i = 0; i < n; i++) {
        cvm__writer_double(w, x[i]);
        cvm__writer_putc(w, (i + 1) % ncomp == 0 || i + 1 == n ? '\n' : ' ');
    }
}

static void point_data(cvm__writer *w, const cvm__mesh_out *mo)
{
    size_t v;
    cvm__writer_puts(w, "      <PointData Scalars=\"marker\">\n");
    begin_array(w, "Int32", "marker", 1);
    for (v = 0; v < mo->nv; v++) {
        cvm__writer_long(w, mo->vmark ? mo->vmark[v] : 0);
        cvm__writer_putc(w, (v + 1) % PER_LINE == 0 || v + 1 == mo->nv ? '\n' : ' ');
    }
    end_array(w);
    if (mo->weight) {
        begin_array(w, "Float64", "weight", 1);
        doubles(w, mo->weight, mo->nv, 1);
        end_array(w);
    }
    if (mo->vattr && mo->nattr > (mo->weight ? 1u : 0u)) {
        size_t skip = mo->weight ? 1 : 0, na = mo->nattr - skip, v2, k;
        begin_array(w, "Float64", "attribute", na);
        for (v2 = 0; v2 < mo->nv; v2++)
            for (k = 0; k < na; k++) {
                cvm__writer_double(w, mo->vattr[v2 * mo->nattr + skip + k]);
                cvm__writer_putc(w, k + 1 == na ? '\n' : ' ');
            }
        end_array(w);
    }
    cvm__writer_puts(w, "      </PointData>\n");
}

/* n doubles, then nzero zeros, one per line. */
static void doubles_then_zeros(cvm__writer *w, const double *x, size_t n, size_t nzero)
{
    size_t i;
    doubles(w, x, n, 1);
    for (i = 0; i < nzero; i++)
        cvm__writer_puts(w, "0\n");
}

static void cell_data(cvm__writer *w, const cvm__mesh_out *mo)
{
    size_t k;
    if (!mo->tattr && !mo->tquality && !mo->tlayer && !mo->nseg)
        return;
    cvm__writer_puts(w, "      <CellData>\n");
    if (mo->nseg) {
        begin_array(w, "Int32", "marker", 1);
        for (k = 0; k < mo->nt + mo->nseg; k++) {
            cvm__writer_long(w, k < mo->nt || !mo->smark ? 0 : mo->smark[k - mo->nt]);
            cvm__writer_putc(w, (k + 1) % PER_LINE == 0 || k + 1 == mo->nt + mo->nseg ? '\n' : ' ');
        }
        end_array(w);
    }
    if (mo->tattr) {
        begin_array(w, "Float64", "attribute", 1);
        doubles_then_zeros(w, mo->tattr, mo->nt, mo->nseg);
        end_array(w);
    }
    if (mo->tquality) {
        begin_array(w, "Float64", mo->tquality_name ? mo->tquality_name : "min_angle_deg", 1);
        doubles_then_zeros(w, mo->tquality, mo->nt, mo->nseg);
        end_array(w);
    }
    if (mo->tlayer) {
        begin_array(w, "Float64", "layer_index", 1);
        doubles_then_zeros(w, mo->tlayer, mo->nt, mo->nseg);
        end_array(w);
    }
    cvm__writer_puts(w, "      </CellData>\n");
}

static void cells(cvm__writer *w, const cvm__mesh_out *mo)
{
    size_t t, n = mo->nt + mo->nseg;
    cvm__writer_puts(w, "      <Cells>\n");
    begin_array(w, "Int32", "connectivity", 1);
    if (mo->coff) {
        for (t = 0; t < mo->nt; t++) {
            int32_t k;
            for (k = mo->coff[t]; k < mo->coff[t + 1]; k++) {
                cvm__writer_long(w, mo->tri[k]);
                cvm__writer_putc(w, k + 1 == mo->coff[t + 1] ? '\n' : ' ');
            }
        }
    }
    for (t = 0; t < 3 * mo->nt && !mo->coff; t++) {
        cvm__writer_long(w, mo->tri[t]);
        cvm__writer_putc(w, t % 3 == 2 ? '\n' : ' ');
    }
    for (t = 0; t < 2 * mo->nseg; t++) {
        cvm__writer_long(w, mo->seg[t]);
        cvm__writer_putc(w, t % 2 == 1 ? '\n' : ' ');
    }
    end_array(w);
    begin_array(w, "Int64", "offsets", 1);
    for (t = 0; t < n; t++) {
        size_t c3 = mo->coff ? (size_t)mo->coff[mo->nt] : 3 * mo->nt;
        cvm__writer_ulong(w, t < mo->nt ? (mo->coff ? (size_t)mo->coff[t + 1] : 3 * (t + 1))
                                        : c3 + 2 * (t + 1 - mo->nt));
        cvm__writer_putc(w, (t + 1) % PER_LINE == 0 || t + 1 == n ? '\n' : ' ');
    }
    end_array(w);
    begin_array(w, "UInt8", "types", 1);
    for (t = 0; t < n; t++) {
        cvm__writer_long(w, t < mo->nt ? (mo->coff ? mo->ctype[t] : 5) : 3);
        cvm__writer_putc(w, (t + 1) % PER_LINE == 0 || t + 1 == n ? '\n' : ' ');
    }
    end_array(w);
    cvm__writer_puts(w, "      </Cells>\n");
}

cvm_status cvm__write_vtu(cvm__writer *w, cvm__ctx *ctx, const cvm__mesh_out *mo)
{
    size_t v;
    int enc = mo->vtu_encoding;
    if (enc == CVM_VTU_AUTO)
        enc = mo->nv > CVM_VTU_AUTO_MAX_ASCII_POINTS ? CVM_VTU_BINARY : CVM_VTU_ASCII;
    if (enc == CVM_VTU_BINARY || enc == CVM_VTU_ZLIB)
        return cvm__write_vtu_binary(w, ctx, mo, enc == CVM_VTU_ZLIB);
    cvm__writer_puts(w, "<?xml version=\"1.0\"?>\n"
                        "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                        "  <UnstructuredGrid>\n");
    cvm__writer_printf(w, "    <Piece NumberOfPoints=\"%lu\" NumberOfCells=\"%lu\">\n",
                       (unsigned long)mo->nv, (unsigned long)(mo->nt + mo->nseg));
    point_data(w, mo);
    cell_data(w, mo);
    cvm__writer_puts(w, "      <Points>\n");
    begin_array(w, "Float64", "coordinates", 3);
    for (v = 0; v < mo->nv; v++) {
        cvm__writer_double(w, mo->xy[2 * v]);
        cvm__writer_putc(w, ' ');
        cvm__writer_double(w, mo->xy[2 * v + 1]);
        cvm__writer_write(w, " 0\n", 3);
    }
    end_array(w);
    cvm__writer_puts(w, "      </Points>\n");
    cells(w, mo);
    cvm__writer_puts(w, "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
    return CVM_OK;
}

/* n ints, ncomp per line. */
static void ints(cvm__writer *w, const int32_t *x, size_t n, size_t ncomp)
{
    size_t i;
    for (i = 0; i < n; i++) {
        cvm__writer_long(w, x[i]);
        cvm__writer_putc(w, (i + 1) % ncomp == 0 || i + 1 == n ? '\n' : ' ');
    }
}

static void field_array(cvm__writer *w, const char *type, const char *name, size_t ntuple)
{
    cvm__writer_printf(w, "      <DataArray type=\"%s\" Name=\"%s\" NumberOfComponents=\"2\" "
                          "NumberOfTuples=\"%lu\" format=\"ascii\">\n",
                       type, name, (unsigned long)ntuple);
}

/* The face table as field data: face_cells (cell a, cell b or -1, the
 * file's cell numbers), face_points, face_edge (the primal edge's vertices),
 * face_lengths (primal, dual). */
static void dual_faces(cvm__writer *w, const cvm__dual_out *d)
{
    size_t f, k;
    int32_t pair[2];
    cvm__writer_puts(w, "    <FieldData>\n");
    for (k = 0; k < 3; k++) {
        static const char *const name[3] = {"face_cells", "face_edge", "face_points"};
        field_array(w, "Int32", name[k], d->nface);
        for (f = 0; f < d->nface; f++) {
            const int32_t *x = d->face + 6 * f + 2 * k;
            pair[0] = x[0];
            pair[1] = x[1];
            if (k == 0) { /* mesh vertex -> the file's cell number */
                pair[0] = d->cell_of[pair[0]];
                pair[1] = pair[1] < 0 ? -1 : d->cell_of[pair[1]];
            }
            ints(w, pair, 2, 2);
        }
        cvm__writer_puts(w, "      </DataArray>\n");
    }
    field_array(w, "Float64", "face_lengths", d->nface);
    doubles(w, d->flen, 2 * d->nface, 2);
    cvm__writer_puts(w, "      </DataArray>\n    </FieldData>\n");
}

void cvm__write_dual_vtu(cvm__writer *w, const cvm__dual_out *d)
{
    size_t c, k;
    cvm__writer_puts(w, "<?xml version=\"1.0\"?>\n"
                        "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                        "  <UnstructuredGrid>\n");
    dual_faces(w, d);
    cvm__writer_printf(w, "    <Piece NumberOfPoints=\"%lu\" NumberOfCells=\"%lu\">\n",
                       (unsigned long)d->npoint, (unsigned long)d->ncell);
    cvm__writer_puts(w, "      <CellData Scalars=\"area\">\n");
    begin_array(w, "Int32", "vertex", 1);
    for (c = 0; c < d->ncell; c++) {
        cvm__writer_long(w, d->vertex[c]);
        cvm__writer_putc(w, (c + 1) % PER_LINE == 0 || c + 1 == d->ncell ? '\n' : ' ');
    }
    end_array(w);
    begin_array(w, "Float64", "area", 1);
    doubles(w, d->area, d->ncell, 1);
    end_array(w);
    begin_array(w, "Float64", "weight", 1);
    doubles(w, d->weight, d->ncell, 1);
    end_array(w);
    cvm__writer_puts(w, "      </CellData>\n      <Points>\n");
    begin_array(w, "Float64", "coordinates", 3);
    for (k = 0; k < d->npoint; k++) {
        cvm__writer_double(w, d->xy[2 * k]);
        cvm__writer_putc(w, ' ');
        cvm__writer_double(w, d->xy[2 * k + 1]);
        cvm__writer_write(w, " 0\n", 3);
    }
    end_array(w);
    cvm__writer_puts(w, "      </Points>\n      <Cells>\n");
    begin_array(w, "Int32", "connectivity", 1);
    for (c = 0; c < d->ncell; c++)
        for (k = (size_t)d->off[c]; k < (size_t)d->off[c + 1]; k++) {
            cvm__writer_long(w, d->corner[k]);
            cvm__writer_putc(w, k + 1 == (size_t)d->off[c + 1] ? '\n' : ' ');
        }
    end_array(w);
    begin_array(w, "Int64", "offsets", 1);
    for (c = 0; c < d->ncell; c++) {
        cvm__writer_ulong(w, (unsigned long long)(d->off[c + 1] - d->off[0]));
        cvm__writer_putc(w, (c + 1) % PER_LINE == 0 || c + 1 == d->ncell ? '\n' : ' ');
    }
    end_array(w);
    begin_array(w, "UInt8", "types", 1);
    for (c = 0; c < d->ncell; c++)
        cvm__writer_puts(w, (c + 1) % PER_LINE == 0 || c + 1 == d->ncell ? "7\n" : "7 ");
    end_array(w);
    cvm__writer_puts(w, "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
}
