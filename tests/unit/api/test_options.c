/* test_options.c - every option key: bounds, defaults, accepted and rejected values, messages. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "api/api_tests.h"
#include "cvmesh.h"

static const cvm_option k_keys[] = {
    CVM_OPT_REJECT_DUPLICATES, CVM_OPT_SPLIT_INTERSECTIONS, CVM_OPT_KEEP_CONVEX_HULL,
    CVM_OPT_CONVEX_HULL_IF_NO_SEGMENTS, CVM_OPT_MIN_ANGLE_DEG, CVM_OPT_MAX_AREA,
    CVM_OPT_ENCROACH_LENS, CVM_OPT_KEEP_SEGMENT_VERTICES, CVM_OPT_MARCH_SEGMENTS,
    CVM_OPT_SWAP, CVM_OPT_SMOOTH_SWEEPS, CVM_OPT_RESTORE_DELAUNAY, CVM_OPT_SMOOTH_METHOD,
    CVM_OPT_RELAX_SWEEPS, CVM_OPT_AFLR_SMOOTH_LAYERS,
    CVM_OPT_TIME_LIMIT_S, CVM_OPT_SEED, CVM_OPT_MAX_STEINER, CVM_OPT_THREADS,
    CVM_OPT_DUAL_SOLVER, CVM_OPT_DUAL_MAX_SWEEPS, CVM_OPT_DUAL_MIN_ANGLE_DEG,
    CVM_OPT_DUAL_CUCKOO_BUDGET, CVM_OPT_DUAL_PATTERN_BUDGET, CVM_OPT_DUAL_MARGIN,
    CVM_OPT_DUAL_TARGET_ANGLE_DEG, CVM_OPT_DUAL_KEEP_INPUT_POINTS, CVM_OPT_DUAL_LAYER_PRIORITY,
    CVM_OPT_DUAL_TOPOLOGY, CVM_OPT_DUAL_PREPASS, CVM_OPT_DUAL_MAXMIN_ROUNDS,
    CVM_OPT_DUAL_MAXMIN_TRIALS, CVM_OPT_DUAL_MERGE_TOL, CVM_OPT_SVG_WINDOW_XMIN,
    CVM_OPT_SVG_WINDOW_YMIN, CVM_OPT_SVG_WINDOW_XMAX, CVM_OPT_SVG_WINDOW_YMAX, CVM_OPT_VTU_ENCODING,
    CVM_OPT_VTU_MERGED_CELLS,
    CVM_OPT_GEN3_GRADING, CVM_OPT_GEN3_LAYERS, CVM_OPT_GEN3_FREESPACE, CVM_OPT_GEN3_SIZE_FROM_SURFACE,
    CVM_OPT_GEN3_SURFACE, CVM_OPT_GEN3_OCTREE_SPLIT_HANGING,
    CVM_OPT_DUAL3_MAX_SWEEPS, CVM_OPT_DUAL3_MIN_DIHEDRAL_DEG, CVM_OPT_DUAL3_BUDGET,
    CVM_OPT_DUAL3_MARGIN, CVM_OPT_DUAL3_SLIDE_BOUNDARY, CVM_OPT_DUAL3_MERGE_TOL, CVM_OPT_DUAL3_FLIPS,
    CVM_OPT_DUAL3_SOLVER, CVM_OPT_DUAL3_CUCKOO_BUDGET, CVM_OPT_DUAL3_ESCALATE,
    CVM_OPT_QUAD_P, CVM_OPT_QUAD_LBFGS_MEMORY, CVM_OPT_QUAD_GRADIENT_TOL, CVM_OPT_QUAD_MAX_ITERATIONS,
    CVM_OPT_QUAD_RECOMBINE, CVM_OPT_QUAD_MIN_QUALITY, CVM_OPT_QUAD_CLIP, CVM_OPT_QUAD_CELLWISE_METRIC,
    CVM_OPT_QUAD_RELOCATIONS, CVM_OPT_QUAD_MEAN_METRIC_VORONOI, CVM_OPT_QUAD_INITIAL_SITES,
    CVM_OPT_QUAD_SMOOTH, CVM_OPT_QUAD_ALL_QUAD, CVM_OPT_QUAD_CYCLES};
#define N_KEYS (sizeof k_keys / sizeof k_keys[0])

static cvm_mesh *new_mesh(void)
{
    cvm_mesh *m = NULL;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_ptr_nonnull(m);
    return m;
}

/* 1 if msg quotes the number v, as %g, %.15g or %.17g would print it. */
static int quotes(const char *msg, double v)
{
    static const char *const fmts[] = {"%g", "%.15g", "%.17g"};
    char buf[64];
    size_t i;
    for (i = 0; i < sizeof fmts / sizeof fmts[0]; i++) {
        snprintf(buf, sizeof buf, fmts[i], v);
        if (strstr(msg, buf))
            return 1;
    }
    return 0;
}

/* set_option(key, v) must fail with CVM_E_OPTION_RANGE, quote the bounds, name the
 * option as the error item, and leave the value unchanged. */
static void expect_rejected(cvm_mesh *m, cvm_option key, const cvm_bounds *b, double v)
{
    double before = -1, after = -2;
    cvm_entity kind = CVM_ENT_NONE;
    int64_t index = -1;
    const char *msg;
    ck_assert_int_eq(cvm_mesh_get_option(&before, m, key), CVM_OK);
    ck_assert_msg(cvm_mesh_set_option(m, key, v) == CVM_E_OPTION_RANGE,
                  "option %d accepted %.17g outside [%.17g, %.17g] (integer %d)", (int)key, v,
                  b->lo, b->hi, (int)b->is_integer);
    msg = cvm_mesh_errmsg(m);
    ck_assert_ptr_nonnull(msg);
    ck_assert_msg(quotes(msg, b->lo) && quotes(msg, b->hi),
                  "message for option %d does not quote its bounds [%.17g, %.17g]: \"%s\"",
                  (int)key, b->lo, b->hi, msg);
    ck_assert_int_eq(cvm_mesh_error_item(&kind, &index, m), CVM_OK);
    ck_assert_int_eq(kind, CVM_ENT_OPTION);
    ck_assert_int_eq(index, (int64_t)key);
    ck_assert_int_eq(cvm_mesh_get_option(&after, m, key), CVM_OK);
    ck_assert_msg(after == before, "rejected value changed option %d", (int)key);
}

/* Every key the library knows is in k_keys, so the tests below cover it: a new
 * option must be added there. */
START_TEST(option_key_list_of_the_tests_is_complete)
{
    int key;
    for (key = -10; key < 3000; key++) {
        cvm_bounds b;
        size_t i;
        int listed = 0;
        if (cvm_option_bounds(&b, (cvm_option)key) != CVM_OK)
            continue;
        for (i = 0; i < N_KEYS; i++)
            listed |= (int)k_keys[i] == key;
        ck_assert_msg(listed, "option key %d has bounds but is missing from k_keys in "
                      "tests/unit/api/test_options.c", key);
    }
    for (key = 0; key < (int)N_KEYS; key++) {
        cvm_bounds b;
        ck_assert_msg(cvm_option_bounds(&b, k_keys[key]) == CVM_OK, "listed key %d is unknown",
                      (int)k_keys[key]);
    }
}
END_TEST

START_TEST(option_bounds_are_consistent_for_every_key)
{
    size_t i;
    for (i = 0; i < N_KEYS; i++) {
        cvm_bounds b;
        ck_assert_int_eq(cvm_option_bounds(&b, k_keys[i]), CVM_OK);
        ck_assert_msg(isfinite(b.lo) && isfinite(b.hi) && isfinite(b.def),
                      "option %d: non-finite bounds", (int)k_keys[i]);
        ck_assert_msg(b.lo <= b.def && b.def <= b.hi, "option %d: default %g outside [%g, %g]",
                      (int)k_keys[i], b.def, b.lo, b.hi);
        ck_assert_msg(b.is_integer == 0 || b.is_integer == 1, "option %d: is_integer %d",
                      (int)k_keys[i], (int)b.is_integer);
        if (b.is_integer)
            ck_assert_msg(b.lo == floor(b.lo) && b.hi == floor(b.hi) && b.def == floor(b.def),
                          "integer option %d has fractional bounds", (int)k_keys[i]);
    }
    ck_assert_int_eq(cvm_option_bounds(NULL, CVM_OPT_SEED), CVM_E_NULL_ARG);
}
END_TEST

START_TEST(fresh_handle_holds_every_default)
{
    cvm_mesh *m = new_mesh();
    size_t i;
    for (i = 0; i < N_KEYS; i++) {
        cvm_bounds b;
        double v = -12345;
        ck_assert_int_eq(cvm_option_bounds(&b, k_keys[i]), CVM_OK);
        ck_assert_int_eq(cvm_mesh_get_option(&v, m, k_keys[i]), CVM_OK);
        ck_assert_msg(v == b.def, "option %d: fresh value %g, default %g", (int)k_keys[i], v, b.def);
    }
    cvm_mesh_free(m);
}
END_TEST

START_TEST(option_accepts_its_bounds_and_default)
{
    cvm_mesh *m = new_mesh();
    size_t i;
    for (i = 0; i < N_KEYS; i++) {
        cvm_bounds b;
        double v;
        double vals[3];
        int k;
        ck_assert_int_eq(cvm_option_bounds(&b, k_keys[i]), CVM_OK);
        vals[0] = b.lo;
        vals[1] = b.hi;
        vals[2] = b.def;
        for (k = 0; k < 3; k++) {
            ck_assert_msg(cvm_mesh_set_option(m, k_keys[i], vals[k]) == CVM_OK,
                          "option %d rejected %.17g: %s", (int)k_keys[i], vals[k],
                          cvm_mesh_errmsg(m));
            ck_assert_str_eq(cvm_mesh_errmsg(m), "");
            ck_assert_int_eq(cvm_mesh_get_option(&v, m, k_keys[i]), CVM_OK);
            ck_assert(v == vals[k]);
        }
    }
    cvm_mesh_free(m);
}
END_TEST

START_TEST(option_rejects_out_of_range_nan_inf_and_fractions)
{
    cvm_mesh *m = new_mesh();
    size_t i;
    for (i = 0; i < N_KEYS; i++) {
        cvm_bounds b;
        ck_assert_int_eq(cvm_option_bounds(&b, k_keys[i]), CVM_OK);
        expect_rejected(m, k_keys[i], &b, nextafter(b.hi, INFINITY));
        expect_rejected(m, k_keys[i], &b, nextafter(b.lo, -INFINITY));
        expect_rejected(m, k_keys[i], &b, b.hi + 1.0 + fabs(b.hi));
        expect_rejected(m, k_keys[i], &b, NAN);
        expect_rejected(m, k_keys[i], &b, INFINITY);
        expect_rejected(m, k_keys[i], &b, -INFINITY);
        expect_rejected(m, k_keys[i], &b, -DBL_MAX);
        if (b.is_integer && b.lo + 0.5 <= b.hi)
            expect_rejected(m, k_keys[i], &b, b.lo + 0.5);
    }
    cvm_mesh_free(m);
}
END_TEST

START_TEST(unknown_option_key_is_rejected)
{
    static const int bad[] = {0, 1, 50, 99, -1, 12345, 100000, 2147483647};
    cvm_mesh *m = new_mesh();
    size_t i;
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        cvm_bounds b;
        double v;
        ck_assert_int_eq(cvm_option_bounds(&b, (cvm_option)bad[i]), CVM_E_OPTION_KEY);
        ck_assert_int_eq(cvm_mesh_set_option(m, (cvm_option)bad[i], 0.0), CVM_E_OPTION_KEY);
        ck_assert_msg(cvm_mesh_errmsg(m)[0] != '\0', "no message for unknown key %d", bad[i]);
        ck_assert_int_eq(cvm_mesh_get_option(&v, m, (cvm_option)bad[i]), CVM_E_OPTION_KEY);
    }
    cvm_mesh_free(m);
}
END_TEST

START_TEST(option_calls_reject_null)
{
    cvm_mesh *m = new_mesh();
    double v;
    ck_assert_int_eq(cvm_mesh_set_option(NULL, CVM_OPT_SEED, 1), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_get_option(&v, NULL, CVM_OPT_SEED), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_get_option(NULL, m, CVM_OPT_SEED), CVM_E_NULL_ARG);
    cvm_mesh_free(m);
}
END_TEST

TCase *api_options_tcase(void)
{
    TCase *tc = tcase_create("options");
    tcase_add_test(tc, option_key_list_of_the_tests_is_complete);
    tcase_add_test(tc, option_bounds_are_consistent_for_every_key);
    tcase_add_test(tc, fresh_handle_holds_every_default);
    tcase_add_test(tc, option_accepts_its_bounds_and_default);
    tcase_add_test(tc, option_rejects_out_of_range_nan_inf_and_fractions);
    tcase_add_test(tc, unknown_option_key_is_rejected);
    tcase_add_test(tc, option_calls_reject_null);
    return tc;
}
