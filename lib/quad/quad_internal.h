/*
 * quad_internal.h - the metric field and the Lp-CVT optimiser of the
 * quad-dominant mesher (Levy and Liu 2010, "Lp centroidal Voronoi
 * tessellation and its applications"; Ekelschot et al., NASA Ames, for the
 * metric-aligned 2D variant and its boundary cells).
 *
 * Metric convention: a metric g is symmetric positive definite, stored as
 * (g11, g12, g22); g = M^T M with M = Lambda^(1/2) Q^T, Q = [q1 q2] the unit
 * eigenvectors, q1 = (cos th, sin th) with th = atan2(2 g12, g11 - g22) / 2.
 * An edge e has the metric length sqrt(e^T g e) = |M e|_2. For p > 2 the
 * energy depends on M (the directions), not only on g; where g is isotropic
 * th = 0 (axis-aligned: the boxes of the test cases). Derivatives dg are two
 * blocks of three (d/dx then d/dy), as cvm_metric_fn.
 *
 * The metric comes from the sizing handle (cvm_sizing_set_metric_fn()): a
 * constant tensor and the built-in fields are callbacks defined here, per-vertex
 * tensors on a background triangulation the log-Euclidean evaluator of
 * metric_background.c. Every evaluation is checked (finite, SPD).
 */
#ifndef CVM_QUAD_INTERNAL_H
#define CVM_QUAD_INTERNAL_H

#include <stddef.h>
#include <stdint.h>
#include "common/common_internal.h"
#include "delaunay/delaunay_internal.h"
#include "refine/refine_internal.h"
#include "sizing/sizing_internal.h"

/* ---- symmetric 2x2 tensors and the metric (metric.c) ---- */

/* Eigen-decomposition of g (and of its derivatives when dg is not NULL):
 * lam[0] >= lam[1] along q1 = (cos th, sin th), q2 = (-sin th, cos th);
 * dlam[2k + m] = d lam_k / d x_m, dth[m] = d th / d x_m. Where an eigenvalue
 * gap closes (g isotropic) a derivative whose formula reads 0/0 is taken as 0. */
typedef struct cvm__eig2 {
    double lam[2], cs, sn; /* q1 = (cs, sn) = (cos th, sin th) */
    double dlam[4], dth[2];
} cvm__eig2;
void cvm__eig2_of(cvm__eig2 *e, const double g[3], const double *dg);
/* g = Q diag(mu) Q^T, Q's first column (cs, sn) = (cos th, sin th), and (dg not NULL) its
 * derivatives from dmu[2k + m] and dth[m]. */
void cvm__eig2_compose(double g[3], double *dg, double cs, double sn, const double mu[2],
                       const double *dmu, const double *dth);

/* M = Lambda^(1/2) Q^T (row-major M[0..3]) of g, and when dM is not NULL its
 * derivatives dM[4m + k] = d M_k / d x_m from dg. g must be SPD. */
void cvm__metric_factor(double M[4], double *dM, const double g[3], const double *dg);

/* |H| with eigen-sizes clamped: each eigenvalue l of the Hessian H (h11, h12,
 * h22) becomes the size h = |l|^(-1/2) clamped to [hmin, hmax], then the larger
 * size is cut to aspect times the smaller; g = Q diag(1/h^2) Q^T. dH (6, the
 * third derivatives as two blocks) gives dg; a clamped size has derivative 0. */
void cvm__metric_hessian_abs(double g[3], double *dg, const double H[3], const double *dH,
                             double hmin, double hmax, double aspect);
/* g = I + grad f grad f^T, and dg from the Hessian H of f (h11, h12, h22). */
void cvm__metric_grad_outer(double g[3], double *dg, const double grad[2], const double *H);

/* The built-in fields, each g(x, y) times scale: */
typedef enum cvm__metric_kind {
    CVM__METRIC_CONSTANT = 0, /* the tensor g of the payload */
    CVM__METRIC_IDENTITY,     /* I */
    CVM__METRIC_STRETCH,      /* diag(1, 1 + 4 y^2) */
    CVM__METRIC_SADDLE,       /* I + grad f grad f^T, f = x^2 - y^2 */
    CVM__METRIC_SSHOCK        /* |Hessian| of 3/4 tanh(2 (sin 5y - 3x)), sizes in [0.005, 0.2],
                                 aspect <= 50 */
} cvm__metric_kind;
/* kind (a cvm__metric_kind), scale, and g (CVM__METRIC_CONSTANT only): the sizing
 * handle's own storage type, so the handle can keep the parameters */
typedef cvm__metric_params cvm__metric_builtin;
/* A cvm_metric_fn (install with has_derivatives = 1) whose payload is a
 * const cvm__metric_builtin *; exact derivatives. Returns 0 (every point accepted). */
int cvm__metric_builtin_fn(void *payload, const double *x, int dim, double *g, double *dg);

/* The checked evaluation of the metric of a sizing handle. Outside the domain
 * (a point the callback refuses) the metric is the value at the nearest point
 * of the boundary polygon bnd (nbnd corners, closed), with its derivative
 * along the boundary. */
typedef struct cvm__metric {
    const cvm_sizing *s;
    const double *bnd; /* 2 per corner; may be NULL */
    size_t nbnd;
} cvm__metric;
/* With dg NULL the callback is called with dg NULL too (it may skip its derivatives).
 * CVM_E_ARGUMENT (message on err naming the point) when the metric has no
 * derivatives (installed with has_derivatives = 0: the optimiser needs them,
 * never finite differences), is not finite, is not positive definite, or is
 * refused with no boundary to fall back on. dg may be NULL. */
cvm_status cvm__metric_eval(const cvm__metric *mt, const double y[2], double g[3], double *dg,
                            cvm__ctx *err);
/* The same, factored: M and dM (8) as cvm__metric_factor(). */
cvm_status cvm__metric_eval_M(const cvm__metric *mt, const double y[2], double M[4], double *dM,
                              cvm__ctx *err);
/* The most points of one cvm__metric_eval_M_batch() (the degree-12 Dunavant rule has 33). */
#define CVM__QUAD_MAXQ 36
/* M (4 per point) and dM (8 per point) at the n <= CVM__QUAD_MAXQ points y (2 each): the
 * energy's quadrature points, its hot path. Each evaluation is checked as cvm__metric_eval()'s,
 * the first failing point (in order) naming the error. The same M as cvm__metric_eval_M() up to
 * rounding and, for the stretch, saddle and S-shock built-ins (M from their own
 * eigen-directions), up to the sign and order of its rows, which the energy |M d|_p^p (p even)
 * does not see; where g is isotropic both take the axes. Not used where a result must not move
 * with the rounding (constant metrics, the boundary, the measures). CVM_OK, the errors of
 * cvm__metric_eval(), CVM_E_INTERNAL when n is too large. */
cvm_status cvm__metric_eval_M_batch(const cvm__metric *mt, const double *y, size_t n, double *M,
                                    double *dM, cvm__ctx *err);

/* ---- log-Euclidean interpolation on a background triangulation (metric_background.c) ---- */

typedef struct cvm__metric_bg {
    double *xy;     /* 2 per node */
    double *logg;   /* 3 per node: log of its tensor */
    int32_t *tri;   /* 3 per triangle */
    size_t np, nt;
    cvm__cell_grid grid;
    int32_t *start, *items; /* triangles by grid cell */
    cvm__ctx *ctx;  /* the allocator of the arrays */
} cvm__metric_bg;
/* Copy the background (np nodes xy, nt triangles tri, a tensor g per node) and
 * take the logs. CVM_OK; CVM_E_ARGUMENT naming the node whose tensor is not
 * finite or not SPD, or the triangle with an index out of range or no area;
 * CVM_E_NOMEM. On error bg is empty (free it anyway). */
cvm_status cvm__metric_bg_build(cvm__metric_bg *bg, cvm__ctx *ctx, const double *xy, size_t np,
                                const int32_t *tri, size_t nt, const double *g);
void cvm__metric_bg_free(cvm__metric_bg *bg);
/* A cvm_metric_fn (has_derivatives = 1), payload a const cvm__metric_bg *:
 * exp of the linear interpolant of the logs in the triangle holding x (the
 * lowest-numbered one on a shared edge), with its exact derivative; returns 1
 * (refused) outside every triangle. */
int cvm__metric_bg_fn(void *payload, const double *x, int dim, double *g, double *dg);

/* ---- symmetric Dunavant rules on the triangle (dunavant.c) ---- */

/* The rule of the lowest even degree >= deg (2..12): rows l0, l1, l2, weight (weights sum
 * to 1); *n_out its number of points, *deg_out its degree. NULL when deg > 12. */
const double (*cvm__dunavant_rule(int deg, size_t *n_out, int *deg_out))[4];

/* ---- the Lp-CVT energy and its gradient (lpcvt_*.c) ---- */

/* A vertex of a Voronoi cell polygon, as a function of the sites. */
enum {
    CVM__PV_CC = 0,    /* the circumcentre of triangle slot t */
    CVM__PV_FIXED = 1  /* the constant off (a boundary edge midpoint, clipping) */
};
typedef struct cvm__pvert {
    int kind;
    int32_t t;
    double off[2];
} cvm__pvert;

/*
 * E = sum over the sites i of Int_{cell i} |M(y) (y - x_i)|_p^p dy, each cell a
 * fan of triangles (site, two consecutive polygon vertices) integrated by the
 * Dunavant rule of degree p. Sites 0..nb-1 are the fixed boundary vertices,
 * a closed counter-clockwise convex polygon whose edges are the domain
 * boundary; sites nb..ns-1 move (with reconstruction they may cross the
 * boundary during a line search: the energy stays defined and pushes them
 * back; cvm__lpcvt_optimise() checks the result).
 * Boundary cells, reconstruction (clip = 0): each boundary site b gets fixed
 * ghost sites outside, A and B at unit metric length (metric at b) along the
 * outward normals of its two boundary edges and, at a corner turning left by
 * more than 1e-9 rad, C where the lines through A and B parallel to those
 * edges meet (one ghost at the mean of A and B on a straight boundary), and
 * four far frame points at 3 times the ghosts' extent; the cells are the
 * Voronoi cells of sites and ghosts, the ghosts' own cells not counted. So a boundary site of a unit lattice has a whole unit cell centred
 * on it, and E is the Voronoi energy of fixed and moving sites (C^1).
 * The metric is M(y) at each quadrature point (the quadrature is then exact
 * only where M is constant, and E has gradient kinks of the size of the
 * quadrature error where the Delaunay topology flips), or, with cellwise
 * set after init, M(x_i) over cell i: every integral exact for degree p,
 * E is C^1 and L-BFGS converges to rounding.
 * Clipping (clip = 1): the Delaunay triangulation constrained by the boundary,
 * a boundary cell closed by its two edge midpoints and the site itself - the
 * cell clipped to the domain while every Voronoi vertex lies in it.
 */
typedef struct cvm__lpcvt {
    cvm__ctx *ctx;
    cvm__metric metric;
    int p, clip;
    int cellwise;       /* 0: M(y) at every quadrature point (default); 1: M(x_i) over cell i */
    int mconst;         /* 1: the metric is a constant built-in (cvm__lpcvt_init() decides): M is
                           Mc everywhere, dM = 0, and no point is evaluated */
    double Mc[4];
    int threads;        /* OpenMP threads of the energy and gradient (default 1; more only when the
                           metric callback may be called concurrently); same bits for any count */
    uint8_t *cstat;     /* per site: 1 when its cell failed (threaded evaluation) */
    const double (*rule)[4];
    size_t nq;
    size_t nb, ns, nall; /* boundary sites, sites, sites and ghosts */
    double *xy;         /* 2 per site then per ghost: the configuration of the last topology */
    double *bmid;       /* 4 per boundary site: midpoints of its edge to the next and from the previous */
    int32_t *seg;       /* 2 per boundary edge */
    cvm__tri2 T;
    cvm__cdt_out co;
    size_t *cstart;     /* ns + 1: cell i is pv[cstart[i] .. cstart[i+1]) */
    uint8_t *copen;     /* per site: 1 when the fan does not close (clipping) */
    cvm__pvert *pv;
    size_t npv, cap_pv;
    double *cc, *gcc;   /* 2 per triangle slot: circumcentre, dE/d circumcentre */
    size_t cap_cc, cap_gcc;
    double *gsite;      /* 2 per site and ghost: dE/d site */
    double *ecell;      /* per site: the energy of its cell (cvm__lpcvt_eval) */
    double *gpv;        /* 2 per polygon vertex: dE/d vertex */
    size_t cap_gpv;
    int32_t *star;
    size_t cap_star;
    int kept;           /* 1: T and the polygons are those of a valid configuration, and the next
                           topology keeps them when T is still Delaunay (reconstruction only) */
    int valid;          /* the last topology: 1, or 0 when the energy is not defined there: a
                           moving site on another, beyond the ghosts (an unbounded cell) or, with
                           clipping, not strictly inside the domain */
} cvm__lpcvt;

/* Prepare L for the boundary polygon bxy (nb >= 3 corners, counter-clockwise,
 * convex) and ni moving sites, the metric of s, exponent p (even, 2..12) and
 * clip. CVM_OK; CVM_E_ARGUMENT (p, a clockwise or non-convex boundary, a bad
 * metric at an edge midpoint: message says which); CVM_E_NOMEM. Free with
 * cvm__lpcvt_free() also after an error. */
cvm_status cvm__lpcvt_init(cvm__lpcvt *L, cvm__ctx *ctx, const cvm_sizing *s, const double *bxy,
                           size_t nb, size_t ni, int p, int clip);
void cvm__lpcvt_free(cvm__lpcvt *L);
/* The Delaunay topology and the cell polygons of the configuration whose moving
 * sites are xi (2 per site); L->valid says whether the energy is defined there.
 * CVM_OK, CVM_E_NOMEM, CVM_E_INTERNAL, CVM_INCOMPLETE_* of the kernel. */
cvm_status cvm__lpcvt_topology(cvm__lpcvt *L, const double *xi);
/* 1 when p lies strictly inside the boundary polygon of L (exact orientations). */
int cvm__lpcvt_inside(const cvm__lpcvt *L, const double *p);
/* The same test against the convex counter-clockwise polygon b (nb >= 3 vertices). */
int cvm__lpcvt_inside_polygon(const double *b, size_t nb, const double *p);
/* Topology, then E and (grad not NULL) dE/d xi (2 per moving site). With
 * L->valid 0 on return E and grad are not written. Errors of the topology and
 * of the metric (CVM_E_ARGUMENT naming the point). */
cvm_status cvm__lpcvt_eval(cvm__lpcvt *L, const double *xi, double *E, double *grad);
/* The same energy, by the same source, in complex arithmetic on the topology of
 * the last cvm__lpcvt_topology() (for complex-step checks): xyz holds the nall
 * sites and ghosts as (x, y) pairs, each coordinate a double _Complex stored as its real and
 * imaginary parts (4 doubles per site); *E_out receives the real and imaginary parts. */
cvm_status cvm__lpcvt_energy_complex(cvm__lpcvt *L, const double *xyz, double E_out[2]);

/* ---- quasi-Newton minimisation: a thin wrapper over liblbfgs (lbfgs.c) ---- */

/* One evaluation: *f and g (n values) at x; *valid 0 when f is not defined at x (the line
 * search then backs off). An error status stops the minimisation and is returned. */
typedef cvm_status (*cvm__minimise_fn)(void *payload, const double *x, double *f, double *g,
                                       int *valid);

typedef struct cvm__lbfgs_opts {
    int memory;         /* corrections kept (default 8) */
    long max_iter;      /* iterations in all, over restarts (0: none) */
    double gtol;        /* stop when |g|_inf <= gtol * |f| / length (default 1e-10) */
    double length;      /* the length scale of that test (the domain's size) */
    double delta;       /* stop when the relative decrease over past iterations is below delta */
    int past;           /* (default 1e-12 over 10) */
    int relocations;    /* cvm__lpcvt_optimise(): relocation attempts after convergence (default 8) */
    double step0;       /* the length in x of the first trial step of each (re)start (default 1,
                           liblbfgs's own); the variables are scaled by it */
} cvm__lbfgs_opts;

typedef enum cvm__lbfgs_stop {
    CVM__LBFGS_GRADIENT = 0, /* the gradient test */
    CVM__LBFGS_DECREASE,     /* too little decrease over the past iterations */
    CVM__LBFGS_ITERATIONS,   /* max_iter */
    CVM__LBFGS_LINE_SEARCH,  /* a line search failed right after a restart of the memory */
    CVM__LBFGS_TIME          /* the time limit or a cancellation (the status says which) */
} cvm__lbfgs_stop;

typedef struct cvm__lbfgs_result {
    double f, gnorm_inf;
    long iterations, evaluations, restarts;
    cvm__lbfgs_stop stop;
    int backend_code;   /* the last return of the backend (liblbfgs: lbfgs()), for diagnostics */
    long outside;       /* cvm__lpcvt_optimise(): moving sites not strictly inside the domain at
                           the end (0 expected: the energy pushes them in; the caller decides) */
} cvm__lbfgs_result;

/* Defaults above (length 1, max_iter 10000). */
void cvm__lbfgs_defaults(cvm__lbfgs_opts *o);
/* Minimise from x (n values, overwritten by the best point found): L-BFGS with the More-Thuente
 * line search; the memory restarts when a line search fails, and the run stops when a line search
 * fails again without progress since the restart. Run control (progress, time limit) of ctx.
 * Returns CVM_OK; CVM_INCOMPLETE_TIME_LIMIT or _CANCELLED (x the last iterate); an error of fn;
 * CVM_E_ARGUMENT when fn is not defined at the start; CVM_E_NOMEM (liblbfgs allocates with the C
 * library's malloc, outside the handle's allocator). */
cvm_status cvm__lbfgs_minimise(double *x, size_t n, cvm__minimise_fn fn, void *payload,
                               const cvm__lbfgs_opts *o, cvm__lbfgs_result *res, cvm__ctx *ctx);

/* ---- the boundary at unit metric length (boundary.c) ---- */

/* The metric length of the segment a + s (b - a), s in [s0, s1]: adaptive Gauss-Kronrod (7, 15)
 * to 1e-12 relative. CVM_OK or the metric's error. */
cvm_status cvm__metric_length(double *out, const cvm__metric *mt, const double *a, const double *b,
                              double s0, double s1, cvm__ctx *err);
/* Subdivide each edge of the closed polygon corners (nc corners, counter-clockwise) into
 * n = max(1, round(L_M)) pieces of equal metric length (Newton on the arc length), so two
 * identical edges under identical metrics get identical points. *xy_out (allocated on ctx, the
 * caller frees it) receives the boundary sites, corners included, in order; *n_out their number.
 * CVM_OK, the metric's errors, CVM_E_NOMEM, CVM_E_TOO_LARGE (more than 2^30 sites). */
cvm_status cvm__boundary_discretise(double **xy_out, size_t *n_out, const cvm__metric *mt,
                                    const double *corners, size_t nc, cvm__ctx *ctx);

/* ---- parallelogram smoothing of the quad-dominant cells (smooth.c) ---- */

typedef struct cvm__quad_smooth_in {
    size_t nv;          /* points */
    size_t first_free;  /* points first_free .. nv - 1 may move; the others are fixed */
    size_t ncell;       /* cells: counter-clockwise polygons conn[off[c] .. off[c + 1]) */
    const int32_t *off, *types, *conn; /* types: CVM_CELL_QUAD or CVM_CELL_TRIANGLE */
    int (*metric)(double x, double y, double g[3], void *user); /* nonzero: refused */
    void *metric_user;
    int sweeps;         /* Gauss-Seidel sweeps over the free points, in index order */
    double *quality;    /* ncell or NULL: after the moves, each quad's 1 - max|corner - 90| / 90
                           in the metric at its vertex mean (as the recombination's) */
} cvm__quad_smooth_in;
/* Move each free point that has a quad to the mean of its quad-edge neighbours, or else towards
 * the mean, over its quads, of the point that makes the quad a parallelogram (full step, half, a
 * quarter): the first move kept is one that leaves every cell of the point strictly convex
 * (exact orient2d) and lowers the cost of its quads, the sum of the squared corner deviations
 * from 90 degrees in the metric at the quad's vertex mean plus, per quad edge, the squared angle
 * to the nearer eigenvector of that metric times its anisotropy (lam1 - lam2) / (lam1 + lam2).
 * Stops after a sweep without a move. Deterministic (serial, index order). xy: 2 nv,
 * updated. *moves_out: the moves kept. CVM_OK, CVM_E_NOMEM (xy unchanged) or CVM_E_ARGUMENT
 * (the metric refused a quad's vertex mean when its quality was written). */
cvm_status cvm__quad_smooth(cvm__ctx *ctx, double *xy, const cvm__quad_smooth_in *in,
                            size_t *moves_out);

/* ---- initial sites and the optimisation (lpcvt_optimise.c) ---- */

/* Int sqrt(det g) dA over the convex polygon bxy (nb corners): a fan from its first corner, each
 * triangle split into four until the degree-8 and degree-12 Dunavant rules agree to 1e-6 relative
 * (depth at most 8); *rho_max the largest sqrt(det g) met. CVM_OK or the metric's error. */
cvm_status cvm__metric_area(double *area, double *rho_max, const cvm__metric *mt, const double *bxy,
                            size_t nb, cvm__ctx *ctx);
/* The initial moving sites of L's domain: N = max(0, round(A_M - nb/2 + 1)) (the interior vertex
 * count of a unit quad grid of metric area A_M and nb boundary edges) points drawn from the
 * density sqrt(det g) by rejection on a Halton sequence (bases 2, 3, 5), rotated by seed
 * (Cranley-Patterson): deterministic and evenly spread, not uniform random. *xi_out (on ctx,
 * the caller frees) and *ni_out. CVM_OK, the metric's errors, CVM_E_NOMEM, CVM_E_TOO_LARGE. */
cvm_status cvm__lpcvt_initial_sites(double **xi_out, size_t *ni_out, const cvm__metric *mt,
                                    const double *bxy, size_t nb, uint64_t seed, cvm__ctx *ctx);
/* The initial moving sites of the convex domain cor (nc corners, counter-clockwise) by an
 * advancing front in metric space (frontal_sites.c): breadth first from the boundary sites bxy
 * (nb), each placed point steps one unit metric length along +-d1 and +-d2, d1 the metric's
 * major eigenvector blended towards the nearest edge's direction where the metric is nearly
 * isotropic (a cross field, angles modulo 90 degrees), d2 metric-orthogonal to it; a step is
 * kept when strictly inside the domain, at least 0.6 from every edge and 0.75 from every point
 * placed (metric lengths at the candidate). At most limit sites. Deterministic: no random
 * numbers. *xi_out (on ctx, the caller frees) and *ni_out. CVM_OK, the metric's errors,
 * CVM_E_NOMEM, CVM_E_TOO_LARGE. */
cvm_status cvm__lpcvt_frontal_sites(double **xi_out, size_t *ni_out, const cvm__metric *mt,
                                    const double *bxy, size_t nb, const double *cor, size_t nc,
                                    size_t limit, cvm__ctx *ctx);
/* Minimise the energy of L over its moving sites xi (ni = L->ns - L->nb, 2 per site, overwritten)
 * with cvm__lbfgs_minimise(); o->length is set from the boundary's bounding box and o->step0 to
 * a quarter of the shortest boundary edge (a first step that moves no site past its
 * neighbours). Then up to
 * o->relocations times escape a local minimum: the 1 + m/256 moving sites of least cell energy
 * (m moving sites) move into as many cells of most energy (half-way from its site to its
 * farthest polygon vertex; each cell once, ties to the lower index) and the sites are optimised
 * again; the move is kept when E drops by more than 1e-9 E, else undone and the
 * relocations stop. res sums the iterations and evaluations of every run. */
cvm_status cvm__lpcvt_optimise(cvm__lpcvt *L, double *xi, const cvm__lbfgs_opts *o,
                               cvm__lbfgs_result *res);

/* One insertion/removal cycle (lpcvt_adapt.c): the Delaunay edges of L's sites at xi (L->nb
 * boundary sites, then the moving sites xi) with a moving end, measured in L's metric
 * (cvm__metric_length()); only sides count, not diagonals: an edge that is the longest of every
 * triangle beside it is left out. *pct_in: the share of the sides with L_M in [1/sqrt 2,
 * sqrt 2]. Each side shorter than 1/sqrt 2 whose ends are both still there loses one end, the
 * moving end with the larger coefficient of variation of its edges' metric lengths; then each
 * side longer than sqrt 2 with both ends kept gets a site at its midpoint. *xo (on L's ctx, the caller frees):
 * the kept moving sites in order, then the new ones (*no in all, *nins added, *nrem removed);
 * NULL when nothing changes or the energy is not defined at xi. CVM_OK, CVM_E_NOMEM, the
 * metric's errors. */
cvm_status cvm__lpcvt_adapt_sites(cvm__lpcvt *L, const double *xi, double **xo, size_t *no,
                                  size_t *nins, size_t *nrem, double *pct_in);

/* ---- measures of a quad-dominant mesh (quad_measures.c) ---- */

/* The number of values of cvm__quad_measures(): CVM_REPORT_QUAD_PCT .. _MIN_SCALED_JACOBIAN. */
#define CVM__QUAD_NMEASURES 13
/* The measures of the mixed cells (off: ncell + 1 offsets into conn, types: CVM_CELL_QUAD or
 * CVM_CELL_TRIANGLE, counter-clockwise ids into xy) in the metric of mt, into
 * out[k] = the value of report CVM_REPORT_QUAD_PCT + k (see include/cvmesh.h). Plain doubles:
 * measures, not decisions. CVM_OK, the metric's errors, CVM_E_NOMEM. */
cvm_status cvm__quad_measures(double *out, const cvm__metric *mt, const double *xy, size_t ncell,
                              const int32_t *off, const int32_t *types, const int32_t *conn,
                              cvm__ctx *ctx);

#endif
