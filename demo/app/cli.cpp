/* SPDX-License-Identifier: MIT */
// cli.cpp - see cli.h.
#include "app/cli.h"

#include <cctype>
#include <cerrno>
#include <cfloat>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <utility>

namespace demo {

const char kUsage[] =
    "usage: billiards [options]\n"
    "  --help, -h                  this text\n"
    "  --scene break|elastic|gas|cradle  scene (default break)\n"
    "  --response collide2d|box2d  who resolves collisions (default collide2d)\n"
    "  --balls N                   gas: number of disks (default 1000); cradle: balls\n"
    "                              in the row (default 5, at most 20)\n"
    "  --place N,X,Y               put ball N (0 = cue ball, 1-15) at X,Y metres, the\n"
    "                              surface being [0,2.54] x [0,1.27]; may repeat; only\n"
    "                              the placed balls are on the table\n"
    "  --seed N                    rack order / gas start (default 1)\n"
    "  --check full|sample|off     the frame checker (tunnelling, overlap, escapes,\n"
    "                              energy): full checks every pair near another each\n"
    "                              frame (default); sample the pairs of every m-th\n"
    "                              ball, m = ceil(N/1024), from a seeded offset drawn\n"
    "                              each frame, the rest whole; off checks nothing\n"
    "  --broadphase tree|cells     who finds the world's candidate pairs in the pool\n"
    "                              scenes: Box2D's b2DynamicTree (default) or the\n"
    "                              world's own cells (the same events, bit for bit)\n"
    "  --headless                  no window (automatic without a display)\n"
    "  --game practice|8ball|9ball practice: clear the table (the window's default);\n"
    "                              8ball, 9ball: two players, WPA-style rules\n"
    "                              (9ball: O declares a push-out, B passes it back)\n"
    "  --players A,B               8ball, 9ball: each human or computer (window default\n"
    "                              human,computer; headless: computer,computer only)\n"
    "  --model sphere|sphere-alciatore|disk  the pool scenes' impacts: balls as\n"
    "                              spheres with 3-D spin, cushions 0.64 D high (default);\n"
    "                              the same with Alciatore's speed-dependent ball-ball\n"
    "                              friction; or the former disks in the plane of the\n"
    "                              centres\n"
    "  --cue-end-mass GRAMS        the cue's end mass that squirt comes from, in\n"
    "                              (0, 170] g (default 5.667 g, m/30: pooltool's\n"
    "                              default; a heavier end mass squirts more)\n"
    "headless only:\n"
    "  --shot DEG,MPS[,SIDE,TOP[,ELEV]]  cue shot, may repeat, each once the table is\n"
    "                              at rest: angle (0 = +x, counter-clockwise), the cue\n"
    "                              ball's speed, the tip's offset right of centre and\n"
    "                              above it as fractions of R, sqrt(SIDE^2+TOP^2) <= 0.5,\n"
    "                              the cue's elevation in degrees, 0 (level, the\n"
    "                              default) to 85 (default 0,12,0,0: the break; none\n"
    "                              with --place)\n"
    "  --seconds S                 simulated time, 0 to 86400 (default: until rest;\n"
    "                              60 for elastic/gas)\n"
    "  --json                      one JSON object on stdout instead of the summary\n"
    "  --events FILE.csv           every event: time,kind,ball,other,x,y,vx,vy,wx,wy,wz\n"
    "  --trace FILE.csv            time, kinetic energy, momentum per frame\n"
    "  --speeds FILE               final speeds, one per line (gas histogram)\n"
    "  --screenshot FILE.png       final frame, rendered offscreen\n"
    "  --screenshot-window FILE.png  final frame drawn in a real window and read back\n"
    "--place and --shot may repeat; any other option taking a value may be given\n"
    "only once; the output files must differ, and their directories exist.\n";

namespace {

[[noreturn]] void fail(const std::string &message) { throw UsageError{message}; }

// A message from its parts, appended into one string (no temporaries).
template <typename... Parts>
std::string cat(const Parts &...parts) {
    std::string s;
    (s += ... += parts);
    return s;
}

// Whether a number's literal has a non-zero digit before its exponent: 0 is
// not an underflow, 1e-400 is.
bool nonzero_literal(const std::string &text) {
    size_t i = text.find_first_not_of("+-");
    const bool hex = i != std::string::npos && text.compare(i, 2, "0x") == 0;
    if (hex || (i != std::string::npos && text.compare(i, 2, "0X") == 0)) i += 2;
    for (; i < text.size(); ++i) {
        const char c = text[i];
        if (hex ? (c == 'p' || c == 'P') : (c == 'e' || c == 'E')) break;
        if ((c >= '1' && c <= '9') || (hex && std::isxdigit(static_cast<unsigned char>(c)) && c != '0')) return true;
    }
    return false;
}

// A number's text is not empty and starts with no blank (strtod and strtoull
// would skip it, and strtoull would then read " -1" as 2^64 - 1).
void check_literal(const std::string &flag, const std::string &text) {
    if (text.empty()) fail(flag + ": empty value (a number is needed)");
    if (std::isspace(static_cast<unsigned char>(text[0])))
        fail(flag + ": '" + text + "' starts with a blank (give the number alone)");
}

double parse_number(const std::string &flag, const std::string &text) {
    check_literal(flag, text);
    errno = 0;
    char *end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    const bool range = errno == ERANGE;
    if (end == text.c_str()) fail(flag + ": '" + text + "' is not a number");
    if (*end != '\0') fail(flag + ": '" + text + "' is not a number (stray '" + std::string(end) + "' after it)");
    if (std::isnan(v)) fail(flag + ": '" + text + "' is not a number (NaN)");
    if (std::isinf(v) && !range) fail(flag + ": '" + text + "' is not a finite number");
    if (std::isinf(v)) fail(flag + ": '" + text + "' overflows (the largest double is about 1.8e308)");
    if (v == 0 && (range || nonzero_literal(text)))
        fail(flag + ": '" + text + "' underflows (non-zero, but rounds to 0)");
    if (v != 0 && std::fabs(v) < DBL_MIN)
        fail(flag + ": '" + text + "' underflows (non-zero, but below 2.2e-308, the smallest normal double)");
    return v;
}

unsigned long long parse_unsigned(const std::string &flag, const std::string &text) {
    check_literal(flag, text);
    errno = 0;
    char *end = nullptr;
    const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
    if (end == text.c_str() || *end != '\0' || text[0] == '+')
        fail(flag + ": '" + text + "' is not a non-negative integer");
    if (text[0] == '-') fail(flag + ": '" + text + "' is negative (a non-negative integer is needed)");
    if (errno == ERANGE) fail(flag + ": '" + text + "' overflows (at most " + std::to_string(ULLONG_MAX) + ")");
    return v;
}

// Whether an option takes a value (for the message that refuses --seed=3).
bool takes_value(const std::string &flag) {
    static const char *const options[] = {"--scene",   "--response", "--balls",  "--place",      "--seed",
                                          "--game",    "--players",  "--seconds", "--shot",      "--events",
                                          "--trace",   "--speeds",   "--screenshot", "--screenshot-window",
                                          "--check",   "--model",    "--broadphase", "--cue-end-mass"};
    for (const char *o : options)
        if (flag == o) return true;
    return false;
}

// The comma-separated fields of a value.
std::vector<std::string> fields(const std::string &text) {
    std::vector<std::string> out;
    size_t start = 0;
    for (;;) {
        const size_t comma = text.find(',', start);
        out.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (comma == std::string::npos) return out;
        start = comma + 1;
    }
}

Shot parse_shot(const std::string &text) {
    const std::vector<std::string> f = fields(text);
    if (f.size() != 2 && f.size() != 4 && f.size() != 5)
        fail("--shot: expected ANGLE_DEG,SPEED_MPS[,SIDE,TOPBACK[,ELEVATION_DEG]], got '" + text + "'");
    Shot s{parse_number("--shot angle", f[0]), parse_number("--shot speed", f[1])};
    if (!(s.speed > 0 && s.speed <= kMaxShotSpeed))
        fail("--shot: speed must be in (0, " + std::to_string(static_cast<int>(kMaxShotSpeed)) + "] m/s");
    if (f.size() >= 4) {
        s.side = parse_number("--shot side", f[2]);
        s.topback = parse_number("--shot topback", f[3]);
        if (std::hypot(s.side, s.topback) > kMaxTipOffset)
            fail("--shot: the tip offset sqrt(SIDE^2 + TOPBACK^2) must be at most 0.5 (a miscue beyond), got '" +
                 text + "'");
    }
    if (f.size() == 5) {
        s.elevation = parse_number("--shot elevation", f[4]);
        if (!(s.elevation >= 0 && s.elevation <= kMaxElevation))
            fail(cat("--shot: the cue's elevation must be in [0, ", std::to_string(static_cast<int>(kMaxElevation)),
                     "] degrees, got '", f[4], "'"));
    }
    return s;
}

Placement parse_place(const std::string &text) {
    const std::vector<std::string> f = fields(text);
    if (f.size() != 3) fail("--place: expected N,X,Y, got '" + text + "'");
    const unsigned long long n = parse_unsigned("--place ball", f[0]);
    if (n > 15) fail("--place: ball numbers run from 0 (the cue ball) to 15, got '" + f[0] + "'");
    return Placement{static_cast<int>(n), parse_number("--place x", f[1]), parse_number("--place y", f[2])};
}

// The option's file name in Options, for the options that name an output
// file; nullptr for the others.
std::string Options::*output_path(const std::string &flag) {
    static const std::pair<const char *, std::string Options::*> paths[] = {
        {"--screenshot", &Options::screenshot}, {"--screenshot-window", &Options::screenshot_window},
        {"--trace", &Options::trace},           {"--speeds", &Options::speeds},
        {"--events", &Options::events}};
    for (const auto &p : paths)
        if (flag == p.first) return p.second;
    return nullptr;
}

std::string path_value(const std::string &flag, const std::string &v) {
    if (v.empty()) fail(flag + ": empty file name");
    // "--events --json" would otherwise write a file named --json
    if (v[0] == '-')
        fail(flag + ": '" + v + "' looks like an option, not a file name (write ./" + v + " for a file of that name)");
    return v;
}

// 8-ball plays from the rack of the break scene, its shots chosen by the
// players: options that set up another table or other shots do not apply.
void check_game(const Options &o) {
    if (o.players_given && !rules_game(o.game)) fail("--players only applies to --game 8ball or 9ball");
    if (o.game == GameMode::None) return;
    if (o.config.scene != Scene::Break) fail("--game is played on the break scene's table (drop --scene)");
    if (!o.config.placements.empty()) fail("--place does not apply to --game (the game starts from the rack)");
    if (o.game == GameMode::Practice && o.headless) fail("--game practice is played in the window (drop --headless)");
    if (!rules_game(o.game)) return;
    for (const std::string &flag : o.headless_only)
        if (flag != "--json" && flag != "--screenshot")
            fail(flag + " does not apply to --game " + (o.game == GameMode::NineBall ? "9ball" : "8ball") +
                 " (its shots are chosen by the players)");
}

void check_consistency(const Options &o) {
    check_game(o);
    const Scene scene = o.config.scene;
    if (scene == Scene::Gas && !o.shots.empty()) fail("--shot does not apply to --scene gas");
    if (scene == Scene::Gas && !o.config.placements.empty()) fail("--place does not apply to --scene gas");
    if (scene != Scene::Gas && scene != Scene::Cradle && o.balls_given)
        fail("--balls only applies to --scene gas and --scene cradle");
    if (scene == Scene::Cradle && o.config.cradle_balls > kMaxCradleBalls)
        fail("--balls: the cradle's row holds at most " + std::to_string(kMaxCradleBalls) + " balls");
    if (scene == Scene::Cradle && !o.config.placements.empty()) fail("--place does not apply to --scene cradle");
    if (!o.config.placements.empty()) {
        const std::string error = placement_error(scene_table(scene, o.config.table), o.config.placements);
        if (!error.empty()) fail("--place: " + error);
        bool cue = false;
        for (const Placement &p : o.config.placements) cue = cue || p.number == 0;
        if (!o.shots.empty() && !cue) fail("--shot needs the cue ball on the table (--place 0,X,Y)");
    }
}

}  // namespace

Options parse(int argc, char **argv) {
    Options o;
    std::map<std::string, std::string> given;  // the options taking one value, given so far
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        // An option's value; --place and --shot accumulate, any other option
        // taking a value may be given once (a second one would silently win).
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) fail(flag + " needs a value");
            std::string v = argv[++i];
            if (flag != "--place" && flag != "--shot") {
                const auto first = given.find(flag);
                if (first != given.end())
                    fail(cat(flag, " given twice ('", first->second, "', then '", v, "'); it takes one value"));
                given.emplace(flag, v);
            }
            return v;
        };
        auto headless_only = [&]() {
            for (const std::string &f : o.headless_only)
                if (f == flag) return;  // --shot may repeat, --json too
            o.headless_only.push_back(flag);
        };
        if (flag == "--help" || flag == "-h") {
            o.help = true;  // the caller prints the usage; the rest is not read
            return o;
        } else if (flag == "--scene") {
            const std::string v = value();
            if (v == "break") o.config.set_scene(Scene::Break);
            else if (v == "elastic") o.config.set_scene(Scene::Elastic);
            else if (v == "gas") o.config.set_scene(Scene::Gas);
            else if (v == "cradle") o.config.set_scene(Scene::Cradle);
            else fail("--scene: unknown scene '" + v + "' (break, elastic, gas or cradle)");
        } else if (flag == "--response") {
            const std::string v = value();
            if (v == "collide2d") o.config.response = Response::Collide2d;
            else if (v == "box2d") o.config.response = Response::Box2d;
            else fail("--response: unknown response '" + v + "' (collide2d or box2d)");
        } else if (flag == "--balls") {
            const std::string v = value();
            const unsigned long long n = parse_unsigned(flag, v);
            if (n < 1 || n > 200000) fail("--balls: must be between 1 and 200000, got '" + v + "'");
            o.config.gas_balls = o.config.cradle_balls = static_cast<int>(n);  // the scene uses its own
            o.balls_given = true;
        } else if (flag == "--place") {
            o.config.placements.push_back(parse_place(value()));
        } else if (flag == "--seed") {
            o.config.seed = parse_unsigned(flag, value());
        } else if (flag == "--check") {
            const std::string v = value();
            if (v == "full") o.config.check = CheckMode::Full;
            else if (v == "sample") o.config.check = CheckMode::Sample;
            else if (v == "off") o.config.check = CheckMode::Off;
            else fail("--check: unknown mode '" + v + "' (full, sample or off)");
        } else if (flag == "--model") {
            const std::string v = value();
            if (v == "sphere") o.config.model.contact = ContactModel::Sphere;
            else if (v == "sphere-alciatore") o.config.model.contact = ContactModel::SphereAlciatore;
            else if (v == "disk") o.config.model.contact = ContactModel::Disk;
            else fail("--model: unknown contact model '" + v + "' (sphere, sphere-alciatore or disk)");
        } else if (flag == "--cue-end-mass") {
            const std::string v = value();
            const double grams = parse_number(flag, v);
            // m / m_e in the squirt angle needs m_e > 0; past the ball's own
            // mass it is no cue's end mass (real shafts: a few to 15 g)
            if (!(grams > 0 && grams <= 1000 * kBallMass))
                fail("--cue-end-mass: must be in (0, 170] grams (at most the ball's mass), got '" + v + "'");
            o.config.model.cue_end_mass = grams / 1000;
        } else if (flag == "--broadphase") {
            const std::string v = value();
            if (v == "tree") o.config.broadphase = demo::WorldBroadphase::Tree;
            else if (v == "cells") o.config.broadphase = demo::WorldBroadphase::Cells;
            else fail("--broadphase: unknown broadphase '" + v + "' (tree or cells)");
        } else if (flag == "--game") {
            const std::string v = value();
            if (v == "practice") o.game = GameMode::Practice;
            else if (v == "8ball") o.game = GameMode::EightBall;
            else if (v == "9ball") o.game = GameMode::NineBall;
            else fail("--game: unknown game '" + v + "' (practice, 8ball or 9ball)");
        } else if (flag == "--players") {
            const std::vector<std::string> f = fields(value());
            if (f.size() != 2) fail("--players: expected two players, e.g. human,computer");
            for (size_t k = 0; k < 2; ++k) {
                if (f[k] != "human" && f[k] != "computer")
                    fail("--players: each player is human or computer, got '" + f[k] + "'");
                o.computer[k] = f[k] == "computer";
            }
            o.players_given = true;
        } else if (flag == "--headless") {
            o.headless = true;
        } else if (flag == "--seconds") {
            const std::string v = value();
            o.seconds = parse_number(flag, v);
            if (o.seconds < 0 || o.seconds > 86400) fail("--seconds: must be between 0 and 86400, got '" + v + "'");
            headless_only();
        } else if (flag == "--shot") {
            o.shots.push_back(parse_shot(value()));
            headless_only();
        } else if (flag == "--json") {
            o.json = true;
            headless_only();
        } else if (std::string Options::*path = output_path(flag)) {
            o.*path = path_value(flag, value());
            headless_only();
        } else {
            const size_t equals = flag.find('=');
            const std::string name = flag.substr(0, equals);
            if (equals != std::string::npos && takes_value(name))
                fail(cat("'", flag, "': give the value as the next argument (", name, " ", flag.substr(equals + 1), ")"));
            if (equals != std::string::npos && (name == "--headless" || name == "--json" || name == "--help"))
                fail(cat("'", flag, "': ", name, " takes no value"));
            if (flag.empty() || flag[0] != '-')
                fail("unexpected argument '" + flag + "' (the options start with --; see --help)");
            fail("unknown option '" + flag + "' (see --help)");
        }
    }
    check_consistency(o);
    return o;
}

}  // namespace demo
