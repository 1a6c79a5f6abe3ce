/* SPDX-License-Identifier: MIT */
// png.h - compressed PNG screenshots (8-bit RGB) through libpng's simplified
// API: deflate with adaptive row filters, so a table picture of mostly
// smooth colour takes tens of kilobytes, not megabytes.
#ifndef C2D_DEMO_PNG_H
#define C2D_DEMO_PNG_H

#include <cstdint>
#include <string>
#include <vector>

namespace demo {

// rgb: width * height * 3 bytes, rows top to bottom.  Returns false and sets
// error if the image cannot be encoded or the file cannot be written
// completely (a full disk included).
bool write_png(const std::string &path, int width, int height, const std::vector<uint8_t> &rgb, std::string &error);

}  // namespace demo

#endif
