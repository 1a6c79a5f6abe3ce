/* SPDX-License-Identifier: MIT */
// cli.h - the command line of the billiards demo: the options, their
// parsing and checks (`billiards --help` lists them).  Bad input is a
// UsageError: the caller prints its message and exits with status 2.
#ifndef C2D_DEMO_CLI_H
#define C2D_DEMO_CLI_H

#include <string>
#include <vector>

#include "pool/sim.h"

namespace demo {

extern const char kUsage[];

// --game: none given (today's runs), practice (clear the table, the
// window's default) or 8-ball; --players: who plays each side of 8-ball.
enum class GameMode { None, Practice, EightBall, NineBall };
// A game by the rules, two players: 8-ball or 9-ball.
inline bool rules_game(GameMode g) { return g == GameMode::EightBall || g == GameMode::NineBall; }

struct Options {
    bool help = false;  // --help or -h: print kUsage, nothing else
    SimConfig config;
    GameMode game = GameMode::None;
    bool players_given = false;
    bool computer[2] = {false, true};  // 8-ball players (window default human,computer)
    bool balls_given = false, headless = false, json = false;
    std::vector<Shot> shots;
    double seconds = -1;  // < 0: the scene's default
    std::string screenshot, screenshot_window, trace, speeds, events;
    // The options given that only a headless run uses (for the message
    // that refuses them in a window).
    std::vector<std::string> headless_only;
};

struct UsageError {
    std::string message;
};

// Parses and checks the command line; throws UsageError.  --help (or -h)
// stops the parsing there and sets help.
Options parse(int argc, char **argv);

}  // namespace demo

#endif
