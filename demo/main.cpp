// main.cpp - command line of the billiards demo: options, headless run,
// JSON / summary output, trace and screenshots.  See `billiards --help`.
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "render.h"
#include "sim.h"

namespace {

using demo::Response;
using demo::Scene;
using demo::Shot;
using demo::Simulation;

const char kUsage[] =
    "usage: billiards [options]\n"
    "  --scene break|elastic|gas   scene (default break)\n"
    "  --response collide2d|box2d  who resolves collisions (default collide2d)\n"
    "  --balls N                   gas: number of disks (default 1000)\n"
    "  --headless                  no window (automatic without a display)\n"
    "  --shot ANGLE_DEG,SPEED_MPS  cue shot, may repeat (default 0,12: the break)\n"
    "  --seconds S                 simulated time (default: until rest; 60 for elastic/gas)\n"
    "  --seed N                    rack order / gas start (default 1)\n"
    "  --json                      one JSON object on stdout instead of the summary\n"
    "  --screenshot FILE.png       final frame, rendered offscreen\n"
    "  --screenshot-window FILE.png  final frame drawn in a real window and read back\n"
    "  --trace FILE.csv            time, kinetic energy, momentum per frame\n"
    "  --speeds FILE               final speeds, one per line (gas histogram)\n";

struct Options {
    demo::SimConfig config;
    bool balls_given = false, headless = false, json = false;
    std::vector<Shot> shots;
    double seconds = -1;  // < 0: the scene's default
    std::string screenshot, screenshot_window, trace, speeds;
};

struct UsageError {
    std::string message;
};

[[noreturn]] void fail(const std::string &message) { throw UsageError{message}; }

double parse_number(const std::string &flag, const std::string &text) {
    errno = 0;
    char *end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(v))
        fail(flag + ": '" + text + "' is not a finite number");
    return v;
}

unsigned long long parse_unsigned(const std::string &flag, const std::string &text) {
    errno = 0;
    char *end = nullptr;
    const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
    if (text.empty() || text[0] == '-' || text[0] == '+' || *end != '\0' || errno == ERANGE)
        fail(flag + ": '" + text + "' is not a non-negative integer");
    return v;
}

Shot parse_shot(const std::string &text) {
    const size_t comma = text.find(',');
    if (comma == std::string::npos) fail("--shot: expected ANGLE_DEG,SPEED_MPS, got '" + text + "'");
    const Shot s{parse_number("--shot angle", text.substr(0, comma)), parse_number("--shot speed", text.substr(comma + 1))};
    if (!(s.speed > 0 && s.speed <= demo::kMaxShotSpeed))
        fail("--shot: speed must be in (0, " + std::to_string(static_cast<int>(demo::kMaxShotSpeed)) + "] m/s");
    return s;
}

void check_consistency(const Options &o) {
    if (o.config.scene == Scene::Gas && !o.shots.empty()) fail("--shot does not apply to --scene gas");
    if (o.config.scene != Scene::Gas && o.balls_given) fail("--balls only applies to --scene gas");
}

Options parse(int argc, char **argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) fail(flag + " needs a value");
            return argv[++i];
        };
        if (flag == "--help" || flag == "-h") {
            std::fputs(kUsage, stdout);
            std::exit(0);
        } else if (flag == "--scene") {
            const std::string v = value();
            if (v == "break") o.config.set_scene(Scene::Break);
            else if (v == "elastic") o.config.set_scene(Scene::Elastic);
            else if (v == "gas") o.config.set_scene(Scene::Gas);
            else fail("--scene: unknown scene '" + v + "' (break, elastic or gas)");
        } else if (flag == "--response") {
            const std::string v = value();
            if (v == "collide2d") o.config.response = Response::Collide2d;
            else if (v == "box2d") o.config.response = Response::Box2d;
            else fail("--response: unknown response '" + v + "' (collide2d or box2d)");
        } else if (flag == "--balls") {
            const unsigned long long n = parse_unsigned(flag, value());
            if (n < 1 || n > 200000) fail("--balls: must be between 1 and 200000");
            o.config.gas_balls = static_cast<int>(n);
            o.balls_given = true;
        } else if (flag == "--seconds") {
            o.seconds = parse_number(flag, value());
            if (o.seconds < 0 || o.seconds > 86400) fail("--seconds: must be between 0 and 86400");
        } else if (flag == "--seed") {
            o.config.seed = parse_unsigned(flag, value());
        } else if (flag == "--shot") {
            o.shots.push_back(parse_shot(value()));
        } else if (flag == "--headless") {
            o.headless = true;
        } else if (flag == "--json") {
            o.json = true;
        } else if (flag == "--screenshot") {
            o.screenshot = value();
        } else if (flag == "--screenshot-window") {
            o.screenshot_window = value();
        } else if (flag == "--trace") {
            o.trace = value();
        } else if (flag == "--speeds") {
            o.speeds = value();
        } else {
            fail("unknown option '" + flag + "' (see --help)");
        }
    }
    check_consistency(o);
    return o;
}

struct Totals {
    double energy_start = 0, energy_end = 0, wall_seconds = 0;
    double momentum_start[2] = {0, 0}, momentum_end[2] = {0, 0};
};

class Trace {
public:
    explicit Trace(const std::string &path) : f_(path.empty() ? nullptr : std::fopen(path.c_str(), "w")) {
        if (!path.empty() && !f_) throw std::runtime_error(path + ": " + std::strerror(errno));
        if (f_) std::fputs("time,kinetic_energy,momentum_x,momentum_y\n", f_);
    }
    ~Trace() {
        if (f_) std::fclose(f_);
    }
    void row(const Simulation &sim) {
        if (!f_) return;
        double p[2];
        sim.momentum(p);
        std::fprintf(f_, "%.6f,%.17g,%.17g,%.17g\n", sim.stats().sim_seconds, sim.energy(), p[0], p[1]);
    }

private:
    FILE *f_;
};

// Shots are played one after another, each once the table is at rest; without
// --seconds the run ends when the last shot has come to rest.
class Headless : public demo::Driver {
public:
    Headless(std::vector<Shot> shots, long frames, Trace &trace)
        : shots_(std::move(shots)), frames_(frames), safety_frames_(3600L * 60L * static_cast<long>(shots_.size() + 1)),
          trace_(trace) {}
    // Takes the next shot, if any is left.
    bool shoot_next(Simulation &sim) {
        if (next_shot_ == shots_.size()) return false;
        sim.shoot(shots_[next_shot_++]);
        return true;
    }
    bool next_frame(Simulation &sim) override {
        const long steps = sim.stats().steps;
        return !(frames_ >= 0 && steps >= frames_) && steps < safety_frames_;
    }
    bool before_step(Simulation &sim, bool was_at_rest) override {
        return !was_at_rest || shoot_next(sim) || frames_ >= 0;
    }
    void after_step(const Simulation &sim) override { trace_.row(sim); }

private:
    std::vector<Shot> shots_;
    size_t next_shot_ = 0;
    long frames_;  // < 0: until the last shot has come to rest
    long safety_frames_;
    Trace &trace_;
};

Totals run_headless(Simulation &sim, const Options &o) {
    std::vector<Shot> shots = o.shots;
    if (shots.empty() && o.config.scene != Scene::Gas) shots.push_back(Shot{0, 12});
    double seconds = o.seconds;
    if (seconds < 0 && sim.lossless()) seconds = 60;
    const long frames = seconds < 0 ? -1 : static_cast<long>(std::ceil(seconds / demo::kFrameDt - 1e-9));
    Trace trace(o.trace);
    Headless headless(shots, frames, trace);
    headless.shoot_next(sim);
    Totals t;
    t.energy_start = sim.energy();
    sim.momentum(t.momentum_start);
    trace.row(sim);
    const auto start = std::chrono::steady_clock::now();
    demo::run(sim, headless);
    t.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    t.energy_end = sim.energy();
    sim.momentum(t.momentum_end);
    return t;
}

const char *scene_name(Scene s) { return s == Scene::Break ? "break" : s == Scene::Elastic ? "elastic" : "gas"; }
const char *response_name(Response r) { return r == Response::Box2d ? "box2d" : "collide2d"; }

void print_json(const Simulation &sim, const Totals &t) {
    const demo::Stats &s = sim.stats();
    std::printf("{\"scene\":\"%s\",\"response\":\"%s\",\"steps\":%ld,\"sim_seconds\":%.17g,\"wall_seconds\":%.6f,"
                "\"balls\":%d,\"ball_ball_collisions\":%ld,\"cushion_collisions\":%ld,\"pocketed\":%d,\"escaped\":%d,"
                "\"tunnelled\":%ld,\"max_overlap\":%.17g,\"energy_start\":%.17g,\"energy_end\":%.17g,"
                "\"momentum_start\":[%.17g,%.17g],\"momentum_end\":[%.17g,%.17g]}\n",
                scene_name(sim.config().scene), response_name(sim.config().response), s.steps, s.sim_seconds,
                t.wall_seconds, sim.balls_total(), s.ball_ball_collisions, s.cushion_collisions, s.pocketed, s.escaped,
                s.tunnelled, s.max_overlap, t.energy_start, t.energy_end, t.momentum_start[0], t.momentum_start[1],
                t.momentum_end[0], t.momentum_end[1]);
}

void print_summary(const Simulation &sim, const Totals &t) {
    const demo::Stats &s = sim.stats();
    const double drift = t.energy_start > 0 ? t.energy_end / t.energy_start - 1 : 0;
    std::printf("billiards: %s scene, %s response, %d balls\n", scene_name(sim.config().scene),
                response_name(sim.config().response), sim.balls_total());
    std::printf("  simulated %.2f s in %ld frames, %.4f s wall: %.0fx real time, %.0f frames/s\n", s.sim_seconds,
                s.steps, t.wall_seconds, s.sim_seconds / std::max(t.wall_seconds, 1e-9),
                static_cast<double>(s.steps) / std::max(t.wall_seconds, 1e-9));
    std::printf("  collisions: %ld ball-ball, %ld cushion; pocketed %d, on the table %d\n", s.ball_ball_collisions,
                s.cushion_collisions, s.pocketed, sim.balls_total() - s.pocketed);
    std::printf("  escaped %d, tunnelled pairs %ld, worst overlap %.3g%% of a diameter\n", s.escaped, s.tunnelled,
                100 * s.max_overlap);
    std::printf("  kinetic energy %.6g J -> %.6g J (%+.3g relative)\n", t.energy_start, t.energy_end, drift);
    std::printf("  momentum (%.6g, %.6g) -> (%.6g, %.6g) kg m/s\n", t.momentum_start[0], t.momentum_start[1],
                t.momentum_end[0], t.momentum_end[1]);
}

bool write_speeds(const Simulation &sim, const std::string &path) {
    FILE *f = std::fopen(path.c_str(), "w");
    if (!f) return false;
    for (const demo::Ball &b : sim.balls())
        if (b.active) std::fprintf(f, "%.17g\n", std::hypot(b.vx, b.vy));
    return std::fclose(f) == 0;
}

int write_outputs(const Simulation &sim, const Options &o) {
    std::string error;
    if (!o.speeds.empty() && !write_speeds(sim, o.speeds)) {
        std::fprintf(stderr, "billiards: %s: %s\n", o.speeds.c_str(), std::strerror(errno));
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

int run(const Options &o) {
    if (!o.headless) {
        std::string why;
        if (demo::play_window(o.config, why) == demo::WindowResult::Ok) return 0;
        std::fprintf(stderr, "billiards: %s; running headless\n", why.c_str());
    }
    Simulation sim(o.config);
    const Totals t = run_headless(sim, o);
    if (sim.stats().event_cap_frames > 0)
        std::fprintf(stderr, "billiards: warning: event budget ran out in %ld frames\n", sim.stats().event_cap_frames);
    if (o.json) print_json(sim, t);
    else print_summary(sim, t);
    return write_outputs(sim, o);
}

}  // namespace

int main(int argc, char **argv) {
    Options o;
    try {
        o = parse(argc, argv);
    } catch (const UsageError &e) {
        std::fprintf(stderr, "billiards: %s\n", e.message.c_str());
        return 2;
    }
    try {
        return run(o);
    } catch (const std::exception &e) {
        std::fprintf(stderr, "billiards: %s\n", e.what());
        return 1;
    }
}
