# SPDX-License-Identifier: MIT
# examples/examples.mk - the examples, built and run by `make test`
# (included by the top-level Makefile):
#   two_body        the README's example (c2d_collide, c2d_collide_normal)
#   ball_in_box     a ball bouncing between four walls (c2d_collide_normal)
#   hard_disk_gas   event-driven hard-disk gas: pressure against Henderson's
#                   equation of state (c2d_time_of_impact, c2d_collide)
#   firmware        float only (C2D_NO_DOUBLE) on a Cortex-M4F, under QEMU
#                   with the MCU harness's start-up code (tests/mcu/mcu.mk)
#   make examples        builds them
#   make test-examples   builds and runs each; each ends with a pass line,
#                        the whole with `test-examples: N passed, M failed`

EXAMPLES := two_body ball_in_box hard_disk_gas
EXAMPLE_BINS := $(EXAMPLES:%=$(B)/examples/%)
EXAMPLE_FIRMWARE := $(MCU_B)/m4f/firmware.elf

.PHONY: examples test-examples
examples: $(EXAMPLE_BINS) $(EXAMPLE_FIRMWARE)

# Header dependencies: .d files (DEPFLAGS), included at the end.
$(B)/examples/%: examples/%.c $(STATIC)
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) $(DEPFLAGS) -Werror -o $@ $< $(STATIC) -lm

# The firmware: MCU_COMPILE gives the target's flags (m4f: C2D_NO_DOUBLE);
# -Wdouble-promotion catches any double arithmetic in the example itself.
$(MCU_B)/%/firmware.o: examples/firmware.c | mcu-deps
	@mkdir -p $(@D)
	$(MCU_COMPILE) $(DEPFLAGS) -Wdouble-promotion -c $< -o $@

$(EXAMPLE_FIRMWARE): $(MCU_B)/m4f/startup_arm.o $(MCU_B)/m4f/firmware.o $(MCU_B)/m4f/lib.o $(MCU_DIR)/arm.ld
	$(MCU_m4f_CC) $(MCU_m4f_ARCH) $(call MCU_ARM_LINK,m4f) -o $@ $(filter %.o,$^) -lgcc

# One check per host example run, one for the firmware's link (no double
# helpers), one for its run under QEMU; `test-examples: N passed, M failed`.
test-examples: examples
	@. tests/harness/tally.sh; c2d_tally_name=test-examples; \
	for x in $(EXAMPLE_BINS); do echo "== $$x"; c2d_check "$$x" $$x; done; \
	echo "== $(EXAMPLE_FIRMWARE) (Cortex-M4F, QEMU)"; \
	if arm-none-eabi-nm $(EXAMPLE_FIRMWARE) | grep -q ' __aeabi_d'; then \
	  c2d_failed "firmware: double-precision helpers linked"; else c2d_passed; fi; \
	c2d_check "firmware under QEMU" sh $(MCU_DIR)/run.sh firmware $(EXAMPLE_FIRMWARE) $(MCU_m4f_QEMU); \
	c2d_summary

TEST_TARGETS += test-examples

-include $(EXAMPLE_BINS:=.d) $(MCU_B)/m4f/firmware.d
