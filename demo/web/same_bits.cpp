/* SPDX-License-Identifier: MIT */
// same_bits.cpp - the simulation alone (demo/pool, no SDL, no window), for
// the native/browser/aarch64 bit-identity check (demo/web/same_bits.sh): the
// rack of --seed SEED, one shot as --shot takes it through the same main
// loop as the headless run (sim.h run: the shot when the table is at rest,
// frames until it is at rest again), then the balls as the page's
// window.collide2d.state() gives them, each coordinate with 17 significant
// digits (the double itself).
// Usage: same_bits [SEED [DEG MPS [SIDE TOP]]]   (default: 1 0 12 0 0, the break)
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "pool/sim.h"

namespace {

class OneShot : public demo::Driver {
public:
    explicit OneShot(const demo::Shot &shot) : shot_(shot) {}
    bool next_frame(demo::Simulation &) override { return true; }
    bool before_step(demo::Simulation &sim, bool was_at_rest) override {
        if (!was_at_rest) return true;
        if (shot_taken_) return false;  // at rest after the shot: done
        sim.shoot(shot_);
        shot_taken_ = true;
        return true;
    }
    void after_step(const demo::Simulation &) override {}
    double frame_seconds() const override { return 0; }

private:
    demo::Shot shot_;
    bool shot_taken_ = false;
};

bool number(const char *text, double &out) {
    char *end = nullptr;
    out = std::strtod(text, &end);
    return end != text && *end == '\0';
}

}  // namespace

int main(int argc, char **argv) {
    double v[5] = {1, 0, 12, 0, 0};
    if (argc > 6 || argc == 3 || argc == 5) {
        std::fprintf(stderr, "usage: same_bits [SEED [DEG MPS [SIDE TOP]]]\n");
        return 2;
    }
    for (int i = 1; i < argc; ++i)
        if (!number(argv[i], v[i - 1])) {
            std::fprintf(stderr, "same_bits: not a number: '%s'\n", argv[i]);
            return 2;
        }
    if (!(v[0] >= 0 && v[0] <= 9007199254740992.0 && v[0] == static_cast<double>(static_cast<uint64_t>(v[0]))) ||
        !(v[2] > 0 && v[2] <= demo::kMaxShotSpeed) || v[3] * v[3] + v[4] * v[4] > 0.25) {
        std::fprintf(stderr, "same_bits: the seed must be an integer in [0, 2^53], speed in (0, %g] m/s, the tip offset at most 0.5\n",
                     demo::kMaxShotSpeed);
        return 2;
    }
    demo::SimConfig config;
    config.seed = static_cast<uint64_t>(v[0]);
    demo::Simulation sim(config);
    OneShot driver(demo::Shot{v[1], v[2], v[3], v[4]});
    demo::run(sim, driver);
    std::printf("{\"balls\":[");
    bool first = true;
    for (const demo::Ball &b : sim.balls()) {
        std::printf("%s{\"number\":%d,\"x\":%.17g,\"y\":%.17g,\"on_table\":%s}", first ? "" : ",", b.number, b.x, b.y,
                    b.active ? "true" : "false");
        first = false;
    }
    std::printf("]}\n");
    return 0;
}
