// toi_accel_scaffold.h - TEMPORARY: a stand-in for the library's
// c2d_time_of_impact_accel until it lands in include/collide2d.h (then this
// file and toi_accel_scaffold.cpp are deleted).
#ifndef C2D_DEMO_TOI_ACCEL_SCAFFOLD_H
#define C2D_DEMO_TOI_ACCEL_SCAFFOLD_H

extern "C" {
#include "collide2d.h"
c2d_status c2d_time_of_impact_accel(const c2d_body *a, c2d_vec2 acc_a, const c2d_body *b, c2d_vec2 acc_b,
                                    double radius_sum, double horizon, double *t);
}

#endif
