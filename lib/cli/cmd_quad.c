/*
 * cmd_quad.c - `cvmesh quad IN.poly|--domain-box X0,Y0,X1,Y1 --metric builtin:NAME[:SCALE]|
 * constant:G11,G12,G22 [-o OUT.vtu|OUT.msh] [--quality] [--timings] [option flags]`: a quad-dominant
 * mesh aligned with a metric (cvm_mesh_quadmesh()); write, report.
 */
#include <stdlib.h>
#include <string.h>

#include "cli.h"

typedef struct qargs {
    const char *in, *metric;
    double box[4];
    int have_box;
    cli_outputs o;
    cli_setting set[CLI_MAX_SETTINGS];
    int nset;
} qargs;

void cli_quad_help(FILE *f)
{
    fprintf(f,
            "usage: cvmesh quad IN.poly|--domain-box X0,Y0,X1,Y1 --metric SPEC [-o OUT.vtu]\n"
            "                   [--quality] [--timings] [option flags]\n"
            "\n"
            "A quad-dominant mesh whose cells have unit size and right angles in the metric:\n"
            "boundary points at unit metric length, interior sites moved by L-BFGS to a\n"
            "minimum of the Lp-CVT energy, their Delaunay triangles paired into quads by a\n"
            "maximum-weight matching (Blossom-Quad). The domain is the convex polygon of\n"
            "IN.poly (one closed loop of segments, no holes, no points inside) or the box of\n"
            "--domain-box.\n"
            "\n"
            "  --metric SPEC             builtin:NAME[:SCALE], NAME one of identity (g = I),\n"
            "                            stretch (diag(1, 1 + 4y^2)), saddle (I + grad f grad f^T,\n"
            "                            f = x^2 - y^2), sshock (|Hessian| of 3/4 tanh(2(sin 5y - 3x)),\n"
            "                            sizes in [0.005, 0.2], aspect <= 50), g times SCALE\n"
            "                            (default 1; 1/h^2 gives edges of length h where g = I);\n"
            "                            or constant:G11,G12,G22\n"
            "  --domain-box X0,Y0,X1,Y1  the rectangle as the domain, instead of IN.poly\n"
            "\n"
            "Outputs and reports (--timings: read, quadmesh, write, quality; --quality prints\n"
            "the quad measures: quads by count and area, corner deviation from 90 degrees in\n"
            "the metric and in Euclidean space, alignment with the metric's eigenvectors,\n"
            "edges at unit metric length, energy, gradient and iterations):\n");
    cli_print_output_help(f, 0, 0);
    fprintf(f, "  (quad-dominant meshes are written to .vtu or .msh: quad and triangle cells)\n");
    cli_print_option_flags(f, CLI_CMD_QUAD);
    fprintf(f, "\nOn bad input the exit status is 1 and one line names the file, point or\n"
               "vertex; no output file is written. Command-line errors exit with 2.\n");
}

static int parse_box(qargs *a, const char *v)
{
    char *end;
    const char *p = v;
    int k;
    for (k = 0; k < 4; k++) {
        a->box[k] = strtod(p, &end);
        if (end == p || (k < 3 && *end != ',') || (k == 3 && *end)) {
            fprintf(stderr, "cvmesh: quad: --domain-box %s: expected X0,Y0,X1,Y1\n", v);
            return CLI_EXIT_USAGE;
        }
        p = end + 1;
    }
    if (!(a->box[2] > a->box[0]) || !(a->box[3] > a->box[1])) {
        fprintf(stderr, "cvmesh: quad: --domain-box %s: needs X1 > X0 and Y1 > Y0\n", v);
        return CLI_EXIT_USAGE;
    }
    a->have_box = 1;
    return CLI_EXIT_OK;
}

/* quad's own flags: 1 taken, 0 not one, or CLI_EXIT_USAGE + 1 after printing why. */
static int own_flag(void *args, int argc, char **argv, int *i)
{
    qargs *a = args;
    const char *v;
    int r;
    if ((r = cli_take_value(argc, argv, i, "--metric", &v)) != 0) {
        if (r > 0)
            a->metric = v;
        return r < 0 ? CLI_EXIT_USAGE + 1 : 1;
    }
    if ((r = cli_take_value(argc, argv, i, "--domain-box", &v)) != 0)
        return r < 0 || parse_box(a, v) ? CLI_EXIT_USAGE + 1 : 1;
    return 0;
}

static int parse(qargs *a, int argc, char **argv)
{
    int r;
    memset(a, 0, sizeof *a);
    a->o.command = "quad";
    if ((r = cli_parse_args("quad", CLI_CMD_QUAD, argc, argv, cli_quad_help, own_flag, a, &a->o,
                            a->set, &a->nset, &a->in)))
        return r;
    if (a->have_box && a->in) {
        fprintf(stderr, "cvmesh: quad: give IN.poly or --domain-box, not both\n");
        return CLI_EXIT_USAGE;
    }
    if ((!a->have_box && cli_need_input("quad", a->in)) || cli_check_outputs("quad", &a->o))
        return CLI_EXIT_USAGE;
    if (!a->metric) {
        fprintf(stderr, "cvmesh: quad: --metric is required (e.g. --metric builtin:identity:4)\n");
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

/* --metric SPEC onto s. CLI_EXIT_OK, or CLI_EXIT_USAGE after printing why. */
static int set_metric(cvm_sizing *s, const char *spec)
{
    static const char *names[] = {"identity", "stretch", "saddle", "sshock"};
    char *end;
    cvm_status st;
    if (strncmp(spec, "builtin:", 8) == 0) {
        const char *n = spec + 8, *colon = strchr(n, ':');
        size_t len = colon ? (size_t)(colon - n) : strlen(n), k;
        double scale = 1;
        if (colon) {
            scale = strtod(colon + 1, &end);
            if (end == colon + 1 || *end || !(scale > 0)) {
                fprintf(stderr, "cvmesh: quad: --metric %s: SCALE must be a positive number\n",
                        spec);
                return CLI_EXIT_USAGE;
            }
        }
        for (k = 0; k < 4; k++)
            if (strlen(names[k]) == len && strncmp(n, names[k], len) == 0)
                break;
        if (k == 4) {
            fprintf(stderr, "cvmesh: quad: --metric %s: unknown built-in (identity, stretch, "
                            "saddle, sshock)\n", spec);
            return CLI_EXIT_USAGE;
        }
        st = cvm_sizing_set_metric_builtin(s, (cvm_metric_builtin)(CVM_METRIC_IDENTITY + (int)k),
                                           scale);
    } else if (strncmp(spec, "constant:", 9) == 0) {
        double g[3];
        const char *p = spec + 9;
        int k;
        for (k = 0; k < 3; k++) {
            g[k] = strtod(p, &end);
            if (end == p || (k < 2 && *end != ',') || (k == 2 && *end)) {
                fprintf(stderr, "cvmesh: quad: --metric %s: expected constant:G11,G12,G22\n",
                        spec);
                return CLI_EXIT_USAGE;
            }
            p = end + 1;
        }
        st = cvm_sizing_set_metric_constant(s, g[0], g[1], g[2]);
    } else {
        fprintf(stderr, "cvmesh: quad: --metric %s: expected builtin:NAME[:SCALE] or "
                        "constant:G11,G12,G22\n", spec);
        return CLI_EXIT_USAGE;
    }
    if (st != CVM_OK) {
        fprintf(stderr, "cvmesh: quad: --metric %s: %s\n", spec, cvm_sizing_errmsg(s));
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

static void report(FILE *f, cvm_mesh *m)
{
    static const struct {
        cvm_report which;
        const char *label, *fmt;
    } rows[] = {
        {CVM_REPORT_QUAD_QUADS, "quads", "%.0f"},
        {CVM_REPORT_QUAD_TRIANGLES, "triangles", "%.0f"},
        {CVM_REPORT_QUAD_INTERIOR_SITES, "interior sites", "%.0f"},
        {CVM_REPORT_QUAD_BOUNDARY_SITES, "boundary sites", "%.0f"},
        {CVM_REPORT_QUAD_PCT, "quads by count", "%.2f %%"},
        {CVM_REPORT_QUAD_AREA_PCT, "quads by area", "%.2f %%"},
        {CVM_REPORT_QUAD_ANGLE_DEV_MEAN_DEG, "corner deviation mean", "%.3f deg (metric)"},
        {CVM_REPORT_QUAD_ANGLE_DEV_P95_DEG, "corner deviation P95", "%.3f deg (metric)"},
        {CVM_REPORT_QUAD_ANGLE_DEV_MAX_DEG, "corner deviation max", "%.3f deg (metric)"},
        {CVM_REPORT_QUAD_EUCLID_ANGLE_DEV_MEAN_DEG, "corner deviation mean", "%.3f deg (Euclidean)"},
        {CVM_REPORT_QUAD_EUCLID_ANGLE_DEV_P95_DEG, "corner deviation P95", "%.3f deg (Euclidean)"},
        {CVM_REPORT_QUAD_CORNERS_80_100_PCT, "quads, corners in [80,100]", "%.2f %%"},
        {CVM_REPORT_QUAD_ALIGNMENT_MEAN_DEG, "alignment mean", "%.3f deg"},
        {CVM_REPORT_QUAD_ALIGNMENT_P95_DEG, "alignment P95", "%.3f deg"},
        {CVM_REPORT_QUAD_UNIT_EDGE_PCT, "edges, L_M in [0.71,1.41]", "%.2f %%"},
        {CVM_REPORT_QUAD_EDGE_DEV_MEAN, "mean |L_M - 1|", "%.4f"},
        {CVM_REPORT_QUAD_MIN_SCALED_JACOBIAN, "min scaled Jacobian", "%.4f"},
        {CVM_REPORT_QUAD_ENERGY, "energy E", "%.10g"},
        {CVM_REPORT_QUAD_GRADIENT_INF, "|grad E|_inf", "%.3g"},
        {CVM_REPORT_QUAD_ITERATIONS, "L-BFGS iterations", "%.0f"},
        {CVM_REPORT_QUAD_EVALUATIONS, "evaluations", "%.0f"},
        {CVM_REPORT_QUAD_SECONDS, "quadmesh time", "%.3f s"},
    };
    size_t i;
    for (i = 0; i < sizeof rows / sizeof rows[0]; i++) {
        double v;
        if (cvm_mesh_get_report(&v, m, rows[i].which) != CVM_OK)
            continue;
        fprintf(f, "%-28s ", rows[i].label);
        fprintf(f, rows[i].fmt, v);
        fputc('\n', f);
    }
}

static int run(qargs *a)
{
    cvm_mesh *m;
    cvm_sizing *s;
    cli_budget budget;
    const char *name = a->in ? a->in : "--domain-box";
    cvm_status st;
    int rc;
    if ((rc = cli_start(&m, &s, a->set, a->nset, 0)))
        return rc;
    if ((rc = set_metric(s, a->metric))) {
        cvm_mesh_free(m);
        cvm_sizing_free(s);
        return rc;
    }
    cli_budget_begin(&budget, m);
    cli_timing_begin(&a->o);
    if (a->have_box) {
        double xy[8];
        cvm_index seg[8] = {0, 1, 1, 2, 2, 3, 3, 0};
        xy[0] = a->box[0], xy[1] = a->box[1], xy[2] = a->box[2], xy[3] = a->box[1];
        xy[4] = a->box[2], xy[5] = a->box[3], xy[6] = a->box[0], xy[7] = a->box[3];
        if (cvm_mesh_set_points(m, xy, 4, 2) != CVM_OK || cvm_mesh_set_segments(m, seg, 4) != CVM_OK)
            return cli_fail(m, s, NULL);
    } else {
        cli_phase("reading", a->in);
        if (cvm_mesh_read(m, a->in) != CVM_OK)
            return cli_fail(m, s, NULL);
        cli_timing_mark(&a->o, "read");
    }
    cli_budget_apply(&budget, m);
    cli_phase("quad meshing", name);
    st = cvm_mesh_quadmesh(m, s);
    cli_timing_mark(&a->o, "quadmesh");
    return cli_finish(m, s, name, st, &a->o, report);
}

int cli_quad(int argc, char **argv)
{
    qargs a;
    int rc = parse(&a, argc, argv);
    if (rc < 0)
        return CLI_EXIT_OK;
    if (rc)
        return rc;
    return run(&a);
}
