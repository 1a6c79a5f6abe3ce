/* SPDX-License-Identifier: MIT */
// png_check.cpp - test helper: decodes a PNG with libpng (independent of the
// demo's own writer) and fails unless it is valid and not blank.
// usage: png_check FILE.png   prints "WIDTHxHEIGHT, N colours"
#include <png.h>

#include <cstdio>
#include <set>
#include <vector>

int main(int argc, char **argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: png_check FILE.png\n");
        return 2;
    }
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&image, argv[1])) {
        std::fprintf(stderr, "png_check: %s: %s\n", argv[1], image.message);
        return 1;
    }
    image.format = PNG_FORMAT_RGB;
    std::vector<png_byte> pixels(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, pixels.data(), 0, nullptr)) {
        std::fprintf(stderr, "png_check: %s: %s\n", argv[1], image.message);
        return 1;
    }
    std::set<unsigned> colours;
    for (size_t i = 0; i + 2 < pixels.size(); i += 3)
        colours.insert(pixels[i] << 16 | pixels[i + 1] << 8 | pixels[i + 2]);
    std::printf("%ux%u, %zu colours\n", image.width, image.height, colours.size());
    return colours.size() > 1 ? 0 : 1;
}
