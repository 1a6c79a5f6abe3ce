/* SPDX-License-Identifier: MIT */
// headless.cpp - see headless.h.  Output files are opened before
// simulating, and any write error is reported (exit 1).
#include "app/headless.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "app/cli.h"
#include "app/render.h"
#include "game/game.h"
#include "pool/cradle.h"
#include "pool/sim.h"

namespace {

using demo::Options;
using demo::Response;
using demo::Scene;
using demo::Shot;
using demo::Simulation;
using demo::UsageError;

// An output file, opened up front; every write error is kept and reported
// when it is closed.
class OutFile {
public:
    OutFile() = default;
    explicit OutFile(const std::string &path, const char *mode = "w") : path_(path) {
        if (path.empty()) return;
        f_ = std::fopen(path.c_str(), mode);
        if (!f_) throw UsageError{path + ": " + std::strerror(errno)};
    }
    OutFile(const OutFile &) = delete;
    OutFile &operator=(const OutFile &) = delete;
    ~OutFile() {
        if (f_) std::fclose(f_);
    }
    FILE *get() const { return f_; }
    // Closes the file; false (with the reason in error) if anything failed.
    bool close(std::string &error) {
        if (!f_) return true;
        const bool failed = std::ferror(f_) != 0;
        const int saved = errno;
        const bool closed = std::fclose(f_) == 0;
        f_ = nullptr;
        if (failed || !closed) {
            error = path_ + ": " + std::strerror(failed ? (saved ? saved : EIO) : errno);
            return false;
        }
        return true;
    }

private:
    std::string path_;
    FILE *f_ = nullptr;
};

struct Totals {
    double energy_start = 0, energy_end = 0, wall_seconds = 0;
    double momentum_start[2] = {0, 0}, momentum_end[2] = {0, 0};
    std::unique_ptr<demo::CradleOutcome> cradle;  // the cradle scene only
};

// --trace and --events, written as the frames go, and the cradle's check
// watching them.
class Recorder {
public:
    explicit Recorder(const Options &o) : trace_(o.trace), events_(o.events) {
        if (trace_.get()) std::fputs("time,kinetic_energy,momentum_x,momentum_y\n", trace_.get());
        if (events_.get()) std::fputs("time,kind,ball,other,x,y,vx,vy,wx,wy,wz\n", events_.get());
    }
    void watch_cradle(const Simulation &sim) { cradle_.reset(new demo::CradleCheck(sim.balls())); }
    const demo::CradleCheck *cradle() const { return cradle_.get(); }
    void frame(const Simulation &sim) {
        if (cradle_) cradle_->frame(sim.frame_events());
        if (trace_.get()) {
            double p[2];
            sim.momentum(p);
            std::fprintf(trace_.get(), "%.6f,%.17g,%.17g,%.17g\n", sim.stats().sim_seconds, sim.energy(), p[0], p[1]);
        }
        if (events_.get()) {
            const std::vector<demo::Ball> &balls = sim.balls();
            for (const demo::Event &e : sim.frame_events()) {
                const int other = e.other < 0 ? -1 : balls[static_cast<size_t>(e.other)].number;
                std::fprintf(events_.get(), "%.17g,%s,%d,%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", e.t,
                             demo::event_name(e.kind), balls[static_cast<size_t>(e.ball)].number, other, e.x, e.y, e.vx,
                             e.vy, e.wx, e.wy, e.wz);
            }
        }
    }
    bool close(std::string &error) { return trace_.close(error) && events_.close(error); }

private:
    OutFile trace_, events_;
    std::unique_ptr<demo::CradleCheck> cradle_;
};

// Shows how far a long run has got, on a terminal only.
class Progress {
public:
    explicit Progress(double seconds) : total_(seconds), on_(isatty(STDERR_FILENO) != 0), start_(Clock::now()), last_(start_) {}
    void frame(const Simulation &sim) {
        if (!on_ || (sim.stats().steps & 63) != 0) return;
        const Clock::time_point now = Clock::now();
        if (now - last_ < std::chrono::milliseconds(500) || now - start_ < std::chrono::seconds(1)) return;
        last_ = now;
        shown_ = true;
        if (total_ > 0)
            std::fprintf(stderr, "\rbilliards: simulated %.0f of %.0f s (%.0f%%)  ", sim.time(), total_,
                         100 * sim.time() / total_);
        else
            std::fprintf(stderr, "\rbilliards: simulated %.0f s, not at rest yet  ", sim.time());
    }
    ~Progress() {
        if (shown_) std::fprintf(stderr, "\r%60s\r", "");
    }
    Progress(const Progress &) = delete;
    Progress &operator=(const Progress &) = delete;

private:
    using Clock = std::chrono::steady_clock;
    double total_;
    bool on_, shown_ = false;
    Clock::time_point start_, last_;
};

// Shots are played one after another, each once the table is at rest; without
// --seconds the run ends when the last shot has come to rest (or after an
// hour of simulated time a shot: a safety net, reported).
class Headless : public demo::Driver {
public:
    Headless(std::vector<Shot> shots, long frames, Recorder &recorder, Progress &progress)
        : shots_(std::move(shots)), frames_(frames),
          safety_frames_(3600L * 60L * static_cast<long>(shots_.size() + 1)), recorder_(recorder), progress_(progress) {}
    // Takes the next shot, if any is left.
    bool shoot_next(Simulation &sim) {
        if (next_shot_ == shots_.size()) return false;
        sim.shoot(shots_[next_shot_++]);
        return true;
    }
    bool next_frame(Simulation &sim) override {
        const long steps = sim.stats().steps;
        if (frames_ >= 0) return steps < frames_;
        if (steps >= safety_frames_) {
            gave_up_ = true;
            return false;
        }
        return true;
    }
    bool before_step(Simulation &sim, bool was_at_rest) override {
        return !was_at_rest || shoot_next(sim) || frames_ >= 0;
    }
    void after_step(const Simulation &sim) override {
        recorder_.frame(sim);
        progress_.frame(sim);
    }
    double frame_seconds() const override { return 0; }
    bool gave_up() const { return gave_up_; }

private:
    std::vector<Shot> shots_;
    size_t next_shot_ = 0;
    long frames_;  // < 0: until the last shot has come to rest
    long safety_frames_;
    Recorder &recorder_;
    Progress &progress_;
    bool gave_up_ = false;
};

const char *scene_name(Scene s) {
    switch (s) {
    case Scene::Break: return "break";
    case Scene::Elastic: return "elastic";
    case Scene::Gas: return "gas";
    default: return "cradle";
    }
}
const char *response_name(Response r) { return r == Response::Box2d ? "box2d" : "collide2d"; }

const char *check_name(demo::CheckMode m) {
    return m == demo::CheckMode::Full ? "full" : m == demo::CheckMode::Sample ? "sample" : "off";
}

void print_model(const Simulation &sim) {
    const demo::SimConfig &c = sim.config();
    const demo::Model &m = c.model;
    std::printf("\"model\":{\"friction\":%s,\"ball_radius\":%.17g,\"ball_mass\":%.17g,\"ball_inertia\":%.17g,"
                "\"gravity\":%.17g,\"mu_slide\":%.17g,\"mu_roll\":%.17g,\"mu_spin\":%.17g,\"spin_deceleration\":%.17g,"
                "\"ball_restitution\":%.17g,\"ball_friction\":%.17g,\"ball_tangential_restitution\":%.17g,"
                "\"cushion_restitution\":%.17g,\"cushion_friction\":%.17g,\"cushion_tangential_restitution\":%.17g,"
                "\"absorb_below\":%.17g,\"table_length\":%.17g,\"table_width\":%.17g",
                m.friction ? "true" : "false", demo::kBallRadius, demo::kBallMass, demo::kBallInertia, m.cloth.gravity,
                m.cloth.slide, m.cloth.roll, m.cloth.spin, m.cloth.spin_deceleration(), m.ball.restitution,
                m.ball.friction, m.ball.tangential_restitution, m.cushion.restitution, m.cushion.friction,
                m.cushion.tangential_restitution, m.absorb_below, sim.table().length, sim.table().width);
    std::printf(",\"contact_model\":\"%s\",\"cushion_height\":%.17g,\"squirt_end_mass\":%.17g",
                demo::contact_model_name(m.contact), m.cushion_height, m.cue_end_mass);
    if (c.scene == Scene::Break) {
        for (const auto &p : {std::make_pair("corner", c.table.corner), std::make_pair("side", c.table.side)})
            std::printf(",\"%s_mouth\":%.17g,\"%s_facing_angle_deg\":%.17g,\"%s_nose_radius\":%.17g,\"%s_shelf\":%.17g,"
                        "\"%s_hole_radius\":%.17g",
                        p.first, p.second.mouth, p.first, p.second.facing_angle_deg, p.first, p.second.nose_radius,
                        p.first, p.second.shelf, p.first, p.second.hole_radius);
    }
    std::printf("}");
}

void print_balls(const std::vector<demo::Ball> &balls) {
    std::printf("\"balls\":[");
    bool first = true;
    for (const demo::Ball &b : balls) {
        std::printf("%s{\"number\":%d,\"x\":%.17g,\"y\":%.17g,\"vx\":%.17g,\"vy\":%.17g,\"wx\":%.17g,\"wy\":%.17g,"
                    "\"wz\":%.17g,\"state\":\"%s\",\"on_table\":%s}",
                    first ? "" : ",", b.number, b.x, b.y, b.vx, b.vy, b.wx, b.wy, b.wz, demo::motion_name(b.motion),
                    b.active ? "true" : "false");
        first = false;
    }
    std::printf("]");
}

void print_numbers(const std::vector<double> &v) {
    std::printf("[");
    for (size_t k = 0; k < v.size(); ++k) std::printf("%s%.17g", k ? "," : "", v[k]);
    std::printf("]");
}

void print_cradle(const demo::CradleOutcome &c) {
    std::printf(",\"cradle\":{\"row\":%d,\"head_on\":%s,\"crossed\":%s,\"speed\":%.17g,\"impacts\":%ld,"
                "\"minimal_impacts\":%ld,\"exact\":%s,\"expected\":",
                c.row, c.head_on ? "true" : "false", c.crossed ? "true" : "false", c.speed, c.impacts, c.minimal_impacts,
                c.exact ? "true" : "false");
    print_numbers(c.expected);
    std::printf(",\"actual\":");
    print_numbers(c.actual);
    std::printf("}");
}

void print_json(const Simulation &sim, const Totals &t) {
    const demo::Stats &s = sim.stats();
    std::printf("{\"scene\":\"%s\",\"response\":\"%s\",\"steps\":%ld,\"sim_seconds\":%.17g,\"wall_seconds\":%.6f,"
                "\"ball_count\":%d,\"ball_ball_collisions\":%ld,\"cushion_collisions\":%ld,\"pocketed\":%d,"
                "\"scratches\":%d,\"escaped\":%d,\"tunnelled\":%ld,\"max_overlap\":%.17g,\"energy_start\":%.17g,"
                "\"energy_end\":%.17g,\"momentum_start\":[%.17g,%.17g],\"momentum_end\":[%.17g,%.17g],",
                scene_name(sim.config().scene), response_name(sim.config().response), s.steps, s.sim_seconds,
                t.wall_seconds, sim.balls_total(), s.ball_ball_collisions, s.cushion_collisions, s.pocketed,
                s.scratches, s.escaped, s.tunnelled, s.max_overlap, t.energy_start, t.energy_end, t.momentum_start[0],
                t.momentum_start[1], t.momentum_end[0], t.momentum_end[1]);
    std::printf("\"check\":\"%s\",\"checked_pairs\":%ld,\"max_energy_step\":%.17g,", check_name(sim.config().check),
                s.checked_pairs, s.max_energy_step);
    print_model(sim);
    std::printf(",");
    print_balls(sim.balls());
    if (t.cradle) print_cradle(*t.cradle);
    std::printf("}\n");
}

void print_summary(const Simulation &sim, const Totals &t) {
    const demo::Stats &s = sim.stats();
    const double drift = t.energy_start > 0 ? t.energy_end / t.energy_start - 1 : 0;
    std::printf("billiards: %s scene, %s response, %d balls\n", scene_name(sim.config().scene),
                response_name(sim.config().response), sim.balls_total());
    std::printf("  simulated %.2f s in %ld frames, %.4f s wall: %.0fx real time, %.0f frames/s\n", s.sim_seconds,
                s.steps, t.wall_seconds, s.sim_seconds / std::max(t.wall_seconds, 1e-9),
                static_cast<double>(s.steps) / std::max(t.wall_seconds, 1e-9));
    std::printf("  collisions: %ld ball-ball, %ld cushion; pocketed %d (+%d cue ball), on the table %d\n",
                s.ball_ball_collisions, s.cushion_collisions, s.pocketed, s.scratches,
                sim.balls_total() - s.pocketed - s.scratches);
    std::printf("  checked %s (%ld pairs): escaped %d, tunnelled pairs %ld, worst overlap %.3g%% of a diameter, "
                "largest energy step %.3g\n",
                check_name(sim.config().check), s.checked_pairs, s.escaped, s.tunnelled, 100 * s.max_overlap,
                s.max_energy_step);
    std::printf("  kinetic energy %.6g J -> %.6g J (%+.3g relative)\n", t.energy_start, t.energy_end, drift);
    std::printf("  momentum (%.6g, %.6g) -> (%.6g, %.6g) kg m/s\n", t.momentum_start[0], t.momentum_start[1],
                t.momentum_end[0], t.momentum_end[1]);
    if (const demo::CradleOutcome *c = t.cradle.get())
        std::printf("  cradle: %d in the row, %ld ball-ball impacts (fewest possible %ld)%s: %s\n", c->row, c->impacts,
                    c->minimal_impacts, c->crossed ? "" : ", the pulse had not crossed",
                    c->exact ? "the last ball leaves at v, the others stand exactly still"
                    : !c->head_on ? "not a head-on shot (angle 0), no textbook outcome"
                                  : "NOT the textbook outcome");
}

Totals run_headless(Simulation &sim, const Options &o, Recorder &recorder) {
    std::vector<Shot> shots = o.shots;
    if (shots.empty() && o.config.scene != Scene::Gas && o.config.placements.empty()) shots.push_back(Shot{0, 12});
    double seconds = o.seconds;
    if (seconds < 0 && sim.lossless()) seconds = 60;
    const long frames = seconds < 0 ? -1 : static_cast<long>(std::ceil(seconds / demo::kFrameDt - 1e-9));
    Progress progress(seconds);
    Headless headless(shots, frames, recorder, progress);
    if (o.config.scene == Scene::Cradle) recorder.watch_cradle(sim);
    headless.shoot_next(sim);
    Totals t;
    t.energy_start = sim.energy();
    sim.momentum(t.momentum_start);
    recorder.frame(sim);
    const auto start = std::chrono::steady_clock::now();
    demo::run(sim, headless);
    t.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    t.energy_end = sim.energy();
    sim.momentum(t.momentum_end);
    if (recorder.cradle()) t.cradle.reset(new demo::CradleOutcome(recorder.cradle()->outcome()));
    if (headless.gave_up()) std::fprintf(stderr, "billiards: warning: not at rest after an hour a shot; stopped there\n");
    return t;
}

bool write_speeds(const Simulation &sim, const std::string &path, std::string &error) {
    OutFile f(path);
    for (const demo::Ball &b : sim.balls())
        if (b.active) std::fprintf(f.get(), "%.17g\n", std::hypot(b.vx, b.vy));
    return f.close(error);
}

// Fails (exit 2) before simulating if an output file cannot be written,
// leaving no file behind: a file it had to create is removed again.
void check_writable(const std::string &flag, const std::string &path) {
    int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
        ::close(fd);
        ::unlink(path.c_str());
        return;
    }
    if (errno == EEXIST) {
        // an existing file is opened without truncating it; a FIFO without a
        // reader (ENXIO) is left to the run
        fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC | O_NONBLOCK);
        if (fd >= 0) {
            ::close(fd);
            return;
        }
        if (errno == ENXIO) return;
    }
    throw UsageError{flag + ": " + path + ": " + std::strerror(errno)};
}

// Every check that can be made before simulating (exit 2 on failure): a
// display for --screenshot-window, each output file writable, no two outputs
// in the same file (a device such as /dev/null aside).
void preflight(const Options &o) {
    const std::pair<const char *, const std::string *> outputs[] = {
        {"--screenshot", &o.screenshot}, {"--screenshot-window", &o.screenshot_window},
        {"--trace", &o.trace},           {"--speeds", &o.speeds},
        {"--events", &o.events}};
    for (size_t i = 0; i < std::size(outputs); ++i) {
        const std::string &a = *outputs[i].second;
        if (a.empty()) continue;
        struct stat sa;
        const bool a_exists = ::stat(a.c_str(), &sa) == 0;
        if (a_exists && S_ISCHR(sa.st_mode)) continue;
        for (size_t k = i + 1; k < std::size(outputs); ++k) {
            const std::string &b = *outputs[k].second;
            struct stat sb;
            if (!b.empty() && (a == b || (a_exists && ::stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev &&
                                          sa.st_ino == sb.st_ino)))
                throw UsageError{std::string(outputs[i].first) + " and " + outputs[k].first + " name the same file ('" +
                                 a + "'); each output needs its own"};
        }
    }
    std::string why;
    if (!o.screenshot_window.empty() && !demo::window_available(why))
        throw UsageError{"--screenshot-window: " + why + "; --screenshot draws the picture offscreen"};
    for (const auto &out : outputs)
        if (!out.second->empty()) check_writable(out.first, *out.second);
}

int write_outputs(const Simulation &sim, const Options &o) {
    std::string error;
    if (!o.speeds.empty() && !write_speeds(sim, o.speeds, error)) {
        std::fprintf(stderr, "billiards: %s\n", error.c_str());
        return 1;
    }
    if (!o.screenshot.empty() && !demo::screenshot_offscreen(sim, o.screenshot, error)) {
        std::fprintf(stderr, "billiards: screenshot: %s\n", error.c_str());
        return 1;
    }
    if (!o.screenshot_window.empty() && demo::screenshot_window(sim, o.screenshot_window, error) != demo::WindowResult::Ok) {
        std::fprintf(stderr, "billiards: window screenshot: %s\n", error.c_str());
        return 1;
    }
    return 0;
}

// --- 8-ball and 9-ball without a window: two computer players (game.h) -----

void print_game_json(const demo::GameRecord &g, const Options &o, const Simulation &table, double wall) {
    std::printf("{\"scene\":\"break\",\"response\":\"%s\",\"game\":\"%s\",\"players\":[\"computer\",\"computer\"],"
                "\"seed\":%llu,\"shots\":[",
                response_name(o.config.response), o.game == demo::GameMode::NineBall ? "9ball" : "8ball",
                static_cast<unsigned long long>(o.config.seed));
    for (size_t i = 0; i < g.shots.size(); ++i) {
        const demo::ShotRecord &r = g.shots[i];
        std::printf("%s{\"player\":%d,\"angle\":%.17g,\"speed\":%.17g,\"side\":%.17g,\"topback\":%.17g,", i ? "," : "",
                    r.player, r.shot.angle_deg, r.shot.speed, r.shot.side, r.shot.topback);
        if (r.placed) std::printf("\"ball_in_hand\":[%.17g,%.17g],", r.cue.x, r.cue.y);
        else std::printf("\"ball_in_hand\":null,");
        std::printf("\"potted\":[");
        for (size_t k = 0; k < r.potted.size(); ++k) std::printf("%s%d", k ? "," : "", r.potted[k]);
        std::printf("],\"foul\":\"%s\",\"keeps_turn\":%s,\"candidates\":%d,\"elevation\":%.17g}",
                    demo::foul_name(r.foul), r.keeps_turn ? "true" : "false", r.candidates, r.shot.elevation);
    }
    std::printf("],\"shot_count\":%zu,\"fouls\":%d,\"groups\":[\"%s\",\"%s\"],\"winner\":", g.shots.size(), g.fouls,
                demo::group_name(g.groups[0]), demo::group_name(g.groups[1]));
    if (g.winner >= 0) std::printf("%d", g.winner);
    else std::printf("null");
    std::printf(",\"reason\":\"%s\",\"candidates\":%ld,\"sim_seconds\":%.17g,\"wall_seconds\":%.6f,\"think_seconds\":%.6f,",
                g.reason.c_str(), g.candidates, g.sim_seconds, wall, g.think_seconds);
    print_model(table);
    std::printf(",");
    print_balls(g.balls);
    std::printf("}\n");
}

void print_game_summary(const demo::GameRecord &g, double wall) {
    std::printf("billiards: %s, computer against computer\n", g.nine_ball ? "9-ball" : "8-ball");
    for (size_t i = 0; i < g.shots.size(); ++i) {
        const demo::ShotRecord &r = g.shots[i];
        std::string potted;
        for (int n : r.potted) potted += (potted.empty() ? "" : " ") + std::to_string(n);
        std::printf("  %3zu  player %d%s  %7.2f deg %5.2f m/s tip %+.2f,%+.2f  potted [%s]%s%s\n", i + 1, r.player + 1,
                    r.placed ? " (ball in hand)" : "", r.shot.angle_deg, r.shot.speed, r.shot.side, r.shot.topback,
                    potted.c_str(), r.foul != demo::Foul::None ? "  foul: " : "",
                    r.foul != demo::Foul::None ? demo::foul_text(r.foul) : "");
    }
    if (g.winner >= 0) {
        const int shooter = g.shots.empty() ? g.winner : g.shots.back().player;
        std::printf("  player %d (%s) wins: %s\n", g.winner + 1, g.nine_ball ? "9-ball" : demo::group_name(g.groups[g.winner]),
                    demo::win_reason(g.winner, shooter, "player " + std::to_string(shooter + 1), g.reason).c_str());
    }
    else std::printf("  %s\n", g.reason.c_str());
    std::printf("  %zu shots, %d fouls; the computer simulated %ld candidate shots in %.3f s (%.0f shots/s, %.1f ms a turn); "
                "%.1f s of play simulated in %.3f s\n",
                g.shots.size(), g.fouls, g.candidates, g.think_seconds,
                static_cast<double>(g.candidates) / std::max(g.think_seconds, 1e-9),
                1000 * g.think_seconds / static_cast<double>(std::max<size_t>(1, g.shots.size())), g.sim_seconds, wall);
}

}  // namespace

void demo::check_headless(const Options &o) {
    if (o.game == demo::GameMode::Practice) throw UsageError{"--game practice is played in the window"};
    if (demo::rules_game(o.game) && o.players_given && !(o.computer[0] && o.computer[1]))
        throw UsageError{"--players: a human player needs the window; headless, a game is --players computer,computer"};
    preflight(o);
}

int demo::run_game_headless(const Options &o) {
    const auto start = std::chrono::steady_clock::now();
    const demo::GameKind kind = o.game == demo::GameMode::NineBall ? demo::GameKind::NineBall : demo::GameKind::EightBall;
    const demo::GameRecord g = demo::play_computer_game(o.config, o.config.seed, kind);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    demo::SimConfig final_table = o.config;
    for (const demo::Ball &b : g.balls)
        if (b.active) final_table.placements.push_back(demo::Placement{b.number, b.x, b.y});
    const Simulation table(final_table);
    if (o.json) print_game_json(g, o, table, wall);
    else print_game_summary(g, wall);
    std::string error;
    // the game's panel: the players and their groups, the result, the tray
    std::vector<std::string> lines;
    std::string who = demo::game_name(kind);
    for (int p = 0; p < 2; ++p) {
        who += "   Player " + std::to_string(p + 1) + " (computer)";
        if (g.groups[p] != demo::Group::Open) who += std::string(": ") + demo::group_name(g.groups[p]);
    }
    lines.push_back(who);
    if (g.winner >= 0) {
        const int shooter = g.shots.empty() ? g.winner : g.shots.back().player;
        lines.push_back("Player " + std::to_string(g.winner + 1) + " wins: " +
                        demo::win_reason(g.winner, shooter, "player " + std::to_string(shooter + 1), g.reason));
    } else {
        lines.push_back(g.reason);
    }
    lines.push_back(std::to_string(g.shots.size()) + " shots, " + std::to_string(g.fouls) + " fouls");
    std::vector<int> pocketed;
    for (const demo::Ball &b : g.balls)
        if (!b.active && b.number != 0) pocketed.push_back(b.number);
    if (!o.screenshot.empty() && !demo::screenshot_offscreen(table, o.screenshot, error, lines, pocketed)) {
        std::fprintf(stderr, "billiards: screenshot: %s\n", error.c_str());
        return 1;
    }
    return 0;  // main checks stdout
}

int demo::run_scene_headless(const Options &o) {
    Recorder recorder(o);
    Simulation sim(o.config);
    const Totals t = run_headless(sim, o, recorder);
    if (sim.stats().event_cap_frames > 0)
        std::fprintf(stderr, "billiards: warning: event budget ran out in %ld frames\n", sim.stats().event_cap_frames);
    if (o.json) print_json(sim, t);
    else print_summary(sim, t);
    std::string error;
    if (!recorder.close(error)) {
        std::fprintf(stderr, "billiards: %s\n", error.c_str());
        return 1;
    }
    return write_outputs(sim, o);  // main checks stdout
}
