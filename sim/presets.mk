# Presets (issue 4): cost, instruction counts and code size of every preset
# against the default. Measurements, not tests: nothing here joins CHECKS.
#   make preset-cost     bloom_process per preset, median of rounds run side
#                        by side with a cold memcpy: sim/docs/presets/cost.md/.csv
#   make preset-icount   instructions per output pixel per preset under
#                        callgrind (deterministic): sim/docs/presets/icount.md
#   make preset-sizes    code size of the core with the default preset only
#                        and with every preset (host size, arm-none-eabi-size):
#                        sim/docs/presets/sizes.md
PRESET_DIR := $(B)/presets
PRESET_SIZES ?= 640x480,1920x1080
PRESET_RUNS ?= 15
PRESET_OFF := -DBLOOM_USE_GAMEDEV=0 -DBLOOM_USE_XNA=0 -DBLOOM_USE_ATTENUATION=0 -DBLOOM_USE_ARM=0 -DBLOOM_USE_COD=0

.PHONY: preset-cost preset-icount preset-sizes

$(PRESET_DIR)/preset_cost: sim/preset_cost.c sim/bench/scene.c sim/bench/scene.h sim/imgio.c $(CORE_SRC) $(CORE_HDR)
	@mkdir -p $(@D)
	$(CC) $(WARN) -O2 -g $(HOST_CPPFLAGS) sim/preset_cost.c sim/bench/scene.c sim/imgio.c $(CORE_SRC) -lm -o $@

preset-cost: $(PRESET_DIR)/preset_cost
	$(PRESET_DIR)/preset_cost --sizes $(PRESET_SIZES) --runs $(PRESET_RUNS) \
	  --md sim/docs/presets/cost.md --csv sim/docs/presets/cost.csv

preset-icount: $(PRESET_DIR)/preset_cost icount-deps
	@sh sim/presets_icount.sh $(PRESET_DIR)/preset_cost sim/docs/presets/icount.md 640x480 1920x1080

# Code size: the core built -O2 for the host and -Os for Cortex-M4, once
# with every preset and once with the default only (BLOOM_USE_<PRESET>=0).
preset-sizes:
	@mkdir -p $(PRESET_DIR)/all $(PRESET_DIR)/def $(PRESET_DIR)/arm-all $(PRESET_DIR)/arm-def
	@for f in $(CORE_SRC); do o=$$(basename $$f .c).o; \
	  $(CC) $(WARN) -O2 $(CPPFLAGS_CORE) -c $$f -o $(PRESET_DIR)/all/$$o && \
	  $(CC) $(WARN) -O2 $(CPPFLAGS_CORE) $(PRESET_OFF) -c $$f -o $(PRESET_DIR)/def/$$o && \
	  $(ARM_CC) $(WARN) -Os -mcpu=cortex-m4 -mthumb -ffreestanding $(CPPFLAGS_CORE) -c $$f -o $(PRESET_DIR)/arm-all/$$o && \
	  $(ARM_CC) $(WARN) -Os -mcpu=cortex-m4 -mthumb -ffreestanding $(CPPFLAGS_CORE) $(PRESET_OFF) -c $$f -o $(PRESET_DIR)/arm-def/$$o || exit 1; done
	@sh sim/presets_sizes.sh $(PRESET_DIR) sim/docs/presets/sizes.md
