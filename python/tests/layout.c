/* SPDX-License-Identifier: MIT */
/* layout.c - the C layout of every public struct and of the scalar types the
 * Python binding mirrors with ctypes, for python/tests/test_layout.py (built
 * by python/python.mk as $(B)/python/layout).  One line each:
 *   struct NAME SIZE ALIGN
 *   field NAME MEMBER OFFSET SIZE
 *   type NAME SIZE ALIGN
 * collide2d.h's and collide2d_world.h's.  C99 has no alignof: the offset of T after a char in a struct is T's. */
#include <stddef.h>
#include <stdio.h>

#include "collide2d.h"
#include "collide2d_world.h"

#define ALIGN(T) offsetof(struct { char c; T t; }, t)
#define STRUCT(T) printf("struct %s %zu %zu\n", #T, sizeof(T), ALIGN(T))
#define FIELD(T, m) printf("field %s %s %zu %zu\n", #T, #m, offsetof(T, m), sizeof(((T *)0)->m))
#define TYPE(T) printf("type %s %zu %zu\n", #T, sizeof(T), ALIGN(T))

int main(void)
{
    TYPE(c2d_status);
    TYPE(size_t);
    TYPE(long);
    TYPE(int);
#ifndef C2D_NO_DOUBLE
    STRUCT(c2d_vec2);
    FIELD(c2d_vec2, x); FIELD(c2d_vec2, y);
    STRUCT(c2d_body);
    FIELD(c2d_body, pos); FIELD(c2d_body, vel); FIELD(c2d_body, mass);
    STRUCT(c2d_disk);
    FIELD(c2d_disk, pos); FIELD(c2d_disk, vel); FIELD(c2d_disk, spin); FIELD(c2d_disk, mass);
    FIELD(c2d_disk, radius); FIELD(c2d_disk, inertia);
    STRUCT(c2d_surface);
    FIELD(c2d_surface, restitution); FIELD(c2d_surface, friction); FIELD(c2d_surface, tangential_restitution);
    STRUCT(c2d_pairs);
    FIELD(c2d_pairs, pos_ax); FIELD(c2d_pairs, pos_ay); FIELD(c2d_pairs, pos_bx); FIELD(c2d_pairs, pos_by);
    FIELD(c2d_pairs, vel_ax); FIELD(c2d_pairs, vel_ay); FIELD(c2d_pairs, vel_bx); FIELD(c2d_pairs, vel_by);
    FIELD(c2d_pairs, mass_a); FIELD(c2d_pairs, mass_b);
    TYPE(c2d_boundary);
    TYPE(c2d_world_event_kind);
    STRUCT(c2d_world_event);
    FIELD(c2d_world_event, kind); FIELD(c2d_world_event, time); FIELD(c2d_world_event, a);
    FIELD(c2d_world_event, b); FIELD(c2d_world_event, impulse);
    STRUCT(c2d_world_desc);
    FIELD(c2d_world_desc, capacity); FIELD(c2d_world_desc, width); FIELD(c2d_world_desc, height);
    FIELD(c2d_world_desc, boundary); FIELD(c2d_world_desc, restitution); FIELD(c2d_world_desc, wall_restitution);
    FIELD(c2d_world_desc, collapse_speed); FIELD(c2d_world_desc, collapse_count);
    FIELD(c2d_world_desc, collapse_time); FIELD(c2d_world_desc, collapse_length);
    FIELD(c2d_world_desc, on_event); FIELD(c2d_world_desc, user); FIELD(c2d_world_desc, statics);
    FIELD(c2d_world_desc, model); FIELD(c2d_world_desc, friction); FIELD(c2d_world_desc, wall_friction);
    FIELD(c2d_world_desc, tangential_restitution); FIELD(c2d_world_desc, inertia_factor);
    FIELD(c2d_world_desc, resolve_impact); FIELD(c2d_world_desc, resolve_wall); FIELD(c2d_world_desc, resolve_static);
    FIELD(c2d_world_desc, broadphase);
    STRUCT(c2d_ball);
    FIELD(c2d_ball, pos); FIELD(c2d_ball, vel); FIELD(c2d_ball, spin); FIELD(c2d_ball, mass);
    FIELD(c2d_ball, radius); FIELD(c2d_ball, inertia);
    STRUCT(c2d_ball_surface);
    FIELD(c2d_ball_surface, restitution); FIELD(c2d_ball_surface, friction);
    FIELD(c2d_ball_surface, friction_boost); FIELD(c2d_ball_surface, friction_decay);
    STRUCT(c2d_cushion);
    FIELD(c2d_cushion, normal); FIELD(c2d_cushion, height); FIELD(c2d_cushion, restitution);
    FIELD(c2d_cushion, friction);
    STRUCT(c2d_world_box);
    FIELD(c2d_world_box, lo); FIELD(c2d_world_box, hi);
    STRUCT(c2d_world_broadphase);
    FIELD(c2d_world_broadphase, insert); FIELD(c2d_world_broadphase, move); FIELD(c2d_world_broadphase, remove);
    FIELD(c2d_world_broadphase, query); FIELD(c2d_world_broadphase, user); FIELD(c2d_world_broadphase, margin);
    TYPE(c2d_world_model);
    STRUCT(c2d_world_contact);
    FIELD(c2d_world_contact, kind); FIELD(c2d_world_contact, time); FIELD(c2d_world_contact, a);
    FIELD(c2d_world_contact, b); FIELD(c2d_world_contact, normal); FIELD(c2d_world_contact, restitution);
    FIELD(c2d_world_contact, collapsed);
    STRUCT(c2d_world_stats);
    FIELD(c2d_world_stats, collisions); FIELD(c2d_world_stats, wall_collisions); FIELD(c2d_world_stats, events);
    FIELD(c2d_world_stats, time); FIELD(c2d_world_stats, virial);
#endif
#ifndef C2D_NO_FLOAT
    STRUCT(c2d_ballf);
    FIELD(c2d_ballf, pos); FIELD(c2d_ballf, vel); FIELD(c2d_ballf, spin); FIELD(c2d_ballf, mass);
    FIELD(c2d_ballf, radius); FIELD(c2d_ballf, inertia);
    STRUCT(c2d_ball_surfacef);
    FIELD(c2d_ball_surfacef, restitution); FIELD(c2d_ball_surfacef, friction);
    FIELD(c2d_ball_surfacef, friction_boost); FIELD(c2d_ball_surfacef, friction_decay);
    STRUCT(c2d_cushionf);
    FIELD(c2d_cushionf, normal); FIELD(c2d_cushionf, height); FIELD(c2d_cushionf, restitution);
    FIELD(c2d_cushionf, friction);
    STRUCT(c2d_vec2f);
    FIELD(c2d_vec2f, x); FIELD(c2d_vec2f, y);
    STRUCT(c2d_bodyf);
    FIELD(c2d_bodyf, pos); FIELD(c2d_bodyf, vel); FIELD(c2d_bodyf, mass);
    STRUCT(c2d_diskf);
    FIELD(c2d_diskf, pos); FIELD(c2d_diskf, vel); FIELD(c2d_diskf, spin); FIELD(c2d_diskf, mass);
    FIELD(c2d_diskf, radius); FIELD(c2d_diskf, inertia);
    STRUCT(c2d_surfacef);
    FIELD(c2d_surfacef, restitution); FIELD(c2d_surfacef, friction); FIELD(c2d_surfacef, tangential_restitution);
    STRUCT(c2d_pairsf);
    FIELD(c2d_pairsf, pos_ax); FIELD(c2d_pairsf, pos_ay); FIELD(c2d_pairsf, pos_bx); FIELD(c2d_pairsf, pos_by);
    FIELD(c2d_pairsf, vel_ax); FIELD(c2d_pairsf, vel_ay); FIELD(c2d_pairsf, vel_bx); FIELD(c2d_pairsf, vel_by);
    FIELD(c2d_pairsf, mass_a); FIELD(c2d_pairsf, mass_b);
#endif
#ifndef C2D_NO_FIXED
    TYPE(c2d_fixed);
    STRUCT(c2d_vec2x);
    FIELD(c2d_vec2x, x); FIELD(c2d_vec2x, y);
    STRUCT(c2d_bodyx);
    FIELD(c2d_bodyx, pos); FIELD(c2d_bodyx, vel); FIELD(c2d_bodyx, mass);
#endif
    return ferror(stdout) ? 1 : 0;
}
