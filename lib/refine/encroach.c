/* encroach.c - which subsegments a point encroaches: diametral circle or lens tests and the queues they feed. */
#include "refine_internal.h"

/*
 * Encroachment is a quality decision, not a topological one: it decides
 * whether a segment is split before a point is inserted, never whether the
 * mesh is valid. A floating dot product is therefore enough; an answer that
 * rounding flips near the circle splits a segment a little early or late.
 * Circle: angle apb > 90 degrees (dot < 0). Lens (Shewchuk): angle apb >=
 * 180 - 2 x min angle, i.e. dot < 0 and dot^2 >= cos^2(2 theta) |pa|^2 |pb|^2.
 */
int cvm__rf_encroaches(const cvm__refiner *R, const double *a, const double *b, const double *p)
{
    double ax = a[0] - p[0], ay = a[1] - p[1], bx = b[0] - p[0], by = b[1] - p[1];
    double dot = ax * bx + ay * by;
    if (!(dot < 0))
        return 0;
    if (!R->p->lens)
        return 1;
    return dot * dot >= R->lens_cos2 * (ax * ax + ay * ay) * (bx * bx + by * by);
}

static const double *enc_pt(const cvm__refiner *R, int32_t v)
{
    return R->T->xy + 2 * (size_t)v;
}

/* Queue edge j of t if it is a subsegment encroached by the apex of t. */
static cvm_status enc_test_edge(cvm__refiner *R, int32_t t, int j)
{
    const cvm__tri2 *T = R->T;
    const int32_t *tv = T->tv + 3 * (size_t)t;
    int32_t seg = T->te[3 * (size_t)t + (size_t)j];
    int32_t a = tv[(j + 1) % 3], b = tv[(j + 2) % 3];
    if (seg < 0)
        return CVM_OK;
    if (!cvm__rf_encroaches(R, enc_pt(R, a), enc_pt(R, b), enc_pt(R, tv[j])))
        return CVM_OK;
    return cvm__rf_segq_push(R, a, b, seg);
}

cvm_status cvm__rf_queue_encroached_star(cvm__refiner *R, int32_t v)
{
    const cvm__tri2 *T = R->T;
    size_t n = cvm__rf_star(R, v), k;
    cvm_status s;
    if (n == 0)
        return cvm__nomem(R->ctx);
    for (k = 0; k < n; k++) {
        int32_t t = R->star[k];
        int j;
        if (!cvm__tri2_in_domain(T, t))
            continue;
        /* every edge of a triangle around v: the one opposite v (apex v) and the
         * two at v (apex the third vertex) */
        for (j = 0; j < 3; j++)
            if ((s = enc_test_edge(R, t, j)))
                return s;
    }
    return CVM_OK;
}

cvm_status cvm__rf_queue_encroached_all(cvm__refiner *R)
{
    const cvm__tri2 *T = R->T;
    size_t t;
    int j;
    cvm_status s;
    for (t = 0; t < T->nt; t++) {
        if (!cvm__tri2_in_domain(T, (int32_t)t))
            continue;
        for (j = 0; j < 3; j++)
            if ((s = enc_test_edge(R, (int32_t)t, j)))
                return s;
    }
    return CVM_OK;
}

static cvm_status enc_push(cvm__refiner *R, int32_t **arr, size_t *cap, size_t n, int32_t val)
{
    if (n >= *cap && cvm__grow(R->ctx, (void **)arr, cap, n + 1, sizeof(int32_t)))
        return cvm__nomem(R->ctx);
    (*arr)[n] = val;
    return CVM_OK;
}

/* Depth-first search of the Bowyer-Watson cavity of v from t0 with the exact
 * in-circle test; a constrained edge bounds it, and x's encroachment of it is
 * recorded. Scratch flag CVM__TF_MARK2 is cleared before returning. */
cvm_status cvm__rf_cavity_encroached(cvm__refiner *R, int32_t v, int32_t t0)
{
    cvm__tri2 *T = R->T;
    const double *x = enc_pt(R, v);
    size_t ncav = 0, top = 0, i;
    cvm_status s = CVM_OK;
    R->nenc = 0;
    if ((s = enc_push(R, &R->cav, &R->cap_cav, ncav++, t0)))
        return s;
    /* t0 contains x, so it is in the cavity whatever the in-circle test says */
    T->tf[t0] |= CVM__TF_MARK2;
    while (top < ncav && !s) {
        int32_t t = R->cav[top++];
        int j;
        for (j = 0; j < 3 && !s; j++) {
            size_t h = 3 * (size_t)t + (size_t)j;
            int32_t nb = T->tn[h] / 3, seg = T->te[h];
            if (seg >= 0) {
                int32_t a = T->tv[3 * (size_t)t + (size_t)(j + 1) % 3];
                int32_t b = T->tv[3 * (size_t)t + (size_t)(j + 2) % 3];
                if (cvm__rf_encroaches(R, enc_pt(R, a), enc_pt(R, b), x) &&
                    !(s = enc_push(R, &R->enc, &R->cap_enc, R->nenc, a)) &&
                    !(s = enc_push(R, &R->enc, &R->cap_enc, R->nenc + 1, b)) &&
                    !(s = enc_push(R, &R->enc, &R->cap_enc, R->nenc + 2, seg)))
                    R->nenc += 3;
                continue;
            }
            if ((T->tf[nb] & CVM__TF_MARK2) || !cvm__tri2_in_domain(T, nb))
                continue;
            if (cvm__tri2_conflict(T, nb, v) > 0 &&
                !(s = enc_push(R, &R->cav, &R->cap_cav, ncav, nb))) {
                T->tf[nb] |= CVM__TF_MARK2;
                ncav++;
            }
        }
    }
    for (i = 0; i < ncav; i++)
        T->tf[R->cav[i]] &= (uint8_t)~CVM__TF_MARK2;
    R->ncav = s ? 0 : ncav;
    R->nenc /= 3;
    return s;
}
