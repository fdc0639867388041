/*
 * write_vtu_binary.c - writes a mesh as a VTK XML UnstructuredGrid with its
 * data in one <AppendedData encoding="raw"> block, plain or zlib-compressed:
 * the same arrays, names and order as the ASCII writer (write_vtu.c).
 *
 * Layout (VTK file formats, "XML File Formats"; vtkZLibDataCompressor):
 * header_type="UInt64", byte_order="LittleEndian" (bytes are put in that
 * order whatever the host's); each array at offset="N" bytes after the '_'
 * is a UInt64 byte count and the values, or with compression the words
 * nblocks, block size (32768), last block size, each block's compressed
 * size, then the zlib streams. The offsets must be known before the XML is
 * written, so compressed arrays are compressed first into memory; plain ones
 * are generated and written a block at a time.
 */
#include <string.h>
#include <zlib.h>

#include "formats.h"

#define BLOCK 32768

enum { A_PMARK, A_WEIGHT, A_PATTR, A_CMARK, A_TATTR, A_TQUAL, A_TLAYER, A_XYZ, A_CONN, A_OFF,
       A_TYPES, A_N };

typedef struct arr {
    int id;
    const char *type, *name;
    size_t ncomp, size, n;    /* components, bytes per value, values */
    unsigned char *z;         /* compressed: header words then blocks */
    size_t zlen;
} arr;

static void put_le(unsigned char *p, uint64_t v, int size)
{
    int i;
    for (i = 0; i < size; i++)
        p[i] = (unsigned char)(v >> (8 * i));
}

static void put_double(unsigned char *p, double x)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    put_le(p, u, 8);
}

/* Values [i0, i0 + n) of array a into dst. */
static void gen(const cvm__mesh_out *mo, const arr *a, size_t i0, size_t n, unsigned char *dst)
{
    size_t e, nt = mo->nt, skip = mo->weight ? 1 : 0, na = a->ncomp;
    size_t c3 = mo->coff ? (size_t)mo->coff[nt] : 3 * nt; /* ids of the cells */
    for (e = i0; e < i0 + n; e++, dst += a->size) {
        switch (a->id) {
        case A_PMARK: put_le(dst, (uint64_t)(int64_t)(mo->vmark ? mo->vmark[e] : 0), 4); break;
        case A_WEIGHT: put_double(dst, mo->weight[e]); break;
        case A_PATTR: put_double(dst, mo->vattr[e / na * mo->nattr + skip + e % na]); break;
        case A_CMARK:
            put_le(dst, (uint64_t)(int64_t)(e < nt || !mo->smark ? 0 : mo->smark[e - nt]), 4);
            break;
        case A_TATTR: put_double(dst, e < nt ? mo->tattr[e] : 0.0); break;
        case A_TQUAL: put_double(dst, e < nt ? mo->tquality[e] : 0.0); break;
        case A_TLAYER: put_double(dst, e < nt ? mo->tlayer[e] : 0.0); break;
        case A_XYZ: put_double(dst, e % 3 == 2 ? 0.0 : mo->xy[e / 3 * 2 + e % 3]); break;
        case A_CONN: put_le(dst, (uint64_t)(int64_t)(e < c3 ? mo->tri[e] : mo->seg[e - c3]), 4); break;
        case A_OFF:
            put_le(dst, e < nt ? (mo->coff ? (uint64_t)mo->coff[e + 1] : 3 * (e + 1))
                               : c3 + 2 * (e + 1 - nt), 8);
            break;
        default: *dst = (unsigned char)(e < nt ? (mo->coff ? mo->ctype[e] : 5) : 3); break; /* A_TYPES */
        }
    }
}

/* The arrays of mo, in the ASCII writer's order; returns how many. */
static size_t list_arrays(const cvm__mesh_out *mo, arr *a)
{
    size_t k = 0, nc = mo->nt + mo->nseg;
    int have_cd = mo->tattr || mo->tquality || mo->tlayer || mo->nseg;
    memset(a, 0, A_N * sizeof *a);
#define ADD(ID, TYPE, NAME, NCOMP, SIZE, N)                                                       \
    do {                                                                                        \
        a[k].id = ID; a[k].type = TYPE; a[k].name = NAME; a[k].ncomp = NCOMP;                     \
        a[k].size = SIZE; a[k].n = N; k++;                                                      \
    } while (0)
    ADD(A_PMARK, "Int32", "marker", 1, 4, mo->nv);
    if (mo->weight)
        ADD(A_WEIGHT, "Float64", "weight", 1, 8, mo->nv);
    if (mo->vattr && mo->nattr > (mo->weight ? 1u : 0u)) {
        size_t na = mo->nattr - (mo->weight ? 1 : 0);
        ADD(A_PATTR, "Float64", "attribute", na, 8, na * mo->nv);
    }
    if (have_cd && mo->nseg)
        ADD(A_CMARK, "Int32", "marker", 1, 4, nc);
    if (mo->tattr)
        ADD(A_TATTR, "Float64", "attribute", 1, 8, nc);
    if (mo->tquality)
        ADD(A_TQUAL, "Float64", mo->tquality_name ? mo->tquality_name : "min_angle_deg", 1, 8, nc);
    if (mo->tlayer)
        ADD(A_TLAYER, "Float64", "layer_index", 1, 8, nc);
    ADD(A_XYZ, "Float64", "coordinates", 3, 8, 3 * mo->nv);
    ADD(A_CONN, "Int32", "connectivity", 1, 4,
        (mo->coff ? (size_t)mo->coff[mo->nt] : 3 * mo->nt) + 2 * mo->nseg);
    ADD(A_OFF, "Int64", "offsets", 1, 8, nc);
    ADD(A_TYPES, "UInt8", "types", 1, 1, nc);
#undef ADD
    return k;
}

static voidpf z_alloc(voidpf ctx, uInt items, uInt size)
{
    if (size && items > SIZE_MAX / size)
        return Z_NULL;
    return cvm__malloc(ctx, (size_t)items * size);
}

static void z_free(voidpf ctx, voidpf p)
{
    cvm__free(ctx, p);
}

/* Compress array a block by block into a->z. */
static cvm_status compress_array(cvm__ctx *ctx, const cvm__mesh_out *mo, arr *a, unsigned char *raw)
{
    size_t bytes = a->n * a->size, nb = (bytes + BLOCK - 1) / BLOCK, per = BLOCK / a->size, b;
    size_t hdr = 8 * (3 + nb), cap = hdr + nb * (size_t)compressBound(BLOCK);
    z_stream zs;
    cvm_status s = CVM_OK;
    memset(&zs, 0, sizeof zs);
    zs.zalloc = z_alloc;
    zs.zfree = z_free;
    zs.opaque = ctx;
    if (!(a->z = cvm__malloc(ctx, cap)))
        return CVM_E_NOMEM;
    if (deflateInit(&zs, Z_BEST_SPEED) != Z_OK)
        return CVM_E_NOMEM;
    put_le(a->z, nb, 8);
    put_le(a->z + 8, BLOCK, 8);
    put_le(a->z + 16, bytes % BLOCK, 8);
    a->zlen = hdr;
    for (b = 0; b < nb && !s; b++) {
        size_t n = b + 1 < nb ? per : a->n - b * per;
        gen(mo, a, b * per, n, raw);
        deflateReset(&zs);
        zs.next_in = raw;
        zs.avail_in = (uInt)(n * a->size);
        zs.next_out = a->z + a->zlen;
        zs.avail_out = (uInt)compressBound(BLOCK);
        if (deflate(&zs, Z_FINISH) != Z_STREAM_END)
            s = CVM_E_NOMEM; /* the output bound holds, so only memory can fail */
        put_le(a->z + 8 * (3 + b), zs.total_out, 8);
        a->zlen += zs.total_out;
    }
    deflateEnd(&zs);
    return s;
}

static void write_array_tag(cvm__writer *w, const arr *a, uint64_t offset)
{
    cvm__writer_printf(w, "        <DataArray type=\"%s\" Name=\"%s\"", a->type, a->name);
    if (a->ncomp > 1)
        cvm__writer_printf(w, " NumberOfComponents=\"%lu\"", (unsigned long)a->ncomp);
    cvm__writer_printf(w, " format=\"appended\" offset=\"%llu\"/>\n", (unsigned long long)offset);
}

/* The XML part: every array's tag with its offset. */
static void write_xml(cvm__writer *w, const cvm__mesh_out *mo, const arr *a, size_t na, int zlib)
{
    static const char *const open_of[A_N] = {"      <PointData Scalars=\"marker\">\n", NULL, NULL,
                                             "      <CellData>\n", NULL, NULL, NULL,
                                             "      <Points>\n", "      <Cells>\n", NULL, NULL};
    uint64_t off = 0;
    size_t k;
    int sec = -1; /* 0 point data, 1 cell data, 2 points, 3 cells */
    static const char *const close_of[4] = {"      </PointData>\n", "      </CellData>\n",
                                            "      </Points>\n", "      </Cells>\n"};
    cvm__writer_printf(w, "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
                          "byte_order=\"LittleEndian\" header_type=\"UInt64\"%s>\n  <UnstructuredGrid>\n",
                       zlib ? " compressor=\"vtkZLibDataCompressor\"" : "");
    cvm__writer_printf(w, "    <Piece NumberOfPoints=\"%lu\" NumberOfCells=\"%lu\">\n",
                       (unsigned long)mo->nv, (unsigned long)(mo->nt + mo->nseg));
    for (k = 0; k < na; k++) {
        int s = a[k].id <= A_PATTR ? 0 : a[k].id <= A_TLAYER ? 1 : a[k].id == A_XYZ ? 2 : 3;
        if (s != sec) {
            if (sec >= 0)
                cvm__writer_puts(w, close_of[sec]);
            cvm__writer_puts(w, s == 1 ? open_of[A_CMARK] : s == 0 ? open_of[A_PMARK] :
                                s == 2 ? open_of[A_XYZ] : open_of[A_CONN]);
            sec = s;
        }
        write_array_tag(w, &a[k], off);
        off += zlib ? a[k].zlen : 8 + a[k].n * a[k].size;
    }
    cvm__writer_puts(w, close_of[sec]);
    cvm__writer_puts(w, "    </Piece>\n  </UnstructuredGrid>\n  <AppendedData encoding=\"raw\">\n   _");
}

cvm_status cvm__write_vtu_binary(cvm__writer *w, cvm__ctx *ctx, const cvm__mesh_out *mo, int zlib)
{
    arr a[A_N];
    size_t na = list_arrays(mo, a), k;
    unsigned char *raw = cvm__malloc(ctx, BLOCK);
    cvm_status s = raw ? CVM_OK : CVM_E_NOMEM;
    for (k = 0; zlib && k < na && !s; k++)
        s = compress_array(ctx, mo, &a[k], raw);
    if (!s) {
        write_xml(w, mo, a, na, zlib);
        for (k = 0; k < na; k++) {
            size_t per = BLOCK / a[k].size, i;
            unsigned char hdr[8];
            if (zlib) {
                cvm__writer_write(w, (const char *)a[k].z, a[k].zlen);
                continue;
            }
            put_le(hdr, a[k].n * a[k].size, 8);
            cvm__writer_write(w, (const char *)hdr, 8);
            for (i = 0; i < a[k].n; i += per) {
                size_t n = a[k].n - i < per ? a[k].n - i : per;
                gen(mo, &a[k], i, n, raw);
                cvm__writer_write(w, (const char *)raw, n * a[k].size);
            }
        }
        cvm__writer_puts(w, "\n  </AppendedData>\n</VTKFile>\n");
    }
    for (k = 0; k < na; k++)
        cvm__free(ctx, a[k].z);
    cvm__free(ctx, raw);
    return s ? cvm__nomem(ctx) : CVM_OK;
}
