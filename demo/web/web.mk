# SPDX-License-Identifier: MIT
# demo/web/web.mk - the billiards game in the browser, included by the
# top-level Makefile (docs/WEB.md).
#   make web        build build/web/index.html (+ index.js, index.wasm): the
#                   game, compiled with emscripten from Debian's packages
#   make web-open   build it, serve it on 127.0.0.1:8024 and print the address
#   make test-web   build it, drive it in headless Chromium (demo/web/test_web.py)
#                   and check the same bits natively, in the browser and on
#                   aarch64 under qemu-user (demo/web/same_bits.sh)
# Offline once the packages are in: emscripten 3.1.6 ships its system
# libraries prebuilt; SDL2 and Box2D come from Debian's source packages
# (scripts/deb_source.sh, a private source list under build/web/src/apt) and
# are compiled once into build/web/sdl2 and build/web/box2d, so a second build
# compiles only the game.  emscripten's own SDL2 port would download SDL from
# GitHub: instead the same port's file list (emscripten's tools/ports/sdl2.py,
# written for SDL 2.0.20) is compiled from Debian's SDL 2.26 with the files
# added since (WEB_SDL_FILES).
# The installed node is not Debian's, so emcc is told where Debian's node
# modules are (NODE_PATH).

WEB_B := build/web
WEB_SRC := $(WEB_B)/src
WEB_DEPS := emscripten binaryen dpkg-dev
WEB_TEST_DEPS := chromium chromium-driver python3-selenium qemu-user g++-aarch64-linux-gnu
WEB_ENV := NODE_PATH=/usr/share/nodejs
WEB_SDL_LIB := $(WEB_B)/sdl2/libSDL2.a
WEB_BOX2D_LIB := $(WEB_B)/box2d/libbox2d.a
WEB_SDL_INC := $(WEB_SRC)/libsdl2/include
WEB_BOX2D_INC := $(WEB_SRC)/box2d/include

# emscripten's SDL2 port list (3.1.6), then the files SDL added after 2.0.20
WEB_SDL_FILES := SDL.c SDL_assert.c SDL_dataqueue.c SDL_error.c SDL_hints.c SDL_log.c atomic/SDL_atomic.c \
  atomic/SDL_spinlock.c audio/SDL_audio.c audio/SDL_audiocvt.c audio/SDL_audiodev.c \
  audio/SDL_audiotypecvt.c audio/SDL_mixer.c audio/SDL_wave.c cpuinfo/SDL_cpuinfo.c \
  dynapi/SDL_dynapi.c events/SDL_clipboardevents.c events/SDL_displayevents.c events/SDL_dropevents.c \
  events/SDL_events.c events/SDL_gesture.c events/SDL_keyboard.c events/SDL_mouse.c events/SDL_quit.c \
  events/SDL_touch.c events/SDL_windowevents.c file/SDL_rwops.c haptic/SDL_haptic.c \
  joystick/SDL_gamecontroller.c joystick/SDL_joystick.c power/SDL_power.c render/SDL_d3dmath.c \
  render/SDL_render.c render/SDL_yuv_sw.c render/direct3d/SDL_render_d3d.c render/direct3d11/SDL_render_d3d11.c \
  render/opengl/SDL_render_gl.c render/opengl/SDL_shaders_gl.c render/opengles/SDL_render_gles.c \
  render/opengles2/SDL_render_gles2.c render/opengles2/SDL_shaders_gles2.c \
  render/psp/SDL_render_psp.c render/software/SDL_blendfillrect.c render/software/SDL_blendline.c \
  render/software/SDL_blendpoint.c render/software/SDL_drawline.c render/software/SDL_drawpoint.c \
  render/software/SDL_render_sw.c render/software/SDL_rotate.c render/software/SDL_triangle.c \
  sensor/SDL_sensor.c sensor/dummy/SDL_dummysensor.c \
  stdlib/SDL_crc32.c stdlib/SDL_getenv.c stdlib/SDL_iconv.c stdlib/SDL_malloc.c stdlib/SDL_qsort.c \
  stdlib/SDL_stdlib.c stdlib/SDL_string.c stdlib/SDL_strtokr.c thread/SDL_thread.c timer/SDL_timer.c \
  video/SDL_RLEaccel.c video/SDL_blit.c video/SDL_blit_0.c video/SDL_blit_1.c video/SDL_blit_A.c \
  video/SDL_blit_N.c video/SDL_blit_auto.c video/SDL_blit_copy.c video/SDL_blit_slow.c \
  video/SDL_bmp.c video/SDL_clipboard.c video/SDL_egl.c video/SDL_fillrect.c video/SDL_pixels.c \
  video/SDL_rect.c video/SDL_shape.c video/SDL_stretch.c video/SDL_surface.c video/SDL_video.c \
  video/SDL_yuv.c video/emscripten/SDL_emscriptenevents.c \
  video/emscripten/SDL_emscriptenframebuffer.c video/emscripten/SDL_emscriptenmouse.c \
  video/emscripten/SDL_emscriptenopengles.c video/emscripten/SDL_emscriptenvideo.c \
  audio/emscripten/SDL_emscriptenaudio.c video/dummy/SDL_nullevents.c \
  video/dummy/SDL_nullframebuffer.c video/dummy/SDL_nullvideo.c video/yuv2rgb/yuv_rgb.c \
  audio/disk/SDL_diskaudio.c audio/dummy/SDL_dummyaudio.c loadso/dlopen/SDL_sysloadso.c \
  power/emscripten/SDL_syspower.c joystick/emscripten/SDL_sysjoystick.c \
  filesystem/emscripten/SDL_sysfilesystem.c timer/unix/SDL_systimer.c haptic/dummy/SDL_syshaptic.c \
  main/dummy/SDL_dummy_main.c locale/SDL_locale.c locale/emscripten/SDL_syslocale.c misc/SDL_url.c \
  misc/dummy/SDL_sysurl.c \
  thread/generic/SDL_syscond.c thread/generic/SDL_sysmutex.c thread/generic/SDL_syssem.c \
  thread/generic/SDL_systhread.c thread/generic/SDL_systls.c \
  SDL_guid.c SDL_list.c SDL_utils.c events/SDL_keysym_to_scancode.c events/SDL_scancode_tables.c \
  joystick/controller_type.c stdlib/SDL_crc16.c

.PHONY: web web-deps web-test-deps web-open test-web web-sources

web-deps:
	@sh scripts/deps.sh $(WEB_DEPS)

web-test-deps: web-deps
	@sh scripts/deps.sh $(WEB_TEST_DEPS)

# the unpacked sources (a symlink per package), fetched once (one stamp, so
# that make -j runs the fetch once)
$(WEB_SRC)/fetched: | web-deps
	sh scripts/deb_source.sh $(WEB_SRC) libsdl2 box2d
	@touch $@
web-sources: $(WEB_SRC)/fetched

$(WEB_SDL_LIB): $(WEB_SRC)/fetched | web-deps
	$(WEB_ENV) sh scripts/emlib.sh $@ $(WEB_SRC)/libsdl2/src "-O2 -w -I$(CURDIR)/$(WEB_SDL_INC)" $(WEB_SDL_FILES)

# Box2D 2.4.1: every source, as Debian's CMake build compiles them
$(WEB_BOX2D_LIB): $(WEB_SRC)/fetched | web-deps
	$(WEB_ENV) sh scripts/emlib.sh $@ $(WEB_SRC)/box2d/src "-O2 -std=c++11 -w -I$(CURDIR)/$(WEB_BOX2D_INC) -I$(CURDIR)/$(WEB_SRC)/box2d/src" \
	  $$(cd $(WEB_SRC)/box2d/src && find . -name '*.cpp' | sed 's|^\./||' | LC_ALL=C sort)

# The game: the library, demo/pool, demo/game, demo/app (but its libpng
# writer: demo/web/png_stored.cpp instead) and the page's hook
WEB_LIB_OBJ := $(patsubst lib/%.c,$(WEB_B)/obj/%.o,$(LIB_SRC))
WEB_DEMO_SRC := $(DEMO_POOL_SRC) $(DEMO_GAME_SRC) $(filter-out demo/app/png.cpp,$(DEMO_APP_SRC)) \
                demo/web/hook.cpp demo/web/png_stored.cpp
WEB_DEMO_OBJ := $(patsubst demo/%.cpp,$(WEB_B)/demo/%.o,$(WEB_DEMO_SRC))
WEB_CFLAGS := -O2 -std=c99 -Wall -Wextra -ffp-contract=off -fno-math-errno -Iinclude
WEB_CXXFLAGS := -O2 -std=c++17 -Wall -Wextra -ffp-contract=off -Iinclude -Idemo -I$(WEB_SDL_INC) -I$(WEB_BOX2D_INC)
# the port's link settings (the audio's resume on a click, SDL's callbacks),
# memory that grows with the table, and what the page's hook calls (the
# page is not minified: Debian's emcc calls htmlmin wrongly)
WEB_LDFLAGS := -O2 -sALLOW_MEMORY_GROWTH=1 -sMINIFY_HTML=0 \
  "-sDEFAULT_LIBRARY_FUNCS_TO_INCLUDE=['\$$autoResumeAudioContext','\$$dynCall']" \
  "-sEXPORTED_RUNTIME_METHODS=['ENV','cwrap','UTF8ToString']" \
  "-sEXPORTED_FUNCTIONS=['_main','_c2d_web_state','_c2d_web_shoot','_c2d_web_at_rest','_c2d_web_frames']" \
  --shell-file demo/web/shell.html

$(WEB_B)/obj/%.o: lib/%.c | web-deps
	@mkdir -p $(@D)
	$(WEB_ENV) nice emcc $(WEB_CFLAGS) -MMD -MP -c $< -o $@

$(WEB_B)/demo/%.o: demo/%.cpp | web-deps web-sources
	@mkdir -p $(@D)
	$(WEB_ENV) nice em++ $(WEB_CXXFLAGS) -MMD -MP -c $< -o $@

$(WEB_B)/index.html: $(WEB_DEMO_OBJ) $(WEB_LIB_OBJ) $(WEB_SDL_LIB) $(WEB_BOX2D_LIB) demo/web/shell.html
	$(WEB_ENV) nice em++ -o $@ $(WEB_DEMO_OBJ) $(WEB_LIB_OBJ) $(WEB_BOX2D_LIB) $(WEB_SDL_LIB) $(WEB_LDFLAGS) || { rm -f $@; exit 1; }

web: $(WEB_B)/index.html
	@echo "web: $(WEB_B)/index.html (+ index.js, index.wasm); make web-open serves it"

web-open: web
	@echo "open http://127.0.0.1:8024/index.html (?practice: practice on the --seed 1 rack); Ctrl-C stops"
	cd $(WEB_B) && python3 -m http.server 8024 --bind 127.0.0.1

-include $(patsubst %.o,%.d,$(WEB_DEMO_OBJ) $(WEB_LIB_OBJ))

# --- the same bits natively, in the browser and on aarch64 (qemu-user): the
# simulation alone (demo/web/same_bits.cpp over demo/pool and the library),
# built for this machine and cross-compiled for aarch64 (static, run under
# qemu-aarch64), Box2D for aarch64 compiled once from the same sources
WEB_A64 := $(WEB_B)/aarch64
WEB_A64_CC := aarch64-linux-gnu-gcc
WEB_A64_CXX := aarch64-linux-gnu-g++
WEB_A64_BOX2D := $(WEB_A64)/box2d/libbox2d.a
WEB_A64_OBJ := $(patsubst lib/%.c,$(WEB_A64)/obj/%.o,$(LIB_SRC)) \
               $(patsubst demo/%.cpp,$(WEB_A64)/demo/%.o,$(DEMO_POOL_SRC) demo/web/same_bits.cpp)

$(WEB_A64_BOX2D): $(WEB_SRC)/fetched | web-test-deps
	EMLIB_CXX=$(WEB_A64_CXX) EMLIB_AR=aarch64-linux-gnu-ar sh scripts/emlib.sh $@ $(WEB_SRC)/box2d/src \
	  "-O2 -std=c++11 -w -I$(CURDIR)/$(WEB_BOX2D_INC) -I$(CURDIR)/$(WEB_SRC)/box2d/src" \
	  $$(cd $(WEB_SRC)/box2d/src && find . -name '*.cpp' | sed 's|^\./||' | LC_ALL=C sort)

$(WEB_A64)/obj/%.o: lib/%.c | web-test-deps
	@mkdir -p $(@D)
	nice $(WEB_A64_CC) $(CFLAGS) $(REQ_CFLAGS) -MMD -MP -c $< -o $@

$(WEB_A64)/demo/%.o: demo/%.cpp | web-test-deps web-sources
	@mkdir -p $(@D)
	nice $(WEB_A64_CXX) -O2 -std=c++17 -Wall -Wextra -ffp-contract=off -Iinclude -Idemo -I$(WEB_BOX2D_INC) -MMD -MP -c $< -o $@

$(WEB_A64)/same_bits: $(WEB_A64_OBJ) $(WEB_A64_BOX2D)
	$(WEB_A64_CXX) -static -o $@ $^ -lm

$(B)/same_bits: $(B)/demo/web/same_bits.o $(DEMO_POOL_LIB) $(STATIC)
	$(CXX) $(CXXFLAGS) $(SAN_FLAGS) -o $@ $^ -lbox2d -lm

$(B)/demo/web/same_bits.o: demo/web/same_bits.cpp | demo-deps
	@mkdir -p $(@D)
	$(CXX) $(DEMO_CXXFLAGS) -c $< -o $@

# Everything the browser test and the bit-identity check run: the page, the
# native game and driver, the aarch64 driver
test-web: $(WEB_B)/index.html $(DEMO_BIN) $(B)/same_bits $(WEB_A64)/same_bits | web-test-deps
	sh demo/web/same_bits.sh $(DEMO_BIN) $(B)/same_bits $(WEB_A64)/same_bits
	/usr/bin/python3 demo/web/test_web.py $(WEB_B) $(DEMO_BIN) $(B)/same_bits

-include $(patsubst %.o,%.d,$(WEB_A64_OBJ))
