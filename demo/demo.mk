# SPDX-License-Identifier: MIT
# demo/demo.mk - the billiards demo, included by the top-level Makefile.
#   make demo        install deps, build $(B)/billiards, run the headless break,
#                    print a summary, write $(B)/billiards.png
#   make play        build and open the window
#   make test-demo   the demo's tests (part of `make test`)
#   make demo-plots  regenerate docs/energy.png, docs/gas_histogram.png,
#                    docs/shot_path.png
# Screenshots are compressed PNGs written with libpng (demo/app/png.cpp); the
# tests' checker reads them back with libpng's reader.
#
# The layers, each its own target, each using only the ones above it here:
#   demo/pool/   the simulation: table, ball motion, engines, checker, the run
#                and the shot seam; no SDL           -> $(B)/demo/libpool.a
#   demo/game/   8-ball: rules, the computer opponent, a match; no SDL
#                                                    -> $(B)/demo/libgame.a
#   demo/app/    the program: command line, headless runner, the window and
#                its drawing, aiming aids, panel, sound, PNG -> $(B)/billiards
#   demo/tests/  test_physics (pool), test_game (game), test_det_math
#                (pool/det_math.h's accuracy), check.h (their tally), test_demo.sh (the program, and the layering),
#                png_check
#                opponent_bench (the opponent's time per turn; not a test)
#   demo/tools/  plots.sh (make demo-plots)
# Includes name their layer (-Idemo: #include "pool/sim.h"), so a layer's
# dependencies show in its include lines; test_demo.sh checks them.  Header
# dependencies come from the compiler (-MMD -MP, the .d files next to the
# objects).

DEMO_DEPS := libbox2d-dev libsdl2-dev libpng-dev
DEMO_TEST_DEPS := xvfb xauth libpng-dev
DEMO_PLOT_DEPS := gnuplot-nox

DEMO_POOL_SRC := $(wildcard demo/pool/*.cpp)
DEMO_GAME_SRC := $(wildcard demo/game/*.cpp)
DEMO_APP_SRC := $(wildcard demo/app/*.cpp)
DEMO_POOL_OBJ := $(patsubst demo/%.cpp,$(B)/demo/%.o,$(DEMO_POOL_SRC))
DEMO_GAME_OBJ := $(patsubst demo/%.cpp,$(B)/demo/%.o,$(DEMO_GAME_SRC))
DEMO_APP_OBJ := $(patsubst demo/%.cpp,$(B)/demo/%.o,$(DEMO_APP_SRC))
DEMO_TEST_OBJ := $(B)/demo/tests/test_physics.o $(B)/demo/tests/test_game.o $(B)/demo/tests/png_check.o \
                 $(B)/demo/tests/opponent_bench.o $(B)/demo/tests/test_det_math.o
DEMO_POOL_LIB := $(B)/demo/libpool.a
DEMO_GAME_LIB := $(B)/demo/libgame.a
DEMO_BIN := $(B)/billiards
DEMO_CXXFLAGS = $(CXXFLAGS) -std=c++17 -Wall -Wextra -ffp-contract=off -Iinclude -Idemo $(SAN_FLAGS) -MMD -MP

.PHONY: demo-deps demo-test-deps demo-plots test-demo

demo-deps:
	@sh scripts/deps.sh $(DEMO_DEPS)

demo-test-deps: demo-deps
	@sh scripts/deps.sh $(DEMO_TEST_DEPS)

# pool/ and game/ are compiled without SDL's flags
$(B)/demo/pool/%.o: demo/pool/%.cpp | demo-deps
	@mkdir -p $(@D)
	$(CXX) $(DEMO_CXXFLAGS) -c $< -o $@

$(B)/demo/game/%.o: demo/game/%.cpp | demo-deps
	@mkdir -p $(@D)
	$(CXX) $(DEMO_CXXFLAGS) -c $< -o $@

# sdl2-config runs in the recipe, after demo-deps has installed it
$(B)/demo/app/%.o: demo/app/%.cpp | demo-deps
	@mkdir -p $(@D)
	$(CXX) $(DEMO_CXXFLAGS) $$(sdl2-config --cflags) -c $< -o $@

$(B)/demo/tests/%.o: demo/tests/%.cpp | demo-test-deps
	@mkdir -p $(@D)
	$(CXX) $(DEMO_CXXFLAGS) -c $< -o $@

$(DEMO_POOL_LIB): $(DEMO_POOL_OBJ)
	@rm -f $@
	$(AR) rcs $@ $^

$(DEMO_GAME_LIB): $(DEMO_GAME_OBJ)
	@rm -f $@
	$(AR) rcs $@ $^

$(DEMO_BIN): $(DEMO_APP_OBJ) $(DEMO_GAME_LIB) $(DEMO_POOL_LIB) $(STATIC)
	$(CXX) $(CXXFLAGS) $(SAN_FLAGS) -o $@ $^ -lbox2d $$(sdl2-config --libs) -lpng -lm

demo: $(DEMO_BIN)
	$(DEMO_BIN) --headless --screenshot $(B)/billiards.png
	@echo "table picture: $(B)/billiards.png"

play: $(DEMO_BIN)
	$(DEMO_BIN)

$(B)/png_check: $(B)/demo/tests/png_check.o
	$(CXX) $(CXXFLAGS) $(SAN_FLAGS) -o $@ $^ -lpng

# The pool model against the textbook laws, and 1,000 random shots
$(B)/test_physics: $(B)/demo/tests/test_physics.o $(DEMO_POOL_LIB) $(STATIC)
	$(CXX) $(CXXFLAGS) $(SAN_FLAGS) -o $@ $^ -lbox2d -lm

# The simulation's own sin, cos, atan2, hypot ... (pool/det_math.h) against
# glibc's on 10^6 inputs each: their stated accuracy
$(B)/test_det_math: $(B)/demo/tests/test_det_math.o $(DEMO_POOL_LIB)
	$(CXX) $(CXXFLAGS) $(SAN_FLAGS) -o $@ $^ -lm

# 8-ball: the rules on constructed shots, and computer-versus-computer games
$(B)/test_game: $(B)/demo/tests/test_game.o $(DEMO_GAME_LIB) $(DEMO_POOL_LIB) $(STATIC)
	$(CXX) $(CXXFLAGS) $(SAN_FLAGS) -o $@ $^ -lbox2d -lm

# The opponent's thinking time per turn (CPU medians, a digest of the shots
# chosen); a measurement, not a test: demo/tests/opponent_bench.cpp
$(B)/opponent_bench: $(B)/demo/tests/opponent_bench.o $(DEMO_GAME_LIB) $(DEMO_POOL_LIB) $(STATIC)
	$(CXX) $(CXXFLAGS) $(SAN_FLAGS) -o $@ $^ -lbox2d -lm

test-demo: $(DEMO_BIN) $(B)/png_check $(B)/test_det_math $(B)/test_physics $(B)/test_game | demo-test-deps
	$(B)/test_det_math
	$(B)/test_physics
	$(B)/test_game
	sh demo/tests/test_demo.sh $(DEMO_BIN) $(B)/png_check

demo-plots: $(DEMO_BIN)
	@sh scripts/deps.sh $(DEMO_PLOT_DEPS)
	sh demo/tools/plots.sh $(DEMO_BIN) docs

-include $(patsubst %.o,%.d,$(DEMO_POOL_OBJ) $(DEMO_GAME_OBJ) $(DEMO_APP_OBJ) $(DEMO_TEST_OBJ))

TEST_TARGETS += test-demo
