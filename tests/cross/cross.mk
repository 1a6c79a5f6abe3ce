# SPDX-License-Identifier: MIT
# tests/cross/cross.mk - the determinism hash on other architectures
# (included by the top-level Makefile, after tests/mcu/mcu.mk):
#   make test-cross          the 100,000 cases of tests/build/hash_cases.c on
#                            x86-64 (this machine), aarch64 and riscv64 Linux
#                            (Debian's cross compilers, static, under
#                            qemu-user) and the Cortex-M4F, Cortex-M7 and RV32
#                            targets (QEMU system mode, semihosting); every
#                            variant's hash must equal x86-64's of this run,
#                            and x86-64's the one in docs/DETERMINISM.md
#   make check-small         the host's hash with C2D_SMALL on (-O2) and off
#                            (-Os): both the table's (lib/internal.h)
#   make determinism-table   the same runs, then rewrites the table of
#                            expected hashes in docs/DETERMINISM.md (after a
#                            change to the library that changes its bits)
# Builds use the library's required flags (-std=c99 -ffp-contract=off
# -fno-math-errno) at -O2 for Linux and the MCU flags of mcu.mk.

CROSS_B := $(B)/cross
CROSS_LINUX := aarch64 riscv64
CROSS_MCU := m4f m7 rv32
CROSS_PKGS := gcc-aarch64-linux-gnu libc6-dev-arm64-cross gcc-riscv64-linux-gnu libc6-dev-riscv64-cross qemu-user
CROSS_HASH_SRC := tests/build/hash_vectors.c tests/build/hash_cases.c tests/harness/harness.c \
  tests/harness/soa_double.c tests/harness/soa_float.c tests/harness/put_stdio.c
CROSS_CFLAGS := -O2 -std=c99 $(WARN) -Werror -ffp-contract=off -fno-math-errno -Iinclude -Ireferee -Itests/harness

.PHONY: cross-deps test-cross determinism-table
cross-deps:
	@sh scripts/deps.sh $(CROSS_PKGS)

# Header dependencies: .d files (MULTI_DEPS: several sources in one
# command; MCU_DEPS_OF: one per source of a relocatable object), included at
# the end.
# The host's: the same sources, one program, as each Linux target's.
$(CROSS_B)/x86-64/hash_vectors: $(CROSS_HASH_SRC) $(LIB_SRC)
	@mkdir -p $(@D)
	$(call MULTI_DEPS,$(CC) $(CROSS_CFLAGS),$(CROSS_HASH_SRC) $(LIB_SRC))
	$(CC) $(CROSS_CFLAGS) -o $@ $(CROSS_HASH_SRC) $(LIB_SRC) -lm

$(CROSS_LINUX:%=$(CROSS_B)/%/hash_vectors): $(CROSS_B)/%/hash_vectors: $(CROSS_HASH_SRC) \
  $(LIB_SRC) | cross-deps
	@mkdir -p $(@D)
	$(call MULTI_DEPS,$*-linux-gnu-gcc $(CROSS_CFLAGS),$(CROSS_HASH_SRC) $(LIB_SRC))
	$*-linux-gnu-gcc $(CROSS_CFLAGS) -static -o $@ $(CROSS_HASH_SRC) $(LIB_SRC) -lm

# On a microcontroller: hash_mcu.c instead of the host's front end, the
# harness and the library built as tests/mcu/mcu.mk builds them.
CROSS_MCU_SRC := tests/cross/hash_mcu.c tests/build/hash_cases.c tests/harness/harness.c \
  tests/harness/soa_double.c tests/harness/soa_float.c
$(MCU_B)/%/hash.o: $(CROSS_MCU_SRC) $(MCU_DIR)/mcu.mk | mcu-deps
	@mkdir -p $(@D)/hash
	for f in $(CROSS_MCU_SRC); do $(MCU_COMPILE) $(call MCU_DEPS_OF,$$(basename $$f .c)) -Ireferee -Itests/build -DC2D_MCU_NAME='"$*"' \
	  -c $$f -o $(@D)/hash/$$(basename $$f .c).o || exit 1; done
	$(MCU_$*_CC) $(MCU_$*_ARCH) -nostdlib -r -o $@ $(patsubst %.c,$(@D)/hash/%.o,$(notdir $(CROSS_MCU_SRC)))

$(MCU_ARM:%=$(MCU_B)/%/hash.elf): $(MCU_B)/%/hash.elf: $(MCU_B)/%/startup_arm.o $(MCU_B)/%/hash.o \
  $(MCU_B)/%/lib.o $(MCU_DIR)/arm.ld
	$(MCU_$*_CC) $(MCU_$*_ARCH) $(call MCU_ARM_LINK,$*) -o $@ $(filter %.o,$^) -Wl,--start-group -lm -lc -lgcc -Wl,--end-group

$(MCU_B)/rv32/hash.elf: $(MCU_B)/rv32/platform_rv32.o $(MCU_B)/rv32/hash.o $(MCU_B)/rv32/lib.o
	$(MCU_rv32_CC) $(MCU_rv32_ARCH) $(MCU_RV32_LINK) -o $@ $^ -lm

comma := ,
CROSS_QEMU_SYS := -nographic -monitor none -semihosting-config enable=on,target=native -kernel
# NAME, DESCRIPTION, COMMAND for each target; x86-64 first: the reference.
CROSS_RUNS = "x86-64" "this machine: $(CC) -O2" "$(CROSS_B)/x86-64/hash_vectors" \
  $(foreach t,$(CROSS_LINUX),"$(t)" "Linux: $(t)-linux-gnu-gcc -O2 -static; qemu-$(t)" \
    "qemu-$(t) $(CROSS_B)/$(t)/hash_vectors") \
  $(foreach t,$(CROSS_MCU),"$(t)" "$(strip $(firstword $(subst $(comma), ,$(MCU_$(t)_DESC))): $(MCU_$(t)_CC) \
    $(MCU_$(t)_ARCH) $(MCU_$(t)_OPTS)) -Os; $(MCU_$(t)_QEMU), semihosting" \
    "$(MCU_$(t)_QEMU) $(CROSS_QEMU_SYS) $(MCU_B)/$(t)/hash.elf")
CROSS_ALL := $(CROSS_B)/x86-64/hash_vectors $(CROSS_LINUX:%=$(CROSS_B)/%/hash_vectors) \
  $(CROSS_MCU:%=$(MCU_B)/%/hash.elf)

# Under SANITIZE=1 it is skipped: none of these builds is sanitised, so the
# run would repeat the plain one.
ifeq ($(SANITIZE),1)
test-cross:
	@echo "cross: skipped under SANITIZE=1 (no sanitised build in it: the plain run covers it)"
else
test-cross: $(CROSS_ALL)
	@sh tests/cross/cross.sh check $(CROSS_B) docs/DETERMINISM.md $(CROSS_RUNS)
endif

# C2D_SMALL (lib/internal.h: on by default under -Os) both ways on this
# machine, against the table: on at -O2, off at -Os.  The MCU runs above are
# -Os builds, so they take it on; this takes it apart from the target.
CROSS_SMALL_FLAGS_on := -DC2D_SMALL=1
CROSS_SMALL_FLAGS_off := -Os -DC2D_SMALL=0
$(CROSS_B)/small/hash_vectors_on $(CROSS_B)/small/hash_vectors_off: $(CROSS_B)/small/hash_vectors_%: \
  $(CROSS_HASH_SRC) $(LIB_SRC)
	@mkdir -p $(@D)
	$(call MULTI_DEPS,$(CC) $(CROSS_CFLAGS) $(CROSS_SMALL_FLAGS_$*),$(CROSS_HASH_SRC) $(LIB_SRC))
	$(CC) $(CROSS_CFLAGS) $(CROSS_SMALL_FLAGS_$*) -o $@ $(CROSS_HASH_SRC) $(LIB_SRC) -lm

.PHONY: check-small
check-small: $(CROSS_B)/small/hash_vectors_on $(CROSS_B)/small/hash_vectors_off
	@sh tests/cross/cross.sh check $(CROSS_B)/small docs/DETERMINISM.md \
	  "x86-64-small" "this machine: $(CC) -O2 -DC2D_SMALL=1" "$(CROSS_B)/small/hash_vectors_on" \
	  "x86-64-Os-not-small" "this machine: $(CC) -Os -DC2D_SMALL=0" "$(CROSS_B)/small/hash_vectors_off"

determinism-table: $(CROSS_ALL)
	@sh tests/cross/cross.sh write $(CROSS_B) docs/DETERMINISM.md $(CROSS_RUNS)

TEST_TARGETS += test-cross check-small

-include $(wildcard $(CROSS_B)/*/*.d)
