/*
** rng.h: the seeded pseudo-random generator of the polygon generators.
**
** xoshiro256** (Blackman and Vigna, 2018) seeded through splitmix64.  The
** state is a plain value owned by the caller (no globals), so two streams
** never interfere and the same (seed, stream) always yields the same numbers
** on every platform: only 64-bit integer arithmetic and one exact conversion
** to double are involved.
**
** Streams: a generator derives independent streams from one user seed with
** wk_rng_seed(&g, seed, stream); geometry and weights use different streams,
** so choosing another weight mode never moves a vertex.
**
** Invariant: the state is never all zero (splitmix64 is a bijection of a
** counter, so four consecutive outputs cannot all be zero).
*/
#ifndef WK_RNG_H
#define WK_RNG_H
#include <stdint.h>

typedef struct wk_rng {
    uint64_t s[4];
} wk_rng;

/* splitmix64: advances *x and returns the next output. */
static inline uint64_t wk_splitmix64(uint64_t *x) {
    uint64_t z = (*x += 0x9E3779B97F4A7C15u);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}

/* Seed g for (seed, stream).  Different streams of one seed are unrelated. */
static inline void wk_rng_seed(wk_rng *g, uint64_t seed, uint64_t stream) {
    /* Mix the stream in through one splitmix step of its own, so that
    ** (seed, stream) and (seed + 1, stream - 1) do not share a state. */
    uint64_t t = stream;
    uint64_t x = seed ^ wk_splitmix64(&t);
    for (int i = 0; i < 4; i++) g->s[i] = wk_splitmix64(&x);
}

static inline uint64_t wk_rng_rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

/* Next 64 random bits (xoshiro256**). */
static inline uint64_t wk_rng_next(wk_rng *g) {
    uint64_t *s = g->s;
    uint64_t result = wk_rng_rotl(s[1] * 5, 7) * 9;
    uint64_t t = s[1] << 17;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = wk_rng_rotl(s[3], 45);
    return result;
}

/* Uniform double in [0, 1): the top 53 bits, converted exactly. */
static inline double wk_rng_unit(wk_rng *g) {
    return (double)(wk_rng_next(g) >> 11) * 0x1.0p-53;
}

/* Uniform double in [a, b) (a <= b). */
static inline double wk_rng_range(wk_rng *g, double a, double b) {
    return a + (b - a) * wk_rng_unit(g);
}

/* Uniform integer in [0, bound), bound >= 1, without modulo bias: draws
** below 2^64 mod bound are rejected (fewer than one in two draws). */
static inline uint64_t wk_rng_below(wk_rng *g, uint64_t bound) {
    uint64_t threshold = (0 - bound) % bound; /* 2^64 mod bound */
    for (;;) {
        uint64_t x = wk_rng_next(g);
        if (x >= threshold) return x % bound;
    }
}

#endif
