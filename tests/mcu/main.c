/* SPDX-License-Identifier: MIT */
/* MCU test harness: runs the library's shared test vectors
 * (tests/vectors/vectors.c, the tables the host cmocka tests use, checked by
 * the same code: tests/vectors/check_template.h, and check_models.h for the
 * rough-contact and accelerated time-of-impact tables) on a bare-metal
 * target.
 * Each failure is printed; the last line is "<target>: N passed, N failed"
 * and the exit status (through semihosting, so QEMU's own) is non-zero on
 * any failure.  No C library, no allocation: the platform supplies mcu.h. */
#include <stddef.h>
#include <stdint.h>
#include "collide2d.h"
#include "check_vectors.h"
#include "mcu.h"

#ifndef C2D_MCU_NAME
#define C2D_MCU_NAME "mcu"
#endif

/* The shared helper's output (tests/harness/harness.h): the console. */
void c2d_put(const char *s) { c2d_mcu_puts(s); }

int main(void)
{
    c2d_tally tally = {0, 0};
    long peak;
    c2d_put(C2D_MCU_NAME ": collide2d ");
    c2d_put_int(c2d_version());
    c2d_put(", vectors:");
#ifndef C2D_NO_DOUBLE
    c2d_put(" double");
#endif
#ifndef C2D_NO_FLOAT
    c2d_put(" float");
#endif
#ifndef C2D_NO_FIXED
    c2d_put(" Q16.16");
#endif
    c2d_put("\n");
#ifndef C2D_NO_DOUBLE
    c2d_check_vectors_d(&tally);
    c2d_check_rough_vectors_d(&tally);
    c2d_check_accel_vectors_d(&tally);
#endif
#ifndef C2D_NO_FLOAT
    c2d_check_vectors_f(&tally);
    c2d_check_rough_vectors_f(&tally);
    c2d_check_accel_vectors_f(&tally);
#endif
#ifndef C2D_NO_FIXED
    c2d_check_vectors_x(&tally);
#endif
    if (tally.passed + tally.failed == 0) {
        c2d_put("FAIL no vectors compiled in\n");
        tally.failed = 1;
    }
    peak = c2d_mcu_stack_peak();
    if (peak >= 0) {
        c2d_put(C2D_MCU_NAME ": stack peak ");
        c2d_put_int(peak);
        c2d_put(" bytes (harness included)\n");
    }
    c2d_put_tally(C2D_MCU_NAME, &tally);
    c2d_mcu_exit(c2d_tally_status(&tally));
}
