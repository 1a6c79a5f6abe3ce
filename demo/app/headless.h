/* SPDX-License-Identifier: MIT */
// headless.h - a run without a window: the scene played to rest (or for
// --seconds) with its shots, or a game of 8-ball between two computer
// players, then what was asked for written out (the summary or JSON on
// stdout, events, trace, speeds, screenshots).  Each returns the exit
// status: 0, or 1 after a write error to a file (with its message on
// stderr; stdout is checked by main).  Whatever can be checked before
// simulating throws UsageError before simulating: a display for
// --screenshot-window, each output file writable (no file left behind),
// no two outputs in one file.
#ifndef C2D_DEMO_HEADLESS_H
#define C2D_DEMO_HEADLESS_H

#include "app/cli.h"

namespace demo {

// --scene with --shot, --place, --seconds and the output files.
int run_scene_headless(const Options &o);

// --game 8ball, --players computer,computer.
int run_game_headless(const Options &o);

}  // namespace demo

#endif
