/* scan.c - splits the bytes of a cvm__reader into numbered lines of fields, dropping comments and blank lines. */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "io_text.h"

#define CHUNK 65536

void cvm__scan_init(cvm__scan *s, cvm__ctx *ctx, cvm__reader *r, const char *name)
{
    memset(s, 0, sizeof *s);
    s->ctx = ctx;
    s->r = r;
    s->name = name;
}

void cvm__scan_free(cvm__scan *s)
{
    cvm__free(s->ctx, s->chunk);
    cvm__free(s->ctx, s->line);
    s->chunk = NULL;
    s->line = NULL;
    s->line_cap = 0;
}

cvm_status cvm__scan_error(cvm__scan *s, cvm_status st, const char *fmt, ...)
{
    char what[CVM__ERRMSG_LEN];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    return cvm__error(s->ctx, st, CVM_ENT_FILE_LINE, (int64_t)s->lineno, "%s:%ld: %s", s->name,
                      s->lineno, what);
}

/* Refill the chunk; *more = 0 at end of file. */
static cvm_status refill(cvm__scan *s, int *more)
{
    long got;
    *more = 0;
    if (s->eof)
        return CVM_OK;
    if (!s->chunk) {
        s->chunk = cvm__malloc(s->ctx, CHUNK);
        if (!s->chunk)
            return cvm__nomem(s->ctx);
    } else if (cvm__poll_cancel(s->ctx, CVM_STAGE_READ, 0.0)) { /* every CHUNK bytes */
        return cvm__error(s->ctx, CVM_INCOMPLETE_CANCELLED, CVM_ENT_NONE, -1,
                          "reading %s was cancelled", s->name);
    }
    got = s->r->read(s->r->self, s->chunk, CHUNK);
    if (got < 0 || got > CHUNK)
        return cvm__error(s->ctx, CVM_E_IO_READ, CVM_ENT_FILE_LINE, (int64_t)(s->lineno + 1),
                          "%s:%ld: read error", s->name, s->lineno + 1);
    s->pos = 0;
    s->len = (size_t)got;
    if (got == 0)
        s->eof = 1;
    else
        *more = 1;
    return CVM_OK;
}

/* Append n bytes to the current line. */
static cvm_status append(cvm__scan *s, const char *p, size_t n)
{
    if (s->line_len + n > CVM__LINE_MAX)
        return cvm__error(s->ctx, CVM_E_IO_FORMAT, CVM_ENT_FILE_LINE, (int64_t)(s->lineno + 1),
                          "%s:%ld: line longer than %d bytes (not a text file?)", s->name,
                          s->lineno + 1, CVM__LINE_MAX);
    if (s->line_len + n + 1 > s->line_cap &&
        cvm__grow(s->ctx, (void **)&s->line, &s->line_cap, s->line_len + n + 1, 1))
        return cvm__nomem(s->ctx);
    memcpy(s->line + s->line_len, p, n);
    s->line_len += n;
    return CVM_OK;
}

/* Read one physical line into s->line; *got = 0 at end of file. */
static cvm_status read_physical(cvm__scan *s, int *got)
{
    cvm_status st;
    int more;
    s->line_len = 0;
    *got = 0;
    for (;;) {
        char *nl;
        size_t n;
        if (s->pos == s->len) {
            if ((st = refill(s, &more)))
                return st;
            if (!more)
                break;
        }
        nl = memchr(s->chunk + s->pos, '\n', s->len - s->pos);
        n = nl ? (size_t)(nl - (s->chunk + s->pos)) : s->len - s->pos;
        *got = 1;
        if (s->nlines < s->lineno + 1)
            s->nlines = s->lineno + 1;
        if ((st = append(s, s->chunk + s->pos, n)))
            return st;
        s->pos += n;
        if (nl) {
            s->pos++;
            break;
        }
    }
    if (*got)
        s->lineno++;
    return CVM_OK;
}

/* Strip the comment, split into NUL-separated fields and count them. */
static cvm_status split(cvm__scan *s)
{
    size_t i, n = 0;
    int in_field = 0;
    char *l = s->line;
    for (i = 0; i < s->line_len; i++) {
        char c = l[i];
        if (c == '\0')
            return cvm__scan_error(s, CVM_E_IO_FORMAT, "NUL byte in line (not a text file?)");
        if (c == '#') {
            s->line_len = i;
            break;
        }
        if (c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f') {
            l[i] = '\0';
            in_field = 0;
        } else if (!in_field) {
            in_field = 1;
            n++;
        }
    }
    l[s->line_len] = '\0';
    s->nfields = n;
    s->cursor = 0;
    return CVM_OK;
}

cvm_status cvm__scan_line(cvm__scan *s, int *got)
{
    cvm_status st;
    for (;;) {
        int have;
        if ((st = read_physical(s, &have)))
            return st;
        if (!have) {
            /* at end of file, messages point at the last line of the file */
            s->lineno = s->nlines > 0 ? s->nlines : 1;
            s->nfields = 0;
            *got = 0;
            return CVM_OK;
        }
        if ((st = split(s)))
            return st;
        if (s->nfields) {
            *got = 1;
            return CVM_OK;
        }
    }
}

const char *cvm__scan_field(cvm__scan *s)
{
    const char *f;
    while (s->cursor < s->line_len && s->line[s->cursor] == '\0')
        s->cursor++;
    if (s->cursor >= s->line_len)
        return NULL;
    f = s->line + s->cursor;
    s->cursor += strlen(f);
    return f;
}
