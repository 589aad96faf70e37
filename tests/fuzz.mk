# libFuzzer targets (tests/fuzz/README.md). Included by the top Makefile.
#   make fuzz        every target for FUZZ_TIME seconds (default 300), one after another
#   make test-fuzz   replay every corpus, then every target for a short bounded time
#                    (a CHECKS target of make test); skipped without clang's libFuzzer
#   make fuzz-build  the targets only (build/fuzz/fuzz_*)
#
# clang -fsanitize=fuzzer,address,undefined over the core, the simulator's
# readers (sim/sim.mk's SIMTOOL_SRC without its main) and the camera tool's
# pure parts; the same libraries as the simulator (libpng, libjpeg, OpenEXR).

FUZZ_TARGETS := ppm pfm png jpeg exr y4m raw aux cam_opts cam_conv api
FUZZ_TIME ?= 300
FUZZ_DIR := $(B)/fuzz
FUZZ_SAN := -O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=all
FUZZ_CFLAGS := $(WARN) $(FUZZ_SAN) $(SIMTOOL_CFLAGS) -DCAM_NO_GPIOD -DCAM_NO_DRM -I$(CAM_DIR) -Itests/fuzz
FUZZ_LIB_SRC := $(CORE_SRC) $(SIM_SRC) $(filter-out sim/bloom_sim.c,$(SIMTOOL_SRC)) \
                $(CAM_DIR)/cam_opts.c $(CAM_DIR)/cam_conv.c $(CAM_DIR)/cam_fmt.c $(CAM_DIR)/cam_aux.c \
                $(CAM_DIR)/drm_pick.c $(CAM_DIR)/gpio.c
FUZZ_LIB_OBJ := $(patsubst %.c,$(FUZZ_DIR)/obj/%.o,$(FUZZ_LIB_SRC))
FUZZ_HDR := $(CORE_HDR) $(SIM_HDR) $(SIMTOOL_HDR) $(CAM_HDR) $(wildcard tests/fuzz/*.h)
FUZZ_BINS := $(addprefix $(FUZZ_DIR)/fuzz_,$(FUZZ_TARGETS))

CHECKS += test-fuzz
.PHONY: fuzz test-fuzz fuzz-build fuzz-seeds

# Instrumented for coverage (fuzzer-no-link); libFuzzer's main comes at the link.
$(FUZZ_DIR)/obj/%.o: %.c $(FUZZ_HDR)
	@mkdir -p $(@D)
	$(CLANG) $(FUZZ_CFLAGS) -fsanitize=fuzzer-no-link -c $< -o $@
$(FUZZ_DIR)/libfuzzbloom.a: $(FUZZ_LIB_OBJ)
	rm -f $@ && ar rcs $@ $^

# One binary per target; fuzz_ppm and fuzz_pfm are one source (the reader
# is one), their corpora differ.
# fuzz_api's configurations are a second source of its own.
FUZZ_MAIN = $(if $(filter ppm pfm,$(1)),fuzz_pnm,fuzz_$(1))
FUZZ_EXTRA_api := $(FUZZ_DIR)/obj/tests/fuzz/fuzz_api_config.o
define FUZZ_LINK
$(FUZZ_DIR)/fuzz_$(1): tests/fuzz/$(call FUZZ_MAIN,$(1)).c $(FUZZ_DIR)/obj/tests/fuzz/fuzz_util.o \
                      $(FUZZ_EXTRA_$(1)) $(FUZZ_DIR)/libfuzzbloom.a $(FUZZ_HDR)
	$$(CLANG) $$(FUZZ_CFLAGS) -fsanitize=fuzzer $$< $(FUZZ_DIR)/obj/tests/fuzz/fuzz_util.o \
	  $(FUZZ_EXTRA_$(1)) $(FUZZ_DIR)/libfuzzbloom.a $$(SIMTOOL_LIBS) -o $$@
endef
$(foreach t,$(FUZZ_TARGETS),$(eval $(call FUZZ_LINK,$(t))))

fuzz-build: $(FUZZ_BINS)

# The runner probes for clang and libFuzzer before building anything.
fuzz: sim-deps
	@B='$(B)' CLANG='$(CLANG)' MAKE='$(MAKE)' FUZZ_TIME='$(FUZZ_TIME)' \
	  FUZZ_TARGETS='$(FUZZ_TARGETS)' EXR='$(if $(filter -DSIM_NO_EXR,$(SIMTOOL_EXR_CFLAGS)),no,yes)' \
	  sh tests/fuzz/run.sh fuzz
test-fuzz: sim-deps
	@B='$(B)' CLANG='$(CLANG)' MAKE='$(MAKE)' FUZZ_TARGETS='$(FUZZ_TARGETS)' \
	  EXR='$(if $(filter -DSIM_NO_EXR,$(SIMTOOL_EXR_CFLAGS)),no,yes)' \
	  sh tests/fuzz/run.sh test

# The seed corpora's generator (gen-* and regress-* files of tests/fuzz/corpus;
# the reproducers of findings there are kept). Run by hand: the corpus is
# committed.
FUZZ_SEEDS_SRC := tests/fuzz/gen_seeds.c tests/fuzz/gen_seeds_img.c tests/fuzz/gen_seeds_api.c
$(FUZZ_DIR)/gen_seeds: $(FUZZ_SEEDS_SRC) tests/fuzz/gen_seeds.h sim/imgio.c sim/imgio.h
	@mkdir -p $(@D)
	$(CLANG) $(WARN) -O1 -g $(SIMTOOL_CFLAGS) $(FUZZ_SEEDS_SRC) sim/imgio.c $(SIMTOOL_LIBS) -o $@
fuzz-seeds: $(FUZZ_DIR)/gen_seeds
	cd $(FUZZ_DIR) && ./gen_seeds $(CURDIR)/tests/fuzz/corpus $(CURDIR)/tests/data
