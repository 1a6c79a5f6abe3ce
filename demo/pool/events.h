/* SPDX-License-Identifier: MIT */
// events.h - what happened during a run, in time order: contacts, pocket
// drops, the cue strike and the balls' changes of motion state.  A
// ball-ball contact is two records at the same time, one for each ball
// (the lower-numbered first), so every ball's state after every change is
// on record.  The same
// records feed --events FILE.csv, the window's sounds (frame_events) and
// the shot seam (simulate_shot).
#ifndef C2D_DEMO_EVENTS_H
#define C2D_DEMO_EVENTS_H

namespace demo {

enum class EventKind { BallBall, Cushion, Jaw, Pocket, Strike, SlideToRoll, RollToSpin, Stop };

// The CSV name: ball_ball, cushion, jaw, pocket, strike, slide_to_roll,
// roll_to_spin, stop.
inline const char *event_name(EventKind kind) {
    switch (kind) {
    case EventKind::BallBall: return "ball_ball";
    case EventKind::Cushion: return "cushion";
    case EventKind::Jaw: return "jaw";
    case EventKind::Pocket: return "pocket";
    case EventKind::Strike: return "strike";
    case EventKind::SlideToRoll: return "slide_to_roll";
    case EventKind::RollToSpin: return "roll_to_spin";
    default: return "stop";
    }
}

struct Event {
    double t;                // simulation time, s
    EventKind kind;
    int ball;                // index into balls()
    int other;               // ball_ball: the other ball's index; otherwise -1
    int feature;             // cushion: index into Table::cushions; jaw: pocket index * 2 + jaw;
                             // pocket: pocket index; otherwise -1
    double x, y, vx, vy;     // `ball` just after the event (a pocket: where it fell)
    double wx, wy, wz;
    double impulse;          // |normal impulse| of a contact, N s; strike: m v; 0 for the others
};

using FrameEvent = Event;

}  // namespace demo

#endif
