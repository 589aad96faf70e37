# Cortex-M example (issue 6): a freestanding firmware running the engine on
# Cortex-M4 and Cortex-M7 under qemu-system-arm, its checksum against the
# host build's, and the flash/RAM/stack figures. Included by the top Makefile.
#   make test-firmware   build, run on mps2-an386 (M4) and mps2-an500 (M7),
#                        compare with the host (installs qemu if missing)
#   make figures         regenerate port/mcu/FIGURES.md
#   make mcu-build       only build $(B)/mcu/ (firmware and host programs)
#
# Firmware builds: $(B)/mcu/<cpu>-<build>/fw_l<levels>.elf with cpu m4|m7,
# build full (every pixel format) | rgb565 (RGB565 only) | min (RGB565 only,
# BLOOM_SMALL) | minnc (min without ring checks), levels 5 (the default
# preset) | 7 (the deepest pyramid 320x240 allows); and the tiles case
# $(B)/mcu/<cpu>-rgb565/fw_tiles.elf (640x480 in strips, fw_tiles.c).

MCU := port/mcu
MCU_B := $(B)/mcu
ARM_SIZE ?= arm-none-eabi-size
QEMU_ARM ?= qemu-system-arm

MCU_CPUS := m4 m7
MCU_CPU_m4 := -mcpu=cortex-m4
MCU_CPU_m7 := -mcpu=cortex-m7
MCU_BUILDS := full rgb565 min minnc
MCU_DEF_full :=
# The default preset only: the figures are for the pipeline a small target runs.
MCU_DEF_nopresets := -DBLOOM_USE_GAMEDEV=0 -DBLOOM_USE_XNA=0 -DBLOOM_USE_ATTENUATION=0 -DBLOOM_USE_ARM=0 -DBLOOM_USE_COD=0
MCU_DEF_rgb565 := -DBLOOM_USE_RGB888=0 -DBLOOM_USE_XRGB8888=0 -DBLOOM_USE_RGBQ16=0 $(MCU_DEF_nopresets)
MCU_DEF_min := $(MCU_DEF_rgb565) -DBLOOM_SMALL=1 -DBLOOM_USE_SKIP=0
MCU_DEF_minnc := $(MCU_DEF_min) -DBLOOM_CHECK_RINGS=0
MCU_LEVELS := 5 7
# Soft-float ABI: the core has no floating point, and the startup code then
# need not enable the FPU.
MCU_CFLAGS := -mthumb -mfloat-abi=soft -Os -g -ffreestanding -ffunction-sections -fdata-sections
MCU_LDFLAGS := -nostdlib -T $(MCU)/mps2.ld -Wl,--gc-sections
MCU_FW := fw_main startup semihost
MCU_HDR := $(MCU)/fw_app.h $(MCU)/fw_stack.h $(MCU)/semihost.h
MCU_CORE_HDR := $(CORE_HDR) $(wildcard include/*.h src/*.h)

CHECKS += test-firmware
.PHONY: test-firmware figures mcu-build

# $(1) cpu, $(2) build: the objects both level counts share. The core gets
# -fstack-usage (the .su files next to the objects feed the figures).
define MCU_OBJ_RULES
$(MCU_B)/$(1)-$(2)/core/%.o: src/%.c $(MCU_CORE_HDR)
	@mkdir -p $$(@D)
	$(ARM_CC) $(WARN) $(MCU_CFLAGS) $(MCU_CPU_$(1)) $(MCU_DEF_$(2)) -fstack-usage \
	  $(CPPFLAGS_CORE) -c $$< -o $$@
$(MCU_B)/$(1)-$(2)/fw/%.o: $(MCU)/%.c $(MCU_HDR) $(MCU_CORE_HDR)
	@mkdir -p $$(@D)
	$(ARM_CC) $(WARN) $(MCU_CFLAGS) $(MCU_CPU_$(1)) $(MCU_DEF_$(2)) -DFW_TARGET \
	  $(CPPFLAGS_CORE) -I$(MCU) -c $$< -o $$@
endef

# $(1) cpu, $(2) build, $(3) levels
define MCU_ELF_RULES
$(MCU_B)/$(1)-$(2)/fw/fw_app_l$(3).o: $(MCU)/fw_app.c $(MCU_HDR) $(MCU_CORE_HDR) $(MCU_APP_DEP_$(2))
	@mkdir -p $$(@D)
	$(ARM_CC) $(WARN) $(MCU_CFLAGS) $(MCU_CPU_$(1)) $(MCU_DEF_$(2)) -DFW_TARGET -DFW_LEVELS=$(3) \
	  $(MCU_APP_DEF_$(2)) $(CPPFLAGS_CORE) -I$(MCU) -c $$< -o $$@
$(MCU_B)/$(1)-$(2)/fw_l$(3).elf: $(patsubst src/%.c,$(MCU_B)/$(1)-$(2)/core/%.o,$(CORE_SRC)) \
    $(patsubst %,$(MCU_B)/$(1)-$(2)/fw/%.o,$(MCU_FW) fw_app_l$(3)) $(MCU)/mps2.ld
	$(ARM_CC) $(MCU_CFLAGS) $(MCU_CPU_$(1)) $(MCU_LDFLAGS) -Wl,-Map=$$(@:.elf=.map) \
	  $$(filter %.o,$$^) -lc -lgcc -o $$@
endef

$(foreach c,$(MCU_CPUS),$(foreach b,$(MCU_BUILDS),$(eval $(call MCU_OBJ_RULES,$(c),$(b)))))
$(foreach c,$(MCU_CPUS),$(foreach b,$(MCU_BUILDS),$(foreach l,$(MCU_LEVELS),\
  $(eval $(call MCU_ELF_RULES,$(c),$(b),$(l))))))

# "minx" (figures.sh): the minimal build with the workspace declared at the
# exact size the target's bloom_workspace_size() reported, MCU_WS_BYTES, in
# place of the BLOOM_WORKSPACE_MAX bound. A stamp file rebuilds it when the
# size changes.
ifneq ($(MCU_WS_BYTES),)
MCU_DEF_minx := $(MCU_DEF_min)
MCU_APP_DEF_minx := -DFW_WS_BYTES=$(MCU_WS_BYTES)
MCU_APP_DEP_minx := $(MCU_B)/ws_bytes
$(shell mkdir -p $(MCU_B) && { echo '$(MCU_WS_BYTES)' | cmp -s - $(MCU_B)/ws_bytes || \
  echo '$(MCU_WS_BYTES)' > $(MCU_B)/ws_bytes; })
$(foreach c,$(MCU_CPUS),$(eval $(call MCU_OBJ_RULES,$(c),minx))$(eval $(call MCU_ELF_RULES,$(c),minx,5)))
mcu-exact: $(patsubst %,$(MCU_B)/%-minx/fw_l5.elf,$(MCU_CPUS))
else
mcu-exact:
	@echo "mcu-exact: needs MCU_WS_BYTES=<bytes> (make figures passes it)"; exit 1
endif
.PHONY: mcu-exact

# The tiles case (fw_tiles.c, issue 14): 640x480 RGB565 in strips with a
# 32 KB workspace, on the RGB565-only build (BLOOM_SMALL builds refuse
# tiles). FW_SRAM_LIMIT makes mps2.ld check that stack, .data and .bss
# (the workspace) fit a 64 KB on-chip SRAM; the frames are in .framebuffer.
MCU_TILES_SRAM := 65536
define MCU_TILES_RULES
$(MCU_B)/$(1)-rgb565/fw/fw_main_tiles.o: $(MCU)/fw_main.c $(MCU_HDR) $(MCU_CORE_HDR)
	@mkdir -p $$(@D)
	$(ARM_CC) $(WARN) $(MCU_CFLAGS) $(MCU_CPU_$(1)) $(MCU_DEF_rgb565) -DFW_TARGET -DFW_MAIN_APP=fw_tiles_app \
	  $(CPPFLAGS_CORE) -I$(MCU) -c $$< -o $$@
$(MCU_B)/$(1)-rgb565/fw_tiles.elf: $(patsubst src/%.c,$(MCU_B)/$(1)-rgb565/core/%.o,$(CORE_SRC)) \
    $(patsubst %,$(MCU_B)/$(1)-rgb565/fw/%.o,fw_main_tiles startup semihost fw_app_l5 fw_tiles) $(MCU)/mps2.ld
	$(ARM_CC) $(MCU_CFLAGS) $(MCU_CPU_$(1)) $(MCU_LDFLAGS) -Wl,--defsym=FW_SRAM_LIMIT=$(MCU_TILES_SRAM) \
	  -Wl,-Map=$$(@:.elf=.map) $$(filter %.o,$$^) -lc -lgcc -o $$@
endef
$(foreach c,$(MCU_CPUS),$(eval $(call MCU_TILES_RULES,$(c))))
$(MCU_B)/host/fw_host_tiles: $(MCU)/fw_tiles.c $(MCU)/fw_app.c $(MCU)/host_main.c $(MCU)/fw_app.h $(CORE_SRC) $(MCU_CORE_HDR)
	@mkdir -p $(@D)
	$(CC) $(WARN) $(CFLAGS) $(CPPFLAGS_CORE) -I$(MCU) -DFW_MAIN_APP=fw_tiles_app $(MCU)/fw_tiles.c $(MCU)/fw_app.c \
	  $(MCU)/host_main.c $(CORE_SRC) -o $@

# The same fw_app.c and core, host compiler: the reference checksums.
$(MCU_B)/host/fw_host_l%: $(MCU)/fw_app.c $(MCU)/host_main.c $(MCU)/fw_app.h $(CORE_SRC) $(MCU_CORE_HDR)
	@mkdir -p $(@D)
	$(CC) $(WARN) $(CFLAGS) $(CPPFLAGS_CORE) -I$(MCU) -DFW_LEVELS=$* $(MCU)/fw_app.c \
	  $(MCU)/host_main.c $(CORE_SRC) -o $@

MCU_ELFS := $(foreach c,$(MCU_CPUS),$(foreach b,$(MCU_BUILDS),$(foreach l,$(MCU_LEVELS),\
  $(MCU_B)/$(c)-$(b)/fw_l$(l).elf)))
MCU_TILES := $(patsubst %,$(MCU_B)/%-rgb565/fw_tiles.elf,$(MCU_CPUS)) $(MCU_B)/host/fw_host_tiles
mcu-build: $(MCU_ELFS) $(patsubst %,$(MCU_B)/host/fw_host_l%,$(MCU_LEVELS)) $(MCU_TILES)

MCU_ENV = B='$(B)' MAKE='$(MAKE)' ARM_CC='$(ARM_CC)' ARM_SIZE='$(ARM_SIZE)' \
          QEMU_ARM='$(QEMU_ARM)' MCU_BUILDS='$(MCU_BUILDS)' MCU_LEVELS='$(MCU_LEVELS)'

test-firmware:
	@$(MCU_ENV) sh $(MCU)/test_firmware.sh

figures:
	@$(MCU_ENV) sh $(MCU)/figures.sh $(MCU)/FIGURES.md
