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

// The game play_window is running, for a page or a tool around the window
// (the web page's window.collide2d, demo/web/hook.cpp): what is on the table,
// and shots played as the player would play them.
class PlayingGame {
public:
    virtual ~PlayingGame() = default;
    virtual const Simulation &simulation() const = 0;
    // A shot as --shot takes it (validated the same way), played as every
    // shot of the window is: from the position on the table as if freshly set
    // up (Simulation::shoot: the engine's clock starts at 0, as a headless
    // run's does; the result depends on the position and the shot alone).  False, and
    // nothing played, unless the table is at rest and a human may shoot (not
    // the computer's turn, no ball in hand).
    virtual bool shoot(const Shot &shot) = 0;
    // Frames drawn in the window so far (a frame rate, over a measured time).
    virtual long frames_drawn() const = 0;
};

// The game being played, or null (before play_window runs one, and after).
PlayingGame *playing_game();

}  // namespace demo

#endif
