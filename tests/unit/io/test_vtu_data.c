/* test_vtu_data.c - binary .vtu data (vtu_data.c): the files VTK and meshio write, and malformed base64, zlib and sizes. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "io/io_tests.h"
#include "support/failing_reader.h"

static cvmtest_alloc g_a;
static cvm__ctx g_ctx;

static void setup(void)
{
    cvmtest_alloc_init(&g_a, 0, 0);
    iotest_ctx(&g_ctx, &g_a);
}

/* The mesh of tests/data/interop/make_interop.py. */
static void assert_square(const cvm__vtu_mesh *vm, const char *file)
{
    static const int32_t tri[12] = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
    static const double xy[10] = {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5};
    size_t k;
    ck_assert_msg(vm->p.np == 5 && vm->nt == 4 && vm->p.nseg == 4, "%s: %lu points %lu triangles "
                  "%lu lines", file, (unsigned long)vm->p.np, (unsigned long)vm->nt,
                  (unsigned long)vm->p.nseg);
    for (k = 0; k < 12; k++)
        ck_assert_msg(vm->tri[k] == tri[k], "%s: corner %lu", file, (unsigned long)k);
    for (k = 0; k < 10; k++)
        ck_assert_msg(vm->p.xy[k] == xy[k], "%s: coordinate %lu", file, (unsigned long)k);
    ck_assert_msg(vm->p.smark != NULL, "%s: no line markers", file);
    for (k = 0; k < 4; k++) {
        ck_assert_int_eq(vm->p.seg[2 * k], (int32_t)k);
        ck_assert_int_eq(vm->p.seg[2 * k + 1], (int32_t)((k + 1) % 4));
        ck_assert_int_eq(vm->p.smark[k], (int32_t)k + 1);
    }
    ck_assert_msg(vm->w != NULL && vm->w[4] == 0.01 && vm->w[0] == 0, "%s: weights", file);
}

static const char *const k_files[] = {
    "square_meshio_ascii.vtu",    "square_meshio_base64.vtu",    "square_meshio_zlib.vtu",
    "square_vtk_ascii.vtu",       "square_vtk_binary.vtu",       "square_vtk_binary_zlib.vtu",
    "square_vtk_appended_raw.vtu", "square_vtk_appended_base64.vtu",
    "square_vtk_appended_zlib.vtu", "square_vtk_appended_zlib_h32_be.vtu"};

START_TEST(vtu_files_of_vtk_and_meshio_are_read)
{
    size_t i;
    for (i = 0; i < sizeof k_files / sizeof k_files[0]; i++) {
        char dir[512], path[600];
        cvm__vtu_mesh vm;
        cvm_status s;
        iotest_path(dir, sizeof dir, iotest_data_dir(), "interop");
        iotest_path(path, sizeof path, dir, k_files[i]);
        s = cvm__read_vtu_file(&g_ctx, path, &vm);
        ck_assert_msg(s == CVM_OK, "%s: %s", k_files[i], g_ctx.errmsg);
        assert_square(&vm, k_files[i]);
        cvm__vtu_mesh_free(&g_ctx, &vm);
        ck_assert_int_eq((int)g_a.live_blocks, 0);
    }
}
END_TEST

/* Every file again with short reads, every allocation failing in turn, and
 * every truncation of the binary ones. */
START_TEST(vtu_binary_files_survive_oom_short_reads_and_truncation)
{
    size_t i;
    for (i = 0; i < sizeof k_files / sizeof k_files[0]; i++) {
        char dir[512], path[600];
        size_t len, cut;
        char *text;
        long k;
        iotest_path(dir, sizeof dir, iotest_data_dir(), "interop");
        iotest_path(path, sizeof path, dir, k_files[i]);
        text = iotest_slurp(path, &len);
        ck_assert_ptr_nonnull(text);
        for (k = 1;; k++) {
            cvmtest_reader tr;
            cvm__reader r;
            cvm__vtu_mesh vm;
            cvm_status s;
            cvmtest_alloc_init(&g_a, k, 0);
            cvmtest_reader_init(&tr, &r, text, len, 13, -1);
            s = cvm__read_vtu(&g_ctx, &r, "t.vtu", &vm);
            ck_assert_int_eq((int)g_a.live_blocks, s == CVM_OK ? (int)g_a.live_blocks : 0);
            if (s == CVM_OK) {
                assert_square(&vm, k_files[i]);
                cvm__vtu_mesh_free(&g_ctx, &vm);
                ck_assert_int_eq((int)g_a.live_blocks, 0);
                break;
            }
            ck_assert_msg(s == CVM_E_NOMEM, "%s, allocation %ld: %s", k_files[i], k, g_ctx.errmsg);
        }
        cvmtest_alloc_init(&g_a, 0, 0);
        for (cut = 1; cut < len; cut += 1 + cut / 40) {
            cvmtest_reader tr;
            cvm__reader r;
            cvm__vtu_mesh vm;
            cvm_status s;
            cvmtest_reader_init(&tr, &r, text, cut, 0, -1);
            s = cvm__read_vtu(&g_ctx, &r, "t.vtu", &vm);
            if (s == CVM_OK)
                cvm__vtu_mesh_free(&g_ctx, &vm);
            else
                ck_assert_msg(g_ctx.errmsg[0] != '\0' && vm.tri == NULL, "%s cut at %lu", k_files[i],
                              (unsigned long)cut);
            ck_assert_int_eq((int)g_a.live_blocks, 0);
        }
        free(text);
    }
}
END_TEST

/* ---- hand-made binary payloads ---- */

static void b64(char *out, const unsigned char *in, size_t n)
{
    static const char a[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    size_t i;
    for (i = 0; i < n; i += 3) {
        unsigned v = (unsigned)in[i] << 16 | (i + 1 < n ? (unsigned)in[i + 1] << 8 : 0) |
                     (i + 2 < n ? in[i + 2] : 0);
        *out++ = a[v >> 18 & 63];
        *out++ = a[v >> 12 & 63];
        *out++ = i + 1 < n ? a[v >> 6 & 63] : '=';
        *out++ = i + 2 < n ? a[v & 63] : '=';
    }
    *out = '\0';
}

static size_t put_word(unsigned char *p, uint64_t v, int size)
{
    int i;
    for (i = 0; i < size; i++)
        p[i] = (unsigned char)(v >> (8 * i));
    return (size_t)size;
}

static const double k_xyz[9] = {0, 0, 0, 1, 0, 0, 0.25, 0.75, 0};

/* A .vtu of one triangle whose Points are format="binary" text pts and
 * VTKFile carries extra attributes. */
static cvm_status parse_points(const char *extra, const char *pts, cvm__vtu_mesh *vm)
{
    char *text = malloc(strlen(pts) + 1024);
    cvmtest_reader tr;
    cvm__reader r;
    cvm_status s;
    ck_assert_ptr_nonnull(text);
    sprintf(text,
            "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
            "byte_order=\"LittleEndian\" %s>\n<UnstructuredGrid>\n"
            "<Piece NumberOfPoints=\"3\" NumberOfCells=\"1\">\n<Points>\n"
            "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"binary\">\n%s\n"
            "</DataArray>\n</Points>\n<Cells>\n"
            "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 2</DataArray>\n"
            "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">3</DataArray>\n"
            "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">5</DataArray>\n"
            "</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n", extra, pts);
    cvmtest_reader_init(&tr, &r, text, strlen(text), 5, -1);
    s = cvm__read_vtu(&g_ctx, &r, "t.vtu", vm);
    free(text);
    return s;
}

/* Uncompressed payload: a header word of hsize bytes giving nbytes, then the coordinates. */
static void plain_payload(char *out, int hsize, uint64_t nbytes, const double *xyz)
{
    unsigned char raw[128];
    size_t n = put_word(raw, nbytes, hsize);
    memcpy(raw + n, xyz, sizeof k_xyz);
    b64(out, raw, n + sizeof k_xyz);
}

/* zlib payload as VTK writes it: header and blocks (of bs bytes) in two base64 strings. */
static void zlib_payload(char *out, int hsize, size_t bs, int corrupt)
{
    const unsigned char *src = (const unsigned char *)k_xyz;
    unsigned char hdr[128], data[512];
    size_t nb = (sizeof k_xyz + bs - 1) / bs, k, h = 0, d = 0;
    h += put_word(hdr + h, nb, hsize);
    h += put_word(hdr + h, bs, hsize);
    h += put_word(hdr + h, sizeof k_xyz % bs, hsize);
    for (k = 0; k < nb; k++) {
        uLongf clen = sizeof data - d;
        size_t len = k + 1 < nb ? bs : sizeof k_xyz - k * bs;
        ck_assert_int_eq(compress(data + d, &clen, src + k * bs, len), Z_OK);
        h += put_word(hdr + h, clen, hsize);
        d += clen;
    }
    if (corrupt)
        data[d / 2] ^= 0x5a;
    b64(out, hdr, h);
    b64(out + strlen(out), data, d);
}

static void expect(cvm_status got, cvm_status want, const char *msg, const cvm__vtu_mesh *vm)
{
    ck_assert_msg(got == want, "status %d, want %d (%s)", got, want, g_ctx.errmsg);
    ck_assert_msg(strstr(g_ctx.errmsg, msg) != NULL, "message '%s' lacks '%s'", g_ctx.errmsg, msg);
    ck_assert_msg(strncmp(g_ctx.errmsg, "t.vtu:", 6) == 0, "'%s' names no file", g_ctx.errmsg);
    ck_assert_ptr_null(vm->tri);
    ck_assert_int_eq((int)g_a.live_blocks, 0);
}

START_TEST(vtu_binary_payloads_are_decoded)
{
    char pts[1024];
    cvm__vtu_mesh vm;
    int h, bs;
    for (h = 4; h <= 8; h += 4) {
        const char *extra = h == 4 ? "header_type=\"UInt32\"" : "header_type=\"UInt64\"";
        char z[200];
        plain_payload(pts, h, sizeof k_xyz, k_xyz);
        ck_assert_msg(parse_points(extra, pts, &vm) == CVM_OK, "%s", g_ctx.errmsg);
        ck_assert(vm.p.xy[4] == 0.25 && vm.p.xy[5] == 0.75 && vm.nt == 1);
        cvm__vtu_mesh_free(&g_ctx, &vm);
        snprintf(z, sizeof z, "%s compressor=\"vtkZLibDataCompressor\"", extra);
        for (bs = 8; bs <= 96; bs += 40) { /* several blocks with a partial last; one block */
            zlib_payload(pts, h, (size_t)bs, 0);
            ck_assert_msg(parse_points(z, pts, &vm) == CVM_OK, "%s", g_ctx.errmsg);
            ck_assert(vm.p.xy[4] == 0.25 && vm.p.xy[5] == 0.75);
            cvm__vtu_mesh_free(&g_ctx, &vm);
        }
    }
    ck_assert_int_eq((int)g_a.live_blocks, 0);
}
END_TEST

START_TEST(vtu_malformed_binary_is_named)
{
    const char *z = "header_type=\"UInt32\" compressor=\"vtkZLibDataCompressor\"";
    char pts[1024];
    double bad[9];
    cvm__vtu_mesh vm;
    size_t n;
    plain_payload(pts, 4, sizeof k_xyz, k_xyz);
    n = strlen(pts);
    pts[n - 2] = '\0'; /* truncated base64 */
    expect(parse_points("", pts, &vm), CVM_E_IO_FORMAT, "t.vtu:8: Points: the data ends early", &vm);
    plain_payload(pts, 4, sizeof k_xyz, k_xyz);
    pts[10] = '*';
    expect(parse_points("", pts, &vm), CVM_E_IO_FORMAT, "t.vtu:7: Points: '*' is not a base64 character", &vm);
    plain_payload(pts, 4, 64, k_xyz); /* 8 doubles, not 9 */
    expect(parse_points("", pts, &vm), CVM_E_IO_FORMAT, "Points: 64 bytes of Float64, expected 9 values", &vm);
    plain_payload(pts, 4, 1000000, k_xyz);
    expect(parse_points("", pts, &vm), CVM_E_IO_FORMAT, "gives 1000000 bytes, more than the file holds", &vm);
    memcpy(bad, k_xyz, sizeof bad);
    bad[4] = nan("");
    plain_payload(pts, 4, sizeof k_xyz, bad);
    expect(parse_points("", pts, &vm), CVM_E_INPUT_NONFINITE, "t.vtu:6: Points: entry 4 (from 0) is not a finite number", &vm);
    bad[4] = -HUGE_VAL;
    plain_payload(pts, 4, sizeof k_xyz, bad);
    expect(parse_points("", pts, &vm), CVM_E_INPUT_NONFINITE, "entry 4", &vm);
    zlib_payload(pts, 4, 32, 1);
    expect(parse_points(z, pts, &vm), CVM_E_IO_FORMAT, "does not inflate", &vm);
    zlib_payload(pts, 4, 32, 0);
    memcpy(pts, "/////", 5); /* nblocks ~ 2^32 */
    expect(parse_points(z, pts, &vm), CVM_E_IO_FORMAT, "Points: bad compression header", &vm);
    zlib_payload(pts, 4, 32, 0);
    pts[strlen(pts) - 6] = '\0';
    expect(parse_points(z, pts, &vm), CVM_E_IO_FORMAT, "Points: ", &vm);
    plain_payload(pts, 4, sizeof k_xyz, k_xyz);
    expect(parse_points("compressor=\"vtkLZ4DataCompressor\"", pts, &vm), CVM_E_UNSUPPORTED,
           "compressor=\"vtkLZ4DataCompressor\" is not read", &vm);
    expect(parse_points("header_type=\"UInt16\"", pts, &vm), CVM_E_UNSUPPORTED,
           "header_type=\"UInt16\" is not read", &vm);
}
END_TEST

/* Integer arrays in binary: UInt64 beyond INT32_MAX, a Float connectivity, appended offsets. */
START_TEST(vtu_binary_integers_and_appended_offsets_are_checked)
{
    static const char head[] =
        "<VTKFile type=\"UnstructuredGrid\" byte_order=\"LittleEndian\" header_type=\"UInt32\">\n"
        "<UnstructuredGrid><Piece NumberOfPoints=\"3\" NumberOfCells=\"1\">\n"
        "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0 0 1 0"
        "</DataArray></Points>\n<Cells>\n"
        "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">3</DataArray>\n"
        "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">5</DataArray>\n";
    char text[2048], enc[256];
    unsigned char raw[64];
    size_t n;
    int i;
    for (i = 0; i < 4; i++) {
        cvmtest_reader tr;
        cvm__reader r;
        cvm__vtu_mesh vm;
        cvm_status s;
        n = put_word(raw, i == 1 ? 12 : 24, 4);
        n += put_word(raw + n, 0, 8);
        n += put_word(raw + n, i == 0 ? (uint64_t)1 << 40 : 1, 8);
        n += put_word(raw + n, 2, 8);
        b64(enc, raw, i == 1 ? 4 + 12 : n);
        if (i < 2)
            snprintf(text, sizeof text, "%s<DataArray type=\"%s\" Name=\"connectivity\" format=\"binary\">%s"
                     "</DataArray>\n</Cells></Piece></UnstructuredGrid></VTKFile>\n", head,
                     i == 0 ? "UInt64" : "Float32", enc);
        else
            snprintf(text, sizeof text, "%s<DataArray type=\"Int64\" Name=\"connectivity\" "
                     "format=\"appended\" offset=\"%d\"/>\n</Cells></Piece></UnstructuredGrid>\n"
                     "<AppendedData encoding=\"base64\">\n _%s\n</AppendedData></VTKFile>\n", head,
                     i == 2 ? 0 : 9999, enc);
        cvmtest_reader_init(&tr, &r, text, strlen(text), 0, -1);
        s = cvm__read_vtu(&g_ctx, &r, "t.vtu", &vm);
        if (i == 2) {
            ck_assert_msg(s == CVM_OK, "%s", g_ctx.errmsg);
            ck_assert(vm.tri[1] == 1 && vm.tri[2] == 2);
            cvm__vtu_mesh_free(&g_ctx, &vm);
            continue;
        }
        expect(s, CVM_E_IO_FORMAT, i == 0 ? "t.vtu:7: connectivity: entry 1 (from 0) of type UInt64 is not an integer" :
               i == 1 ? "connectivity: entry 0 (from 0) of type Float32 is not an integer" :
               "t.vtu:7: connectivity: missing or bad offset=", &vm);
    }
}
END_TEST

TCase *io_vtu_data_tcase(void)
{
    TCase *tc = tcase_create("vtu_data");
    tcase_add_checked_fixture(tc, setup, NULL);
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, vtu_files_of_vtk_and_meshio_are_read);
    tcase_add_test(tc, vtu_binary_files_survive_oom_short_reads_and_truncation);
    tcase_add_test(tc, vtu_binary_payloads_are_decoded);
    tcase_add_test(tc, vtu_malformed_binary_is_named);
    tcase_add_test(tc, vtu_binary_integers_and_appended_offsets_are_checked);
    return tc;
}
