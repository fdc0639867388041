/*
 * write_svg.c - draws a mesh as an SVG picture: triangles filled by a colour
 * ramp of their smallest angle (red 0 deg .. green 60 deg, from mo->tquality;
 * uniform grey-blue without it) or, for an AFLR mesh (mo->tlayer), by their
 * layer index in eight colours that repeat (grey where no front reached),
 * thin triangle edges, segments drawn thicker,
 * y pointing up, the view fitted to the mesh or to a window (triangles wholly
 * outside it left out, the rest clipped), and a labelled legend for the colours.
 * Coordinates are rounded to 0.01 px: this is a picture, not data.
 */
#include <math.h>
#include <stdio.h>

#include "formats.h"

#define WIDTH 800.0
#define MARGIN 10.0
#define LEGEND 34.0

typedef struct view {
    double minx, maxy, scale;
    double win[4]; /* shown region: xmin, ymin, xmax, ymax */
} view;

/* v with 2 decimals into buf, without the C locale's decimal point. */
static const char *px(char *buf, size_t len, double v)
{
    long long c = llround(v * 100.0);
    const char *sign = c < 0 ? "-" : "";
    if (c < 0)
        c = -c;
    snprintf(buf, len, "%s%lld.%02lld", sign, c / 100, c % 100);
    return buf;
}

static void point(cvm__writer *w, const view *vw, const double *p, const char *sep)
{
    char bx[32], by[32];
    cvm__writer_printf(w, "%s,%s%s", px(bx, sizeof bx, MARGIN + (p[0] - vw->minx) * vw->scale),
                       px(by, sizeof by, MARGIN + (vw->maxy - p[1]) * vw->scale), sep);
}

/* RdYlGn-like ramp over [0, 60] degrees. */
static void ramp(double q, int *rgb)
{
    static const int stops[5][3] = {
        {215, 48, 39}, {252, 141, 89}, {254, 224, 139}, {145, 207, 96}, {26, 152, 80}};
    double t = q / 60.0 * 4.0, f;
    int i, k;
    if (!(t > 0))
        t = 0;
    if (t > 4)
        t = 4;
    i = t >= 4 ? 3 : (int)t;
    f = t - i;
    for (k = 0; k < 3; k++)
        rgb[k] = (int)lround(stops[i][k] + f * (stops[i + 1][k] - stops[i][k]));
}

/* Colour of layer index q: eight alternating hues by integer layer, grey below 0. */
static void layer_colour(double q, int *rgb)
{
    static const int pal[8][3] = {{31, 119, 180}, {255, 187, 120}, {44, 160, 44}, {255, 152, 150},
                                  {148, 103, 189}, {219, 219, 141}, {23, 190, 207}, {247, 182, 210}};
    int k;
    if (!(q >= 0) || !isfinite(q)) {
        rgb[0] = rgb[1] = rgb[2] = 200;
        return;
    }
    for (k = 0; k < 3; k++)
        rgb[k] = pal[(long long)floor(q) % 8][k];
}

static int has_window(const cvm__mesh_out *mo)
{
    return mo->window[2] > mo->window[0] && mo->window[3] > mo->window[1];
}

/* The view: the window when one is set, else the bounding box of the triangles. */
static void fit(view *vw, const cvm__mesh_out *mo, double *w_out, double *h_out)
{
    double minx = 0, miny = 0, maxx = 1, maxy = 1, span;
    size_t t;
    int first = 1;
    if (has_window(mo)) {
        minx = mo->window[0];
        miny = mo->window[1];
        maxx = mo->window[2];
        maxy = mo->window[3];
        first = 0;
    }
    for (t = 0; first == 1 && t < 3 * mo->nt; t++) {
        const double *p = mo->xy + 2 * (size_t)mo->tri[t];
        if (t == 0) {
            minx = maxx = p[0];
            miny = maxy = p[1];
        }
        minx = p[0] < minx ? p[0] : minx;
        maxx = p[0] > maxx ? p[0] : maxx;
        miny = p[1] < miny ? p[1] : miny;
        maxy = p[1] > maxy ? p[1] : maxy;
    }
    /* The picture is WIDTH px wide whatever the aspect of the window; a mesh
     * without a window keeps its longer side at WIDTH. */
    span = has_window(mo) ? maxx - minx : maxx - minx > maxy - miny ? maxx - minx : maxy - miny;
    if (!(span > 0) || !isfinite(span))
        span = 1;
    vw->minx = minx;
    vw->maxy = maxy;
    vw->scale = (WIDTH - 2 * MARGIN) / span;
    if (!isfinite(vw->scale) || !(vw->scale > 0))
        vw->scale = 1;
    *w_out = (maxx - minx) * vw->scale + 2 * MARGIN;
    *h_out = (maxy - miny) * vw->scale + 2 * MARGIN;
    vw->win[0] = minx;
    vw->win[1] = miny;
    vw->win[2] = maxx;
    vw->win[3] = maxy;
}

/* Points a, b (and c, when not NULL) all lie on one outer side of the view. */
static int outside(const view *vw, const double *a, const double *b, const double *c)
{
    int k;
    for (k = 0; k < 2; k++) {
        double lo = vw->win[k], hi = vw->win[k + 2];
        if (a[k] < lo && b[k] < lo && (!c || c[k] < lo))
            return 1;
        if (a[k] > hi && b[k] > hi && (!c || c[k] > hi))
            return 1;
    }
    return 0;
}

static void legend_layers(cvm__writer *w, double top)
{
    char bx[32], by[32];
    int i, rgb[3];
    for (i = 0; i < 8; i++) {
        layer_colour(i, rgb);
        cvm__writer_printf(w, "<rect x=\"%s\" y=\"%s\" width=\"20\" height=\"10\" fill=\"#%02x%02x%02x\"/>\n",
                           px(bx, sizeof bx, MARGIN + 20.0 * i), px(by, sizeof by, top + 4), rgb[0],
                           rgb[1], rgb[2]);
    }
    for (i = 0; i < 8; i++)
        cvm__writer_printf(w, "<text x=\"%s\" y=\"%s\" font-family=\"sans-serif\" font-size=\"10\" "
                              "text-anchor=\"middle\">%d</text>\n",
                           px(bx, sizeof bx, MARGIN + 20.0 * i + 10), px(by, sizeof by, top + 26), i);
    cvm__writer_printf(w, "<text x=\"%s\" y=\"%s\" font-family=\"sans-serif\" font-size=\"11\">"
                          "advancing-front layer of each triangle (layer 8 has the colour of 0, and so on; "
                          "grey: no front)</text>\n",
                       px(bx, sizeof bx, MARGIN + 170), px(by, sizeof by, top + 13));
}

/* Twelve swatches of 5 degrees, labelled every 15 degrees, and the caption. */
static void legend(cvm__writer *w, double top)
{
    char bx[32], by[32];
    int i, rgb[3];
    for (i = 0; i < 12; i++) {
        ramp(5.0 * i + 2.5, rgb);
        cvm__writer_printf(w, "<rect x=\"%s\" y=\"%s\" width=\"20\" height=\"10\" fill=\"#%02x%02x%02x\"/>\n",
                           px(bx, sizeof bx, MARGIN + 20.0 * i), px(by, sizeof by, top + 4), rgb[0],
                           rgb[1], rgb[2]);
    }
    for (i = 0; i <= 4; i++)
        cvm__writer_printf(w, "<text x=\"%s\" y=\"%s\" font-family=\"sans-serif\" font-size=\"10\" "
                              "text-anchor=\"middle\">%d</text>\n",
                           px(bx, sizeof bx, MARGIN + 60.0 * i), px(by, sizeof by, top + 26), 15 * i);
    cvm__writer_printf(w, "<text x=\"%s\" y=\"%s\" font-family=\"sans-serif\" font-size=\"11\">"
                          "smallest angle of each triangle, degrees (red: small, green: 60)</text>\n",
                       px(bx, sizeof bx, MARGIN + 250), px(by, sizeof by, top + 13));
}

cvm_status cvm__write_svg(cvm__writer *w, cvm__ctx *ctx, const cvm__mesh_out *mo)
{
    view vw;
    double width, height, stroke, seg_stroke;
    char bw[32], bh[32], bs[32];
    size_t t, k;
    size_t shown = 0;
    (void)ctx;
    fit(&vw, mo, &width, &height);
    for (t = 0; t < mo->nt; t++)
        shown += !outside(&vw, mo->xy + 2 * (size_t)mo->tri[3 * t], mo->xy + 2 * (size_t)mo->tri[3 * t + 1],
                          mo->xy + 2 * (size_t)mo->tri[3 * t + 2]);
    /* edges about a twentieth of a typical triangle's size, within [0.05, 1] px */
    stroke = shown ? 0.05 * sqrt(width * height / (double)shown) : 1.0;
    stroke = stroke < 0.05 ? 0.05 : stroke > 1.0 ? 1.0 : stroke;
    seg_stroke = 3 * stroke < 1.5 ? 1.5 : 3 * stroke;
    cvm__writer_printf(w, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                          "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 %s %s\" "
                          "width=\"%s\" height=\"%s\">\n",
                       px(bw, sizeof bw, width), px(bh, sizeof bh, height + (mo->tquality || mo->tlayer ? LEGEND : 0)),
                       bw, bh);
    cvm__writer_printf(w, "<title>cvmesh: %lu vertices, %lu triangles, %lu segments</title>\n",
                       (unsigned long)mo->nv, (unsigned long)mo->nt, (unsigned long)mo->nseg);
    cvm__writer_puts(w, "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n");
    if (has_window(mo)) { /* triangles across the window's edge are cut at it */
        char bx[32], by[32];
        cvm__writer_printf(w, "<clipPath id=\"window\"><rect x=\"%s\" y=\"%s\" ", px(bx, sizeof bx, MARGIN),
                           px(by, sizeof by, MARGIN));
        cvm__writer_printf(w, "width=\"%s\" height=\"%s\"/></clipPath>\n<g clip-path=\"url(#window)\">\n",
                           px(bx, sizeof bx, width - 2 * MARGIN), px(by, sizeof by, height - 2 * MARGIN));
    }
    cvm__writer_printf(w, "<g stroke=\"#303030\" stroke-width=\"%s\" stroke-linejoin=\"round\" fill=\"#c9d8ea\">\n",
                       px(bs, sizeof bs, stroke < 0.01 ? 0.01 : stroke));
    for (t = 0; t < mo->nt; t++) {
        const double *a = mo->xy + 2 * (size_t)mo->tri[3 * t], *b = mo->xy + 2 * (size_t)mo->tri[3 * t + 1];
        const double *c = mo->xy + 2 * (size_t)mo->tri[3 * t + 2];
        double own;
        if (outside(&vw, a, b, c))
            continue;
        own = 0.04 * vw.scale *
                     sqrt(fabs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])));
        cvm__writer_puts(w, "<polygon points=\"");
        for (k = 0; k < 3; k++)
            point(w, &vw, mo->xy + 2 * (size_t)mo->tri[3 * t + k], k < 2 ? " " : "\"");
        if (own < 0.8 * stroke) /* a small triangle in a graded mesh: thinner edges */
            cvm__writer_printf(w, " stroke-width=\"%s\"", px(bs, sizeof bs, own < 0.01 ? 0.01 : own));
        if (mo->tlayer || mo->tquality) {
            int rgb[3];
            if (mo->tlayer)
                layer_colour(mo->tlayer[t], rgb);
            else
                ramp(mo->tquality[t], rgb);
            cvm__writer_printf(w, " fill=\"#%02x%02x%02x\"", rgb[0], rgb[1], rgb[2]);
        }
        cvm__writer_puts(w, "/>\n");
    }
    cvm__writer_puts(w, "</g>\n");
    if (mo->nseg) {
        cvm__writer_printf(w, "<path fill=\"none\" stroke=\"#000000\" stroke-width=\"%s\" "
                              "stroke-linecap=\"round\" d=\"",
                           px(bs, sizeof bs, seg_stroke));
        int any = 0;
        for (k = 0; k < mo->nseg; k++) {
            if (outside(&vw, mo->xy + 2 * (size_t)mo->seg[2 * k], mo->xy + 2 * (size_t)mo->seg[2 * k + 1], NULL))
                continue;
            cvm__writer_puts(w, any++ ? " M" : "M");
            point(w, &vw, mo->xy + 2 * (size_t)mo->seg[2 * k], " L");
            point(w, &vw, mo->xy + 2 * (size_t)mo->seg[2 * k + 1], "");
        }
        cvm__writer_puts(w, "\"/>\n");
    }
    if (has_window(mo))
        cvm__writer_puts(w, "</g>\n");
    if (mo->tlayer)
        legend_layers(w, height);
    else if (mo->tquality)
        legend(w, height);
    cvm__writer_puts(w, "</svg>\n");
    return CVM_OK;
}
