/* dunavant.c - the choice of a symmetric Dunavant rule on the triangle by its degree. */
#include "quad_internal.h"
#include "dunavant_tables.h"

const double (*cvm__dunavant_rule(int deg, size_t *n_out, int *deg_out))[4]
{
    static const struct {
        int deg;
        size_t n;
        const double (*rule)[4];
    } rules[] = {
        {2, 3, cvm__dunavant_2},    {4, 6, cvm__dunavant_4},    {6, 12, cvm__dunavant_6},
        {8, 16, cvm__dunavant_8},   {10, 25, cvm__dunavant_10}, {12, 33, cvm__dunavant_12},
    };
    size_t k;
    for (k = 0; k < sizeof rules / sizeof rules[0]; k++)
        if (rules[k].deg >= deg) {
            *n_out = rules[k].n;
            *deg_out = rules[k].deg;
            return rules[k].rule;
        }
    *n_out = 0;
    *deg_out = 0;
    return NULL;
}
