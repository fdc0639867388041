/* test_write.c - cvm_mesh_write (lib/api/mesh_write.c): formats, state, failures, OOM, round trip. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "api/api_tests.h"
#include "support/failing_alloc.h"
#include "support/fixtures.h"
#include "io/io_tests.h"

static char *g_dir;

static void setup(void)
{
    g_dir = iotest_tmpdir();
}

static void teardown(void)
{
    iotest_rmdir(g_dir);
    free(g_dir);
}

static void in_dir(char *buf, size_t len, const char *name)
{
    snprintf(buf, len, "%s/%s", g_dir, name);
}

START_TEST(write_needs_a_triangulation_and_a_known_extension)
{
    cvm_mesh *m;
    char path[4096];
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    in_dir(path, sizeof path, "m.vtu");
    ck_assert_int_eq(cvm_mesh_write(m, path), CVM_E_STATE);
    ck_assert_int_eq(cvmtest_pslg_set(m, &cvmtest_square_with_hole), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    in_dir(path, sizeof path, "m.obj");
    ck_assert_int_eq(cvm_mesh_write(m, path), CVM_E_UNSUPPORTED);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "m.obj"));
    ck_assert_int_eq(cvm_mesh_write(m, NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_write(NULL, path), CVM_E_NULL_ARG);
    in_dir(path, sizeof path, "missing/m.vtu");
    ck_assert_int_eq(cvm_mesh_write(m, path), CVM_E_IO_OPEN);
    ck_assert_int_eq(iotest_count_entries(g_dir), 0);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(node_output_reads_back_and_matches_the_triangles)
{
    cvm_mesh *m, *r;
    char path[4096];
    double xy[16], back[16];
    cvm_index tri[24];
    size_t nv, nt, k;
    long n, i, a, b, c;
    FILE *f;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvmtest_pslg_set(m, &cvmtest_square_with_hole), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    in_dir(path, sizeof path, "m.node");
    ck_assert_msg(cvm_mesh_write(m, path) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(iotest_count_entries(g_dir), 3);
    ck_assert_int_eq(cvm_mesh_create(&r), CVM_OK);
    ck_assert_msg(cvm_mesh_read(r, path) == CVM_OK, "%s", cvm_mesh_errmsg(r));
    ck_assert_int_eq(cvm_mesh_count(&nv, r, CVM_ENT_INPUT_POINT), CVM_OK);
    ck_assert_uint_eq(nv, 8);
    ck_assert_int_eq(cvm_mesh_triangulate(r), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_points(back, 16, r), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_points(xy, 16, m), CVM_OK);
    ck_assert_int_eq(memcmp(xy, back, sizeof xy), 0);
    ck_assert_int_eq(cvm_mesh_count(&nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(tri, 3 * nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    in_dir(path, sizeof path, "m.ele");
    f = fopen(path, "r");
    ck_assert_ptr_nonnull(f);
    ck_assert_int_eq(fscanf(f, "%ld %ld %ld", &n, &a, &b), 3);
    ck_assert_int_eq((int)n, (int)nt);
    for (k = 0; k < nt; k++) {
        ck_assert_int_eq(fscanf(f, "%ld %ld %ld %ld", &i, &a, &b, &c), 4);
        ck_assert(a == tri[3 * k] && b == tri[3 * k + 1] && c == tri[3 * k + 2]);
    }
    fclose(f);
    cvm_mesh_free(r);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(write_runs_out_of_memory_and_the_handle_goes_on)
{
    static const char *const names[] = {"m.vtu", "m.msh", "m.node", "m.svg"};
    cvmtest_alloc a;
    cvm_mesh *m;
    char path[4096];
    size_t i;
    long live;
    cvmtest_alloc_init(&a, 0, 0);
    ck_assert_int_eq(cvmtest_mesh_create(&m, &a), CVM_OK);
    ck_assert_int_eq(cvmtest_pslg_set(m, &cvmtest_square_with_hole), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    live = a.live_blocks;
    for (i = 0; i < 4; i++) {
        long k;
        in_dir(path, sizeof path, names[i]);
        for (k = 1;; k++) {
            cvm_status s;
            cvmtest_alloc_arm(&a, k, 0);
            s = cvm_mesh_write(m, path);
            ck_assert_int_eq((int)a.live_blocks, (int)live);
            if (s == CVM_OK)
                break;
            ck_assert_msg(s == CVM_E_NOMEM, "%s k=%ld: %s", names[i], k, cvm_mesh_errmsg(m));
            ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "out of memory"));
            ck_assert(k < 200);
        }
    }
    ck_assert_int_eq(iotest_count_entries(g_dir), 6);
    cvm_mesh_free(m);
    ck_assert_int_eq((int)a.live_blocks, 0);
}
END_TEST

/* The .msh writer's regions (one surface per attribute) and node classes under
 * every failed allocation. */
START_TEST(msh_with_regions_runs_out_of_memory_and_the_handle_goes_on)
{
    /* two unit squares side by side, split by the segment 4-5 */
    static const double xy[] = {0, 0, 1, 0, 2, 0, 2, 1, 1, 1, 0, 1};
    static const cvm_index seg[] = {0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 0, 1, 4};
    static const double regions[] = {0.5, 0.5, 1, 0, 1.5, 0.5, 2, 0};
    cvmtest_alloc a;
    cvm_mesh *m;
    char path[4096], *text;
    long k, live;
    cvmtest_alloc_init(&a, 0, 0);
    ck_assert_int_eq(cvmtest_mesh_create(&m, &a), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 6, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, seg, 7), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_regions(m, regions, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    live = a.live_blocks;
    in_dir(path, sizeof path, "r.msh");
    for (k = 1;; k++) {
        cvm_status s;
        cvmtest_alloc_arm(&a, k, 0);
        s = cvm_mesh_write(m, path);
        ck_assert_int_eq((int)a.live_blocks, (int)live);
        if (s == CVM_OK)
            break;
        ck_assert_msg(s == CVM_E_NOMEM, "k=%ld: %s", k, cvm_mesh_errmsg(m));
        ck_assert(k < 200);
    }
    text = iotest_slurp(path, NULL);
    ck_assert_ptr_nonnull(text);
    ck_assert_ptr_nonnull(strstr(text, "2 1 \"region_1\"\n2 2 \"region_2\"\n"));
    /* corners 1 and 4 join three segments: point entities; every node is classified */
    ck_assert_ptr_nonnull(strstr(text, "$Entities\n2 1 2 0\n"));
    free(text);
    cvm_mesh_free(m);
    ck_assert_int_eq((int)a.live_blocks, 0);
}
END_TEST

/* Write text to dir/name (a plain file standing for an older output). */
static void put_file(const char *name, const char *text)
{
    char path[4096];
    FILE *f;
    in_dir(path, sizeof path, name);
    f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fputs(text, f);
    ck_assert_int_eq(fclose(f), 0);
}

/* 1 when dir/name holds exactly text. */
static int file_is(const char *name, const char *text)
{
    char path[4096], *got;
    int same;
    in_dir(path, sizeof path, name);
    got = iotest_slurp(path, NULL);
    same = got && strcmp(got, text) == 0;
    free(got);
    return same;
}

static int file_has(const char *name, const char *needle)
{
    char path[4096], *got;
    int has;
    in_dir(path, sizeof path, name);
    got = iotest_slurp(path, NULL);
    has = got && strstr(got, needle) != NULL;
    free(got);
    return has;
}

static cvm_mesh *square_mesh(void)
{
    cvm_mesh *m;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvmtest_pslg_set(m, &cvmtest_square_with_hole), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    return m;
}

static cvm_status stage(cvm_mesh *m, const char *name, int dual)
{
    char path[4096];
    in_dir(path, sizeof path, name);
    return dual ? cvm_mesh_stage_write_dual(m, path) : cvm_mesh_stage_write(m, path);
}

START_TEST(staged_files_replace_their_targets_only_at_commit)
{
    cvm_mesh *m = square_mesh();
    put_file("a.vtu", "old mesh\n");
    ck_assert_msg(stage(m, "a.vtu", 0) == CVM_OK, "%s", cvm_mesh_errmsg(m));
    ck_assert_int_eq(stage(m, "b.svg", 0), CVM_OK);
    ck_assert_int_eq(stage(m, "c.node", 0), CVM_OK);
    ck_assert_int_eq(stage(m, "d.vtu", 1), CVM_OK);
    ck_assert(file_is("a.vtu", "old mesh\n"));
    ck_assert_int_eq(iotest_count_entries(g_dir), 1 + 6); /* a.vtu and six temporaries */
    ck_assert_int_eq(cvm_mesh_commit_writes(m), CVM_OK);
    ck_assert_int_eq(iotest_count_entries(g_dir), 6);
    ck_assert(file_has("a.vtu", "<VTKFile"));
    ck_assert(file_has("b.svg", "<svg "));
    ck_assert(file_has("c.ele", " 3 "));
    ck_assert(file_has("d.vtu", "Name=\"area\""));
    ck_assert_int_eq(cvm_mesh_commit_writes(m), CVM_OK); /* nothing staged: nothing to do */
    ck_assert_int_eq(iotest_count_entries(g_dir), 6);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(a_failed_stage_discards_every_staged_file)
{
    cvm_mesh *m = square_mesh();
    put_file("a.vtu", "old mesh\n");
    ck_assert_int_eq(stage(m, "a.vtu", 0), CVM_OK);
    ck_assert_int_eq(stage(m, "no/such/b.svg", 0), CVM_E_IO_OPEN);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "b.svg"));
    ck_assert_int_eq(iotest_count_entries(g_dir), 1);
    ck_assert_int_eq(cvm_mesh_commit_writes(m), CVM_OK);
    ck_assert(file_is("a.vtu", "old mesh\n"));
    /* a wrong extension or a missing dual format discards too */
    ck_assert_int_eq(stage(m, "a.vtu", 0), CVM_OK);
    ck_assert_int_eq(stage(m, "d.svg", 1), CVM_E_UNSUPPORTED);
    ck_assert_int_eq(cvm_mesh_commit_writes(m), CVM_OK);
    ck_assert(file_is("a.vtu", "old mesh\n"));
    ck_assert_int_eq(iotest_count_entries(g_dir), 1);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(discard_and_free_remove_staged_files)
{
    cvm_mesh *m = square_mesh();
    put_file("a.vtu", "old mesh\n");
    ck_assert_int_eq(stage(m, "a.vtu", 0), CVM_OK);
    ck_assert_int_eq(stage(m, "c.node", 0), CVM_OK);
    ck_assert_int_eq(cvm_mesh_discard_writes(m), CVM_OK);
    ck_assert_int_eq(iotest_count_entries(g_dir), 1);
    ck_assert_int_eq(cvm_mesh_discard_writes(m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_discard_writes(NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_commit_writes(NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_stage_write(NULL, "x.vtu"), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_stage_write_dual(NULL, "x.vtu"), CVM_E_NULL_ARG);
    ck_assert_int_eq(cvm_mesh_stage_write(m, NULL), CVM_E_NULL_ARG);
    ck_assert_int_eq(stage(m, "b.svg", 0), CVM_OK);
    ck_assert_int_eq(stage(m, "d.vtu", 1), CVM_OK);
    cvm_mesh_free(m);
    ck_assert_int_eq(iotest_count_entries(g_dir), 1);
    ck_assert(file_is("a.vtu", "old mesh\n"));
}
END_TEST

/* The target of the last rename becomes a non-empty directory between the
 * stage and the commit, so that rename fails (for root too): the files
 * already replaced come back as they were, a new one goes away. */
START_TEST(a_failed_rename_puts_the_replaced_files_back)
{
    cvm_mesh *m = square_mesh();
    char dir[4096], inner[4200];
    put_file("a.node", "old node\n");
    put_file("a.ele", "old ele\n");
    ck_assert_int_eq(stage(m, "new.vtu", 0), CVM_OK);
    ck_assert_int_eq(stage(m, "a.node", 0), CVM_OK);
    in_dir(dir, sizeof dir, "a.edge");
    ck_assert_int_eq(mkdir(dir, 0755), 0);
    snprintf(inner, sizeof inner, "%s/keep", dir);
    ck_assert_int_eq(iotest_count_entries(dir), 0);
    {
        FILE *f = fopen(inner, "w");
        ck_assert_ptr_nonnull(f);
        fclose(f);
    }
    ck_assert_int_eq(cvm_mesh_commit_writes(m), CVM_E_IO_WRITE);
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "cannot replace"));
    ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "a.edge"));
    ck_assert(file_is("a.node", "old node\n"));
    ck_assert(file_is("a.ele", "old ele\n"));
    ck_assert_int_eq(iotest_count_entries(g_dir), 3); /* a.node, a.ele, the directory */
    ck_assert_int_eq(unlink(inner), 0);
    ck_assert_int_eq(rmdir(dir), 0);
    /* the handle goes on: the same set now commits */
    ck_assert_int_eq(stage(m, "a.node", 0), CVM_OK);
    ck_assert_int_eq(cvm_mesh_commit_writes(m), CVM_OK);
    ck_assert(file_has("a.ele", " 3 "));
    ck_assert_int_eq(iotest_count_entries(g_dir), 3);
    cvm_mesh_free(m);
}
END_TEST

typedef struct cancel_probe {
    int calls, write_calls;
    double last_fraction;
} cancel_probe;

/* Stop at the first report from a write. */
static int stop_in_write(void *payload, cvm_stage stage, double fraction)
{
    cancel_probe *p = (cancel_probe *)payload;
    p->calls++;
    if (stage != CVM_STAGE_WRITE)
        return 0;
    p->write_calls++;
    p->last_fraction = fraction;
    return 1;
}

/* Enough points that every format takes a few hundred puts. */
static cvm_mesh *grid_mesh(void)
{
    cvm_mesh *m;
    double xy[2 * 400];
    int i;
    for (i = 0; i < 400; i++) {
        xy[2 * i] = (double)(i % 20) + 0.01 * (double)((i * 7) % 13);
        xy[2 * i + 1] = (double)(i / 20) + 0.01 * (double)((i * 5) % 11);
    }
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 400, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    return m;
}

START_TEST(a_cancelled_write_changes_no_file)
{
    static const char *const names[] = {"m.vtu", "m.msh", "m.node", "m.svg"};
    cvm_mesh *m = grid_mesh();
    cancel_probe p;
    size_t i;
    put_file("m.vtu", "old mesh\n");
    for (i = 0; i < 4; i++) {
        char path[4096];
        memset(&p, 0, sizeof p);
        ck_assert_int_eq(cvm_mesh_set_progress(m, stop_in_write, 1, &p), CVM_OK);
        in_dir(path, sizeof path, names[i]);
        ck_assert_int_eq(cvm_mesh_write(m, path), CVM_INCOMPLETE_CANCELLED);
        ck_assert_ptr_nonnull(strstr(cvm_mesh_errmsg(m), "cancelled"));
        ck_assert_int_eq(p.write_calls, 1);
        ck_assert(p.last_fraction >= 0 && p.last_fraction < 1);
        ck_assert_int_eq(iotest_count_entries(g_dir), 1);
        ck_assert(file_is("m.vtu", "old mesh\n"));
    }
    memset(&p, 0, sizeof p);
    ck_assert_int_eq(stage(m, "a.svg", 0), CVM_INCOMPLETE_CANCELLED);
    {
        char path[4096];
        in_dir(path, sizeof path, "d.vtu");
        ck_assert_int_eq(cvm_mesh_write_dual(m, path), CVM_INCOMPLETE_CANCELLED);
    }
    /* a cancelled stage discards what was staged before it */
    ck_assert_int_eq(cvm_mesh_set_progress(m, NULL, 0, NULL), CVM_OK);
    ck_assert_int_eq(stage(m, "m.vtu", 0), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_progress(m, stop_in_write, 1, &p), CVM_OK);
    ck_assert_int_eq(stage(m, "d.vtu", 1), CVM_INCOMPLETE_CANCELLED);
    ck_assert_int_eq(cvm_mesh_commit_writes(m), CVM_OK);
    ck_assert(file_is("m.vtu", "old mesh\n"));
    ck_assert_int_eq(iotest_count_entries(g_dir), 1);
    cvm_mesh_free(m);
}
END_TEST

static int count_writes(void *payload, cvm_stage stage, double fraction)
{
    cancel_probe *p = (cancel_probe *)payload;
    if (stage == CVM_STAGE_WRITE) {
        ck_assert(fraction >= p->last_fraction && fraction <= 1);
        p->last_fraction = fraction;
        p->write_calls++;
    }
    return 0;
}

START_TEST(a_write_reports_its_progress)
{
    cvm_mesh *m = grid_mesh();
    cancel_probe p;
    char path[4096];
    memset(&p, 0, sizeof p);
    ck_assert_int_eq(cvm_mesh_set_progress(m, count_writes, 1, &p), CVM_OK);
    in_dir(path, sizeof path, "m.node");
    ck_assert_int_eq(cvm_mesh_write(m, path), CVM_OK);
    ck_assert_int_gt(p.write_calls, 10);
    ck_assert(p.last_fraction > 0.5);
    cvm_mesh_free(m);
}
END_TEST

START_TEST(staged_writes_run_out_of_memory_and_change_nothing)
{
    cvmtest_alloc a;
    cvm_mesh *m;
    long k, live;
    cvmtest_alloc_init(&a, 0, 0);
    ck_assert_int_eq(cvmtest_mesh_create(&m, &a), CVM_OK);
    ck_assert_int_eq(cvmtest_pslg_set(m, &cvmtest_square_with_hole), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
    live = a.live_blocks;
    for (k = 1;; k++) {
        cvm_status s;
        put_file("a.node", "old node\n");
        put_file("b.vtu", "old mesh\n");
        cvmtest_alloc_arm(&a, k, 0);
        s = stage(m, "a.node", 0);
        if (!s)
            s = stage(m, "b.vtu", 0);
        if (!s)
            s = stage(m, "c.vtu", 1);
        if (!s)
            s = cvm_mesh_commit_writes(m);
        cvmtest_alloc_arm(&a, 0, 0);
        ck_assert_int_eq((int)a.live_blocks, (int)live);
        if (s == CVM_OK)
            break;
        ck_assert_msg(s == CVM_E_NOMEM, "k=%ld: %s", k, cvm_mesh_errmsg(m));
        ck_assert(file_is("a.node", "old node\n"));
        ck_assert(file_is("b.vtu", "old mesh\n"));
        ck_assert_int_eq(iotest_count_entries(g_dir), 2);
        ck_assert(k < 300);
    }
    ck_assert(file_has("b.vtu", "<VTKFile"));
    ck_assert_int_eq(iotest_count_entries(g_dir), 5);
    cvm_mesh_free(m);
    ck_assert_int_eq((int)a.live_blocks, 0);
}
END_TEST

TCase *api_write_tcase(void)
{
    TCase *tc = tcase_create("write");
    tcase_add_checked_fixture(tc, setup, teardown);
    tcase_add_test(tc, write_needs_a_triangulation_and_a_known_extension);
    tcase_add_test(tc, node_output_reads_back_and_matches_the_triangles);
    tcase_add_test(tc, write_runs_out_of_memory_and_the_handle_goes_on);
    tcase_add_test(tc, msh_with_regions_runs_out_of_memory_and_the_handle_goes_on);
    tcase_add_test(tc, staged_files_replace_their_targets_only_at_commit);
    tcase_add_test(tc, a_failed_stage_discards_every_staged_file);
    tcase_add_test(tc, discard_and_free_remove_staged_files);
    tcase_add_test(tc, a_failed_rename_puts_the_replaced_files_back);
    tcase_add_test(tc, a_cancelled_write_changes_no_file);
    tcase_add_test(tc, a_write_reports_its_progress);
    tcase_add_test(tc, staged_writes_run_out_of_memory_and_change_nothing);
    return tc;
}
