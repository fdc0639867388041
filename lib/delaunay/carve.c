/* carve.c - flood fills bounded by constrained edges: removing the exterior and holes, assigning regional attributes. */
#include "delaunay_internal.h"
#include "tri2_store.h"

/* Visit every triangle reachable from the seeds without crossing a
 * constrained edge (or entering a triangle already OUT when skip_out), and
 * apply op: 0 = mark OUT, 1 = set attribute value. */
static cvm_status flood(cvm__tri2 *T, const int32_t *seeds, size_t nseeds, int op, double value)
{
    size_t n = 0, i;
    cvm_status s = CVM_OK;
    for (i = 0; i < nseeds; i++) {
        int32_t t = seeds[i];
        if (t < 0 || (T->tf[t] & CVM__TF_MARK2))
            continue;
        if (op == 1 && (T->tf[t] & CVM__TF_OUT))
            continue;
        if (n >= T->cap_stack &&
            cvm__grow(T->ctx, (void **)&T->stack, &T->cap_stack, n + 1, sizeof(int32_t))) {
            s = CVM_E_NOMEM;
            goto out;
        }
        T->tf[t] |= CVM__TF_MARK2;
        T->stack[n++] = t;
    }
    while (n) {
        int32_t t = T->stack[--n];
        int j;
        if (op == 0)
            T->tf[t] |= CVM__TF_OUT;
        else if (T->ta)
            T->ta[t] = value;
        for (j = 0; j < 3; j++) {
            size_t h = 3 * (size_t)t + j;
            int32_t u = T->tn[h] / 3;
            if (T->te && T->te[h] >= 0)
                continue;
            if (T->tf[u] & CVM__TF_MARK2)
                continue;
            if (op == 1 && ((T->tf[u] & CVM__TF_OUT) || cvm__tri2_is_ghost(T, u)))
                continue;
            if (n >= T->cap_stack &&
                cvm__grow(T->ctx, (void **)&T->stack, &T->cap_stack, n + 1, sizeof(int32_t))) {
                s = CVM_E_NOMEM;
                goto out;
            }
            T->tf[u] |= CVM__TF_MARK2;
            T->stack[n++] = u;
        }
    }
out:
    for (i = 0; i < T->nt; i++)
        T->tf[i] &= (uint8_t)~CVM__TF_MARK2;
    return s;
}

cvm_status cvm__tri2_flood_out(cvm__tri2 *T, const int32_t *seeds, size_t nseeds, int exterior)
{
    cvm_status s;
    size_t t;
    if (exterior) {
        int32_t *g = NULL;
        size_t ng = 0, cap = 0;
        for (t = 0; t < T->nt; t++) {
            if (!cvm__tri2_is_live(T, (int32_t)t) || !cvm__tri2_is_ghost(T, (int32_t)t))
                continue;
            if (ng >= cap && cvm__grow(T->ctx, (void **)&g, &cap, ng + 1, sizeof(int32_t))) {
                cvm__free(T->ctx, g);
                return CVM_E_NOMEM;
            }
            g[ng++] = (int32_t)t;
        }
        s = flood(T, g, ng, 0, 0.0);
        cvm__free(T->ctx, g);
        if (s)
            return s;
    } else {
        /* ghosts are never part of the domain */
        for (t = 0; t < T->nt; t++)
            if (cvm__tri2_is_live(T, (int32_t)t) && cvm__tri2_is_ghost(T, (int32_t)t))
                T->tf[t] |= CVM__TF_OUT;
    }
    return flood(T, seeds, nseeds, 0, 0.0);
}

cvm_status cvm__tri2_flood_attribute(cvm__tri2 *T, int32_t seed, double value)
{
    cvm_status s = cvm__tri2_enable_attributes(T);
    if (s)
        return s;
    return flood(T, &seed, 1, 1, value);
}
