// game.cpp - see game.h.  Each shot: the player's plan (ball in hand first,
// if any), the shot played to rest, the rules' verdict; the 8 spotted again
// if it fell on the break.  A ball in hand without the cue ball on the table
// (a scratch) is placed by the plan.
#include "game.h"

namespace demo {

void respot_eight(const Table &table, std::vector<Ball> &balls) {
    for (Ball &b : balls)
        if (b.number == 8 && !b.active) {
            const Point p = eight_spot(table, balls);
            b = Ball{p.x, p.y, 0, 0, 8, true};
        }
}

GameRecord play_computer_game(const SimConfig &config, uint64_t seed) {
    GameRecord game;
    const Setup setup = set_up(Scene::Break, config.table, 0, config.seed);
    std::vector<Ball> balls = setup.balls;
    GameState state;
    Opponent players[2] = {Opponent(config, seed), Opponent(config, seed + 1)};
    while (!state.over() && static_cast<int>(game.shots.size()) < kMaxGameShots) {
        ShotRecord r;
        r.player = state.turn;
        const Plan plan = players[state.turn].choose(state, balls);
        if (plan.place_cue)
            for (Ball &b : balls)
                if (b.number == 0) b = Ball{plan.cue.x, plan.cue.y, 0, 0, 0, true};
        r.shot = plan.shot;
        r.placed = plan.place_cue;
        r.cue = plan.cue;
        r.candidates = plan.candidates;
        r.think_seconds = plan.think_seconds;
        const ShotOutcome out = simulate_shot(config, balls, plan.shot);
        const ShotFacts facts = shot_facts(out.events, balls);
        const Verdict v = apply_shot(state, facts, balls);
        r.potted = facts.potted;
        r.foul = v.foul;
        r.keeps_turn = v.keeps_turn;
        balls = out.balls;
        if (v.respot_eight) respot_eight(setup.table, balls);
        game.fouls += v.foul != Foul::None;
        game.candidates += plan.candidates;
        game.think_seconds += plan.think_seconds;
        game.sim_seconds += out.seconds;
        if (v.winner >= 0) game.reason = v.reason;
        game.shots.push_back(r);
    }
    game.balls = balls;
    game.winner = state.winner;
    game.groups[0] = state.group[0];
    game.groups[1] = state.group[1];
    if (game.winner < 0) game.reason = "no winner after " + std::to_string(kMaxGameShots) + " shots";
    return game;
}

}  // namespace demo
