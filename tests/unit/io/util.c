/* util.c - helpers of the io tests: data directories, a failing context, temporary directories. */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "io/io_tests.h"
#include "support/failing_reader.h"

const char *iotest_domain_dir(void)
{
    const char *d = getenv("CVM_DATA_DIR");
    return d && *d ? d : "examples/data";
}

const char *iotest_data_dir(void)
{
    const char *d = getenv("CVM_TEST_DATA");
    return d && *d ? d : "tests/data";
}

void iotest_path(char *buf, size_t len, const char *dir, const char *name)
{
    snprintf(buf, len, "%s/%s", dir, name);
}

void iotest_ctx(cvm__ctx *ctx, cvmtest_alloc *a)
{
    cvm__ctx_init_default(ctx);
    ctx->alloc_fn = cvmtest_malloc;
    ctx->realloc_fn = cvmtest_realloc;
    ctx->free_fn = cvmtest_free;
    ctx->payload = a;
}

cvm_status iotest_parse(cvm__ctx *ctx, const char *text, size_t len, int is_poly, cvm__pslg *p)
{
    cvmtest_reader tr;
    cvm__reader r;
    cvmtest_reader_init(&tr, &r, text, len ? len : strlen(text), 0, -1);
    return cvm__read_triangle_format(ctx, &r, is_poly ? "t.poly" : "t.node", is_poly, p);
}

char *iotest_tmpdir(void)
{
    const char *base = getenv("TMPDIR");
    size_t n;
    char *d;
    if (!base || !*base)
        base = "/tmp";
    n = strlen(base) + 32;
    d = malloc(n);
    ck_assert_ptr_nonnull(d);
    snprintf(d, n, "%s/cvmtest_io_XXXXXX", base);
    ck_assert_ptr_nonnull(mkdtemp(d));
    return d;
}

int iotest_count_entries(const char *dir)
{
    DIR *dp = opendir(dir);
    struct dirent *e;
    int n = 0;
    if (!dp)
        return -1;
    while ((e = readdir(dp)) != NULL)
        if (strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0)
            n++;
    closedir(dp);
    return n;
}

void iotest_rmdir(const char *dir)
{
    DIR *dp = opendir(dir);
    struct dirent *e;
    char path[4096];
    if (!dp)
        return;
    while ((e = readdir(dp)) != NULL) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        unlink(path);
    }
    closedir(dp);
    rmdir(dir);
}

char *iotest_slurp(const char *path, size_t *len_out)
{
    FILE *f = fopen(path, "rb");
    char *buf;
    long n;
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    buf = malloc((size_t)n + 1);
    if (buf && fread(buf, 1, (size_t)n, f) != (size_t)n) {
        free(buf);
        buf = NULL;
    }
    fclose(f);
    if (buf) {
        buf[n] = '\0';
        if (len_out)
            *len_out = (size_t)n;
    }
    return buf;
}

size_t iotest_count(const char *hay, const char *needle)
{
    size_t n = 0, k = strlen(needle);
    const char *p = hay;
    while ((p = strstr(p, needle)) != NULL) {
        n++;
        p += k;
    }
    return n;
}

/* Corners, the centre and its neighbours carry values that print badly with
 * few digits (0.1, 1/3, tiny and huge magnitudes). */
static const double k_xy[] = {0, 0, 1, 0, 1, 1, 0.1, 1.0 / 3.0, 0.5000000000000001, 0.4999999999999999};
static const int32_t k_vmark[] = {1, 2, 3, -4, 0};
static const double k_vattr[] = {1e-300, -2.5, 1e300, 0.1, 3.0};
static const int32_t k_tri[] = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
static const double k_tattr[] = {1, 2, 0.30000000000000004, -7};
static const int32_t k_edge[] = {0, 1, 0, 3, 0, 4, 1, 2, 1, 4, 2, 3, 2, 4, 3, 4};
static const int32_t k_emark[] = {7, 1, 0, 7, 0, 9, 0, 0};
static const int32_t k_seg[] = {0, 1, 1, 2, 2, 3};
static const int32_t k_smark[] = {7, 7, 9};
static const double k_q[] = {10, 20, 45, 60};

void iotest_mesh_out(cvm__mesh_out *mo)
{
    memset(mo, 0, sizeof *mo);
    mo->xy = k_xy;
    mo->nv = 5;
    mo->vmark = k_vmark;
    mo->vattr = k_vattr;
    mo->nattr = 1;
    mo->tri = k_tri;
    mo->nt = 4;
    mo->tattr = k_tattr;
    mo->edge = k_edge;
    mo->emark = k_emark;
    mo->ne = 8;
    mo->seg = k_seg;
    mo->smark = k_smark;
    mo->nseg = 3;
    mo->tquality = k_q;
}
