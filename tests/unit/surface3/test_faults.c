/* test_faults.c - the 3D surface readers on malformed files (status and a message naming file:line and the item), out of memory at every allocation, and short reads and read errors at every byte. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "support/failing_reader.h"
#include "surface3/surface3_tests.h"

#define TET_OFF "OFF\n4 4 0\n1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n"
#define TET_FACES "3 0 1 2\n3 0 2 3\n3 0 3 1\n3 1 3 2\n"
#define TET_NODES "4 3 0 0\n1 1 1 1\n2 1 -1 -1\n3 -1 1 -1\n4 -1 -1 1\n"
#define TET_FACETS "4 1\n1 0 1\n3 1 2 3\n1 0 1\n3 1 3 4\n1 0 1\n3 1 4 2\n1 0 1\n3 2 4 3\n"
#define STL_FACET(v) "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex " v "\nendloop\nendfacet\n"

typedef struct bad_case {
    const char *what, *name, *text;
    cvm_status status;
    const char *msg1, *msg2;
} bad_case;

static const bad_case k_bad[] = {
    {"off truncated", "t.off", TET_OFF "3 0 1 2\n3 0 2 3\n", CVM_E_IO_FORMAT, "t.off:8:", "face 2 of 4"},
    {"off bad count", "t.off", "OFF\n4 -1 0\n", CVM_E_IO_FORMAT, "t.off:2:", "negative face count"},
    {"off too many faces", "t.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n", CVM_E_IO_FORMAT,
     "t.off:7:", "unexpected content"},
    {"off bad index", "t.off", TET_OFF "3 0 1 2\n3 0 2 4\n3 0 3 1\n3 1 3 2\n", CVM_E_IO_FORMAT, "t.off:8:",
     "face 1 names point 4, but points are numbered 0..3"},
    {"off nan", "t.off", "OFF\n4 4 0\n1 1 1\n1 nan -1\n", CVM_E_INPUT_NONFINITE, "t.off:4:", "point 1"},
    {"off huge count", "t.off", "OFF\n99999999999 1 0\n", CVM_E_TOO_LARGE, "t.off:2:", "point count"},
    {"off colour format", "t.off", "COFF\n", CVM_E_UNSUPPORTED, "t.off:1:", "COFF"},
    {"stl inf", "t.stl", "solid x\n" STL_FACET("0 inf 0") "endsolid x\n", CVM_E_INPUT_NONFINITE, "t.stl:6:",
     "facet 1"},
    {"stl no endsolid", "t.stl", "solid x\n" STL_FACET("0 1 0"), CVM_E_IO_FORMAT, "t.stl:", "no 'endsolid'"},
    {"stl quad", "t.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\n"
     "vertex 0 1 0\nendloop\nendfacet\nendsolid\n", CVM_E_IO_FORMAT, "t.stl:7:", "more than 3 vertices"},
    {"stl garbage", "t.stl", "hello", CVM_E_IO_FORMAT, "t.stl", "not an STL file"},
    {"poly bad index", "t.poly", TET_NODES "4 1\n1 0 1\n3 1 2 3\n1 0 1\n3 1 3 5\n", CVM_E_IO_FORMAT,
     "t.poly:10:", "facet 2 names point 5, but points are numbered 1..4"},
    {"poly truncated", "t.poly", TET_NODES "4 1\n1 0 1\n3 1 2 3\n", CVM_E_IO_FORMAT, "t.poly:",
     "facet 2 of 4"},
    {"poly 2d", "t.poly", "4 2 0 0\n", CVM_E_IO_FORMAT, "t.poly:1:", "dimension 2"},
    {"poly nan region", "t.poly", TET_NODES TET_FACETS "0\n1\n1 0 0 nan 1\n", CVM_E_INPUT_NONFINITE,
     "t.poly:17:", "region 1"},
    {"poly point sequence", "t.poly", "2 3 0 0\n1 0 0 0\n3 1 0 0\n", CVM_E_IO_FORMAT, "t.poly:3:",
     "out of sequence"},
    {"smesh fields", "t.smesh", TET_NODES "4 1\n3 1 2 3 1\n3 1 3\n", CVM_E_IO_FORMAT, "t.smesh:8:",
     "facet 2"},
};

START_TEST(malformed_files_give_status_and_line)
{
    const bad_case *c = &k_bad[_i];
    cvmtest_alloc a;
    cvm__ctx ctx;
    cvm__surf3 s;
    cvm_status st;
    cvmtest_alloc_init(&a, 0, 0);
    s3test_ctx(&ctx, &a);
    st = s3test_parse(&ctx, c->name, c->text, 0, &s);
    ck_assert_msg(st == c->status, "%s: status %d, expected %d (%s)", c->what, (int)st, (int)c->status,
                  ctx.errmsg);
    ck_assert_msg(strstr(ctx.errmsg, c->msg1) && strstr(ctx.errmsg, c->msg2),
                  "%s: message '%s' lacks '%s' or '%s'", c->what, ctx.errmsg, c->msg1, c->msg2);
    ck_assert_uint_eq(s.np, 0);
    ck_assert_ptr_null(s.xyz);
    ck_assert_int_eq(a.live_blocks, 0);
}
END_TEST

/* A binary STL header with a count that does not match the length. */
START_TEST(binary_stl_with_wrong_length_names_the_sizes)
{
    unsigned char buf[84 + 50 + 10];
    cvm__ctx ctx;
    cvm__surf3 s;
    memset(buf, 0, sizeof buf);
    buf[80] = 2; /* 2 facets need 184 bytes; the file has 144 */
    cvm__ctx_init_default(&ctx);
    ck_assert_int_eq(s3test_parse(&ctx, "b.stl", (const char *)buf, sizeof buf, &s), CVM_E_IO_FORMAT);
    ck_assert_ptr_nonnull(strstr(ctx.errmsg, "b.stl: byte 80: binary STL with 2 facets"));
    ck_assert_ptr_nonnull(strstr(ctx.errmsg, "has 144"));
}
END_TEST

START_TEST(binary_stl_nan_names_the_byte_and_facet)
{
    unsigned char buf[84 + 50];
    unsigned char nan_le[4] = {0, 0, 0xc0, 0x7f};
    cvm__ctx ctx;
    cvm__surf3 s;
    memset(buf, 0, sizeof buf);
    buf[80] = 1;
    memcpy(buf + 84 + 12 + 4 * 4, nan_le, 4); /* vertex 2, y */
    cvm__ctx_init_default(&ctx);
    ck_assert_int_eq(s3test_parse(&ctx, "b.stl", (const char *)buf, sizeof buf, &s), CVM_E_INPUT_NONFINITE);
    ck_assert_msg(strstr(ctx.errmsg, "byte 112: facet 1 has a non-finite y in vertex 2") != NULL, "%s",
                  ctx.errmsg);
}
END_TEST

/* The small inputs of the fault sweeps: one of each format. */
static const char *k_files[] = {"tetra.off", "tetra.stl", "tetra_binary.stl", "tetra.poly", "two_cubes.smesh",
                                "two_cubes.poly"};
#define N_FILES (sizeof k_files / sizeof k_files[0])

static char *load(const char *name, size_t *len)
{
    char path[4096];
    char *text;
    s3test_path(path, sizeof path, name);
    text = s3test_slurp(path, len);
    ck_assert_msg(text != NULL, "cannot read %s", path);
    return text;
}

/* Allocation i fails, for every i, transient and persistent: CVM_E_NOMEM and
 * nothing leaked, until a run meets no failure and reads the whole surface. */
START_TEST(readers_survive_out_of_memory_at_every_allocation)
{
    size_t len;
    char *text = load(k_files[_i], &len);
    int persistent;
    for (persistent = 0; persistent <= 1; persistent++) {
        long i;
        for (i = 1;; i++) {
            cvmtest_alloc a;
            cvm__ctx ctx;
            cvm__surf3 s;
            cvm_status st;
            cvmtest_alloc_init(&a, i, persistent);
            s3test_ctx(&ctx, &a);
            st = s3test_parse(&ctx, k_files[_i], text, len, &s);
            if (a.n_failed == 0) {
                ck_assert_msg(st == CVM_OK, "%s: %s", k_files[_i], ctx.errmsg);
                ck_assert_uint_gt(s.npoly, 0);
                cvm__surf3_free(&ctx, &s);
                ck_assert_int_eq(a.live_blocks, 0);
                ck_assert_int_gt(i, 3);
                break;
            }
            ck_assert_msg(st == CVM_E_NOMEM, "%s: allocation %ld: status %d (%s)", k_files[_i], i, (int)st,
                          ctx.errmsg);
            ck_assert_int_eq(a.live_blocks, 0);
        }
    }
    free(text);
}
END_TEST

/* Short reads of 1..7 bytes give the same surface; a read error after any
 * number of bytes is an error (never CVM_OK) and leaks nothing. */
START_TEST(readers_handle_short_reads_and_read_errors)
{
    size_t len, k, chunk;
    char *text = load(k_files[_i], &len);
    cvm__surf3 ref;
    cvm__ctx ctx0;
    cvm__ctx_init_default(&ctx0);
    ck_assert_int_eq(s3test_parse(&ctx0, k_files[_i], text, len, &ref), CVM_OK);
    for (chunk = 1; chunk <= 7; chunk++) {
        cvmtest_reader tr;
        cvm__reader r;
        cvm__surf3 s;
        cvm_status st;
        cvmtest_reader_init(&tr, &r, text, len, chunk, -1);
        if (strstr(k_files[_i], ".off"))
            st = cvm__read_off(&ctx0, &r, "x.off", &s);
        else if (strstr(k_files[_i], ".stl"))
            st = cvm__read_stl(&ctx0, &r, "x.stl", &s);
        else
            st = cvm__read_tetpoly(&ctx0, &r, "x", strstr(k_files[_i], ".smesh") != NULL, NULL, &s);
        ck_assert_int_eq(st, CVM_OK);
        ck_assert_uint_eq(s.np, ref.np);
        ck_assert_uint_eq(s.npoly, ref.npoly);
        ck_assert_int_eq(memcmp(s.xyz, ref.xyz, 3 * s.np * sizeof(double)), 0);
        cvm__surf3_free(&ctx0, &s);
    }
    for (k = 0; k <= len; k += 1 + len / 400) {
        cvmtest_alloc a;
        cvm__ctx ctx;
        cvmtest_reader tr;
        cvm__reader r;
        cvm__surf3 s;
        cvm_status st;
        cvmtest_alloc_init(&a, 0, 0);
        s3test_ctx(&ctx, &a);
        cvmtest_reader_init(&tr, &r, text, len, 3, (long)k);
        if (strstr(k_files[_i], ".off"))
            st = cvm__read_off(&ctx, &r, "x.off", &s);
        else if (strstr(k_files[_i], ".stl"))
            st = cvm__read_stl(&ctx, &r, "x.stl", &s);
        else
            st = cvm__read_tetpoly(&ctx, &r, "x", strstr(k_files[_i], ".smesh") != NULL, NULL, &s);
        ck_assert_msg(st == CVM_E_IO_READ, "%s: read error after %lu bytes: status %d (%s)", k_files[_i],
                      (unsigned long)k, (int)st, ctx.errmsg);
        ck_assert_int_eq(a.live_blocks, 0);
    }
    cvm__surf3_free(&ctx0, &ref);
    free(text);
}
END_TEST

START_TEST(file_reader_refuses_unknown_extensions_and_missing_files)
{
    cvm__ctx ctx;
    cvm__surf3 s;
    cvm__ctx_init_default(&ctx);
    ck_assert_int_eq(cvm__read_surface3_file(&ctx, "x.obj", &s), CVM_E_UNSUPPORTED);
    ck_assert_ptr_nonnull(strstr(ctx.errmsg, ".off, .stl, .poly or .smesh"));
    ck_assert_int_eq(cvm__read_surface3_file(&ctx, "/nonexistent/x.off", &s), CVM_E_IO_OPEN);
    ck_assert_int_eq(cvm__read_surface3_file(&ctx, "/nonexistent/x.poly", &s), CVM_E_IO_OPEN);
}
END_TEST

TCase *surface3_faults_tcase(void)
{
    TCase *tc = tcase_create("faults");
    tcase_set_timeout(tc, 120);
    tcase_add_loop_test(tc, malformed_files_give_status_and_line, 0, (int)(sizeof k_bad / sizeof k_bad[0]));
    tcase_add_test(tc, binary_stl_with_wrong_length_names_the_sizes);
    tcase_add_test(tc, binary_stl_nan_names_the_byte_and_facet);
    tcase_add_loop_test(tc, readers_survive_out_of_memory_at_every_allocation, 0, (int)N_FILES);
    tcase_add_loop_test(tc, readers_handle_short_reads_and_read_errors, 0, (int)N_FILES);
    tcase_add_test(tc, file_reader_refuses_unknown_extensions_and_missing_files);
    return tc;
}
