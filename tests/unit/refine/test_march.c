/* test_march.c - marching segments with the sizing: pieces graded across segment ends. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "refine/refine_tests.h"
#include "support/mesh_oracle.h"

/* A 10 x 5 rectangle whose bottom side starts with a segment of length 0.01
 * followed by one of length 0.01 x jump, then the rest of the side: adjacent
 * input segments that jump by the given ratio at a fixed input vertex. */
static void set_jump_rectangle(cvm_mesh *m, double jump)
{
    double xy[12];
    cvm_index seg[12];
    int k;
    xy[0] = 0, xy[1] = 0;
    xy[2] = 0.01, xy[3] = 0;
    xy[4] = 0.01 + 0.01 * jump, xy[5] = 0;
    xy[6] = 10, xy[7] = 0;
    xy[8] = 10, xy[9] = 5;
    xy[10] = 0, xy[11] = 5;
    for (k = 0; k < 6; k++) {
        seg[2 * k] = k;
        seg[2 * k + 1] = (k + 1) % 6;
    }
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 6, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, seg, 6), CVM_OK);
}

static int cmp_edge(const void *pa, const void *pb)
{
    const cvm_index *a = pa, *b = pb;
    if (a[0] != b[0])
        return a[0] < b[0] ? -1 : 1;
    return (a[1] > b[1]) - (a[1] < b[1]);
}

/* The largest ratio between the two boundary edges (edges of one triangle
 * only, found here from the triangles) at any boundary vertex of m; *nb: the
 * number of boundary edges. */
static double worst_boundary_jump(cvm_mesh *m, size_t *nb)
{
    double *xy, worst = 1.0, *len;
    cvm_index *tri, *e;
    size_t nv, nt, k, n = 0;
    int *cnt;
    rtest_fetch(m, &xy, &nv, &tri, &nt);
    e = malloc(6 * nt * sizeof *e);
    len = malloc(2 * (nv + 1) * sizeof *len);
    cnt = calloc(nv + 1, sizeof *cnt);
    ck_assert(e && len && cnt);
    for (k = 0; k < 3 * nt; k++) {
        cvm_index a = tri[k], b = tri[k - k % 3 + (k + 1) % 3];
        e[2 * k] = a < b ? a : b;
        e[2 * k + 1] = a < b ? b : a;
    }
    qsort(e, 3 * nt, 2 * sizeof *e, cmp_edge);
    for (k = 0; k < 3 * nt; k++) {
        int dup = (k > 0 && !cmp_edge(e + 2 * k, e + 2 * k - 2)) ||
                  (k + 1 < 3 * nt && !cmp_edge(e + 2 * k, e + 2 * k + 2));
        const double *p, *q;
        double l;
        int end;
        if (dup)
            continue;
        n++;
        p = xy + 2 * (size_t)e[2 * k];
        q = xy + 2 * (size_t)e[2 * k + 1];
        l = hypot(q[0] - p[0], q[1] - p[1]);
        for (end = 0; end < 2; end++) {
            cvm_index v = e[2 * k + (size_t)end];
            ck_assert_int_lt(cnt[v], 2);
            len[2 * (size_t)v + (size_t)cnt[v]++] = l;
        }
    }
    for (k = 0; k < nv; k++) {
        if (cnt[k] != 2)
            continue;
        if (len[2 * k] / len[2 * k + 1] > worst)
            worst = len[2 * k] / len[2 * k + 1];
        if (len[2 * k + 1] / len[2 * k] > worst)
            worst = len[2 * k + 1] / len[2 * k];
    }
    *nb = n;
    free(xy);
    free(tri);
    free(e);
    free(len);
    free(cnt);
    return worst;
}

/* Adjacent input segments of 0.01 and 0.03 (0.1) against a size of 1: the
 * march grades the pieces away from the short segment, so no two consecutive
 * boundary pieces of the output differ by 2:1 or more, whatever the algorithm,
 * and the input vertices stay. */
static void check_graded(double jump)
{
    static const cvm_algorithm algos[] = {CVM_ALGO_DELAUNAY, CVM_ALGO_FRONTAL, CVM_ALGO_AFLR};
    size_t a;
    for (a = 0; a < 3; a++) {
        cvm_mesh *m;
        size_t nb;
        double worst;
        ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
        set_jump_rectangle(m, jump);
        ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
        ck_assert_int_eq(rtest_refine_uniform(m, 1.0, algos[a]), CVM_OK);
        cvmtest_assert_valid(m);
        worst = worst_boundary_jump(m, &nb);
        ck_assert_msg(worst < 2.0, "jump %g, algorithm %d: consecutive boundary pieces differ by %g",
                      jump, (int)algos[a], worst);
        /* graded: more pieces than the 30 + 3 that an ungraded march would give */
        ck_assert_uint_gt(nb, 40);
        cvm_mesh_free(m);
    }
}

START_TEST(three_to_one_jump_is_graded)
{
    check_graded(3.0);
}
END_TEST

START_TEST(ten_to_one_jump_is_graded)
{
    check_graded(10.0);
}
END_TEST

static int cancel_at_once(void *payload, cvm_stage stage, double fraction)
{
    (void)fraction;
    ++*(int *)payload;
    return stage == CVM_STAGE_REFINE;
}

/* Planning the march (before any insertion) checks the progress callback and
 * the time limit: a stop there leaves the triangulation as it was, valid. */
START_TEST(march_planning_can_be_cancelled)
{
    cvm_mesh *m;
    size_t n0, n1;
    double steiner = -1;
    int calls = 0;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    set_jump_rectangle(m, 10.0);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(&n0, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_progress(m, cancel_at_once, 1, &calls), CVM_OK);
    ck_assert_int_eq(rtest_refine_uniform(m, 1.0, CVM_ALGO_DELAUNAY), CVM_INCOMPLETE_CANCELLED);
    ck_assert_int_eq(calls, 1);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "cancelled while planning the segment splits"));
    ck_assert_int_eq(cvm_mesh_get_measure(&steiner, m, CVM_MEASURE_REFINE_STEINER), CVM_OK);
    ck_assert(steiner == 0);
    ck_assert_int_eq(cvm_mesh_count(&n1, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_uint_eq(n1, n0);
    cvmtest_assert_valid(m);
    cvm_mesh_free(m);
}
END_TEST

TCase *refine_march_tcase(void)
{
    TCase *tc = tcase_create("march");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, three_to_one_jump_is_graded);
    tcase_add_test(tc, ten_to_one_jump_is_graded);
    tcase_add_test(tc, march_planning_can_be_cancelled);
    return tc;
}
