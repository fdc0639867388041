/* marker_names.c - the marker <-> name table of a mesh handle (Gmsh physical names): set, get,
 * list, and the names of a .msh file read by cvm_mesh_read(). */
#include <stdlib.h>
#include <string.h>

#include "api_internal.h"

/* Index of (dim, tag) in m's sorted table, or where it would go (*found 0). */
static size_t find(const cvm_mesh *m, int32_t dim, int32_t tag, int *found)
{
    size_t lo = 0, hi = m->nnames;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        const cvm__phys_name *p = &m->names[mid];
        if (p->dim < dim || (p->dim == dim && p->tag < tag))
            lo = mid + 1;
        else
            hi = mid;
    }
    *found = lo < m->nnames && m->names[lo].dim == dim && m->names[lo].tag == tag;
    return lo;
}

void cvm__mesh_set_names(cvm_mesh *m, cvm__phys_name *names, size_t n)
{
    cvm__free(&m->ctx, m->names);
    m->names = names;
    m->nnames = n;
}

/* Order of a file's names: (dim, tag), then position (the first of a repeat wins). */
typedef struct keyed {
    cvm__phys_name name;
    size_t pos;
} keyed;

static int cmp_keyed(const void *pa, const void *pb)
{
    const keyed *a = pa, *b = pb;
    if (a->name.dim != b->name.dim)
        return a->name.dim < b->name.dim ? -1 : 1;
    if (a->name.tag != b->name.tag)
        return a->name.tag < b->name.tag ? -1 : 1;
    return a->pos < b->pos ? -1 : a->pos > b->pos;
}

cvm_status cvm__mesh_read_names(cvm_mesh *m, const char *path, cvm__phys_name **names_out,
                                size_t *n_out)
{
    cvm__phys_name *names;
    keyed *k;
    size_t n, i, j;
    cvm_status s;
    *names_out = NULL;
    *n_out = 0;
    if (!cvm__path_has_ext(path, ".msh"))
        return CVM_OK;
    if ((s = cvm__read_msh_names_file(&m->ctx, path, &names, &n)) || !n)
        return s;
    k = cvm__malloc(&m->ctx, n * sizeof *k);
    if (!k) {
        cvm__free(&m->ctx, names);
        return cvm__nomem(&m->ctx);
    }
    for (i = 0; i < n; i++) {
        k[i].name = names[i];
        k[i].pos = i;
    }
    qsort(k, n, sizeof *k, cmp_keyed);
    for (i = 0, j = 0; i < n; i++)
        if (j == 0 || k[i].name.dim != names[j - 1].dim || k[i].name.tag != names[j - 1].tag)
            names[j++] = k[i].name;
    cvm__free(&m->ctx, k);
    *names_out = names;
    *n_out = j;
    return CVM_OK;
}

cvm_status cvm_mesh_set_marker_name(cvm_mesh *m, int dim, int32_t marker, const char *name)
{
    size_t at, len, k;
    int found;
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    if (dim < 0 || dim > 3)
        return cvm__error(&m->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "marker name: dimension %d is not 0, 1, 2 or 3", dim);
    at = find(m, dim, marker, &found);
    if (!name) { /* remove */
        if (found) {
            memmove(m->names + at, m->names + at + 1, (m->nnames - at - 1) * sizeof *m->names);
            m->nnames--;
        }
        return CVM_OK;
    }
    len = strlen(name);
    if (len == 0 || len >= sizeof m->names[0].name)
        return cvm__error(&m->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                          "marker name of (%d, %ld) has %lu bytes (1 to %lu)", dim, (long)marker,
                          (unsigned long)len, (unsigned long)sizeof m->names[0].name - 1);
    for (k = 0; k < len; k++)
        if ((unsigned char)name[k] < 0x20 || name[k] == '"' || name[k] == 0x7f)
            return cvm__error(&m->ctx, CVM_E_ARGUMENT, CVM_ENT_NONE, -1,
                              "marker name of (%d, %ld): byte %lu is a control character or a "
                              "double quote (a .msh file could not hold it)",
                              dim, (long)marker, (unsigned long)k);
    if (!found) {
        cvm__phys_name *grown = cvm__realloc(&m->ctx, m->names, (m->nnames + 1) * sizeof *grown);
        if (!grown)
            return cvm__nomem(&m->ctx);
        m->names = grown;
        memmove(m->names + at + 1, m->names + at, (m->nnames - at) * sizeof *m->names);
        m->nnames++;
        m->names[at].dim = dim;
        m->names[at].tag = marker;
    }
    memcpy(m->names[at].name, name, len + 1);
    return CVM_OK;
}

const char *cvm_mesh_get_marker_name(const cvm_mesh *m, int dim, int32_t marker)
{
    int found;
    size_t at;
    if (!m)
        return NULL;
    at = find(m, dim, marker, &found);
    return found ? m->names[at].name : NULL;
}

cvm_status cvm_mesh_copy_marker_name_keys(int32_t *dst, size_t dst_len, const cvm_mesh *m)
{
    size_t k;
    if (!m || (!dst && dst_len))
        return CVM_E_NULL_ARG;
    if (dst_len < 2 * m->nnames)
        return CVM_E_BUFFER_TOO_SMALL;
    for (k = 0; k < m->nnames; k++) {
        dst[2 * k] = m->names[k].dim;
        dst[2 * k + 1] = m->names[k].tag;
    }
    return CVM_OK;
}

cvm_status cvm_mesh_count_marker_names(size_t *out, const cvm_mesh *m)
{
    if (!out || !m)
        return CVM_E_NULL_ARG;
    *out = m->nnames;
    return CVM_OK;
}
