/* reader.c - a cvm__reader that reads a file through stdio. */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "io_internal.h"

static long file_read(void *self, char *buf, size_t len)
{
    FILE *f = (FILE *)self;
    size_t got = fread(buf, 1, len, f);
    if (got == 0 && ferror(f))
        return -1;
    return (long)got;
}

cvm_status cvm__file_reader_open(cvm__ctx *ctx, cvm__reader *r, const char *path)
{
    FILE *f;
    r->read = file_read;
    r->self = NULL;
    errno = 0;
    f = fopen(path, "rb");
    if (!f) {
        char why[128];
        cvm__strerror(errno, why, sizeof why);
        return cvm__error(ctx, CVM_E_IO_OPEN, CVM_ENT_NONE, -1, "cannot open %s: %s", path, why);
    }
    {
        /* fopen() opens a directory on POSIX systems; only the first read
           fails, with a bare "read error": say what it is instead */
        struct stat st;
        if (fstat(fileno(f), &st) == 0 && S_ISDIR(st.st_mode)) {
            fclose(f);
            return cvm__error(ctx, CVM_E_IO_OPEN, CVM_ENT_NONE, -1,
                              "cannot read %s: it is a directory", path);
        }
    }
    r->self = f;
    return CVM_OK;
}

void cvm__file_reader_close(cvm__reader *r)
{
    if (r->self)
        fclose((FILE *)r->self);
    r->self = NULL;
}

void cvm__strerror(int err, char *buf, size_t len)
{
    if (len == 0)
        return;
    if (err == 0) {
        snprintf(buf, len, "unknown error");
        return;
    }
    /* XSI strerror_r (thread-safe), selected by _POSIX_C_SOURCE >= 200112L */
    if (strerror_r(err, buf, len) != 0)
        snprintf(buf, len, "error %d", err);
}
