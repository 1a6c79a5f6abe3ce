/* SPDX-License-Identifier: MIT */
/* hash_vectors.c - hash the bits of every output and status of the library
 * over a fixed, generated set of cases, for tests/build/determinism.sh (the
 * library built by gcc and clang at several optimisation levels) and
 * tests/cross/cross.sh (the host's values against other architectures).
 *
 * The cases and the hashes are tests/build/hash_cases.c, shared with the
 * microcontroller driver (tests/cross/hash_mcu.c); this file is the host's
 * front end.  Standalone on purpose (no GMP, no cmocka).
 * Usage: hash_vectors [COUNT [DUMP]]  prints the inputs' hash, one hash per
 * variant compiled in, and "hash_vectors: COUNT cases, hash H" (all
 * variants together); then, over the models' own 20,000 cases, their
 * inputs' hash ("model-inputs"), one hash per model and variant
 * ("rough-double" ...) and "hash_vectors: N model cases, models hash H".
 * The world's hashes ("world hash H", "world-portable hash H": without its
 * memory size, and its number of events) come between
 * the two, when the world is compiled in: the last three lines stay the
 * models' (accel-double, accel-float, models hash).
 * DUMP receives the raw bytes hashed, to locate differences (cmp -l).  Bad arguments: a message and exit status 2. */
#include "collide2d.h"
#include "hash_cases.h"

#include <stdio.h>
#include <stdlib.h>

static FILE *dump;

static void to_dump(const void *p, size_t n)
{
    if (dump != NULL && fwrite(p, 1, n, dump) != n) {
        perror("hash_vectors: dump");
        exit(2);
    }
}

int main(int argc, char **argv)
{
    unsigned long count = C2D_HV_DEFAULT_COUNT;
    c2d_hv_hash h;
    c2d_hv_models_hash m;
    c2d_hv_world_hash wh;
    char hex[17];
    int v;
    if (argc > 1) {
        char *end;
        count = strtoul(argv[1], &end, 10);
        if (end == argv[1] || *end != '\0' || argv[1][0] == '-') {
            fprintf(stderr, "usage: hash_vectors [COUNT [DUMP]]\n");
            return 2;
        }
    }
    if (argc > 3) {
        fprintf(stderr, "usage: hash_vectors [COUNT [DUMP]]\n");
        return 2;
    }
    if (argc > 2 && (dump = fopen(argv[2], "wb")) == NULL) {
        perror(argv[2]);
        return 2;
    }
    c2d_hv_run(count, &h, dump != NULL ? to_dump : NULL);
    c2d_hv_hex(h.inputs, hex);
    printf("hash_vectors: inputs hash %s\n", hex);
    for (v = 0; v < C2D_HV_VARIANTS; v++) {
        if (!h.present[v]) continue;
        c2d_hv_hex(h.variant[v], hex);
        printf("hash_vectors: %s hash %s\n", c2d_hv_name[v], hex);
    }
    c2d_hv_hex(c2d_hv_combined(&h), hex);
    printf("hash_vectors: %lu cases, hash %s\n", count, hex);
    c2d_hv_run_world(&wh, dump != NULL ? to_dump : NULL);
    if (wh.present) {
        c2d_hv_hex(wh.hash, hex);
        printf("hash_vectors: world hash %s\n", hex);
        c2d_hv_hex(wh.portable, hex);
        printf("hash_vectors: world-portable hash %s\n", hex);
        printf("hash_vectors: world scenes, %lu events\n", wh.events);
    }
    c2d_hv_run_models(C2D_HV_MODELS_DEFAULT_COUNT, &m, dump != NULL ? to_dump : NULL);
    c2d_hv_hex(m.inputs, hex);
    printf("hash_vectors: model-inputs hash %s\n", hex);
    for (v = 0; v < C2D_HV_MODELS; v++) {
        if (!m.present[v]) continue;
        c2d_hv_hex(m.model[v], hex);
        printf("hash_vectors: %s hash %s\n", c2d_hv_model_name[v], hex);
    }
    c2d_hv_hex(c2d_hv_models_combined(&m), hex);
    printf("hash_vectors: %lu model cases, models hash %s\n", C2D_HV_MODELS_DEFAULT_COUNT, hex);
    if (dump != NULL && fclose(dump) != 0) {
        perror(argv[2]);
        return 2;
    }
    return 0;
}
