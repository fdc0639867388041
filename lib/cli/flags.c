/*
 * flags.c - the one table that maps command-line flags to library option
 * keys (STYLE section 5: no switch strings), with their parsing and help.
 * A new option gets a row here; a new subcommand gets a CLI_CMD_* bit.
 */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

#define TRI CLI_CMD_TRIANGULATE
#define REF CLI_CMD_REFINE
#define OPT CLI_CMD_OPTIMISE
#define TET CLI_CMD_TETRAHEDRALIZE
#define M3 CLI_CMD_MESH3
#define QUA CLI_CMD_QUAD

static const cli_option_flag k_flags[] = {
    {"--grading", "G", CVM_OPT_GEN3_GRADING, 0, M3,
     "size near the surface grows as l + G x distance from its triangles (default 0.3)"},
    {"--layers", "N", CVM_OPT_GEN3_LAYERS, 0, M3, "near-field layers (default 1; only 1 so far)"},
    {"--opt-sweeps", "N", CVM_OPT_DUAL3_MAX_SWEEPS, 0, M3 | OPT, "--optimise: sweep limit (default 50)"},
    {"--opt-budget", "N", CVM_OPT_DUAL3_BUDGET, 0, M3 | OPT, "--optimise: trial positions per vertex and sweep (default 48)"},
    {"--opt-min-dihedral", "DEG", CVM_OPT_DUAL3_MIN_DIHEDRAL_DEG, 0, M3 | OPT,
     "--optimise: no move takes a dihedral angle below min(DEG, before) (default 10)"},
    {"--opt-fixed-boundary", NULL, CVM_OPT_DUAL3_SLIDE_BOUNDARY, 0, M3 | OPT,
     "--optimise: no boundary vertex moves (by default those inside an axis-aligned planar facet slide in it)"},
    {"--opt-slide-surface", NULL, CVM_OPT_DUAL3_SLIDE_BOUNDARY, 2, M3 | OPT,
     "--optimise: boundary vertices of smooth curved or oblique surface patches also slide, on the surface as it was"},
    {"--opt-no-flips", NULL, CVM_OPT_DUAL3_FLIPS, 0, M3 | OPT,
     "--optimise: keep the connectivity (by default flips repair the faces a move leaves not locally regular)"},
    {"--opt-solver", "N", CVM_OPT_DUAL3_SOLVER, 0, M3 | OPT,
     "--optimise: per-vertex search: 1 compass (default), 2 cuckoo, 3 compass then cuckoo where it found no move"},
    {"--opt-escalate", "E", CVM_OPT_DUAL3_ESCALATE, 0, M3 | OPT,
     "--optimise: when the sweeps stall, double the search budget and search every vertex again, up to E times the budget (default 1: stop)"},
    {"--opt-cuckoo-budget", "N", CVM_OPT_DUAL3_CUCKOO_BUDGET, 0, M3 | OPT,
     "--optimise: evaluations per vertex and sweep of the cuckoo search (default 300)"},
    {"--opt-margin", "F", CVM_OPT_DUAL3_MARGIN, 0, M3 | OPT,
     "--optimise: wanted depth of the power vertex inside each face, x mean edge (default 0.03)"},
    {"--merge-tol", "F", CVM_OPT_DUAL3_MERGE_TOL, 0, M3 | TET,
     "merged dual cells (mesh3 --quality, --merged-cells): tetrahedra whose dual edge is below F x 0.38 x the mean edge (0: none)"},
    {"--merged-cells", NULL, CVM_OPT_VTU_MERGED_CELLS, 1, M3 | TET,
     ".vtu output: each merged dual cell (--merge-tol) as one VTK_POLYHEDRON instead of its tetrahedra"},
    {"--uniform", NULL, CVM_OPT_GEN3_SIZE_FROM_SURFACE, 0, M3,
     "uniform size H everywhere instead of following the surface's triangles"},
    {"--octree-split-hanging", NULL, CVM_OPT_GEN3_OCTREE_SPLIT_HANGING, 1, M3,
     "--freespace octree: split once every leaf with finer leaves across a face, then balance again"},
    {"--remesh-planar", NULL, CVM_OPT_GEN3_SURFACE, 1, M3,
     "re-mesh the surface's planar facets at the size H (2D frontal refiner) before meshing"},
    {"--remesh-surface", NULL, CVM_OPT_GEN3_SURFACE, 2, M3,
     "re-mesh the whole surface (curved parts too) with near-equilateral triangles at a size that follows its curvature, before meshing"},
    {"--keep-hull", NULL, CVM_OPT_KEEP_CONVEX_HULL, 1, TRI | REF | OPT,
     "keep every triangle of the convex hull (holes are still removed)"},
    {"--no-split-intersections", NULL, CVM_OPT_SPLIT_INTERSECTIONS, 0, TRI | REF | OPT,
     "fail on crossing segments instead of splitting them"},
    {"--reject-duplicates", NULL, CVM_OPT_REJECT_DUPLICATES, 1, TRI | REF | OPT | TET | M3,
     "fail on duplicate points instead of merging them"},
    {"--seed", "S", CVM_OPT_SEED, 0, TRI | REF | OPT | TET | M3 | QUA, "seed of the random insertion order"},
    {"--threads", "N", CVM_OPT_THREADS, 0, TRI | REF | OPT | TET | M3 | QUA, "threads for parallel stages (0: OpenMP default; only optimise is parallel in 0.1)"},
    {"--time-limit", "SECONDS", CVM_OPT_TIME_LIMIT_S, 0, TRI | REF | OPT | TET | M3 | QUA, "stop the whole command after this time (0: none)"},
    {"--min-angle", "DEG", CVM_OPT_MIN_ANGLE_DEG, 0, REF | OPT, "smallest angle wanted (default 30)"},
    {"--max-area", "A", CVM_OPT_MAX_AREA, 0, REF | OPT, "largest triangle area (0 or negative: none, as in a .poly region)"},
    {"--max-steiner", "N", CVM_OPT_MAX_STEINER, 0, REF | OPT | M3, "stop after adding N points (0: no limit; mesh3: --freespace refine)"},
    {"--lens", NULL, CVM_OPT_ENCROACH_LENS, 1, REF | OPT, "diametral lenses instead of circles"},
    {"--no-march", NULL, CVM_OPT_MARCH_SEGMENTS, 0, REF | OPT,
     "split segments only when encroached (no marching with the size)"},
    {"--resample-boundary", NULL, CVM_OPT_KEEP_SEGMENT_VERTICES, 0, REF | OPT,
     "re-discretise chains of segments forming smooth curves with the size (inner input "
     "vertices move onto new points on the input polyline; corners above 30 degrees stay)"},
    {"--swap", NULL, CVM_OPT_SWAP, 1, REF,
     "frontal: swap edges towards vertex degree 6 after refining (the default)"},
    {"--no-swap", NULL, CVM_OPT_SWAP, 0, REF, "frontal: no degree swapping"},
    {"--smooth", "SWEEPS", CVM_OPT_SMOOTH_SWEEPS, 0, REF,
     "frontal/aflr: sweeps of smoothing after refining (-1: frontal 4, aflr 3; 0: none)"},
    {"--relax", "SWEEPS", CVM_OPT_RELAX_SWEEPS, 0, REF,
     "frontal/aflr: ODT relaxation sweeps before smoothing (-1: frontal 3, aflr 5; 0: none)"},
    {"--smooth-layers", "N", CVM_OPT_AFLR_SMOOTH_LAYERS, 0, REF,
     "aflr: smooth the points of every N completed layers during the pass (default 0: off)"},
    {"--smooth-method", "N", CVM_OPT_SMOOTH_METHOD, 0, REF,
     "frontal/aflr smoothing: 0 smart Laplacian (default), 1 max-min angle (Freitag), 2 both, 3 both, max-min guarded"},
    {"--solver", "N", CVM_OPT_DUAL_SOLVER, 0, OPT,
     "local solver of the dual optimiser: 1 pattern search (default), 2 cuckoo search"},
    {"--max-sweeps", "N", CVM_OPT_DUAL_MAX_SWEEPS, 0, OPT, "sweeps of the dual optimiser (default 50)"},
    {"--dual-min-angle", "DEG", CVM_OPT_DUAL_MIN_ANGLE_DEG, 0, OPT,
     "smallest angle a move of the dual optimiser may create (default 30)"},
    {"--target-angle", "DEG", CVM_OPT_DUAL_TARGET_ANGLE_DEG, 0, OPT,
     "the dual optimiser also improves triangles with a smaller angle (default 40)"},
    {"--margin", "F", CVM_OPT_DUAL_MARGIN, 0, OPT,
     "keep power vertices F x the edge length inside each edge (default 0.15)"},
    {"--cuckoo-budget", "N", CVM_OPT_DUAL_CUCKOO_BUDGET, 0, OPT,
     "evaluations per vertex of the cuckoo solver (default 300)"},
    {"--keep-input-points", NULL, CVM_OPT_DUAL_KEEP_INPUT_POINTS, 1, OPT,
     "the dual optimiser moves no input point (only its weight)"},
    {"--merge-tol", "F", CVM_OPT_DUAL_MERGE_TOL, 0, OPT,
     "merge triangles whose dual edge is below F x l/sqrt(3) (default 0.1)"},
    {"--maxmin-trials", "N", CVM_OPT_DUAL_MAXMIN_TRIALS, 0, OPT,
     "dual optimiser: removal-trial calls after the max-min rounds (default 0: none)"},
    {"--maxmin-rounds", "N", CVM_OPT_DUAL_MAXMIN_ROUNDS, 0, OPT,
     "rounds of the dual optimiser's final max-min-angle phase (0: none; default 5)"},
    {"--vtu-encoding", "ascii|binary|zlib|auto", CVM_OPT_VTU_ENCODING, 0, TRI | REF | OPT | QUA,
     ".vtu data: ascii (0), binary (1, raw appended), zlib (2) or auto (3: ascii up to 1000000 vertices, binary above)"},
    {"--p", "P", CVM_OPT_QUAD_P, 0, QUA, "exponent of the Lp-CVT energy, even, 2 to 12 (default 6)"},
    {"--recombine", "blossom|greedy|none", CVM_OPT_QUAD_RECOMBINE, 0, QUA,
     "pairing of triangles into quads (default blossom: maximum-weight matching)"},
    {"--min-quality", "Q", CVM_OPT_QUAD_MIN_QUALITY, 0, QUA,
     "smallest quality of a quad formed, 1 - max|corner - 90|/90 in the metric (default 0.5)"},
    {"--lbfgs-memory", "M", CVM_OPT_QUAD_LBFGS_MEMORY, 0, QUA, "corrections kept by L-BFGS (default 8)"},
    {"--gradient-tol", "T", CVM_OPT_QUAD_GRADIENT_TOL, 0, QUA,
     "stop at |grad E|_inf <= T x E / L (default 1e-10)"},
    {"--max-iter", "N", CVM_OPT_QUAD_MAX_ITERATIONS, 0, QUA,
     "L-BFGS iterations of each run (default 10000, 0: none)"},
    {"--relocations", "N", CVM_OPT_QUAD_RELOCATIONS, 0, QUA,
     "escapes from a local minimum after convergence (default 0)"},
    {"--clip", NULL, CVM_OPT_QUAD_CLIP, 1, QUA,
     "clip the boundary cells to the domain instead of reconstructing them"},
    {"--cellwise-metric", NULL, CVM_OPT_QUAD_CELLWISE_METRIC, 1, QUA,
     "the metric of each site over its whole cell (faster, exact integrals)"},
    {"--mean-metric-voronoi", "0|1|2", CVM_OPT_QUAD_MEAN_METRIC_VORONOI, 0, QUA,
     "Voronoi cells of the energy: 0 Euclidean, 1 mean metric, 2 1 if g is constant"},
    {"--initial-sites", "frontal|halton", CVM_OPT_QUAD_INITIAL_SITES, 0, QUA,
     "start: a metric-aligned front from the boundary (default) or density samples"},
    {"--smooth", "N", CVM_OPT_QUAD_SMOOTH, 0, QUA,
     "sweeps of parallelogram smoothing after the recombination (default 200)"},
    {"--all-quad", NULL, CVM_OPT_QUAD_ALL_QUAD, 1, QUA,
     "split every cell into quads (a quad into 4, a triangle into 3) at the metric's size"},
    {"--cycles", "N", CVM_OPT_QUAD_CYCLES, 0, QUA,
     "insertion/removal cycles while < 95% of edges have unit metric length (default 3)"},
};

/* Flags whose value is a word: the word -> the option value. */
static const struct {
    int key;
    const char *word;
    double value;
} k_words[] = {{CVM_OPT_VTU_ENCODING, "ascii", CVM_VTU_ASCII},
               {CVM_OPT_VTU_ENCODING, "binary", CVM_VTU_BINARY},
               {CVM_OPT_VTU_ENCODING, "zlib", CVM_VTU_ZLIB},
               {CVM_OPT_QUAD_RECOMBINE, "blossom", 0},
               {CVM_OPT_QUAD_RECOMBINE, "greedy", 1},
               {CVM_OPT_QUAD_RECOMBINE, "none", 2},
               {CVM_OPT_QUAD_INITIAL_SITES, "frontal", 0},
               {CVM_OPT_QUAD_INITIAL_SITES, "halton", 1},
               {CVM_OPT_VTU_ENCODING, "auto", CVM_VTU_AUTO}};

/* 1 and *v when f takes words and val is one of them. */
static int word_value(const cli_option_flag *f, const char *val, double *v)
{
    size_t k;
    for (k = 0; k < sizeof k_words / sizeof k_words[0]; k++)
        if ((int)f->key == k_words[k].key && strcmp(val, k_words[k].word) == 0) {
            *v = k_words[k].value;
            return 1;
        }
    return 0;
}

#define NFLAGS (sizeof k_flags / sizeof k_flags[0])

/* --svg-window XMIN,YMIN,XMAX,YMAX: one flag, four options. */
#define WINDOW_FLAG "--svg-window"
static const cli_option_flag k_window[4] = {
    {WINDOW_FLAG, "XMIN", CVM_OPT_SVG_WINDOW_XMIN, 0, TRI | REF | OPT, ""},
    {WINDOW_FLAG, "YMIN", CVM_OPT_SVG_WINDOW_YMIN, 0, TRI | REF | OPT, ""},
    {WINDOW_FLAG, "XMAX", CVM_OPT_SVG_WINDOW_XMAX, 0, TRI | REF | OPT, ""},
    {WINDOW_FLAG, "YMAX", CVM_OPT_SVG_WINDOW_YMAX, 0, TRI | REF | OPT, ""},
};

/* The four numbers of --svg-window into set; 1, or -1 after printing why. */
static int parse_window(int argc, char **argv, int *i, cli_setting *set, int *nset)
{
    const char *arg = argv[*i] + strlen(WINDOW_FLAG), *p;
    double v[4];
    int k;
    if (*arg == '=') {
        p = arg + 1;
    } else if (*i + 1 < argc) {
        p = argv[++*i];
    } else {
        fprintf(stderr, "cvmesh: " WINDOW_FLAG " needs a value (XMIN,YMIN,XMAX,YMAX)\n");
        return -1;
    }
    for (k = 0; k < 4; k++) {
        char *end;
        v[k] = strtod(p, &end);
        if (end == p || !isfinite(v[k]) || *end != (k < 3 ? ',' : '\0')) {
            fprintf(stderr, "cvmesh: " WINDOW_FLAG " '%s': expected four numbers XMIN,YMIN,XMAX,YMAX\n",
                    argv[*i]);
            return -1;
        }
        p = end + 1;
    }
    if (!(v[2] > v[0] && v[3] > v[1])) {
        fprintf(stderr, "cvmesh: " WINDOW_FLAG " %.17g,%.17g,%.17g,%.17g: needs XMAX > XMIN and YMAX > YMIN\n",
                v[0], v[1], v[2], v[3]);
        return -1;
    }
    if (*nset + 4 > CLI_MAX_SETTINGS) {
        fprintf(stderr, "cvmesh: too many option flags\n");
        return -1;
    }
    for (k = 0; k < 4; k++) {
        set[*nset].flag = &k_window[k];
        set[*nset].value = v[k];
        (*nset)++;
    }
    return 1;
}

/* The flag named by arg ("--seed" or "--seed=5"); *value_out points after '='. */
static const cli_option_flag *find(unsigned cmd, const char *arg, const char **value_out)
{
    size_t i;
    *value_out = NULL;
    for (i = 0; i < NFLAGS; i++) {
        size_t n = strlen(k_flags[i].name);
        if (!(k_flags[i].commands & cmd) || strncmp(arg, k_flags[i].name, n) != 0)
            continue;
        if (arg[n] == '\0')
            return &k_flags[i];
        if (arg[n] == '=' && k_flags[i].arg) {
            *value_out = arg + n + 1;
            return &k_flags[i];
        }
    }
    return NULL;
}

/* An integer option takes its value exactly: strtod() would round a seed of
 * 2^53 + 1 to 2^53 without a word, so a whole number is read as an integer
 * and one beyond 2^53 in magnitude (not every such integer is a double) is
 * refused. 1 when val (v after strtod) is fine, else 0 after printing why. */
static int exact_integer(const cli_option_flag *f, const char *val, double v)
{
    const double lim = 9007199254740992.0; /* 2^53 */
    const char *p = val + (val[0] == '-' || val[0] == '+');
    cvm_bounds b;
    if (cvm_option_bounds(&b, f->key) != CVM_OK || !b.is_integer)
        return 1;
    if (*p && strspn(p, "0123456789") == strlen(p)) {
        char *end;
        long long n;
        errno = 0;
        n = strtoll(val, &end, 10);
        if (errno != ERANGE && n >= -(long long)lim && n <= (long long)lim)
            return 1;
    } else if (fabs(v) < lim) {
        return 1;
    }
    fprintf(stderr, "cvmesh: %s %s: integers beyond 2^53 = 9007199254740992 cannot be taken "
                    "exactly (range %.17g..%.17g)\n", f->name, val, b.lo, b.hi);
    return 0;
}

int cli_parse_option_flag(unsigned cmd, int argc, char **argv, int *i, cli_setting *set,
                          int *nset)
{
    const char *val;
    const cli_option_flag *f = find(cmd, argv[*i], &val);
    char *end;
    double v;
    size_t nw = strlen(WINDOW_FLAG);
    if (strncmp(argv[*i], WINDOW_FLAG, nw) == 0 && (argv[*i][nw] == '\0' || argv[*i][nw] == '='))
        return parse_window(argc, argv, i, set, nset);
    if (!f)
        return 0;
    if (*nset >= CLI_MAX_SETTINGS) {
        fprintf(stderr, "cvmesh: too many option flags\n");
        return -1;
    }
    if (!f->arg) {
        v = f->value;
    } else {
        if (!val) {
            if (*i + 1 >= argc) {
                fprintf(stderr, "cvmesh: %s needs a value (%s)\n", f->name, f->arg);
                return -1;
            }
            val = argv[++*i];
        }
        if (word_value(f, val, &v)) {
            set[*nset].flag = f;
            set[*nset].value = v;
            (*nset)++;
            return 1;
        }
        v = strtod(val, &end);
        if (end == val || *end != '\0') {
            if (f->key == CVM_OPT_VTU_ENCODING)
                fprintf(stderr, "cvmesh: %s expects %s, got '%s'\n", f->name, f->arg, val);
            else
                fprintf(stderr, "cvmesh: %s expects a number, got '%s'\n", f->name, val);
            return -1;
        }
        if (!exact_integer(f, val, v))
            return -1;
    }
    set[*nset].flag = f;
    set[*nset].value = v;
    (*nset)++;
    return 1;
}

int cli_apply_settings(cvm_mesh *m, const cli_setting *set, int nset)
{
    int k;
    for (k = 0; k < nset; k++) {
        if (cvm_mesh_set_option(m, set[k].flag->key, set[k].value) != CVM_OK) {
            char v[32];
            fprintf(stderr, "cvmesh: %s %s: %s\n", set[k].flag->name,
                    cli_fmt_number(v, sizeof v, set[k].value), cvm_mesh_errmsg(m));
            return CLI_EXIT_USAGE;
        }
    }
    return CLI_EXIT_OK;
}

void cli_print_option_flags(FILE *f, unsigned cmd)
{
    size_t i;
    for (i = 0; i < NFLAGS; i++) {
        char left[64];
        cvm_bounds b;
        if (!(k_flags[i].commands & cmd))
            continue;
        snprintf(left, sizeof left, "%s%s%s", k_flags[i].name, k_flags[i].arg ? " " : "",
                 k_flags[i].arg ? k_flags[i].arg : "");
        fprintf(f, "  %-26s %s", left, k_flags[i].help);
        if (k_flags[i].arg && cvm_option_bounds(&b, k_flags[i].key) == CVM_OK) {
            char d[32], lo[32], hi[32];
            fprintf(f, " [default %s, range %s..%s]", cli_fmt_number(d, sizeof d, b.def),
                    cli_fmt_number(lo, sizeof lo, b.lo), cli_fmt_number(hi, sizeof hi, b.hi));
        }
        fputc('\n', f);
    }
    fprintf(f, "  %-26s %s\n", WINDOW_FLAG " X0,Y0,X1,Y1",
            "the .svg picture shows only [X0, X1] x [Y0, Y1] (default: the whole mesh)");
}

int cli_parse_algo(const char *name, const char *s, int with_aflr, cvm_algorithm *out)
{
    if (strcmp(s, "delaunay") == 0)
        *out = CVM_ALGO_DELAUNAY;
    else if (strcmp(s, "frontal") == 0)
        *out = CVM_ALGO_FRONTAL;
    else if (with_aflr && strcmp(s, "aflr") == 0)
        *out = CVM_ALGO_AFLR;
    else {
        fprintf(stderr, "cvmesh: %s: unknown --algo '%s' (%s)\n", name, s,
                with_aflr ? "delaunay, frontal or aflr" : "delaunay or frontal");
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

int cli_parse_nonnegative(const char *flag, const char *v, double *out)
{
    char *end;
    double x = strtod(v, &end);
    if (*end || !(x >= 0) || !isfinite(x)) {
        fprintf(stderr, "cvmesh: %s %s: must be a number >= 0\n", flag, v);
        return CLI_EXIT_USAGE;
    }
    *out = x;
    return CLI_EXIT_OK;
}

int cli_parse_positive(const char *flag, const char *v, double *out)
{
    char *end;
    double x = strtod(v, &end);
    if (*end || !(x > 0) || !isfinite(x)) {
        fprintf(stderr, "cvmesh: %s %s: must be a positive number\n", flag, v);
        return CLI_EXIT_USAGE;
    }
    *out = x;
    return CLI_EXIT_OK;
}

int cli_parse_tail(const char *name, unsigned cmd, int argc, char **argv, int *i,
                   cli_setting *set, int *nset, const char **in)
{
    const char *s = argv[*i];
    int r = cli_parse_option_flag(cmd, argc, argv, i, set, nset);
    if (r < 0)
        return CLI_EXIT_USAGE;
    if (r > 0)
        return CLI_EXIT_OK;
    if (s[0] == '-' && s[1] != '\0') {
        fprintf(stderr, "cvmesh: %s: unknown flag '%s' (see cvmesh %s --help)\n", name, s, name);
        return CLI_EXIT_USAGE;
    }
    if (*in) {
        fprintf(stderr, "cvmesh: %s: more than one input file ('%s' and '%s')\n", name, *in, s);
        return CLI_EXIT_USAGE;
    }
    *in = s;
    return CLI_EXIT_OK;
}

int cli_parse_args(const char *name, unsigned cmd, int argc, char **argv, void (*help)(FILE *),
                   cli_own_flags own, void *args, cli_outputs *o, cli_setting *set, int *nset,
                   const char **in)
{
    int i, r;
    for (i = 1; i < argc; i++) {
        if (strcmp(argv[i], "-h") == 0 || strcmp(argv[i], "--help") == 0) {
            help(stdout);
            return -1;
        }
        if (own && (r = own(args, argc, argv, &i)) != 0) {
            if (r > 1)
                return r - 1;
            continue;
        }
        if ((r = cli_parse_outputs(o, argc, argv, &i)) != 0) {
            if (r < 0)
                return CLI_EXIT_USAGE;
            continue;
        }
        if ((r = cli_parse_tail(name, cmd, argc, argv, &i, set, nset, in)))
            return r;
    }
    return CLI_EXIT_OK;
}

int cli_check_outputs3(const char *name, const char *in, const cli_outputs *o)
{
    size_t n = o->out ? strlen(o->out) : 0;
    if (cli_need_input(name, in) || cli_check_outputs(name, o))
        return CLI_EXIT_USAGE;
    if ((n > 4 && strcmp(o->out, "-") != 0 && strcmp(o->out + n - 4, ".svg") == 0) ||
        (o->format && strcmp(o->format, "svg") == 0)) {
        fprintf(stderr, "cvmesh: %s: no .svg picture of a 3D mesh (use .vtu, .msh or .node)\n",
                name);
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

int cli_need_input(const char *name, const char *in)
{
    if (in)
        return CLI_EXIT_OK;
    fprintf(stderr, "cvmesh: %s: no input file (see cvmesh %s --help)\n", name, name);
    return CLI_EXIT_USAGE;
}

int cli_fail(cvm_mesh *m, cvm_sizing *sz, const char *prefix)
{
    const char *msg;
    if (cli_interrupted())
        return cli_stop(m, sz);
    cli_progress_clear();
    msg = cvm_mesh_errmsg(m);
    /* a message about an item read from the file starts with "FILE:LINE: " already */
    if (prefix && strncmp(msg, prefix, strlen(prefix)) == 0 && msg[strlen(prefix)] == ':')
        prefix = NULL;
    fprintf(stderr, "cvmesh: %s%s%s\n", prefix ? prefix : "", prefix ? ": " : "", msg);
    cvm_sizing_free(sz);
    cvm_mesh_free(m);
    return CLI_EXIT_FAIL;
}
