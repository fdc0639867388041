/* rng.c - the per-handle deterministic random stream (xoshiro256**, Blackman & Vigna),
 * and the normal and Levy variates the cuckoo searches draw from it. */
#include <math.h>

#include "common_internal.h"

static uint64_t splitmix64(uint64_t *x)
{
    uint64_t z = (*x += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

void cvm__rng_seed(cvm__rng *r, uint64_t seed)
{
    int i;
    for (i = 0; i < 4; i++)
        r->s[i] = splitmix64(&seed);
}

static uint64_t rotl(uint64_t x, int k)
{
    return (x << k) | (x >> (64 - k));
}

uint64_t cvm__rng_next(cvm__rng *r)
{
    uint64_t *s = r->s;
    uint64_t result = rotl(s[1] * 5, 7) * 9;
    uint64_t t = s[1] << 17;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = rotl(s[3], 45);
    return result;
}

uint64_t cvm__rng_below(cvm__rng *r, uint64_t n)
{
    uint64_t lim, x;
    if (n <= 1)
        return 0;
    lim = (uint64_t)-1 - ((uint64_t)-1) % n;
    do {
        x = cvm__rng_next(r);
    } while (x >= lim);
    return x % n;
}

double cvm__rng_uniform(cvm__rng *r)
{
    return (double)(cvm__rng_next(r) >> 11) * (1.0 / 9007199254740992.0);
}

double cvm__rng_gauss(cvm__rng *r)
{
    double u1 = cvm__rng_uniform(r), u2 = cvm__rng_uniform(r);
    return sqrt(-2.0 * log(1.0 - u1)) * cos(6.283185307179586 * u2);
}

double cvm__rng_levy(cvm__rng *r)
{
    /* Mantegna's algorithm for beta = 1.5: sigma_u, then u / |v|^(1 / beta) */
    const double sigma = 0.69657450255769682;
    double uu = cvm__rng_gauss(r) * sigma, vv = fabs(cvm__rng_gauss(r));
    return uu / pow(vv > 1e-300 ? vv : 1e-300, 1.0 / 1.5);
}
