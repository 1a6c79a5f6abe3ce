/* SPDX-License-Identifier: MIT */
// opponent_bench.cpp - the computer opponent's thinking time, measured the
// same way every time: computer-versus-computer games of seeds FIRST..LAST
// (default 1-8), every turn but the break timed in CPU time of the thread
// (Plan::cpu_seconds), medians reported, and a digest of every shot chosen
// so that a faster opponent can be shown to choose the same shots.
//   build/opponent_bench [--plain] [FIRST LAST]
// --plain: both computers without position play (Search::Plain), the
// opponent of before it (digest 2d4a975dd0f8c1c9 on seeds 1-8 since the
// demo's own elementary functions; 7069196ad8fa2fe8 before them).
//   build/opponent_bench --duel [FIRST LAST]
// position play against plain, one game a seed (position play breaks on
// the odd seeds, so each side breaks half the games): the wins of each.
// Instruction counts, deterministic (divide Ir by the turns printed):
//   valgrind --tool=callgrind --toggle-collect='demo::Opponent::choose*'
//     build/opponent_bench 1 2
// Not part of make test (it takes seconds, and times are not asserted).
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "game/game.h"

namespace {

// FNV-1a over the bytes of a double: the digest of the games.
void mix(uint64_t &h, double x) {
    unsigned char b[sizeof x];
    std::memcpy(b, &x, sizeof x);
    for (unsigned char c : b) h = (h ^ c) * 0x100000001b3ULL;
}

double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

int main(int argc, char **argv) {
    bool plain = false, duel = false;
    if (argc > 1 && std::strcmp(argv[1], "--plain") == 0) plain = true;
    if (argc > 1 && std::strcmp(argv[1], "--duel") == 0) duel = true;
    if (plain || duel) --argc, ++argv;
    char *end = nullptr;
    const long first = argc > 1 ? std::strtol(argv[1], &end, 10) : 1;
    if (argc > 1 && (end == argv[1] || *end)) return std::fprintf(stderr, "opponent_bench: FIRST: a number\n"), 2;
    const long last = argc > 2 ? std::strtol(argv[2], &end, 10) : (duel ? 100 : 8);
    if (argc > 2 && (end == argv[2] || *end)) return std::fprintf(stderr, "opponent_bench: LAST: a number\n"), 2;
    if (duel) {
        long won = 0, lost = 0, none = 0, shots = 0;
        for (long seed = first; seed <= last; ++seed) {
            demo::SimConfig config;
            config.set_scene(demo::Scene::Break);
            config.seed = static_cast<uint64_t>(seed);
            const int me = seed % 2 ? 0 : 1;  // position play's seat
            demo::Search search[2];
            search[me] = demo::Search::Position;
            search[1 - me] = demo::Search::Plain;
            const demo::GameRecord g = demo::play_computer_game(config, config.seed, search);
            shots += static_cast<long>(g.shots.size());
            if (g.winner < 0) ++none;
            else if (g.winner == me) ++won;
            else ++lost;
        }
        const long games = last - first + 1;
        std::printf("duel, seeds %ld-%ld: position play won %ld, plain won %ld, no winner %ld; position play's "
                    "win rate %.1f%% (%.1f shots a game)\n",
                    first, last, won, lost, none, games > 0 ? 100.0 * static_cast<double>(won) / static_cast<double>(games) : 0.0,
                    games > 0 ? static_cast<double>(shots) / static_cast<double>(games) : 0.0);
        return 0;
    }
    const demo::Search both[2] = {plain ? demo::Search::Plain : demo::Search::Position,
                                  plain ? demo::Search::Plain : demo::Search::Position};
    std::vector<double> all;
    long turns = 0, candidates = 0, wins[2] = {0, 0};
    uint64_t digest = 0xcbf29ce484222325ULL;
    for (long seed = first; seed <= last; ++seed) {
        demo::SimConfig config;
        config.set_scene(demo::Scene::Break);
        config.seed = static_cast<uint64_t>(seed);
        const demo::GameRecord g = demo::play_computer_game(config, config.seed, both);
        std::vector<double> cpu;
        long cands = 0;
        for (const demo::ShotRecord &r : g.shots) {
            mix(digest, r.shot.angle_deg);
            mix(digest, r.shot.speed);
            mix(digest, r.shot.side);
            mix(digest, r.shot.topback);
            mix(digest, r.cue.x);
            mix(digest, r.cue.y);
            if (r.candidates == 0) continue;  // the break: nothing to think about
            cpu.push_back(r.cpu_seconds);
            cands += r.candidates;
        }
        if (g.winner >= 0) ++wins[g.winner];
        std::printf("seed %ld: %zu shots, %zu turns thought, %ld candidates, winner %d, median %.2f ms/turn\n", seed,
                    g.shots.size(), cpu.size(), cands, g.winner, 1e3 * median(cpu));
        all.insert(all.end(), cpu.begin(), cpu.end());
        turns += static_cast<long>(cpu.size());
        candidates += cands;
    }
    double total = 0;
    for (double t : all) total += t;
    std::printf("turns %ld, candidates %ld (%.1f a turn), CPU median %.2f ms/turn, mean %.2f ms/turn, "
                "%.0f candidates/s, wins %ld-%ld, digest %016llx\n",
                turns, candidates, turns ? static_cast<double>(candidates) / static_cast<double>(turns) : 0.0,
                1e3 * median(all), turns ? 1e3 * total / static_cast<double>(turns) : 0.0,
                total > 0 ? static_cast<double>(candidates) / total : 0.0, wins[0], wins[1],
                static_cast<unsigned long long>(digest));
    return 0;
}
