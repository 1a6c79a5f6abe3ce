/* SPDX-License-Identifier: MIT */
// controller.h - the game in a window: the player's side of the main loop
// (sim.h run), turning the mouse and keys into aim, spin and shots, the
// match's turns (game.h) and the computer's shots into play, and each frame
// into a picture (window.h) and sounds (audio.h).
#ifndef C2D_DEMO_CONTROLLER_H
#define C2D_DEMO_CONTROLLER_H

#include <string>

#include "app/render.h"
#include "game/game.h"
#include "pool/sim.h"

namespace demo {

// The game (keys in the help box it opens with, H toggles it): aim with the
// mouse, press and drag to pull the cue back, release to shoot; spin on the
// panel's cue-ball diagram or the arrow keys.  Unavailable (with the reason
// in error) when there is no display or no window/renderer can be made.
WindowResult play_window(const SimConfig &config, const Players &players, std::string &error);

}  // namespace demo

#endif
