/* test_pslg_build.c - the engine's PSLG -> constrained triangulation (lib/delaunay/pslg_build.c) and slot reordering (tri2.c). */
#include <string.h>

#include "delaunay/delaunay_tests.h"
#include "delaunay/delaunay_internal.h"

/* The unit square split by its diagonal 0-2, a duplicate of point 0 last. */
static const double sq_xy[10] = {0, 0, 1, 0, 1, 1, 0, 1, 0, 0};
static const int32_t sq_seg[10] = {0, 1, 1, 2, 2, 3, 3, 0, 0, 2};

static void square_input(cvm__cdt_input *in)
{
    memset(in, 0, sizeof *in);
    in->xy = sq_xy;
    in->np = 5;
    in->seg = sq_seg;
    in->nseg = 5;
}

static size_t domain_count(const cvm__tri2 *T)
{
    size_t t, n = 0;
    for (t = 0; t < T->nt; t++)
        n += cvm__tri2_in_domain(T, (int32_t)t);
    return n;
}

/* Input errors come back as faults naming the items, with no message: the
 * API words them (in the file's terms when read from one). */
START_TEST(input_faults_name_items_without_a_message)
{
    static const int32_t cross[4] = {0, 2, 1, 3};
    static const double outside[2] = {5, 5};
    cvm__ctx ctx;
    cvm__tri2 T;
    cvm__cdt_input in;
    cvm__cdt_out out;
    cvm__cdt_fault f;
    cvm__ctx_init_default(&ctx);

    square_input(&in);
    in.reject_duplicates = 1;
    memset(&out, 0, sizeof out);
    cvm__tri2_init(&T, &ctx);
    ck_assert_int_eq(cvm__cdt_build(&T, &in, &out, &f), CVM_E_INPUT_DUPLICATE);
    ck_assert_int_eq(f.kind, CVM__CDT_FAULT_DUPLICATE);
    ck_assert_uint_eq(f.item, 4);
    ck_assert_uint_eq(f.other, 0);
    ck_assert_str_eq(ctx.errmsg, "");
    cvm__tri2_destroy(&T);

    square_input(&in);
    in.seg = cross;
    in.nseg = 2;
    cvm__tri2_init(&T, &ctx);
    ck_assert_int_eq(cvm__cdt_build(&T, &in, &out, &f), CVM_E_INPUT_INTERSECTING);
    ck_assert_int_eq(f.kind, CVM__CDT_FAULT_CROSSING);
    ck_assert_uint_eq(f.item, 1);
    ck_assert_uint_eq(f.other, 0);
    ck_assert_str_eq(ctx.errmsg, "");
    cvm__tri2_destroy(&T);

    square_input(&in);
    in.holes = outside;
    in.nholes = 1;
    cvm__tri2_init(&T, &ctx);
    ck_assert_int_eq(cvm__cdt_build(&T, &in, &out, &f), CVM_E_INPUT_OUTSIDE);
    ck_assert_int_eq(f.kind, CVM__CDT_FAULT_HOLE_OUTSIDE);
    ck_assert_uint_eq(f.item, 0);
    ck_assert_str_eq(ctx.errmsg, "");
    cvm__tri2_destroy(&T);

    cvm__free(&ctx, out.input_map);
    cvm__free(&ctx, out.vmark);
    cvm__free(&ctx, out.vattr);
}
END_TEST

/* Crossing segments split with split = 1: the crossing vertex takes the
 * marker of the segment recovered second and attributes interpolated along
 * it; duplicates merge; the boundary vertices of marker 0 take their segment's. */
START_TEST(split_crossing_takes_segment_data)
{
    static const int32_t seg[12] = {0, 1, 1, 2, 2, 3, 3, 0, 0, 2, 1, 3};
    static const int32_t smark[6] = {1, 1, 1, 1, 7, 9};
    static const double attr[5] = {0, 2, 4, 6, 8};
    cvm__ctx ctx;
    cvm__tri2 T;
    cvm__cdt_input in;
    cvm__cdt_out out;
    cvm__cdt_fault f;
    int32_t x;
    cvm__ctx_init_default(&ctx);
    square_input(&in);
    in.seg = seg;
    in.nseg = 6;
    in.smark = smark;
    in.pattr = attr;
    in.nattr = 1;
    in.split = 1;
    memset(&out, 0, sizeof out);
    cvm__tri2_init(&T, &ctx);
    ck_assert_msg(cvm__cdt_build(&T, &in, &out, &f) == CVM_OK, "%s", ctx.errmsg);
    ck_assert_uint_eq(out.n_dup, 1);
    ck_assert_int_eq(out.input_map[4], out.input_map[0]);
    ck_assert_uint_eq(T.nv, 5); /* 4 distinct points and the crossing */
    x = 4;
    ck_assert(T.xy[2 * x] == 0.5 && T.xy[2 * x + 1] == 0.5);
    ck_assert_int_eq(out.vmark[x], 9);
    ck_assert(out.vattr[x] == 0.5 * 2 + 0.5 * 6);
    ck_assert_int_eq(out.vmark[out.input_map[2]], 1);
    ck_assert_uint_eq(domain_count(&T), 4);
    cvm__tri2_destroy(&T);
    cvm__free(&ctx, out.input_map);
    cvm__free(&ctx, out.vmark);
    cvm__free(&ctx, out.vattr);
}
END_TEST

/* Reordering puts the chosen slots first, rotated, and keeps the structure valid. */
START_TEST(reorder_moves_and_rotates_slots)
{
    cvm__ctx ctx;
    cvm__tri2 T;
    cvm__cdt_input in;
    cvm__cdt_out out;
    cvm__cdt_fault f;
    int32_t slot[2], v[2][3];
    uint8_t rot[2] = {1, 2};
    size_t t, n = 0;
    int j;
    cvm__ctx_init_default(&ctx);
    square_input(&in);
    memset(&out, 0, sizeof out);
    cvm__tri2_init(&T, &ctx);
    ck_assert_int_eq(cvm__cdt_build(&T, &in, &out, &f), CVM_OK);
    for (t = T.nt; t-- > 0 && n < 2;) /* the domain triangles, last first */
        if (cvm__tri2_in_domain(&T, (int32_t)t))
            slot[n++] = (int32_t)t;
    ck_assert_uint_eq(n, 2);
    for (n = 0; n < 2; n++)
        for (j = 0; j < 3; j++)
            v[n][j] = T.tv[3 * (size_t)slot[n] + (size_t)j];
    ck_assert_int_eq(cvm__tri2_reorder(&T, slot, rot, 2), CVM_OK);
    for (n = 0; n < 2; n++)
        for (j = 0; j < 3; j++)
            ck_assert_int_eq(T.tv[3 * n + (size_t)j], v[n][(j + rot[n]) % 3]);
    ck_assert_uint_eq(T.n_dead, 0);
    ck_assert_msg(cvm__tri2_check(&T) == CVM_OK, "%s", ctx.errmsg);
    ck_assert_int_eq(cvm__cdt_check_chains(&T, sq_seg, 5, out.input_map), CVM_OK);
    cvm__tri2_destroy(&T);
    cvm__free(&ctx, out.input_map);
    cvm__free(&ctx, out.vmark);
    cvm__free(&ctx, out.vattr);
}
END_TEST

TCase *delaunay_pslg_build_tcase(void)
{
    TCase *tc = tcase_create("pslg_build");
    tcase_add_test(tc, input_faults_name_items_without_a_message);
    tcase_add_test(tc, split_crossing_takes_segment_data);
    tcase_add_test(tc, reorder_moves_and_rotates_slots);
    return tc;
}
