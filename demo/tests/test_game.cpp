/* SPDX-License-Identifier: MIT */
// test_game.cpp - 8-ball: the rules (rules.h) on constructed shots, checked
// over every ball and every combination that matters rather than one
// example each; the facts read from a shot's events; ball-in-hand placement;
// and computer-versus-computer games (game.h) that run to a winner by the
// rules, the same game from the same seed.
// usage: test_game [GAMES]   (default 3 games, seeds 1..GAMES)
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "game/game.h"
#include "tests/check.h"

namespace {

using namespace demo;

using demo_tests::check;

// A table holding the cue ball and the given object balls (positions do not
// matter to the rules).
std::vector<Ball> table_with(const std::vector<int> &numbers) {
    std::vector<Ball> balls{Ball{0.5, 0.6, 0, 0, 0, true}};
    double x = 1.0;
    for (int n : numbers) balls.push_back(Ball{x += 0.07, 0.6, 0, 0, n, true});
    return balls;
}

std::vector<int> all_but(const std::vector<int> &gone) {
    std::vector<int> out;
    for (int n = 1; n <= 15; ++n) {
        bool keep = true;
        for (int g : gone) keep = keep && g != n;
        if (keep) out.push_back(n);
    }
    return out;
}

GameState after_break(Group shooter, int turn = 0) {
    GameState s;
    s.breaking = false;
    s.turn = turn;
    s.group[turn] = shooter;
    s.group[1 - turn] = shooter == Group::Open ? Group::Open : shooter == Group::Solids ? Group::Stripes : Group::Solids;
    return s;
}

ShotFacts facts(int first_hit, std::vector<int> potted, bool rail) {
    ShotFacts f;
    f.first_hit = first_hit;
    f.potted = std::move(potted);
    f.rail_after_contact = rail;
    return f;
}

// --- fouls: the turn passes with ball in hand, whoever shoots, whatever group
void fouls() {
    const std::vector<Ball> full = table_with(all_but({}));
    bool scratch = true, no_hit = true, wrong = true, eight_first = true, no_rail = true, legal_miss = true;
    int cases = 0;
    for (int turn = 0; turn < 2; ++turn)
        for (Group g : {Group::Solids, Group::Stripes})
            for (int n = 1; n <= 15; ++n) {
                if (n == 8) continue;
                ++cases;
                const bool mine = group_of(n) == g;
                GameState s = after_break(g, turn);
                Verdict v = apply_shot(s, facts(n, {0}, true), full);
                scratch = scratch && v.foul == Foul::Scratch && s.turn == 1 - turn && s.ball_in_hand && !v.keeps_turn;
                s = after_break(g, turn);
                v = apply_shot(s, facts(n, {}, true), full);
                if (!mine) wrong = wrong && v.foul == Foul::WrongBallFirst && s.turn == 1 - turn && s.ball_in_hand;
                else legal_miss = legal_miss && v.foul == Foul::None && s.turn == 1 - turn && !s.ball_in_hand;
                s = after_break(g, turn);
                v = apply_shot(s, facts(n, {}, false), full);
                if (mine) no_rail = no_rail && v.foul == Foul::NoRail && s.turn == 1 - turn && s.ball_in_hand;
                s = after_break(g, turn);
                v = apply_shot(s, facts(-1, {}, true), full);
                no_hit = no_hit && v.foul == Foul::NoBallHit && s.turn == 1 - turn && s.ball_in_hand;
                s = after_break(Group::Open, turn);
                v = apply_shot(s, facts(8, {n}, true), full);
                eight_first = eight_first && v.foul == Foul::WrongBallFirst && s.open() && s.turn == 1 - turn;
            }
    check(cases == 2 * 2 * 14, "fouls: every case ran (2 players x 2 groups x the 14 balls but the 8)");
    check(scratch, "a scratch is a foul after any first contact: turn passes, ball in hand");
    check(no_hit, "hitting no ball is a foul: turn passes, ball in hand");
    check(wrong, "each of the opponent's balls first is a foul, for either group and player");
    check(eight_first, "the 8 first on an open table is a foul, and a ball potted on it assigns no group");
    check(no_rail, "no pot and no rail after a legal contact is a foul, for every ball of the group");
    check(legal_miss, "a legal contact with a rail and no pot passes the turn without a foul");
}

// --- groups: the table stays open after the break; the first legal pot
// assigns the group of the first ball that fell
void groups() {
    bool open_after_break = true, assigned = true, continued = true;
    int firsts = 0, seconds = 0;
    for (int n = 1; n <= 15; ++n) {
        if (n == 8) continue;
        ++firsts;
        const std::vector<Ball> full = table_with(all_but({}));
        GameState s;
        Verdict v = apply_shot(s, facts(1, {n}, true), full);
        open_after_break = open_after_break && s.open() && v.keeps_turn && !s.breaking && s.turn == 0;
        for (int second = 1; second <= 15; ++second) {
            if (second == 8 || second == n) continue;
            ++seconds;
            GameState t = after_break(Group::Open, 1);
            v = apply_shot(t, facts(second, {n, second}, false), full);
            assigned = assigned && v.group_assigned && t.group[1] == group_of(n) && t.group[0] != group_of(n) &&
                       t.group[0] != Group::Open;
            continued = continued && v.keeps_turn && t.turn == 1 && v.foul == Foul::None;
        }
    }
    check(firsts == 14 && seconds == 14 * 13, "groups: every case ran (14 balls first, each with the 13 others second)");
    check(open_after_break, "every ball potted on the break keeps the table open and the breaker at the table");
    check(assigned, "the first legal pot assigns the first fallen ball's group, the other to the opponent");
    check(continued, "a legal pot keeps the shooter at the table");
    const std::vector<Ball> full = table_with(all_but({}));
    bool others_only = true;
    for (int n = 9; n <= 15; ++n) {
        GameState s = after_break(Group::Solids);
        const Verdict v = apply_shot(s, facts(1, {n}, false), full);
        others_only = others_only && v.foul == Foul::None && !v.keeps_turn && s.turn == 1 && !s.ball_in_hand;
    }
    check(others_only, "potting only the opponent's balls after a legal hit passes the turn, no foul");
}

// --- the break
void break_shot() {
    const std::vector<Ball> full = table_with(all_but({}));
    GameState s;
    ShotFacts f = facts(1, {}, true);
    f.balls_to_rail = 3;
    Verdict v = apply_shot(s, f, full);
    check(v.foul == Foul::IllegalBreak && s.turn == 1 && s.ball_in_hand, "a break with no pot and 3 balls to a rail is a foul");
    s = GameState{};
    f.balls_to_rail = 4;
    v = apply_shot(s, f, full);
    check(v.foul == Foul::None && s.turn == 1 && !s.ball_in_hand && s.open(), "4 balls to a rail: a legal break, turn passes");
    s = GameState{};
    v = apply_shot(s, facts(1, {8}, true), full);
    check(v.respot_eight && s.winner < 0 && !s.breaking, "the 8 on the break is spotted again, the game goes on");
    s = GameState{};
    v = apply_shot(s, facts(1, {3, 0}, true), full);
    check(v.foul == Foul::Scratch && s.turn == 1 && s.ball_in_hand && s.open(), "a scratch on the break: ball in hand, table open");
}

// --- the 8 after the break: win only with the group cleared and no foul
void eight_ball() {
    bool all = true;
    for (int turn = 0; turn < 2; ++turn)
        for (Group g : {Group::Solids, Group::Stripes})
            for (bool cleared : {false, true})
                for (int foul = 0; foul < 3; ++foul) {
                    std::vector<int> gone;
                    if (cleared)
                        for (int n = 1; n <= 15; ++n)
                            if (group_of(n) == g) gone.push_back(n);
                    const std::vector<Ball> before = table_with(all_but(gone));
                    GameState s = after_break(g, turn);
                    const int own = g == Group::Solids ? 3 : 12, theirs = g == Group::Solids ? 12 : 3;
                    const int first = foul == 2 ? theirs : cleared ? 8 : own;
                    std::vector<int> potted{8};
                    if (foul == 1) potted.push_back(0);
                    const Verdict v = apply_shot(s, facts(first, potted, true), before);
                    const int expected = cleared && foul == 0 ? turn : 1 - turn;
                    all = all && v.winner == expected && s.winner == expected && s.over();
                }
    check(all, "the 8 wins with the group cleared and no foul; loses early, on a scratch or a wrong first ball");
    GameState s = after_break(Group::Solids);
    std::vector<Ball> before = table_with(all_but({1, 2, 3, 4, 5, 6, 7}));
    const Verdict v = apply_shot(s, facts(8, {}, true), before);
    check(v.foul == Foul::None && s.turn == 1 && !s.over(), "with the group cleared the 8 is the legal first ball");
    s = after_break(Group::Solids);
    check(!legal_target(s, 8, table_with(all_but({1, 2, 3, 4, 5, 6})) ), "the 8 is not a legal first ball while one of the group is left");
}

// --- facts from events: first contact, rails after it, pots in order
void facts_from_events() {
    const std::vector<Ball> balls = table_with({5, 12});
    const auto ev = [](double t, EventKind k, int ball, int other) {
        return Event{t, k, ball, other, -1, 0, 0, 0, 0, 0, 0, 0, 0};
    };
    std::vector<Event> events = {ev(0, EventKind::Strike, 0, -1), ev(0.1, EventKind::Cushion, 0, -1),
                                 ev(0.2, EventKind::BallBall, 0, 2), ev(0.2, EventKind::BallBall, 2, 0),
                                 ev(0.3, EventKind::BallBall, 1, 2), ev(0.5, EventKind::Pocket, 1, -1),
                                 ev(0.6, EventKind::Pocket, 0, -1)};
    ShotFacts f = shot_facts(events, balls);
    check(f.first_hit == 12, "first_hit is the first ball the cue ball touched (by number)");
    check(!f.rail_after_contact, "a cushion before the first contact does not count as a rail after it");
    check(f.potted == std::vector<int>({5, 0}), "potted lists numbers in the order they fell");
    events.push_back(ev(0.7, EventKind::Jaw, 2, -1));
    f = shot_facts(events, balls);
    check(f.rail_after_contact && f.balls_to_rail == 1, "a jaw after the contact counts as a rail");
}

void placement() {
    const Table table = scene_table(Scene::Break, TableSpec{});
    const std::vector<Ball> balls = {Ball{0.5, 0.6, 0, 0, 0, true}, Ball{1.2, 0.6, 0, 0, 5, true}, Ball{2.0, 0.3, 0, 0, 12, true}};
    const Ball &five = balls[1];
    bool ok = true;
    for (int k = 0; k < 64; ++k) {
        const double a = 2 * M_PI * k / 64;
        ok = ok && !cue_placement_ok(table, balls, five.x + 0.99 * kBallDiameter * std::cos(a), five.y + 0.99 * kBallDiameter * std::sin(a));
        ok = ok && cue_placement_ok(table, balls, five.x + 1.01 * kBallDiameter * std::cos(a), five.y + 1.01 * kBallDiameter * std::sin(a));
    }
    check(ok, "ball in hand: refused over a ball, allowed just clear of it, all round");
    check(!cue_placement_ok(table, balls, 0.5 * kBallRadius, 0.6) && !cue_placement_ok(table, balls, 1.0, table.width),
          "ball in hand: refused off the playing surface");
    std::vector<Ball> rack = set_up(Scene::Break, TableSpec{}, 0, 1).balls;
    for (Ball &b : rack)
        if (b.number == 8) b.active = false;
    respot_eight(table, rack);
    bool clear = true;
    for (const Ball &a : rack)
        for (const Ball &b : rack)
            if (a.number == 8 && b.number != 8) clear = clear && std::hypot(a.x - b.x, a.y - b.y) >= kBallDiameter;
    check(clear, "the 8 spotted again into a full rack touches no ball");
}

// --- computer against computer
// Position play (opponent.h: position_value, with_position) on a
// constructed table: solids to shoot, the 1 a quarter metre out of the
// corner pocket at (0, 0) with the cue ball 0.4 m straight behind it, the 8
// and stripes elsewhere.  Left so (a straight pot at every speed tried) the
// table is worth at least 0.5; the same table with six stripes ringed
// round the cue ball (2.1 R from it: every path out passes within 2R of
// one) has no potting line and is worth 0, with no shot tried.  A
// candidate leaving the first is then preferred to one leaving the second
// even when the second's own score (its ease, 0.9) beats the first's (0.2).
void position_play() {
    SimConfig config;
    config.set_scene(Scene::Break);
    config.broadphase = WorldBroadphase::List;
    const Table table = scene_table(config.scene, config.table);
    const Pocket *corner = &table.pockets[0];
    for (const Pocket &p : table.pockets)
        if (p.x + p.y < corner->x + corner->y) corner = &p;
    const double mx = 0.5 * (corner->mouth[0].x + corner->mouth[1].x), my = 0.5 * (corner->mouth[0].y + corner->mouth[1].y);
    const double ax = mx + (corner->x - mx) / 3, ay = my + (corner->y - my) / 3;  // opponent.cpp's aim point
    const double cx = 0.5 * table.length, cy = 0.5 * table.width, d = std::hypot(cx - ax, cy - ay);
    const double ux = (cx - ax) / d, uy = (cy - ay) / d;
    const Ball cue{ax + 0.65 * ux, ay + 0.65 * uy, 0, 0, 0, true};
    std::vector<Ball> open{cue, Ball{ax + 0.25 * ux, ay + 0.25 * uy, 0, 0, 1, true}, Ball{1.27, 1.0, 0, 0, 8, true},
                           Ball{2.2, 1.0, 0, 0, 15, true}};
    std::vector<Ball> ringed = open;
    for (int k = 0; k < 6; ++k) {
        const double a = k * M_PI / 3, r = 2.1 * kBallRadius;
        open.push_back(Ball{2.0 + r * std::cos(a), 0.35 + r * std::sin(a), 0, 0, 9 + k, true});
        ringed.push_back(Ball{cue.x + r * std::cos(a), cue.y + r * std::sin(a), 0, 0, 9 + k, true});
    }
    GameState state;
    state.breaking = false;
    state.group[0] = Group::Solids;
    state.group[1] = Group::Stripes;
    int tried_open = 0, tried_ringed = 0;
    const double with_shot = position_value(config, table, state, open, &tried_open);
    const double without = position_value(config, table, state, ringed, &tried_ringed);
    std::printf("    position values: %.3f (%d shots tried), snookered %.3f (%d tried)\n", with_shot, tried_open, without,
                tried_ringed);
    check(with_shot >= 0.5 && with_shot <= 1 && tried_open > 0, "a straight pot left: the table is worth 0.5 or more");
    check(without == 0 && tried_ringed == 0, "the cue ball ringed by the other group: no potting line, worth 0");
    check(best_ease(state, table, ringed) == 0 && best_ease(state, table, open) > 0, "the ring blocks every line");
    const double leaves_shot = with_position(100 + 50 * 0.2, with_shot), leaves_none = with_position(100 + 50 * 0.9, without);
    check(leaves_shot > leaves_none, "position play prefers the candidate leaving a shot to one leaving none");
}

void games(int count) {
    SimConfig config;
    for (int seed = 1; seed <= count; ++seed) {
        config.seed = static_cast<uint64_t>(seed);
        const GameRecord g = play_computer_game(config, config.seed);
        bool turns = true;
        int counted = 0;
        for (size_t i = 0; i + 1 < g.shots.size(); ++i) {
            const ShotRecord &r = g.shots[i];
            turns = turns && (g.shots[i + 1].player == (r.keeps_turn ? r.player : 1 - r.player));
            turns = turns && (g.shots[i + 1].placed == (r.foul != Foul::None));
        }
        for (const ShotRecord &r : g.shots) counted += r.foul != Foul::None;
        bool eight_down = false, winner_cleared = true;
        for (const Ball &b : g.balls) {
            if (b.number == 8) eight_down = !b.active;
            if (b.active && g.winner >= 0 && group_of(b.number) == g.groups[g.winner] && g.reason.find("after clearing") != std::string::npos)
                winner_cleared = false;
        }
        std::printf("    seed %d: %zu shots, %d fouls, winner %d (%s), %ld candidates, %.2f s thinking (%.0f shots/s)\n",
                    seed, g.shots.size(), g.fouls, g.winner, g.reason.c_str(), g.candidates, g.think_seconds,
                    static_cast<double>(g.candidates) / std::max(1e-9, g.think_seconds));
        const std::string s = " (seed " + std::to_string(seed) + ")";
        check(g.winner == 0 || g.winner == 1, "the game ends with a winner" + s);
        check(eight_down && winner_cleared, "it ends on the 8, the winner's group cleared when won on the 8" + s);
        check(turns && counted == g.fouls, "the turn passes exactly when the rules say, ball in hand after each foul" + s);
        if (seed == 1) {
            const GameRecord again = play_computer_game(config, config.seed);
            bool same = again.shots.size() == g.shots.size() && again.winner == g.winner;
            for (size_t i = 0; same && i < g.shots.size(); ++i)
                same = g.shots[i].shot.angle_deg == again.shots[i].shot.angle_deg &&
                       g.shots[i].shot.speed == again.shots[i].shot.speed && g.shots[i].potted == again.shots[i].potted;
            check(same, "the same seed plays the same game");
        }
    }
}

}  // namespace

int main(int argc, char **argv) {
    const int count = argc > 1 ? static_cast<int>(std::strtol(argv[1], nullptr, 10)) : 3;
    fouls();
    groups();
    break_shot();
    eight_ball();
    facts_from_events();
    placement();
    position_play();
    games(count);
    return demo_tests::check_summary("test_game");
}
