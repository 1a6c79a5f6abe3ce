/* SPDX-License-Identifier: MIT */
/* ball_in_box.c - a ball bouncing in a box: four immovable walls, each an
 * INFINITY-mass body met with c2d_collide_normal (restitution e).  The run
 * is event-driven: the next wall contact is found exactly in closed form,
 * the ball is moved there, and the wall's normal (pointing from the ball
 * towards the wall) resolves the impact.  Each bounce multiplies the normal
 * speed by e and keeps the tangential one, so after the run the velocity is
 * predicted exactly: vx e^(x bounces), vy e^(y bounces) in magnitude.
 * Usage: ball_in_box [BOUNCES [RESTITUTION]]   (default 12 0.9) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "collide2d.h"

#define BOX_W 4.0  /* m */
#define BOX_H 3.0  /* m */
#define RADIUS 0.25 /* m */

static int parse(const char *text, double lo, double hi, double *out)
{
    char *end;
    double v = strtod(text, &end);
    if (end == text || *end != '\0' || !(v >= lo && v <= hi)) return 0;
    *out = v;
    return 1;
}

int main(int argc, char **argv)
{
    static const char *const names[4] = {"left", "right", "bottom", "top"};
    static const c2d_vec2 normals[4] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}}; /* ball -> wall */
    c2d_body ball = {{1.0, 1.0}, {3.0, 2.2}, 0.5};                           /* m, m/s, kg */
    c2d_body wall = {{0.0, 0.0}, {0.0, 0.0}, INFINITY};
    double bounces = 12, e = 0.9, t = 0, vx0 = fabs(ball.vel.x), vy0 = fabs(ball.vel.y);
    int n, hits[2] = {0, 0}, ok;
    if (argc > 3 || (argc > 1 && !parse(argv[1], 1, 1e6, &bounces)) || (argc > 2 && !parse(argv[2], 0, 1, &e))) {
        fprintf(stderr, "usage: ball_in_box [BOUNCES (1..1e6) [RESTITUTION (0..1)]]\n");
        return 2;
    }
    printf("box %g x %g m, ball radius %g m, restitution %g\n", BOX_W, BOX_H, RADIUS, e);
    printf("%7s %-7s %9s %9s %9s %9s\n", "t/s", "wall", "x/m", "y/m", "vx m/s", "vy m/s");
    for (n = 0; n < (int)bounces; n++) {
        /* Time to each wall along the current velocity (the ball's edge). */
        double tx = ball.vel.x > 0 ? (BOX_W - RADIUS - ball.pos.x) / ball.vel.x
                  : ball.vel.x < 0 ? (RADIUS - ball.pos.x) / ball.vel.x : INFINITY;
        double ty = ball.vel.y > 0 ? (BOX_H - RADIUS - ball.pos.y) / ball.vel.y
                  : ball.vel.y < 0 ? (RADIUS - ball.pos.y) / ball.vel.y : INFINITY;
        double dt = tx < ty ? tx : ty;
        int k = tx < ty ? (ball.vel.x > 0) : 2 + (ball.vel.y > 0);
        c2d_status s;
        if (!(dt < INFINITY)) break; /* at rest */
        if (dt < 0) dt = 0;          /* a rounding past the wall */
        t += dt;
        ball.pos.x += ball.vel.x * dt;
        ball.pos.y += ball.vel.y * dt;
        s = c2d_collide_normal(&ball, &wall, normals[k], e);
        if (s != C2D_OK) {
            fprintf(stderr, "ball_in_box: %s wall gave %s\n", names[k], c2d_status_string(s));
            return 1;
        }
        hits[k / 2]++;
        printf("%7.3f %-7s %9.4f %9.4f %9.4f %9.4f\n", t, names[k], ball.pos.x, ball.pos.y, ball.vel.x, ball.vel.y);
    }
    /* |vx| = vx0 e^(side hits), |vy| = vy0 e^(floor/ceiling hits), within
     * a few roundings. */
    ok = fabs(fabs(ball.vel.x) - vx0 * pow(e, hits[0])) <= 1e-14 * vx0 &&
         fabs(fabs(ball.vel.y) - vy0 * pow(e, hits[1])) <= 1e-14 * vy0 && ball.pos.x >= RADIUS - 1e-12 &&
         ball.pos.x <= BOX_W - RADIUS + 1e-12 && ball.pos.y >= RADIUS - 1e-12 && ball.pos.y <= BOX_H - RADIUS + 1e-12;
    printf("ball_in_box: %d bounces (%d side, %d floor/ceiling), speed %.6f of the start: %s\n", hits[0] + hits[1],
           hits[0], hits[1], hypot(ball.vel.x, ball.vel.y) / hypot(vx0, vy0), ok ? "passed" : "FAILED");
    return ok ? 0 : 1;
}
