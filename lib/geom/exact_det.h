/* exact_det.h - exact determinants of raw coordinates: the last stage of every predicate. */
#ifndef CVM_GEOM_EXACT_DET_H
#define CVM_GEOM_EXACT_DET_H

/*
 * All of these compute from the untranslated input doubles with expansion
 * arithmetic only, so they are exact as long as nothing overflows or underflows
 * (callers rescale first: cvm__rescale_exponent). They are slow; the predicates
 * reach them only after their filter and adaptive stages failed. The *_exact
 * functions return a double with the sign of the exact determinant (the most
 * significant component of the exact expansion); the tests call them directly.
 */

/* h[0..11] = det [px py 1; qx qy 1; rx ry 1] (only x, y are read). */
int cvm__orient2d_raw(const double *p, const double *q, const double *r, double *h);

/* h[0..95] = det [p 1; q 1; r 1; s 1] for 3D points = det [p-s; q-s; r-s]. */
int cvm__orient3d_raw(const double *p, const double *q, const double *r, const double *s,
                      double *h);

/* h = sign * (|p|^2 - w) * t for a point p of dim 2 or 3, sign = +1 or -1,
 * tlen <= 96; h needs room for 4 * dim * tlen + 2 * tlen components. */
int cvm__lift_scale(int tlen, const double *t, const double *p, int dim, double w, double sign,
                    double *h);

double cvm__orient2d_exact(const double *a, const double *b, const double *c);
double cvm__incircle_exact(const double *a, const double *b, const double *c, const double *d);
double cvm__power2d_exact(const double *a, const double *b, const double *c, const double *d,
                          double wa, double wb, double wc, double wd);
double cvm__orient3d_exact(const double *a, const double *b, const double *c, const double *d);
double cvm__insphere_exact(const double *a, const double *b, const double *c, const double *d,
                           const double *e);
double cvm__power3d_exact(const double *a, const double *b, const double *c, const double *d,
                          const double *e, double wa, double wb, double wc, double wd, double we);

#endif
