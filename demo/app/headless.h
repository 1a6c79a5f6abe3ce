/* SPDX-License-Identifier: MIT */
// headless.h - a run without a window: the scene played to rest (or for
// --seconds) with its shots, or a game of 8-ball between two computer
// players, then what was asked for written out (the summary or JSON on
// stdout, events, trace, speeds, screenshots).  Each returns the exit
// status: 0, or 1 after a write error to a file (with its message on
// stderr; stdout is checked by main).  Whatever can be checked before
// simulating is checked by check_headless, which the caller runs first.
#ifndef C2D_DEMO_HEADLESS_H
#define C2D_DEMO_HEADLESS_H

#include "app/cli.h"

namespace demo {

// Every refusal of a headless run, before anything is simulated or said
// (throws UsageError: exit 2): --game practice (the window's only), human
// --players with --game 8ball, a display for --screenshot-window, each
// output file writable (no file left behind), no two outputs in one file.
// main calls it before either run below, and before it says that a run
// without a window falls back to headless, so a refused run prints only why.
void check_headless(const Options &o);

// --scene with --shot, --place, --seconds and the output files.
int run_scene_headless(const Options &o);

// --game 8ball, --players computer,computer.
int run_game_headless(const Options &o);

}  // namespace demo

#endif
