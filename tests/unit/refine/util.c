/* util.c - helpers of the refine tests: shared data paths, an own .poly segment parser, quality measured from coordinates. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "refine/refine_tests.h"
#include "support/mesh_oracle.h"

void rtest_fetch(cvm_mesh *m, double **xy, size_t *nv, cvm_index **tri, size_t *nt)
{
    ck_assert_int_eq(cvm_mesh_count(nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    *xy = malloc((2 * *nv + 1) * sizeof **xy);
    *tri = malloc((3 * *nt + 1) * sizeof **tri);
    ck_assert(*xy && *tri);
    ck_assert_int_eq(cvm_mesh_copy_points(*xy, 2 * *nv, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(*tri, 3 * *nt, m, CVM_ENT_TRIANGLE), CVM_OK);
}

void rtest_data_path(char *buf, size_t len, const char *name)
{
    const char *d = getenv("CVM_DATA_DIR");
    snprintf(buf, len, "%s/%s", d && *d ? d : "examples/data", name);
}

/* Next number of f, skipping '#' comments; 0 at the end. */
static int next_num(FILE *f, double *out)
{
    int c;
    for (;;) {
        c = fgetc(f);
        if (c == EOF)
            return 0;
        if (c == '#') {
            while (c != '\n' && c != EOF)
                c = fgetc(f);
            continue;
        }
        if (c == '-' || c == '+' || c == '.' || (c >= '0' && c <= '9')) {
            ungetc(c, f);
            return fscanf(f, "%lf", out) == 1;
        }
    }
}

/* Read the rest of the current line's numbers after the first one. */
static size_t line_nums(FILE *f, double *v, size_t max)
{
    size_t n = 0;
    int c;
    for (;;) {
        c = fgetc(f);
        if (c == EOF || c == '\n' || c == '#') {
            if (c == '#')
                while (c != '\n' && c != EOF)
                    c = fgetc(f);
            return n;
        }
        if (c == ' ' || c == '\t' || c == '\r')
            continue;
        ungetc(c, f);
        if (n < max && fscanf(f, "%lf", &v[n]) == 1)
            n++;
        else
            return n;
    }
}

cvm_index *rtest_poly_segments(const char *path, size_t *nseg)
{
    FILE *f = fopen(path, "r");
    double hdr[4], v[16], x;
    size_t np, i, ns;
    long base = -1;
    cvm_index *segs;
    ck_assert_msg(f != NULL, "cannot open %s", path);
    ck_assert(next_num(f, &hdr[0]));
    ck_assert_uint_eq(line_nums(f, hdr + 1, 3), 3);
    np = (size_t)hdr[0];
    for (i = 0; i < np; i++) {
        ck_assert(next_num(f, &x));
        if (base < 0)
            base = (long)x;
        line_nums(f, v, 16);
    }
    ck_assert(next_num(f, &x));
    line_nums(f, v, 16);
    ns = (size_t)x;
    segs = malloc((2 * ns + 1) * sizeof *segs);
    for (i = 0; i < ns; i++) {
        ck_assert(next_num(f, &x));
        ck_assert_uint_ge(line_nums(f, v, 16), 2);
        segs[2 * i] = (cvm_index)((long)v[0] - base);
        segs[2 * i + 1] = (cvm_index)((long)v[1] - base);
    }
    fclose(f);
    *nseg = ns;
    return segs;
}

static void fetch(cvm_mesh *m, double **xy, size_t *nv, cvm_index **tri, size_t *nt)
{
    ck_assert_int_eq(cvm_mesh_count(nv, m, CVM_ENT_VERTEX), CVM_OK);
    ck_assert_int_eq(cvm_mesh_count(nt, m, CVM_ENT_TRIANGLE), CVM_OK);
    *xy = malloc((2 * *nv + 1) * sizeof **xy);
    *tri = malloc((3 * *nt + 1) * sizeof **tri);
    ck_assert_int_eq(cvm_mesh_copy_points(*xy, 2 * *nv, m), CVM_OK);
    ck_assert_int_eq(cvm_mesh_copy_cells(*tri, 3 * *nt, m, CVM_ENT_TRIANGLE), CVM_OK);
}

void rtest_measure(cvm_mesh *m, rtest_quality *q)
{
    double *xy;
    cvm_index *tri;
    size_t t;
    fetch(m, &xy, &q->nv, &tri, &q->nt);
    q->min_angle = 180;
    q->max_edge = 0;
    q->max_circumradius = 0;
    for (t = 0; t < q->nt; t++) {
        const double *a = xy + 2 * tri[3 * t], *b = xy + 2 * tri[3 * t + 1], *c = xy + 2 * tri[3 * t + 2];
        double la = hypot(b[0] - c[0], b[1] - c[1]), lb = hypot(c[0] - a[0], c[1] - a[1]);
        double lc = hypot(a[0] - b[0], a[1] - b[1]);
        double area2 = fabs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
        double r = la * lb * lc / (2 * area2), ang = cvmtest_tri_min_angle_deg(a, b, c);
        if (ang < q->min_angle)
            q->min_angle = ang;
        if (r > q->max_circumradius)
            q->max_circumradius = r;
        if (la > q->max_edge)
            q->max_edge = la;
        if (lb > q->max_edge)
            q->max_edge = lb;
        if (lc > q->max_edge)
            q->max_edge = lc;
    }
    free(xy);
    free(tri);
}

double rtest_min_angle_away(cvm_mesh *m, const double *apex, size_t napex, double dist)
{
    double *xy, best = 180;
    cvm_index *tri;
    size_t nv, nt, t, i;
    int k;
    fetch(m, &xy, &nv, &tri, &nt);
    for (t = 0; t < nt; t++) {
        int near = 0;
        for (k = 0; k < 3 && !near; k++)
            for (i = 0; i < napex; i++) {
                const double *p = xy + 2 * tri[3 * t + k];
                if (hypot(p[0] - apex[2 * i], p[1] - apex[2 * i + 1]) < dist)
                    near = 1;
            }
        if (!near) {
            double a = cvmtest_tri_min_angle_deg(xy + 2 * tri[3 * t], xy + 2 * tri[3 * t + 1], xy + 2 * tri[3 * t + 2]);
            if (a < best)
                best = a;
        }
    }
    free(xy);
    free(tri);
    return best;
}

void rtest_assert_identical(cvm_mesh *a, cvm_mesh *b)
{
    double *xa, *xb;
    cvm_index *ta, *tb;
    size_t nva, nta, nvb, ntb;
    fetch(a, &xa, &nva, &ta, &nta);
    fetch(b, &xb, &nvb, &tb, &ntb);
    ck_assert_uint_eq(nva, nvb);
    ck_assert_uint_eq(nta, ntb);
    ck_assert_msg(memcmp(xa, xb, 2 * nva * sizeof *xa) == 0, "points differ between two runs");
    ck_assert_msg(memcmp(ta, tb, 3 * nta * sizeof *ta) == 0, "triangles differ between two runs");
    free(xa);
    free(xb);
    free(ta);
    free(tb);
}

cvm_status rtest_refine_uniform(cvm_mesh *m, double h, cvm_algorithm algo)
{
    cvm_sizing *s;
    cvm_status st;
    ck_assert_int_eq(cvm_sizing_create(&s), CVM_OK);
    ck_assert_int_eq(cvm_sizing_set_uniform(s, h), CVM_OK);
    st = cvm_mesh_refine(m, s, algo);
    cvm_sizing_free(s);
    return st;
}

/* Read, triangulate and refine one shared geometry; returns the mesh. */
static cvm_mesh *shared_refined(const char *path, double h, cvm_algorithm algo, size_t *nv0)
{
    cvm_mesh *m;
    cvm_status s;
    ck_assert_int_eq(cvm_mesh_create(&m), CVM_OK);
    ck_assert_msg(cvm_mesh_read(m, path) == CVM_OK, "%s: %s", path, cvm_mesh_errmsg(m));
    ck_assert_msg(cvm_mesh_triangulate(m) == CVM_OK, "%s: %s", path, cvm_mesh_errmsg(m));
    ck_assert_int_eq(cvm_mesh_count(nv0, m, CVM_ENT_VERTEX), CVM_OK);
    s = rtest_refine_uniform(m, h, algo);
    ck_assert_msg(s == CVM_OK, "%s: refine returned %s: %s", path, cvm_status_str(s), cvm_mesh_errmsg(m));
    return m;
}

void rtest_assert_refined(cvm_mesh *m, const char *what, const cvm_index *segs, size_t nseg,
                          int delaunay, long euler, double h, rtest_quality *q)
{
    cvmtest_expect e;
    cvmtest_expect_init(&e);
    e.delaunay = delaunay;
    e.segs = segs;
    e.nseg = nseg;
    e.check_euler = 1;
    e.euler = euler;
    cvmtest_assert_valid_ex(m, &e);
    rtest_measure(m, q);
    ck_assert_msg(q->min_angle >= 30.0 - 1e-9, "%s: min angle %.17g < 30", what, q->min_angle);
    ck_assert_msg(q->max_circumradius <= h * (1 + 1e-9), "%s: circumradius %.17g > size %g", what,
                  q->max_circumradius, h);
}

void rtest_shared_geometry(const char *name, double h, long euler, cvm_algorithm algo)
{
    char path[1024];
    cvm_mesh *m, *m2;
    rtest_quality q;
    size_t nseg, nv0, nv0b;
    double d;
    cvm_index *segs;
    rtest_data_path(path, sizeof path, name);
    segs = rtest_poly_segments(path, &nseg);
    m = shared_refined(path, h, algo, &nv0);
    rtest_assert_refined(m, name, segs, nseg, 0, euler, h, &q);
    ck_assert_msg(q.max_edge <= 2 * h * (1 + 1e-9), "%s: edge %.17g > 2 x size", name, q.max_edge);
    /* frontal and AFLR keep frontal's acceptance bound through the clean-ups,
     * swaps and smoothing: circumradius <= sqrt(0.5) x size (uniform size here) */
    if (algo == CVM_ALGO_FRONTAL || algo == CVM_ALGO_AFLR)
        ck_assert_msg(q.max_circumradius <= 0.70710678118654757 * h * (1 + 1e-9),
                      "%s: circumradius %.17g > 0.707 x size", name, q.max_circumradius);
    ck_assert_msg(q.nt >= 1000 && q.nt <= 20000, "%s: %lu triangles", name, (unsigned long)q.nt);
    ck_assert_int_eq(cvm_mesh_get_measure(&d, m, CVM_MEASURE_REFINE_STEINER), CVM_OK);
    ck_assert_double_eq(d, (double)(q.nv - nv0));
    ck_assert_int_eq(cvm_mesh_get_measure(&d, m, CVM_MEASURE_REFINE_UNMET_ANGLE), CVM_OK);
    ck_assert_double_eq(d, 0);
    ck_assert_int_eq(cvm_mesh_get_measure(&d, m, CVM_MEASURE_REFINE_UNMET_SIZE), CVM_OK);
    ck_assert_double_eq(d, 0);
    ck_assert_int_eq(cvm_mesh_get_measure(&d, m, CVM_MEASURE_REFINE_REQUESTED_ANGLE), CVM_OK);
    ck_assert_double_eq(d, 30);
    ck_assert_int_eq(cvm_mesh_get_measure(&d, m, CVM_MEASURE_REFINE_MET_ANGLE), CVM_OK);
    ck_assert(d >= 30.0 - 1e-9);
    m2 = shared_refined(path, h, algo, &nv0b);
    rtest_assert_identical(m, m2);
    cvm_mesh_free(m2);
    cvm_mesh_free(m);
    free(segs);
}

void rtest_set_wedge(cvm_mesh *m, double angle_deg)
{
    double a = angle_deg * 3.14159265358979323846 / 180, xy[10];
    static const cvm_index seg[] = {0, 1, 1, 2, 2, 3, 3, 0};
    xy[0] = 0;
    xy[1] = 0;
    xy[2] = 1;
    xy[3] = 0;
    xy[4] = 1;
    xy[5] = tan(a);
    xy[6] = 0.5 * cos(a);
    xy[7] = 0.5 * sin(a);
    /* a lone point off the domain keeps the slanted side off the convex hull
     * (splits of slanted hull edges may be refused: see split_segment.c) */
    xy[8] = 0.5;
    xy[9] = 1.0;
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, 5, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, seg, 4), CVM_OK);
}

void rtest_set_star(cvm_mesh *m, size_t spikes, unsigned long seed)
{
    double *xy = malloc(2 * spikes * sizeof *xy);
    cvm_index *seg = malloc(2 * spikes * sizeof *seg);
    size_t i;
    for (i = 0; i < spikes; i++) {
        double t = 2 * 3.14159265358979323846 * (double)i / (double)spikes, r;
        seed = seed * 6364136223846793005ul + 1442695040888963407ul;
        r = 0.2 + 0.8 * (double)(seed >> 11) / 9007199254740992.0;
        xy[2 * i] = r * cos(t);
        xy[2 * i + 1] = r * sin(t);
        seg[2 * i] = (cvm_index)i;
        seg[2 * i + 1] = (cvm_index)((i + 1) % spikes);
    }
    ck_assert_int_eq(cvm_mesh_set_points(m, xy, spikes, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, seg, spikes), CVM_OK);
    free(xy);
    free(seg);
}

void rtest_set_unit_square(cvm_mesh *m)
{
    static const double sq[] = {0, 0, 1, 0, 1, 1, 0, 1};
    static const cvm_index seg[] = {0, 1, 1, 2, 2, 3, 3, 0};
    ck_assert_int_eq(cvm_mesh_set_points(m, sq, 4, 2), CVM_OK);
    ck_assert_int_eq(cvm_mesh_set_segments(m, seg, 4), CVM_OK);
    ck_assert_int_eq(cvm_mesh_triangulate(m), CVM_OK);
}
