/* SPDX-License-Identifier: MIT */
// The header from C++: extern "C" linkage, no C-only constructs.
#include "collide2d.h"

#include <cstdio>

int main()
{
    c2d_body a = {{0.0, 0.0}, {1.0, 0.0}, 1.0};
    c2d_body b = {{1.0, 1.0}, {0.0, 0.0}, 1.0};
    if (c2d_collide(&a, &b, 1.0) != C2D_OK || a.vel.x != 0.5 || a.vel.y != -0.5) {
        std::fprintf(stderr, "cxx_smoke: wrong result\n");
        std::printf("cxx_smoke: 0 passed, 1 failed\n");
        return 1;
    }
    std::printf("cxx_smoke: 1 passed, 0 failed\n");
    return 0;
}
