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
    bool words = true;
    for (Foul f : {Foul::Scratch, Foul::NoBallHit, Foul::WrongBallFirst, Foul::NoRail, Foul::IllegalBreak}) {
        GameState s = after_break(Group::Solids);
        const Verdict v = f == Foul::Scratch ? apply_shot(s, facts(3, {0}, true), table_with(all_but({})))
                        : f == Foul::NoBallHit ? apply_shot(s, facts(-1, {}, false), table_with(all_but({})))
                        : f == Foul::WrongBallFirst ? apply_shot(s, facts(12, {}, true), table_with(all_but({})))
                        : f == Foul::NoRail ? apply_shot(s, facts(3, {}, false), table_with(all_but({})))
                                            : Verdict{};
        words = words && std::string(foul_text(f)).find('_') == std::string::npos &&
                (f == Foul::IllegalBreak || (v.foul == f && v.reason == std::string("foul: ") + foul_text(f)));
    }
    check(words, "a foul's verdict says it in words (foul_text), not its JSON name");
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
    bool all = true, words = true, said = true;
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
                    // the verdict in words; the winner's line says who did it
                    words = words && v.reason.find('_') == std::string::npos;
                    const std::string line = win_reason(expected, turn, "Player " + std::to_string(turn + 1), v.reason);
                    said = said && (expected == turn ? line == v.reason
                                                     : line == "Player " + std::to_string(turn + 1) + " " + v.reason);
                }
    check(all, "the 8 wins with the group cleared and no foul; loses early, on a scratch or a wrong first ball");
    check(words, "the verdicts on the 8 name no internal foul names (no '_')");
    check(said, "the winner's line names the loser when the loser's shot ended the game");
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

// --- 9-ball (rules.h): every lowest ball against every first contact

std::vector<Ball> nine_table(int lowest) {
    std::vector<int> n;
    for (int k = lowest; k <= 9; ++k) n.push_back(k);
    return table_with(n);
}

GameState nine_after_break(int turn = 0) {
    GameState s;
    s.game = GameKind::NineBall;
    s.breaking = false;
    s.turn = turn;
    return s;
}

void nine_ball_first_contact() {
    bool lowest = true, wrong = true, legal = true, no_rail = true, eight_is_a_ball = true;
    int cases = 0;
    for (int low = 1; low <= 9; ++low) {
        const std::vector<Ball> t = nine_table(low);
        lowest = lowest && lowest_ball(t) == low;
        for (int hit = low; hit <= 9; ++hit)
            for (int turn = 0; turn < 2; ++turn) {
                ++cases;
                GameState s = nine_after_break(turn);
                Verdict v = apply_shot(s, facts(hit, {}, true), t);
                if (hit != low) wrong = wrong && v.foul == Foul::WrongBallFirst && s.turn == 1 - turn && s.ball_in_hand;
                else legal = legal && v.foul == Foul::None && s.turn == 1 - turn && !s.ball_in_hand && !s.over();
                s = nine_after_break(turn);
                v = apply_shot(s, facts(low, {}, false), t);
                no_rail = no_rail && v.foul == Foul::NoRail && s.ball_in_hand;
                if (low <= 8 && hit == low) {
                    s = nine_after_break(turn);
                    v = apply_shot(s, facts(low, {8}, false), t);
                    eight_is_a_ball = eight_is_a_ball && v.foul == Foul::None && v.keeps_turn && !s.over() && s.turn == turn;
                }
            }
    }
    std::printf("    9-ball first contact: %d cases\n", cases);
    check(cases == 90, "9-ball: 90 lowest-ball and first-contact cases were judged");
    check(lowest, "9-ball: the lowest-numbered ball on the table is the one to hit");
    check(wrong, "9-ball: hitting any other ball first is a foul, ball in hand to the other player");
    check(legal, "9-ball: hitting the lowest first with a rail and nothing down is legal and passes the turn");
    check(no_rail, "9-ball: nothing down and no rail after the contact is a foul");
    check(eight_is_a_ball, "9-ball: the 8 is an ordinary ball (potted, it keeps the table)");
}

void nine_ball_the_nine() {
    bool wins = true, combination = true, spotted = true;
    int cases = 0;
    for (int low = 1; low <= 8; ++low)
        for (int turn = 0; turn < 2; ++turn) {
            const std::vector<Ball> t = nine_table(low);
            ++cases;
            GameState s = nine_after_break(turn);
            Verdict v = apply_shot(s, facts(low, {low, 9}, false), t);
            combination = combination && s.winner == turn && v.winner == turn;
            s = nine_after_break(turn);
            v = apply_shot(s, facts(low, {9}, true), t);
            wins = wins && s.winner == turn && v.foul == Foul::None;
            s = nine_after_break(turn);
            v = apply_shot(s, facts(low == 8 ? 9 : low + 1, {9}, true), t);
            spotted = spotted && v.respot_nine && !s.over() && v.foul == Foul::WrongBallFirst && s.turn == 1 - turn;
            s = nine_after_break(turn);
            v = apply_shot(s, facts(low, {9, 0}, true), t);
            spotted = spotted && v.respot_nine && !s.over() && v.foul == Foul::Scratch && s.ball_in_hand;
        }
    check(cases == 16, "9-ball: the 9's fate judged with every lowest ball, for both players");
    check(wins, "9-ball: the 9 potted on a legal shot wins");
    check(combination, "9-ball: the 9 potted in a combination off the lowest ball wins");
    check(spotted, "9-ball: the 9 potted on a foul is spotted, no winner, ball in hand to the other player");
}

void nine_ball_three_fouls() {
    const std::vector<Ball> t = nine_table(3);
    GameState s = nine_after_break(0);
    bool going = true;
    for (int k = 0; k < 2; ++k) {
        apply_shot(s, facts(5, {}, true), t);   // player 0 fouls
        apply_shot(s, facts(3, {}, true), t);   // player 1 plays a legal miss
        going = going && !s.over() && s.turn == 0 && s.fouls_in_row[0] == k + 1 && s.fouls_in_row[1] == 0;
    }
    const Verdict third = apply_shot(s, facts(-1, {}, false), t);
    check(going, "9-ball: fouls count per player while he makes no legal shot");
    check(third.winner == 1 && s.winner == 1, "9-ball: a third foul in a row loses the game");
    s = nine_after_break(0);
    apply_shot(s, facts(5, {}, true), t);
    apply_shot(s, facts(3, {}, true), t);
    apply_shot(s, facts(5, {}, true), t);
    apply_shot(s, facts(3, {}, true), t);
    apply_shot(s, facts(3, {3}, true), t);  // player 0: a legal pot in between
    check(s.fouls_in_row[0] == 0 && !s.over(), "9-ball: a legal shot clears the player's fouls");
}

void nine_ball_break_and_push_out() {
    const std::vector<Ball> t = nine_table(1);
    GameState s;
    s.game = GameKind::NineBall;
    ShotFacts f = facts(2, {4}, true);
    Verdict v = apply_shot(s, f, t);
    check(v.foul == Foul::WrongBallFirst && !s.push_out_allowed, "9-ball: the break must hit the 1 first");
    s = GameState{};
    s.game = GameKind::NineBall;
    f = facts(1, {}, true);
    f.balls_to_rail = 3;
    v = apply_shot(s, f, t);
    check(v.foul == Foul::IllegalBreak, "9-ball: nothing down and three balls to a rail is an illegal break");
    s = GameState{};
    s.game = GameKind::NineBall;
    v = apply_shot(s, facts(1, {9}, true), t);
    check(s.winner == 0 && v.winner == 0, "9-ball: the 9 on a legal break wins");
    s = GameState{};
    s.game = GameKind::NineBall;
    f = facts(1, {}, true);
    f.balls_to_rail = 4;
    apply_shot(s, f, t);
    check(s.turn == 1 && s.push_out_allowed && !s.ball_in_hand, "9-ball: after a legal dry break the other player may push out");
    GameState pushed = s;
    check(declare_push_out(pushed) && pushed.push_out, "9-ball: the shot after the break can be declared a push-out");
    v = apply_shot(pushed, facts(-1, {}, false), t);
    check(v.foul == Foul::None && pushed.turn == 0 && pushed.may_pass_back, "9-ball: a push-out needs no contact nor rail; the other player chooses");
    GameState back = pushed;
    check(pass_back(back) && back.turn == 1 && !back.may_pass_back && !back.ball_in_hand, "9-ball: passed back, the pusher shoots again");
    check(!pass_back(back), "9-ball: a shot can be passed back only once, right after the push-out");
    apply_shot(pushed, facts(1, {}, true), t);
    check(!declare_push_out(pushed), "9-ball: only the shot right after the break can be a push-out");
    GameState p9 = s;
    declare_push_out(p9);
    v = apply_shot(p9, facts(4, {9}, false), t);
    check(v.respot_nine && !p9.over(), "9-ball: the 9 potted on a push-out is spotted");
    GameState scratch = s;
    declare_push_out(scratch);
    v = apply_shot(scratch, facts(1, {0}, true), t);
    check(v.foul == Foul::Scratch && scratch.ball_in_hand && !scratch.may_pass_back, "9-ball: a scratch on a push-out is a foul");
    GameState eight;
    check(!declare_push_out(eight), "8-ball has no push-out");
}

// --- the window's game is the headless one: the same seed played frame by
// frame through a Simulation as the window plays it (the main loop's rule:
// at rest, a pocketed cue ball back on the head spot; the shot from the
// table at rest; frames of kFrameDt until at rest) gives the same shots and
// the same table as play_computer_game, bit for bit
GameRecord play_framed_game(const SimConfig &config, uint64_t seed, GameKind kind) {
    GameRecord game;
    SimConfig c = config;
    if (kind == GameKind::NineBall)
        for (const Ball &b : set_up_nine_ball(config.table, config.seed).balls) c.placements.push_back(Placement{b.number, b.x, b.y});
    Simulation sim(c);
    GameState state;
    state.game = kind;
    Opponent players[2] = {Opponent(config, seed), Opponent(config, seed + 1)};
    while (!state.over() && static_cast<int>(game.shots.size()) < kMaxGameShots) {
        sim.respot_cue();
        std::vector<Ball> balls = sim.balls();
        const Plan plan = players[state.turn].choose(state, balls);
        if (plan.place_cue)
            for (Ball &b : balls)
                if (b.number == 0) b = Ball{plan.cue.x, plan.cue.y, 0, 0, 0, true};
        if (plan.place_cue) sim.set_balls(balls);
        const std::vector<Ball> before = sim.balls();
        std::vector<Event> events;
        sim.shoot(plan.shot);
        do {
            sim.step();
            events.insert(events.end(), sim.frame_events().begin(), sim.frame_events().end());
        } while (!sim.at_rest());
        const Verdict v = apply_shot(state, shot_facts(events, before), before);
        ShotRecord r;
        r.player = 1 - state.turn;
        r.shot = plan.shot;
        r.potted = shot_facts(events, before).potted;
        game.shots.push_back(r);
        if (v.respot_eight || v.respot_nine) {
            balls = sim.balls();
            respot(sim.table(), balls, v.respot_nine ? 9 : 8);
            sim.set_balls(balls);
        }
    }
    game.balls = sim.balls();
    game.winner = state.winner;
    return game;
}

void window_plays_the_headless_game() {
    SimConfig config;
    int compared = 0;
    for (GameKind kind : {GameKind::EightBall, GameKind::NineBall})
        for (int seed = 1; seed <= 2; ++seed) {
            config.seed = static_cast<uint64_t>(seed);
            const GameRecord h = play_computer_game(config, config.seed, kind);
            const GameRecord w = play_framed_game(config, config.seed, kind);
            bool same = h.shots.size() == w.shots.size() && h.winner == w.winner && h.balls.size() == w.balls.size();
            for (size_t i = 0; same && i < h.shots.size(); ++i)
                same = h.shots[i].shot.angle_deg == w.shots[i].shot.angle_deg && h.shots[i].shot.speed == w.shots[i].shot.speed &&
                       h.shots[i].potted == w.shots[i].potted;
            for (size_t i = 0; same && i < h.balls.size(); ++i)
                same = h.balls[i].active == w.balls[i].active && (!h.balls[i].active || (h.balls[i].x == w.balls[i].x && h.balls[i].y == w.balls[i].y));
            std::printf("    %s seed %d: headless %zu shots, framed %zu shots\n", game_name(kind), seed, h.shots.size(), w.shots.size());
            ++compared;
            check(same, std::string(game_name(kind)) + " seed " + std::to_string(seed) +
                            ": played frame by frame as in the window, the same shots and table as headless");
        }
    check(compared == 4, "four games compared frame by frame against headless");
}

// --- 9-ball, computer against computer: the diamond rack, and games that
// end by the 9 or by three fouls, the turn passing as the rules say
void nine_ball_games(int count) {
    SimConfig config;
    const Setup rack = set_up_nine_ball(config.table, 1);
    bool diamond = rack.balls.size() == 10;
    for (const Ball &b : rack.balls) diamond = diamond && b.number >= 0 && b.number <= 9;
    const auto at = [&](int n) {
        for (const Ball &b : rack.balls)
            if (b.number == n) return b;
        return Ball{};
    };
    // the 1 at the apex (nearest the head rail of the nine), the 9 at the centre (two rows behind it)
    for (const Ball &b : rack.balls)
        if (b.number > 1) diamond = diamond && b.x > at(1).x;
    diamond = diamond && std::fabs(at(9).y - at(1).y) < kBallRadius && at(9).x > at(1).x + 3 * kBallRadius;
    check(diamond, "the 9-ball rack: balls 1-9, the 1 at the apex, the 9 in the middle");
    for (int seed = 1; seed <= count; ++seed) {
        config.seed = static_cast<uint64_t>(seed);
        const GameRecord g = play_computer_game(config, config.seed, GameKind::NineBall);
        bool turns = true, nine_down = false;
        for (size_t i = 0; i + 1 < g.shots.size(); ++i) {
            const ShotRecord &r = g.shots[i];
            turns = turns && (g.shots[i + 1].player == (r.keeps_turn ? r.player : 1 - r.player));
            turns = turns && (g.shots[i + 1].placed == (r.foul != Foul::None));
        }
        for (const Ball &b : g.balls)
            if (b.number == 9) nine_down = !b.active;
        const bool by_nine = g.reason.find("potted the 9") != std::string::npos;
        const bool by_fouls = g.reason.find("third foul") != std::string::npos;
        std::printf("    9-ball seed %d: %zu shots, %d fouls, winner %d (%s)\n", seed, g.shots.size(), g.fouls, g.winner,
                    g.reason.c_str());
        const std::string s = " (9-ball seed " + std::to_string(seed) + ")";
        check(g.winner == 0 || g.winner == 1, "the game ends with a winner" + s);
        check((by_nine && nine_down) || by_fouls, "it ends with the 9 down or on a third foul" + s);
        check(turns, "the turn passes exactly when the rules say, ball in hand after each foul" + s);
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
    nine_ball_first_contact();
    nine_ball_the_nine();
    nine_ball_three_fouls();
    nine_ball_break_and_push_out();
    position_play();
    games(count);
    nine_ball_games(count);
    window_plays_the_headless_game();
    return demo_tests::check_summary("test_game");
}
