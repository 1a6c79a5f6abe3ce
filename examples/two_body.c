/* SPDX-License-Identifier: MIT */
/* two_body.c - the README's example: two equal disks in an oblique elastic
 * impact (c2d_collide), then one of them against an immovable wall with
 * restitution 0.8 (c2d_collide_normal).  Prints each step and checks the
 * results the README states; exit status 1 if any differs.
 * Usage: two_body   (no arguments) */
#include <math.h> /* INFINITY */
#include <stdio.h>

#include "collide2d.h"

static int expect(const char *what, c2d_status s, const c2d_body *body, double vx, double vy)
{
    int ok = s == C2D_OK && body->vel.x == vx && body->vel.y == vy;
    printf("%-34s %-10s vel (%g, %g)%s\n", what, c2d_status_string(s), body->vel.x, body->vel.y,
           ok ? "" : "   <- expected ok and a different velocity");
    return ok;
}

int main(int argc, char **argv)
{
    c2d_body a = {{0.0, 0.0}, {1.0, 0.0}, 1.0}; /* position, velocity, mass */
    c2d_body b = {{1.0, 1.0}, {0.0, 0.0}, 1.0};
    c2d_body wall = {{2.0, 1.0}, {0.0, 0.0}, INFINITY}; /* immovable */
    c2d_vec2 towards_wall = {1.0, 0.0};                 /* from b towards the wall */
    c2d_status s;
    int ok = 1;
    (void)argv;
    if (argc > 1) {
        fprintf(stderr, "usage: two_body (no arguments)\n");
        return 2;
    }

    /* Equal masses, e = 1: the normal components (along (1, 1)) swap. */
    s = c2d_collide(&a, &b, 1.0);
    ok &= expect("c2d_collide, e = 1: a", s, &a, 0.5, -0.5);
    ok &= expect("c2d_collide, e = 1: b", s, &b, 0.5, 0.5);
    printf("momentum (%g, %g), energy %g: both as before\n", a.vel.x + b.vel.x, a.vel.y + b.vel.y,
           0.5 * (a.vel.x * a.vel.x + a.vel.y * a.vel.y + b.vel.x * b.vel.x + b.vel.y * b.vel.y));

    /* b hits the wall: the normal component reverses and is scaled by 0.8. */
    s = c2d_collide_normal(&b, &wall, towards_wall, 0.8);
    ok &= expect("c2d_collide_normal, e = 0.8: b", s, &b, -0.4, 0.5);

    /* Moving away from the wall now: nothing happens, nothing is written. */
    s = c2d_collide_normal(&b, &wall, towards_wall, 0.8);
    printf("%-34s %s\n", "again (receding):", c2d_status_string(s));
    ok &= s == C2D_SEPARATING;

    printf("two_body: %s\n", ok ? "passed" : "FAILED");
    return ok ? 0 : 1;
}
