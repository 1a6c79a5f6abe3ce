/* SPDX-License-Identifier: MIT */
// draw_balls.cpp - see draw_balls.h.  Each pixel of a ball is supersampled
// 3x3: a sample at (sx, sy) radii from the centre sees the sphere's point
// with world normal n = (sx, -sy, sqrt(1 - sx^2 - sy^2)); its body
// coordinates q = R^T n decide the material (stripe: |q_z| < 0.5; number
// circle: |q_x| > cos 30 degrees, the digits mapped onto it gnomonically,
// upright along +z), and Blinn-Phong lighting from the upper left shades it.
// Orientations follow Rodrigues' formula, R <- exp(dt [w]x) R, with the
// columns re-orthonormalised after each step.
#include "app/draw_balls.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "app/font.h"

namespace demo {

namespace {

constexpr double kDecalCos = 0.809;      // number circle: 36 degrees around +-x
constexpr double kDecalTan = 0.727;
constexpr double kStripeHalf = 0.5;      // stripe: |z| below this
constexpr double kCueDotCos = 0.985;     // the cue ball's two small red dots (10 degrees)

Colour ball_colour(int number) {
    static const Colour colours[8] = {rgb8(246, 244, 232), rgb8(250, 196, 18), rgb8(24, 70, 196), rgb8(214, 30, 34),
                                      rgb8(104, 40, 150),  rgb8(250, 118, 22), rgb8(24, 128, 64), rgb8(130, 32, 36)};
    if (number == 8) return rgb8(18, 18, 20);
    const int k = number > 8 ? number - 8 : number;  // stripes 9-15 share 1-7's colours
    return k >= 0 && k < 8 ? colours[k] : colours[0];
}

struct Light {
    double lx, ly, lz, hx, hy, hz;
    Light() {
        const double l = std::sqrt(0.4 * 0.4 + 0.5 * 0.5 + 0.77 * 0.77);
        lx = -0.4 / l, ly = 0.5 / l, lz = 0.77 / l;
        const double h = std::sqrt(lx * lx + ly * ly + (lz + 1) * (lz + 1));
        hx = lx / h, hy = ly / h, hz = (lz + 1) / h;
    }
};

// The balls' numbers: the 5x7 font where a font pixel gets at least 2.2
// screen pixels, else bold 3x5 digits, legible on a ball 12 pixels across.
bool small_digit_on(char c, int column, int row) {
    static const unsigned char rows[10][5] = {{7, 5, 5, 5, 7}, {2, 6, 2, 2, 7}, {7, 1, 7, 4, 7}, {7, 1, 3, 1, 7},
                                              {5, 5, 7, 1, 1}, {7, 4, 7, 1, 7}, {7, 4, 7, 5, 7}, {7, 1, 2, 2, 2},
                                              {7, 5, 7, 5, 7}, {7, 5, 7, 1, 7}};
    if (c < '0' || c > '9' || column < 0 || column > 2 || row < 0 || row > 4) return false;
    return (rows[c - '0'][row] >> (2 - column)) & 1;
}

struct Label {
    std::string text;
    int columns = 0, rows = 0, advance = 0;
    double size = 0;  // tangent-plane units (ball radii) per font pixel
    bool small = false;

    Label(int number, float radius) : text(number > 0 ? std::to_string(number) : "") {
        for (int pass = 0; pass < 2 && !text.empty(); ++pass) {
            small = pass == 1;
            advance = small ? 4 : kGlyphAdvance;
            rows = small ? 5 : kGlyphRows;
            columns = static_cast<int>(text.size()) * advance - 1;
            // the text's box fills the number circle's inscribed width
            size = 0.9 * kDecalTan / std::hypot(columns / 2.0, rows / 2.0);
            if (size * radius >= 2.2) break;
        }
    }
    // Whether a digit covers the circle's point (u, v) (u right, v up).
    bool at(double u, double v) const {
        const double col = u / size + columns / 2.0, row = -v / size + rows / 2.0;
        if (text.empty() || col < 0 || row < 0 || col >= columns || row >= rows) return false;
        const int c = static_cast<int>(col), r = static_cast<int>(row);
        const char digit = text[static_cast<size_t>(c / advance)];
        return small ? small_digit_on(digit, c % advance, r) : glyph_on(digit, c % advance, r);
    }
};

// The material at body point q of ball `number`.
Colour surface(int number, const Label &label, double qx, double qy, double qz) {
    const Colour white = ball_colour(0);
    if (number == 0) return std::fabs(qx) > kCueDotCos ? rgb8(200, 30, 30) : white;
    if (number < 0) return white;  // the spin selector's plain cue ball
    if (std::fabs(qx) > kDecalCos) {
        const double side = qx > 0 ? 1.0 : -1.0;
        // seen from outside the +x pole, right is +y; from the -x pole, -y
        return label.at(side * qy / std::fabs(qx), qz / std::fabs(qx)) ? rgb8(20, 20, 20) : white;
    }
    if (number > 8 && std::fabs(qz) >= kStripeHalf) return white;
    return ball_colour(number);
}

Mat3 multiply(const Mat3 &a, const Mat3 &b) {
    Mat3 c{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) c.m[i][j] += a.m[i][k] * b.m[k][j];
    return c;
}

// Rotation by angle about the unit axis (x, y, z).
Mat3 rotation(double x, double y, double z, double angle) {
    const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
    return Mat3{{{t * x * x + c, t * x * y - s * z, t * x * z + s * y},
                 {t * x * y + s * z, t * y * y + c, t * y * z - s * x},
                 {t * x * z - s * y, t * y * z + s * x, t * z * z + c}}};
}

// Gram-Schmidt on the columns, so rounding never shears the ball.
void orthonormalise(Mat3 &r) {
    double a[3] = {r.m[0][0], r.m[1][0], r.m[2][0]}, b[3] = {r.m[0][1], r.m[1][1], r.m[2][1]};
    const double la = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    for (double &x : a) x /= la;
    const double d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    for (int i = 0; i < 3; ++i) b[i] -= d * a[i];
    const double lb = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
    for (double &x : b) x /= lb;
    const double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    for (int i = 0; i < 3; ++i) r.m[i][0] = a[i], r.m[i][1] = b[i], r.m[i][2] = c[i];
}

}  // namespace

Mat3 rest_pose(int number) {
    // body x up (the number faces the viewer), body z (text up, stripe axis)
    // towards the top of the screen, then a small per-ball tilt and turn
    const Mat3 up = {{{0, 1, 0}, {0, 0, 1}, {1, 0, 0}}};
    const double turn = 0.35 * std::sin(number * 2.4), tilt = 0.22 + 0.12 * std::sin(number * 1.7);
    const double axis = number * 1.3;
    return multiply(rotation(std::cos(axis), std::sin(axis), 0, tilt), multiply(rotation(0, 0, 1, turn), up));
}

void BallPoses::reset(const std::vector<Ball> &balls) {
    poses_.clear();
    for (const Ball &b : balls) poses_.push_back(rest_pose(b.number));
}

void BallPoses::advance(const std::vector<Ball> &balls, double dt) {
    if (poses_.size() != balls.size()) reset(balls);
    for (size_t i = 0; i < balls.size(); ++i) {
        if (!balls[i].active) continue;
        const Ball &b = balls[i];
        const double rate = std::sqrt(b.wx * b.wx + b.wy * b.wy + b.wz * b.wz);
        if (rate * dt < 1e-9) continue;
        poses_[i] = multiply(rotation(b.wx / rate, b.wy / rate, b.wz / rate, rate * dt), poses_[i]);
        orthonormalise(poses_[i]);
    }
}

Mat3 BallPoses::pose(size_t i) const { return i < poses_.size() ? poses_[i] : rest_pose(0); }

void draw_ball(Canvas &canvas, float cx, float cy, float radius, int number, const Mat3 &pose) {
    static const Light light;
    const Label label(number, radius);
    const int x0 = static_cast<int>(std::floor(cx - radius)), x1 = static_cast<int>(std::ceil(cx + radius));
    const int y0 = static_cast<int>(std::floor(cy - radius)), y1 = static_cast<int>(std::ceil(cy + radius));
    constexpr int kSub = 3;
    for (int py = y0; py <= y1; ++py)
        for (int px = x0; px <= x1; ++px) {
            Colour sum{0, 0, 0};
            int covered = 0;
            for (int k = 0; k < kSub * kSub; ++k) {
                const double sx = (px + (k % kSub + 0.5) / kSub - cx) / radius;
                const double sy = (py + (k / kSub + 0.5) / kSub - cy) / radius;  // NOLINT(bugprone-integer-division)
                const double r2 = sx * sx + sy * sy;
                if (r2 >= 1) continue;
                const double nx = sx, ny = -sy, nz = std::sqrt(1 - r2);
                // q = R^T n
                const double qx = pose.m[0][0] * nx + pose.m[1][0] * ny + pose.m[2][0] * nz;
                const double qy = pose.m[0][1] * nx + pose.m[1][1] * ny + pose.m[2][1] * nz;
                const double qz = pose.m[0][2] * nx + pose.m[1][2] * ny + pose.m[2][2] * nz;
                const Colour base = surface(number, label, qx, qy, qz);
                const double diffuse = std::max(0.0, nx * light.lx + ny * light.ly + nz * light.lz);
                const double nh = std::max(0.0, nx * light.hx + ny * light.hy + nz * light.hz);
                const double nh2 = nh * nh, nh4 = nh2 * nh2, nh8 = nh4 * nh4, nh16 = nh8 * nh8;
                const double spec = 0.7 * nh16 * nh16 * nh16 * nh8 * nh4 + 0.06 * nh4 * nh2;  // nh^60, nh^6
                const float lit = static_cast<float>(0.3 + 0.78 * diffuse), shine = static_cast<float>(spec);
                sum = {sum.r + std::min(1.0f, base.r * lit + shine), sum.g + std::min(1.0f, base.g * lit + shine),
                       sum.b + std::min(1.0f, base.b * lit + shine)};
                ++covered;
            }
            if (covered == 0) continue;
            const float n = static_cast<float>(covered);
            canvas.blend(px, py, {sum.r / n, sum.g / n, sum.b / n}, n / (kSub * kSub));
        }
}

void draw_falling(Canvas &canvas, const View &view, double x, double y, double hx, double hy, int number,
                  const Mat3 &pose, double progress) {
    const double t = std::clamp(progress, 0.0, 1.0);
    const float cx = view.px(x + (hx - x) * 0.6 * t), cy = view.py(y + (hy - y) * 0.6 * t);
    const float radius = view.length(kBallRadius) * static_cast<float>(1 - 0.35 * t);
    draw_ball(canvas, cx, cy, radius, number, pose);
    canvas.fill_disk(cx, cy, radius + 0.5f, {0, 0, 0}, static_cast<float>(0.9 * t));
}

void draw_balls(Canvas &canvas, const View &view, const std::vector<Ball> &balls, const BallPoses &poses) {
    const float radius = view.length(kBallRadius);
    for (const Ball &b : balls)
        if (b.active) canvas.soft_disk(view.px(b.x) + 0.3f * radius, view.py(b.y) + 0.35f * radius, 1.35f * radius, {0, 0, 0}, 0.5f);
    for (size_t i = 0; i < balls.size(); ++i)
        if (balls[i].active) draw_ball(canvas, view.px(balls[i].x), view.py(balls[i].y), radius, balls[i].number, poses.pose(i));
}

void draw_gas(Canvas &canvas, const View &view, const std::vector<Ball> &balls, double mean_speed) {
    const float radius = std::max(1.0f, view.length(kBallRadius));
    const double scale = std::max(1e-12, 2 * mean_speed);
    for (const Ball &b : balls) {
        if (!b.active) continue;
        const float f = static_cast<float>(std::min(1.0, std::hypot(b.vx, b.vy) / scale));
        canvas.fill_disk(view.px(b.x), view.py(b.y), radius, {0.24f + 0.76f * f, 0.47f + 0.24f * (1 - f), 1 - f});
    }
}

}  // namespace demo
