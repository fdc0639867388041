/* write_triangle.c - writes a mesh as Triangle's .node, .ele and .edge files, numbered from 0. */
#include "formats.h"

/* <#vertices> 2 <#attributes> 1, then: <vertex> <x> <y> [attributes] <marker>.
 * Every vertex is written, used by a triangle or not, so ids stay the same. */
void cvm__write_node(cvm__writer *w, const cvm__mesh_out *mo)
{
    size_t v, k, na = mo->vattr ? mo->nattr : 0;
    cvm__writer_printf(w, "%lu 2 %lu 1\n", (unsigned long)mo->nv, (unsigned long)na);
    for (v = 0; v < mo->nv; v++) {
        cvm__writer_printf(w, "%lu ", (unsigned long)v);
        cvm__writer_double(w, mo->xy[2 * v]);
        cvm__writer_puts(w, " ");
        cvm__writer_double(w, mo->xy[2 * v + 1]);
        for (k = 0; k < na; k++) {
            cvm__writer_puts(w, " ");
            cvm__writer_double(w, mo->vattr[v * na + k]);
        }
        cvm__writer_printf(w, " %ld\n", (long)(mo->vmark ? mo->vmark[v] : 0));
    }
}

/* <#triangles> 3 <#attributes>, then: <triangle> <v0> <v1> <v2> [regional attribute]. */
void cvm__write_ele(cvm__writer *w, const cvm__mesh_out *mo)
{
    size_t t;
    cvm__writer_printf(w, "%lu 3 %d\n", (unsigned long)mo->nt, mo->tattr ? 1 : 0);
    for (t = 0; t < mo->nt; t++) {
        const int32_t *v = mo->tri + 3 * t;
        cvm__writer_printf(w, "%lu %ld %ld %ld", (unsigned long)t, (long)v[0], (long)v[1], (long)v[2]);
        if (mo->tattr) {
            cvm__writer_puts(w, " ");
            cvm__writer_double(w, mo->tattr[t]);
        }
        cvm__writer_puts(w, "\n");
    }
}

/* <#edges> 1, then: <edge> <v0> <v1> <boundary marker> (0 for interior edges). */
void cvm__write_edge(cvm__writer *w, const cvm__mesh_out *mo)
{
    size_t e;
    cvm__writer_printf(w, "%lu 1\n", (unsigned long)mo->ne);
    for (e = 0; e < mo->ne; e++)
        cvm__writer_printf(w, "%lu %ld %ld %ld\n", (unsigned long)e, (long)mo->edge[2 * e],
                           (long)mo->edge[2 * e + 1], (long)(mo->emark ? mo->emark[e] : 0));
}
