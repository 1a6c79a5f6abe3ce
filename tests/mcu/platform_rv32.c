/* SPDX-License-Identifier: MIT */
/* RV32 platform for the MCU harness: picolibc's semihosting crt0 has already
 * set up the stack, .data and .bss, and its exit() is the semihosting exit,
 * so QEMU exits with the harness's status.  Output goes through a host file
 * opened as ":tt" (the host's stdout, as on Cortex-M), not picolibc's stdout,
 * which QEMU sends to stderr. */
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "mcu.h"

void c2d_mcu_puts(const char *s)
{
    static int console = -1;
    if (console < 0) console = open(":tt", O_WRONLY | O_CREAT | O_TRUNC); /* mode "w" */
    (void)write(console, s, strlen(s));
}

void c2d_mcu_exit(int status)
{
    exit(status);
}

/* picolibc's crt0 owns the stack; nothing painted it. */
long c2d_mcu_stack_peak(void)
{
    return -1;
}
