/* SPDX-License-Identifier: MIT */
// font.h - a 5x7 bitmap font (printable ASCII, with descenders: cells of
// 5x9 font pixels), drawn at an integer scale with an optional drop shadow.
// The balls' numbers sample the same glyphs on the sphere (glyph_on).
#ifndef C2D_DEMO_FONT_H
#define C2D_DEMO_FONT_H

#include <string>
#include <vector>

#include "app/canvas.h"

namespace demo {

constexpr int kGlyphColumns = 5;
constexpr int kGlyphRows = 7;       // capital height
constexpr int kGlyphCellRows = 9;   // with descenders
constexpr int kGlyphAdvance = 6;    // columns per character, spacing included
constexpr int kLineAdvance = 12;    // rows per line, spacing included

// Whether font pixel (column, row) of c is set; row 0 is the top of a
// capital, rows 7 and 8 the descenders.  Unknown characters draw as '?'.
bool glyph_on(char c, int column, int row);

// Width and height in canvas pixels of one line of text at scale.
int text_width(const std::string &text, int scale);
inline int text_height(int scale) { return kGlyphRows * scale; }

struct TextStyle {
    int scale = 2;
    Colour colour{1, 1, 1};
    bool shadow = true;  // a dark copy one font pixel down-right
};

// Draws one line with its top-left corner at (x, y); returns the width.
int draw_text(Canvas &canvas, const std::string &text, int x, int y, const TextStyle &style);

// The largest scale <= preferred at which text fits in max_width (at least 1).
int fit_scale(const std::string &text, int max_width, int preferred);

// Breaks text into lines of at most max_width pixels at scale, at spaces.
std::vector<std::string> wrap(const std::string &text, int max_width, int scale);

}  // namespace demo

#endif
