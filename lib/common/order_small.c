/* order_small.c - a stable argsort of a few values spread through an array of structs. */
#include "common_internal.h"

static double order_key(const double *key, size_t stride, int i)
{
    return *(const double *)(const void *)((const char *)key + (size_t)i * stride);
}

void cvm__order_small(const double *key, size_t stride, int *order, int n)
{
    int i, j;
    for (i = 0; i < n; i++)
        order[i] = i;
    for (i = 1; i < n; i++) {
        int k = order[i];
        double fk = order_key(key, stride, k);
        for (j = i; j > 0 && (order_key(key, stride, order[j - 1]) > fk ||
                              (order_key(key, stride, order[j - 1]) == fk && order[j - 1] > k));
             j--)
            order[j] = order[j - 1];
        order[j] = k;
    }
}
