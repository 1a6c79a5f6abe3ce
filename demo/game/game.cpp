/* SPDX-License-Identifier: MIT */
// game.cpp - see game.h.  Each shot: the player's plan (ball in hand first,
// if any), the shot played to rest, the rules' verdict; the 8 spotted again
// if it fell on the break.  A ball in hand without the cue ball on the table
// (a scratch) is placed by the plan.
#include "game/game.h"

namespace demo {

void respot(const Table &table, std::vector<Ball> &balls, int number) {
    for (Ball &b : balls)
        if (b.number == number && !b.active) {
            const Point p = spot_point(table, balls, number);
            b = Ball{p.x, p.y, 0, 0, number, true};
        }
}

void respot_eight(const Table &table, std::vector<Ball> &balls) { respot(table, balls, 8); }

GameRecord play_computer_game(const SimConfig &config, uint64_t seed, GameKind kind) {
    const Search both[2] = {Search::Position, Search::Position};
    return play_computer_game(config, seed, both, kind);
}

GameRecord play_computer_game(const SimConfig &config, uint64_t seed, const Search search[2], GameKind kind) {
    GameRecord game;
    const Setup setup = kind == GameKind::NineBall ? set_up_nine_ball(config.table, config.seed)
                                                   : set_up(Scene::Break, config.table, 0, config.seed);
    std::vector<Ball> balls = setup.balls;
    GameState state;
    state.game = kind;
    game.nine_ball = kind == GameKind::NineBall;
    Opponent players[2] = {Opponent(config, seed, search[0]), Opponent(config, seed + 1, search[1])};
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
        r.cpu_seconds = plan.cpu_seconds;
        const ShotOutcome out = simulate_shot(config, balls, plan.shot);
        const ShotFacts facts = shot_facts(out.events, balls);
        const Verdict v = apply_shot(state, facts, balls);
        r.potted = facts.potted;
        r.foul = v.foul;
        r.keeps_turn = v.keeps_turn;
        balls = out.balls;
        if (v.respot_eight) respot_eight(setup.table, balls);
        if (v.respot_nine) respot(setup.table, balls, 9);
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

Match::Match(const SimConfig &config, const Players &players)
    : players_(players), config_(config), opponents_{Opponent(config, config.seed), Opponent(config, config.seed + 1)},
      table_(scene_table(config.scene, config.table)) {
    state_.game = players.kind;
}

void Match::reset() {
    state_ = GameState{};
    state_.game = players_.kind;
    opponents_[0] = Opponent(config_, config_.seed + static_cast<uint64_t>(2 * ++plans_));
    opponents_[1] = Opponent(config_, config_.seed + static_cast<uint64_t>(2 * plans_ + 1));
    running_ = false;
    last_.clear();
    last_reason_.clear();
    last_shooter_ = -1;
}

void Match::shot_started(const std::vector<Ball> &balls) {
    before_ = balls;
    events_.clear();
    running_ = true;
}

void Match::add_events(const std::vector<Event> &events) {
    if (running_) events_.insert(events_.end(), events.begin(), events.end());
}

bool Match::shot_ended(const Table &table, std::vector<Ball> &balls) {
    if (!running_) return false;
    running_ = false;
    if (!eight_ball()) return false;
    const int shooter = state_.turn;
    const Verdict v = apply_shot(state_, shot_facts(events_, before_), before_);
    last_ = name(shooter) + ": " + v.reason;
    last_reason_ = v.reason;
    last_shooter_ = shooter;
    if (v.respot_nine) {
        respot(table, balls, 9);
        last_ += "; the 9 is spotted again";
        return true;
    }
    if (!v.respot_eight) return false;
    respot_eight(table, balls);
    last_ += "; the 8 is spotted again";
    return true;
}

bool Match::push_out() {
    if (running_ || !demo::declare_push_out(state_)) return false;
    last_ = name(state_.turn) + " plays a push-out";
    return true;
}

bool Match::pass_back() {
    const int from = state_.turn;
    if (running_ || !demo::pass_back(state_)) return false;
    last_ = name(from) + " passes the shot back";
    return true;
}

bool Match::computer_passes_back(const std::vector<Ball> &balls) const {
    return computer_to_play() && demo::computer_passes_back(state_, table_, balls);
}

bool computer_passes_back(const GameState &state, const Table &table, const std::vector<Ball> &balls) {
    return state.may_pass_back && best_ease(state, table, balls) < kPassBackEase;
}

Plan Match::plan(const std::vector<Ball> &balls) {
    const Plan p = opponents_[state_.turn].choose(state_, balls);
    candidates_ += p.candidates;
    think_seconds_ += p.think_seconds;
    return p;
}

std::string Match::name(int player) const {
    return "Player " + std::to_string(player + 1) + (computer(player) ? " (computer)" : "");
}

std::vector<std::string> Match::status(bool placing) const {
    std::vector<std::string> lines;
    std::string who = std::string(game_name(state_.game)) + "   ";
    for (int p = 0; p < 2; ++p) {
        who += (p ? "   " : "") + name(p);
        if (state_.group[p] != Group::Open) who += std::string(": ") + group_name(state_.group[p]);
    }
    if (state_.game == GameKind::EightBall && state_.open() && !state_.breaking) who += "   (table open)";
    lines.push_back(who);
    if (running_) {
        lines.push_back("> " + name(state_.turn) + (state_.breaking ? " breaks" : " shoots"));
    } else if (!state_.over()) {
        std::string turn = "> " + name(state_.turn) + (state_.breaking ? " to break" : " to shoot");
        if (state_.ball_in_hand) turn += placing ? ", ball in hand: click to put the cue ball down" : ", ball in hand";
        if (state_.push_out) turn += ", push-out";
        else if (state_.push_out_allowed && !computer(state_.turn)) turn += " (O: push-out)";
        if (state_.may_pass_back && !computer(state_.turn)) turn += " (B: pass it back)";
        lines.push_back(turn);
    }
    if (!last_.empty()) lines.push_back(last_);
    return lines;
}

std::string Match::result() const {
    if (!state_.over()) return "";
    const int w = state_.winner;
    const std::string winner = players_.computer[0] != players_.computer[1] ? (computer(w) ? "The computer wins" : "You win")
                                                                           : name(w) + " wins";
    const std::string loser = players_.computer[0] != players_.computer[1] ? (computer(1 - w) ? "the computer" : "you")
                                                                          : name(1 - w);
    return winner + ": " + win_reason(w, last_shooter_, loser, last_reason_) + ". Press R for a new game.";
}

std::string win_reason(int winner, int shooter, const std::string &shooter_name, const std::string &reason) {
    return winner == shooter ? reason : shooter_name + " " + reason;
}

}  // namespace demo
