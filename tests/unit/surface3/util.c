/* util.c - helpers of the surface3 tests: data paths, a failing context, parsing text, volumes. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "support/failing_reader.h"
#include "surface3/surface3_tests.h"

void s3test_path(char *buf, size_t len, const char *name)
{
    const char *d = getenv("CVM_DATA3D_DIR");
    snprintf(buf, len, "%s/%s", d && *d ? d : "examples/data3d", name);
}

void s3test_ctx(cvm__ctx *ctx, cvmtest_alloc *a)
{
    cvm__ctx_init_default(ctx);
    ctx->alloc_fn = cvmtest_malloc;
    ctx->realloc_fn = cvmtest_realloc;
    ctx->free_fn = cvmtest_free;
    ctx->payload = a;
}

void s3test_read(cvm__ctx *ctx, const char *name, cvm__surf3 *s)
{
    char path[4096];
    cvm_status st;
    s3test_path(path, sizeof path, name);
    st = cvm__read_surface3_file(ctx, path, s);
    ck_assert_msg(st == CVM_OK, "%s: %s", path, ctx->errmsg);
}

cvm_status s3test_parse(cvm__ctx *ctx, const char *name, const char *text, size_t len, cvm__surf3 *s)
{
    cvmtest_reader tr;
    cvm__reader r;
    cvmtest_reader_init(&tr, &r, text, len ? len : strlen(text), 0, -1);
    if (strstr(name, ".off"))
        return cvm__read_off(ctx, &r, name, s);
    if (strstr(name, ".stl"))
        return cvm__read_stl(ctx, &r, name, s);
    return cvm__read_tetpoly(ctx, &r, name, strstr(name, ".smesh") != NULL, NULL, s);
}

double s3test_volume(const cvm__surf3 *s)
{
    double v = 0.0;
    size_t k, i;
    for (k = 0; k < s->npoly; k++) {
        const int32_t *idx = s->pidx + s->poff[k];
        size_t n = (size_t)(s->poff[k + 1] - s->poff[k]);
        for (i = 1; i + 1 < n; i++) {
            const double *a = s->xyz + 3 * idx[0], *b = s->xyz + 3 * idx[i], *c = s->xyz + 3 * idx[i + 1];
            v += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                  a[2] * (b[0] * c[1] - b[1] * c[0])) / 6.0;
        }
    }
    return v;
}

char *s3test_slurp(const char *path, size_t *len)
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
        *len = (size_t)n;
    }
    return buf;
}
