/* SPDX-License-Identifier: MIT */
// canvas.h - the window's pixels, drawn in software: an RGB frame buffer with
// antialiased primitives (disks, rings, thick lines, convex polygons,
// rectangles) blended in sRGB.  The same frame goes to the window (one
// streaming texture) and to screenshots, so what the tests and the README
// show is what the player sees.  Coverage antialiasing: a pixel whose centre
// lies at signed distance d inside an edge is covered min(1, max(0, d + 0.5)).
#ifndef C2D_DEMO_CANVAS_H
#define C2D_DEMO_CANVAS_H

#include <cstdint>
#include <vector>

namespace demo {

struct Colour {
    float r, g, b;  // 0..1, sRGB
};

Colour mix(Colour a, Colour b, float t);  // a + (b - a) t
Colour scaled(Colour c, float k);         // each channel times k, clamped to 1
constexpr Colour rgb8(int r, int g, int b) {
    return {static_cast<float>(r) / 255.0f, static_cast<float>(g) / 255.0f, static_cast<float>(b) / 255.0f};
}

struct PointF {
    float x, y;
};

class Canvas {
public:
    Canvas() = default;
    Canvas(int width, int height);
    int width() const { return width_; }
    int height() const { return height_; }
    // 0xffRRGGBB per pixel, rows top to bottom (SDL_PIXELFORMAT_ARGB8888).
    const std::vector<uint32_t> &pixels() const { return pixels_; }
    std::vector<uint32_t> &pixels() { return pixels_; }
    // width * height * 3 bytes, for PNG files.
    std::vector<uint8_t> rgb() const;

    void clear(Colour c);
    void put(int x, int y, Colour c);
    void blend(int x, int y, Colour c, float alpha);
    Colour get(int x, int y) const;

    void fill_rect(float x0, float y0, float x1, float y1, Colour c, float alpha = 1);
    void fill_disk(float cx, float cy, float radius, Colour c, float alpha = 1);
    void ring(float cx, float cy, float radius, float thickness, Colour c, float alpha = 1);
    // A line of the given width with round ends.
    void line(PointF a, PointF b, float thickness, Colour c, float alpha = 1);
    void dashed_line(PointF a, PointF b, float thickness, float dash, Colour c, float alpha = 1);
    // Vertices in either winding order.
    void fill_convex(const std::vector<PointF> &polygon, Colour c, float alpha = 1);
    // A soft round shadow: alpha falls off smoothly from the centre to radius.
    void soft_disk(float cx, float cy, float radius, Colour c, float alpha);

private:
    struct Box {
        int x0, y0, x1, y1;  // inclusive-exclusive, clipped
    };
    Box clip(float x0, float y0, float x1, float y1) const;

    int width_ = 0, height_ = 0;
    std::vector<uint32_t> pixels_;
};

}  // namespace demo

#endif
