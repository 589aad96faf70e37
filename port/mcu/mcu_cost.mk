# Cost on the targets (issue 21, section 4): instructions per frame on
# Cortex-M4/M7 counted under unicorn (port/mcu/mcu_count.py) and on
# Cortex-A (aarch64, armhf) under qemu-user with a counting TCG plugin
# (sim/bench/insn_plugin.c), a cycle estimate by instruction class, and the
# page sim/docs/targets.md. Included by the top Makefile (after mcu.mk, whose
# variables it uses).
#   make target-cost     regenerate sim/docs/targets.md (installs
#                        python3-unicorn, python3-capstone, qemu-user and
#                        the cross compilers if missing: port/mcu/cost_deps.sh)
#   make target-cost-page  rewrite the page from the last run's results
#                        ($(B)/cost/results.json), running nothing
#   make target-cost-a   count Cortex-A again, keep the last Cortex-M results
#                        (a change to the NEON or the armhf code only)
#   make cost-build      only build $(B)/cost/
# COST_JOBS=N runs N emulations at once (500 to 940 s for the whole page
# with COST_JOBS=2 on this 2-core machine, shared with other work).
#
# Sample widths: COST_WIDTHS lists the row sample widths costed, each built
# with COST_CFLAGS_<width> added to the core's and the bench's flags: 16 sets
# cfg.sample_bits = 16 in the benches (unity, attenuation, xna, arm; the minimal
# build has no 16-bit samples). `make target-cost COST_WIDTHS='32 16'`.

COST_B := $(B)/cost
COST_WIDTHS ?= 32
COST_CFLAGS_32 :=
COST_CFLAGS_16 := -DBLOOM_COST_SAMPLE_BITS=16
COST_MCU_BUILDS := full rgb565 min
COST_A_ARCHS := aarch64 armhf
COST_FW := fw_main startup semihost fw_app fw_cost
COST_A_SRC := sim/bench/icount.c sim/bench/scene.c sim/bench/variants.c sim/imgio.c
COST_HDR := $(MCU_HDR) $(MCU_CORE_HDR)

.PHONY: target-cost target-cost-page target-cost-a cost-build cost-selftest

# $(1) width, $(2) cpu, $(3) build: the bench firmware, core and firmware
# objects compiled as mcu.mk compiles the firmware's, plus the width's flags.
define COST_FW_RULES
$(COST_B)/w$(1)/$(2)-$(3)/core/%.o: src/%.c $(COST_HDR)
	@mkdir -p $$(@D)
	$(ARM_CC) $(WARN) $(MCU_CFLAGS) $(MCU_CPU_$(2)) $(MCU_DEF_$(3)) $(COST_CFLAGS_$(1)) \
	  $(CPPFLAGS_CORE) -c $$< -o $$@
$(COST_B)/w$(1)/$(2)-$(3)/fw/%.o: $(MCU)/%.c $(COST_HDR)
	@mkdir -p $$(@D)
	$(ARM_CC) $(WARN) $(MCU_CFLAGS) $(MCU_CPU_$(2)) $(MCU_DEF_$(3)) $(COST_CFLAGS_$(1)) -DFW_TARGET \
	  -DFW_MAIN_APP=fw_cost_app $(CPPFLAGS_CORE) -I$(MCU) -c $$< -o $$@
$(COST_B)/w$(1)/$(2)-$(3)/fw_cost.elf: $(patsubst src/%.c,$(COST_B)/w$(1)/$(2)-$(3)/core/%.o,$(CORE_SRC)) \
    $(patsubst %,$(COST_B)/w$(1)/$(2)-$(3)/fw/%.o,$(COST_FW)) $(MCU)/mps2.ld
	$(ARM_CC) $(MCU_CFLAGS) $(MCU_CPU_$(2)) $(MCU_LDFLAGS) $$(filter %.o,$$^) -lc -lgcc -o $$@
endef
# $(1) width: the host build of the bench (its checksums are the reference).
define COST_HOST_RULES
$(COST_B)/w$(1)/host/fw_host_cost: $(MCU)/fw_cost.c $(MCU)/fw_app.c $(MCU)/host_main.c $(CORE_SRC) $(COST_HDR)
	@mkdir -p $$(@D)
	$(CC) $(WARN) $(CFLAGS) $(COST_CFLAGS_$(1)) $(CPPFLAGS_CORE) -I$(MCU) -DFW_MAIN_APP=fw_cost_app \
	  $(MCU)/fw_cost.c $(MCU)/fw_app.c $(MCU)/host_main.c $(CORE_SRC) -o $$@
endef
# $(1) width, $(2) arch: bloom_icount (sim/bench/icount.c) cross-built
# static, as tests/cross.mk builds the ARM Linux binaries.
define COST_A_RULES
$(COST_B)/w$(1)/$(2)/bloom_icount: $(COST_A_SRC) $(wildcard sim/bench/*.h sim/*.h) $(COST_HDR)
	@mkdir -p $$(@D)
	$$(CROSS_CC_$(2)) $(WARN) $$(CROSS_CFLAGS) $(COST_CFLAGS_$(1)) -static $(HOST_CPPFLAGS) -Isim/bench \
	  $(COST_A_SRC) $(CORE_SRC) -lm -o $$@
endef
$(foreach w,$(COST_WIDTHS),$(eval $(call COST_HOST_RULES,$(w)))\
  $(foreach c,$(MCU_CPUS),$(foreach b,$(COST_MCU_BUILDS),$(eval $(call COST_FW_RULES,$(w),$(c),$(b)))))\
  $(foreach a,$(COST_A_ARCHS),$(eval $(call COST_A_RULES,$(w),$(a)))))

$(COST_B)/insn_plugin.so: sim/bench/insn_plugin.c
	@mkdir -p $(@D)
	$(CC) $(WARN) -O2 -fPIC -shared $< -o $@

COST_TARGETS := $(COST_B)/insn_plugin.so $(foreach w,$(COST_WIDTHS),$(COST_B)/w$(w)/host/fw_host_cost \
  $(foreach c,$(MCU_CPUS),$(foreach b,$(COST_MCU_BUILDS),$(COST_B)/w$(w)/$(c)-$(b)/fw_cost.elf)) \
  $(foreach a,$(COST_A_ARCHS),$(COST_B)/w$(w)/$(a)/bloom_icount))
cost-build: $(COST_TARGETS)

target-cost:
	@sh $(MCU)/cost_deps.sh
	@$(MAKE) --no-print-directory cost-build
	@/usr/bin/python3 sim/bench/targets.py --build $(COST_B) --widths '$(COST_WIDTHS)' \
	  --builds '$(COST_MCU_BUILDS)' --archs '$(COST_A_ARCHS)' --out sim/docs/targets.md

target-cost-page:
	@/usr/bin/python3 sim/bench/targets.py --build $(COST_B) --page-only --out sim/docs/targets.md

target-cost-a:
	@sh $(MCU)/cost_deps.sh
	@$(MAKE) --no-print-directory cost-build
	@/usr/bin/python3 sim/bench/targets.py --build $(COST_B) --widths '$(COST_WIDTHS)' --cortex-a-only \
	  --builds '$(COST_MCU_BUILDS)' --archs '$(COST_A_ARCHS)' --out sim/docs/targets.md

# The counters checked on hand-written programs of known counts (run by
# make test-runner through tests/selftest/selftest.sh).
cost-selftest:
	@B='$(B)' CC='$(CC)' ARM_CC='$(ARM_CC)' CROSS_CC_aarch64='$(CROSS_CC_aarch64)' sh $(MCU)/cost_selftest.sh
