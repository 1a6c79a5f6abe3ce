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
#ifndef C2D_DEMO_RULES_H
#define C2D_DEMO_RULES_H

#include <string>
#include <vector>

#include "pool/events.h"
#include "pool/motion.h"
#include "pool/table.h"

namespace demo {

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
    int turn = 0;                       // the player to shoot, 0 or 1
    Group group[2] = {Group::Open, Group::Open};
    bool breaking = true;               // the next shot is the break
    bool ball_in_hand = false;          // the shooter may place the cue ball anywhere
    int winner = -1;                    // 0 or 1 once the game is over
    bool open() const { return group[0] == Group::Open; }
    bool over() const { return winner >= 0; }
};

// What the rules made of a shot.
struct Verdict {
    Foul foul = Foul::None;
    bool keeps_turn = false;
    bool group_assigned = false;  // this shot gave the shooter a group
    bool respot_eight = false;    // the 8 fell on the break: put it back
    int winner = -1;              // the game ended on this shot
    std::string reason;           // for people: why the game ended or the turn passed
};

// Whether ball `number` is a legal first contact for the shooter, given the
// balls on the table before the shot.
bool legal_target(const GameState &state, int number, const std::vector<Ball> &before);
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

}  // namespace demo

#endif
