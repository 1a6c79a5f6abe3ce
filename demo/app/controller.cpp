/* SPDX-License-Identifier: MIT */
// controller.cpp - see controller.h.  The window's game is a Driver of the
// shared main loop (sim.h run), which paces it at 1/60 s of wall time per
// frame.
#include "app/controller.h"

#include <SDL.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "app/aim.h"
#include "app/audio.h"
#include "app/canvas.h"
#include "app/draw_balls.h"
#include "app/engine_view.h"
#include "app/hud.h"
#include "app/png.h"
#include "app/view.h"
#include "app/window.h"

namespace demo {

namespace {

constexpr double kFullPull = 0.35;  // m of mouse drag (on the table's scale) for full power

// The player's side of the main loop.  Each frame: events (aim, stroke,
// spin, keys), the simulation's step, sounds for its contacts, the balls'
// orientations, the picture, then a wait for the frame's deadline.
class Game : public Driver, public PlayingGame {
public:
    Game(const SimConfig &config, const Players &players, Window &window, Audio &audio)
        : config_(config), match_(config, players), window_(window), audio_(audio), frequency_(static_cast<double>(SDL_GetPerformanceFrequency())),
          deadline_(static_cast<double>(SDL_GetPerformanceCounter()) / frequency_),
          help_(!(players.eight_ball && players.computer[0] && players.computer[1])) {}
    void start(const Simulation &sim);
    bool next_frame(Simulation &sim) override;
    bool before_step(Simulation &sim, bool was_at_rest) override;
    void after_step(const Simulation &sim) override;
    void attach(Simulation &sim) { sim_ = &sim; }
    const Simulation &simulation() const override { return *sim_; }
    bool shoot(const Shot &shot) override;
    long frames_drawn() const override { return drawn_; }

private:
    // The table is at rest for the next shot (the practice table not cleared,
    // the game not over).
    bool table_ready(const Simulation &sim) const {
        if (!pool(sim) || !sim.at_rest() || !sim.cue_on_table() || match_.shot_running()) return false;
        return match_.eight_ball() ? !match_.state().over() : sim.object_balls_left() > 0;
    }
    // A human may aim and shoot.
    bool can_shoot(const Simulation &sim) const { return table_ready(sim) && !match_.computer_to_play() && !placing_; }
    void judge_shot(Simulation &sim);
    void computer_turn(Simulation &sim);
    void place_at_mouse(Simulation &sim);
    void new_game(Simulation &sim);
    bool handle_event(Simulation &sim, const SDL_Event &e);
    void handle_key(Simulation &sim, const SDL_Keysym &key);
    void aim_at_mouse(const Simulation &sim);
    void shoot(Simulation &sim);
    void play(Simulation &sim, const Shot &shot);
    void sound_and_drops(const Simulation &sim);
    Overlay overlay(const Simulation &sim) const;
    void screenshot(const Canvas &frame);

    const SimConfig config_;
    Match match_;
    Window &window_;
    Audio &audio_;
    const double frequency_;
    double deadline_;  // s, when the frame being drawn is due
    Screen layout_{kDefaultWidth, kDefaultWidth, 1, 1, 0, false};
    TableShape shape_{};
    Backdrop backdrop_;
    Canvas frame_;
    BallPoses poses_;
    std::vector<Drop> drops_;
    AimState aim_;
    bool dragging_ = false, dialing_ = false;
    bool help_;  // the keys' box: shown at the start unless no one at the window plays
    bool follow_mouse_ = true, was_ready_ = false;
    double press_x_ = 0, press_y_ = 0, mouse_x_ = 0, mouse_y_ = 0;  // canvas pixels
    int shots_ = 0, screenshots_ = 0, skipped_ = 0;
    double last_speed_ = 0;
    bool placing_ = false;     // a human's ball in hand: the cue ball follows the mouse until a click
    int rest_frames_ = 0;      // frames the table has been at rest
    int aim_frames_ = -1;      // the computer's shot: frames since it was planned (-1: not yet)
    Plan plan_;
    double player_side_ = 0, player_topback_ = 0, player_elevation_ = 0;  // the player's, kept over the computer's turn
    Simulation *sim_ = nullptr;  // the one play_window runs
    long drawn_ = 0;
};

PlayingGame *g_playing = nullptr;

// The computer waits a moment once the table is at rest, then shows its aim
// and the cue drawn back for a second before it plays.
constexpr int kThinkFrames = 30;
constexpr int kComputerAimFrames = 60;

// The cue ball put at p, at rest.
void put_cue(Simulation &sim, Point p) {
    std::vector<Ball> balls = sim.balls();
    for (Ball &b : balls)
        if (b.number == 0) b = Ball{p.x, p.y, 0, 0, 0, true};
    sim.set_balls(balls);
}

void Game::start(const Simulation &sim) {
    shape_ = table_shape(sim.table());
    poses_.reset(sim.balls());
    drops_.clear();
    shots_ = 0;
    dragging_ = dialing_ = false;
    aim_.power = 0;
}

bool Game::next_frame(Simulation &sim) {
    int width = 0, height = 0;
    window_.output_size(width, height);
    if (width != layout_.width || height != layout_.height) layout_ = layout_for(sim, width, height);
    SDL_Event e;
    while (SDL_PollEvent(&e))
        if (!handle_event(sim, e)) return false;
    return true;
}

// The aim follows the mouse when it moves (and when the table comes to
// rest), so the fine-aim keys and Shift + mouse keep what they set.
bool Game::before_step(Simulation &sim, bool) {
    if (match_.shot_running() && sim.at_rest()) judge_shot(sim);
    rest_frames_ = sim.at_rest() ? rest_frames_ + 1 : 0;
    if (match_.computer_to_play() && table_ready(sim)) computer_turn(sim);
    if (placing_) place_at_mouse(sim);
    const bool ready = can_shoot(sim);
    if (ready && !dragging_ && !dialing_ && (follow_mouse_ || !was_ready_)) aim_at_mouse(sim);
    follow_mouse_ = false;
    was_ready_ = ready;
    return true;
}

// The shot has come to rest: the rules' verdict, and who plays next.
void Game::judge_shot(Simulation &sim) {
    std::vector<Ball> balls = sim.balls();
    if (match_.shot_ended(sim.table(), balls)) sim.set_balls(balls);
    placing_ = match_.eight_ball() && match_.state().ball_in_hand && !match_.computer_to_play() && !match_.state().over();
    aim_frames_ = -1;
}

void Game::computer_turn(Simulation &sim) {
    if (rest_frames_ < kThinkFrames) return;
    if (aim_frames_ < 0 && match_.computer_passes_back(sim.balls())) {
        match_.pass_back();
        return;
    }
    if (aim_frames_ < 0) {
        plan_ = match_.plan(sim.balls());
        if (plan_.place_cue) put_cue(sim, plan_.cue);
        // the player's own tip and elevation come back after the computer's shot
        player_side_ = aim_.side, player_topback_ = aim_.topback, player_elevation_ = aim_.elevation;
        aim_.angle = plan_.shot.angle_deg * M_PI / 180;
        aim_.side = plan_.shot.side;
        aim_.topback = plan_.shot.topback;
        aim_.elevation = plan_.shot.elevation;
        aim_frames_ = 0;
    }
    aim_.power = std::min(1.0, plan_.shot.speed / kMaxPlaySpeed) * std::min(1.0, 1.5 * aim_frames_ / kComputerAimFrames);
    if (++aim_frames_ < kComputerAimFrames) return;
    match_.shot_started(sim.balls());
    sim.shoot(plan_.shot);
    last_speed_ = plan_.shot.speed;
    aim_.power = 0;
    aim_.side = player_side_, aim_.topback = player_topback_, aim_.elevation = player_elevation_;
    aim_frames_ = -1;
    ++shots_;
}

// Ball in hand: the cue ball goes where the mouse is whenever it may.
void Game::place_at_mouse(Simulation &sim) {
    if (!sim.at_rest() || layout_.panel.contains(static_cast<float>(mouse_x_), static_cast<float>(mouse_y_))) return;
    const Point p{layout_.view.wx(mouse_x_), layout_.view.wy(mouse_y_)};
    std::vector<Ball> others = sim.balls();
    if (!cue_placement_ok(sim.table(), others, p.x, p.y)) return;
    for (const Ball &b : others)
        if (b.number == 0 && b.active && b.x == p.x && b.y == p.y) return;
    put_cue(sim, p);
}

void Game::new_game(Simulation &sim) {
    sim = Simulation(config_);
    start(sim);
    match_.reset();
    placing_ = false;
    aim_frames_ = -1;
    rest_frames_ = 0;
    if (!pool(sim)) sim.shoot(Shot{0, kMaxPlaySpeed});
}

void Game::aim_at_mouse(const Simulation &sim) {
    if (layout_.panel.contains(static_cast<float>(mouse_x_), static_cast<float>(mouse_y_))) return;
    const Ball &cue = sim.balls()[0];
    const double dx = layout_.view.wx(mouse_x_) - cue.x, dy = layout_.view.wy(mouse_y_) - cue.y;
    if (std::hypot(dx, dy) > kBallRadius) aim_.angle = std::atan2(dy, dx);
}

void Game::shoot(Simulation &sim) {
    const double speed = aim_.power * kMaxPlaySpeed;
    aim_.power = 0;
    if (speed < 0.02 || !can_shoot(sim)) return;
    play(sim, Shot{aim_.angle * 180.0 / M_PI, speed, aim_.side, aim_.topback, aim_.elevation});
}

// (Simulation::shoot starts the engine afresh from a table at rest: a shot's
// outcome depends on the position and the shot alone.)
void Game::play(Simulation &sim, const Shot &shot) {
    match_.shot_started(sim.balls());
    sim.shoot(shot);
    ++shots_;
    last_speed_ = shot.speed;
    help_ = false;
}

bool Game::shoot(const Shot &shot) {
    const bool finite = std::isfinite(shot.angle_deg) && std::isfinite(shot.speed) && std::isfinite(shot.side) &&
                        std::isfinite(shot.topback) && std::isfinite(shot.elevation);
    if (!finite || !(shot.speed > 0 && shot.speed <= kMaxShotSpeed) || shot.side * shot.side + shot.topback * shot.topback > 0.25 ||
        !(shot.elevation >= 0 && shot.elevation <= kMaxElevation) || !sim_ || !can_shoot(*sim_))
        return false;
    aim_.power = 0;
    dragging_ = false;
    play(*sim_, shot);
    return true;
}

bool Game::handle_event(Simulation &sim, const SDL_Event &e) {
    int win_w = 1, win_h = 1;
    SDL_GetWindowSize(window_.window, &win_w, &win_h);
    const double sx = static_cast<double>(layout_.width) / std::max(1, win_w);  // high-DPI: window to canvas pixels
    const double sy = static_cast<double>(layout_.height) / std::max(1, win_h);
    switch (e.type) {
    case SDL_QUIT: return false;
    case SDL_KEYDOWN:
        if (e.key.keysym.sym == SDLK_ESCAPE) return false;
        handle_key(sim, e.key.keysym);
        break;
    case SDL_MOUSEMOTION:
        if ((SDL_GetModState() & KMOD_SHIFT) && !dragging_ && !dialing_ && can_shoot(sim)) {
            aim_.angle -= e.motion.xrel * 0.0006;  // fine aim: a tenth of the mouse's turn, roughly
        } else {
            mouse_x_ = e.motion.x * sx;
            mouse_y_ = e.motion.y * sy;
            follow_mouse_ = true;
        }
        if (dragging_) aim_.power = std::min(1.0, std::hypot(mouse_x_ - press_x_, mouse_y_ - press_y_) / layout_.view.scale / kFullPull);
        if (dialing_) dial_offset(spin_dial(layout_), static_cast<float>(mouse_x_), static_cast<float>(mouse_y_), aim_.side, aim_.topback);
        break;
    case SDL_MOUSEBUTTONDOWN:
        mouse_x_ = e.button.x * sx;
        mouse_y_ = e.button.y * sy;
        if (e.button.button == SDL_BUTTON_LEFT && placing_) {
            place_at_mouse(sim);
            const Ball &cue = sim.balls()[0];
            // put down only where the mouse is (a legal place), not where it last was
            placing_ = !(cue.active && std::hypot(cue.x - layout_.view.wx(mouse_x_), cue.y - layout_.view.wy(mouse_y_)) < 1e-9);
        } else if (e.button.button == SDL_BUTTON_LEFT) {
            if (dial_offset(spin_dial(layout_), static_cast<float>(mouse_x_), static_cast<float>(mouse_y_), aim_.side, aim_.topback)) {
                dialing_ = true;
            } else if (can_shoot(sim) && !layout_.panel.contains(static_cast<float>(mouse_x_), static_cast<float>(mouse_y_))) {
                dragging_ = true;
                press_x_ = mouse_x_;
                press_y_ = mouse_y_;
                aim_.power = 0;
            }
        } else if (e.button.button == SDL_BUTTON_RIGHT) {
            dragging_ = false;
            aim_.power = 0;
        }
        break;
    case SDL_MOUSEBUTTONUP:
        // a touch has no hover: the aim follows the finger only when it
        // lifts (a tap aims where it lands; a drag has shot by then)
        if (e.button.which == SDL_TOUCH_MOUSEID) follow_mouse_ = true;
        if (e.button.button == SDL_BUTTON_LEFT) {
            dialing_ = false;
            if (dragging_) {
                dragging_ = false;
                shoot(sim);
            }
        }
        break;
    case SDL_MOUSEWHEEL:
        aim_.topback += 0.05 * e.wheel.y;
        clamp_offset(aim_.side, aim_.topback);
        break;
    default: break;
    }
    return true;
}

void Game::handle_key(Simulation &sim, const SDL_Keysym &key) {
    const double step = 0.05;
    switch (key.sym) {
    case SDLK_r: new_game(sim); break;
    case SDLK_h:
    case SDLK_F1: help_ = !help_; break;
    case SDLK_m: audio_.toggle_mute(); break;
    case SDLK_F12:
    case SDLK_p: screenshot(frame_); break;
    case SDLK_UP: aim_.topback += step; break;
    case SDLK_DOWN: aim_.topback -= step; break;
    case SDLK_LEFT: aim_.side -= step; break;
    case SDLK_RIGHT: aim_.side += step; break;
    case SDLK_c: aim_.side = aim_.topback = 0; break;
    // 9-ball: declare a push-out, or hand the shot back after one
    case SDLK_o:
        if (!match_.computer_to_play() && table_ready(sim)) match_.push_out();
        break;
    case SDLK_b:
        if (!match_.computer_to_play() && table_ready(sim)) match_.pass_back();
        break;
    // the cue's elevation in 5-degree steps: swerve, and masse when steep
    case SDLK_PAGEUP: aim_.elevation = std::min(kMaxElevation, aim_.elevation + 5); break;
    case SDLK_PAGEDOWN: aim_.elevation = std::max(0.0, aim_.elevation - 5); break;
    case SDLK_l: aim_.elevation = 0; break;
    case SDLK_COMMA: aim_.angle += (key.mod & KMOD_SHIFT ? 1.0 : 0.1) * M_PI / 180; break;
    case SDLK_PERIOD: aim_.angle -= (key.mod & KMOD_SHIFT ? 1.0 : 0.1) * M_PI / 180; break;
    default: break;
    }
    clamp_offset(aim_.side, aim_.topback);
}

void Game::sound_and_drops(const Simulation &sim) {
    for (Drop &d : drops_) d.age += kFrameDt;
    drops_.erase(std::remove_if(drops_.begin(), drops_.end(), [](const Drop &d) { return d.age > kDropSeconds; }), drops_.end());
    const double length = sim.table().length;
    for (const Contact &c : frame_contacts(sim)) {
        const double pan = 2 * c.x / length - 1;
        switch (c.kind) {
        case ContactKind::BallBall: audio_.play(Sound::Click, c.impulse, pan); break;
        case ContactKind::Cushion: audio_.play(Sound::Cushion, c.impulse, pan); break;
        case ContactKind::Strike: audio_.play(Sound::Strike, c.impulse, pan); break;
        case ContactKind::Pocket: {
            audio_.play(Sound::Pocket, c.impulse, pan);
            const size_t i = static_cast<size_t>(c.ball), k = static_cast<size_t>(c.pocket);
            if (i < sim.balls().size() && k < sim.table().pockets.size())
                drops_.push_back({sim.balls()[i].number, c.x, c.y, sim.table().pockets[k].x, sim.table().pockets[k].y,
                                  poses_.pose(i), 0.0});
            break;
        }
        }
    }
}

Overlay Game::overlay(const Simulation &sim) const {
    Overlay o;
    o.drops = drops_;
    o.aiming = can_shoot(sim) || (match_.computer_to_play() && aim_frames_ >= 0 && table_ready(sim));
    o.aim = aim_;
    o.help = help_;
    const int left = sim.object_balls_left();
    char line[160];
    if (match_.eight_ball()) {
        o.panel.lines = match_.status(placing_);
    } else {
        std::snprintf(line, sizeof line, "Practice: clear the table   Shots %d   Balls left %d", shots_, left);
        o.panel.lines.emplace_back(line);
    }
    if (last_speed_ > 0 && !match_.eight_ball()) {
        std::snprintf(line, sizeof line, "Last shot %.1f m/s", last_speed_);
        o.panel.lines.emplace_back(line);
    }
    std::string keys = "H help   R rack   M ";
    keys += !audio_.available() ? "(no sound)" : audio_.muted() ? "unmute" : "mute";
    o.panel.lines.push_back(keys);
    o.panel.pocketed = pocketed_numbers(sim);
    o.panel.power = aim_.power;
    o.panel.max_speed = kMaxPlaySpeed;
    o.panel.side = aim_.side;
    o.panel.topback = aim_.topback;
    o.panel.elevation = aim_.elevation;
    if (match_.eight_ball()) o.banner = match_.result();
    else if (left == 0 && sim.at_rest())
        o.banner = "Table cleared in " + std::to_string(shots_) + (shots_ == 1 ? " shot" : " shots") + ". Press R to rack again.";
    return o;
}

void Game::screenshot(const Canvas &frame) {
    if (frame.width() <= 1) return;
    char path[64];
    std::snprintf(path, sizeof path, "billiards-%03d.png", ++screenshots_);
    std::string error;
    if (write_png(path, frame.width(), frame.height(), frame.rgb(), error)) std::printf("billiards: saved %s\n", path);
    else std::fprintf(stderr, "billiards: screenshot: %s\n", error.c_str());
    std::fflush(stdout);
}

void Game::after_step(const Simulation &sim) {
    match_.add_events(sim.frame_events());
    if (pool(sim)) {
        sound_and_drops(sim);
        poses_.advance(sim.balls(), kFrameDt);
    }
    // run() holds each frame to 1/60 s of wall time; a machine too slow to
    // draw every frame skips drawing (up to 3 frames in 4), not time
    deadline_ += kFrameDt;
    const double now = static_cast<double>(SDL_GetPerformanceCounter()) / frequency_;
    if (now - deadline_ > 0.25) deadline_ = now;  // a pause: as run() does, count afresh
    if (now > deadline_ + 0.5 * kFrameDt && skipped_ < 3) {
        ++skipped_;
        return;
    }
    skipped_ = 0;
    if (frame_.width() != layout_.width || frame_.height() != layout_.height) frame_ = Canvas(layout_.width, layout_.height);
    draw_frame(frame_, backdrop_.get(sim, shape_, layout_), layout_, sim, shape_, poses_, overlay(sim));
    if (window_.show(frame_)) {
        SDL_RenderPresent(window_.renderer);
        ++drawn_;
    }
}

}  // namespace

WindowResult play_window(const SimConfig &config, const Players &players, std::string &error) {
    Simulation sim(config);
    Window w;
    const WindowResult opened = open_window(sim, w, error);
    if (opened != WindowResult::Ok) return opened;
    Audio audio(pool(sim));  // the gas would be a roar: silent
    if (pool(sim) && !audio.available()) std::fprintf(stderr, "billiards: no sound (%s)\n", audio.problem().c_str());
    Game game(config, players, w, audio);
    game.start(sim);
    game.attach(sim);
    if (!pool(sim)) sim.shoot(Shot{0, kMaxPlaySpeed});
    g_playing = &game;
    run(sim, game);  // in the browser: never returns, the game lives on with the page
    g_playing = nullptr;
    return WindowResult::Ok;
}

PlayingGame *playing_game() { return g_playing; }

}  // namespace demo
