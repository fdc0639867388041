/* slurp.c - reads everything a cvm__reader gives into one NUL-terminated buffer. */
#include "io_internal.h"

cvm_status cvm__slurp(cvm__ctx *ctx, cvm__reader *r, const char *name, char **out, size_t *n_out)
{
    size_t cap = 0, n = 0;
    char *buf = NULL;
    *out = NULL;
    *n_out = 0;
    for (;;) {
        long got;
        if (n + 65536 + 1 > cap && cvm__grow(ctx, (void **)&buf, &cap, n + 65536 + 1, 1)) {
            cvm__free(ctx, buf);
            return cvm__nomem(ctx);
        }
        if (n && cvm__poll_cancel(ctx, CVM_STAGE_READ, 0.0)) {
            cvm__free(ctx, buf);
            return cvm__error(ctx, CVM_INCOMPLETE_CANCELLED, CVM_ENT_NONE, -1,
                              "reading %s was cancelled", name);
        }
        got = r->read(r->self, buf + n, 65536);
        if (got < 0 || got > 65536) {
            cvm__free(ctx, buf);
            return cvm__error(ctx, CVM_E_IO_READ, CVM_ENT_FILE_LINE, -1, "%s: read error", name);
        }
        if (got == 0)
            break;
        n += (size_t)got;
    }
    buf[n] = '\0';
    *out = buf;
    *n_out = n;
    return CVM_OK;
}
