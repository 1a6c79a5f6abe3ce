/* SPDX-License-Identifier: MIT */
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

#include "game/opponent.h"
#include "game/rules.h"
#include "pool/sim.h"

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
    double cpu_seconds = 0;   // CPU time of the choosing (not deterministic)
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
// The same with each player's search (opponent.h: player 0 breaks).
GameRecord play_computer_game(const SimConfig &config, uint64_t seed, const Search search[2]);

// The window's 8-ball: the rules' state between the frames of the shared
// main loop.  The window tells it when a shot starts, hands it each frame's
// events, and asks for the verdict when the table is at rest; a computer's
// turn is planned here.
class Match {
public:
    Match(const SimConfig &config, const Players &players);
    void reset();
    bool eight_ball() const { return players_.eight_ball; }
    const GameState &state() const { return state_; }
    bool computer(int player) const { return players_.computer[player]; }
    // 8-ball, not over, and the computer's turn.
    bool computer_to_play() const { return eight_ball() && !state_.over() && computer(state_.turn); }
    void shot_started(const std::vector<Ball> &balls);
    bool shot_running() const { return running_; }
    void add_events(const std::vector<Event> &events);
    // The shot has come to rest on `balls`: the verdict.  Returns true if
    // balls changed (the 8 spotted again after the break).
    bool shot_ended(const Table &table, std::vector<Ball> &balls);
    Plan plan(const std::vector<Ball> &balls);
    // The panel's lines: the players and their groups, whose turn, the last
    // verdict; placing: a human has the cue ball in hand, not yet put down.
    std::vector<std::string> status(bool placing) const;
    // The end of the game, for the banner ("" while it goes on).
    std::string result() const;
    long candidates() const { return candidates_; }
    double think_seconds() const { return think_seconds_; }

private:
    std::string name(int player) const;
    Players players_;
    SimConfig config_;
    GameState state_;
    Opponent opponents_[2];
    std::vector<Ball> before_;
    std::vector<Event> events_;
    bool running_ = false;
    std::string last_;
    int plans_ = 0;
    long candidates_ = 0;
    double think_seconds_ = 0;
};

// Puts the 8 back on its spot (after it fell on the break).
void respot_eight(const Table &table, std::vector<Ball> &balls);

}  // namespace demo

#endif
