// png.h - minimal PNG writer (8-bit RGB, uncompressed "stored" deflate).
// The screenshots are small and rare; a 60-line writer keeps the demo free
// of libpng/zlib, one dependency fewer on a fresh machine.
#ifndef C2D_DEMO_PNG_H
#define C2D_DEMO_PNG_H

#include <cstdint>
#include <string>
#include <vector>

namespace demo {

// rgb: width * height * 3 bytes, rows top to bottom.  Returns false and sets
// error if the file cannot be written.
bool write_png(const std::string &path, int width, int height, const std::vector<uint8_t> &rgb, std::string &error);

}  // namespace demo

#endif
