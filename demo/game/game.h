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
    bool nine_ball = false;      // the game was 9-ball
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
    bool eight_ball = false;  // a game by the rules (8-ball or 9-ball, `kind`), not practice
    bool computer[2] = {false, true};
    GameKind kind = GameKind::EightBall;
};

// Two computer players, the rack shuffled by config.seed, execution errors
// from seed.  Ends with a winner or after kMaxGameShots shots.
// kind: 8-ball (the 15-ball rack) or 9-ball (the diamond, set_up_nine_ball);
// the computer never declares a 9-ball push-out.
GameRecord play_computer_game(const SimConfig &config, uint64_t seed, GameKind kind = GameKind::EightBall);
// The same with each player's search (opponent.h: player 0 breaks).
GameRecord play_computer_game(const SimConfig &config, uint64_t seed, const Search search[2],
                              GameKind kind = GameKind::EightBall);

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
    // 9-ball: the player to shoot declares a push-out (rules.h
    // declare_push_out), or hands the shot back after the other's push-out
    // (pass_back); false when the rules do not allow it now.
    bool push_out();
    bool pass_back();
    // 9-ball, after a push-out, the computer to shoot: whether it hands the
    // shot back (computer_passes_back) rather than play it.
    bool computer_passes_back(const std::vector<Ball> &balls) const;
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
    Table table_;  // the table the computer judges a pass-back on
    std::vector<Ball> before_;
    std::vector<Event> events_;
    bool running_ = false;
    std::string last_;
    std::string last_reason_;  // the last verdict's reason
    int last_shooter_ = -1;    // who played the last shot
    int plans_ = 0;
    long candidates_ = 0;
    double think_seconds_ = 0;
};

// Why the game was won, said of the winner: the verdict's reason as it is
// when the winner took the last shot ("potted the 8 after clearing the
// group"), else what the loser did, named ("Player 2 (computer) potted the 8
// before clearing the group").
std::string win_reason(int winner, int shooter, const std::string &shooter_name, const std::string &reason);

// 9-ball, after the other player's push-out: the computer hands the shot
// back when it has no potting line on the lowest ball with an ease
// (opponent.h best_ease) of at least kPassBackEase, e.g. a cut under 60
// degrees from within 1 m.
constexpr double kPassBackEase = 0.25;
bool computer_passes_back(const GameState &state, const Table &table, const std::vector<Ball> &balls);

// Puts the 8 back on its spot (after it fell on the break).
void respot_eight(const Table &table, std::vector<Ball> &balls);
// Puts ball `number` back on its spot if it is off the table (spot_point).
void respot(const Table &table, std::vector<Ball> &balls, int number);

}  // namespace demo

#endif
