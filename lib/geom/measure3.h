/*
 * measure3.h - measures of a tetrahedron (floating point; the exact
 * predicates are in geom_internal.h): volume, dihedral angles, circumcentre
 * and power vertex, radius-edge ratio.
 */
#ifndef CVM_GEOM_MEASURE3_H
#define CVM_GEOM_MEASURE3_H

/* Squared distance between 3D points. */
static inline double cvm__dist2_3(const double *a, const double *b)
{
    double x = a[0] - b[0], y = a[1] - b[1], z = a[2] - b[2];
    return x * x + y * y + z * z;
}

/* Signed volume of (a, b, c, d): > 0 when cvm__orient3d(a, b, c, d) > 0. */
double cvm__tet_volume(const double *a, const double *b, const double *c, const double *d);
/* The six dihedral angles of (a, b, c, d), degrees, at the edges ab, ac, ad,
 * bc, bd, cd; min and max into lo, hi. A flat tetrahedron gives 0 and 180. */
void cvm__tet_dihedral_range_deg(const double *a, const double *b, const double *c,
                                 const double *d, double *lo, double *hi);
/* The six dihedral angles, degrees, at the edges ab, ac, ad, bc, bd, cd. */
void cvm__tet_dihedrals_deg(const double *a, const double *b, const double *c, const double *d,
                            double out[6]);
/* The point whose power distance |x - p|^2 - w is the same to the four
 * weighted corners (the circumcentre when every weight is 0) into o; 0, or -1
 * when the tetrahedron is flat (o unset). w may be NULL (all 0). */
int cvm__tet_power_centre(const double *a, const double *b, const double *c, const double *d,
                          const double *w, double *o);
/* Circumcircle of the triangle (a, b, c) in space: centre into c_out, squared
 * radius into *r2, and the unit normal -(b - a) x (c - a) / |.| into n (into
 * the domain for a surface triangle whose right-hand normal points out).
 * Nothing is checked: a flat triangle gives inf or NaN. */
void cvm__tri3_circle(const double *a, const double *b, const double *c, double *c_out,
                      double *r2, double *n);
/* Circumradius / shortest edge; inf for a flat tetrahedron. */
double cvm__tet_radius_edge(const double *a, const double *b, const double *c, const double *d);

#endif
