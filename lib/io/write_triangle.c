/* write_triangle.c - writes a mesh as Triangle's .node, .ele and .edge files, numbered from 0. */
#include "formats.h"

/* <#vertices> 2 <#attributes> 1, then: <vertex> <x> <y> [attributes] <marker>.
 * Every vertex is written, used by a triangle or not, so ids stay the same. */
void cvm__write_node(cvm__writer *w, const cvm__mesh_out *mo)
{
    size_t v, k, na = mo->vattr ? mo->nattr : 0;
    cvm__writer_printf(w, "%lu 2 %lu 1\n", (unsigned long)mo->nv, (unsigned long)na);
    for (v = 0; v < mo->nv; v++) {
        cvm__writer_ulong(w, v);
        cvm__writer_putc(w, ' ');
        cvm__writer_double(w, mo->xy[2 * v]);
        cvm__writer_putc(w, ' ');
        cvm__writer_double(w, mo->xy[2 * v + 1]);
        for (k = 0; k < na; k++) {
            cvm__writer_putc(w, ' ');
            cvm__writer_double(w, mo->vattr[v * na + k]);
        }
        cvm__writer_putc(w, ' ');
        cvm__writer_long(w, mo->vmark ? mo->vmark[v] : 0);
        cvm__writer_putc(w, '\n');
    }
}

/* <#triangles> 3 <#attributes>, then: <triangle> <v0> <v1> <v2> [regional attribute]. */
void cvm__write_ele(cvm__writer *w, const cvm__mesh_out *mo)
{
    size_t t;
    cvm__writer_printf(w, "%lu 3 %d\n", (unsigned long)mo->nt, mo->tattr ? 1 : 0);
    for (t = 0; t < mo->nt; t++) {
        const int32_t *v = mo->tri + 3 * t;
        int j;
        cvm__writer_ulong(w, t);
        for (j = 0; j < 3; j++) {
            cvm__writer_putc(w, ' ');
            cvm__writer_long(w, v[j]);
        }
        if (mo->tattr) {
            cvm__writer_putc(w, ' ');
            cvm__writer_double(w, mo->tattr[t]);
        }
        cvm__writer_putc(w, '\n');
    }
}

/* <#edges> 1, then: <edge> <v0> <v1> <boundary marker> (0 for interior edges). */
void cvm__write_edge(cvm__writer *w, const cvm__mesh_out *mo)
{
    size_t e;
    cvm__writer_printf(w, "%lu 1\n", (unsigned long)mo->ne);
    for (e = 0; e < mo->ne; e++) {
        cvm__writer_ulong(w, e);
        cvm__writer_putc(w, ' ');
        cvm__writer_long(w, mo->edge[2 * e]);
        cvm__writer_putc(w, ' ');
        cvm__writer_long(w, mo->edge[2 * e + 1]);
        cvm__writer_putc(w, ' ');
        cvm__writer_long(w, mo->emark ? mo->emark[e] : 0);
        cvm__writer_putc(w, '\n');
    }
}
