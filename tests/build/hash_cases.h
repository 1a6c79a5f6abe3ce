/* SPDX-License-Identifier: MIT */
/* hash_cases.h - the determinism hash: a fixed stream of generated cases run
 * through every entry point compiled in, and FNV-1a hashes of the bits of
 * every output and status, one per variant.
 *
 * Freestanding (no C library, no allocation: only the compiler's headers,
 * the library's, the shared harness and referee/rng.h), so the same code
 * runs on the host (tests/build/hash_vectors.c), on Linux targets under
 * qemu-user and on microcontrollers under QEMU (tests/cross/hash_mcu.c).
 * The case stream does not depend on which variants are compiled in, so a
 * float-only target's float hash is comparable with the host's.  Bytes are
 * hashed as they lie in memory: every target checked is little-endian. */
#ifndef C2D_HASH_CASES_H
#define C2D_HASH_CASES_H

#include <stddef.h>
#include <stdint.h>

#define C2D_HV_DEFAULT_COUNT 100000ul

enum { C2D_HV_DOUBLE, C2D_HV_FLOAT, C2D_HV_FIXED, C2D_HV_VARIANTS };

typedef struct c2d_hv_hash {
    uint64_t inputs;                    /* the generated cases themselves */
    uint64_t variant[C2D_HV_VARIANTS];  /* each variant's outputs and statuses */
    int present[C2D_HV_VARIANTS];       /* compiled in (C2D_NO_* not defined) */
} c2d_hv_hash;

/* The variants' names as printed: "double", "float", "Q16.16". */
extern const char *const c2d_hv_name[C2D_HV_VARIANTS];

/* Runs `count` cases.  sink, if not NULL, receives every run of bytes
 * hashed (to locate a difference between two targets with cmp -l). */
void c2d_hv_run(unsigned long count, c2d_hv_hash *h, void (*sink)(const void *p, size_t n));

/* The models (c2d_collide_rough and _normal, c2d_time_of_impact_accel), in
 * double and float, hashed apart from the variants above over their own
 * case stream, so the variants' recorded hashes do not move when models
 * are added: "rough-double", "rough-float", "accel-double", "accel-float". */
#define C2D_HV_MODELS_DEFAULT_COUNT 20000ul

enum { C2D_HV_ROUGH_DOUBLE, C2D_HV_ROUGH_FLOAT, C2D_HV_ACCEL_DOUBLE, C2D_HV_ACCEL_FLOAT, C2D_HV_MODELS };

typedef struct c2d_hv_models_hash {
    uint64_t inputs;                /* the generated model cases themselves */
    uint64_t model[C2D_HV_MODELS];  /* each model's outputs and statuses */
    int present[C2D_HV_MODELS];     /* its variant compiled in */
} c2d_hv_models_hash;

extern const char *const c2d_hv_model_name[C2D_HV_MODELS];

/* Runs `count` model cases (sink as for c2d_hv_run). */
void c2d_hv_run_models(unsigned long count, c2d_hv_models_hash *h, void (*sink)(const void *p, size_t n));

/* The event-driven world (collide2d_world.h), hashed apart from the above
 * over scenes of its own (hash_cases.c: walls with e < 1 and the collapse
 * rule, a periodic elastic gas, accelerations and timers whose callback
 * changes the motion among static segments and circles, kicks and a
 * removal between uneven slices): every event (kind, time, indices,
 * impulse), every status, and the final states and statistics, and the
 * world's size (c2d_world_bytes).  "world-portable" is the same without
 * the size, which depends on the pointer size: 32-bit targets (the
 * firmware) compare that one.  Not present (present 0) when the world is
 * compiled out (C2D_NO_WORLD, or C2D_NO_DOUBLE).  The expected value is in
 * docs/DETERMINISM.md's table ("world"): it moves whenever the world's
 * arithmetic or event order changes, by design. */
typedef struct c2d_hv_world_hash {
    uint64_t hash;          /* "world" */
    uint64_t portable;      /* "world-portable": without c2d_world_bytes */
    unsigned long events;   /* the events hashed, for the printout */
    int present;
} c2d_hv_world_hash;

void c2d_hv_run_world(c2d_hv_world_hash *h, void (*sink)(const void *p, size_t n));

/* One hash over the variants compiled in (FNV-1a of their hashes). */
uint64_t c2d_hv_combined(const c2d_hv_hash *h);

/* The same over the models compiled in. */
uint64_t c2d_hv_models_combined(const c2d_hv_models_hash *h);

/* 16 lower-case hex digits and a terminating NUL into out[17]. */
void c2d_hv_hex(uint64_t v, char out[17]);

#endif
