# SPDX-License-Identifier: MIT
# tests/mcu/mcu.mk - the library on microcontrollers (included by Makefile).
#
#   make cross       builds lib/ with -Os -ffreestanding for Cortex-M0, M4F, M7
#                    and RV32, prints the size table (build/mcu/SIZES.md),
#                    fails if it differs from docs/SIZES.md, and fails on
#                    any outside symbol but compiler helpers and
#                    sqrt/sqrtf, on recursion or unbounded stack, on double
#                    arithmetic or a sqrtf call on M4F, and if the Q16.16 path
#                    does not link on M0 with -nostdlib -lgcc.
#   make sizes       the same build and checks; writes docs/SIZES.md.
#   make test-mcu    runs the shared test vectors (tests/vectors/vectors.c) on the
#                    four cores (plus Q16.16 alone on M0) under QEMU, each
#                    linked once against lib/ and once against the
#                    amalgamated single file (make amalgamate).
#   make lint-misra  cppcheck's MISRA C:2012 addon on lib/; deviations are
#                    in docs/MISRA.md and tests/mcu/misra.supp.
#
# Cross flags are fixed, not taken from CFLAGS: the table measures one build.
# -fno-math-errno lets sqrtf become vsqrt.f32 (sqrt vsqrt.f64 on M7): sqrt of
# a negative number never happens in the library, so errno is never needed.

MCU_B := $(B)/mcu
MCU_DIR := tests/mcu
MCU_CROSS := m0 m4f m7 rv32 m0q16
MCU_RUN := m0 m4f m7 rv32 m0q16

# One install step for every MCU target: under make -j two apt-get runs at
# once would fight over the dpkg lock.
MCU_PKGS := gcc-arm-none-eabi binutils-arm-none-eabi libnewlib-arm-none-eabi \
  gcc-riscv64-unknown-elf binutils-riscv64-unknown-elf picolibc-riscv64-unknown-elf \
  qemu-system-arm qemu-system-misc cppcheck

# The event-driven world is in every build that has double (m0, m7, rv32):
# it copies no struct whole and passes none by value (gcc -Os makes such
# copies memcpy calls on these cores; sizes.sh fails on any).
MCU_CFLAGS := -std=c99 $(WARN) -Werror -ffp-contract=off -Os -ffreestanding -fno-math-errno \
  -ffunction-sections -fdata-sections

# Per target: compiler, core flags, library options, table description,
# emulator, and the extra checks of `make cross`.
MCU_m0_CC := arm-none-eabi-gcc
MCU_m0_ARCH := -mcpu=cortex-m0 -mthumb
MCU_m0_OPTS :=
MCU_m0_DESC := Cortex-M0, soft float; double, float, Q16.16
MCU_m0_QEMU := qemu-system-arm -M microbit
MCU_m0_CHECKS := --profile c2d_collidef
MCU_m0_RAM := 16K

MCU_m4f_CC := arm-none-eabi-gcc
MCU_m4f_ARCH := -mcpu=cortex-m4 -mfloat-abi=hard -mfpu=fpv4-sp-d16
MCU_m4f_OPTS := -DC2D_NO_DOUBLE
MCU_m4f_DESC := Cortex-M4F, single-precision FPU; float, Q16.16 (C2D_NO_DOUBLE)
MCU_m4f_QEMU := qemu-system-arm -M mps2-an386
MCU_m4f_RAM := 16K
MCU_m4f_CHECKS := --forbid '^__aeabi_d' --inline sqrtf=vsqrt.f32 --profile c2d_collidef --profile library

MCU_m7_CC := arm-none-eabi-gcc
MCU_m7_ARCH := -mcpu=cortex-m7 -mfloat-abi=hard -mfpu=fpv5-d16
MCU_m7_OPTS :=
MCU_m7_DESC := Cortex-M7, double-precision FPU; double, float, Q16.16
MCU_m7_QEMU := qemu-system-arm -M mps2-an500
MCU_m7_RAM := 64K

MCU_rv32_CC := riscv64-unknown-elf-gcc
MCU_rv32_ARCH := -march=rv32imac -mabi=ilp32
MCU_rv32_OPTS :=
MCU_rv32_DESC := RV32IMAC, soft float; double, float, Q16.16
MCU_rv32_QEMU := qemu-system-riscv32 -M virt -bios none

MCU_m0q16_CC := arm-none-eabi-gcc
MCU_m0q16_ARCH := -mcpu=cortex-m0 -mthumb
MCU_m0q16_OPTS := -DC2D_NO_DOUBLE -DC2D_NO_FLOAT
MCU_m0q16_DESC := Cortex-M0, Q16.16 only (C2D_NO_DOUBLE C2D_NO_FLOAT), linked -nostdlib -lgcc
MCU_m0q16_QEMU := qemu-system-arm -M microbit
MCU_m0q16_RAM := 16K

# Only the compiler's own headers (stddef.h, stdint.h, float.h): no C
# library's.  Asked of the compiler when the recipe runs, after deps.
MCU_COMPILE = $(MCU_$*_CC) $(MCU_$*_ARCH) $(MCU_$*_OPTS) $(MCU_CFLAGS) \
  -nostdinc -isystem "$$($(MCU_$*_CC) $(MCU_$*_ARCH) -print-file-name=include)" -Iinclude \
  -Itests/harness -Itests/vectors -I$(MCU_DIR)

# The harness: main.c, the vector table and its checks (tests/vectors/), the
# shared test helper (tests/harness/), as on the host.
MCU_TEST_SRC := $(MCU_DIR)/main.c tests/vectors/vectors.c $(wildcard tests/vectors/check_*.c) tests/harness/harness.c
# Header dependencies: .d files, included at the end.  A relocatable object
# linked from several compiles has one .d per source (-MF), each naming the
# object make knows ($@, -MT).
MCU_DEPS_OF = $(DEPFLAGS) -MT $@ -MF $(basename $@).$(1).d

MCU_ARM := m0 m4f m7
# RAM: 16 KiB (the micro:bit's nRF51) where the harness fits, 64 KiB on the
# M7 (its MPS2 board has 4 MiB), where the world's hash scenes
# (tests/cross/hash_mcu.c: 22.5 KiB of world memory) run.
MCU_ARM_LINK = -nostdlib -T $(MCU_DIR)/arm.ld -Wl,--gc-sections -Wl,--defsym=__c2d_ram_size=$(MCU_$(1)_RAM)
# picolibc's semihosting crt0 and console; code and data in the virt board's RAM.
MCU_RV32_LINK := --specs=picolibc.specs --crt0=semihost --oslib=semihost -Wl,--gc-sections \
  -Wl,--defsym=__flash=0x80000000,--defsym=__flash_size=0x100000 \
  -Wl,--defsym=__ram=0x80100000,--defsym=__ram_size=0x100000

.PHONY: mcu-deps lint-misra
mcu-deps:
	@sh scripts/deps.sh $(MCU_PKGS)

# Every build step waits for the install (order-only: no rebuilds), and all
# of them are prerequisites in this one make, so -j never builds a file twice.
# The size table and call graph come from the amalgamation (one translation
# unit, so the stack analysis sees every call); lib.o is lib/'s translation
# units linked relocatably, what a firmware build of lib/ links.
$(MCU_B)/%/collide2d.o: $(AMALGAMATION) $(MCU_DIR)/mcu.mk | mcu-deps
	@mkdir -p $(@D)
	$(MCU_COMPILE) $(DEPFLAGS) -fstack-usage -fcallgraph-info=su -c $(AMALGAMATION) -o $@

$(MCU_B)/%/lib.o: $(LIB_SRC) $(MCU_DIR)/mcu.mk | mcu-deps
	@mkdir -p $(@D)/lib
	for f in $(LIB_SRC); do $(MCU_COMPILE) $(call MCU_DEPS_OF,$$(basename $$f .c)) -c $$f -o $(@D)/lib/$$(basename $$f .c).o || exit 1; done
	$(MCU_$*_CC) $(MCU_$*_ARCH) -nostdlib -r -o $@ $(patsubst lib/%.c,$(@D)/lib/%.o,$(LIB_SRC))

# tests.o: the harness's translation units linked relocatably, as lib.o.
$(MCU_B)/%/tests.o: $(MCU_TEST_SRC) $(MCU_DIR)/mcu.mk | mcu-deps
	@mkdir -p $(@D)/tests
	for f in $(MCU_TEST_SRC); do \
	  $(MCU_COMPILE) $(call MCU_DEPS_OF,$$(basename $$f .c)) -DC2D_MCU_NAME='"$*"' -c $$f -o $(@D)/tests/$$(basename $$f .c).o || exit 1; done
	$(MCU_$*_CC) $(MCU_$*_ARCH) -nostdlib -r -o $@ $(patsubst %.c,$(@D)/tests/%.o,$(notdir $(MCU_TEST_SRC)))

$(MCU_B)/%/startup_arm.o: $(MCU_DIR)/startup_arm.c | mcu-deps
	@mkdir -p $(@D)
	$(MCU_COMPILE) $(DEPFLAGS) -c $< -o $@

$(MCU_B)/%/q16_caller.o: $(MCU_DIR)/q16_caller.c | mcu-deps
	@mkdir -p $(@D)
	$(MCU_COMPILE) $(DEPFLAGS) -c $< -o $@

# The C library's side (stdio-free: open/write/exit) needs picolibc's headers.
$(MCU_B)/rv32/platform_rv32.o: $(MCU_DIR)/platform_rv32.c | mcu-deps
	@mkdir -p $(@D)
	$(MCU_rv32_CC) $(MCU_rv32_ARCH) --specs=picolibc.specs -std=c99 $(WARN) -Werror -Os $(DEPFLAGS) -c $< -o $@

# newlib's libm supplies sqrt/sqrtf where the core has no FPU for them.
# harness.elf links lib/, harness_all.elf the amalgamation.
$(MCU_ARM:%=$(MCU_B)/%/harness.elf): $(MCU_B)/%/harness.elf: $(MCU_B)/%/startup_arm.o $(MCU_B)/%/tests.o \
  $(MCU_B)/%/lib.o $(MCU_DIR)/arm.ld
	$(MCU_$*_CC) $(MCU_$*_ARCH) $(call MCU_ARM_LINK,$*) -o $@ $(filter %.o,$^) \
	  -Wl,--start-group -lm -lc -lgcc -Wl,--end-group

$(MCU_ARM:%=$(MCU_B)/%/harness_all.elf): $(MCU_B)/%/harness_all.elf: $(MCU_B)/%/startup_arm.o $(MCU_B)/%/tests.o \
  $(MCU_B)/%/collide2d.o $(MCU_DIR)/arm.ld
	$(MCU_$*_CC) $(MCU_$*_ARCH) $(call MCU_ARM_LINK,$*) -o $@ $(filter %.o,$^) \
	  -Wl,--start-group -lm -lc -lgcc -Wl,--end-group

# Q16.16 alone: libgcc is the only library.
$(MCU_B)/m0q16/harness.elf: $(MCU_B)/m0q16/startup_arm.o $(MCU_B)/m0q16/tests.o \
  $(MCU_B)/m0q16/lib.o $(MCU_DIR)/arm.ld
	$(MCU_m0q16_CC) $(MCU_m0q16_ARCH) $(call MCU_ARM_LINK,m0q16) -o $@ $(filter %.o,$^) -lgcc

$(MCU_B)/m0q16/harness_all.elf: $(MCU_B)/m0q16/startup_arm.o $(MCU_B)/m0q16/tests.o \
  $(MCU_B)/m0q16/collide2d.o $(MCU_DIR)/arm.ld
	$(MCU_m0q16_CC) $(MCU_m0q16_ARCH) $(call MCU_ARM_LINK,m0q16) -o $@ $(filter %.o,$^) -lgcc

$(MCU_B)/m0q16/q16_link.elf: $(MCU_B)/m0q16/q16_caller.o $(MCU_B)/m0q16/collide2d.o
	$(MCU_m0q16_CC) $(MCU_m0q16_ARCH) -nostdlib -Wl,--gc-sections -Wl,-e,c2d_q16_entry -o $@ $^ -lgcc

$(MCU_B)/rv32/harness.elf: $(MCU_B)/rv32/platform_rv32.o $(MCU_B)/rv32/tests.o \
  $(MCU_B)/rv32/lib.o
	$(MCU_rv32_CC) $(MCU_rv32_ARCH) $(MCU_RV32_LINK) -o $@ $^ -lm

$(MCU_B)/rv32/harness_all.elf: $(MCU_B)/rv32/platform_rv32.o $(MCU_B)/rv32/tests.o \
  $(MCU_B)/rv32/collide2d.o
	$(MCU_rv32_CC) $(MCU_rv32_ARCH) $(MCU_RV32_LINK) -o $@ $^ -lm

# The size table: each target's section (sizes.sh, one check per target),
# then the table in $(MCU_B)/SIZES.md.  `make cross` compares it with the
# tracked docs/SIZES.md (one more check) and never writes docs/; `make sizes`
# copies it there when every target's checks passed.
MCU_TABLE := rm -f $(MCU_B)/rows.md $(MCU_B)/sections.md; \
	$(foreach t,$(MCU_CROSS),if sh $(MCU_DIR)/sizes.sh $(MCU_$(t)_CHECKS) --rows $(MCU_B)/rows.md \
	  $(t) "$(MCU_$(t)_DESC)" $(MCU_B)/$(t)/collide2d.o $(MCU_$(t)_CC) $(MCU_$(t)_ARCH) \
	  >>$(MCU_B)/sections.md; then c2d_passed; else c2d_failed "$(t) (see above)"; fi;) \
	{ echo '\# Sizes on microcontrollers'; echo; \
	  echo 'Generated by `make sizes` (tests/mcu/mcu.mk, tests/mcu/sizes.sh; `make cross` checks it): do not edit.'; \
	  echo 'The library (lib/, as the single file of `make amalgamate`) built with `$(MCU_CFLAGS)`.'; \
	  echo 'Bytes. *code*: what linking only that function brings in from the library (--gc-sections);'; \
	  echo '*+ helpers*: the libgcc routines that adds; *stack*: worst case through the library'"'"'s own'; \
	  echo 'call graph (-fstack-usage, -fcallgraph-info; helper frames not counted), *+ callbacks*: the world'"'"'s, plus'; \
	  echo 'the caller'"'"'s on_event, resolvers and broadphase (the only indirect calls). No recursion, no allocation.'; \
	  echo 'The world needs double: it is in the m0, m7 and rv32 builds.'; echo; \
	  echo '| target | core, variants | text | data | bss | text with libgcc helpers | worst stack | outside symbols |'; \
	  echo '|---|---|---:|---:|---:|---:|---:|---|'; \
	  cat $(MCU_B)/rows.md; echo; cat $(MCU_B)/sections.md; } >$(MCU_B)/SIZES.md

.PHONY: sizes
cross: $(MCU_CROSS:%=$(MCU_B)/%/collide2d.o) $(MCU_B)/m0q16/q16_link.elf
	@. tests/harness/tally.sh; c2d_tally_name=cross; $(MCU_TABLE); \
	cat $(MCU_B)/SIZES.md; \
	if cmp -s $(MCU_B)/SIZES.md docs/SIZES.md; then c2d_passed; else \
	  diff -u docs/SIZES.md $(MCU_B)/SIZES.md | head -n 60; \
	  echo "cross: docs/SIZES.md differs from the table just generated ($(MCU_B)/SIZES.md, diff above): run make sizes and commit it" >&2; \
	  c2d_failed "docs/SIZES.md is stale"; fi; \
	c2d_summary

sizes: $(MCU_CROSS:%=$(MCU_B)/%/collide2d.o) $(MCU_B)/m0q16/q16_link.elf
	@. tests/harness/tally.sh; c2d_tally_name=sizes; $(MCU_TABLE); \
	if [ $$c2d_fail -ne 0 ]; then echo "sizes: docs/SIZES.md not written (a target failed its checks, see above)" >&2; c2d_summary; exit 1; fi; \
	cp $(MCU_B)/SIZES.md docs/SIZES.md && echo "sizes: docs/SIZES.md written from $(MCU_B)/SIZES.md"; \
	c2d_summary

# One check per QEMU run (run.sh prints each run's own tally).
test-mcu: $(MCU_RUN:%=$(MCU_B)/%/harness.elf) $(MCU_RUN:%=$(MCU_B)/%/harness_all.elf)
	@. tests/harness/tally.sh; c2d_tally_name=test-mcu; \
	$(foreach t,$(MCU_RUN),echo "== $(t), lib/"; \
	  c2d_check "$(t), lib/" sh $(MCU_DIR)/run.sh $(t) $(MCU_B)/$(t)/harness.elf $(MCU_$(t)_QEMU); \
	  echo "== $(t), amalgamation"; \
	  c2d_check "$(t), amalgamation" sh $(MCU_DIR)/run.sh $(t) $(MCU_B)/$(t)/harness_all.elf $(MCU_$(t)_QEMU);) \
	c2d_summary

# MISRA C:2012 through cppcheck's addon (rule numbers only: the rule texts are
# not shipped).  One configuration: every variant compiled in.  A rule that
# is suppressed must be explained in docs/MISRA.md; a suppression that no
# longer matches anything fails too, so the list never goes stale.
MISRA_SUPP := $(MCU_DIR)/misra.supp
lint-misra: | mcu-deps
	@rm -rf $(MCU_B)/misra && mkdir -p $(MCU_B)/misra
	@. tests/harness/tally.sh; c2d_tally_name=lint-misra; \
	c2d_check "cppcheck's MISRA addon on lib/ (findings above)" \
	  cppcheck --addon=misra --std=c99 -Iinclude -DC2D_MISRA_CHECK --cppcheck-build-dir=$(MCU_B)/misra \
	  --suppressions-list=$(MISRA_SUPP) --enable=information --suppress=missingIncludeSystem \
	  --error-exitcode=1 --quiet --template='{file}:{line}: {id}: {message}' $(LIB_SRC); \
	for r in $$(sed -n 's/^misra-c2012-\([0-9.]*\):.*/\1/p' $(MISRA_SUPP) | sort -u); do \
	  c2d_check "rule $$r suppressed but not in docs/MISRA.md" grep -qF "## Rule $$r " docs/MISRA.md; \
	done; c2d_summary

TEST_TARGETS += cross test-mcu lint-misra
LINT_TARGETS += lint-misra

-include $(wildcard $(MCU_B)/*/*.d)
