/* SPDX-License-Identifier: MIT */
// check.h - the demo's C++ tests' tally (test_physics, test_game): each
// check prints "ok - WHAT" or "FAIL - WHAT" and counts; a test's main ends
// with check_summary("NAME"), which prints "NAME: N passed, M failed" (the
// project's tally line, tests/harness/tally.sh) and returns the exit status.
#ifndef C2D_DEMO_TESTS_CHECK_H
#define C2D_DEMO_TESTS_CHECK_H

#include <cstdio>
#include <string>

namespace demo_tests {

inline int &passed() {
    static int n = 0;
    return n;
}

inline int &failed() {
    static int n = 0;
    return n;
}

inline void check(bool ok, const std::string &what) {
    std::printf("%s - %s\n", ok ? "ok" : "FAIL", what.c_str());
    (ok ? passed() : failed()) += 1;
}

inline int check_summary(const char *name) {
    std::printf("%s: %d passed, %d failed\n", name, passed(), failed());
    return failed() == 0 ? 0 : 1;
}

}  // namespace demo_tests

#endif
