/* options.c - the option table: keys, bounds, defaults, get and set. */
#include <math.h>
#include <string.h>

#include "api_internal.h"

typedef struct option_def {
    cvm_option key;
    const char *name;
    cvm_bounds b;
} option_def;

/* One row per key; slot = row index. Never reorder released keys' meaning. */
static const option_def k_options[] = {
    {CVM_OPT_REJECT_DUPLICATES, "REJECT_DUPLICATES", {0, 1, 0, 1}},
    {CVM_OPT_SPLIT_INTERSECTIONS, "SPLIT_INTERSECTIONS", {0, 1, 1, 1}},
    {CVM_OPT_KEEP_CONVEX_HULL, "KEEP_CONVEX_HULL", {0, 1, 0, 1}},
    {CVM_OPT_CONVEX_HULL_IF_NO_SEGMENTS, "CONVEX_HULL_IF_NO_SEGMENTS", {1, 1, 1, 1}},
    {CVM_OPT_MIN_ANGLE_DEG, "MIN_ANGLE_DEG", {0, 40, 30, 0}},
    {CVM_OPT_MAX_AREA, "MAX_AREA", {-1e300, 1e300, 0, 0}},
    {CVM_OPT_ENCROACH_LENS, "ENCROACH_LENS", {0, 1, 0, 1}},
    {CVM_OPT_KEEP_SEGMENT_VERTICES, "KEEP_SEGMENT_VERTICES", {0, 1, 1, 1}},
    {CVM_OPT_MARCH_SEGMENTS, "MARCH_SEGMENTS", {0, 1, 1, 1}},
    {CVM_OPT_SWAP, "SWAP", {0, 1, 1, 1}},
    {CVM_OPT_SMOOTH_SWEEPS, "SMOOTH_SWEEPS", {-1, 100, -1, 1}},
    {CVM_OPT_RESTORE_DELAUNAY, "RESTORE_DELAUNAY", {1, 1, 1, 1}},
    {CVM_OPT_SMOOTH_METHOD, "SMOOTH_METHOD", {0, 3, 0, 1}},
    {CVM_OPT_RELAX_SWEEPS, "RELAX_SWEEPS", {-1, 100, -1, 1}},
    {CVM_OPT_TIME_LIMIT_S, "TIME_LIMIT_S", {0, 1e9, 0, 0}},
    {CVM_OPT_SEED, "SEED", {0, 9007199254740992.0, 1, 1}},
    {CVM_OPT_MAX_STEINER, "MAX_STEINER", {0, 2147483647.0, 0, 1}},
    {CVM_OPT_THREADS, "THREADS", {0, 1024, 0, 1}},
    {CVM_OPT_DUAL_SOLVER, "DUAL_SOLVER", {1, 2, 1, 1}},
    {CVM_OPT_DUAL_MAX_SWEEPS, "DUAL_MAX_SWEEPS", {0, 100000, 50, 1}},
    {CVM_OPT_DUAL_MIN_ANGLE_DEG, "DUAL_MIN_ANGLE_DEG", {0, 50, 30, 0}},
    {CVM_OPT_DUAL_CUCKOO_BUDGET, "DUAL_CUCKOO_BUDGET", {30, 1000000, 300, 1}},
    {CVM_OPT_DUAL_PATTERN_BUDGET, "DUAL_PATTERN_BUDGET", {1, 1000000, 60, 1}},
    {CVM_OPT_DUAL_MARGIN, "DUAL_MARGIN", {0, 0.25, 0.15, 0}},
    {CVM_OPT_DUAL_TARGET_ANGLE_DEG, "DUAL_TARGET_ANGLE_DEG", {0, 60, 40, 0}},
    {CVM_OPT_DUAL_KEEP_INPUT_POINTS, "DUAL_KEEP_INPUT_POINTS", {0, 1, 0, 1}},
    {CVM_OPT_DUAL_LAYER_PRIORITY, "DUAL_LAYER_PRIORITY", {0, 100, 1, 0}},
    {CVM_OPT_DUAL_TOPOLOGY, "DUAL_TOPOLOGY", {0, 2, 1, 1}},
    {CVM_OPT_DUAL_PREPASS, "DUAL_PREPASS", {0, 1, 0, 1}},
    {CVM_OPT_DUAL_MAXMIN_ROUNDS, "DUAL_MAXMIN_ROUNDS", {0, 10000, 5, 1}},
    {CVM_OPT_DUAL_MAXMIN_TRIALS, "DUAL_MAXMIN_TRIALS", {0, 64, 0, 1}},
    {CVM_OPT_DUAL_MERGE_TOL, "DUAL_MERGE_TOL", {0, 1, 0.1, 0}},
    {CVM_OPT_AFLR_SMOOTH_LAYERS, "AFLR_SMOOTH_LAYERS", {0, 1000, 0, 1}},
    {CVM_OPT_SVG_WINDOW_XMIN, "SVG_WINDOW_XMIN", {-1e300, 1e300, 0, 0}},
    {CVM_OPT_SVG_WINDOW_YMIN, "SVG_WINDOW_YMIN", {-1e300, 1e300, 0, 0}},
    {CVM_OPT_SVG_WINDOW_XMAX, "SVG_WINDOW_XMAX", {-1e300, 1e300, 0, 0}},
    {CVM_OPT_SVG_WINDOW_YMAX, "SVG_WINDOW_YMAX", {-1e300, 1e300, 0, 0}},
    {CVM_OPT_VTU_ENCODING, "VTU_ENCODING", {0, 3, 3, 1}},
    {CVM_OPT_VTU_MERGED_CELLS, "VTU_MERGED_CELLS", {0, 1, 0, 1}},
    {CVM_OPT_GEN3_GRADING, "GEN3_GRADING", {0.01, 100, 0.3, 0}},
    {CVM_OPT_GEN3_LAYERS, "GEN3_LAYERS", {1, 16, 1, 1}},
    {CVM_OPT_GEN3_FREESPACE, "GEN3_FREESPACE", {0, 2, 0, 1}},
    {CVM_OPT_GEN3_SIZE_FROM_SURFACE, "GEN3_SIZE_FROM_SURFACE", {0, 1, 1, 1}},
    {CVM_OPT_GEN3_SURFACE, "GEN3_SURFACE", {0, 2, 0, 1}},
    {CVM_OPT_GEN3_OCTREE_SPLIT_HANGING, "GEN3_OCTREE_SPLIT_HANGING", {0, 1, 0, 1}},
    {CVM_OPT_DUAL3_MAX_SWEEPS, "DUAL3_MAX_SWEEPS", {0, 1e6, 50, 1}},
    {CVM_OPT_DUAL3_MIN_DIHEDRAL_DEG, "DUAL3_MIN_DIHEDRAL_DEG", {0, 60, 10, 0}},
    {CVM_OPT_DUAL3_BUDGET, "DUAL3_BUDGET", {1, 100000, 48, 1}},
    {CVM_OPT_DUAL3_MARGIN, "DUAL3_MARGIN", {0, 0.2, 0.03, 0}},
    {CVM_OPT_DUAL3_ESCALATE, "DUAL3_ESCALATE", {1, 64, 1, 1}},
    {CVM_OPT_DUAL3_SLIDE_BOUNDARY, "DUAL3_SLIDE_BOUNDARY", {0, 2, 1, 1}},
    {CVM_OPT_DUAL3_MERGE_TOL, "DUAL3_MERGE_TOL", {0, 1, 0.1, 0}},
    {CVM_OPT_DUAL3_FLIPS, "DUAL3_FLIPS", {0, 1, 1, 1}},
    {CVM_OPT_DUAL3_SOLVER, "DUAL3_SOLVER", {1, 3, 1, 1}},
    {CVM_OPT_DUAL3_CUCKOO_BUDGET, "DUAL3_CUCKOO_BUDGET", {40, 1e6, 300, 1}},
    {CVM_OPT_QUAD_P, "QUAD_P", {2, 12, 6, 1}},
    {CVM_OPT_QUAD_LBFGS_MEMORY, "QUAD_LBFGS_MEMORY", {1, 64, 8, 1}},
    {CVM_OPT_QUAD_GRADIENT_TOL, "QUAD_GRADIENT_TOL", {0, 1, 1e-10, 0}},
    {CVM_OPT_QUAD_MAX_ITERATIONS, "QUAD_MAX_ITERATIONS", {0, 1e9, 10000, 1}},
    {CVM_OPT_QUAD_RECOMBINE, "QUAD_RECOMBINE", {0, 2, 0, 1}},
    {CVM_OPT_QUAD_MIN_QUALITY, "QUAD_MIN_QUALITY", {0, 1, 0.5, 0}},
    {CVM_OPT_QUAD_CLIP, "QUAD_CLIP", {0, 1, 0, 1}},
    {CVM_OPT_QUAD_CELLWISE_METRIC, "QUAD_CELLWISE_METRIC", {0, 1, 0, 1}},
    {CVM_OPT_QUAD_RELOCATIONS, "QUAD_RELOCATIONS", {0, 64, 0, 1}},
    {CVM_OPT_QUAD_MEAN_METRIC_VORONOI, "QUAD_MEAN_METRIC_VORONOI", {0, 2, 2, 1}},
    {CVM_OPT_QUAD_INITIAL_SITES, "QUAD_INITIAL_SITES", {0, 1, 0, 1}},
    {CVM_OPT_QUAD_SMOOTH, "QUAD_SMOOTH", {0, 1000, 200, 1}},
    {CVM_OPT_QUAD_ALL_QUAD, "QUAD_ALL_QUAD", {0, 1, 0, 1}},
    {CVM_OPT_QUAD_CYCLES, "QUAD_CYCLES", {0, 20, 3, 1}},
};

#define NOPT (sizeof k_options / sizeof k_options[0])

typedef char option_table_fits[(NOPT <= CVM__NOPTIONS) ? 1 : -1];

int cvm__option_slot(cvm_option key)
{
    size_t i;
    for (i = 0; i < NOPT; i++)
        if (k_options[i].key == key)
            return (int)i;
    return -1;
}

void cvm__options_default(double *opt)
{
    size_t i;
    memset(opt, 0, CVM__NOPTIONS * sizeof *opt);
    for (i = 0; i < NOPT; i++)
        opt[i] = k_options[i].b.def;
}

double cvm__opt(const cvm_mesh *m, cvm_option key)
{
    int s = cvm__option_slot(key);
    return s >= 0 ? m->opt[s] : 0.0;
}

cvm_status cvm_option_bounds(cvm_bounds *out, cvm_option key)
{
    int s;
    if (!out)
        return CVM_E_NULL_ARG;
    s = cvm__option_slot(key);
    if (s < 0)
        return CVM_E_OPTION_KEY;
    *out = k_options[s].b;
    return CVM_OK;
}

cvm_status cvm_mesh_set_option(cvm_mesh *m, cvm_option key, double value)
{
    int s;
    const cvm_bounds *b;
    if (!m)
        return CVM_E_NULL_ARG;
    CVM__BEGIN(m);
    s = cvm__option_slot(key);
    if (s < 0)
        return cvm__error(&m->ctx, CVM_E_OPTION_KEY, CVM_ENT_OPTION, (int64_t)key,
                          "unknown option key %d", (int)key);
    b = &k_options[s].b;
    if (!(value >= b->lo && value <= b->hi))
        return cvm__error(&m->ctx, CVM_E_OPTION_RANGE, CVM_ENT_OPTION, (int64_t)key,
                          "option %s = %.17g is outside its bounds [%.17g, %.17g]",
                          k_options[s].name, value, b->lo, b->hi);
    if (b->is_integer && value != floor(value))
        return cvm__error(&m->ctx, CVM_E_OPTION_RANGE, CVM_ENT_OPTION, (int64_t)key,
                          "option %s = %.17g must be a whole number in [%.17g, %.17g]",
                          k_options[s].name, value, b->lo, b->hi);
    m->opt[s] = value;
    return CVM_OK;
}

cvm_status cvm_mesh_get_option(double *out, const cvm_mesh *m, cvm_option key)
{
    int s;
    if (!out || !m)
        return CVM_E_NULL_ARG;
    s = cvm__option_slot(key);
    if (s < 0)
        return CVM_E_OPTION_KEY;
    *out = m->opt[s];
    return CVM_OK;
}
