/* SPDX-License-Identifier: MIT */
/* Code size per call site (make bench: compiled with the library's flags,
 * sizes read with nm -S).  Each function makes one call: the library call
 * or the C2D_INLINE front end, with the restitution a parameter (var_) or
 * the constant 1 (one_).  The size difference is what one inline call site
 * costs over a plain call. */
#define C2D_INLINE
#include "collide2d.h"

/* 1 when the inline forms are really the header's front ends here. */
const int site_as_written = C2D_INLINE_AS_WRITTEN;

c2d_status site_var_call_collide(c2d_body *a, c2d_body *b, double e) { return c2d_collide(a, b, e); }
c2d_status site_var_inline_collide(c2d_body *a, c2d_body *b, double e) { return c2d_collide_inline(a, b, e); }
c2d_status site_one_call_collide(c2d_body *a, c2d_body *b) { return c2d_collide(a, b, 1.0); }
c2d_status site_one_inline_collide(c2d_body *a, c2d_body *b) { return c2d_collide_inline(a, b, 1.0); }

c2d_status site_var_call_normal(c2d_body *a, c2d_body *b, c2d_vec2 n, double e) { return c2d_collide_normal(a, b, n, e); }
c2d_status site_var_inline_normal(c2d_body *a, c2d_body *b, c2d_vec2 n, double e)
{
    return c2d_collide_normal_inline(a, b, n, e);
}
c2d_status site_one_call_normal(c2d_body *a, c2d_body *b, c2d_vec2 n) { return c2d_collide_normal(a, b, n, 1.0); }
c2d_status site_one_inline_normal(c2d_body *a, c2d_body *b, c2d_vec2 n) { return c2d_collide_normal_inline(a, b, n, 1.0); }

c2d_status site_var_call_collidef(c2d_bodyf *a, c2d_bodyf *b, float e) { return c2d_collidef(a, b, e); }
c2d_status site_var_inline_collidef(c2d_bodyf *a, c2d_bodyf *b, float e) { return c2d_collidef_inline(a, b, e); }
c2d_status site_one_call_collidef(c2d_bodyf *a, c2d_bodyf *b) { return c2d_collidef(a, b, 1.0f); }
c2d_status site_one_inline_collidef(c2d_bodyf *a, c2d_bodyf *b) { return c2d_collidef_inline(a, b, 1.0f); }

c2d_status site_var_call_normalf(c2d_bodyf *a, c2d_bodyf *b, c2d_vec2f n, float e) { return c2d_collide_normalf(a, b, n, e); }
c2d_status site_var_inline_normalf(c2d_bodyf *a, c2d_bodyf *b, c2d_vec2f n, float e)
{
    return c2d_collide_normalf_inline(a, b, n, e);
}
c2d_status site_one_call_normalf(c2d_bodyf *a, c2d_bodyf *b, c2d_vec2f n) { return c2d_collide_normalf(a, b, n, 1.0f); }
c2d_status site_one_inline_normalf(c2d_bodyf *a, c2d_bodyf *b, c2d_vec2f n)
{
    return c2d_collide_normalf_inline(a, b, n, 1.0f);
}
