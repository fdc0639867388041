/*
 * read_tetele.c - parses TetGen's .ele (the tetrahedra of a mesh whose points
 * are in a .node) into flat arrays.
 *
 * Format (H. Si, TetGen 1.5 user's manual, section 5.2.4):
 *   <#tetrahedra> [<nodes per tetrahedron: 4 or 10> [<#attributes>]]
 *   <number> <n1> <n2> <n3> <n4> [<n5> ... <n10>] [attributes...]
 * Tetrahedra are numbered in sequence from 0 or 1, as the first one says; the
 * corners use the numbering of the .node (its first point number, base). Of
 * the attributes, the first is kept as the region attribute; the others are
 * checked to be numbers and dropped. Quadratic tetrahedra (10 nodes) are
 * refused with CVM_E_UNSUPPORTED. Nothing may follow the last tetrahedron.
 */
#include <limits.h>
#include <stdio.h>
#include <string.h>

#include "surf3_io.h"

#define ELE_MAX_ATTR 10000

cvm_status cvm__read_tetele(cvm__ctx *ctx, cvm__reader *r, const char *name, long long base,
                            size_t np, cvm__tetele *out)
{
    cvm__scan sc;
    long long nt = 0, nodes = 4, nattr = 0, i, k, first = 0, num, v;
    cvm_status s;
    size_t n, cap_tet = 0, cap_attr = 0;
    memset(out, 0, sizeof *out);
    cvm__scan_init(&sc, ctx, r, name);
    if ((s = cvm__s3_need_line(&sc, "the tetrahedron count line")))
        goto done;
    n = sc.nfields;
    if (n > 3) {
        s = cvm__scan_error(&sc, CVM_E_IO_FORMAT,
                            "tetrahedron count line: expected at most 3 fields (tetrahedra, nodes "
                            "per tetrahedron, attributes), found %lu", (unsigned long)n);
        goto done;
    }
    if ((s = cvm__s3_count(&sc, "tetrahedron count", &nt)) ||
        (n > 1 && (s = cvm__s3_int(&sc, "nodes per tetrahedron", LLONG_MIN, LLONG_MAX, &nodes))) ||
        (n > 2 && (s = cvm__s3_count(&sc, "attribute count", &nattr))))
        goto done;
    if (nodes == 10) {
        s = cvm__scan_error(&sc, CVM_E_UNSUPPORTED,
                            "quadratic tetrahedra (10 nodes) are not supported: only 4 corners");
        goto done;
    }
    if (nodes != 4) {
        s = cvm__scan_error(&sc, CVM_E_IO_FORMAT, "%lld nodes per tetrahedron: expected 4", nodes);
        goto done;
    }
    if (nattr > ELE_MAX_ATTR) {
        s = cvm__scan_error(&sc, CVM_E_TOO_LARGE, "%lld attributes per tetrahedron: at most %d",
                            nattr, ELE_MAX_ATTR);
        goto done;
    }
    for (i = 0; i < nt; i++) {
        char what[64];
        double a;
        snprintf(what, sizeof what, "tetrahedron %lld of %lld", i + 1, nt);
        /* grown as lines arrive: the header's count alone allocates nothing */
        if (cvm__grow(ctx, (void **)&out->tet, &cap_tet, 4 * ((size_t)i + 1), sizeof *out->tet) ||
            (nattr && cvm__grow(ctx, (void **)&out->attr, &cap_attr, (size_t)i + 1,
                                sizeof *out->attr))) {
            s = cvm__nomem(ctx);
            goto done;
        }
        if ((s = cvm__s3_need_line(&sc, what)) ||
            (s = cvm__s3_want_fields(&sc, (size_t)(5 + nattr), (size_t)(5 + nattr), what,
                                     nattr ? "number, 4 corners, attributes" : "number, 4 corners")) ||
            (s = cvm__s3_int(&sc, "tetrahedron number", LLONG_MIN, LLONG_MAX, &num)))
            goto done;
        if (i == 0) {
            if (num != 0 && num != 1) {
                s = cvm__scan_error(&sc, CVM_E_IO_FORMAT,
                                    "the first tetrahedron is numbered %lld: it must be 0 or 1", num);
                goto done;
            }
            first = num;
        } else if (num != first + i) {
            s = cvm__scan_error(&sc, CVM_E_IO_FORMAT,
                                "tetrahedron number %lld out of sequence: expected %lld", num,
                                first + i);
            goto done;
        }
        for (k = 0; k < 4; k++) {
            const char *f = cvm__scan_field(&sc);
            int rr = cvm__parse_long(f, LLONG_MIN, LLONG_MAX, &v);
            if (rr == 1) {
                s = cvm__scan_error(&sc, CVM_E_IO_FORMAT,
                                    "tetrahedron %lld: corner %lld: expected an integer, found "
                                    "'%.40s'", num, k + 1, f);
                goto done;
            }
            if (rr || v < base || v >= base + (long long)np) {
                s = cvm__scan_error(&sc, CVM_E_IO_FORMAT,
                                    "tetrahedron %lld names point %.40s, but points are numbered "
                                    "%lld..%lld", num, f, base, base + (long long)np - 1);
                goto done;
            }
            out->tet[4 * (size_t)i + (size_t)k] = (int32_t)(v - base);
        }
        for (k = 0; k < nattr; k++) {
            if ((s = cvm__s3_real(&sc, "attribute of tetrahedron", num, &a)))
                goto done;
            if (k == 0)
                out->attr[i] = a;
        }
    }
    out->nt = (size_t)nt;
    out->first = first;
    s = cvm__s3_expect_end(&sc, "last tetrahedron");
done:
    cvm__scan_free(&sc);
    if (s)
        cvm__tetele_free(ctx, out);
    return s;
}

void cvm__tetele_free(cvm__ctx *ctx, cvm__tetele *t)
{
    cvm__free(ctx, t->tet);
    cvm__free(ctx, t->attr);
    memset(t, 0, sizeof *t);
}
