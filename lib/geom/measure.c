/* measure.c - plain-double measures of 2D triangles: angles, smallest-angle sin^2, areas, circumradii. */
#include <float.h>
#include <math.h>

#include "geom/measure.h"

double cvm__tri_area(const double *a, const double *b, const double *c)
{
    return cvm__cross2(a, b, c) / 2;
}

double cvm__tri_area_abs(const double *a, const double *b, const double *c)
{
    return fabs(cvm__cross2(a, b, c)) / 2;
}

double cvm__circumradius2_sides(double l0, double l1, double l2, double cross)
{
    return l0 * l1 * l2 / (4 * cross * cross);
}

double cvm__circumradius2(const double *a, const double *b, const double *c)
{
    return cvm__circumradius2_sides(cvm__dist2(b, c), cvm__dist2(c, a), cvm__dist2(a, b),
                                    cvm__cross2(a, b, c));
}

double cvm__vec_angle(double ux, double uy, double wx, double wy)
{
    return atan2(fabs(ux * wy - uy * wx), ux * wx + uy * wy);
}

double cvm__corner_angle(const double *o, const double *a, const double *b)
{
    return cvm__vec_angle(a[0] - o[0], a[1] - o[1], b[0] - o[0], b[1] - o[1]);
}

double cvm__turn_angle(const double *a, const double *b, const double *c)
{
    return cvm__vec_angle(b[0] - a[0], b[1] - a[1], c[0] - b[0], c[1] - b[1]);
}

double cvm__tri_min_angle_deg(const double *a, const double *b, const double *c)
{
    const double *p[3];
    double best = 180.0;
    int q;
    p[0] = a;
    p[1] = b;
    p[2] = c;
    for (q = 0; q < 3; q++) {
        double x = cvm__corner_angle(p[q], p[(q + 1) % 3], p[(q + 2) % 3]) * (180.0 / CVM__PI);
        if (x < best)
            best = x;
    }
    return best;
}

double cvm__min_sin2(const double *a, const double *b, const double *c)
{
    double ab = cvm__dist2(a, b), bc = cvm__dist2(b, c), ca = cvm__dist2(c, a);
    double cr = cvm__cross2(a, b, c);
    double mn = ab < bc ? (ab < ca ? ab : ca) : (bc < ca ? bc : ca);
    double pr = ab * bc * ca;
    return pr > 0 ? cr * cr * mn / pr : 0.0;
}

double cvm__min_sin2_sides(double l0, double l1, double l2, double cross)
{
    double lmin = l0 < l1 ? (l0 < l2 ? l0 : l2) : (l1 < l2 ? l1 : l2);
    return lmin * cross * cross / (l0 * l1 * l2);
}

double cvm__min_sin2_ccw(const double *a, const double *b, const double *c)
{
    double cross = cvm__cross2(a, b, c);
    if (!(cross > 0))
        return 0.0;
    return cvm__min_sin2_sides(cvm__dist2(b, c), cvm__dist2(a, c), cvm__dist2(a, b), cross);
}

double cvm__min_sin2_corners(const double *a, const double *b, const double *c)
{
    const double *p[3];
    double l2[3], cr = cvm__cross2(a, b, c), m = HUGE_VAL;
    int k;
    p[0] = a;
    p[1] = b;
    p[2] = c;
    for (k = 0; k < 3; k++)
        l2[k] = cvm__dist2(p[(k + 1) % 3], p[(k + 2) % 3]); /* the side opposite corner k */
    for (k = 0; k < 3; k++) {
        /* the angle at corner k lies between the sides opposite corners k+1 and k+2 */
        double s = cr * cr / (l2[(k + 1) % 3] * l2[(k + 2) % 3]);
        m = s < m ? s : m;
    }
    return m;
}

/* ---- range-safe measures (for reports on any finite input) ---- */

/* An edge vector whose larger component lies in [SAFE_LO, SAFE_HI] gives
 * products that neither overflow (2^1001 < DBL_MAX) nor lose precision to
 * subnormals (2^-1000 > DBL_MIN). */
#define SAFE_LO 0x1p-500
#define SAFE_HI 0x1p+500

static int in_safe_range(double x, double y)
{
    double mx = fmax(fabs(x), fabs(y));
    return mx >= SAFE_LO && mx <= SAFE_HI;
}

/* q - p as u * 2^(return value), the larger component of u in [1, 2) (u = 0
 * for p = q). Exact unless the difference overflows; then it comes from the
 * halved coordinates (which round only subnormal parts). */
static int scaled_diff(const double *p, const double *q, double *u)
{
    double x = q[0] - p[0], y = q[1] - p[1], mx;
    int e = 0;
    if (!(fabs(x) <= DBL_MAX && fabs(y) <= DBL_MAX)) {
        x = 0.5 * q[0] - 0.5 * p[0];
        y = 0.5 * q[1] - 0.5 * p[1];
        e = 1;
    }
    mx = fmax(fabs(x), fabs(y));
    if (mx > 0) {
        int k = ilogb(mx);
        x = ldexp(x, -k);
        y = ldexp(y, -k);
        e += k;
    }
    u[0] = x;
    u[1] = y;
    return e;
}

/* Angle at a of triangle a, b, c, degrees; *dot receives the dot product of
 * the two edge vectors (times a positive factor outside the safe range). */
double cvm__corner_angle_deg_safe(const double *a, const double *b, const double *c, double *dot)
{
    double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - a[0], vy = c[1] - a[1];
    if (!in_safe_range(ux, uy) || !in_safe_range(vx, vy)) {
        double u[2], v[2];
        scaled_diff(a, b, u);
        scaled_diff(a, c, v);
        ux = u[0];
        uy = u[1];
        vx = v[0];
        vy = v[1];
    }
    *dot = ux * vx + uy * vy;
    return cvm__vec_angle(ux, uy, vx, vy) * (180.0 / CVM__PI);
}

/* Signed area of triangle a, b, c (positive counter-clockwise); +-inf only
 * when its magnitude exceeds the largest double. */
double cvm__tri_area_safe(const double *a, const double *b, const double *c)
{
    double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - a[0], vy = c[1] - a[1];
    double u[2], v[2];
    int e;
    if (in_safe_range(ux, uy) && in_safe_range(vx, vy))
        return 0.5 * (ux * vy - uy * vx);
    e = scaled_diff(a, b, u) + scaled_diff(a, c, v);
    return ldexp(0.5 * (u[0] * v[1] - u[1] * v[0]), e);
}

/* The corner (0, 1, 2 for a, b, c) whose angle is the smallest, decided
 * from the very doubles whose atan2 gives each angle: corner k's angle is
 * atan2(y[k], x[k]), so when x[k] > 0 and y[k] x[j] < y[j] x[k] by a
 * relative margin of 2^-40 for every other acute corner j, the true atan2
 * of corner k is smaller by far more than atan2's rounding (a relative gap
 * of at least 0.4 * 2^-40 for angles up to 60 degrees, against 2^-52), and
 * so is its computed value; an obtuse or right corner's value is never below
 * an acute one's. -1 when no corner wins clearly (near-isosceles triangles)
 * or an edge vector is outside the safe range. */
static int smallest_corner(const double *const *p)
{
    double x[3], y[3];
    int k, j;
    for (k = 0; k < 3; k++) {
        const double *o = p[k], *q = p[(k + 1) % 3], *r = p[(k + 2) % 3];
        double ux = q[0] - o[0], uy = q[1] - o[1], vx = r[0] - o[0], vy = r[1] - o[1];
        if (!in_safe_range(ux, uy) || !in_safe_range(vx, vy))
            return -1;
        y[k] = fabs(ux * vy - uy * vx);
        x[k] = ux * vx + uy * vy;
    }
    for (k = 0; k < 3; k++) {
        int wins = x[k] > 0;
        for (j = 0; wins && j < 3; j++)
            if (j != k && x[j] > 0 && !(y[k] * x[j] < y[j] * x[k] * (1 - 0x1p-40)))
                wins = 0;
        if (wins)
            return k;
    }
    return -1;
}

/* The minimum of the three corner angles; one atan2 instead of three when
 * smallest_corner() can tell which it is, with the same result bits. */
double cvm__min_angle_deg(const double *a, const double *b, const double *c)
{
    const double *p[3];
    double d, x, y, z;
    int k;
    p[0] = a;
    p[1] = b;
    p[2] = c;
    if ((k = smallest_corner(p)) >= 0)
        return cvm__corner_angle_deg_safe(p[k], p[(k + 1) % 3], p[(k + 2) % 3], &d);
    x = cvm__corner_angle_deg_safe(a, b, c, &d);
    y = cvm__corner_angle_deg_safe(b, c, a, &d);
    z = cvm__corner_angle_deg_safe(c, a, b, &d);
    x = x < y ? x : y;
    return x < z ? x : z;
}

double cvm__metric_angle_deg(const double g[3], const double *o, const double *a, const double *b)
{
    double u[2], v[2], uv, uu, vv, c;
    u[0] = a[0] - o[0];
    u[1] = a[1] - o[1];
    v[0] = b[0] - o[0];
    v[1] = b[1] - o[1];
    uv = g[0] * u[0] * v[0] + g[1] * (u[0] * v[1] + u[1] * v[0]) + g[2] * u[1] * v[1];
    uu = g[0] * u[0] * u[0] + 2 * g[1] * u[0] * u[1] + g[2] * u[1] * u[1];
    vv = g[0] * v[0] * v[0] + 2 * g[1] * v[0] * v[1] + g[2] * v[1] * v[1];
    c = uv / sqrt(uu * vv);
    c = c > 1 ? 1 : c < -1 ? -1 : c;
    return acos(c) * (180 / CVM__PI);
}
