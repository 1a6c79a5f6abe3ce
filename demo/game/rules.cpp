/* SPDX-License-Identifier: MIT */
// rules.cpp - see rules.h.  The rules only read what happened (the shot's
// events and the table before and after); they never move a ball, so the
// window, the headless game and the computer opponent's look-ahead judge a
// shot the same way.
#include "game/rules.h"

#include <algorithm>
#include <cmath>

#include "pool/det_math.h"

namespace demo {

namespace {

constexpr int kEight = 8;
constexpr int kNine = 9;
constexpr int kFoulsToLose = 3;  // WPA 9-ball: three successive fouls
constexpr int kBreakRailBalls = 4;  // WPA: four object balls to a rail, or a pot

bool on_table(const std::vector<Ball> &balls, int number) {
    for (const Ball &b : balls)
        if (b.number == number) return b.active;
    return false;
}

bool potted(const ShotFacts &f, int number) { return std::find(f.potted.begin(), f.potted.end(), number) != f.potted.end(); }

Group other(Group g) { return g == Group::Solids ? Group::Stripes : g == Group::Stripes ? Group::Solids : Group::Open; }

// The first foul of a shot after the break, if any (the 8's fate is
// decided separately).
Foul foul_of(const GameState &state, const ShotFacts &f, const std::vector<Ball> &before) {
    if (potted(f, 0)) return Foul::Scratch;
    if (f.first_hit < 0) return Foul::NoBallHit;
    if (!legal_target(state, f.first_hit, before)) return Foul::WrongBallFirst;
    const bool object_potted = std::any_of(f.potted.begin(), f.potted.end(), [](int n) { return n != 0; });
    if (!object_potted && !f.rail_after_contact) return Foul::NoRail;
    return Foul::None;
}

Foul break_foul(const ShotFacts &f) {
    if (potted(f, 0)) return Foul::Scratch;
    const bool object_potted = std::any_of(f.potted.begin(), f.potted.end(), [](int n) { return n != 0; });
    if (!object_potted && f.balls_to_rail < kBreakRailBalls) return Foul::IllegalBreak;
    return Foul::None;
}

// Passes the turn; a foul gives the incoming player ball in hand.
void pass_turn(GameState &state, Verdict &v) {
    v.keeps_turn = false;
    state.turn = 1 - state.turn;
    state.ball_in_hand = v.foul != Foul::None;
}

void end_game(GameState &state, Verdict &v, int winner, const std::string &why) {
    v.winner = winner;
    state.winner = winner;
    v.reason = why;
    v.keeps_turn = false;
    state.ball_in_hand = false;
}

Verdict apply_break(GameState &state, const ShotFacts &f) {
    Verdict v;
    state.breaking = false;
    v.foul = break_foul(f);
    v.respot_eight = potted(f, kEight);
    const bool object_potted = std::any_of(f.potted.begin(), f.potted.end(), [](int n) { return n != 0 && n != kEight; });
    if (v.foul == Foul::None && object_potted) {
        v.keeps_turn = true;
        state.ball_in_hand = false;
        v.reason = "potted on the break: the table is open";
        return v;
    }
    v.reason = v.foul == Foul::None ? "nothing potted on the break" : std::string("foul on the break: ") + foul_text(v.foul);
    pass_turn(state, v);
    return v;
}

// --- 9-ball

bool any_object(const ShotFacts &f) {
    return std::any_of(f.potted.begin(), f.potted.end(), [](int n) { return n != 0; });
}

// A 9-ball foul: the cue ball down, no contact, the lowest ball not hit
// first, or nothing down and no rail after the contact; on the break also
// fewer than four balls to a cushion with nothing down.  A push-out fouls
// only by a scratch.
Foul nine_foul(const GameState &state, const ShotFacts &f, const std::vector<Ball> &before) {
    if (potted(f, 0)) return Foul::Scratch;
    if (state.push_out) return Foul::None;
    if (f.first_hit < 0) return Foul::NoBallHit;
    if (f.first_hit != lowest_ball(before)) return Foul::WrongBallFirst;
    if (state.breaking) return !any_object(f) && f.balls_to_rail < kBreakRailBalls ? Foul::IllegalBreak : Foul::None;
    if (!any_object(f) && !f.rail_after_contact) return Foul::NoRail;
    return Foul::None;
}

// The fouling player's count; the third in a row loses.
bool third_foul(GameState &state, Verdict &v, int shooter) {
    if (++state.fouls_in_row[shooter] < kFoulsToLose) return false;
    end_game(state, v, 1 - shooter, std::string("a third foul in a row (") + foul_text(v.foul) + ")");
    return true;
}

Verdict apply_nine(GameState &state, const ShotFacts &f, const std::vector<Ball> &before) {
    Verdict v;
    const int shooter = state.turn;
    const bool was_break = state.breaking, was_push = state.push_out;
    v.foul = nine_foul(state, f, before);
    state.breaking = false;
    state.push_out = false;
    state.push_out_allowed = was_break && v.foul == Foul::None && !potted(f, kNine);
    state.may_pass_back = false;
    if (v.foul != Foul::None) {
        v.respot_nine = potted(f, kNine);
        if (third_foul(state, v, shooter)) return v;
        v.reason = std::string(was_break ? "foul on the break: " : "foul: ") + foul_text(v.foul) +
                   (state.fouls_in_row[shooter] == kFoulsToLose - 1 ? " (two fouls in a row: a third loses)" : "");
        pass_turn(state, v);
        return v;
    }
    state.fouls_in_row[shooter] = 0;
    if (was_push) {
        v.respot_nine = potted(f, kNine);
        v.reason = "push-out: the other player shoots or passes it back";
        state.may_pass_back = true;
        pass_turn(state, v);
        return v;
    }
    if (potted(f, kNine)) {
        end_game(state, v, shooter, was_break ? "potted the 9 on the break" : "potted the 9");
        return v;
    }
    state.ball_in_hand = false;
    if (any_object(f)) {
        v.keeps_turn = true;
        v.reason = was_break ? "potted on the break" : "potted";
        return v;
    }
    v.reason = was_break ? "nothing potted on the break" : "nothing potted";
    pass_turn(state, v);
    return v;
}

}  // namespace

const char *game_name(GameKind g) { return g == GameKind::NineBall ? "9-ball" : "8-ball"; }

int lowest_ball(const std::vector<Ball> &before) {
    int lowest = 0;
    for (const Ball &b : before)
        if (b.active && b.number > 0 && (lowest == 0 || b.number < lowest)) lowest = b.number;
    return lowest;
}

bool declare_push_out(GameState &state) {
    if (state.game != GameKind::NineBall || !state.push_out_allowed || state.over()) return false;
    state.push_out = true;
    return true;
}

bool pass_back(GameState &state) {
    if (state.game != GameKind::NineBall || !state.may_pass_back || state.over()) return false;
    state.may_pass_back = false;
    state.turn = 1 - state.turn;
    return true;
}

const char *group_name(Group g) { return g == Group::Solids ? "solids" : g == Group::Stripes ? "stripes" : "open"; }

Group group_of(int number) {
    if (number >= 1 && number <= 7) return Group::Solids;
    if (number >= 9 && number <= 15) return Group::Stripes;
    return Group::Open;
}

const char *foul_name(Foul f) {
    switch (f) {
    case Foul::Scratch: return "scratch";
    case Foul::NoBallHit: return "no_ball_hit";
    case Foul::WrongBallFirst: return "wrong_ball_first";
    case Foul::NoRail: return "no_rail";
    case Foul::IllegalBreak: return "illegal_break";
    default: return "none";
    }
}

const char *foul_text(Foul f) {
    switch (f) {
    case Foul::Scratch: return "the cue ball fell in";
    case Foul::NoBallHit: return "the cue ball hit no ball";
    case Foul::WrongBallFirst: return "the wrong ball hit first";
    case Foul::NoRail: return "no ball went to a rail";
    case Foul::IllegalBreak: return "fewer than four balls went to a rail";
    default: return "no foul";
    }
}

ShotFacts shot_facts(const std::vector<Event> &events, const std::vector<Ball> &balls) {
    ShotFacts f;
    const auto number = [&](int index) { return index >= 0 && static_cast<size_t>(index) < balls.size() ? balls[static_cast<size_t>(index)].number : -1; };
    double contact_time = INFINITY;
    std::vector<int> railed;
    for (const Event &e : events) {
        const int n = number(e.ball);
        switch (e.kind) {
        case EventKind::BallBall:
            if (f.first_hit < 0 && n == 0) {
                f.first_hit = number(e.other);
                contact_time = e.t;
            }
            break;
        case EventKind::Cushion:
        case EventKind::Jaw:
            if (e.t >= contact_time) f.rail_after_contact = true;
            if (n > 0 && std::find(railed.begin(), railed.end(), n) == railed.end()) railed.push_back(n);
            break;
        case EventKind::Pocket: f.potted.push_back(n); break;
        default: break;
        }
    }
    f.balls_to_rail = static_cast<int>(railed.size());
    return f;
}

bool group_cleared(const GameState &state, const std::vector<Ball> &before) {
    const Group g = state.group[state.turn];
    if (g == Group::Open) return false;
    return std::none_of(before.begin(), before.end(), [g](const Ball &b) { return b.active && group_of(b.number) == g; });
}

bool legal_target(const GameState &state, int number, const std::vector<Ball> &before) {
    if (!on_table(before, number) || number == 0) return false;
    if (state.game == GameKind::NineBall) return state.push_out || number == lowest_ball(before);
    if (state.breaking) return true;
    if (state.open()) return number != kEight;
    if (group_cleared(state, before)) return number == kEight;
    return group_of(number) == state.group[state.turn];
}

Verdict apply_shot(GameState &state, const ShotFacts &f, const std::vector<Ball> &before) {
    if (state.over()) return Verdict{};
    if (state.game == GameKind::NineBall) return apply_nine(state, f, before);
    if (state.breaking) return apply_break(state, f);
    Verdict v;
    const int shooter = state.turn;
    const bool on_the_eight = group_cleared(state, before);
    v.foul = foul_of(state, f, before);
    if (potted(f, kEight)) {
        if (on_the_eight && v.foul == Foul::None) end_game(state, v, shooter, "potted the 8 after clearing the group");
        else if (v.foul != Foul::None) end_game(state, v, 1 - shooter, std::string("potted the 8 with a foul (") + foul_text(v.foul) + ")");
        else end_game(state, v, 1 - shooter, "potted the 8 before clearing the group");
        return v;
    }
    if (v.foul != Foul::None) {
        v.reason = std::string("foul: ") + foul_text(v.foul);
        pass_turn(state, v);
        return v;
    }
    state.ball_in_hand = false;
    int first_object = -1;
    for (int n : f.potted)
        if (n != 0 && first_object < 0) first_object = n;
    if (state.open() && first_object > 0) {
        state.group[shooter] = group_of(first_object);
        state.group[1 - shooter] = other(state.group[shooter]);
        v.group_assigned = true;
    }
    const Group mine = state.group[shooter];
    const bool own_potted = std::any_of(f.potted.begin(), f.potted.end(), [&](int n) { return n != 0 && group_of(n) == mine; });
    if (own_potted) {
        v.keeps_turn = true;
        v.reason = v.group_assigned ? std::string("takes ") + group_name(mine) : "potted";
        return v;
    }
    v.reason = "nothing of the group potted";
    pass_turn(state, v);
    return v;
}

bool cue_placement_ok(const Table &table, const std::vector<Ball> &balls, double x, double y) {
    if (!(x >= kBallRadius && x <= table.length - kBallRadius && y >= kBallRadius && y <= table.width - kBallRadius))
        return false;
    return std::none_of(balls.begin(), balls.end(), [&](const Ball &b) {
        return b.active && b.number != 0 && det_hypot(b.x - x, b.y - y) < kBallDiameter;
    });
}

Point eight_spot(const Table &table, const std::vector<Ball> &balls) { return spot_point(table, balls, kEight); }

Point spot_point(const Table &table, const std::vector<Ball> &balls, int number) {
    const double y = table.width / 2, foot = 0.75 * table.length;
    const auto free_at = [&](double x) {
        return std::none_of(balls.begin(), balls.end(), [&](const Ball &b) {
            return b.active && b.number != number && det_hypot(b.x - x, b.y - y) < kBallDiameter * 1.001;
        });
    };
    // quarter-radius steps towards the foot rail, then towards the head rail
    const double step = kBallRadius * 0.25;
    const int towards_foot = static_cast<int>((table.length - kBallRadius - foot) / step);
    const int towards_head = static_cast<int>((foot - kBallRadius) / step);
    for (int k = 0; k <= towards_foot; ++k)
        if (free_at(foot + k * step)) return {foot + k * step, y};
    for (int k = 1; k <= towards_head; ++k)
        if (free_at(foot - k * step)) return {foot - k * step, y};
    return {foot, y};
}

}  // namespace demo
