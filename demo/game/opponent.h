/* SPDX-License-Identifier: MIT */
// opponent.h - the computer player of 8-ball (rules.h), without SDL.  It
// chooses a shot by playing candidate shots to rest with the same engine the
// game uses (sim.h simulate_shot) and judging each with the same rules.
//
// Candidates, from the cue ball's position:
//   pots     for each legal object ball and each pocket whose line from the
//            ball is clear: the ghost-ball aim (the cue ball's centre at
//            contact sits 2R behind the ball on the line from the pocket's
//            mouth through the ball), if the cue ball's path to it is clear
//            and the cut is under 75 degrees; at 4 speeds (1.2, 2, 3, 4.5
//            m/s) and 5 tips (centre, follow 0.35 R, draw 0.35 R, left and
//            right english 0.3 R)
//   safeties straight at each legal ball's centre and at half-ball hits on
//            either side, at 2 and 4 m/s (so a shot is found when no pot is)
// Ball in hand: the cue ball is tried straight behind each potting line at
// 0.25 and 0.45 m from the ghost ball (legal placements only), with the
// pot candidates of that line.
// Score of a candidate (higher is better): a win 1e6, a loss -1e6; a foul
// -1000; a shot that keeps the table 100 plus 50 times the best "ease" of
// the next shot (cos(cut) / (1 + distance), over the clear potting lines);
// a legal shot that hands over the table minus 20 times the opponent's best
// ease (a safety); a shot that never settles -1e5.  Position play
// (Search::Position, the default): the 4 best candidates that keep the
// table are weighed again by the next shot from where each leaves the cue
// ball (position_value, with_position): up to 27 more shots each, simulated
// the same way; when none keeps the table, the 4 best safeties lose 100
// times the value of the table they leave the opponent.
// The chosen shot is played with a seeded execution error (angle +-0.25
// degrees, speed +-4%, uniform), so a game depends on --seed only and is
// the same on every machine.  The break: 12 m/s from the head spot at the
// apex ball, with the same error.
// Cost: about 105 candidates a turn on seeds 1-8, 46 M instructions and
// 3.5 ms of CPU without position play, 149 shots, 61.5 M and 6.5 ms with it
// (build/opponent_bench; docs/GAME.md has the figures), most
// of it the world's predictions in the library, so the work is cut only
// where it cannot change the choice: the candidate runs find pairs with a
// plain list of the 16 boxes (WorldBroadphase::List, its margin 3 R) instead
// of Box2D's tree; once a shot
// scoring a foul or better is known, a run whose events already make it a
// foul or a loss (a scratch, a wrong first contact, the 8 too early) ends
// there; once a win is known the rest are not played.  A later candidate
// replaces the best only with a strictly higher score, so the shot chosen
// is the one a full weighing of every candidate would choose.
#ifndef C2D_DEMO_OPPONENT_H
#define C2D_DEMO_OPPONENT_H

#include <cstdint>
#include <vector>

#include "game/rules.h"
#include "pool/sim.h"

namespace demo {

// How deep the opponent looks: Plain scores each candidate by its own run
// (the score above); Position (the default) then weighs the best that keep
// the table (or, if none does, the best safeties) again by the next shot
// they leave (position_value).
enum class Search { Plain, Position };

struct Plan {
    Shot shot{0, 0};
    bool place_cue = false;  // ball in hand: put the cue ball at cue first
    Point cue{0, 0};
    double score = 0;        // the candidate's score (before the execution error)
    int candidates = 0;      // candidates weighed to choose this one (those cut short or skipped included,
                             // and position play's next shots)
    double think_seconds = 0;  // wall time (not deterministic; for the figures only)
    double cpu_seconds = 0;    // the thread's CPU time choosing (not deterministic; opponent_bench)
};

class Opponent {
public:
    Opponent(const SimConfig &config, uint64_t seed, Search search = Search::Position);
    // The shot for the player state.turn, on the table at rest `balls`.
    Plan choose(const GameState &state, const std::vector<Ball> &balls);

private:
    SimConfig config_;
    Table table_;
    Rng rng_;
    Search search_;
};

// The ease of the best potting line for `state`'s shooter with the cue ball
// where it is in balls (0 if none): cos(cut) / (1 + distance in m).
double best_ease(const GameState &state, const Table &table, const std::vector<Ball> &balls);

// Position play: how good the table at rest `balls` is for `state`'s shooter
// to shoot next, in [0, 1], from the best score of the next shots tried
// (pots only: the 3 easiest potting lines from the cue ball, at 1.2, 2 and 3
// m/s, centre, follow and draw, each played to rest like a candidate):
// 1 if one wins, 0.5 + ease / 2 (0.5 to 1) if the best keeps the table
// (its score 100 + 50 ease), 0 if none does (no potting line, or none that
// pots).  tried (if not null): the shots simulated.
double position_value(const SimConfig &config, const Table &table, const GameState &state,
                      const std::vector<Ball> &balls, int *tried = nullptr);
// A candidate's score with position play: score + 100 value, so a shot that
// keeps the table and leaves a next shot that does (value >= 0.5) outranks
// any that leaves none (scores 100 to 150 before).
double with_position(double score, double value);

}  // namespace demo

#endif
