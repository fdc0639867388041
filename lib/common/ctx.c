/* ctx.c - allocation hooks and error recording of the per-handle context. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "common_internal.h"

static void *default_malloc(void *payload, size_t size)
{
    (void)payload;
    return malloc(size);
}

static void *default_realloc(void *payload, void *p, size_t size)
{
    (void)payload;
    return realloc(p, size);
}

static void default_free(void *payload, void *p)
{
    (void)payload;
    free(p);
}

void cvm__ctx_init_default(cvm__ctx *ctx)
{
    memset(ctx, 0, sizeof *ctx);
    ctx->alloc_fn = default_malloc;
    ctx->realloc_fn = default_realloc;
    ctx->free_fn = default_free;
}

void *cvm__malloc(cvm__ctx *ctx, size_t size)
{
    return ctx->alloc_fn(ctx->payload, size ? size : 1);
}

void *cvm__calloc(cvm__ctx *ctx, size_t n, size_t size)
{
    size_t bytes;
    void *p;
    if (!cvm__mul_ok(n, size, &bytes))
        return NULL;
    p = cvm__malloc(ctx, bytes);
    if (p)
        memset(p, 0, bytes);
    return p;
}

void *cvm__realloc(cvm__ctx *ctx, void *p, size_t size)
{
    if (!p)
        return cvm__malloc(ctx, size);
    return ctx->realloc_fn(ctx->payload, p, size ? size : 1);
}

void cvm__free(cvm__ctx *ctx, void *p)
{
    if (p)
        ctx->free_fn(ctx->payload, p);
}

int cvm__mul_ok(size_t n, size_t size, size_t *out)
{
    if (size && n > (size_t)-1 / size)
        return 0;
    *out = n * size;
    return 1;
}

cvm_status cvm__grow(cvm__ctx *ctx, void **p, size_t *cap, size_t need, size_t elem)
{
    size_t ncap, bytes;
    void *q;
    if (need <= *cap && *p)
        return CVM_OK;
    ncap = *cap < 16 ? 16 : *cap;
    while (ncap < need) {
        if (ncap > (size_t)-1 / 2)
            return CVM_E_NOMEM;
        ncap += ncap / 2 + 8;
    }
    if (!cvm__mul_ok(ncap, elem, &bytes))
        return CVM_E_NOMEM;
    q = cvm__realloc(ctx, *p, bytes);
    if (!q)
        return CVM_E_NOMEM;
    *p = q;
    *cap = ncap;
    return CVM_OK;
}

/* Length of the well-formed UTF-8 sequence at p (at most n bytes) that is not a
 * C1 control (U+0080..U+009F), or 0. Overlong forms and surrogates are refused. */
static size_t utf8_len(const unsigned char *p, size_t n)
{
    unsigned c = p[0];
    size_t k, len = c >= 0xF0 && c <= 0xF4 ? 4 : c >= 0xE0 ? 3 : c >= 0xC2 && c < 0xE0 ? 2 : 0;
    if (len == 0 || len > n)
        return 0;
    for (k = 1; k < len; k++)
        if ((p[k] & 0xC0) != 0x80)
            return 0;
    if ((c == 0xC2 && p[1] < 0xA0) || (c == 0xE0 && p[1] < 0xA0) || (c == 0xED && p[1] >= 0xA0) ||
        (c == 0xF0 && p[1] < 0x90) || (c == 0xF4 && p[1] >= 0x90))
        return 0;
    return len;
}

void cvm__escape_text(char *dst, size_t cap, const char *src)
{
    static const char hex[] = "0123456789abcdef";
    const unsigned char *p = (const unsigned char *)src;
    size_t n = strlen(src), i = 0, o = 0;
    if (cap == 0)
        return;
    while (i < n) {
        size_t len = p[i] >= 0x20 && p[i] < 0x7F ? 1 : p[i] >= 0x80 ? utf8_len(p + i, n - i) : 0;
        if (len) {
            if (o + len >= cap)
                break;
            memcpy(dst + o, p + i, len);
            o += len;
            i += len;
            continue;
        }
        if (o + 4 >= cap)
            break;
        dst[o++] = '\\';
        dst[o++] = 'x';
        dst[o++] = hex[p[i] >> 4];
        dst[o++] = hex[p[i] & 15];
        i++;
    }
    dst[o] = '\0';
}

cvm_status cvm__error(cvm__ctx *ctx, cvm_status s, cvm_entity kind, int64_t index,
                      const char *fmt, ...)
{
    char raw[CVM__ERRMSG_LEN];
    va_list ap;
    ctx->status = s;
    ctx->err_kind = kind;
    ctx->err_index = index;
    va_start(ap, fmt);
    vsnprintf(raw, sizeof raw, fmt, ap);
    va_end(ap);
    /* fields of input files and file names are echoed: never let their
       control bytes reach a terminal, and keep the message valid UTF-8 */
    cvm__escape_text(ctx->errmsg, sizeof ctx->errmsg, raw);
    return s;
}

cvm_status cvm__nomem(cvm__ctx *ctx)
{
    return cvm__error(ctx, CVM_E_NOMEM, CVM_ENT_NONE, -1, "out of memory");
}

cvm_status cvm__check_dim(cvm__ctx *ctx, int dim, const char *call)
{
    if (dim == 2)
        return CVM_OK;
    if (dim == 3)
        return cvm__error(ctx, CVM_E_UNSUPPORTED, CVM_ENT_NONE, -1,
                          "%s: dim 3 is not supported yet (the 3D kernel is not in this version)",
                          call);
    return cvm__error(ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                      "%s: dim must be 2 (or 3 once the 3D kernel exists), got %d", call, dim);
}

void cvm__clear_error(cvm__ctx *ctx)
{
    ctx->status = CVM_OK;
    ctx->err_kind = CVM_ENT_NONE;
    ctx->err_index = -1;
    ctx->errmsg[0] = '\0';
}
