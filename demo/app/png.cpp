/* SPDX-License-Identifier: MIT */
// png.cpp - see png.h.  The image is encoded in memory
// (png_image_write_to_memory: first call sizes it, second fills it), then
// written with plain stdio so every write error is seen.
#include "app/png.h"

#include <png.h>  // NOLINT(readability-duplicate-include): libpng's header, not demo/app/png.h

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace demo {

bool write_png(const std::string &path, int width, int height, const std::vector<uint8_t> &rgb, std::string &error) {
    if (width <= 0 || height <= 0 || rgb.size() != static_cast<size_t>(width) * static_cast<size_t>(height) * 3) {
        error = path + ": bad image size";
        return false;
    }
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = static_cast<png_uint_32>(width);
    image.height = static_cast<png_uint_32>(height);
    image.format = PNG_FORMAT_RGB;
    png_alloc_size_t bytes = 0;
    const png_int_32 stride = width * 3;
    if (!png_image_write_to_memory(&image, nullptr, &bytes, 0, rgb.data(), stride, nullptr)) {
        error = path + ": cannot encode PNG: " + image.message;
        return false;
    }
    std::vector<uint8_t> file(bytes);
    if (!png_image_write_to_memory(&image, file.data(), &bytes, 0, rgb.data(), stride, nullptr)) {
        error = path + ": cannot encode PNG: " + image.message;
        return false;
    }
    FILE *f = std::fopen(path.c_str(), "wb");
    if (!f) {
        error = path + ": " + std::strerror(errno);
        return false;
    }
    const bool written = std::fwrite(file.data(), 1, bytes, f) == bytes && std::fflush(f) == 0;
    const int saved = errno;
    if (std::fclose(f) != 0 || !written) {
        error = path + ": write failed: " + std::strerror(written ? errno : saved);
        return false;
    }
    return true;
}

}  // namespace demo
