/* SPDX-License-Identifier: MIT */
/* callgrind.h - callgrind's client requests where valgrind's header is
 * installed, no-ops elsewhere (the bench then builds without valgrind). */
#ifndef C2D_BENCH_CALLGRIND_H
#define C2D_BENCH_CALLGRIND_H
#if defined(__has_include)
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#endif
#endif
#ifndef CALLGRIND_ZERO_STATS
#define CALLGRIND_ZERO_STATS
#define CALLGRIND_DUMP_STATS_AT(name) ((void)(name))
#endif
#endif
