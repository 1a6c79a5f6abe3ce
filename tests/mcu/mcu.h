/* SPDX-License-Identifier: MIT */
/* The two things the MCU test harness needs from a bare-metal platform: a
 * console and a way to end the run with a status the emulator passes on as
 * its own exit code (semihosting).  startup_arm.c provides them for
 * Cortex-M, platform_rv32.c (on picolibc's semihosting crt0) for RV32. */
#ifndef C2D_MCU_H
#define C2D_MCU_H

void c2d_mcu_puts(const char *s);
void c2d_mcu_exit(int status) __attribute__((noreturn));
/* Deepest stack use so far in bytes (painted-stack high-water mark), or -1
 * where the platform does not measure it. */
long c2d_mcu_stack_peak(void);

#endif
