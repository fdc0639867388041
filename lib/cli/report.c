/* report.c - prints the quality report of --quality: counts, angles, regularity, degrees, the power dual (q1-q5). */
#include "cli.h"

#define BAR 40

static void bars(FILE *f, const double *h, size_t n, const char *const *labels)
{
    size_t i, first = n, last = 0;
    double top = 0;
    for (i = 0; i < n; i++) {
        if (h[i] > 0) {
            if (first == n)
                first = i;
            last = i;
        }
        if (h[i] > top)
            top = h[i];
    }
    for (i = first; i <= last && first < n; i++) {
        int k, len = top > 0 ? (int)(BAR * h[i] / top + 0.5) : 0;
        fprintf(f, "  %-9s %10.0f ", labels[i], h[i]);
        for (k = 0; k < len; k++)
            fputc('#', f);
        fputc('\n', f);
    }
}

int cli_print_quality(FILE *f, cvm_mesh *m, int full)
{
    static const char *const angle_labels[18] = {
        "0-10",    "10-20",   "20-30",   "30-40",   "40-50",   "50-60",
        "60-70",   "70-80",   "80-90",   "90-100",  "100-110", "110-120",
        "120-130", "130-140", "140-150", "150-160", "160-170", "170-180"};
    static const char *const degree_labels[16] = {"0", "1", "2",  "3",  "4",  "5",  "6",  "7",
                                                  "8", "9", "10", "11", "12", "13", "14", "15+"};
    static const struct {
        cvm_measure which;
        const char *label, *fmt;
    } rows[] = {
        {CVM_MEASURE_MIN_ANGLE_DEG, "min angle", "%.6g deg"},
        {CVM_MEASURE_MAX_ANGLE_DEG, "max angle", "%.6g deg"},
        {CVM_MEASURE_REGULAR_PCT, "angles in [55, 65] deg", "%.2f %%"},
        {CVM_MEASURE_OBTUSE_PCT, "obtuse (not well-centred)", "%.2f %%"},
        {CVM_MEASURE_DEGREE6_PCT, "interior degree 6", "%.2f %%"},
        {CVM_MEASURE_MIN_DUAL_EDGE_RATIO, "min dual edge ratio", "%.6g"},
        {CVM_MEASURE_MIN_EDGE, "min edge", "%.6g"},
        {CVM_MEASURE_MAX_EDGE, "max edge", "%.6g"},
        {CVM_MEASURE_AREA, "area", "%.10g"},
    };
    static const struct {
        cvm_entity kind;
        const char *label;
    } counts[] = {{CVM_ENT_VERTEX, "vertices"},
                  {CVM_ENT_TRIANGLE, "triangles"},
                  {CVM_ENT_EDGE, "edges"},
                  {CVM_ENT_SEGMENT, "segments"},
                  {CVM_ENT_DUPLICATE, "duplicates merged"}};
    double angle[18], degree[16], v, n_interior = 0;
    size_t i, n, nt = 0, ne = 0;
    if (cvm_mesh_copy_histogram(angle, 18, m, CVM_HIST_ANGLE_DEG) != CVM_OK ||
        cvm_mesh_copy_histogram(degree, 16, m, CVM_HIST_DEGREE) != CVM_OK) {
        fprintf(stderr, "cvmesh: quality: %s\n", cvm_mesh_errmsg(m));
        return CLI_EXIT_FAIL;
    }
    for (i = 0; i < 16; i++)
        n_interior += degree[i];
    for (i = 0; i < sizeof counts / sizeof counts[0]; i++) {
        if (cvm_mesh_count(&n, m, counts[i].kind) != CVM_OK)
            n = 0;
        if (counts[i].kind == CVM_ENT_TRIANGLE)
            nt = n;
        if (counts[i].kind == CVM_ENT_EDGE)
            ne = n;
        fprintf(f, "%-28s %lu\n", counts[i].label, (unsigned long)n);
    }
    for (i = 0; i < sizeof rows / sizeof rows[0]; i++) {
        if (cvm_mesh_get_measure(&v, m, rows[i].which) != CVM_OK) {
            fprintf(stderr, "cvmesh: quality: %s\n", cvm_mesh_errmsg(m));
            return CLI_EXIT_FAIL;
        }
        fprintf(f, "%-28s ", rows[i].label);
        /* interior edges = 3T - E; without them (or interior vertices) a measure is undefined */
        if ((rows[i].which == CVM_MEASURE_DEGREE6_PCT && n_interior == 0) ||
            (rows[i].which == CVM_MEASURE_MIN_DUAL_EDGE_RATIO && 3 * nt <= ne))
            fprintf(f, "n/a");
        else
            fprintf(f, rows[i].fmt, v);
        fputc('\n', f);
    }
    if (full) {
        fprintf(f, "angle histogram (degrees: angles)\n");
        bars(f, angle, 18, angle_labels);
        fprintf(f, "degree histogram (degree: interior vertices)\n");
        if (n_interior == 0)
            fprintf(f, "  (no interior vertices)\n");
        bars(f, degree, 16, degree_labels);
    }
    return cli_print_dual_quality(f, m, full);
}

/* Labels "lo-hi" of nb bins of width w (the last open: "lo+"), into lab[nb][32]. */
static void bin_labels(char (*lab)[32], size_t nb, double w)
{
    size_t i;
    for (i = 0; i < nb; i++) {
        if (i + 1 == nb)
            snprintf(lab[i], sizeof lab[i], "%g+", w * (double)i);
        else
            snprintf(lab[i], sizeof lab[i], "%g-%g", w * (double)i, w * (double)(i + 1));
    }
}

int cli_print_dual_quality(FILE *f, cvm_mesh *m, int full)
{
    static const struct {
        cvm_measure which;
        const char *label, *fmt;
    } rows[] = {
        {CVM_MEASURE_DUAL_OUTSIDE_PCT, "power vertex outside", "%.3f %%"},
        {CVM_MEASURE_DUAL_OUTSIDE_BOUNDARY_PCT, "  at the boundary", "%.3f %%"},
        {CVM_MEASURE_MIN_DUAL_EDGE, "min dual edge", "%.6g"},
        {CVM_MEASURE_TIME_STEP_PROXY, "time-step proxy", "%.6g"},
        {CVM_MEASURE_VANISHED_VERTICES, "vanished vertices", "%.0f"},
        {CVM_MEASURE_Q1_MEAN_DEG, "q1 mean min angle", "%.4g deg"},
        {CVM_MEASURE_Q1_MIN_BOUNDARY_DEG, "q1 min at the boundary", "%.4g deg"},
        {CVM_MEASURE_Q2_MAX, "q2 max", "%.4g"},
        {CVM_MEASURE_Q2_MEAN, "q2 mean", "%.4g"},
        {CVM_MEASURE_Q2_MAX_BOUNDARY, "q2 max at the boundary", "%.4g"},
        {CVM_MEASURE_Q3_MAX, "q3 max", "%.4g"},
        {CVM_MEASURE_Q4_MAX, "q4 max", "%.4g"},
        {CVM_MEASURE_Q5_MIN, "q5 min", "%.4g"},
        {CVM_MEASURE_Q5_MEAN, "q5 mean", "%.4g"},
        {CVM_MEASURE_Q5_MIN_BOUNDARY, "q5 min at the boundary", "%.4g"},
    };
    static const struct {
        cvm_histogram which;
        size_t nb;
        double w;
        const char *title;
    } hists[] = {
        {CVM_HIST_Q1, 12, 5, "q1 histogram (min angle, degrees: triangles)"},
        {CVM_HIST_Q2, 20, 0.25, "q2 histogram (|centroid - power vertex| / inradius: triangles)"},
        {CVM_HIST_Q3, 20, 0.05, "q3 histogram (crossing offset from the edge midpoint / l: interior edges)"},
        {CVM_HIST_Q4, 20, 0.05, "q4 histogram (crossing offset from the dual edge midpoint / l: interior edges)"},
        {CVM_HIST_Q5, 20, 0.1, "q5 histogram (dual edge / (l / sqrt 3): interior edges)"},
    };
    const char *lp[20];
    char lab[20][32];
    double h[20], v;
    size_t i, k;
    fprintf(f, "power dual (q3-q5 over the local size l = primal edge length)\n");
    for (i = 0; i < sizeof rows / sizeof rows[0]; i++) {
        if (cvm_mesh_get_measure(&v, m, rows[i].which) != CVM_OK) {
            fprintf(stderr, "cvmesh: quality: %s\n", cvm_mesh_errmsg(m));
            return CLI_EXIT_FAIL;
        }
        fprintf(f, "%-28s ", rows[i].label);
        fprintf(f, rows[i].fmt, v);
        fputc('\n', f);
    }
    for (i = 0; full && i < sizeof hists / sizeof hists[0]; i++) {
        if (cvm_mesh_copy_histogram(h, 20, m, hists[i].which) != CVM_OK) {
            fprintf(stderr, "cvmesh: quality: %s\n", cvm_mesh_errmsg(m));
            return CLI_EXIT_FAIL;
        }
        bin_labels(lab, hists[i].nb, hists[i].w);
        for (k = 0; k < hists[i].nb; k++)
            lp[k] = lab[k];
        fprintf(f, "%s\n", hists[i].title);
        bars(f, h, hists[i].nb, lp);
    }
    return CLI_EXIT_OK;
}

int cli_is_triangulated(const cvm_mesh *m)
{
    size_t n = 0;
    return cvm_mesh_count(&n, m, CVM_ENT_TRIANGLE) == CVM_OK && n > 0;
}

int cli_finish(cvm_mesh *m, cvm_sizing *sz, const char *in, cvm_status s, cli_outputs *o,
               void (*report)(FILE *, cvm_mesh *))
{
    FILE *rep = cli_report_stream(o);
    int rc;
    if (cli_interrupted() || cvm_status_is_error(s))
        return cli_fail(m, sz, in);
    cli_progress_clear();
    if (s != CVM_OK)
        fprintf(stderr, "cvmesh: note: %s: %s\n", in, cvm_mesh_errmsg(m));
    if ((rc = cli_write_outputs(m, o)) < 0)
        return cli_stop(m, sz);
    if (!rc && (o->out || o->svg || o->dual))
        cli_timing_mark(o, "write");
    if (!rc && o->quality) {
        cli_phase("computing the quality report", NULL);
        if (!(rc = cli_print_quality(rep, m, o->quality == 2)) && report)
            report(rep, m);
        cli_timing_mark(o, "quality");
    }
    if (cli_interrupted())
        return cli_stop(m, sz);
    cli_note_nothing_to_do(o->command, in, o);
    cvm_sizing_free(sz);
    cvm_mesh_free(m);
    return rc;
}

int cli_start(cvm_mesh **m, cvm_sizing **sz, const cli_setting *set, int nset, double size)
{
    int rc;
    *m = NULL;
    *sz = NULL;
    if (cvm_mesh_create(m) != CVM_OK || cvm_sizing_create(sz) != CVM_OK) {
        fprintf(stderr, "cvmesh: out of memory\n");
        cvm_mesh_free(*m);
        return CLI_EXIT_FAIL;
    }
    cvm_mesh_set_progress(*m, cli_progress, 256, NULL);
    if ((rc = cli_apply_settings(*m, set, nset)) == CLI_EXIT_OK && size > 0 &&
        cvm_sizing_set_uniform(*sz, size) != CVM_OK) {
        fprintf(stderr, "cvmesh: --size: %s\n", cvm_sizing_errmsg(*sz));
        rc = CLI_EXIT_USAGE;
    }
    if (rc) {
        cvm_sizing_free(*sz);
        cvm_mesh_free(*m);
        *m = NULL;
        *sz = NULL;
    }
    return rc;
}

int cli_finish3(cvm_mesh *m, cli_outputs *o, const char *name, const char *in,
               void (*report)(FILE *f, cvm_mesh *m))
{
    int rc = cli_write_outputs(m, o);
    if (rc < 0)
        return cli_stop(m, NULL);
    if (rc) {
        cvm_mesh_free(m);
        return rc;
    }
    if (o->out)
        cli_timing_mark(o, "write");
    if (o->quality) {
        cli_phase("computing the quality report", NULL);
        report(cli_report_stream(o), m);
        cli_timing_mark(o, "quality");
    }
    if (cli_interrupted())
        return cli_stop(m, NULL);
    cli_note_nothing_to_do(name, in, o);
    cvm_mesh_free(m);
    return CLI_EXIT_OK;
}
