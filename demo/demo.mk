# SPDX-License-Identifier: MIT
# demo/demo.mk - the billiards demo, included by the top-level Makefile.
#   make demo        install deps, build $(B)/billiards, run the headless break,
#                    print a summary, write $(B)/billiards.png
#   make play        build and open the window
#   make test-demo   the demo's tests (part of `make test`)
#   make demo-plots  regenerate docs/energy.png, docs/gas_histogram.png,
#                    docs/shot_path.png
# Screenshots are compressed PNGs written with libpng (demo/png.cpp); the
# tests' checker reads them back with libpng's reader.

DEMO_DEPS := libbox2d-dev libsdl2-dev
DEMO_TEST_DEPS := xvfb xauth libpng-dev
DEMO_PLOT_DEPS := gnuplot-nox
# the simulation (no SDL): scene, table, ball motion, engines, checker, the
# run and the shot seam; test_physics links these alone
DEMO_SIM_SRC := demo/scene.cpp demo/table.cpp demo/motion.cpp demo/exact_engine.cpp demo/broadphase.cpp demo/slow_contact.cpp demo/box2d_engine.cpp demo/checker.cpp demo/sim.cpp demo/cradle.cpp
# 8-ball: rules, the computer opponent, a headless game (issue 11, part C)
DEMO_SIM_SRC += demo/rules.cpp demo/opponent.cpp demo/game.cpp
DEMO_SRC := demo/main.cpp demo/cli.cpp $(DEMO_SIM_SRC) demo/render.cpp demo/png.cpp
DEMO_HDR := demo/cli.h demo/scene.h demo/table.h demo/motion.h demo/model.h demo/events.h demo/engine.h demo/exact_engine.h demo/broadphase.h demo/event_queue.h demo/slow_contact.h demo/box2d_engine.h demo/checker.h demo/sim.h demo/cradle.h demo/render.h demo/png.h
DEMO_HDR += demo/rules.h demo/opponent.h demo/game.h
# the window: software drawing, aiming aids, panel, sound (issue 11, part B)
DEMO_SRC += demo/canvas.cpp demo/font.cpp demo/engine_view.cpp demo/draw_table.cpp demo/draw_balls.cpp demo/aim.cpp demo/hud.cpp demo/audio.cpp
DEMO_HDR += demo/canvas.h demo/font.h demo/view.h demo/engine_view.h demo/draw_table.h demo/draw_balls.h demo/aim.h demo/hud.h demo/audio.h
DEMO_DEPS += libpng-dev
DEMO_OBJ := $(patsubst demo/%.cpp,$(B)/demo/%.o,$(DEMO_SRC))
DEMO_BIN := $(B)/billiards
DEMO_CXXFLAGS = $(CXXFLAGS) -std=c++17 -Wall -Wextra -ffp-contract=off -Iinclude $(SAN_FLAGS)

.PHONY: demo-deps demo-test-deps demo-plots test-demo

demo-deps:
	@sh scripts/deps.sh $(DEMO_DEPS)

demo-test-deps: demo-deps
	@sh scripts/deps.sh $(DEMO_TEST_DEPS)

# sdl2-config runs in the recipe, after demo-deps has installed it
$(B)/demo/%.o: demo/%.cpp $(DEMO_HDR) $(LIB_HDR) | demo-deps
	@mkdir -p $(@D)
	$(CXX) $(DEMO_CXXFLAGS) $$(sdl2-config --cflags) -c $< -o $@

$(DEMO_BIN): $(DEMO_OBJ) $(STATIC)
	$(CXX) $(CXXFLAGS) $(SAN_FLAGS) -o $@ $(DEMO_OBJ) $(STATIC) -lbox2d $$(sdl2-config --libs) -lpng -lm

demo: $(DEMO_BIN)
	$(DEMO_BIN) --headless --screenshot $(B)/billiards.png
	@echo "table picture: $(B)/billiards.png"

play: $(DEMO_BIN)
	$(DEMO_BIN)

$(B)/png_check: demo/png_check.cpp | demo-test-deps
	@mkdir -p $(@D)
	$(CXX) $(DEMO_CXXFLAGS) -o $@ $< -lpng

# The pool model against the textbook laws, and 1,000 random shots
$(B)/test_physics: demo/test_physics.cpp $(patsubst demo/%.cpp,$(B)/demo/%.o,$(DEMO_SIM_SRC)) $(STATIC) $(DEMO_HDR)
	$(CXX) $(DEMO_CXXFLAGS) -o $@ $< $(patsubst demo/%.cpp,$(B)/demo/%.o,$(DEMO_SIM_SRC)) $(STATIC) -lbox2d -lm

# 8-ball: the rules on constructed shots, and computer-versus-computer games
$(B)/test_game: demo/test_game.cpp $(patsubst demo/%.cpp,$(B)/demo/%.o,$(DEMO_SIM_SRC)) $(STATIC) $(DEMO_HDR)
	$(CXX) $(DEMO_CXXFLAGS) -o $@ $< $(patsubst demo/%.cpp,$(B)/demo/%.o,$(DEMO_SIM_SRC)) $(STATIC) -lbox2d -lm

test-demo: $(DEMO_BIN) $(B)/png_check $(B)/test_physics $(B)/test_game | demo-test-deps
	$(B)/test_physics
	$(B)/test_game
	sh demo/test_demo.sh $(DEMO_BIN) $(B)/png_check

demo-plots: $(DEMO_BIN)
	@sh scripts/deps.sh $(DEMO_PLOT_DEPS)
	sh demo/plots.sh $(DEMO_BIN) docs

TEST_TARGETS += test-demo
