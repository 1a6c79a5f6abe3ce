/* SPDX-License-Identifier: MIT */
// draw_table.h - the table under the balls: cloth, cushions (rubber behind
// each cushion face, the jaw facings and noses), the pocket holes (exactly
// the circles a ball's centre must enter to fall), wooden rails with their
// diamonds.  Drawn pixel by pixel from the simulation's geometry
// (TableShape), antialiased where materials meet; the result is cached and
// copied under each frame.
#ifndef C2D_DEMO_DRAW_TABLE_H
#define C2D_DEMO_DRAW_TABLE_H

#include "app/canvas.h"
#include "app/engine_view.h"
#include "app/view.h"

namespace demo {

enum class TableStyle { Pool, Box };  // Box: the gas scene's dark box

// Clears the canvas to black (the letterbox) and draws the table in
// layout.table.
void draw_table(Canvas &canvas, const TableShape &table, const Screen &layout, TableStyle style);

}  // namespace demo

#endif
