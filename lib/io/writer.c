/*
 * writer.c - an output file that appears whole or not at all: text goes to a
 * fresh temporary file beside the target (with the target's permissions when
 * it replaces one), which is flushed, synced, closed and then renamed over
 * the target; any failure or cancellation removes the temporary file. A
 * write set renames several such files together and puts back the files it
 * replaced when one rename fails.
 * Text collects in a buffer inside the writer (so a number costs a memcpy,
 * not a locked stdio call) and goes to the file a block at a time.
 */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io_text.h"

/* Size of the writer's own buffer; holds any one number or short line. */
#define WBUF 65536

struct cvm__writer {
    cvm__ctx *ctx;
    FILE *f;
    char *path;     /* as the caller named it, for messages */
    char *target;   /* the file replaced: path, or where its symbolic link leads */
    char *tmp;      /* temporary file, NULL when writing in place */
    int err;        /* errno of the first output error, 0 if none */
    int cancelled;  /* 1 once the progress callback asked to stop */
    int finished;   /* 1 once the file is closed */
    cvm_status status; /* result of cvm__writer_finish() */
    uint64_t nput;  /* values and strings put so far */
    uint64_t before;/* for the fraction: puts of earlier files of the same write */
    uint64_t expect;/* for the fraction: about how many puts in all (0: unknown) */
    uint64_t poll;  /* ask the progress callback every poll puts */
    char *bak;      /* during a set's commit: a hard link to the replaced file, or NULL */
    int existed;    /* during a set's commit: the target existed before */
    size_t used;    /* bytes of buf not yet given to f */
    char buf[WBUF];
};

static char *dup_str(cvm__ctx *ctx, const char *s)
{
    size_t n = strlen(s) + 1;
    char *d = cvm__malloc(ctx, n);
    if (d)
        memcpy(d, s, n);
    return d;
}

static uint64_t mix(uint64_t z)
{
    z += 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* Write target + ".tmp." + 6 characters, different for each attempt. */
static void tmp_name(char *buf, size_t len, const char *target, const void *w, unsigned attempt)
{
    static const char digits[] = "0123456789abcdefghijklmnopqrstuvwxyz";
    double now = cvm__now();
    uint64_t t, z;
    char sfx[7];
    int i;
    memcpy(&t, &now, sizeof t);
    z = mix(t ^ mix((uint64_t)getpid()) ^ mix((uint64_t)(uintptr_t)w) ^ mix(attempt));
    for (i = 0; i < 6; i++) {
        sfx[i] = digits[z % 36];
        z /= 36;
    }
    sfx[6] = '\0';
    snprintf(buf, len, "%s.tmp.%s", target, sfx);
}

static cvm_status os_error(cvm__writer *w, cvm_status s, const char *verb, int err)
{
    char why[128];
    cvm__strerror(err, why, sizeof why);
    return cvm__error(w->ctx, s, CVM_ENT_NONE, -1, "cannot %s %s: %s", verb, w->path, why);
}

/* Follow the symbolic links of w->path (at most 40) into w->target. */
static cvm_status follow_links(cvm__writer *w)
{
    char link[4096];
    int depth;
    if (!(w->target = dup_str(w->ctx, w->path)))
        return cvm__nomem(w->ctx);
    for (depth = 0; depth < 40; depth++) {
        struct stat st;
        ssize_t n;
        size_t dir = 0, i, len;
        char *next;
        if (lstat(w->target, &st) != 0 || !S_ISLNK(st.st_mode))
            return CVM_OK;
        n = readlink(w->target, link, sizeof link);
        if (n < 0 || (size_t)n >= sizeof link)
            return CVM_OK; /* cannot say: write through the link */
        if (link[0] != '/')
            for (i = 0; w->target[i]; i++)
                if (w->target[i] == '/')
                    dir = i + 1;
        len = dir + (size_t)n;
        if (!(next = cvm__malloc(w->ctx, len + 1)))
            return cvm__nomem(w->ctx);
        memcpy(next, w->target, dir);
        memcpy(next + dir, link, (size_t)n);
        next[len] = '\0';
        cvm__free(w->ctx, w->target);
        w->target = next;
    }
    return CVM_OK;
}

/* Decide the target: path itself, or the file its links lead to.
 * *in_place = 1 when the target exists and is not a regular file, or is
 * still a link (a loop). */
static cvm_status resolve(cvm__writer *w, int *in_place)
{
    struct stat st;
    cvm_status s = follow_links(w);
    *in_place = 0;
    if (s)
        return s;
    if (lstat(w->target, &st) == 0 && !S_ISREG(st.st_mode))
        *in_place = 1;
    return CVM_OK;
}

/* The replaced file's owner and permissions go to the temporary file, so the
 * rename keeps them; a new file gets the umask's. Best effort: a failure
 * (another owner, a file system without modes) leaves the umask's. */
static void keep_attributes(int fd, const char *target)
{
    struct stat st;
    if (lstat(target, &st) != 0 || !S_ISREG(st.st_mode))
        return;
    if (st.st_uid != geteuid() || st.st_gid != getegid()) {
        if (fchown(fd, st.st_uid, st.st_gid) != 0) {
            /* not allowed: the new file keeps our owner */
        }
    }
    if (fchmod(fd, st.st_mode & 07777) != 0) {
        /* keep the umask's permissions */
    }
}

static cvm_status open_tmp(cvm__writer *w)
{
    size_t len = strlen(w->target) + 16;
    unsigned attempt;
    int fd = -1;
    w->tmp = cvm__malloc(w->ctx, len);
    if (!w->tmp)
        return cvm__nomem(w->ctx);
    for (attempt = 0; attempt < 100; attempt++) {
        tmp_name(w->tmp, len, w->target, w, attempt);
        fd = open(w->tmp, O_WRONLY | O_CREAT | O_EXCL, 0666);
        if (fd >= 0 || errno != EEXIST)
            break;
    }
    if (fd < 0) {
        int err = errno;
        cvm__free(w->ctx, w->tmp);
        w->tmp = NULL;
        return os_error(w, CVM_E_IO_OPEN, "create", err);
    }
    keep_attributes(fd, w->target);
    w->f = fdopen(fd, "w");
    if (!w->f) {
        int err = errno;
        close(fd);
        unlink(w->tmp);
        cvm__free(w->ctx, w->tmp);
        w->tmp = NULL;
        return os_error(w, CVM_E_IO_OPEN, "create", err);
    }
    return CVM_OK;
}

static void free_writer(cvm__writer *w)
{
    cvm__ctx *ctx = w->ctx;
    cvm__free(ctx, w->path);
    cvm__free(ctx, w->target);
    cvm__free(ctx, w->tmp);
    cvm__free(ctx, w->bak);
    cvm__free(ctx, w);
}

cvm_status cvm__writer_open(cvm__writer **out, cvm__ctx *ctx, const char *path)
{
    cvm__writer *w;
    cvm_status s;
    int in_place;
    *out = NULL;
    w = cvm__calloc(ctx, 1, sizeof *w);
    if (!w)
        return cvm__nomem(ctx);
    w->ctx = ctx;
    w->poll = ctx->progress_every > 64 ? (uint64_t)ctx->progress_every : 64;
    w->path = dup_str(ctx, path);
    if (!w->path) {
        free_writer(w);
        return cvm__nomem(ctx);
    }
    if ((s = resolve(w, &in_place))) {
        free_writer(w);
        return s;
    }
    if (in_place) {
        w->f = fopen(w->path, "w");
        s = w->f ? CVM_OK : os_error(w, CVM_E_IO_OPEN, "open", errno);
    } else {
        s = open_tmp(w);
    }
    if (s) {
        free_writer(w);
        return s;
    }
    *out = w;
    return CVM_OK;
}

static void note_error(cvm__writer *w)
{
    if (!w->err)
        w->err = errno ? errno : EIO;
}

void cvm__writer_expect(cvm__writer *w, uint64_t before, uint64_t total)
{
    w->before = before;
    w->expect = total;
}

/* 1 when nothing more is to be written: an error, or a cancellation, which
 * the progress callback (stage CVM_STAGE_WRITE) is asked about every w->poll
 * puts. */
static int stopped(cvm__writer *w)
{
    if (w->err || w->cancelled || !w->f)
        return 1;
    if (++w->nput % w->poll == 0) {
        double f = w->expect ? (double)(w->before + w->nput) / (double)w->expect : 0.0;
        if (cvm__poll_cancel(w->ctx, CVM_STAGE_WRITE, f > 0.99 ? 0.99 : f))
            w->cancelled = 1;
    }
    return w->cancelled;
}

/* Give the buffered bytes to the file. */
static void flush_buf(cvm__writer *w)
{
    if (w->used && !w->err && w->f) {
        errno = 0;
        if (fwrite(w->buf, 1, w->used, w->f) != w->used)
            note_error(w);
    }
    w->used = 0;
}

/* Room for n more bytes in buf (n <= WBUF); 0 after an output error or a
 * cancellation. */
static int room(cvm__writer *w, size_t n)
{
    if (w->err || w->cancelled || !w->f)
        return 0;
    if (WBUF - w->used < n)
        flush_buf(w);
    return !w->err;
}

void cvm__writer_write(cvm__writer *w, const char *s, size_t n)
{
    if (stopped(w))
        return;
    if (n > WBUF) {
        flush_buf(w);
        if (w->err || !w->f)
            return;
        errno = 0;
        if (fwrite(s, 1, n, w->f) != n)
            note_error(w);
        return;
    }
    if (!room(w, n))
        return;
    memcpy(w->buf + w->used, s, n);
    w->used += n;
}

void cvm__writer_puts(cvm__writer *w, const char *s)
{
    cvm__writer_write(w, s, strlen(s));
}

/* Not counted as a put: separators would make the progress fraction depend
 * on the layout more than on the size. */
void cvm__writer_putc(cvm__writer *w, char c)
{
    if (!room(w, 1))
        return;
    w->buf[w->used++] = c;
}

void cvm__writer_printf(cvm__writer *w, const char *fmt, ...)
{
    va_list ap;
    int r;
    if (stopped(w))
        return;
    va_start(ap, fmt);
    r = vsnprintf(w->buf + w->used, WBUF - w->used, fmt, ap);
    va_end(ap);
    if (r < 0) {
        note_error(w);
        return;
    }
    if ((size_t)r < WBUF - w->used) {
        w->used += (size_t)r;
        return;
    }
    /* did not fit: flush and print again, straight to the file if too long */
    flush_buf(w);
    if (w->err)
        return;
    va_start(ap, fmt);
    if ((size_t)r < WBUF) {
        vsnprintf(w->buf, WBUF, fmt, ap);
        w->used = (size_t)r;
    } else {
        errno = 0;
        if (vfprintf(w->f, fmt, ap) < 0)
            note_error(w);
    }
    va_end(ap);
}

void cvm__writer_double(cvm__writer *w, double x)
{
    const char *t = x > 0 ? "inf" : "-inf";
    if (stopped(w) || !room(w, CVM__DOUBLE_BUF))
        return;
    if (isnan(x))
        t = "nan";
    else if (!isinf(x))
        t = NULL;
    if (t) {
        memcpy(w->buf + w->used, t, strlen(t));
        w->used += strlen(t);
    } else {
        w->used += cvm__format_double(w->buf + w->used, x);
    }
}

void cvm__writer_long(cvm__writer *w, long long v)
{
    if (!stopped(w) && room(w, CVM__INT_BUF))
        w->used += cvm__format_long(w->buf + w->used, v);
}

void cvm__writer_ulong(cvm__writer *w, unsigned long long v)
{
    if (!stopped(w) && room(w, CVM__INT_BUF))
        w->used += cvm__format_ulong(w->buf + w->used, v);
}

cvm_status cvm__writer_finish(cvm__writer *w)
{
    if (w->finished)
        return w->status;
    w->finished = 1;
    flush_buf(w);
    errno = 0;
    if (fflush(w->f) != 0)
        note_error(w);
    if (ferror(w->f))
        note_error(w);
    errno = 0;
    if (!w->err && !w->cancelled && w->tmp && fsync(fileno(w->f)) != 0)
        note_error(w);
    errno = 0;
    if (fclose(w->f) != 0)
        note_error(w);
    w->f = NULL;
    if (w->cancelled)
        w->status = cvm__error(w->ctx, CVM_INCOMPLETE_CANCELLED, CVM_ENT_NONE, -1,
                               "writing %s was cancelled", w->path);
    else
        w->status = w->err ? os_error(w, CVM_E_IO_WRITE, "write", w->err) : CVM_OK;
    return w->status;
}

void cvm__writer_discard(cvm__writer *w)
{
    if (!w)
        return;
    if (w->f)
        fclose(w->f);
    if (w->tmp)
        unlink(w->tmp);
    free_writer(w);
}

cvm_status cvm__writer_commit(cvm__writer *w)
{
    cvm_status s = cvm__writer_finish(w);
    if (!s && w->tmp && rename(w->tmp, w->target) != 0)
        s = os_error(w, CVM_E_IO_WRITE, "replace", errno);
    if (s) {
        cvm__writer_discard(w);
        return s;
    }
    free_writer(w);
    return CVM_OK;
}

void cvm__write_set_init(cvm__write_set *ws, cvm__ctx *ctx)
{
    ws->ctx = ctx;
    ws->w = NULL;
    ws->n = ws->cap = 0;
}

cvm_status cvm__write_set_add(cvm__write_set *ws, cvm__writer *w)
{
    cvm_status s = cvm__writer_finish(w);
    if (!s && cvm__grow(ws->ctx, (void **)&ws->w, &ws->cap, ws->n + 1, sizeof *ws->w))
        s = cvm__nomem(ws->ctx);
    if (s) {
        cvm__writer_discard(w);
        return s;
    }
    ws->w[ws->n++] = w;
    return CVM_OK;
}

void cvm__write_set_discard(cvm__write_set *ws)
{
    size_t i;
    for (i = 0; i < ws->n; i++)
        cvm__writer_discard(ws->w[i]);
    cvm__free(ws->ctx, ws->w);
    cvm__write_set_init(ws, ws->ctx);
}

/* Before any rename: note whether w's target exists and, when it is a
 * regular file, keep it under a second name (a hard link) so that a failed
 * commit can put it back. No link (a file system without them) leaves only
 * the note: then that file cannot be put back. CVM_OK or CVM_E_NOMEM. */
static cvm_status keep_old(cvm__writer *w)
{
    size_t len = strlen(w->target) + 16;
    unsigned attempt;
    struct stat st;
    w->existed = lstat(w->target, &st) == 0;
    if (!w->existed || !S_ISREG(st.st_mode))
        return CVM_OK;
    if (!(w->bak = cvm__malloc(w->ctx, len)))
        return cvm__nomem(w->ctx);
    for (attempt = 0; attempt < 100; attempt++) {
        tmp_name(w->bak, len, w->target, w->bak, attempt);
        if (link(w->target, w->bak) == 0)
            return CVM_OK;
        if (errno != EEXIST)
            break;
    }
    cvm__free(w->ctx, w->bak);
    w->bak = NULL;
    return CVM_OK;
}

/* Undo the renames of writers 0 .. n-1 (last first): put each replaced file
 * back, or remove the new file where there was none. */
static void put_back(cvm__writer **w, size_t n)
{
    while (n-- > 0) {
        if (!w[n]->tmp)
            continue;
        if (w[n]->bak) {
            if (rename(w[n]->bak, w[n]->target) == 0) {
                cvm__free(w[n]->ctx, w[n]->bak);
                w[n]->bak = NULL;
            }
        } else if (!w[n]->existed) {
            unlink(w[n]->target);
        }
    }
}

cvm_status cvm__write_set_commit(cvm__write_set *ws)
{
    cvm_status s = CVM_OK;
    size_t i, done = 0;
    int err = 0;
    for (i = 0; i < ws->n && !s; i++)
        if (ws->w[i]->tmp)
            s = keep_old(ws->w[i]);
    for (i = 0; i < ws->n && !s; i++, done++) {
        cvm__writer *w = ws->w[i];
        if (w->tmp && rename(w->tmp, w->target) != 0) {
            err = errno;
            s = CVM_E_IO_WRITE;
            break;
        }
    }
    if (s == CVM_E_IO_WRITE) {
        put_back(ws->w, done);
        s = os_error(ws->w[done], CVM_E_IO_WRITE, "replace", err);
    }
    for (i = 0; i < ws->n; i++) {
        cvm__writer *w = ws->w[i];
        if (w->bak)
            unlink(w->bak);
        if (i < done) { /* renamed: its temporary name is the target's now */
            cvm__free(w->ctx, w->tmp);
            w->tmp = NULL;
        }
        cvm__writer_discard(w);
    }
    cvm__free(ws->ctx, ws->w);
    cvm__write_set_init(ws, ws->ctx);
    return s;
}
