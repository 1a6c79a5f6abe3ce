/* SPDX-License-Identifier: MIT */
/* consumer.c - the smallest program a user of collide2d writes, built by
 * tests/consumers/run.sh through each way of picking the library up
 * (CMake find_package, add_subdirectory, FetchContent; pkg-config).  It
 * checks the README's two-body example and the library's version against
 * the header it was compiled with, and prints one pass line.
 * Usage: consumer   (C2D_CONSUMER_HOW names the path at compile time) */
#include <stdio.h>

#include "collide2d.h"

#ifndef C2D_CONSUMER_HOW
#define C2D_CONSUMER_HOW "unnamed"
#endif

int main(void)
{
    c2d_body a = {{0.0, 0.0}, {1.0, 0.0}, 1.0};
    c2d_body b = {{1.0, 1.0}, {0.0, 0.0}, 1.0};
    c2d_status s = c2d_collide(&a, &b, 1.0);
    if (s != C2D_OK || a.vel.x != 0.5 || a.vel.y != -0.5 || b.vel.x != 0.5 || b.vel.y != 0.5) {
        fprintf(stderr, "consumer %s: FAILED: c2d_collide gave %s, a.vel (%g, %g), b.vel (%g, %g)\n",
                C2D_CONSUMER_HOW, c2d_status_string(s), a.vel.x, a.vel.y, b.vel.x, b.vel.y);
        return 1;
    }
    if (c2d_version() != C2D_VERSION) {
        fprintf(stderr, "consumer %s: FAILED: library version %ld, header %ld\n", C2D_CONSUMER_HOW,
                c2d_version(), (long)C2D_VERSION);
        return 1;
    }
    printf("consumer %s: collide2d %d.%d.%d, c2d_collide ok: passed\n", C2D_CONSUMER_HOW, C2D_VERSION_MAJOR,
           C2D_VERSION_MINOR, C2D_VERSION_PATCH);
    return 0;
}
