/* SPDX-License-Identifier: MIT */
// main.cpp - the billiards demo's entry point: decides between the window
// and a headless run (before SDL touches the video system) and runs it: the
// game in the window (controller.h) or, headless, what was asked for
// (headless.h).
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "app/cli.h"
#include "app/controller.h"
#include "app/headless.h"
#include "app/render.h"
#include "game/game.h"

namespace {

using demo::Options;
using demo::UsageError;

// Whether a window can be tried: an X or Wayland display is named.  Decided
// before SDL initialises video, so SDL has no chance to complain first.
bool display_named(std::string &why) {
    const char *x = std::getenv("DISPLAY"), *wayland = std::getenv("WAYLAND_DISPLAY");
    if ((x && *x) || (wayland && *wayland)) {
        // with X only, keep SDL from probing Wayland (which prints its own
        // complaint when XDG_RUNTIME_DIR is unset)
        if (!(wayland && *wayland)) setenv("SDL_VIDEODRIVER", "x11", 0);
        return true;
    }
    why = "no display (neither DISPLAY nor WAYLAND_DISPLAY is set)";
    return false;
}

std::string joined(const std::vector<std::string> &flags) {
    std::string s;
    for (const std::string &f : flags) s += (s.empty() ? "" : ", ") + f;
    return s;
}

int run(const Options &o) {
    std::string why;
    const bool display = display_named(why);  // also for --headless --screenshot-window
    if (!o.headless && display) {
        if (!o.headless_only.empty())
            throw UsageError{joined(o.headless_only) + ": only for a headless run (add --headless)"};
        const bool nine = o.game == demo::GameMode::NineBall;
        demo::SimConfig config = o.config;
        if (nine)  // the window racks from placements: the 9-ball diamond of the same seed
            for (const demo::Ball &b : demo::set_up_nine_ball(config.table, config.seed).balls)
                config.placements.push_back(demo::Placement{b.number, b.x, b.y});
        const demo::Players players{demo::rules_game(o.game), {o.computer[0], o.computer[1]},
                                    nine ? demo::GameKind::NineBall : demo::GameKind::EightBall};
        if (demo::play_window(config, players, why) == demo::WindowResult::Ok) return 0;
    }
    // a run that headless would refuse says only why (exit 2), not that it
    // falls back to headless first
    demo::check_headless(o);
    if (!o.headless) std::fprintf(stderr, "billiards: %s; running headless\n", why.c_str());
    if (demo::rules_game(o.game)) return demo::run_game_headless(o);
    return demo::run_scene_headless(o);
}

// Everything written to stdout (--help, the summary, --json) reaches it, or
// the run fails: status 1 and a message, also when the run itself succeeded.
int finish_stdout(int status) {
    errno = 0;
    const bool flushed = std::fflush(stdout) == 0;
    int error = flushed ? 0 : errno;
    if (std::ferror(stdout) && !error) error = EIO;
    errno = 0;
    // EBADF from the close alone: stdout was closed and nothing written to it
    if (std::fclose(stdout) != 0 && !error && errno != EBADF) error = errno ? errno : EIO;
    if (!error) return status;
    std::fprintf(stderr, "billiards: standard output: %s\n", std::strerror(error));
    return 1;
}

}  // namespace

int main(int argc, char **argv) {
    try {
        const Options o = demo::parse(argc, argv);
        if (o.help) {
            std::fputs(demo::kUsage, stdout);
            return finish_stdout(0);
        }
        return finish_stdout(run(o));
    } catch (const UsageError &e) {
        std::fprintf(stderr, "billiards: %s\n", e.message.c_str());
        return 2;
    } catch (const std::exception &e) {
        std::fprintf(stderr, "billiards: %s\n", e.what());
        return 1;
    }
}
