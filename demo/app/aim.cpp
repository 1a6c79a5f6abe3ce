/* SPDX-License-Identifier: MIT */
// aim.cpp - see aim.h.  A ball of radius R moving from c along the unit d
// meets: another ball at the least t >= 0 with |c + t d - b| = 2R; a cushion
// face or jaw facing (the lines a ball's surface touches, normal n) at
// t = ((c - a).n - R) / (-d.n) when d.n < 0 and the contact lies on the
// segment; a nose (or a point jaw) of radius r at |c + t d - p| = R + r; a
// pocket when its centre enters the capture circle.  The stun shot's paths
// after a cut of angle theta: the object ball along the line of centres at
// v cos(theta), the cue ball along the tangent line at v sin(theta).
#include "app/aim.h"

#include <algorithm>
#include <cmath>

namespace demo {

namespace {

constexpr double kCueLength = 1.47;     // m
constexpr double kTipDiameter = 0.013;  // m
constexpr double kButtDiameter = 0.030; // m
constexpr double kMaxPull = 0.22;       // m the cue draws back at full power

// The least t >= 0 at which a point moving from (x, y) along (dx, dy)
// comes within `reach` of (px, py); -1 if never.
double time_to_circle(double x, double y, double dx, double dy, double px, double py, double reach) {
    const double fx = x - px, fy = y - py;
    const double b = fx * dx + fy * dy, c = fx * fx + fy * fy - reach * reach;
    if (c <= 0) return b < 0 ? 0 : -1;  // touching already: only if approaching
    const double disc = b * b - c;
    if (b >= 0 || disc < 0) return -1;
    return -b - std::sqrt(disc);
}

double time_to_face(const Segment &s, double x, double y, double dx, double dy) {
    const double dn = dx * s.nx + dy * s.ny;
    if (dn >= 0) return -1;
    const double gap = (x - s.ax) * s.nx + (y - s.ay) * s.ny - kBallRadius;
    if (gap < -kBallRadius) return -1;  // behind the face
    const double t = std::max(0.0, gap) / -dn;
    const double cx = x + t * dx, cy = y + t * dy;
    const double ex = s.bx - s.ax, ey = s.by - s.ay, len2 = ex * ex + ey * ey;
    const double u = len2 > 0 ? ((cx - s.ax) * ex + (cy - s.ay) * ey) / len2 : -1;
    return u >= 0 && u <= 1 ? t : -1;
}

void consider(AimHit &best, double t, AimHit::Kind kind, int index, double nx, double ny) {
    if (t < 0 || (best.kind != AimHit::Nothing && t >= best.distance)) return;
    best.kind = kind;
    best.distance = t;
    best.ball = index;
    best.nx = nx;
    best.ny = ny;
}

// Colour of the cue along its length, s metres from the tip.
Colour cue_material(double s) {
    if (s < 0.008) return rgb8(60, 110, 190);       // chalked tip
    if (s < 0.030) return rgb8(238, 236, 226);      // ferrule
    if (s < 0.95) return rgb8(226, 196, 146);       // maple shaft
    if (s < 0.97) return rgb8(240, 240, 235);       // joint ring
    if (s < 1.27) return rgb8(40, 28, 24);          // wrap
    if (s < 1.45) return rgb8(110, 30, 30);         // butt
    return rgb8(20, 20, 20);                        // bumper
}

void draw_cue(Canvas &canvas, const View &v, double tip_x, double tip_y, double dx, double dy) {
    const double scale = v.scale;
    const float ux = static_cast<float>(dx), uy = static_cast<float>(-dy);  // canvas direction of the shot
    const PointF tip = v.at(tip_x, tip_y);
    const float length = static_cast<float>(kCueLength * scale);
    const float r_tip = static_cast<float>(kTipDiameter / 2 * scale), r_butt = static_cast<float>(kButtDiameter / 2 * scale);
    const PointF butt = {tip.x - ux * length, tip.y - uy * length};
    // its shadow on the cloth, down and right, tapered like the cue
    const float off = static_cast<float>(0.02 * scale), nx = -uy, ny = ux;
    canvas.fill_convex({{tip.x + off + nx * r_tip, tip.y + off + ny * r_tip},
                        {butt.x + off + nx * r_butt, butt.y + off + ny * r_butt},
                        {butt.x + off - nx * r_butt, butt.y + off - ny * r_butt},
                        {tip.x + off - nx * r_tip, tip.y + off - ny * r_tip}},
                       {0, 0, 0}, 0.22f);
    const float pad = r_butt + 2;
    const int x0 = std::max(0, static_cast<int>(std::min(tip.x, butt.x) - pad));
    const int x1 = std::min(canvas.width() - 1, static_cast<int>(std::max(tip.x, butt.x) + pad));
    const int y0 = std::max(0, static_cast<int>(std::min(tip.y, butt.y) - pad));
    const int y1 = std::min(canvas.height() - 1, static_cast<int>(std::max(tip.y, butt.y) + pad));
    for (int py = y0; py <= y1; ++py)
        for (int px = x0; px <= x1; ++px) {
            const float rx = static_cast<float>(px) + 0.5f - tip.x, ry = static_cast<float>(py) + 0.5f - tip.y;
            const float along = -(rx * ux + ry * uy);  // pixels behind the tip
            const float across = rx * -uy + ry * ux;
            if (along < -1 || along > length + 1) continue;
            const float half = r_tip + (r_butt - r_tip) * std::clamp(along / length, 0.0f, 1.0f);
            const float cover = std::clamp(half - std::fabs(across) + 0.5f, 0.0f, 1.0f) *
                                std::clamp(along + 0.5f, 0.0f, 1.0f) * std::clamp(length - along + 0.5f, 0.0f, 1.0f);
            if (cover <= 0) continue;
            const float t = std::clamp(across / std::max(half, 0.5f), -1.0f, 1.0f);
            const float light = 0.55f + 0.5f * std::sqrt(1 - t * t) + 0.25f * std::max(0.0f, -t) * (1 - std::fabs(t));
            canvas.blend(px, py, scaled(cue_material(along / scale), light), cover);
        }
}

}  // namespace

AimHit first_contact(const TableShape &table, const std::vector<Ball> &balls, int moving, double x, double y,
                     double dx, double dy, double max_distance) {
    AimHit best;
    for (size_t i = 0; i < balls.size(); ++i) {
        const Ball &b = balls[i];
        if (static_cast<int>(i) == moving || !b.active) continue;
        const double t = time_to_circle(x, y, dx, dy, b.x, b.y, kBallDiameter);
        if (t >= 0) {
            const double cx = x + t * dx, cy = y + t * dy, d = std::hypot(b.x - cx, b.y - cy);
            consider(best, t, AimHit::Ball, static_cast<int>(i), (b.x - cx) / d, (b.y - cy) / d);
        }
    }
    auto face = [&](const Segment &s) { consider(best, time_to_face(s, x, y, dx, dy), AimHit::Cushion, -1, s.nx, s.ny); };
    auto point = [&](double px, double py, double r) {
        const double t = time_to_circle(x, y, dx, dy, px, py, kBallRadius + r);
        if (t < 0) return;
        const double cx = x + t * dx - px, cy = y + t * dy - py, d = std::hypot(cx, cy);
        consider(best, t, AimHit::Cushion, -1, cx / d, cy / d);
    };
    for (const Segment &s : table.cushions) {
        face(s);
        if (!table.pockets.empty()) point(s.ax, s.ay, 0), point(s.bx, s.by, 0);
    }
    for (size_t p = 0; p < table.pockets.size(); ++p) {
        const PocketShape &pocket = table.pockets[p];
        for (const JawShape &j : pocket.jaws) {
            face(j.facing);
            point(j.nose_x, j.nose_y, j.nose_r);
        }
        const double t = time_to_circle(x, y, dx, dy, pocket.x, pocket.y, pocket.radius);
        if (t >= 0) consider(best, t, AimHit::Pocket, static_cast<int>(p), 0, 0);
    }
    if (best.kind != AimHit::Nothing && best.distance > max_distance) best = AimHit{};
    if (best.kind == AimHit::Nothing) best.distance = max_distance;
    best.x = x + best.distance * dx;
    best.y = y + best.distance * dy;
    return best;
}

void draw_aim(Canvas &canvas, const View &v, const TableShape &table, const std::vector<Ball> &balls, const AimState &aim) {
    if (balls.empty() || !balls[0].active) return;
    const Ball &cue = balls[0];
    const double dx = std::cos(aim.angle), dy = std::sin(aim.angle);
    const AimHit hit = first_contact(table, balls, 0, cue.x, cue.y, dx, dy, 4.0);
    const float radius = v.length(kBallRadius), thin = std::max(1.0f, radius * 0.12f);
    const Colour white{1, 1, 1};
    canvas.dashed_line(v.at(cue.x, cue.y), v.at(hit.x, hit.y), thin, radius * 0.5f, white, 0.55f);
    if (hit.kind == AimHit::Ball) {
        // cut angle: between the aim and the line of centres
        const double cos_cut = std::clamp(dx * hit.nx + dy * hit.ny, 0.0, 1.0);
        const double sin_cut = std::sqrt(1 - cos_cut * cos_cut);
        const Ball &object = balls[static_cast<size_t>(hit.ball)];
        const AimHit path = first_contact(table, balls, hit.ball, object.x, object.y, hit.nx, hit.ny, 0.15 + 0.6 * cos_cut);
        canvas.line(v.at(object.x, object.y), v.at(path.x, path.y), thin * 1.4f, rgb8(255, 236, 120), 0.85f);
        double tx = dx - cos_cut * hit.nx, ty = dy - cos_cut * hit.ny;
        const double tl = std::hypot(tx, ty);
        if (tl > 1e-9) {
            tx /= tl, ty /= tl;
            const double reach = 0.08 + 0.4 * sin_cut;
            canvas.line(v.at(hit.x, hit.y), v.at(hit.x + reach * tx, hit.y + reach * ty), thin, rgb8(150, 210, 255), 0.8f);
        }
    } else if (hit.kind == AimHit::Cushion) {
        const double dn = dx * hit.nx + dy * hit.ny, rx = dx - 2 * dn * hit.nx, ry = dy - 2 * dn * hit.ny;
        canvas.dashed_line(v.at(hit.x, hit.y), v.at(hit.x + 0.25 * rx, hit.y + 0.25 * ry), thin, radius * 0.35f, white, 0.4f);
    } else if (hit.kind == AimHit::Pocket) {
        const PocketShape &p = table.pockets[static_cast<size_t>(hit.ball)];
        canvas.ring(v.px(p.x), v.py(p.y), v.length(p.radius), thin, rgb8(255, 90, 80), 0.8f);
    }
    if (hit.kind != AimHit::Nothing && hit.kind != AimHit::Pocket) {
        canvas.fill_disk(v.px(hit.x), v.py(hit.y), radius, white, 0.18f);
        canvas.ring(v.px(hit.x), v.py(hit.y), radius - thin / 2, thin, white, 0.9f);
    }
    // the cue: its tip offset sideways by the english, drawn back with the power
    const double gap = kBallRadius + 0.012 + kMaxPull * aim.power;
    const double side = aim.side * kBallRadius;
    draw_cue(canvas, v, cue.x - gap * dx + side * dy, cue.y - gap * dy - side * dx, dx, dy);
}

}  // namespace demo
