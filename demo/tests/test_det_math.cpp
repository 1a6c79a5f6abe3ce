/* SPDX-License-Identifier: MIT */
// test_det_math.cpp - the simulation's own elementary functions
// (pool/det_math.h) against glibc's: the largest distance in ulps over 10^6
// inputs per function and range, asserted within the header's bound against
// the exact value plus one ulp (glibc's own error for these functions is
// below one ulp: the glibc manual's table of errors for x86-64), and the
// special values of C's definitions.  The inputs come from a fixed seed, so a
// run is reproducible; the distances it prints are the accuracy measured.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <random>

#include "pool/det_math.h"
#include "tests/check.h"

using demo_tests::check;

namespace {

using demo::kPi;

// IEEE doubles as integers in the order of their values: the distance of two
// finite doubles in ulps (units in the last place of the smaller binade).
int64_t ordered(double x) {
    int64_t i;
    std::memcpy(&i, &x, sizeof i);
    return i < 0 ? INT64_MIN - i : i;
}
uint64_t ulps(double a, double b) {
    if (a != a || b != b) return (a != a && b != b) ? 0 : UINT64_MAX;
    const int64_t d = ordered(a) - ordered(b);
    return static_cast<uint64_t>(d < 0 ? -d : d);
}

// a double with a uniformly chosen sign and exponent in [lo, hi] and a uniform
// significand: every scale of the range is tried alike
struct Draw {
    std::mt19937_64 rng{20261203};  // NOLINT(cert-msc32-c,cert-msc51-cpp): the same inputs every run
    double scaled(int lo, int hi, bool any_sign = true) {
        std::uniform_int_distribution<int> e(lo, hi);
        std::uniform_real_distribution<double> m(1.0, 2.0);
        const double v = std::ldexp(m(rng), e(rng));
        return any_sign && (rng() & 1) ? -v : v;
    }
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
};

constexpr int kCount = 1000000;

// The largest distance of f from g over kCount inputs from draw(), asserted
// <= bound + 1 (bound: the function's error against the exact value).
void compare(const char *what, uint64_t bound, const std::function<double()> &draw,
             const std::function<double(double)> &f, const std::function<double(double)> &g) {
    uint64_t worst = 0;
    double at = 0;
    for (int i = 0; i < kCount; ++i) {
        const double x = draw();
        const uint64_t d = ulps(f(x), g(x));
        if (d > worst) worst = d, at = x;
    }
    std::printf("  %-34s max %llu ulp from glibc (at %.17g)\n", what, static_cast<unsigned long long>(worst), at);
    check(worst <= bound + 1, what);
}

void compare2(const char *what, uint64_t bound, const std::function<double()> &draw,
              const std::function<double(double, double)> &f, const std::function<double(double, double)> &g) {
    uint64_t worst = 0;
    double at_y = 0, at_x = 0;
    for (int i = 0; i < kCount; ++i) {
        const double y = draw(), x = draw();
        const uint64_t d = ulps(f(y, x), g(y, x));
        if (d > worst) worst = d, at_y = y, at_x = x;
    }
    std::printf("  %-34s max %llu ulp from glibc (at %.17g, %.17g)\n", what, static_cast<unsigned long long>(worst), at_y, at_x);
    check(worst <= bound + 1, what);
}

bool same(double a, double b) {
    uint64_t ua = 0, ub = 0;
    std::memcpy(&ua, &a, sizeof a);
    std::memcpy(&ub, &b, sizeof b);
    return ua == ub;
}

}  // namespace

int main() {
    Draw d;
    // the bounds against the exact value, as det_math.h states them
    compare("sin, |x| in [2^-30, 2^20]", 1, [&] { return d.scaled(-30, 20); }, demo::det_sin, [](double x) { return std::sin(x); });
    compare("sin, x in [-2pi, 2pi]", 1, [&] { return d.uniform(-2 * kPi, 2 * kPi); }, demo::det_sin, [](double x) { return std::sin(x); });
    compare("cos, |x| in [2^-30, 2^20]", 1, [&] { return d.scaled(-30, 20); }, demo::det_cos, [](double x) { return std::cos(x); });
    compare("cos, x in [-2pi, 2pi]", 1, [&] { return d.uniform(-2 * kPi, 2 * kPi); }, demo::det_cos, [](double x) { return std::cos(x); });
    compare("tan, x in [-pi/2, pi/2]", 5, [&] { return d.uniform(-kPi / 2, kPi / 2); }, demo::det_tan, [](double x) { return std::tan(x); });
    compare("atan, |x| in [2^-40, 2^70]", 1, [&] { return d.scaled(-40, 70); }, demo::det_atan, [](double x) { return std::atan(x); });
    compare("asin, x in [-1, 1]", 6, [&] { return d.uniform(-1, 1); }, demo::det_asin, [](double x) { return std::asin(x); });
    compare("asin, |x| in [2^-30, 1)", 6, [&] { return d.scaled(-30, -1); }, demo::det_asin, [](double x) { return std::asin(x); });
    compare("acos, x in [-1, 1]", 6, [&] { return d.uniform(-1, 1); }, demo::det_acos, [](double x) { return std::acos(x); });
    compare("acos, 1 - x, x in [2^-40, 1/2]", 6, [&] { return 1 - d.scaled(-40, -2, false); }, demo::det_acos,
            [](double x) { return std::acos(x); });
    compare2("atan2, |y|, |x| in [2^-20, 2^20]", 3, [&] { return d.scaled(-20, 20); }, demo::det_atan2,
             [](double y, double x) { return std::atan2(y, x); });
    compare2("hypot, |x|, |y| in [2^-30, 2^30]", 2, [&] { return d.scaled(-30, 30); }, demo::det_hypot,
             [](double x, double y) { return std::hypot(x, y); });
    compare2("hypot, |x|, |y| in [2^-1070, 2^1020]", 2, [&] { return d.scaled(-1070, 1020); }, demo::det_hypot,
             [](double x, double y) { return std::hypot(x, y); });

    // special values, as C defines them
    const double inf = INFINITY, nan = NAN;
    check(same(demo::det_sin(-0.0), -0.0) && same(demo::det_sin(0.0), 0.0), "sin(+-0) = +-0");
    check(demo::det_cos(0.0) == 1 && demo::det_sin(inf) != demo::det_sin(inf), "cos(0) = 1, sin(inf) is NaN");
    check(same(demo::det_atan2(0.0, 1.0), 0.0) && same(demo::det_atan2(-0.0, 1.0), -0.0), "atan2(+-0, 1) = +-0");
    check(demo::det_atan2(0.0, -1.0) == kPi && demo::det_atan2(-0.0, -0.0) == -kPi, "atan2(+-0, x<0 or -0) = +-pi");
    check(demo::det_atan2(1.0, 0.0) == kPi / 2 && demo::det_atan2(-1.0, -0.0) == -kPi / 2, "atan2(y, +-0) = +-pi/2");
    check(demo::det_atan2(inf, -inf) == 3 * kPi / 4 && demo::det_atan2(-1.0, inf) == 0, "atan2 at infinities");
    check(demo::det_atan(inf) == kPi / 2 && demo::det_atan(-inf) == -kPi / 2, "atan(+-inf) = +-pi/2");
    check(demo::det_acos(1.0) == 0 && demo::det_acos(-1.0) == kPi && demo::det_asin(1.0) == kPi / 2, "acos(+-1), asin(1)");
    check(demo::det_asin(1.5) != demo::det_asin(1.5), "asin outside [-1, 1] is NaN");
    check(demo::det_hypot(3, 4) == 5 && demo::det_hypot(-inf, nan) == inf && demo::det_hypot(0, -0.0) == 0, "hypot(3, 4), inf, 0");
    check(demo::det_hypot(1e300, 1e300) == std::hypot(1e300, 1e300) && demo::det_hypot(3e-320, 4e-320) == 5e-320,
            "hypot without overflow or underflow");
    return demo_tests::check_summary("test_det_math");
}
