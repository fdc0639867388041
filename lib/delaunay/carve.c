/* carve.c - flood fills bounded by constrained edges: removing the exterior and holes, assigning regional attributes. */
#include "delaunay_internal.h"
#include "tri2_store.h"

/* Append t to the flood list T->stack[0..*n) and mark it CVM__TF_MARK2. */
static cvm_status flood_push(cvm__tri2 *T, size_t *n, int32_t t)
{
    if (*n >= T->cap_stack &&
        cvm__grow(T->ctx, (void **)&T->stack, &T->cap_stack, *n + 1, sizeof(int32_t)))
        return CVM_E_NOMEM;
    T->tf[t] |= CVM__TF_MARK2;
    T->stack[(*n)++] = t;
    return CVM_OK;
}

/* Visit every triangle reachable from the seeds without crossing a
 * constrained edge (or, with op 1, entering a triangle that is OUT or a
 * ghost) and not already carrying CVM__TF_MARK2, and apply op: 0 = mark OUT,
 * 1 = set attribute value. The visited triangles stay on T->stack[0..*n_out)
 * with CVM__TF_MARK2 set; *removed_out (may be NULL) receives how many of them
 * were in the domain before. The list is read in order rather than popped, so
 * the marks can be cleared in time proportional to the flood. */
static cvm_status flood_marked(cvm__tri2 *T, const int32_t *seeds, size_t nseeds, int op,
                               double value, size_t *n_out, size_t *removed_out)
{
    size_t n = 0, head, i, removed = 0;
    cvm_status s = CVM_OK;
    for (i = 0; i < nseeds && !s; i++) {
        int32_t t = seeds[i];
        if (t < 0 || (T->tf[t] & CVM__TF_MARK2))
            continue;
        if (op == 1 && (T->tf[t] & CVM__TF_OUT))
            continue;
        s = flood_push(T, &n, t);
    }
    for (head = 0; head < n && !s; head++) {
        int32_t t = T->stack[head];
        int j;
        if (op == 0) {
            removed += (size_t)cvm__tri2_in_domain(T, t);
            T->tf[t] |= CVM__TF_OUT;
        } else if (T->ta) {
            T->ta[t] = value;
        }
        for (j = 0; j < 3 && !s; j++) {
            size_t h = 3 * (size_t)t + j;
            int32_t u = T->tn[h] / 3;
            if (T->te && T->te[h] >= 0)
                continue;
            if (T->tf[u] & CVM__TF_MARK2)
                continue;
            if (op == 1 && ((T->tf[u] & CVM__TF_OUT) || cvm__tri2_is_ghost(T, u)))
                continue;
            s = flood_push(T, &n, u);
        }
    }
    *n_out = n;
    if (removed_out)
        *removed_out = removed;
    return s;
}

static void flood_unmark(cvm__tri2 *T, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        T->tf[T->stack[i]] &= (uint8_t)~CVM__TF_MARK2;
}

static cvm_status flood(cvm__tri2 *T, const int32_t *seeds, size_t nseeds, int op, double value)
{
    size_t n = 0;
    cvm_status s = flood_marked(T, seeds, nseeds, op, value, &n, NULL);
    flood_unmark(T, n);
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

cvm_status cvm__tri2_flood_out_more(cvm__tri2 *T, int32_t seed, size_t *visited_out,
                                    size_t *removed_out)
{
    return flood_marked(T, &seed, 1, 0, 0.0, visited_out, removed_out);
}

void cvm__tri2_clear_mark2(cvm__tri2 *T)
{
    size_t t;
    for (t = 0; t < T->nt; t++)
        T->tf[t] &= (uint8_t)~CVM__TF_MARK2;
}

cvm_status cvm__tri2_flood_attribute(cvm__tri2 *T, int32_t seed, double value)
{
    cvm_status s = cvm__tri2_enable_attributes(T);
    if (s)
        return s;
    return flood(T, &seed, 1, 1, value);
}
