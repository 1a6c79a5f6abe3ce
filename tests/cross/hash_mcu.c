/* SPDX-License-Identifier: MIT */
/* hash_mcu.c - the determinism hash on a microcontroller: the cases and
 * hashes of tests/build/hash_cases.c (the host's, bit for bit), printed
 * through the semihosting console as the host's hash_vectors prints them,
 * "<target>: <variant> hash H", for the variants compiled in (C2D_NO_* as
 * the target's library), the world's if compiled in ("world-portable"
 * only, with 4-byte pointers), then the models' hashes ("model-inputs",
 * "rough-double" ...) for those compiled in.  tests/cross/cross.sh
 * compares them with x86-64.
 * The last line is "<target>: 1 passed, 0 failed" once the run completed. */
#include "collide2d.h"
#include "harness.h"
#include "hash_cases.h"
#include "mcu.h"

#ifndef C2D_MCU_NAME
#define C2D_MCU_NAME "mcu"
#endif

/* The shared helper's output (tests/harness/harness.h): the console. */
void c2d_put(const char *s) { c2d_mcu_puts(s); }

/* "<target>: <what> hash H" (what: a variant or model, "inputs",
 * "model-inputs", "N cases," or "N model cases, models"). */
static void put_hash(const char *what, long cases, uint64_t v)
{
    char hex[17];
    c2d_hv_hex(v, hex);
    c2d_put(C2D_MCU_NAME ": ");
    if (cases >= 0) c2d_put_int(cases);
    c2d_put(what);
    c2d_put(" hash ");
    c2d_put(hex);
    c2d_put("\n");
}

int main(void)
{
    static c2d_hv_hash h;
    static c2d_hv_models_hash m;
    static c2d_hv_world_hash wh;
    c2d_tally tally = {1, 0};
    int v;
    c2d_hv_run(C2D_HV_DEFAULT_COUNT, &h, NULL);
    put_hash("inputs", -1, h.inputs);
    for (v = 0; v < C2D_HV_VARIANTS; v++)
        if (h.present[v]) put_hash(c2d_hv_name[v], -1, h.variant[v]);
    put_hash(" cases,", (long)C2D_HV_DEFAULT_COUNT, c2d_hv_combined(&h));
    c2d_hv_run_world(&wh, NULL); /* none without double (C2D_NO_DOUBLE) */
    /* "world" hashes c2d_world_bytes, which 4-byte pointers make smaller:
     * only "world-portable" is comparable with x86-64's there. */
    if (wh.present && sizeof(void *) == 8) put_hash("world", -1, wh.hash);
    if (wh.present) put_hash("world-portable", -1, wh.portable);
    c2d_hv_run_models(C2D_HV_MODELS_DEFAULT_COUNT, &m, NULL);
    put_hash("model-inputs", -1, m.inputs);
    for (v = 0; v < C2D_HV_MODELS; v++)
        if (m.present[v]) put_hash(c2d_hv_model_name[v], -1, m.model[v]);
    put_hash(" model cases, models", (long)C2D_HV_MODELS_DEFAULT_COUNT, c2d_hv_models_combined(&m));
    c2d_put_tally(C2D_MCU_NAME, &tally);
    c2d_mcu_exit(0);
}
