/* SPDX-License-Identifier: MIT */
/* world_fixture.h - what the world's unit tests share: a seeded
 * splitmix64 stream and a world in malloc'd memory (include after check.h
 * and collide2d_world.h, once per test program). */
#ifndef C2D_WORLD_FIXTURE_H
#define C2D_WORLD_FIXTURE_H

#include <stdlib.h>

static uint64_t rng_state;
static inline double uniform(void) /* splitmix64 -> [-1, 1) */
{
    uint64_t z = (rng_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return (double)(z >> 11) * 0x1p-52 - 1.0;
}

/* A world for d in fresh memory (*mem, for the caller to free). */
static inline c2d_world *new_world(const c2d_world_desc *d, void **mem)
{
    size_t bytes = c2d_world_bytes(d);
    c2d_world *w = NULL;
    assert_true(bytes > 0);
    *mem = malloc(bytes);
    assert_non_null(*mem);
    assert_status(c2d_world_init(&w, *mem, bytes, d), C2D_OK);
    return w;
}

#endif
