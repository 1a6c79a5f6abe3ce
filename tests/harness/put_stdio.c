/* SPDX-License-Identifier: MIT */
/* put_stdio.c - the shared helper's output on a host: standard output.
 * (On a microcontroller tests/mcu/main.c supplies c2d_put.) */
#include <stdio.h>

#include "harness.h"

void c2d_put(const char *s) { (void)fputs(s, stdout); }
