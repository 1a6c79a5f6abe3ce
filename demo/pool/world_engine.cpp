/* SPDX-License-Identifier: MIT */
// world_engine.cpp - see world_engine.h.
//
// The world holds each ball's position and velocity and its acceleration
// on the cloth; this engine keeps what the world does not know, each ball's
// spin, as a Track (motion.h) from its last change, and turns the state
// changes into the world's terms: an acceleration and a timer at the
// track's end (slide -> roll -> stop), set again whenever the motion
// changes.  Contacts are resolved by the world's built-in rule in the
// frictionless scenes (c2d_collide, a wall's normal negated) and by the
// pool model here (the world's resolvers): sphere_contact.h's ball-ball,
// face (cushion or jaw facing) and nose impacts in the run's contact model
// (spheres with 3-D spin by default), each with the world's effective
// restitution (its collapse rule).  Contacts approaching slower than Model::absorb_below are
// absorbed rather than bounced (model.h): the velocities become the nearest
// that approach nothing a ball touches, and pairs that their accelerations
// press together end their slides or move on as one (on_event, which may
// change any ball).  Pockets are the world's sensors: a ball whose centre
// enters the hole is taken out of the world at that event.
//
// Tables: a closed box (elastic, gas, cradle) is the world's own box, its
// cushions the world's walls; the pool table's cushions, jaw facings, noses
// and holes are statics in a box a margin wider than the rails (kMargin:
// the world's box starts at 0, the pockets reach beyond the cushion lines),
// positions shifted by the margin on the way in and out.  Ball i is disk
// world_index_[i]; a ball put back on the table (place_ball) makes a new
// world with every ball on the table as it is, so ball_of_ maps the
// world's indices back.  The world's clock starts at 0 with each world;
// epoch_ is the simulated time of that start.
//
// What the world reports becomes the demo's records as before: a ball-ball
// impact two Event records (the lower-numbered ball first) with each ball's
// state after it and the normal impulse's magnitude, a cushion, jaw or
// pocket record, a change of motion state; and for the checker the pair
// (FrameLog::contacts) and each changed ball's new motion (a waypoint).
#include "pool/world_engine.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "pool/broadphase.h"
#include "pool/det_math.h"
#include "pool/slow_contact.h"
#include "pool/sphere_contact.h"

extern "C" {
#include "collide2d_world.h"
}

namespace demo {

namespace {

constexpr size_t kNoDisk = std::numeric_limits<size_t>::max();

// The world's walls 0..3 are x = 0, x = width, y = 0, y = height;
// closed_box's cushions are y = 0, y = width, x = 0, x = length.
constexpr int kCushionOfWall[4] = {2, 3, 0, 1};

// The pool table inside the world's box: the pockets' holes reach about a
// ball beyond the cushion lines.  A power of two, the shift changes a
// coordinate by at most half an ulp of the shifted value.
constexpr double kMargin = 0.25;

// How far a ball's centre moves before the world moves its box in the box
// list (c2d_world_broadphase.margin; the world's default is half a radius).
// The events are the same bits for any margin (collide2d_world.h); what it
// trades is the box events (a ball rolling 1 m with the default crosses
// its box about 70 times, each a full prediction) against candidates per
// prediction (more pairs and statics in a bigger box).  Measured on the
// opponent's candidates (build/opponent_bench, callgrind): 0.5 R 121 M
// instructions a turn, 1 R 104 M, 2 R 60 M, 3 R (0.086 m) 46 M, 4 R 46 M,
// 6 R 50 M, once the statics are cut to those in reach (GAME.md).
constexpr double kListMargin = 3 * kBallRadius;

// The box's cushions as closed_box makes them: the table's rectangle.
bool is_closed_box(const Table &table) {
    const std::vector<Segment> &c = table.cushions;
    return table.pockets.empty() && c.size() == 4 && c[0].ay == 0 && c[0].by == 0 && c[1].ay == table.width &&
           c[2].ax == 0 && c[2].bx == 0 && c[3].ax == table.length;
}

// A static of the world, as the table knows it.
struct Feature {
    EventKind kind;    // Cushion, Jaw (a facing or a nose) or Pocket (a hole: a sensor)
    int feature;       // Event::feature
    bool nose;         // a jaw's rounded point: an immovable disk
    double x, y, r;    // the nose (table coordinates)
};

class WorldEngine : public Engine {
public:
    WorldEngine(const std::vector<Ball> &balls, const Table &table, const Model &model, WorldBroadphase broadphase);
    void step(double dt, Stats &stats, FrameLog &log) override;
    bool settle(double max_seconds, Stats &stats, FrameLog &log) override;
    void set_motion(int i, const Ball &state) override;
    void place_ball(int i, Point p) override;
    double now() const override { return epoch_ + (settled_ ? last_event_ : world_now_); }

private:
    // the world's calls
    static void on_event(void *user, const c2d_world_event *event);
    static void tree_insert(void *user, size_t disk, const c2d_world_box *box);
    static void tree_move(void *user, size_t disk, const c2d_world_box *box);
    static void tree_remove(void *user, size_t disk);
    static void list_insert(void *user, size_t disk, const c2d_world_box *box);
    static void list_move(void *user, size_t disk, const c2d_world_box *box);
    static void list_remove(void *user, size_t disk);
    static void list_query(void *user, const c2d_world_box *box, c2d_world_report report, void *context);
    static void tree_query(void *user, const c2d_world_box *box, c2d_world_report report, void *context);
    static c2d_status resolve_impact(void *user, const c2d_world_contact *c, c2d_body *a, c2d_body *b);
    static c2d_status resolve_static(void *user, const c2d_world_contact *c, c2d_body *a, c2d_body *b);

    void build();
    void add_statics(size_t &count, bool add);
    size_t add(size_t i);
    int overlapped(const Ball &b) const;
    void advance(double world_t, Stats &stats, FrameLog &log, bool record_paths, bool sample_after = true);
    void sample();
    bool moving() const;

    // states
    Ball with_spin(int i, double t, double x, double y, double vx, double vy) const;
    Ball state_of(size_t disk, double t) const;
    Ball ball_at(int i, double t) const;
    Motion motion_of(const Ball &b) const;
    void restart(int i, const Ball &b, double t, bool set_velocity, bool fresh = false);

    // contacts
    c2d_status resolve_pair(const c2d_world_contact &c, c2d_body &a, c2d_body &b);
    c2d_status resolve_fixed(const c2d_world_contact &c, c2d_body &a);
    void limits_of(int i, double t, const Ball &b, int partner, const Ball *partner_state, std::vector<Limit> &out) const;
    Ball absorbed(int i, double t, const Ball &b, int partner, const Ball *partner_state);
    void pressed_group(int a, int b, double t, std::vector<int> &group) const;
    void move_together(int a, int b, double t);
    void join(int a, int b, double t);
    double closing_by_acceleration(int a, int b, double t) const;

    // events
    bool resolving(const c2d_world_event &e) const;
    void count_contact(int i, double t);
    bool crowded(int i, double t) const;
    static constexpr long kMostAtOnce = 8;
    std::vector<double> instant_;  // per ball: the instant of its last contact (world time)
    std::vector<long> at_once_;    // per ball: its contacts at that instant
    // the same for its contacts with cushions, jaws and noses, apart
    std::vector<double> fixed_instant_;
    std::vector<long> fixed_at_once_;
    void take_resting_acceleration(int i);
    void impact(const c2d_world_event &e);
    void fixed(const c2d_world_event &e);
    void timer(const c2d_world_event &e);
    void pocket(const c2d_world_event &e);
    Ball after_event(int i, double t) const;
    void record(double t, EventKind kind, int ball, int other, int feature, double impulse);
    void waypoint(int i);

    const Model model_;
    const Table table_;
    const bool walls_;     // the table is the world's box (else statics)
    const double offset_;  // world coordinate - table coordinate
    std::vector<Feature> statics_;  // by the world's static index
    std::vector<Segment> faces_;  // what a ball can lean on: the rails' cushions, the jaws' facings
    std::vector<uint64_t> memory_;  // the world's buffer (8-byte aligned)
    const bool use_tree_;           // a caller broadphase (Box2D's tree or the box list) finds the candidates, else the cells
    const bool use_list_;           // that broadphase is the box list
    c2d_world_broadphase tree_calls_{};
    std::unique_ptr<Broadphase> tree_;  // each disk's box, tagged with its index
    std::vector<int32> proxy_;          // disk -> the tree's proxy
    std::vector<uintptr_t> found_;      // a query's tags
    // the list: each disk's box by disk, in double (no rounding to the
    // tree's floats), and whether it is in the world
    std::vector<c2d_world_box> boxes_;
    std::vector<unsigned char> listed_;
    c2d_world *world_ = nullptr;
    std::vector<size_t> world_index_;  // ball -> disk, kNoDisk off the table
    std::vector<int> ball_of_;         // disk -> ball
    std::vector<Track> track_;         // each ball's motion since its last change (world time)
    double epoch_ = 0, world_now_ = 0, last_event_ = 0;
    bool settled_ = false;
    // the advance in progress: where its records go
    Stats *stats_ = nullptr;
    FrameLog *log_ = nullptr;
    double frame_start_ = 0;  // world time
    bool record_paths_ = true;
    // The contact a resolver has just resolved, for the event that follows:
    // the balls' states before and after it (spins included).
    struct Resolved {
        bool seen = false, absorbed = false;
        size_t a = 0, b = 0;
        double t = 0, nx = 0, ny = 0;
        Ball before_a{}, before_b{}, after_a{}, after_b{};
    } resolved_;
    std::vector<Limit> limits_;
    std::vector<int> group_;
};

WorldEngine::WorldEngine(const std::vector<Ball> &balls, const Table &table, const Model &model,
                         WorldBroadphase broadphase)
    : Engine(balls), model_(model), table_(table), walls_(is_closed_box(table)),
      offset_(is_closed_box(table) ? 0.0 : kMargin), faces_(table.cushions),
      use_tree_(broadphase != WorldBroadphase::Cells), use_list_(broadphase == WorldBroadphase::List) {
    for (const Pocket &p : table.pockets)
        for (const Jaw &j : p.jaws) faces_.push_back(j.facing);
    track_.resize(balls_.size());
    for (Ball &b : balls_) {
        if (!model_.friction) b.wx = b.wy = b.wz = 0;
        b.motion = motion_of(b);
    }
    build();
}

// The frictionless scenes have no rolling: a moving ball glides ("sliding").
Motion WorldEngine::motion_of(const Ball &b) const {
    if (model_.friction || !b.active) return classify(b);
    return b.vx != 0 || b.vy != 0 ? Motion::Sliding : Motion::Stationary;
}

// The table's statics in the world's order of indices (segments, circles
// and sensors share it): each rail's cushion, each pocket's jaws (facing,
// then nose), then each pocket's hole.  add false: only counts them.
void WorldEngine::add_statics(size_t &count, bool add) {
    const double o = offset_, e = model_.cushion.restitution;
    count = 0;
    auto segment = [&](const Segment &s, EventKind kind, int feature) {
        if (add && c2d_world_add_segment(world_, c2d_vec2{s.ax + o, s.ay + o}, c2d_vec2{s.bx + o, s.by + o}, e,
                                         nullptr) != C2D_OK)
            throw std::logic_error("world_engine: the world refused a cushion");
        if (add) statics_.push_back(Feature{kind, feature, false, 0, 0, 0});
        ++count;
    };
    if (walls_) return;
    for (size_t c = 0; c < table_.cushions.size(); ++c) segment(table_.cushions[c], EventKind::Cushion, static_cast<int>(c));
    for (size_t p = 0; p < table_.pockets.size(); ++p)
        for (int j = 0; j < 2; ++j) {
            const Jaw &jaw = table_.pockets[p].jaws[j];
            const int feature = static_cast<int>(p) * 2 + j;
            segment(jaw.facing, EventKind::Jaw, feature);
            if (add && c2d_world_add_circle(world_, c2d_vec2{jaw.nose_x + o, jaw.nose_y + o}, jaw.nose_r, e, nullptr) != C2D_OK)
                throw std::logic_error("world_engine: the world refused a jaw");
            if (add) statics_.push_back(Feature{EventKind::Jaw, feature, true, jaw.nose_x, jaw.nose_y, jaw.nose_r});
            ++count;
        }
    for (size_t p = 0; p < table_.pockets.size(); ++p) {
        const Pocket &k = table_.pockets[p];
        if (add && c2d_world_add_sensor(world_, c2d_vec2{k.x + o, k.y + o}, k.capture_radius, nullptr) != C2D_OK)
            throw std::logic_error("world_engine: the world refused a pocket");
        if (add) statics_.push_back(Feature{EventKind::Pocket, static_cast<int>(p), false, 0, 0, 0});
        ++count;
    }
}

// A new world at time 0 holding every ball on the table as it is now.
void WorldEngine::build() {
    c2d_world_desc d{};
    d.capacity = balls_.size();
    d.width = table_.length + 2 * offset_;
    d.height = table_.width + 2 * offset_;
    d.boundary = C2D_WALLS;
    d.restitution = model_.ball.restitution;
    d.wall_restitution = model_.cushion.restitution;
    d.on_event = &WorldEngine::on_event;
    d.user = this;
    if (model_.friction) {
        d.resolve_impact = &WorldEngine::resolve_impact;
        d.resolve_static = &WorldEngine::resolve_static;
    }
    if (use_tree_) {
        if (use_list_) {
            boxes_.clear();
            listed_.clear();
            tree_calls_ = c2d_world_broadphase{&WorldEngine::list_insert, &WorldEngine::list_move,
                                               &WorldEngine::list_remove, &WorldEngine::list_query, this, kListMargin};
        } else {
            tree_ = make_dynamic_tree();
            proxy_.clear();
            tree_calls_ = c2d_world_broadphase{&WorldEngine::tree_insert, &WorldEngine::tree_move,
                                               &WorldEngine::tree_remove, &WorldEngine::tree_query, this, 0};
        }
        d.broadphase = &tree_calls_;
    }
    add_statics(d.statics, false);
    const size_t bytes = c2d_world_bytes(&d);
    memory_.assign(bytes / sizeof(uint64_t) + 1, 0);
    if (bytes == 0 || c2d_world_init(&world_, memory_.data(), memory_.size() * sizeof(uint64_t), &d) != C2D_OK)
        throw std::logic_error("world_engine: the world refused the table");
    statics_.clear();
    add_statics(d.statics, true);
    epoch_ += world_now_;
    world_now_ = 0;
    instant_.assign(balls_.size(), -1);  // the new world's clock starts at 0
    at_once_.assign(balls_.size(), 0);
    fixed_instant_.assign(balls_.size(), -1);
    fixed_at_once_.assign(balls_.size(), 0);
    world_index_.assign(balls_.size(), kNoDisk);
    ball_of_.clear();
    for (size_t i = 0; i < balls_.size(); ++i) {
        if (!balls_[i].active) {
            track_[i] = make_track(balls_[i], 0, model_.cloth, model_.friction);
            continue;
        }
        world_index_[i] = add(i);
        ball_of_.push_back(static_cast<int>(i));
    }
    for (size_t i = 0; i < balls_.size(); ++i)
        if (balls_[i].active) restart(static_cast<int>(i), balls_[i], 0, false, true);
}

// Ball i into the world.  Touching balls (a rack, the cradle's row) can be
// an ulp inside each other after rounding, which the world refuses: such a
// ball goes in where it just touches, moved out along the line of centres
// from the ball it overlaps an ulp at a time.
size_t WorldEngine::add(size_t i) {
    Ball &b = balls_[i];
    for (int tries = 0; tries < 64; ++tries) {
        const c2d_body body{{b.x + offset_, b.y + offset_}, {b.vx, b.vy}, kBallMass};
        size_t disk;
        if (c2d_world_add(world_, &body, kBallRadius, &disk) == C2D_OK) return disk;
        const int other = overlapped(b);
        if (other < 0) break;
        const Ball &o = balls_[static_cast<size_t>(other)];
        const double dx = b.x - o.x, dy = b.y - o.y;
        if (!(det_hypot(dx, dy) > kBallDiameter * (1 - 1e-12))) break;  // a real overlap, not rounding
        b.x = dx == 0 ? b.x : std::nextafter(b.x, dx > 0 ? INFINITY : -INFINITY);
        b.y = dy == 0 ? b.y : std::nextafter(b.y, dy > 0 ? INFINITY : -INFINITY);
    }
    throw std::logic_error("world_engine: the world refused ball " + std::to_string(b.number));
}

// A ball already in the world that b overlaps (in the world's
// coordinates), or -1.
int WorldEngine::overlapped(const Ball &b) const {
    for (int k : ball_of_) {
        const Ball &o = balls_[static_cast<size_t>(k)];
        const double dx = (o.x + offset_) - (b.x + offset_), dy = (o.y + offset_) - (b.y + offset_);
        if (dx * dx + dy * dy < kBallDiameter * kBallDiameter) return k;
    }
    return -1;
}

// --- states ------------------------------------------------------------

// Ball i at world time t with the world's position and velocity (table
// coordinates) and the spin of its track; a rolling ball's spin follows
// its velocity exactly (u = 0).
Ball WorldEngine::with_spin(int i, double t, double x, double y, double vx, double vy) const {
    const Track &k = track_[static_cast<size_t>(i)];
    Ball b = state_at(k, t);
    b.x = x, b.y = y, b.vx = vx, b.vy = vy;
    if (b.motion == Motion::Rolling) {
        b.wx = -vy / kBallRadius;
        b.wy = vx / kBallRadius;
    }
    return b;
}

// Disk `disk` as the world has it now (during an event: at its time).
Ball WorldEngine::state_of(size_t disk, double t) const {
    c2d_body body;
    c2d_world_get(world_, disk, &body);
    const int i = ball_of_[disk];
    if (!model_.friction) {
        Ball b = balls_[static_cast<size_t>(i)];
        b.x = body.pos.x - offset_, b.y = body.pos.y - offset_, b.vx = body.vel.x, b.vy = body.vel.y;
        b.motion = motion_of(b);
        return b;
    }
    return with_spin(i, t, body.pos.x - offset_, body.pos.y - offset_, body.vel.x, body.vel.y);
}

// Ball i at world time t from its track alone (the world's position to
// rounding): for the slow contacts' geometry.
Ball WorldEngine::ball_at(int i, double t) const {
    const Ball &b = balls_[static_cast<size_t>(i)];
    return b.active ? state_at(track_[static_cast<size_t>(i)], t) : b;
}

// Ball i takes state b (its motion state set) at world time t: a new track,
// and in the world its acceleration and a timer at the track's end
// (set_velocity: its velocity too, when the world has not set it).  fresh:
// the disk was just added to a new world (at its time 0, with no
// acceleration and no timer), so setting an acceleration of +0 or no timer
// would change nothing but the disk's count and cost a prediction each
// (a ball at rest: two of the three predictions of every ball in every new
// world, the opponent's candidates' included); they are left out.
void WorldEngine::restart(int i, const Ball &b, double t, bool set_velocity, bool fresh) {
    const size_t k = static_cast<size_t>(i), disk = world_index_[k];
    track_[k] = make_track(b, t, model_.cloth, model_.friction);
    if (set_velocity) c2d_world_set_velocity(world_, disk, c2d_vec2{b.vx, b.vy});
    if (model_.friction) {
        const Track &n = track_[k];
        const bool no_acceleration = n.ax == 0 && n.ay == 0 && !std::signbit(n.ax) && !std::signbit(n.ay);
        if (!(fresh && no_acceleration)) c2d_world_set_acceleration(world_, disk, c2d_vec2{n.ax, n.ay});
        if (!(fresh && n.t_end == INFINITY)) c2d_world_set_timer(world_, disk, n.t_end);
    }
    waypoint(i);
}

// --- contacts ----------------------------------------------------------

c2d_status WorldEngine::resolve_impact(void *user, const c2d_world_contact *c, c2d_body *a, c2d_body *b) {
    return static_cast<WorldEngine *>(user)->resolve_pair(*c, *a, *b);
}

c2d_status WorldEngine::resolve_static(void *user, const c2d_world_contact *c, c2d_body *a, c2d_body *) {
    return static_cast<WorldEngine *>(user)->resolve_fixed(*c, *a);
}

// Two balls: absorbed if slower than absorb_below (each in turn against all
// it touches, the other one's new state included), else rough.
c2d_status WorldEngine::resolve_pair(const c2d_world_contact &c, c2d_body &a, c2d_body &b) {
    const int ia = ball_of_[c.a], ib = ball_of_[c.b];
    count_contact(ia, c.time);
    count_contact(ib, c.time);
    if (crowded(ia, c.time) || crowded(ib, c.time)) return C2D_INVALID;
    const Ball sa = with_spin(ia, c.time, a.pos.x - offset_, a.pos.y - offset_, a.vel.x, a.vel.y);
    const Ball sb = with_spin(ib, c.time, b.pos.x - offset_, b.pos.y - offset_, b.vel.x, b.vel.y);
    const double d = det_hypot(c.normal.x, c.normal.y), nx = c.normal.x / d, ny = c.normal.y / d;
    Resolved r;
    r.seen = true;
    r.a = c.a, r.b = c.b, r.t = c.time, r.nx = nx, r.ny = ny, r.before_a = sa, r.before_b = sb;
    if ((sa.vx - sb.vx) * nx + (sa.vy - sb.vy) * ny < model_.absorb_below) {
        // (if that leaves them approaching by rounding, the world bounces
        // them itself; on_event still sees an absorbed contact)
        r.absorbed = true;
        r.after_a = absorbed(ia, c.time, sa, ib, &sb);
        r.after_b = absorbed(ib, c.time, sb, ia, &r.after_a);
    } else {
        r.after_a = sa, r.after_b = sb;
        if (!collide_balls(model_, c.restitution, r.after_a, r.after_b)) {
            r.after_a = r.after_b = Ball{};
            resolved_ = r;  // a graze: the world's own rule, no spin changed
            return C2D_INVALID;
        }
        r.after_a.motion = motion_of(r.after_a);
        r.after_b.motion = motion_of(r.after_b);
    }
    a.vel = c2d_vec2{r.after_a.vx, r.after_a.vy};
    b.vel = c2d_vec2{r.after_b.vx, r.after_b.vy};
    resolved_ = r;
    return C2D_OK;
}

// A cushion face, jaw facing or nose: absorbed if slower than absorb_below,
// else rough against an immovable wall at the contact point or the nose.
c2d_status WorldEngine::resolve_fixed(const c2d_world_contact &c, c2d_body &a) {
    const int i = ball_of_[c.a];
    // More than kMostAtOnce contacts of a ball with the statics at one
    // instant: the world's own resolution (its collapse rule ends it).
    // Without it a ball pressed into a jaw by its slide took the pool
    // model's absorbed contact again and again at one instant for ever (an
    // opponent's position-play run, seed 6).  Counted apart from the
    // ball-ball contacts, so no pair's count changes.
    const size_t k = static_cast<size_t>(i);
    if (fixed_instant_[k] == c.time) ++fixed_at_once_[k];
    else fixed_instant_[k] = c.time, fixed_at_once_[k] = 1;
    if (fixed_at_once_[k] > kMostAtOnce) return C2D_INVALID;
    const Feature &f = statics_[c.b];
    const Ball sa = with_spin(i, c.time, a.pos.x - offset_, a.pos.y - offset_, a.vel.x, a.vel.y);
    const double d = det_hypot(c.normal.x, c.normal.y), nx = c.normal.x / d, ny = c.normal.y / d;
    Resolved r;
    r.seen = true;
    r.a = c.a, r.b = c.b, r.t = c.time, r.nx = nx, r.ny = ny, r.before_a = sa;
    if (sa.vx * nx + sa.vy * ny < model_.absorb_below) {
        r.absorbed = true;
        r.after_a = absorbed(i, c.time, sa, -1, nullptr);
    } else {
        r.after_a = sa;
        if (!(f.nose ? collide_nose(model_, c.restitution, r.after_a, f.x, f.y, f.r)
                     : collide_face(model_, c.restitution, r.after_a, nx, ny))) {
            r.after_a = Ball{};
            resolved_ = r;  // a graze: the world's own rule, no spin changed
            return C2D_INVALID;
        }
    }
    r.after_a.motion = motion_of(r.after_a);
    a.vel = c2d_vec2{r.after_a.vx, r.after_a.vy};
    resolved_ = r;
    return C2D_OK;
}

// The constraints of everything ball i (in state b) touches at time t:
// other balls (moving away at their own speed along the line of centres;
// the partner in the state given) and the faces and noses.
void WorldEngine::limits_of(int i, double t, const Ball &b, int partner, const Ball *partner_state,
                            std::vector<Limit> &out) const {
    out.clear();
    const double reach = kBallDiameter * (1 + 1e-9);
    for (int k : ball_of_) {
        if (k == i || !balls_[static_cast<size_t>(k)].active) continue;
        const Ball o = partner_state != nullptr && k == partner ? *partner_state : ball_at(k, t);
        const double dx = o.x - b.x, dy = o.y - b.y, d = det_hypot(dx, dy);
        // a ball moving off lets b follow at its speed; one coming at b
        // is held back when it is absorbed itself, not b pushed away
        if (d > 0 && d <= reach) out.push_back(Limit{dx / d, dy / d, std::max(0.0, (o.vx * dx + o.vy * dy) / d)});
    }
    for (const Segment &w : faces_) {
        const double ex = w.bx - w.ax, ey = w.by - w.ay, along = (b.x - w.ax) * ex + (b.y - w.ay) * ey;
        const double gap = (b.x - w.ax) * w.nx + (b.y - w.ay) * w.ny - kBallRadius;
        // (a face a diameter behind the ball is no contact: the far side of a rail)
        if (along >= 0 && along <= ex * ex + ey * ey && gap <= kBallDiameter * 1e-9 && gap >= -kBallDiameter)
            out.push_back(Limit{-w.nx, -w.ny, 0});
    }
    for (const Feature &f : statics_) {
        if (!f.nose) continue;
        const double dx = f.x - b.x, dy = f.y - b.y, d = det_hypot(dx, dy);
        if (d <= (kBallRadius + f.r) * (1 + 1e-9)) out.push_back(Limit{dx / d, dy / d, 0});
    }
}

// Ball i at time t after an absorbed contact (Model::absorb_below): its
// velocity becomes the nearest that approaches nothing it touches.  Left
// slower than absorb_below it stops (top and back spin too: a slow ball
// pressed into others would otherwise keep pushing).  Else, if its spin is
// at least rolling speed (R |w_xy| >= |v|), the contacts take its slip and
// it rolls (w_xy from v), else its spin's rolling velocity
// v_roll = R (wy, -wx), towards which friction pulls it, is limited the same
// way.  Energy only decreases.
Ball WorldEngine::absorbed(int i, double t, const Ball &before, int partner, const Ball *partner_state) {
    Ball b = before;
    limits_of(i, t, b, partner, partner_state, limits_);
    nearest_within(b.vx, b.vy, limits_);
    if (det_hypot(b.vx, b.vy) < model_.absorb_below) {
        b.vx = b.vy = 0;
        roll(b);
    } else if (kBallRadius * det_hypot(b.wx, b.wy) >= det_hypot(b.vx, b.vy)) {
        roll(b);
    } else {
        double rx = kBallRadius * b.wy, ry = -kBallRadius * b.wx;
        nearest_within(rx, ry, limits_);
        b.wx = -ry / kBallRadius;
        b.wy = rx / kBallRadius;
        b.motion = motion_of(b);
    }
    return b;
}

// The balls in sustained contact with a and b at t: those touching them,
// directly or through others, and not moving apart along the line of
// centres faster than absorb_below.
void WorldEngine::pressed_group(int a, int b, double t, std::vector<int> &group) const {
    group = {a, b};
    const double reach = kBallDiameter * (1 + 1e-9);
    for (size_t k = 0; k < group.size(); ++k) {
        const Ball m = ball_at(group[k], t);
        for (int index : ball_of_) {
            if (!balls_[static_cast<size_t>(index)].active || std::find(group.begin(), group.end(), index) != group.end())
                continue;
            const Ball o = ball_at(index, t);
            const double dx = o.x - m.x, dy = o.y - m.y, d = det_hypot(dx, dy);
            if (d <= reach && ((o.vx - m.vx) * dx + (o.vy - m.vy) * dy) / d <= model_.absorb_below) group.push_back(index);
        }
    }
}

// A sustained contact: the accelerations press a and b together, so
// absorbing velocities alone would only bring them back into contact an
// instant later, again and again.  If any ball of the group in contact
// (pressed_group) slides, the sliding ones end their slides at once (the
// state each slide would end in: less energy); else the group moves on as
// one, every ball taking its mean velocity and z spin and rolling (momentum
// kept, energy lost).
void WorldEngine::move_together(int a, int b, double t) {
    std::vector<int> &group = group_;
    pressed_group(a, b, t, group);
    for (int m : group) {  // slides end
        const Ball before = ball_at(m, t), s = slid(before);
        if (!same_motion(s, before)) restart(m, s, t, true);
    }
    if (closing_by_acceleration(a, b, t) <= 0) return;
    double vx = 0, vy = 0, wz = 0;  // all roll or stand: they move on as one
    for (int m : group) {
        const Ball s = ball_at(m, t);
        vx += s.vx, vy += s.vy, wz += s.wz;
    }
    const double n = static_cast<double>(group.size());
    for (int m : group) {
        const Ball before = ball_at(m, t);
        Ball s = before;
        s.vx = vx / n, s.vy = vy / n, s.wz = wz / n;
        roll(s);
        if (!same_motion(s, before)) restart(m, s, t, true);
    }
}

// A crowded pair (count_contact) moves on as one: both take their mean
// velocity and z spin and roll (momentum kept, energy lost), so they
// neither approach nor press each other (the same velocity and the same
// deceleration), and the instant ends.  Without it the world's own
// resolution and the tracks' state changes pass an approach of a few ulp
// back and forth for ever (a ball rolling tangentially past one at rest,
// its deceleration pressing into it by rounding: the impact gives the
// resting ball 1e-19 m/s, its slide and roll end at once, the approach is
// back).
void WorldEngine::join(int a, int b, double t) {
    Ball sa = ball_at(a, t), sb = ball_at(b, t);
    const double vx = 0.5 * (sa.vx + sb.vx), vy = 0.5 * (sa.vy + sb.vy), wz = 0.5 * (sa.wz + sb.wz);
    for (Ball *s : {&sa, &sb}) {
        s->vx = vx, s->vy = vy, s->wz = wz;
        roll(*s);
    }
    restart(a, sa, t, true);
    restart(b, sb, t, true);
}

// How fast the accelerations of balls a and b (their current tracks) close
// their line of centres at time t, m/s^2 (> 0: pressing together).
double WorldEngine::closing_by_acceleration(int a, int b, double t) const {
    const Track &ta = track_[static_cast<size_t>(a)], &tb = track_[static_cast<size_t>(b)];
    double ax, ay, bx, by;
    position_at(ta, t, ax, ay);
    position_at(tb, t, bx, by);
    const double dx = bx - ax, dy = by - ay, d = det_hypot(dx, dy);
    return ((ta.ax - tb.ax) * dx + (ta.ay - tb.ay) * dy) / d;
}

// --- Box2D's tree as the world's broadphase -------------------------------

// The world's boxes in the tree's float coordinates, in millimetres: the
// tree fattens every box by b2_aabbExtension (0.1 of its unit), a tenth of
// a millimetre there instead of 10 cm (three balls) in metres.  Rounded
// outwards (lo down, hi up), so every pair of boxes that overlap in double
// overlap in float: more candidates at most, never fewer (a missed impact).
constexpr double kTreeUnit = 1024;  // a power of two: the scaling itself is exact

float float_down(double v) {
    const float f = static_cast<float>(v);
    return static_cast<double>(f) > v ? std::nextafter(f, -INFINITY) : f;
}

float float_up(double v) {
    const float f = static_cast<float>(v);
    return static_cast<double>(f) < v ? std::nextafter(f, INFINITY) : f;
}

b2AABB tree_box(const c2d_world_box &b) {
    b2AABB a;
    a.lowerBound.Set(float_down(b.lo.x * kTreeUnit), float_down(b.lo.y * kTreeUnit));
    a.upperBound.Set(float_up(b.hi.x * kTreeUnit), float_up(b.hi.y * kTreeUnit));
    return a;
}

void WorldEngine::tree_insert(void *user, size_t disk, const c2d_world_box *box) {
    WorldEngine &w = *static_cast<WorldEngine *>(user);
    if (w.proxy_.size() <= disk) w.proxy_.resize(disk + 1, b2_nullNode);
    w.proxy_[disk] = w.tree_->add(tree_box(*box), disk);
}

void WorldEngine::tree_move(void *user, size_t disk, const c2d_world_box *box) {
    WorldEngine &w = *static_cast<WorldEngine *>(user);
    w.tree_->move(w.proxy_[disk], tree_box(*box));
}

void WorldEngine::tree_remove(void *user, size_t disk) {
    WorldEngine &w = *static_cast<WorldEngine *>(user);
    w.tree_->remove(w.proxy_[disk]);
    w.proxy_[disk] = b2_nullNode;
}

// Every disk whose box overlaps `box` (the tree's answer: touching counts).
// A query runs inside a prediction, never inside another query, so one
// list of tags serves.
void WorldEngine::tree_query(void *user, const c2d_world_box *box, c2d_world_report report, void *context) {
    WorldEngine &w = *static_cast<WorldEngine *>(user);
    w.found_.clear();
    w.tree_->query(tree_box(*box), w.found_);
    for (uintptr_t tag : w.found_) report(context, static_cast<size_t>(tag));
}

// --- a plain list as the world's broadphase -----------------------------

// Every disk's box in an array by disk, a query comparing it with each: on
// the pool table's 16 balls 16 comparisons of doubles cost less than one
// descent of the tree, a move is one store (the tree removes, re-inserts and
// rebalances a leaf), and no box is rounded to float.  Touching counts (as
// the tree's b2TestOverlap); the world's results are the same bits whatever
// broadphase finds the candidates.
void WorldEngine::list_insert(void *user, size_t disk, const c2d_world_box *box) {
    WorldEngine &w = *static_cast<WorldEngine *>(user);
    if (w.boxes_.size() <= disk) {
        w.boxes_.resize(disk + 1);
        w.listed_.resize(disk + 1, 0);
    }
    w.boxes_[disk] = *box;
    w.listed_[disk] = 1;
}

void WorldEngine::list_move(void *user, size_t disk, const c2d_world_box *box) {
    static_cast<WorldEngine *>(user)->boxes_[disk] = *box;
}

void WorldEngine::list_remove(void *user, size_t disk) { static_cast<WorldEngine *>(user)->listed_[disk] = 0; }

void WorldEngine::list_query(void *user, const c2d_world_box *box, c2d_world_report report, void *context) {
    const WorldEngine &w = *static_cast<const WorldEngine *>(user);
    const c2d_world_box q = *box;
    for (size_t disk = 0; disk < w.boxes_.size(); ++disk) {
        const c2d_world_box &b = w.boxes_[disk];
        if (w.listed_[disk] && b.lo.x <= q.hi.x && q.lo.x <= b.hi.x && b.lo.y <= q.hi.y && q.lo.y <= b.hi.y)
            report(context, disk);
    }
}

// --- events ------------------------------------------------------------

void WorldEngine::on_event(void *user, const c2d_world_event *event) {
    WorldEngine &w = *static_cast<WorldEngine *>(user);
    w.last_event_ = event->time;
    switch (event->kind) {
    case C2D_WORLD_IMPACT: w.impact(*event); break;
    case C2D_WORLD_WALL:
    case C2D_WORLD_STATIC: w.fixed(*event); break;
    case C2D_WORLD_TIMER: w.timer(*event); break;
    case C2D_WORLD_SENSOR: w.pocket(*event); break;
    }
    w.resolved_.seen = false;
}

// Ball i just after an event at t: its new track's start, or as it was.
Ball WorldEngine::after_event(int i, double t) const {
    const size_t k = static_cast<size_t>(i);
    if (!balls_[k].active) return balls_[k];  // pocketed: where it fell
    return track_[k].t0 == t ? track_[k].start : state_of(world_index_[k], t);
}

// Event records carry the ball's state just after the event.
void WorldEngine::record(double t, EventKind kind, int ball, int other, int feature, double impulse) {
    const Ball b = after_event(ball, t);
    log_->events.push_back(Event{epoch_ + t, kind, ball, other, feature, b.x, b.y, b.vx, b.vy, b.wx, b.wy, b.wz, impulse});
}

// Where ball i's new track starts, for the checker.
void WorldEngine::waypoint(int i) {
    if (!log_ || !record_paths_) return;
    const Track &k = track_[static_cast<size_t>(i)];
    log_->waypoints.push_back(Waypoint{i, k.t0 - frame_start_, k.start.x, k.start.y, k.start.vx, k.start.vy, k.ax, k.ay});
}

// The world's rest rule for a pair pressed together by their accelerations
// takes each one's component towards the other away (they rest on each
// other); imposing the track's again would press them back at once, an
// endless stream of impacts at one instant, so the track takes the world's
// (the checker's waypoint with it).
void WorldEngine::take_resting_acceleration(int i) {
    const size_t k = static_cast<size_t>(i);
    c2d_vec2 a;
    if (c2d_world_get_acceleration(world_, world_index_[k], &a) != C2D_OK || (a.x == track_[k].ax && a.y == track_[k].ay))
        return;
    Ball rested = state_of(world_index_[k], last_event_);
    rested.motion = track_[k].start.motion;
    track_[k].start = rested, track_[k].t0 = last_event_;
    track_[k].ax = a.x, track_[k].ay = a.y;
    waypoint(i);
}

// A ball's contacts at one instant are counted, per ball, whichever pair
// they are with: a slow contact the pool model and the world's rest rule
// pass back and forth (the model's track pressing the pair together
// again) can cycle through several pairs (6-10, 10-14, 6-10, ...), and a
// count that any other pair resets never ends it.  A ball with more than
// kMostAtOnce contacts at one instant is crowded: its contacts there are
// the world's own (resolution, rest rule, collapse rule, which end), with
// no change of ours.  The count depends on the events alone, never on how
// the advance is sliced into frames.
void WorldEngine::count_contact(int i, double t) {
    const size_t k = static_cast<size_t>(i);
    if (instant_[k] == t) ++at_once_[k];
    else instant_[k] = t, at_once_[k] = 1;
}

bool WorldEngine::crowded(int i, double t) const {
    const size_t k = static_cast<size_t>(i);
    return instant_[k] == t && at_once_[k] > kMostAtOnce;
}

// Whether event e is the contact a resolver has just seen.
bool WorldEngine::resolving(const c2d_world_event &e) const {
    return resolved_.seen && resolved_.a == e.a && resolved_.b == e.b && resolved_.t == e.time;
}

// Whether the world kept the velocity a resolver gave (w: the world's state
// after the contact).
bool kept(const Ball &w, const Ball &given) { return w.vx == given.vx && w.vy == given.vy; }

// State s where the world has the ball (w).
Ball with_position(Ball s, const Ball &w) {
    s.x = w.x, s.y = w.y;
    return s;
}

void WorldEngine::impact(const c2d_world_event &e) {
    const int ia = ball_of_[e.a], ib = ball_of_[e.b];
    Ball a = state_of(e.a, e.time), b = state_of(e.b, e.time);
    // a crowded ball's contact is the world's own (its resolver refused)
    const bool mine = resolving(e) && !crowded(ia, e.time) && !crowded(ib, e.time);
    if (mine && kept(a, resolved_.after_a) && kept(b, resolved_.after_b)) {  // the resolver's spins
        a = with_position(resolved_.after_a, a), b = with_position(resolved_.after_b, b);
    } else {  // the world's own resolution: no spin changed
        a.motion = motion_of(a), b.motion = motion_of(b);
    }
    // a ball the contact left as it was keeps its track
    if (!mine || !same_motion(a, resolved_.before_a)) restart(ia, a, e.time, false);
    if (!mine || !same_motion(b, resolved_.before_b)) restart(ib, b, e.time, false);
    take_resting_acceleration(ia);
    take_resting_acceleration(ib);
    if (mine && resolved_.absorbed && closing_by_acceleration(ia, ib, e.time) > 0) move_together(ia, ib, e.time);
    else if (!mine && (crowded(ia, e.time) || crowded(ib, e.time))) join(ia, ib, e.time);
    ++stats_->ball_ball_collisions;
    if (record_paths_) log_->contacts.push_back(pair_key(ia, ib));
    double impulse = det_hypot(e.impulse.x, e.impulse.y);
    if (mine) {
        const Ball after = after_event(ia, e.time);
        impulse = kBallMass * std::fabs((after.vx - resolved_.before_a.vx) * resolved_.nx +
                                        (after.vy - resolved_.before_a.vy) * resolved_.ny);
    }
    // one record for each ball, the lower-numbered first
    const bool a_first = balls_[static_cast<size_t>(ia)].number <= balls_[static_cast<size_t>(ib)].number;
    record(e.time, EventKind::BallBall, a_first ? ia : ib, a_first ? ib : ia, -1, impulse);
    record(e.time, EventKind::BallBall, a_first ? ib : ia, a_first ? ia : ib, -1, impulse);
}

// A wall of the box, or a static: a cushion face, jaw facing or nose.
void WorldEngine::fixed(const c2d_world_event &e) {
    const int i = ball_of_[e.a];
    Ball a = state_of(e.a, e.time);
    const bool mine = resolving(e);
    double impulse = det_hypot(e.impulse.x, e.impulse.y);
    if (mine && kept(a, resolved_.after_a)) a = with_position(resolved_.after_a, a);
    else a.motion = motion_of(a);  // the world's own resolution: no spin changed
    if (mine)
        impulse = kBallMass * std::fabs((a.vx - resolved_.before_a.vx) * resolved_.nx +
                                        (a.vy - resolved_.before_a.vy) * resolved_.ny);
    if (!mine || !same_motion(a, resolved_.before_a)) restart(i, a, e.time, false);
    ++stats_->cushion_collisions;
    EventKind kind = EventKind::Cushion;
    int feature = e.kind == C2D_WORLD_WALL ? kCushionOfWall[e.b] : -1;
    if (e.kind == C2D_WORLD_STATIC) kind = statics_[e.b].kind, feature = statics_[e.b].feature;
    record(e.time, kind, i, -1, feature, impulse);
}

// A track's end: rolling (w from v exactly), spinning in place, or at rest
// (v and w exactly 0), named by the state entered.
void WorldEngine::timer(const c2d_world_event &e) {
    const int i = ball_of_[e.a];
    const Motion was = track_[static_cast<size_t>(i)].start.motion;
    Ball b = state_of(e.a, e.time);
    bool stopped = false;
    if (was == Motion::Sliding) {
        roll(b);
    } else if (was == Motion::Rolling) {
        b.vx = b.vy = b.wx = b.wy = 0;
        b.motion = b.wz != 0 ? Motion::Spinning : Motion::Stationary;
        stopped = true;
    } else {
        b.wz = 0;
        b.motion = Motion::Stationary;
    }
    restart(i, b, e.time, stopped);
    EventKind kind = EventKind::Stop;
    if (b.motion == Motion::Rolling) kind = EventKind::SlideToRoll;
    else if (b.motion == Motion::Spinning) kind = EventKind::RollToSpin;
    record(e.time, kind, i, -1, -1, 0);
}

// A ball's centre has entered a hole: it falls, out of the world.
void WorldEngine::pocket(const c2d_world_event &e) {
    const int i = ball_of_[e.a];
    const size_t k = static_cast<size_t>(i);
    const Ball a = state_of(e.a, e.time);
    c2d_world_remove(world_, e.a);
    world_index_[k] = kNoDisk;
    Ball &b = balls_[k];
    b = a;
    b.vx = b.vy = b.wx = b.wy = b.wz = 0;
    b.active = false;
    b.motion = Motion::Pocketed;
    track_[k] = make_track(b, e.time, model_.cloth, model_.friction);
    if (b.number == 0) ++stats_->scratches;
    else ++stats_->pocketed;
    record(e.time, EventKind::Pocket, i, -1, statics_[e.b].feature, kBallMass * det_hypot(a.vx, a.vy));
}

// --- running -------------------------------------------------------------

// sample_after false: balls_ keeps the states of the last sample (settle
// samples once at its end: nothing during a run reads an active ball's
// state from balls_, only its number and whether it is on the table).
void WorldEngine::advance(double world_t, Stats &stats, FrameLog &log, bool record_paths, bool sample_after) {
    stats_ = &stats, log_ = &log, frame_start_ = world_now_, record_paths_ = record_paths;
    c2d_world_advance(world_, world_t);
    world_now_ = world_t;
    stats_ = nullptr, log_ = nullptr;
    if (sample_after) sample();
}

void WorldEngine::sample() {
    for (size_t disk = 0; disk < ball_of_.size(); ++disk) {
        Ball &b = balls_[static_cast<size_t>(ball_of_[disk])];
        if (b.active) b = state_of(disk, world_now_);
    }
}

bool WorldEngine::moving() const {
    for (size_t i = 0; i < balls_.size(); ++i)
        if (balls_[i].active && track_[i].start.motion != Motion::Stationary) return true;
    return false;
}

void WorldEngine::step(double dt, Stats &stats, FrameLog &log) {
    // accelerating balls curve: the checker needs their motion from the start
    for (size_t i = 0; i < balls_.size(); ++i) {
        const Track &k = track_[i];
        if (balls_[i].active && (k.ax != 0 || k.ay != 0)) {
            const Ball &b = balls_[i];
            log.waypoints.push_back(Waypoint{static_cast<int>(i), 0, b.x, b.y, b.vx, b.vy, k.ax, k.ay});
        }
    }
    advance(world_now_ + dt, stats, log, true);
}

// Runs a second of the world at a time (a quarter with a stop question,
// asked after each) until every ball stands still (the last event's time
// is then the run's end), max_seconds are over or the question says stop;
// the world's frame independence makes the chunks the same as one advance.
bool WorldEngine::settle(double max_seconds, Stats &stats, FrameLog &log) {
    const double end = world_now_ + max_seconds;
    last_event_ = world_now_;
    const double stretch = stop_ ? kStopStretch : 1.0;
    while (moving() && world_now_ < end) {
        advance(std::min(end, world_now_ + stretch), stats, log, false, false);
        if (stop_ && moving() && stop_(log.events)) break;
    }
    sample();
    settled_ = !moving();
    return settled_;
}

void WorldEngine::set_motion(int i, const Ball &state) {
    const size_t k = static_cast<size_t>(i);
    if (!balls_[k].active) return;
    Ball b = state_of(world_index_[k], world_now_);
    b.vx = state.vx;
    b.vy = state.vy;
    if (model_.friction) b.wx = state.wx, b.wy = state.wy, b.wz = state.wz;
    b.motion = motion_of(b);
    restart(i, b, world_now_, true);
    balls_[k] = state_of(world_index_[k], world_now_);
}

void WorldEngine::place_ball(int i, Point p) {
    Ball &b = balls_[static_cast<size_t>(i)];
    if (b.active) return;
    b = Ball{p.x, p.y, 0, 0, b.number, true};
    build();
}

}  // namespace

std::unique_ptr<Engine> make_world_engine(const std::vector<Ball> &balls, const Table &table, const Model &model,
                                          WorldBroadphase broadphase) {
    return std::unique_ptr<Engine>(new WorldEngine(balls, table, model, broadphase));
}

}  // namespace demo
