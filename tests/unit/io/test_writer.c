/* test_writer.c - atomic output files: whole file or nothing, in every failure. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io/io_tests.h"
#include "io/io_text.h"

static cvmtest_alloc g_a;
static cvm__ctx g_ctx;
static char *g_dir;

static void setup(void)
{
    cvmtest_alloc_init(&g_a, 0, 0);
    iotest_ctx(&g_ctx, &g_a);
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

static cvm_status write_text(const char *path, const char *text, int commit)
{
    cvm__writer *w;
    cvm_status s = cvm__writer_open(&w, &g_ctx, path);
    if (s)
        return s;
    cvm__writer_puts(w, text);
    cvm__writer_printf(w, "%d", 42);
    cvm__writer_double(w, 0.1);
    if (!commit) {
        cvm__writer_discard(w);
        return CVM_OK;
    }
    return cvm__writer_commit(w);
}

START_TEST(commit_leaves_exactly_the_file)
{
    char path[4096], *text;
    in_dir(path, sizeof path, "out.txt");
    ck_assert_int_eq(write_text(path, "hello ", 1), CVM_OK);
    text = iotest_slurp(path, NULL);
    ck_assert_str_eq(text, "hello 420.1");
    free(text);
    ck_assert_int_eq(iotest_count_entries(g_dir), 1);
    ck_assert_int_eq((int)g_a.live_blocks, 0);
}
END_TEST

START_TEST(discard_leaves_nothing_and_keeps_old_file)
{
    char path[4096], *text;
    in_dir(path, sizeof path, "out.txt");
    ck_assert_int_eq(write_text(path, "new", 0), CVM_OK);
    ck_assert_int_eq(iotest_count_entries(g_dir), 0);
    ck_assert_int_eq(write_text(path, "old ", 1), CVM_OK);
    ck_assert_int_eq(write_text(path, "new", 0), CVM_OK);
    text = iotest_slurp(path, NULL);
    ck_assert_str_eq(text, "old 420.1");
    free(text);
    ck_assert_int_eq(iotest_count_entries(g_dir), 1);
    ck_assert_int_eq((int)g_a.live_blocks, 0);
}
END_TEST

START_TEST(missing_directory_is_io_open_and_creates_nothing)
{
    char path[4096];
    in_dir(path, sizeof path, "no/such/dir/out.txt");
    ck_assert_int_eq(write_text(path, "x", 1), CVM_E_IO_OPEN);
    ck_assert_ptr_nonnull(strstr(g_ctx.errmsg, "cannot create"));
    ck_assert_ptr_nonnull(strstr(g_ctx.errmsg, "no/such/dir/out.txt"));
    ck_assert_int_eq(iotest_count_entries(g_dir), 0);
    ck_assert_int_eq((int)g_a.live_blocks, 0);
}
END_TEST

START_TEST(full_device_is_io_write_and_leaves_no_temporary)
{
    char path[4096];
    struct stat st;
    /* Linux (and so Debian) always has /dev/full: its absence is a broken
       test machine, not a reason to pass without checking */
    ck_assert_msg(stat("/dev/full", &st) == 0 && S_ISCHR(st.st_mode),
                  "/dev/full is missing or not a character device");
    in_dir(path, sizeof path, "full.vtu");
    ck_assert_int_eq(symlink("/dev/full", path), 0);
    ck_assert_int_eq(write_text(path, "data that cannot fit", 1), CVM_E_IO_WRITE);
    ck_assert_ptr_nonnull(strstr(g_ctx.errmsg, "cannot write"));
    ck_assert_ptr_nonnull(strstr(g_ctx.errmsg, "full.vtu"));
    ck_assert_int_eq(iotest_count_entries(g_dir), 1); /* the link only */
    ck_assert_int_eq(lstat(path, &st), 0);
    ck_assert(S_ISLNK(st.st_mode));
    ck_assert_int_eq((int)g_a.live_blocks, 0);
}
END_TEST

START_TEST(symbolic_link_keeps_pointing_at_the_replaced_file)
{
    char path[4096], target[4096], *text;
    struct stat st;
    in_dir(target, sizeof target, "real.txt");
    in_dir(path, sizeof path, "link.txt");
    ck_assert_int_eq(write_text(target, "old ", 1), CVM_OK);
    ck_assert_int_eq(symlink("real.txt", path), 0);
    ck_assert_int_eq(write_text(path, "new ", 1), CVM_OK);
    ck_assert_int_eq(lstat(path, &st), 0);
    ck_assert(S_ISLNK(st.st_mode));
    text = iotest_slurp(target, NULL);
    ck_assert_str_eq(text, "new 420.1");
    free(text);
    ck_assert_int_eq(iotest_count_entries(g_dir), 2);
}
END_TEST

START_TEST(directory_target_is_io_open)
{
    char path[4096];
    in_dir(path, sizeof path, "sub.txt");
    ck_assert_int_eq(mkdir(path, 0700), 0);
    ck_assert_int_eq(write_text(path, "x", 1), CVM_E_IO_OPEN);
    ck_assert_int_eq(iotest_count_entries(g_dir), 1);
    rmdir(path);
}
END_TEST

START_TEST(writer_open_runs_out_of_memory_cleanly)
{
    char path[4096];
    long k;
    in_dir(path, sizeof path, "oom.txt");
    for (k = 1;; k++) {
        cvm_status s;
        cvmtest_alloc_init(&g_a, k, 0);
        s = write_text(path, "x", 1);
        ck_assert_int_eq((int)g_a.live_blocks, 0);
        if (s == CVM_OK)
            break;
        ck_assert_int_eq(s, CVM_E_NOMEM);
        ck_assert_int_eq(iotest_count_entries(g_dir), 0);
        ck_assert(k < 100);
    }
    ck_assert_int_eq(iotest_count_entries(g_dir), 1);
}
END_TEST

static int mode_of(const char *path)
{
    struct stat st;
    ck_assert_int_eq(stat(path, &st), 0);
    return (int)(st.st_mode & 07777);
}

START_TEST(a_replaced_file_keeps_its_permissions)
{
    char path[4096];
    mode_t old = umask(022);
    in_dir(path, sizeof path, "private.txt");
    ck_assert_int_eq(write_text(path, "old ", 1), CVM_OK);
    ck_assert_int_eq(mode_of(path), 0644); /* a new file: 0666 under the umask */
    ck_assert_int_eq(chmod(path, 0600), 0);
    ck_assert_int_eq(write_text(path, "new ", 1), CVM_OK);
    ck_assert_int_eq(mode_of(path), 0600);
    ck_assert_int_eq(chmod(path, 0751), 0);
    ck_assert_int_eq(write_text(path, "new ", 1), CVM_OK);
    ck_assert_int_eq(mode_of(path), 0751);
    umask(077);
    in_dir(path, sizeof path, "fresh.txt");
    ck_assert_int_eq(write_text(path, "x", 1), CVM_OK);
    ck_assert_int_eq(mode_of(path), 0600);
    umask(old);
    ck_assert_int_eq((int)g_a.live_blocks, 0);
}
END_TEST

/* Expected text, grown alongside what the writer is given. */
typedef struct text {
    char *s;
    size_t n, cap;
} text;

static void text_add(text *t, const char *s, size_t n)
{
    if (t->n + n + 1 > t->cap) {
        t->cap = 2 * (t->n + n + 1);
        t->s = realloc(t->s, t->cap);
        ck_assert_ptr_nonnull(t->s);
    }
    memcpy(t->s + t->n, s, n);
    t->n += n;
    t->s[t->n] = '\0';
}

/* Every kind of put, many times over, with a printf longer than the
 * writer's buffer among them: the file holds exactly the expected bytes. */
START_TEST(buffered_output_keeps_every_byte_in_order)
{
    char path[4096], buf[64], *got, *big = malloc(200001);
    text want = {NULL, 0, 0};
    cvm__writer *w;
    uint64_t z = 5;
    size_t len, i;
    ck_assert_ptr_nonnull(big);
    memset(big, 'b', 200000);
    big[200000] = '\0';
    in_dir(path, sizeof path, "many.txt");
    ck_assert_int_eq(cvm__writer_open(&w, &g_ctx, path), CVM_OK);
    for (i = 0; i < 60000; i++) {
        double x;
        long long v;
        z = z * 6364136223846793005ull + 1442695040888963407ull;
        memcpy(&x, &z, sizeof x);
        v = (long long)z >> (z % 60);
        switch (i % 8) {
        case 0:
            cvm__writer_double(w, x);
            if (isnan(x))
                snprintf(buf, sizeof buf, "nan");
            else if (isinf(x))
                snprintf(buf, sizeof buf, x > 0 ? "inf" : "-inf");
            else
                cvm__format_double_libc(buf, x);
            break;
        case 1:
            cvm__writer_long(w, v);
            snprintf(buf, sizeof buf, "%lld", v);
            break;
        case 2:
            cvm__writer_ulong(w, z);
            snprintf(buf, sizeof buf, "%llu", (unsigned long long)z);
            break;
        case 3:
            cvm__writer_putc(w, ' ');
            snprintf(buf, sizeof buf, " ");
            break;
        case 4:
            cvm__writer_puts(w, "abc\n");
            snprintf(buf, sizeof buf, "abc\n");
            break;
        case 5:
            cvm__writer_write(w, "x\0y", 3);
            memcpy(buf, "x\0y", 3);
            text_add(&want, buf, 3);
            continue;
        case 6:
            cvm__writer_printf(w, "<%ld %s>", (long)i, "p");
            snprintf(buf, sizeof buf, "<%ld %s>", (long)i, "p");
            break;
        default:
            if (i % 20000 == 7) {
                cvm__writer_printf(w, "%s", big);
                text_add(&want, big, 200000);
                cvm__writer_write(w, big, 100000);
                text_add(&want, big, 100000);
            }
            continue;
        }
        text_add(&want, buf, strlen(buf));
    }
    ck_assert_int_eq(cvm__writer_commit(w), CVM_OK);
    got = iotest_slurp(path, &len);
    ck_assert_uint_eq(len, want.n);
    ck_assert(memcmp(got, want.s, len) == 0);
    free(got);
    free(want.s);
    free(big);
    ck_assert_int_eq((int)g_a.live_blocks, 0);
}
END_TEST

/* A device that refuses every block: the error surfaces at the end, after
 * many blocks went out, and nothing is left behind. */
START_TEST(full_device_after_many_blocks_is_io_write)
{
    char path[4096];
    struct stat st;
    cvm__writer *w;
    long i;
    ck_assert_msg(stat("/dev/full", &st) == 0 && S_ISCHR(st.st_mode),
                  "/dev/full is missing or not a character device");
    in_dir(path, sizeof path, "full.node");
    ck_assert_int_eq(symlink("/dev/full", path), 0);
    ck_assert_int_eq(cvm__writer_open(&w, &g_ctx, path), CVM_OK);
    for (i = 0; i < 100000; i++) {
        cvm__writer_double(w, i * 0.1);
        cvm__writer_putc(w, '\n');
    }
    ck_assert_int_eq(cvm__writer_commit(w), CVM_E_IO_WRITE);
    ck_assert_ptr_nonnull(strstr(g_ctx.errmsg, "full.node"));
    ck_assert_int_eq(iotest_count_entries(g_dir), 1);
    ck_assert_int_eq((int)g_a.live_blocks, 0);
}
END_TEST

TCase *io_writer_tcase(void)
{
    TCase *tc = tcase_create("writer");
    tcase_add_checked_fixture(tc, setup, teardown);
    tcase_add_test(tc, commit_leaves_exactly_the_file);
    tcase_add_test(tc, a_replaced_file_keeps_its_permissions);
    tcase_add_test(tc, discard_leaves_nothing_and_keeps_old_file);
    tcase_add_test(tc, missing_directory_is_io_open_and_creates_nothing);
    tcase_add_test(tc, full_device_is_io_write_and_leaves_no_temporary);
    tcase_add_test(tc, symbolic_link_keeps_pointing_at_the_replaced_file);
    tcase_add_test(tc, directory_target_is_io_open);
    tcase_add_test(tc, writer_open_runs_out_of_memory_cleanly);
    tcase_add_test(tc, buffered_output_keeps_every_byte_in_order);
    tcase_add_test(tc, full_device_after_many_blocks_is_io_write);
    return tc;
}
