// game.h - a game of 8-ball played to the end without a window: the rack of
// the break scene (sim.h, scene.h), shots through the shot seam
// (simulate_shot, no frames), judged by the rules (rules.h), each chosen by
// the computer opponent (opponent.h).  Used by `billiards --game 8ball
// --headless` and by the tests; SDL-free.
#ifndef C2D_DEMO_GAME_H
#define C2D_DEMO_GAME_H

#include <cstdint>
#include <string>
#include <vector>

#include "opponent.h"
#include "rules.h"
#include "sim.h"

namespace demo {

struct ShotRecord {
    int player;            // 0 or 1
    Shot shot;
    bool placed = false;   // ball in hand: the cue ball was put at cue first
    Point cue{0, 0};
    std::vector<int> potted;  // numbers, in the order they fell (0 = the cue ball)
    Foul foul = Foul::None;
    bool keeps_turn = false;
    int candidates = 0;       // shots the computer simulated to choose it
    double think_seconds = 0; // wall time (not deterministic)
};

struct GameRecord {
    std::vector<ShotRecord> shots;
    std::vector<Ball> balls;     // the table at the end
    Group groups[2] = {Group::Open, Group::Open};
    int winner = -1;             // -1: no winner within the shot limit
    std::string reason;          // how the game ended
    int fouls = 0;
    long candidates = 0;         // every shot the computer simulated
    double think_seconds = 0;    // wall time of all the choosing
    double sim_seconds = 0;      // simulated time of the shots played
};

constexpr int kMaxGameShots = 400;

// Who plays in the window: practice (clear the table alone) or 8-ball, and
// for 8-ball which sides the computer plays.
struct Players {
    bool eight_ball = false;
    bool computer[2] = {false, true};
};

// Two computer players, the rack shuffled by config.seed, execution errors
// from seed.  Ends with a winner or after kMaxGameShots shots.
GameRecord play_computer_game(const SimConfig &config, uint64_t seed);

// Puts the 8 back on its spot (after it fell on the break).
void respot_eight(const Table &table, std::vector<Ball> &balls);

}  // namespace demo

#endif
