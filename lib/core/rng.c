/* xoshiro128** (Blackman & Vigna), seeded through splitmix64. The state
 * lives in the handle that draws from it, so runs are reproducible and
 * handles never share a stream. */
#include "core/core_internal.h"

static uint64_t splitmix64(uint64_t *x)
{
    uint64_t z = (*x += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

void ms_rng_seed(ms_rng *r, uint64_t seed)
{
    uint64_t x = seed;
    uint64_t a = splitmix64(&x), b = splitmix64(&x);
    r->s[0] = (uint32_t)a;
    r->s[1] = (uint32_t)(a >> 32);
    r->s[2] = (uint32_t)b;
    r->s[3] = (uint32_t)(b >> 32);
    if (!(r->s[0] | r->s[1] | r->s[2] | r->s[3]))
        r->s[0] = 1; /* the all-zero state is a fixed point */
}

static uint32_t rotl(uint32_t x, int k)
{
    return (x << k) | (x >> (32 - k));
}

uint32_t ms_rng_u32(ms_rng *r)
{
    uint32_t *s = r->s;
    uint32_t result = rotl(s[1] * 5u, 7) * 9u;
    uint32_t t = s[1] << 9;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = rotl(s[3], 11);
    return result;
}

float ms_rng_uniform(ms_rng *r)
{
    return (float)(ms_rng_u32(r) >> 8) * (1.0f / 16777216.0f);
}

long ms_rng_poisson(ms_rng *r, double mean)
{
    if (!(mean > 0))
        return 0;
    if (mean > 64) {
        /* Normal approximation (Box-Muller) for large means: the count only
         * sets how many drops fall, so its tail shape does not matter. */
        double u1 = ((double)ms_rng_u32(r) + 1.0) / 4294967296.0;
        double u2 = (double)ms_rng_u32(r) / 4294967296.0;
        double z = sqrt(-2.0 * log(u1)) * cos(6.283185307179586 * u2);
        double k = floor(mean + sqrt(mean) * z + 0.5);
        return k < 0 ? 0 : (long)k;
    }
    /* Knuth: multiply uniforms until the product drops below e^-mean. */
    double limit = exp(-mean), p = 1.0;
    long k = -1;
    do {
        ++k;
        p *= ((double)ms_rng_u32(r) + 0.5) / 4294967296.0;
    } while (p > limit);
    return k;
}
