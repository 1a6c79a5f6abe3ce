/* SPDX-License-Identifier: MIT */
/* world/predict.h - a disk's next event: impacts, walls, statics, sensors, cell and box crossings.
 * Part of lib/world.c, which includes the parts once, in order. */

typedef struct c2d_w_best {
    double when;
    uint32_t kind, partner;
    uint64_t pcount;
} c2d_w_best;

C2D_W_HOT void c2d_w_consider(c2d_w_best *b, double when, uint32_t kind, uint32_t partner, uint64_t pcount)
{
    if (when < b->when || (when == b->when && (kind < b->kind || (kind == b->kind && partner < b->partner)))) {
        b->when = when;
        b->kind = kind;
        b->partner = partner;
        b->pcount = pcount;
    }
}

/* The cells around coordinate c of m along one axis, each once (a
 * periodic grid wraps). */
C2D_W_HOT size_t c2d_w_neighbours(size_t c, size_t m, int periodic, size_t *cell)
{
    size_t n = 0;
    if (c > 0) cell[n++] = c - 1;
    else if (periodic) cell[n++] = m - 1;
    cell[n++] = c;
    if (c + 1 < m) cell[n++] = c + 1;
    else if (periodic) cell[n++] = 0;
    return n;
}

/* A caller broadphase's margin for disk p. */
static double c2d_w_margin(const c2d_world *w, const c2d_w_disk *p)
{
    return w->bp.margin > 0 ? w->bp.margin : 0.5 * p->radius;
}

/* The first time >= now at which a disk at x (time t) with speed v reaches
 * `to`. */
C2D_W_HOT double c2d_w_reach(double t, double x, double v, double to, double now)
{
    double when = t + (to - x) / v;
    return when < now ? now : when;
}

/* The first time >= now at which a coordinate x + v s + a s^2 / 2 (s the
 * time since t) passes `to` moving in direction dir (+1: upwards, -1:
 * downwards): g(s) = dir (x(s) - to) rising through 0.  C2D_W_INF for never.
 * With a == 0 it is c2d_w_reach's time (the same bits).  Otherwise the roots
 * of A s^2 + B s + C come from the cancellation-free pair q / A, C / q
 * (q = -(B + sign(B) sqrt(D)) / 2); g already past 0 (rounding) and rising
 * is due at once, past 0 and falling back is no event (else a disk that
 * just crossed into a cell could cross back and forth at one instant); a
 * double root with A < 0 only touches (no event), with A > 0 it passes.  Errors: a few ulp of the root, plus near a tangency (D ~ 0) the
 * rounding of D: a path that in exact arithmetic passes `to` by less than
 * a few ulp of the coordinates may be taken as a touch and the reverse. */
static double c2d_w_meet(double t, double x, double v, double a, double to, double dir, double now)
{
    double A, B, C, D, q, r1, r2, lo, hi, vertex;
    if (a == 0) return dir * v > 0 ? c2d_w_reach(t, x, v, to, now) : C2D_W_INF;
    A = dir * (0.5 * a), B = dir * v, C = dir * (x - to);
    D = B * B - 4 * A * C;
    vertex = t + -B / (2 * A);
    if (!(D >= 0)) { /* A > 0: g > 0 throughout (past already): at its lowest */
        if (A < 0) return C2D_W_INF;
        return vertex < now ? now : vertex;
    }
    if (D == 0 && A < 0) return C2D_W_INF;
    q = -0.5 * (B + (B >= 0 ? C2D_W_SQRT(D) : -C2D_W_SQRT(D)));
    r1 = q / A;
    r2 = q != 0 ? C / q : r1;
    lo = r1 < r2 ? r1 : r2, hi = r1 < r2 ? r2 : r1;
    if (A > 0) return t + hi < now ? now : t + hi;
    if (t + lo >= now) return t + lo;
    /* Past the rising root: beyond `to` and still rising (rounding) is due at
     * once; past the top, g falls back and never rises again. */
    return now < vertex ? now : C2D_W_INF;
}

/* An impact that leaves both velocities as they were (an approach speed
 * so small that even the elastic impulse rounds away) changes nothing, so
 * it is no impact either. */
static int c2d_w_unchanged(const c2d_body *a0, const c2d_body *a, const c2d_body *b0, const c2d_body *b)
{
    return a->vel.x == a0->vel.x && a->vel.y == a0->vel.y && b->vel.x == b0->vel.x && b->vel.y == b0->vel.y;
}

/* A pair's contact at the very time `now` that c2d_collide would refuse
 * (touching with no approach speed, pushed together by accelerations) or
 * resolve to the same velocities even at e = 1: no event, or the world
 * would predict it again and again at one instant (the collapse rule
 * makes an impact elastic after collapse_count of them, so a pair whose
 * elastic impact changes something always ends). */
static int c2d_w_refused_now(const c2d_body *a, const c2d_body *b)
{
    c2d_body ta, tb;
    c2d_w_body_copy(&ta, a), c2d_w_body_copy(&tb, b);
    return C2D_W_COLLIDE(&ta, &tb, 1.0) != C2D_OK || c2d_w_unchanged(a, &ta, b, &tb);
}

/* Disk p has had collapse_count impacts at this very instant (the
 * collapse rule, c2d_w_collapses). */
static int c2d_w_crowded(const c2d_world *w, const c2d_w_disk *p, double now)
{
    return p->last == now && p->same >= w->collapse_count;
}

/* Touching disks p (body a) and q (b) that c2d_collide refuses now but
 * whose accelerations press together (relative normal acceleration
 * closing) meet now all the same, for the pair rest rule (c2d_w_pair):
 * else they would pass through each other.  Not once either has had
 * collapse_count impacts at this instant, so rounding left in the rule's
 * projections cannot loop. */
static int c2d_w_pressed(const c2d_world *w, const c2d_w_disk *p, const c2d_w_disk *q, const c2d_body *a,
                         const c2d_body *b)
{
    const double nx = b->pos.x - a->pos.x, ny = b->pos.y - a->pos.y;
    if (c2d_w_crowded(w, p, w->now) || c2d_w_crowded(w, q, w->now)) return 0;
    return (p->ax - q->ax) * nx + (p->ay - q->ay) * ny > 0;
}

/* The contact point and normal (from the disk towards the static) of a
 * disk centred at (px, py) against static k: a circle's centre; a
 * segment's end when the centre's foot on its line lies beyond it, else
 * the foot, the normal then the segment's own normal (signed).  The
 * prediction and the impact use the same, so they agree on refusals. */
static void c2d_w_static_contact(const c2d_w_static *st, double px, double py, c2d_vec2 *point, c2d_vec2 *normal)
{
    if (st->shape == C2D_W_SEGMENT) {
        const double tx = (st->bx - st->ax) / st->len, ty = (st->by - st->ay) / st->len;
        const double u = tx * (px - st->ax) + ty * (py - st->ay);
        if (u > 0 && u < st->len) {
            const double side = st->nx * (px - st->ax) + st->ny * (py - st->ay) >= 0 ? -1.0 : 1.0;
            point->x = st->ax + tx * u, point->y = st->ay + ty * u;
            normal->x = side * st->nx, normal->y = side * st->ny;
            return;
        }
        if (!(u > 0)) point->x = st->ax, point->y = st->ay;
        else point->x = st->bx, point->y = st->by;
    } else {
        point->x = st->ax, point->y = st->ay;
    }
    normal->x = point->x - px, normal->y = point->y - py;
}

static int c2d_w_static_refused(const c2d_w_static *st, const c2d_body *a)
{
    c2d_body ta, tb;
    c2d_vec2 n;
    c2d_w_body_copy(&ta, a);
    c2d_w_static_contact(st, a->pos.x, a->pos.y, &tb.pos, &n);
    tb.vel.x = tb.vel.y = 0, tb.mass = C2D_W_INF;
    return C2D_W_COLLIDE_NORMAL(&ta, &tb, &n, 1.0) != C2D_OK || (ta.vel.x == a->vel.x && ta.vel.y == a->vel.y);
}

/* Disk p (at a, now) entering sensor k: a point meeting a circle, from
 * outside only.  Inside, or just entered and a hair outside by rounding
 * (within 2^-26 of the radius: (1 + 2^-26)^2 < 1 + 2^-25), is no event:
 * otherwise the entry would repeat at once. */
static void c2d_w_predict_sensor(const c2d_world *w, const c2d_w_disk *p, const c2d_body *a, size_t k,
                                 c2d_w_best *best)
{
    const c2d_w_static *st = &w->stat[k];
    const c2d_w_entered *en = &w->entered[p - w->disk];
    const double dx = a->pos.x - st->ax, dy = a->pos.y - st->ay, dd = dx * dx + dy * dy, rr = st->radius * st->radius;
    c2d_body b;
    double toi;
    c2d_status r;
    c2d_body ref;
    c2d_vec2 acc, zero;
    double when;
    if (dd < rr || (en->sensor == k + 1 && dd <= rr * (1 + 0x1p-25))) return;
    b.pos.x = st->ax, b.pos.y = st->ay, b.vel.x = b.vel.y = 0, b.mass = C2D_W_INF;
    ref.pos.x = p->x, ref.pos.y = p->y, ref.vel.x = p->vx, ref.vel.y = p->vy, ref.mass = p->mass;
    acc.x = p->ax, acc.y = p->ay, zero.x = zero.y = 0;
    /* From the reference state, as every static (the time then depends on
     * the state alone); an entry found there before now is one already
     * passed: a straight path enters a circle once, a curved one may enter
     * again, sought from now. */
    if (acc.x == 0 && acc.y == 0) {
        r = C2D_W_TOI(&ref, &b, st->radius, &toi);
        if (r != C2D_OK || !(p->t + toi >= w->now)) return;
        when = p->t + toi;
    } else {
        r = C2D_W_TOI_ACCEL(&ref, &acc, &b, &zero, st->radius, p->timer - p->t, &toi);
        if (r == C2D_OK && p->t + toi >= w->now) {
            when = p->t + toi;
        } else {
            r = C2D_W_TOI_ACCEL(a, &acc, &b, &zero, st->radius, p->timer - w->now, &toi);
            if (r != C2D_OK) return;
            when = w->now + toi;
        }
    }
    c2d_w_consider(best, when, C2D_W_WALL, (uint32_t)(4 + k), 0);
}

/* Whether static st's box (a segment's ends, a circle's or sensor's
 * centre +- radius: a, b and radius as stored, so the box costs no memory
 * and the world's layout stays as it was) meets box r, touching counts. */
C2D_W_HOT int c2d_w_static_meets(const c2d_w_static *st, const c2d_world_box *r)
{
    const double lx = st->ax < st->bx ? st->ax : st->bx, hx = st->ax < st->bx ? st->bx : st->ax;
    const double ly = st->ay < st->by ? st->ay : st->by, hy = st->ay < st->by ? st->by : st->ay;
    return lx - st->radius <= r->hi.x && hx + st->radius >= r->lo.x && ly - st->radius <= r->hi.y &&
           hy + st->radius >= r->lo.y;
}

/* Whether a point (a segment's end) meets box r, touching counts: the
 * same test as c2d_w_static_meets on the end alone. */
C2D_W_HOT int c2d_w_point_meets(double x, double y, const c2d_world_box *r)
{
    return x <= r->hi.x && x >= r->lo.x && y <= r->hi.y && y >= r->lo.y;
}

/* Disk p against the statics whose boxes meet its reach (and not `seen`,
 * tried already; NULL: none), from its reference state (time p->t, so the
 * times depend on that state alone; an approach already due is clamped to
 * now): a circle (radius sum r + R), a segment's two ends (points) and its
 * interior (the normal coordinate reaching +-r, on the side the centre is
 * now, with the foot within the segment).  With acceleration the horizon is
 * the disk's timer, where its motion may change.  A static beyond the reach
 * cannot be met before the disk's next crossing (c2d_w_reach_of), where it
 * is tried, from the same reference state, if it then comes into reach.
 * The same holds for each end of a segment on its own: a rail's box meets
 * the reach of every disk along it, its ends (the pockets' corners) only
 * those of disks near them, so an end is tried when it is in the reach
 * and was not in `seen` (a meeting with it is at the end itself, which
 * the disk's body covers, inside its shell, a radius within the reach),
 * and the interior when the segment's box is.  A time of impact skipped
 * so would be later than the crossing: the events are the same bits. */
static void c2d_w_predict_statics(const c2d_world *w, const c2d_w_disk *p, const c2d_body *a,
                                  const c2d_world_box *reach, const c2d_world_box *seen, c2d_w_best *best)
{
    const double now = w->now;
    size_t k;
    c2d_vec2 acc;
    c2d_body ref;
    ref.pos.x = p->x, ref.pos.y = p->y, ref.vel.x = p->vx, ref.vel.y = p->vy, ref.mass = p->mass;
    acc.x = p->ax, acc.y = p->ay;
    for (k = 0; k < w->nstatic; k++) {
        const c2d_w_static *st = &w->stat[k];
        const uint32_t partner = (uint32_t)(4 + k);
        int end, fresh;
        if (!c2d_w_static_meets(st, reach)) continue;
        fresh = seen == NULL || !c2d_w_static_meets(st, seen); /* the whole static came into reach */
        if (st->shape == C2D_W_SENSOR) {
            if (fresh) c2d_w_predict_sensor(w, p, a, k, best);
            continue;
        }
        for (end = 0; end < (st->shape == C2D_W_CIRCLE ? 1 : 2); end++) {
            c2d_body b;
            double toi, when;
            c2d_status r;
            b.pos.x = end ? st->bx : st->ax, b.pos.y = end ? st->by : st->ay;
            if (st->shape == C2D_W_CIRCLE ? !fresh
                                          : !c2d_w_point_meets(b.pos.x, b.pos.y, reach) ||
                                                (seen != NULL && c2d_w_point_meets(b.pos.x, b.pos.y, seen)))
                continue;
            b.vel.x = b.vel.y = 0, b.mass = C2D_W_INF;
            if (acc.x == 0 && acc.y == 0) r = C2D_W_TOI(&ref, &b, p->radius + st->radius, &toi);
            else {
                c2d_vec2 zero;
                zero.x = zero.y = 0;
                r = C2D_W_TOI_ACCEL(&ref, &acc, &b, &zero, p->radius + st->radius, p->timer - p->t, &toi);
            }
            if (r != C2D_OK) continue;
            when = p->t + toi;
            if (when <= now) {
                if (c2d_w_static_refused(st, a)) continue;
                when = now;
            }
            c2d_w_consider(best, when, C2D_W_WALL, partner, 0);
        }
        if (st->shape == C2D_W_SEGMENT && fresh) {
            const double d0 = st->nx * (p->x - st->ax) + st->ny * (p->y - st->ay);
            const double vn = st->nx * p->vx + st->ny * p->vy, an = st->nx * acc.x + st->ny * acc.y;
            const double dnow = st->nx * (a->pos.x - st->ax) + st->ny * (a->pos.y - st->ay);
            const double when = dnow >= 0 ? c2d_w_meet(p->t, d0, vn, an, p->radius, -1, now)
                                          : c2d_w_meet(p->t, d0, vn, an, -p->radius, 1, now);
            if (when < C2D_W_INF) {
                const double dt = when - p->t;
                const double x = c2d_w_at(p->x, p->vx, acc.x, dt), y = c2d_w_at(p->y, p->vy, acc.y, dt);
                const double u = ((st->bx - st->ax) * (x - st->ax) + (st->by - st->ay) * (y - st->ay)) / st->len;
                if (u >= 0 && u <= st->len && !(when == now && c2d_w_static_refused(st, a)))
                    c2d_w_consider(best, when, C2D_W_WALL, partner, 0);
            }
        }
    }
}

/* Disk p as a body at time t (from its reference state). */
static void c2d_w_body_at(const c2d_w_disk *p, double t, c2d_body *b)
{
    const double dt = t - p->t;
    b->pos.x = c2d_w_at(p->x, p->vx, p->ax, dt), b->pos.y = c2d_w_at(p->y, p->vy, p->ay, dt);
    b->vel.x = c2d_w_vel(p->vx, p->ax, dt), b->vel.y = c2d_w_vel(p->vy, p->ay, dt);
    b->mass = p->mass;
}

/* The nearest periodic image of a displacement d along a side: the shift
 * (-side, 0 or side) to add.  Stored positions are within [0, side) and
 * rebased before they go side / 24 from it, so one shift is enough. */
C2D_W_HOT double c2d_w_image_shift(double d, double side)
{
    if (d > 0.5 * side) return -side;
    if (d < -0.5 * side) return side;
    return 0;
}

/* The canonical frame of pair (p, q), p the lower index: the later of
 * their state times t0 (returned), both extrapolated to it, q's image the
 * nearest to p there (*shift, added to q's positions).  It depends only on
 * the two stored states, so the pair's time of impact is the same bits
 * whoever predicts it, whenever and from whatever broadphase.
 * Why the nearest image at t0 is the one they meet in: at contact the
 * displacement's components are at most the radius sum <= width / 3 (the
 * box is at least 3 largest diameters); each disk stays within
 * e = side / 24 of its reference position per axis (the rebase), so from t0
 * to the contact the displacement changes by less than 3 e = side / 8 (the
 * later disk moves less than e from its reference at t0, the earlier one
 * less than 2 e); hence at t0 the contact image's components were below
 * side / 3 + side / 8 < side / 2: it is the nearest one. */
static double c2d_w_pair_start(const c2d_world *w, const c2d_w_disk *p, const c2d_w_disk *q, c2d_body *a, c2d_body *b,
                               c2d_vec2 *shift)
{
    const double t0 = p->t > q->t ? p->t : q->t;
    c2d_w_body_at(p, t0, a);
    c2d_w_body_at(q, t0, b);
    shift->x = shift->y = 0;
    if (w->periodic) {
        shift->x = c2d_w_image_shift(b->pos.x - a->pos.x, w->width);
        shift->y = c2d_w_image_shift(b->pos.y - a->pos.y, w->height);
        b->pos.x += shift->x, b->pos.y += shift->y;
    }
    return t0;
}

static int c2d_w_curved(const c2d_world *w, const c2d_w_disk *p, const c2d_w_disk *q)
{
    return w->accel && (p->ax != 0 || p->ay != 0 || q->ax != 0 || q->ay != 0);
}

/* q's image shift in pair (p, q), p the lower index, as its prediction
 * chose it: a straight pair from its relative position as
 * c2d_w_try_straight computes it, a curved one from c2d_w_pair_start's. */
static void c2d_w_pair_shift(const c2d_world *w, const c2d_w_disk *p, const c2d_w_disk *q, c2d_vec2 *shift)
{
    shift->x = shift->y = 0;
    if (!w->periodic) return;
    if (c2d_w_curved(w, p, q)) {
        c2d_body a, b;
        (void)c2d_w_pair_start(w, p, q, &a, &b, shift); /* only the shift is wanted */
    } else {
        const double t0 = p->t > q->t ? p->t : q->t, sp = t0 - p->t, sq = t0 - q->t;
        shift->x = c2d_w_image_shift((q->x + q->vx * sq) - (p->x + p->vx * sp), w->width);
        shift->y = c2d_w_image_shift((q->y + q->vy * sq) - (p->y + p->vy * sp), w->height);
    }
}

/* The pair at time t as its impact sees it (q shifted to its image). */
static void c2d_w_pair_at(const c2d_w_disk *p, const c2d_w_disk *q, double t, const c2d_vec2 *shift, c2d_body *a,
                          c2d_body *b)
{
    c2d_w_body_at(p, t, a);
    c2d_w_body_at(q, t, b);
    b->pos.x += shift->x, b->pos.y += shift->y;
}

/* A pair due at once (time <= now) that c2d_collide would refuse at now
 * (touching with no approach speed, pushed together by accelerations, or
 * a graze rounded into the past): no event, or the world would predict it
 * again and again. */
static int c2d_w_pair_refused_now(const c2d_world *w, const c2d_w_disk *p, const c2d_w_disk *q, const c2d_vec2 *shift)
{
    c2d_body a, b;
    c2d_w_pair_at(p, q, w->now, shift, &a, &b);
    return c2d_w_refused_now(&a, &b);
}

/* What a prediction keeps of its own disk i for its straight candidates. */
typedef struct c2d_w_self {
    double x, y, vx, vy, t, radius, now;
    double x0, y0;                /* x + vx * 0 and y + vy * 0: the position at age +0 */
    double width, height, hw, hh; /* the box, and half of it (periodic) */
    double nhw, nhh;              /* minus the halves (the same bits as -hw, -hh), loaded not negated per candidate */
    int periodic;
    uint32_t i;
} c2d_w_self;

/* The nearest image of a pair's relative position (dx, dy): each
 * component shifted by the side once at most (see c2d_w_image_shift). */
C2D_W_HOT void c2d_w_nearest(const c2d_w_self *s, double *dx, double *dy)
{
    if (*dx > s->hw) *dx -= s->width;
    else if (*dx < s->nhw) *dx += s->width;
    if (*dy > s->hh) *dy -= s->height;
    else if (*dy < s->nhh) *dy += s->height;
}

/* c2d_time_of_impact's plain path (lib/real/toi.h, c2d_toi_plain) for a
 * pair in the relative frame (a at the origin at rest, b at d moving at
 * v), operation for operation, so its time is the same bits: the
 * subtractions b - a it starts with are exact against a zero (-0 - +0 is
 * -0), and every quantity it forms is a product of two components, a
 * square or an absolute value, so negating d and v (the higher index's
 * view, c2d_w_try_straight) changes none of them.  Inlined, it costs no
 * call, no argument checks and no bodies; dv = d.v and k = |dx vx| +
 * |dy vy| are the candidate test's dot and mag (the same expressions, so
 * the same bits).  1: an impact at
 * *t; 0: none (receding, a miss, no relative motion); -1: the plain path
 * would not decide (outside its window, near touching, near a graze),
 * and the library's call does. */
C2D_W_HOT int c2d_w_toi_plain(double dx, double dy, double vx, double vy, double r, double dv, double k, double *t)
{
    const double lo = 0x1p-100, hi = 0x1p100, u8 = 0x1p-50, u16 = 0x1p-49; /* C2D_R_TOI_WINDOW, 8u, 16u */
    const double ax = C2D_W_FABS(dx), ay = C2D_W_FABS(dy), bx = C2D_W_FABS(vx), by = C2D_W_FABS(vy);
    double q, r2, a2, dist, speed, cross, h, kc;
    /* The window (every input 0 or within [lo, hi], their sum at most hi):
     * first as all nonzero, the common case, then with zeros left out. */
    if (!((ax + ay) + (bx + by) + r <= hi)) return -1;
    if (!(ax >= lo && ay >= lo && bx >= lo && by >= lo && r >= lo) &&
        !((ax == 0 || ax >= lo) && (ay == 0 || ay >= lo) && (bx == 0 || bx >= lo) && (by == 0 || by >= lo) &&
          (r == 0 || r >= lo)))
        return -1;
    if ((vx == 0 && vy == 0) || (dx == 0 && dy == 0)) return 0;
    if (!(C2D_W_FABS(dv) > u8 * k)) return -1;
    if (dv > 0) return 0;
    q = dx * dx + dy * dy;
    r2 = r * r;
    if (!(C2D_W_FABS(q - r2) > u16 * (q > r2 ? q : r2))) return -1; /* touching: the library's c2d_toi_touching */
    if (q < r2) {
        *t = 0;
        return 1;
    }
    a2 = vx * vx + vy * vy;
    cross = dx * vy - dy * vx;
    kc = C2D_W_FABS(dx * vy) + C2D_W_FABS(dy * vx);
    if (!(C2D_W_FABS(cross * cross - r2 * a2) > u16 * (C2D_W_FABS(cross) * kc + r2 * a2))) return -1;
    if (cross * cross > r2 * a2) return 0;
    dist = C2D_W_SQRT(q);
    speed = C2D_W_SQRT(a2);
    h = C2D_W_FABS(cross) / speed;
    *t = (dist - r) * (dist + r) / (speed * C2D_W_SQRT((r - h) * (r + h)) - dv);
    return 1;
}

/* A straight pair (no acceleration on either): its relative state in the
 * canonical frame is q minus p, both at t0 = the later state time (each
 * x + v s with s >= 0 its own age at t0: the same bits whichever disk
 * predicts), the nearest image.  Swapping p and q negates every component
 * exactly (rounding is symmetric), so the lower index's view is the
 * predictor's negated when the predictor is the higher index.  The time of
 * impact is c2d_time_of_impact of that relative state (a at the origin at
 * rest, b moving), when it can beat the best so far; the filters first,
 * each certain despite rounding (the estimates' errors are far below
 * 2^-40 of their terms, taken far from underflow): receding or no relative
 * motion; a miss (the discriminant negative); or no contact before the
 * best event so far.  The last: with h = -d.v, c = |d|^2 - rs^2 > 0, the
 * time is t = c / (h + sqrt(h^2 - |v|^2 c)) >= c / (2 h) (a bound tighter
 * by the square root rejected too few more to pay for it, measured).
 * c2d_time_of_impact's own time is within ulp(t) + ulp(|d|) / s of the
 * exact one (s the approach speed, about h / |d|): relative to t (at
 * least c / (2 h)) that is below 2^-52 + 2^-51 (|d|^2 + rs^2) / c, so
 * below 2^-40 when c > 2^-10 (|d|^2 + rs^2), and a margin 2^-40 then
 * covers it; nearer contact the test is not taken.  They see the same
 * numbers as the time of impact, and are symmetric in the sign. */
C2D_W_HOT void c2d_w_try_straight(const c2d_world *w, const c2d_w_self *self, uint32_t j, c2d_w_best *best)
{
    const c2d_w_disk *q = &w->disk[j];
    const double qt = q->t, rs = self->radius + q->radius;
    double t0, dx, dy, dvx = q->vx - self->vx, dvy = q->vy - self->vy, dot, mag, toi, when;
    /* t0 = the later state time; when it is the predictor's own (most
     * often: it has just had an impact), its age sp is +0 and its
     * position x + vx sp is the frame's x0 (the same operation). */
    if (qt <= self->t) {
        const double sq = self->t - qt;
        t0 = self->t;
        dx = (q->x + q->vx * sq) - self->x0, dy = (q->y + q->vy * sq) - self->y0;
    } else {
        const double sp = qt - self->t, sq = qt - qt;
        t0 = qt;
        dx = (q->x + q->vx * sq) - (self->x + self->vx * sp), dy = (q->y + q->vy * sq) - (self->y + self->vy * sp);
    }
    c2d_body a, b;
    if (self->periodic) c2d_w_nearest(self, &dx, &dy);
    dot = dx * dvx + dy * dvy;
    mag = C2D_W_FABS(dx * dvx) + C2D_W_FABS(dy * dvy);
    /* No relative motion gives mag = 0 (dx, dy finite), so it is tested
     * only below the range, off the path most candidates take. */
    if (mag >= 0x1p-900 && mag <= 0x1p900) {
        double dd, err, c;
        if (dot > mag * 0x1p-40) return;
        dd = dx * dx + dy * dy;
        err = (dd + rs * rs) * 0x1p-40, c = (dd - rs * rs) - err;
        if (c > 0 && c <= 0x1p900 && err >= 0x1p-900) {
            const double dh = -dot + mag * 0x1p-40, vv = (dvx * dvx + dvy * dvy) * (1 - 0x1p-40);
            if (dh * dh < vv * c * (1 - 0x1p-40)) return;
            if (c > (dd + rs * rs) * 0x1p-10 && best->when - t0 < c / (2 * dh) * (1 - 0x1p-40)) return;
        }
    } else if (dvx == 0 && dvy == 0) {
        return;
    }
    switch (c2d_w_toi_plain(dx, dy, dvx, dvy, rs, dot, mag, &toi)) {
    case 0: return;
    case 1: break;
    default:
        if (j < self->i) dx = -dx, dy = -dy, dvx = -dvx, dvy = -dvy;
        a.pos.x = a.pos.y = a.vel.x = a.vel.y = 0, a.mass = 1;
        b.pos.x = dx, b.pos.y = dy, b.vel.x = dvx, b.vel.y = dvy, b.mass = 1; /* masses: ignored */
        if (C2D_W_TOI(&a, &b, rs, &toi) != C2D_OK) return;
        break;
    }
    when = t0 + toi;
    if (when <= self->now) {
        const uint32_t lo = j < self->i ? j : self->i, hi = j < self->i ? self->i : j;
        c2d_vec2 shift;
        c2d_w_pair_shift(w, &w->disk[lo], &w->disk[hi], &shift);
        if (c2d_w_pair_refused_now(w, &w->disk[lo], &w->disk[hi], &shift)) return;
        when = self->now;
    }
    c2d_w_consider(best, when, C2D_W_PAIR, j, q->count);
}

static void c2d_w_self_of(const c2d_world *w, uint32_t i, c2d_w_self *self)
{
    const c2d_w_disk *p = &w->disk[i];
    self->x = p->x, self->y = p->y, self->vx = p->vx, self->vy = p->vy, self->t = p->t, self->radius = p->radius;
    self->x0 = p->x + p->vx * 0.0, self->y0 = p->y + p->vy * 0.0;
    self->now = w->now, self->i = i;
    self->width = w->width, self->height = w->height, self->hw = 0.5 * w->width, self->hh = 0.5 * w->height;
    self->nhw = -self->hw, self->nhh = -self->hh;
    self->periodic = w->periodic;
}

/* Disk i's candidate j: their next impact in the canonical frame if it can
 * beat the best so far; curved paths by c2d_time_of_impact_accel (lower
 * index first, absolute positions at t0) with the earlier timer as the
 * horizon (where either motion may change; a timer's change makes the
 * other's prediction stale). */
static void c2d_w_try_pair(const c2d_world *w, const c2d_w_self *self, uint32_t j, c2d_w_best *best)
{
    const c2d_w_disk *d = w->disk;
    const uint32_t i = self->i, lo = i < j ? i : j, hi = i < j ? j : i;
    const c2d_w_disk *p = &d[lo], *q = &d[hi];
    c2d_body a, b;
    c2d_vec2 shift, pa, qa;
    double t0, toi, when;
    if (j == i || d[j].kind == C2D_W_GONE) return;
    if (!c2d_w_curved(w, p, q)) {
        c2d_w_try_straight(w, self, j, best);
        return;
    }
    t0 = c2d_w_pair_start(w, p, q, &a, &b, &shift);
    pa.x = p->ax, pa.y = p->ay, qa.x = q->ax, qa.y = q->ay;
    if (C2D_W_TOI_ACCEL(&a, &pa, &b, &qa, p->radius + q->radius, (p->timer < q->timer ? p->timer : q->timer) - t0, &toi) !=
        C2D_OK)
        return;
    when = t0 + toi;
    if (when <= w->now) {
        /* Refused now, unless pressed together (the pair rest rule). */
        c2d_w_pair_at(p, q, w->now, &shift, &a, &b);
        if (c2d_w_refused_now(&a, &b) && !c2d_w_pressed(w, p, q, &a, &b)) return;
        when = w->now;
    }
    c2d_w_consider(best, when, C2D_W_PAIR, j, d[j].count);
}

/* The sides of a range [lo, hi] along one axis a disk's coordinate (x at
 * its time t, speed v, acceleration acc) leaves first: with acceleration
 * both sides (c2d_w_meet), straight only the one the velocity points to.
 * `has` says which sides exist (bit 0: lo, bit 1: hi); partners base + 0
 * (lo) and base + 1 (hi). */
C2D_W_HOT void c2d_w_leave(c2d_w_best *best, double t, double x, double v, double acc, double lo, double hi, unsigned has,
                        uint32_t base, double now)
{
    if (acc == 0) {
        if (v < 0 && (has & 1u)) c2d_w_consider(best, c2d_w_reach(t, x, v, lo, now), C2D_W_CELL, base, 0);
        if (v > 0 && (has & 2u)) c2d_w_consider(best, c2d_w_reach(t, x, v, hi, now), C2D_W_CELL, base + 1, 0);
        return;
    }
    if (has & 1u) c2d_w_consider(best, c2d_w_meet(t, x, v, acc, lo, -1, now), C2D_W_CELL, base, 0);
    if (has & 2u) c2d_w_consider(best, c2d_w_meet(t, x, v, acc, hi, 1, now), C2D_W_CELL, base + 1, 0);
}

/* The image of a range's start `lo` (and so of the range) in a disk's frame:
 * its stored position is in [0, side) up to a rebase's excursion, the
 * range's in [0, side), so the shift is the one that brings the range's
 * centre nearest the disk's centre x. */
C2D_W_HOT double c2d_w_frame_shift(double x, double lo, double hi, double side)
{
    return c2d_w_image_shift(0.5 * (lo + hi) - x, side);
}

/* Walls: the centre at radius from them (straight: only those the
 * velocity points to). */
static void c2d_w_predict_walls(const c2d_world *w, const c2d_w_disk *p, c2d_w_best *best)
{
    const double now = w->now, r = p->radius;
    if (p->ax == 0 && p->ay == 0) {
        if (p->vx < 0) c2d_w_consider(best, c2d_w_reach(p->t, p->x, p->vx, r, now), C2D_W_WALL, 0, 0);
        if (p->vx > 0) c2d_w_consider(best, c2d_w_reach(p->t, p->x, p->vx, w->width - r, now), C2D_W_WALL, 1, 0);
        if (p->vy < 0) c2d_w_consider(best, c2d_w_reach(p->t, p->y, p->vy, r, now), C2D_W_WALL, 2, 0);
        if (p->vy > 0) c2d_w_consider(best, c2d_w_reach(p->t, p->y, p->vy, w->height - r, now), C2D_W_WALL, 3, 0);
        return;
    }
    c2d_w_consider(best, c2d_w_meet(p->t, p->x, p->vx, p->ax, r, -1, now), C2D_W_WALL, 0, 0);
    c2d_w_consider(best, c2d_w_meet(p->t, p->x, p->vx, p->ax, w->width - r, 1, now), C2D_W_WALL, 1, 0);
    c2d_w_consider(best, c2d_w_meet(p->t, p->y, p->vy, p->ay, r, -1, now), C2D_W_WALL, 2, 0);
    c2d_w_consider(best, c2d_w_meet(p->t, p->y, p->vy, p->ay, w->height - r, 1, now), C2D_W_WALL, 3, 0);
}

/* Periodic: the rebase, when the centre first goes `rebase` from its
 * reference position along either axis (straight: at rebase / max |v|). */
static void c2d_w_predict_rebase(const c2d_world *w, const c2d_w_disk *p, c2d_w_best *best)
{
    const double e = w->rebase, now = w->now;
    if (p->ax == 0 && p->ay == 0) {
        const double sx = C2D_W_FABS(p->vx), sy = C2D_W_FABS(p->vy), s = sx > sy ? sx : sy;
        if (s > 0) {
            const double when = p->t + e / s;
            c2d_w_consider(best, when < now ? now : when, C2D_W_CELL, C2D_W_REBASE, 0);
        }
        return;
    }
    c2d_w_consider(best, c2d_w_meet(p->t, p->x, p->vx, p->ax, p->x - e, -1, now), C2D_W_CELL, C2D_W_REBASE, 0);
    c2d_w_consider(best, c2d_w_meet(p->t, p->x, p->vx, p->ax, p->x + e, 1, now), C2D_W_CELL, C2D_W_REBASE, 0);
    c2d_w_consider(best, c2d_w_meet(p->t, p->y, p->vy, p->ay, p->y - e, -1, now), C2D_W_CELL, C2D_W_REBASE, 0);
    c2d_w_consider(best, c2d_w_meet(p->t, p->y, p->vy, p->ay, p->y + e, 1, now), C2D_W_CELL, C2D_W_REBASE, 0);
}

/* The built-in broadphase: leaving the cell is an event, and the
 * candidates are the disks of the 3 x 3 cells around (fewer against
 * walls; each cell once). */
/* One cell along an axis beyond c (dir -1 or +1), wrapping when periodic:
 * 1 and *cell, or 0 at a wall. */
C2D_W_HOT size_t c2d_w_beyond(size_t c, size_t m, int periodic, int dir, size_t *cell)
{
    if (dir < 0) {
        if (c > 0) *cell = c - 1;
        else if (periodic) *cell = m - 1;
        else return 0;
        return 1;
    }
    if (c + 1 < m) *cell = c + 1;
    else if (periodic) *cell = 0;
    else return 0;
    return 1;
}

/* A cell's first disk j (C2D_W_NONE: empty) added to the candidates'
 * starts, its state fetched ahead. */
C2D_W_HOT size_t c2d_w_first(const c2d_w_disk *d, uint32_t *first, size_t n, uint32_t j)
{
    if (j == C2D_W_NONE) return n;
    first[n] = j;
#ifdef __GNUC__
    __builtin_prefetch(&d[j]);
#else
    (void)d;
#endif
    return n + 1;
}

C2D_W_NO_SLP static void c2d_w_predict_cells(const c2d_world *w, uint32_t i, const c2d_body *a, c2d_w_best *best, c2d_w_best *cross,
                                uint32_t side)
{
    const c2d_w_disk *d = w->disk, *p = &d[i];
    const size_t mx = w->mx, my = w->my, cx = p->cell % mx, cy = p->cell / mx;
    const int per = w->periodic;
    size_t k, l, nc, nr, n = 0, col[3] = {0, 0, 0}, row[3]; /* col zeroed: gcc cannot see nc == 3 fills it */
    uint32_t first[9];
    c2d_w_self self;
    {
        double x0 = (double)cx * w->cw, x1 = cx + 1 == mx ? w->width : (double)(cx + 1) * w->cw;
        double y0 = (double)cy * w->ch, y1 = cy + 1 == my ? w->height : (double)(cy + 1) * w->ch;
        if (per) {
            const double fx = c2d_w_frame_shift(a->pos.x, x0, x1, w->width);
            const double fy = c2d_w_frame_shift(a->pos.y, y0, y1, w->height);
            x0 += fx, x1 += fx, y0 += fy, y1 += fy;
        }
        c2d_w_leave(cross, p->t, p->x, p->vx, p->ax, x0, x1, (cx > 0 || per ? 1u : 0u) | (cx + 1 < mx || per ? 2u : 0u),
                    0, w->now);
        c2d_w_leave(cross, p->t, p->y, p->vy, p->ay, y0, y1, (cy > 0 || per ? 1u : 0u) | (cy + 1 < my || per ? 2u : 0u),
                    2, w->now);
    }
    /* All 3 x 3, or after a crossing the strip beyond the new cell. */
    if (side == C2D_W_NONE || side >= 2) nc = c2d_w_neighbours(cx, mx, per, col);
    else nc = c2d_w_beyond(cx, mx, per, side == 0 ? -1 : 1, col);
    if (side == C2D_W_NONE || side < 2) nr = c2d_w_neighbours(cy, my, per, row);
    else nr = c2d_w_beyond(cy, my, per, side == 2 ? -1 : 1, row);
    /* The cells' first disks, loaded (and their states fetched) all at
     * once before any is used: with many disks these are cache misses, and
     * independent ones overlap. */
    for (l = 0; l < nr; l++) {
        const uint32_t *h = &w->head[row[l] * mx];
        if (nc == 3) { /* unrolled: the common case (no loop per cell) */
            const uint32_t j0 = h[col[0]], j1 = h[col[1]], j2 = h[col[2]];
            n = c2d_w_first(d, first, n, j0);
            n = c2d_w_first(d, first, n, j1);
            n = c2d_w_first(d, first, n, j2);
        } else {
            for (k = 0; k < nc; k++) n = c2d_w_first(d, first, n, h[col[k]]);
        }
    }
    c2d_w_self_of(w, i, &self);
    if (!w->accel) { /* every pair straight, and no removed disk in a cell */
        for (k = 0; k < n; k++) {
            uint32_t j = first[k];
            do {
                if (j != i) c2d_w_try_straight(w, &self, j, best);
                j = d[j].next;
            } while (j != C2D_W_NONE);
        }
        return;
    }
    for (k = 0; k < n; k++) {
        uint32_t j;
        for (j = first[k]; j != C2D_W_NONE; j = d[j].next) c2d_w_try_pair(w, &self, j, best);
    }
}

/* The box a caller's broadphase gets for a disk centred at (x, y). */
static void c2d_w_box_of(const c2d_world *w, const c2d_w_disk *p, double x, double y, c2d_world_box *box)
{
    const double h = (p->radius + c2d_w_margin(w, p)) * C2D_W_BOX_SLACK;
    box->lo.x = x - h, box->lo.y = y - h, box->hi.x = x + h, box->hi.y = y + h;
}

typedef struct c2d_w_query {
    const c2d_world *w;
    c2d_w_self self;
    c2d_w_best *best;
} c2d_w_query;

static void c2d_w_report(void *context, size_t disk)
{
    const c2d_w_query *q = (const c2d_w_query *)context;
    if (disk < q->w->count) c2d_w_try_pair(q->w, &q->self, (uint32_t)disk, q->best);
}

/* Ask the caller's broadphase for the disks whose boxes overlap `box`, and
 * in a periodic box its images across each side it comes within the
 * largest half-size of a box of (a box near the other side may stick out
 * towards it across the wrap). */
static void c2d_w_query_images(const c2d_world *w, const c2d_world_box *box, c2d_world_report report, void *ctx)
{
    double sx[3], sy[3];
    size_t nx = 1, ny = 1, k, l;
    sx[0] = sy[0] = 0;
    if (w->periodic) {
        const double h = w->hmax;
        if (box->lo.x < h) sx[nx++] = w->width;
        if (box->hi.x > w->width - h) sx[nx++] = -w->width;
        if (box->lo.y < h) sy[ny++] = w->height;
        if (box->hi.y > w->height - h) sy[ny++] = -w->height;
    }
    for (l = 0; l < ny; l++)
        for (k = 0; k < nx; k++) {
            c2d_world_box b;
            c2d_w_box_copy(&b, box);
            b.lo.x += sx[k], b.hi.x += sx[k], b.lo.y += sy[l], b.hi.y += sy[l];
            w->bp.query(w->bp.user, &b, report, ctx);
        }
}

/* The caller's broadphase: leaving the box's inner range (centre +-
 * margin) is an event, and the candidates are what it reports. */
static void c2d_w_predict_caller(const c2d_world *w, uint32_t i, const c2d_body *a, c2d_w_best *best)
{
    const c2d_w_disk *p = &w->disk[i];
    const double m = c2d_w_margin(w, p), bx = w->box[2 * (size_t)i], by = w->box[2 * (size_t)i + 1];
    double fx = 0, fy = 0;
    c2d_world_box box;
    c2d_w_query ctx;
    if (w->periodic) {
        fx = c2d_w_frame_shift(a->pos.x, bx, bx, w->width);
        fy = c2d_w_frame_shift(a->pos.y, by, by, w->height);
    }
    c2d_w_leave(best, p->t, p->x, p->vx, p->ax, bx + fx - m, bx + fx + m, 3u, C2D_W_BOX, w->now);
    c2d_w_leave(best, p->t, p->y, p->vy, p->ay, by + fy - m, by + fy + m, 3u, C2D_W_BOX, w->now);
    c2d_w_box_of(w, p, bx, by, &box);
    ctx.w = w, ctx.best = best;
    c2d_w_self_of(w, i, &ctx.self);
    c2d_w_query_images(w, &box, c2d_w_report, &ctx);
}

/* Where disk i (at a, now) can reach before its next crossing, as a box
 * in its own frame: its centre stays in `cell` (up to rounding) and its
 * body within a radius of it, so the 3 x 3 cells around, at least a
 * diameter beyond on every side, hold it with room to spare; with a
 * caller's broadphase the centre stays within margin of its box's centre,
 * and the shell grown by a radius more holds it. */
static void c2d_w_reach_of(const c2d_world *w, uint32_t i, const c2d_body *a, size_t cell, c2d_world_box *reach)
{
    const c2d_w_disk *p = &w->disk[i];
    double x0, x1, y0, y1, gx, gy;
    if (w->caller) {
        const double h = (p->radius + c2d_w_margin(w, p)) * C2D_W_BOX_SLACK + p->radius;
        x0 = x1 = w->box[2 * (size_t)i], y0 = y1 = w->box[2 * (size_t)i + 1];
        gx = gy = h;
    } else {
        const size_t cx = cell % w->mx, cy = cell / w->mx;
        x0 = (double)cx * w->cw, x1 = cx + 1 == w->mx ? w->width : (double)(cx + 1) * w->cw;
        y0 = (double)cy * w->ch, y1 = cy + 1 == w->my ? w->height : (double)(cy + 1) * w->ch;
        gx = w->cw, gy = w->ch;
    }
    if (w->periodic) {
        const double fx = c2d_w_frame_shift(a->pos.x, x0, x1, w->width);
        const double fy = c2d_w_frame_shift(a->pos.y, y0, y1, w->height);
        x0 += fx, x1 += fx, y0 += fy, y1 += fy;
    }
    reach->lo.x = x0 - gx, reach->hi.x = x1 + gx, reach->lo.y = y0 - gy, reach->hi.y = y1 + gy;
}

/* The cell disk p has just left by `side` (it is now in p->cell). */
static size_t c2d_w_cell_left(const c2d_world *w, const c2d_w_disk *p, uint32_t side)
{
    size_t cx = p->cell % w->mx, cy = p->cell / w->mx;
    switch (side) {
    case 0: cx = cx + 1 == w->mx ? 0 : cx + 1; break;
    case 1: cx = (cx == 0 ? w->mx : cx) - 1; break;
    case 2: cy = cy + 1 == w->my ? 0 : cy + 1; break;
    default: cy = (cy == 0 ? w->my : cy) - 1; break;
    }
    return cy * w->mx + cx;
}

/* Disk i's event: the earlier of its best event other than a crossing
 * (kept, with its time, through the crossings) and its crossing. */
static void c2d_w_settle(c2d_world *w, uint32_t i, const c2d_w_best *best, const c2d_w_best *cross)
{
    c2d_w_disk *p = &w->disk[i];
    p->kind = best->kind;
    p->partner = best->partner;
    p->pcount = best->pcount;
    w->node[i].mwhen = best->when;
    if (cross->when < best->when ||
        (cross->when == best->when && (C2D_W_CELL < best->kind || (C2D_W_CELL == best->kind && cross->partner < best->partner)))) {
        p->side = cross->partner;
        c2d_w_q_set(w, i, cross->when, C2D_W_TIE_KIND(C2D_W_CELL) | (uint64_t)i << 31 | (uint64_t)i);
    } else if (best->kind == C2D_W_PAIR) {
        const uint64_t lo = i < best->partner ? i : best->partner, hi = i < best->partner ? best->partner : i;
        p->side = C2D_W_NONE;
        c2d_w_q_set(w, i, best->when, lo << 31 | hi); /* kind C2D_W_PAIR = 0 */
    } else {
        p->side = C2D_W_NONE;
        c2d_w_q_set(w, i, best->when, C2D_W_TIE_KIND(best->kind) | (uint64_t)i << 31 | (uint64_t)i);
    }
}

static void c2d_w_best_none(c2d_w_best *b)
{
    b->when = C2D_W_INF;
    b->kind = C2D_W_IDLE;
    b->partner = 0;
    b->pcount = 0;
}

/* Disk i's next event, predicted from scratch. */
static void c2d_w_predict(c2d_world *w, uint32_t i)
{
    c2d_w_disk *p = &w->disk[i];
    c2d_w_best best, cross;
    c2d_body a;
    c2d_w_best_none(&best);
    c2d_w_best_none(&cross);
    c2d_w_body_at(p, w->now, &a);
    if (!w->periodic) c2d_w_predict_walls(w, p, &best);
    else c2d_w_predict_rebase(w, p, &best);
    if (p->timer < C2D_W_INF) c2d_w_consider(&best, p->timer, C2D_W_TIMER, 0, 0);
    /* A disk at rest meets no static: every time of impact with it is
     * C2D_SEPARATING (no relative motion), a segment's interior is never
     * reached (c2d_w_meet, v = a = 0) and a sensor never entered; worth
     * skipping, since a world's disks at rest are predicted at every add
     * and setter (a pool table before a shot: every ball). */
    if (w->nstatic > 0 && !(p->vx == 0 && p->vy == 0 && p->ax == 0 && p->ay == 0)) {
        c2d_world_box reach;
        c2d_w_reach_of(w, i, &a, p->cell, &reach);
        c2d_w_predict_statics(w, p, &a, &reach, NULL, &best);
    }
    if (w->caller) c2d_w_predict_caller(w, i, &a, &best);
    else c2d_w_predict_cells(w, i, &a, &best, &cross, C2D_W_NONE);
    c2d_w_settle(w, i, &best, &cross);
}

/* Disk i's next event after crossing into a new cell by `side`: its
 * state is unchanged, so its best other event stands (unless it is an
 * impact whose partner has moved since: then from scratch), and only the
 * strip of 3 cells that has come into its 3 x 3 is new. */
static void c2d_w_predict_crossed(c2d_world *w, uint32_t i, uint32_t side)
{
    c2d_w_disk *p = &w->disk[i];
    c2d_w_best best, cross;
    c2d_body a;
    if (p->kind == C2D_W_PAIR && w->disk[p->partner].count != p->pcount) {
        c2d_w_predict(w, i);
        return;
    }
    best.when = w->node[i].mwhen, best.kind = p->kind, best.partner = p->partner, best.pcount = p->pcount;
    c2d_w_best_none(&cross);
    c2d_w_body_at(p, w->now, &a);
    if (w->nstatic > 0) { /* the statics that have come into reach */
        c2d_world_box reach, seen;
        c2d_w_reach_of(w, i, &a, p->cell, &reach);
        c2d_w_reach_of(w, i, &a, c2d_w_cell_left(w, p, side), &seen);
        c2d_w_predict_statics(w, p, &a, &reach, &seen, &best);
    }
    c2d_w_predict_cells(w, i, &a, &best, &cross, side);
    c2d_w_settle(w, i, &best, &cross);
}
