/* SPDX-License-Identifier: MIT */
// rules.h - 8-ball (after the WPA rules, simplified where a computer game
// has no referee to ask: no called shots, no push-outs), without SDL.
//
// A game: the break, then turns.  The table is open after the break; the
// first legal shot after the break that pots object balls gives the shooter
// the group of the first ball that fell (solids 1-7, stripes 9-15), the
// opponent the other.  A shooter keeps the table while each shot is legal
// and pots at least one of the shooter's own group (on an open table: any
// ball but the 8).
//
// Fouls (the turn passes, the incoming player has the cue ball in hand
// anywhere on the table; balls potted on a foul stay down):
//   scratch          the cue ball falls
//   no ball hit      the cue ball touches no object ball
//   wrong ball first the first ball touched is not the shooter's: of the
//                    shooter's group, or any but the 8 on an open table, or
//                    the 8 once the group is cleared
//   no rail          after that first contact no ball falls and no ball
//                    (cue ball included) touches a cushion or a jaw
// The break is legal if a ball falls or at least four object balls reach a
// cushion; otherwise it is a foul, as is a scratch on the break (WPA lets
// the opponent choose to re-rack; here the opponent takes ball in hand).
// The 8: potted on the break it is spotted again (on the foot spot, or the
// nearest free point towards the foot rail) and the game goes on; potted
// later it wins for a shooter whose group was cleared before the shot, on
// a shot without a foul, and loses in every other case (potted early, or
// with a foul such as a scratch).
//
// 9-ball (GameKind::NineBall, after the WPA rules): balls 1-9, racked in a
// diamond with the 1 at the apex on the foot spot and the 9 in the middle.
// Every shot, the break included, must first contact the lowest-numbered
// ball on the table; then a ball must fall or a ball reach a cushion (the
// same no-rail foul as 8-ball). The break is legal when a ball falls or at
// least four object balls reach a cushion. Any ball potted on a legal shot
// keeps the table; the 9 potted on a legal shot (the break and combinations
// included) wins. The 9 potted on a foul or a push-out is spotted on the
// foot spot (as the 8 after the break). A foul gives the incoming player
// ball in hand anywhere. Push-out: the shot right after a legal break may be
// declared a push-out (declare_push_out): no contact or rail is needed, only
// a scratch is a foul, and balls other than the 9 potted stay down; then the
// incoming player chooses to shoot or to pass the shot back (pass_back).
// Three fouls in a row by one player, on three successive turns without a
// legal shot between, lose the game (WPA 9-ball 1.9; the warning after the
// second foul is the verdict's reason).
#ifndef C2D_DEMO_RULES_H
#define C2D_DEMO_RULES_H

#include <string>
#include <vector>

#include "pool/events.h"
#include "pool/motion.h"
#include "pool/table.h"

namespace demo {

enum class GameKind { EightBall, NineBall };

enum class Group { Open, Solids, Stripes };
const char *group_name(Group g);  // "open", "solids", "stripes"
// The group a ball belongs to (Open for the cue ball and the 8).
Group group_of(int number);

enum class Foul { None, Scratch, NoBallHit, WrongBallFirst, NoRail, IllegalBreak };
const char *foul_name(Foul f);  // "none", "scratch", "no_ball_hit", "wrong_ball_first", "no_rail", "illegal_break"
// The foul in words, for players (the verdicts' reasons, the window):
// "no foul", "the cue ball fell in", "the cue ball hit no ball", "the wrong
// ball hit first", "no ball went to a rail", "fewer than four balls went to a
// rail".  foul_name's names stay those of the headless JSON.
const char *foul_text(Foul f);

// What a shot did, as the rules see it.
struct ShotFacts {
    int first_hit = -1;           // number of the first object ball the cue ball touched; -1 none
    std::vector<int> potted;      // numbers of the balls that fell, in order (0 = the cue ball)
    bool rail_after_contact = false;  // a ball touched a cushion or jaw after first_hit's contact
    int balls_to_rail = 0;        // object balls that touched a cushion or jaw (the break's test)
};

// Reads the facts from a shot's events; balls are the table before the shot
// (events name balls by index into it).
ShotFacts shot_facts(const std::vector<Event> &events, const std::vector<Ball> &balls);

struct GameState {
    GameKind game = GameKind::EightBall;
    int turn = 0;                       // the player to shoot, 0 or 1
    Group group[2] = {Group::Open, Group::Open};
    bool breaking = true;               // the next shot is the break
    bool ball_in_hand = false;          // the shooter may place the cue ball anywhere
    int winner = -1;                    // 0 or 1 once the game is over
    // 9-ball only:
    int fouls_in_row[2] = {0, 0};       // each player's fouls since his last legal shot
    bool push_out_allowed = false;      // the shot after the break: it may be a push-out
    bool push_out = false;              // the next shot is a declared push-out
    bool may_pass_back = false;         // after a push-out: the shooter may hand the shot back
    bool open() const { return group[0] == Group::Open; }
    bool over() const { return winner >= 0; }
};

// What the rules made of a shot.
struct Verdict {
    Foul foul = Foul::None;
    bool keeps_turn = false;
    bool group_assigned = false;  // this shot gave the shooter a group
    bool respot_eight = false;    // the 8 fell on the break: put it back
    bool respot_nine = false;     // 9-ball: the 9 fell on a foul or a push-out: put it back
    int winner = -1;              // the game ended on this shot
    std::string reason;           // for people: why the game ended or the turn passed
};

// Whether ball `number` is a legal first contact for the shooter, given the
// balls on the table before the shot.
bool legal_target(const GameState &state, int number, const std::vector<Ball> &before);
// 9-ball: the lowest-numbered object ball on `before` (0 if none).
int lowest_ball(const std::vector<Ball> &before);
// 9-ball: the shooter declares the next shot a push-out; false (and no
// change) unless it is the shot right after the break.
bool declare_push_out(GameState &state);
// 9-ball: after a push-out the shooter hands the shot back to the player who
// pushed; false (and no change) when there was no push-out just before.
bool pass_back(GameState &state);
// The game's name for people: "8-ball" or "9-ball".
const char *game_name(GameKind g);

// Whether the shooter's group is off the table (the 8 is next).
bool group_cleared(const GameState &state, const std::vector<Ball> &before);

// Applies one shot played from the table `before`.  Updates state (turn,
// groups, ball in hand, winner).
Verdict apply_shot(GameState &state, const ShotFacts &facts, const std::vector<Ball> &before);

// Whether the cue ball may be placed (ball in hand) with its centre at
// (x, y): on the playing surface, touching no ball still on the table.
bool cue_placement_ok(const Table &table, const std::vector<Ball> &balls, double x, double y);

// Where the 8 goes back after falling on the break: the foot spot, or the
// nearest free point on the long axis towards the foot rail (then towards
// the head rail).
Point eight_spot(const Table &table, const std::vector<Ball> &balls);
// The same spot for any ball (the 9 of 9-ball): balls other than `number`
// must leave it free.
Point spot_point(const Table &table, const std::vector<Ball> &balls, int number);

}  // namespace demo

#endif
