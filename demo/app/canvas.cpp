/* SPDX-License-Identifier: MIT */
// canvas.cpp - see canvas.h.
#include "app/canvas.h"

#include <algorithm>
#include <cmath>

namespace demo {

namespace {

float clamp01(float v) { return std::min(1.0f, std::max(0.0f, v)); }

uint32_t pack(Colour c) {
    // never negative, so adding 0.5 and truncating rounds to nearest (and is
    // much faster than lround here, once per channel per pixel)
    const auto channel = [](float v) { return static_cast<uint32_t>(clamp01(v) * 255.0f + 0.5f); };  // NOLINT(bugprone-incorrect-roundings)
    return 0xff000000u | channel(c.r) << 16 | channel(c.g) << 8 | channel(c.b);
}

Colour unpack(uint32_t p) {
    constexpr float k = 1.0f / 255.0f;
    return {static_cast<float>((p >> 16) & 0xff) * k, static_cast<float>((p >> 8) & 0xff) * k, static_cast<float>(p & 0xff) * k};
}

// Distance from p to the segment ab.
float segment_distance(float px, float py, PointF a, PointF b) {
    const float dx = b.x - a.x, dy = b.y - a.y;
    const float len2 = dx * dx + dy * dy;
    float t = len2 > 0 ? ((px - a.x) * dx + (py - a.y) * dy) / len2 : 0.0f;
    t = clamp01(t);
    return std::hypot(px - (a.x + t * dx), py - (a.y + t * dy));
}

}  // namespace

Colour mix(Colour a, Colour b, float t) {
    return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t};
}

Colour scaled(Colour c, float k) { return {std::min(1.0f, c.r * k), std::min(1.0f, c.g * k), std::min(1.0f, c.b * k)}; }

Canvas::Canvas(int width, int height)
    : width_(std::max(1, width)), height_(std::max(1, height)),
      pixels_(static_cast<size_t>(width_) * static_cast<size_t>(height_), 0xff000000u) {}

std::vector<uint8_t> Canvas::rgb() const {
    std::vector<uint8_t> out;
    out.reserve(pixels_.size() * 3);
    for (uint32_t p : pixels_) {
        out.push_back(static_cast<uint8_t>(p >> 16));
        out.push_back(static_cast<uint8_t>(p >> 8));
        out.push_back(static_cast<uint8_t>(p));
    }
    return out;
}

void Canvas::clear(Colour c) { std::fill(pixels_.begin(), pixels_.end(), pack(c)); }

void Canvas::put(int x, int y, Colour c) {
    if (x >= 0 && y >= 0 && x < width_ && y < height_) pixels_[static_cast<size_t>(y) * static_cast<size_t>(width_) + static_cast<size_t>(x)] = pack(c);
}

Colour Canvas::get(int x, int y) const {
    if (x < 0 || y < 0 || x >= width_ || y >= height_) return {0, 0, 0};
    return unpack(pixels_[static_cast<size_t>(y) * static_cast<size_t>(width_) + static_cast<size_t>(x)]);
}

void Canvas::blend(int x, int y, Colour c, float alpha) {
    if (alpha <= 0 || x < 0 || y < 0 || x >= width_ || y >= height_) return;
    uint32_t &p = pixels_[static_cast<size_t>(y) * static_cast<size_t>(width_) + static_cast<size_t>(x)];
    p = alpha >= 1 ? pack(c) : pack(mix(unpack(p), c, alpha));
}

Canvas::Box Canvas::clip(float x0, float y0, float x1, float y1) const {
    Box b{static_cast<int>(std::floor(x0)), static_cast<int>(std::floor(y0)), static_cast<int>(std::ceil(x1)) + 1,
          static_cast<int>(std::ceil(y1)) + 1};
    b.x0 = std::max(0, b.x0);
    b.y0 = std::max(0, b.y0);
    b.x1 = std::min(width_, b.x1);
    b.y1 = std::min(height_, b.y1);
    return b;
}

void Canvas::fill_rect(float x0, float y0, float x1, float y1, Colour c, float alpha) {
    const Box b = clip(x0, y0, x1, y1);
    // fully covered pixels in 8-bit fixed point: p + (c - p) a / 256
    const uint32_t colour = pack(c), a = static_cast<uint32_t>(clamp01(alpha) * 256.0f + 0.5f);  // NOLINT(bugprone-incorrect-roundings): >= 0
    for (int y = b.y0; y < b.y1; ++y) {
        const float py = static_cast<float>(y) + 0.5f;
        const float cy = clamp01(std::min(py - y0, y1 - py) + 0.5f);
        uint32_t *row = pixels_.data() + static_cast<size_t>(y) * static_cast<size_t>(width_);
        for (int x = b.x0; x < b.x1; ++x) {
            const float px = static_cast<float>(x) + 0.5f;
            const float cx = clamp01(std::min(px - x0, x1 - px) + 0.5f);
            if (cx * cy < 1) {
                blend(x, y, c, alpha * cx * cy);
                continue;
            }
            uint32_t &p = row[x];
            uint32_t out = 0xff000000u;
            for (int shift = 0; shift < 24; shift += 8) {
                const uint32_t from = (p >> shift) & 0xff, to = (colour >> shift) & 0xff;
                out |= ((from * (256 - a) + to * a) >> 8) << shift;
            }
            p = out;
        }
    }
}

void Canvas::fill_disk(float cx, float cy, float radius, Colour c, float alpha) {
    const Box b = clip(cx - radius - 1, cy - radius - 1, cx + radius + 1, cy + radius + 1);
    for (int y = b.y0; y < b.y1; ++y)
        for (int x = b.x0; x < b.x1; ++x) {
            const float d = std::hypot(static_cast<float>(x) + 0.5f - cx, static_cast<float>(y) + 0.5f - cy);
            blend(x, y, c, alpha * clamp01(radius - d + 0.5f));
        }
}

void Canvas::soft_disk(float cx, float cy, float radius, Colour c, float alpha) {
    const Box b = clip(cx - radius, cy - radius, cx + radius, cy + radius);
    for (int y = b.y0; y < b.y1; ++y)
        for (int x = b.x0; x < b.x1; ++x) {
            const float d = std::hypot(static_cast<float>(x) + 0.5f - cx, static_cast<float>(y) + 0.5f - cy) / radius;
            if (d < 1) blend(x, y, c, alpha * (1 - d * d) * (1 - d * d));
        }
}

void Canvas::ring(float cx, float cy, float radius, float thickness, Colour c, float alpha) {
    const float half = thickness / 2, outer = radius + half + 1;
    const Box b = clip(cx - outer, cy - outer, cx + outer, cy + outer);
    for (int y = b.y0; y < b.y1; ++y)
        for (int x = b.x0; x < b.x1; ++x) {
            const float d = std::hypot(static_cast<float>(x) + 0.5f - cx, static_cast<float>(y) + 0.5f - cy);
            blend(x, y, c, alpha * clamp01(half - std::fabs(d - radius) + 0.5f));
        }
}

void Canvas::line(PointF a, PointF b, float thickness, Colour c, float alpha) {
    const float half = thickness / 2, pad = half + 1;
    const Box box = clip(std::min(a.x, b.x) - pad, std::min(a.y, b.y) - pad, std::max(a.x, b.x) + pad, std::max(a.y, b.y) + pad);
    for (int y = box.y0; y < box.y1; ++y)
        for (int x = box.x0; x < box.x1; ++x) {
            const float d = segment_distance(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f, a, b);
            // thin lines keep their weight: coverage scaled by the width below a pixel
            blend(x, y, c, alpha * std::min(1.0f, thickness) * clamp01(std::max(half, 0.5f) - d + 0.5f));
        }
}

void Canvas::dashed_line(PointF a, PointF b, float thickness, float dash, Colour c, float alpha) {
    const float length = std::hypot(b.x - a.x, b.y - a.y);
    if (length <= 0 || dash <= 0) return;
    const float ux = (b.x - a.x) / length, uy = (b.y - a.y) / length;
    const int dashes = static_cast<int>(std::ceil(length / (2 * dash)));
    for (int k = 0; k < dashes; ++k) {
        const float s = static_cast<float>(k) * 2 * dash, e = std::min(length, s + dash);
        line({a.x + ux * s, a.y + uy * s}, {a.x + ux * e, a.y + uy * e}, thickness, c, alpha);
    }
}

void Canvas::fill_convex(const std::vector<PointF> &polygon, Colour c, float alpha) {
    if (polygon.size() < 3) return;
    float x0 = polygon[0].x, x1 = x0, y0 = polygon[0].y, y1 = y0, area = 0;
    for (size_t i = 0; i < polygon.size(); ++i) {
        const PointF &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
        x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
        area += p.x * q.y - q.x * p.y;
    }
    if (area == 0) return;
    const float sign = area > 0 ? 1.0f : -1.0f;
    struct Edge {
        float x, y, ex, ey;  // a point and the unit direction times the winding's sign
    };
    std::vector<Edge> edges;
    for (size_t i = 0; i < polygon.size(); ++i) {
        const PointF &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
        const float len = std::hypot(q.x - p.x, q.y - p.y);
        if (len > 0) edges.push_back({p.x, p.y, sign * (q.x - p.x) / len, sign * (q.y - p.y) / len});
    }
    const Box b = clip(x0, y0, x1, y1);
    for (int y = b.y0; y < b.y1; ++y)
        for (int x = b.x0; x < b.x1; ++x) {
            const float px = static_cast<float>(x) + 0.5f, py = static_cast<float>(y) + 0.5f;
            float inside = 1e9f;  // least signed distance to an edge, > 0 inside
            for (const Edge &e : edges) inside = std::min(inside, e.ex * (py - e.y) - e.ey * (px - e.x));
            if (inside > -0.5f) blend(x, y, c, alpha * clamp01(inside + 0.5f));
        }
}

}  // namespace demo
