// engine_view.cpp - see engine_view.h.  Each quantity is read through a
// small trait that looks for the engine's field by name (std::void_t); the
// fallbacks are:
//   spin      rolling without slipping, w = (-vy/R, vx/R, 0)
//   jaws      point noses at the cushion segments' ends, facings from them
//             into the rail leaning towards the pocket by the regulation
//             facing angles less 90 degrees (corner 142, side 104)
//   contacts  the balls before and after a frame: new contacts counted by
//             stats(), matched to the balls whose velocity changed (a pair
//             that touches: ball-ball; one near a cushion: cushion), and balls
//             that left the table; the impulse is m |dv|
#include "engine_view.h"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>

namespace demo {

namespace {

template <class T, class = void> struct HasSpin : std::false_type {};
template <class T> struct HasSpin<T, std::void_t<decltype(std::declval<T &>().wz)>> : std::true_type {};

template <class T, class = void> struct HasTipOffset : std::false_type {};
template <class T> struct HasTipOffset<T, std::void_t<decltype(std::declval<T &>().topback)>> : std::true_type {};

template <class T, class = void> struct HasJaws : std::false_type {};
template <class T> struct HasJaws<T, std::void_t<decltype(std::declval<T &>().jaws)>> : std::true_type {};

template <class T, class = void> struct HasFrameEvents : std::false_type {};
template <class T>
struct HasFrameEvents<T, std::void_t<decltype(std::declval<const T &>().frame_events())>> : std::true_type {};

constexpr double kCornerLean = (142.0 - 90.0) * M_PI / 180.0;
constexpr double kSideLean = (104.0 - 90.0) * M_PI / 180.0;
constexpr double kCushionRubber = 0.045;  // m, nose to wood (drawn)

template <class B> Vec3 spin_of(const B &b) {
    if constexpr (HasSpin<B>::value) return {b.wx, b.wy, b.wz};
    else return {-b.vy / kBallRadius, b.vx / kBallRadius, 0.0};
}

// The end of a cushion segment nearest to (x, y), with the direction along
// the segment pointing out of it (towards the pocket) and its normal.
struct CushionEnd {
    double x, y, tx, ty, nx, ny, distance;
};

std::vector<CushionEnd> ends_near(const Table &t, double x, double y) {
    std::vector<CushionEnd> ends;
    for (const Segment &s : t.cushions) {
        const double len = std::hypot(s.bx - s.ax, s.by - s.ay);
        if (len <= 0) continue;
        const double ux = (s.bx - s.ax) / len, uy = (s.by - s.ay) / len;
        ends.push_back({s.ax, s.ay, -ux, -uy, s.nx, s.ny, std::hypot(s.ax - x, s.ay - y)});
        ends.push_back({s.bx, s.by, ux, uy, s.nx, s.ny, std::hypot(s.bx - x, s.by - y)});
    }
    std::sort(ends.begin(), ends.end(), [](const CushionEnd &a, const CushionEnd &b) { return a.distance < b.distance; });
    return ends;
}

JawShape point_jaw(const CushionEnd &e, double lean, double pocket_x, double pocket_y) {
    // into the rail (-n), turned towards the pocket (+t) by lean
    const double fx = -e.nx * std::cos(lean) + e.tx * std::sin(lean);
    const double fy = -e.ny * std::cos(lean) + e.ty * std::sin(lean);
    const double length = kCushionRubber / std::cos(lean);
    double nx = -fy, ny = fx;  // perpendicular, turned to face the pocket's side
    if (nx * (pocket_x - e.x) + ny * (pocket_y - e.y) < 0) nx = -nx, ny = -ny;
    return JawShape{Segment{e.x, e.y, e.x + fx * length, e.y + fy * length, nx, ny}, e.x, e.y, 0.0};
}

template <class P> PocketShape pocket_shape(const P &p, const Table &t) {
    PocketShape shape{p.x, p.y, p.capture_radius, {}};
    if constexpr (HasJaws<P>::value) {
        for (int k = 0; k < 2; ++k) {
            const auto &j = p.jaws[k];
            shape.jaws[k] = JawShape{j.facing, j.nose_x, j.nose_y, j.nose_r};
        }
    } else {
        const std::vector<CushionEnd> ends = ends_near(t, p.x, p.y);
        const bool corner = (p.x <= 0 || p.x >= t.length) && (p.y <= 0 || p.y >= t.width);
        for (size_t k = 0; k < 2 && k < ends.size(); ++k)
            shape.jaws[k] = point_jaw(ends[k], corner ? kCornerLean : kSideLean, p.x, p.y);
    }
    return shape;
}

template <class S> Shot shot_with_offset(double angle_deg, double speed, double side, double topback) {
    S shot{};
    shot.angle_deg = angle_deg;
    shot.speed = speed;
    if constexpr (HasTipOffset<S>::value) {
        shot.side = side;
        shot.topback = topback;
    } else {
        (void)side, (void)topback;
    }
    return shot;
}

template <class S> bool engine_contacts(const S &sim, std::vector<Contact> &out) {
    if constexpr (HasFrameEvents<S>::value) {
        for (const auto &e : sim.frame_events()) {
            using Kind = decltype(e.kind);
            if (e.kind == Kind::BallBall) out.push_back({ContactKind::BallBall, e.x, e.y, e.impulse});
            else if (e.kind == Kind::Cushion || e.kind == Kind::Jaw) out.push_back({ContactKind::Cushion, e.x, e.y, e.impulse});
            else if (e.kind == Kind::Pocket) out.push_back({ContactKind::Pocket, e.x, e.y, e.impulse});
        }
        return true;
    } else {
        (void)sim, (void)out;
        return false;
    }
}

double speed_change(const Ball &a, const Ball &b) { return std::hypot(b.vx - a.vx, b.vy - a.vy); }

// Distance from a ball's centre to the nearest cushion face or jaw.
double cushion_gap(const Table &t, const Ball &b) {
    double gap = 1e9;
    for (const Segment &s : t.cushions) {
        const double dx = s.bx - s.ax, dy = s.by - s.ay, len2 = dx * dx + dy * dy;
        const double u = len2 > 0 ? std::clamp(((b.x - s.ax) * dx + (b.y - s.ay) * dy) / len2, 0.0, 1.0) : 0.0;
        gap = std::min(gap, std::hypot(b.x - s.ax - u * dx, b.y - s.ay - u * dy));
    }
    return gap;
}

}  // namespace

TableShape table_shape(const Table &table) {
    TableShape shape{table.length, table.width, table.rail, std::min(kCushionRubber, 0.45 * table.rail), table.cushions, {}};
    for (const auto &p : table.pockets) shape.pockets.push_back(pocket_shape(p, table));
    return shape;
}

Vec3 angular_velocity(const Ball &ball) { return spin_of(ball); }

Shot make_shot(double angle_deg, double speed, double side, double topback) {
    return shot_with_offset<Shot>(angle_deg, speed, side, topback);
}

bool shots_take_spin() { return HasTipOffset<Shot>::value; }

void ContactListener::before(const Simulation &sim) {
    balls_ = sim.balls();
    ball_ball_ = sim.stats().ball_ball_collisions;
    cushion_ = sim.stats().cushion_collisions;
    primed_ = true;
}

std::vector<Contact> ContactListener::after(const Simulation &sim) {
    std::vector<Contact> out;
    if (engine_contacts(sim, out) || !primed_) return out;
    primed_ = false;
    const std::vector<Ball> &now = sim.balls();
    if (now.size() != balls_.size()) return out;
    constexpr double kThreshold = 0.03;  // m/s; rolling resistance takes 0.0025 a frame
    long pairs = sim.stats().ball_ball_collisions - ball_ball_;
    long cushions = sim.stats().cushion_collisions - cushion_;
    std::vector<char> used(now.size(), 0);
    std::vector<std::pair<double, std::pair<size_t, size_t>>> touching;
    for (size_t i = 0; i < now.size(); ++i) {
        if (balls_[i].active && !now[i].active) {
            out.push_back({ContactKind::Pocket, balls_[i].x, balls_[i].y, kBallMass * std::hypot(balls_[i].vx, balls_[i].vy)});
            used[i] = 1;
        }
    }
    for (size_t i = 0; i < now.size() && pairs > 0; ++i) {
        if (!now[i].active || speed_change(balls_[i], now[i]) < kThreshold) continue;
        for (size_t j = i + 1; j < now.size(); ++j) {
            if (!now[j].active || speed_change(balls_[j], now[j]) < kThreshold) continue;
            const double reach = kBallDiameter + std::hypot(now[i].vx - now[j].vx, now[i].vy - now[j].vy) * kFrameDt + 1e-3;
            if (std::hypot(now[i].x - now[j].x, now[i].y - now[j].y) < reach)
                touching.push_back({kBallMass * 0.5 * (speed_change(balls_[i], now[i]) + speed_change(balls_[j], now[j])), {i, j}});
        }
    }
    std::sort(touching.begin(), touching.end(), [](const auto &a, const auto &b) { return a.first > b.first; });
    for (const auto &t : touching) {
        if (pairs-- <= 0) break;
        const size_t i = t.second.first, j = t.second.second;
        used[i] = used[j] = 1;
        out.push_back({ContactKind::BallBall, 0.5 * (now[i].x + now[j].x), 0.5 * (now[i].y + now[j].y), t.first});
    }
    for (size_t i = 0; i < now.size() && cushions > 0; ++i) {
        const double dv = speed_change(balls_[i], now[i]);
        if (used[i] || !now[i].active || dv < kThreshold) continue;
        const double reach = kBallRadius + std::hypot(now[i].vx, now[i].vy) * kFrameDt + 2e-3;
        if (cushion_gap(sim.table(), now[i]) < reach) {
            out.push_back({ContactKind::Cushion, now[i].x, now[i].y, kBallMass * dv});
            --cushions;
        }
    }
    return out;
}

}  // namespace demo
