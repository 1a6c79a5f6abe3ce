// render.cpp - see render.h.
#include "render.h"

#include <SDL.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "png.h"

namespace demo {

namespace {

constexpr int kLogicalWidth = 1200;
constexpr double kMaxPlaySpeed = 12.0;       // m/s, a hard break
constexpr double kPowerPerPixel = 0.04;      // m/s per logical pixel dragged

struct Rgb { uint8_t r, g, b; };

// World (metres, y up) to logical pixels (y down), rails included.
struct View {
    double scale, left, top;
    int width, height;
    explicit View(const Table &t) {
        const double w = t.length + 2 * t.rail, h = t.width + 2 * t.rail;
        width = kLogicalWidth;
        height = static_cast<int>(std::lround(kLogicalWidth * h / w));
        scale = width / w;
        left = -t.rail;
        top = t.width + t.rail;
    }
    float px(double x) const { return static_cast<float>((x - left) * scale); }
    float py(double y) const { return static_cast<float>((top - y) * scale); }
    double wx(double sx) const { return sx / scale + left; }
    double wy(double sy) const { return top - sy / scale; }
};

void set_colour(SDL_Renderer *r, Rgb c) { SDL_SetRenderDrawColor(r, c.r, c.g, c.b, 255); }

void fill_disk(SDL_Renderer *r, float cx, float cy, float radius) {
    const int rows = static_cast<int>(std::ceil(radius));
    for (int dy = -rows; dy <= rows; ++dy) {
        const float y = static_cast<float>(dy);
        const float half = std::sqrt(std::max(0.0f, radius * radius - y * y));
        if (half > 0) SDL_RenderDrawLineF(r, cx - half, cy + y, cx + half, cy + y);
    }
}

// Horizontal band through the middle of a disk: the stripe of balls 9-15.
void fill_band(SDL_Renderer *r, float cx, float cy, float radius) {
    const int rows = static_cast<int>(radius * 0.55f);
    for (int dy = -rows; dy <= rows; ++dy) {
        const float y = static_cast<float>(dy);
        const float half = std::sqrt(std::max(0.0f, radius * radius - y * y));
        SDL_RenderDrawLineF(r, cx - half, cy + y, cx + half, cy + y);
    }
}

Rgb ball_colour(int number) {
    static const Rgb colours[8] = {{250, 250, 240}, {245, 200, 20}, {20, 60, 200}, {220, 30, 30},
                                   {90, 30, 140},   {250, 120, 20}, {20, 130, 60}, {130, 30, 30}};
    if (number == 8) return {15, 15, 15};
    const int k = number > 8 ? number - 8 : number; // stripes 9-15 share 1-7's colours
    return k >= 0 && k < 8 ? colours[k] : colours[0];
}

Rgb speed_colour(double speed, double scale) {
    const double f = std::min(1.0, speed / scale);
    return {static_cast<uint8_t>(60 + 195 * f), static_cast<uint8_t>(120 + 60 * (1 - f)), static_cast<uint8_t>(255 * (1 - f))};
}

// 3x5 bitmap glyphs for the few characters the heads-up display uses.
const uint8_t *glyph(char c) {
    static const struct { char c; uint8_t rows[5]; } font[] = {
        {'0', {7, 5, 5, 5, 7}}, {'1', {2, 6, 2, 2, 7}}, {'2', {7, 1, 7, 4, 7}}, {'3', {7, 1, 7, 1, 7}},
        {'4', {5, 5, 7, 1, 1}}, {'5', {7, 4, 7, 1, 7}}, {'6', {7, 4, 7, 5, 7}}, {'7', {7, 1, 2, 2, 2}},
        {'8', {7, 5, 7, 5, 7}}, {'9', {7, 5, 7, 1, 7}}, {'S', {7, 4, 7, 1, 7}}, {'H', {5, 5, 7, 5, 5}},
        {'O', {7, 5, 5, 5, 7}}, {'T', {7, 2, 2, 2, 2}}, {'B', {6, 5, 6, 5, 6}}, {'A', {2, 5, 7, 5, 5}},
        {'L', {4, 4, 4, 4, 7}}, {'C', {7, 4, 4, 4, 7}}, {'E', {7, 4, 6, 4, 7}}, {'R', {6, 5, 6, 5, 5}},
        {'D', {6, 5, 5, 5, 6}}, {'I', {7, 2, 2, 2, 7}}, {'N', {5, 7, 7, 5, 5}}, {'K', {5, 5, 6, 5, 5}},
        {'Y', {5, 5, 2, 2, 2}}, {'P', {6, 5, 6, 4, 4}}, {'-', {0, 0, 7, 0, 0}}, {'/', {1, 1, 2, 4, 4}},
    };
    for (const auto &g : font)
        if (g.c == c) return g.rows;
    return nullptr;
}

void draw_text(SDL_Renderer *r, const std::string &text, int x, int y, int pixel) {
    for (char c : text) {
        const uint8_t *rows = glyph(c);
        for (int row = 0; rows && row < 5; ++row)
            for (int col = 0; col < 3; ++col)
                if (rows[row] & (4 >> col)) {
                    SDL_Rect dot = {x + col * pixel, y + row * pixel, pixel, pixel};
                    SDL_RenderFillRect(r, &dot);
                }
        x += 4 * pixel;
    }
}

void draw_table(SDL_Renderer *r, const Table &t, const View &v, bool felt) {
    set_colour(r, felt ? Rgb{105, 62, 30} : Rgb{70, 70, 80});
    SDL_RenderClear(r);
    set_colour(r, felt ? Rgb{25, 115, 60} : Rgb{15, 15, 25});
    SDL_FRect surface = {v.px(0), v.py(t.width), static_cast<float>(t.length * v.scale), static_cast<float>(t.width * v.scale)};
    SDL_RenderFillRectF(r, &surface);
    set_colour(r, {5, 5, 5});
    for (const Pocket &p : t.pockets) fill_disk(r, v.px(p.x), v.py(p.y), static_cast<float>(p.draw_radius * v.scale));
}

void draw_balls(SDL_Renderer *r, const Simulation &sim, const View &v) {
    const float radius = std::max(1.0f, static_cast<float>(kBallRadius * v.scale));
    const bool gas = sim.config().scene == Scene::Gas;
    double mean_speed = 0;
    if (gas) mean_speed = std::sqrt(2 * sim.energy() / (kBallMass * std::max(1, sim.balls_total())));
    for (const Ball &b : sim.balls()) {
        if (!b.active) continue;
        const float x = v.px(b.x), y = v.py(b.y);
        if (gas) {
            set_colour(r, speed_colour(std::hypot(b.vx, b.vy), 2 * mean_speed));
            fill_disk(r, x, y, radius);
            continue;
        }
        const bool stripe = b.number > 8;
        set_colour(r, stripe ? ball_colour(0) : ball_colour(b.number));
        fill_disk(r, x, y, radius);
        if (stripe) {
            set_colour(r, ball_colour(b.number));
            fill_band(r, x, y, radius);
        }
    }
}

struct Aim {
    bool visible = false;
    double angle = 0, speed = 0;
};

struct Hud {
    bool show = false;
    int shots = 0;
    Aim aim;
};

void draw_frame(SDL_Renderer *r, const Simulation &sim, const Hud &hud) {
    const View v(sim.table());
    draw_table(r, sim.table(), v, sim.config().scene != Scene::Gas);
    draw_balls(r, sim, v);
    if (hud.aim.visible && sim.cue_on_table()) {
        const Ball &cue = sim.balls()[0];
        const double reach = 0.15 + hud.aim.speed * 0.08;
        set_colour(r, {240, 240, 200});
        SDL_RenderDrawLineF(r, v.px(cue.x), v.py(cue.y), v.px(cue.x + reach * std::cos(hud.aim.angle)),
                            v.py(cue.y + reach * std::sin(hud.aim.angle)));
    }
    if (!hud.show) return;
    const int left = sim.object_balls_left();
    set_colour(r, {250, 250, 250});
    const int pixel = std::max(2, v.height / 120);
    draw_text(r, "SHOTS " + std::to_string(hud.shots), pixel * 3, pixel * 2, pixel);
    draw_text(r, "BALLS " + std::to_string(left), v.width - pixel * 40, pixel * 2, pixel);
    if (left == 0) draw_text(r, "CLEARED IN " + std::to_string(hud.shots) + " SHOTS - R", v.width / 3, v.height / 2, pixel * 2);
}

bool read_surface_rgb(SDL_Surface *s, std::vector<uint8_t> &rgb) {
    if (SDL_LockSurface(s) != 0) return false;
    rgb.resize(static_cast<size_t>(s->w) * static_cast<size_t>(s->h) * 3);
    size_t k = 0;
    for (int y = 0; y < s->h; ++y) {
        const uint32_t *row = reinterpret_cast<const uint32_t *>(static_cast<const uint8_t *>(s->pixels) + static_cast<ptrdiff_t>(y) * s->pitch);
        for (int x = 0; x < s->w; ++x) SDL_GetRGB(row[x], s->format, &rgb[k], &rgb[k + 1], &rgb[k + 2]), k += 3;
    }
    SDL_UnlockSurface(s);
    return true;
}

bool have_display(std::string &reason) {
    if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) {
        reason = std::string("no display: ") + SDL_GetError();
        return false;
    }
    const char *driver = SDL_GetCurrentVideoDriver();
    if (!driver || !std::strcmp(driver, "offscreen") || !std::strcmp(driver, "dummy")) {
        reason = std::string("no display (SDL video driver '") + (driver ? driver : "none") + "')";
        SDL_Quit();
        return false;
    }
    return true;
}

struct Window {
    SDL_Window *window = nullptr;
    SDL_Renderer *renderer = nullptr;
    ~Window() {
        if (renderer) SDL_DestroyRenderer(renderer);
        if (window) SDL_DestroyWindow(window);
        SDL_Quit();  // also closes SDL's D-Bus connection
    }
};

// Resizable window whose renderer keeps the table's aspect (letterboxed).
WindowResult open_window(const Simulation &sim, Window &w, std::string &error) {
    if (!have_display(error)) return WindowResult::Unavailable;
    const View v(sim.table());
    w.window = SDL_CreateWindow("collide2d billiards", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, v.width, v.height,
                                SDL_WINDOW_RESIZABLE);
    if (!w.window) {
        error = std::string("cannot create window: ") + SDL_GetError();
        return WindowResult::Unavailable;
    }
    w.renderer = SDL_CreateRenderer(w.window, -1, SDL_RENDERER_ACCELERATED | SDL_RENDERER_PRESENTVSYNC);
    if (!w.renderer) w.renderer = SDL_CreateRenderer(w.window, -1, SDL_RENDERER_SOFTWARE);
    if (!w.renderer) {
        error = std::string("cannot create renderer: ") + SDL_GetError();
        return WindowResult::Unavailable;
    }
    SDL_RenderSetLogicalSize(w.renderer, v.width, v.height);
    return WindowResult::Ok;
}

}  // namespace

bool screenshot_offscreen(const Simulation &sim, const std::string &path, std::string &error) {
    const View v(sim.table());
    SDL_Surface *surface = SDL_CreateRGBSurfaceWithFormat(0, v.width, v.height, 32, SDL_PIXELFORMAT_RGBA32);
    SDL_Renderer *r = surface ? SDL_CreateSoftwareRenderer(surface) : nullptr;
    std::vector<uint8_t> rgb;
    bool ok = false;
    if (r) {
        draw_frame(r, sim, Hud{});
        SDL_RenderPresent(r);
        ok = read_surface_rgb(surface, rgb);
    }
    if (!ok) error = std::string("offscreen rendering failed: ") + SDL_GetError();
    if (r) SDL_DestroyRenderer(r);
    if (surface) SDL_FreeSurface(surface);
    return ok && write_png(path, v.width, v.height, rgb, error);
}

WindowResult screenshot_window(const Simulation &sim, const std::string &path, std::string &error) {
    Window w;
    const WindowResult opened = open_window(sim, w, error);
    if (opened != WindowResult::Ok) return opened;
    SDL_Event e;
    while (SDL_PollEvent(&e)) {
    }
    draw_frame(w.renderer, sim, Hud{});
    int width = 0, height = 0;
    SDL_GetRendererOutputSize(w.renderer, &width, &height);
    std::vector<uint8_t> rgb(static_cast<size_t>(width) * static_cast<size_t>(height) * 3);
    // read back what this window's renderer drew, before it is presented
    if (SDL_RenderReadPixels(w.renderer, nullptr, SDL_PIXELFORMAT_RGB24, rgb.data(), width * 3) != 0) {
        error = std::string("cannot read the window's pixels: ") + SDL_GetError();
        return WindowResult::Failed;
    }
    SDL_RenderPresent(w.renderer);
    return write_png(path, width, height, rgb, error) ? WindowResult::Ok : WindowResult::Failed;
}

namespace {

// The player's side of the main loop: aim with the mouse, shoot on release;
// each frame is drawn and held until its time comes (real time).
class Game : public Driver {
public:
    Game(const SimConfig &config, SDL_Renderer *renderer)
        : config_(config), renderer_(renderer), next_tick_(SDL_GetTicks64()) {
        hud_.show = config.scene != Scene::Gas;
    }
    bool next_frame(Simulation &sim) override;
    bool before_step(Simulation &sim, bool) override {
        update_aim(sim);
        return true;
    }
    void after_step(const Simulation &sim) override;

private:
    void update_aim(const Simulation &sim);
    bool handle_event(Simulation &sim, const SDL_Event &e);

    const SimConfig config_;
    SDL_Renderer *renderer_;
    uint64_t next_tick_;  // ms, when the next frame is due
    Hud hud_;
    bool dragging_ = false;
    double press_x_ = 0, press_y_ = 0;  // logical pixels
    double mouse_x_ = 0, mouse_y_ = 0;
};

void Game::update_aim(const Simulation &sim) {
    const View v(sim.table());
    const bool can_shoot = sim.at_rest() && sim.cue_on_table() && sim.object_balls_left() > 0;
    hud_.aim.visible = can_shoot;
    if (!can_shoot) return;
    const Ball &cue = sim.balls()[0];
    if (!dragging_) hud_.aim.angle = std::atan2(v.wy(mouse_y_) - cue.y, v.wx(mouse_x_) - cue.x);
    const double dragged = dragging_ ? std::hypot(mouse_x_ - press_x_, mouse_y_ - press_y_) : 0.0;
    hud_.aim.speed = std::min(kMaxPlaySpeed, dragged * kPowerPerPixel);
}

// Returns false when the player quits.
bool Game::handle_event(Simulation &sim, const SDL_Event &e) {
    switch (e.type) {
    case SDL_QUIT: return false;
    case SDL_KEYDOWN:
        if (e.key.keysym.sym == SDLK_ESCAPE) return false;
        if (e.key.keysym.sym == SDLK_r) {
            sim = Simulation(config_);
            hud_.shots = 0;
            dragging_ = false;
        }
        break;
    case SDL_MOUSEMOTION:
        mouse_x_ = e.motion.x;
        mouse_y_ = e.motion.y;
        break;
    case SDL_MOUSEBUTTONDOWN:
        if (e.button.button == SDL_BUTTON_LEFT && hud_.aim.visible) {
            dragging_ = true;
            press_x_ = mouse_x_ = e.button.x;
            press_y_ = mouse_y_ = e.button.y;
        } else if (e.button.button == SDL_BUTTON_RIGHT) {
            dragging_ = false;
        }
        break;
    case SDL_MOUSEBUTTONUP:
        if (e.button.button == SDL_BUTTON_LEFT && dragging_) {
            dragging_ = false;
            if (hud_.aim.speed > 0) {
                sim.shoot(Shot{hud_.aim.angle * 180.0 / M_PI, hud_.aim.speed});
                ++hud_.shots;
            }
        }
        break;
    default: break;
    }
    return true;
}

bool Game::next_frame(Simulation &sim) {
    SDL_Event e;
    while (SDL_PollEvent(&e))
        if (!handle_event(sim, e)) return false;
    return true;
}

void Game::after_step(const Simulation &sim) {
    draw_frame(renderer_, sim, hud_);
    SDL_RenderPresent(renderer_);
    // keep real time even without vsync
    next_tick_ += 1000 / 60;
    const uint64_t now = SDL_GetTicks64();
    if (next_tick_ > now) SDL_Delay(static_cast<uint32_t>(next_tick_ - now));
    else next_tick_ = now;
}

}  // namespace

WindowResult play_window(const SimConfig &config, std::string &error) {
    Simulation sim(config);
    Window w;
    const WindowResult opened = open_window(sim, w, error);
    if (opened != WindowResult::Ok) return opened;
    if (config.scene != Scene::Break) sim.shoot(Shot{0, kMaxPlaySpeed});
    Game game(config, w.renderer);
    run(sim, game);
    return WindowResult::Ok;
}

}  // namespace demo
