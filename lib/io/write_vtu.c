/*
 * write_vtu.c - writes a mesh as a VTK XML UnstructuredGrid (.vtu, ASCII),
 * readable by ParaView and meshio: points (z = 0), triangles (VTK type 5),
 * point data "marker" (and "attribute" when there are point attributes), cell
 * data "attribute" (regional attribute), "min_angle_deg" and "layer_index"
 * (AFLR) when given.
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
        cvm__writer_puts(w, (i + 1) % ncomp == 0 || i + 1 == n ? "\n" : " ");
    }
}

static void point_data(cvm__writer *w, const cvm__mesh_out *mo)
{
    size_t v;
    cvm__writer_puts(w, "      <PointData Scalars=\"marker\">\n");
    begin_array(w, "Int32", "marker", 1);
    for (v = 0; v < mo->nv; v++)
        cvm__writer_printf(w, "%ld%s", (long)(mo->vmark ? mo->vmark[v] : 0),
                           (v + 1) % PER_LINE == 0 || v + 1 == mo->nv ? "\n" : " ");
    end_array(w);
    if (mo->vattr && mo->nattr) {
        begin_array(w, "Float64", "attribute", mo->nattr);
        doubles(w, mo->vattr, mo->nv * mo->nattr, mo->nattr);
        end_array(w);
    }
    cvm__writer_puts(w, "      </PointData>\n");
}

static void cell_data(cvm__writer *w, const cvm__mesh_out *mo)
{
    if (!mo->tattr && !mo->tquality)
        return;
    cvm__writer_puts(w, "      <CellData>\n");
    if (mo->tattr) {
        begin_array(w, "Float64", "attribute", 1);
        doubles(w, mo->tattr, mo->nt, 1);
        end_array(w);
    }
    if (mo->tquality) {
        begin_array(w, "Float64", "min_angle_deg", 1);
        doubles(w, mo->tquality, mo->nt, 1);
        end_array(w);
    }
    if (mo->tlayer) {
        begin_array(w, "Float64", "layer_index", 1);
        doubles(w, mo->tlayer, mo->nt, 1);
        end_array(w);
    }
    cvm__writer_puts(w, "      </CellData>\n");
}

static void cells(cvm__writer *w, const cvm__mesh_out *mo)
{
    size_t t;
    cvm__writer_puts(w, "      <Cells>\n");
    begin_array(w, "Int32", "connectivity", 1);
    for (t = 0; t < mo->nt; t++)
        cvm__writer_printf(w, "%ld %ld %ld\n", (long)mo->tri[3 * t], (long)mo->tri[3 * t + 1],
                           (long)mo->tri[3 * t + 2]);
    end_array(w);
    begin_array(w, "Int64", "offsets", 1);
    for (t = 0; t < mo->nt; t++)
        cvm__writer_printf(w, "%lu%s", (unsigned long)(3 * (t + 1)),
                           (t + 1) % PER_LINE == 0 || t + 1 == mo->nt ? "\n" : " ");
    end_array(w);
    begin_array(w, "UInt8", "types", 1);
    for (t = 0; t < mo->nt; t++)
        cvm__writer_puts(w, (t + 1) % PER_LINE == 0 || t + 1 == mo->nt ? "5\n" : "5 ");
    end_array(w);
    cvm__writer_puts(w, "      </Cells>\n");
}

cvm_status cvm__write_vtu(cvm__writer *w, cvm__ctx *ctx, const cvm__mesh_out *mo)
{
    size_t v;
    (void)ctx;
    cvm__writer_puts(w, "<?xml version=\"1.0\"?>\n"
                        "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                        "  <UnstructuredGrid>\n");
    cvm__writer_printf(w, "    <Piece NumberOfPoints=\"%lu\" NumberOfCells=\"%lu\">\n",
                       (unsigned long)mo->nv, (unsigned long)mo->nt);
    point_data(w, mo);
    cell_data(w, mo);
    cvm__writer_puts(w, "      <Points>\n");
    begin_array(w, "Float64", "coordinates", 3);
    for (v = 0; v < mo->nv; v++) {
        cvm__writer_double(w, mo->xy[2 * v]);
        cvm__writer_puts(w, " ");
        cvm__writer_double(w, mo->xy[2 * v + 1]);
        cvm__writer_puts(w, " 0\n");
    }
    end_array(w);
    cvm__writer_puts(w, "      </Points>\n");
    cells(w, mo);
    cvm__writer_puts(w, "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
    return CVM_OK;
}
