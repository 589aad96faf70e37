# bloom: fixed-point streaming bloom engine.
#   make            library and host tools (build/)
#   make test       every test (installs its Debian packages first if missing)
#   make demo       a real image through the engine: before/after + error summary
#   make freestanding  Cortex-M4 build of the core; proves it needs only memcpy/memset
#   make tables     regenerate src/pixel/bloom_tables.c
#   make memtable   the workspace/latency table of README (and workspace against strip width)
#   make tile-table workspace and callgrind overhead against strip width: sim/docs/tiles.md
#   make deps       install the Debian packages the targets use

CC ?= cc
CLANG ?= clang
ARM_CC ?= arm-none-eabi-gcc
ARM_NM ?= arm-none-eabi-nm
B := build

WARN := -std=c11 -Wall -Wextra -Werror -Wshadow -Wstrict-prototypes -Wmissing-prototypes \
        -Wcast-align -Wpointer-arith -Wvla
CFLAGS ?= -O2 -g
# The core's modules (src/<module>/), lowest first: pixel (formats, tables,
# fixed-point helpers), kernels (row kernels and SIMD twins), graph (the
# engine's graph and its construction), presets (one file per preset),
# engine (set-up, scheduler, row/band/frame calls). Headers by module name.
CORE_MODULES := pixel kernels graph presets engine
CPPFLAGS_CORE := -Iinclude -Isrc $(addprefix -Isrc/,$(CORE_MODULES))
HOST_CPPFLAGS := $(CPPFLAGS_CORE) -Isim -Isim/model -Itests -D_POSIX_C_SOURCE=200809L
SAN := -O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer

CORE_SRC := $(sort $(foreach m,$(CORE_MODULES),$(wildcard src/$(m)/*.c)))
CORE_HDR := $(wildcard include/*.h src/*.h src/*/*.h)
# sim/model/: the float and bit-true models, the specification the tests
# hold the core to; sim/imgio.c: the image files the tools and tests read.
SIM_SRC := sim/model/bloom_model.c sim/imgio.c sim/model/model_presets.c \
           $(filter-out sim/model/model_presets.c,$(sort $(wildcard sim/model/model_*.c)))
SIM_HDR := sim/model/bloom_model.h sim/model/model_cod.h sim/imgio.h
TESTS := $(patsubst tests/%.c,%,$(wildcard tests/test_*.c))
# Make targets `make test` runs after the test binaries, one verdict each
# (tests/verdict.sh: a closing line "N passed, N failed, N skipped" or, for
# a recipe that is its own check, its exit status; a line "skipped: WHAT:
# WHY" names a skip, and under CI=true fails).
CHECKS := test-runner check-layout check-format freestanding clang-build check-tables test-small test-precision test-clang-san

.PHONY: all test test-runner check-layout check-format format demo freestanding tables check-tables deps clean clang-build memtable tile-table test-small test-precision test-clang-san
.DELETE_ON_ERROR:

all: $(B)/libbloom.a $(B)/bloom_demo $(B)/bloom_info

# ---- optimised host build ------------------------------------------------
$(B)/obj/%.o: src/%.c $(CORE_HDR) | $(B)/obj
	@mkdir -p $(@D)
	$(CC) $(WARN) $(CFLAGS) $(CPPFLAGS_CORE) -c $< -o $@
$(B)/libbloom.a: $(patsubst src/%.c,$(B)/obj/%.o,$(CORE_SRC))
	rm -f $@ && ar rcs $@ $^
$(B)/bloom_demo: sim/bloom_demo.c $(SIM_SRC) $(SIM_HDR) $(B)/libbloom.a
	$(CC) $(WARN) $(CFLAGS) $(HOST_CPPFLAGS) sim/bloom_demo.c $(SIM_SRC) $(B)/libbloom.a -lm -o $@
$(B)/bloom_info: sim/bloom_info.c sim/bench/tile_strips.h $(B)/libbloom.a
	$(CC) $(WARN) $(CFLAGS) $(CPPFLAGS_CORE) $< $(B)/libbloom.a -o $@
memtable: $(B)/bloom_info
	$(B)/bloom_info
# make tile-table (issue 14, item 2): workspace and callgrind instructions of
# a tiling in strips against the untiled frame, sim/docs/tiles.md
# (sim/bench/tile_icount.sh; installs valgrind if missing). Not a test.
$(B)/tiles/bloom_tile_icount: sim/bench/tile_icount.c sim/bench/tile_strips.h sim/bench/scene.c sim/imgio.c \
    $(B)/libbloom.a
	@mkdir -p $(@D)
	$(CC) $(WARN) $(CFLAGS) $(HOST_CPPFLAGS) -Isim/bench $(filter %.c,$^) $(B)/libbloom.a -lm -o $@
tile-table: $(B)/tiles/bloom_tile_icount $(B)/bloom_info
	@sh sim/bench/deps.sh icount
	TILE_CFLAGS='$(CFLAGS)' sh sim/bench/tile_icount.sh $(B)/tiles/bloom_tile_icount $(B)/bloom_info sim/docs/tiles.md
$(B)/gen_tables: sim/gen_tables.c | $(B)
	$(CC) $(WARN) -O2 $< -lm -o $@

# ---- sanitized test build ------------------------------------------------
# The core and the model are compiled once for every test binary.
SAN_OBJ := $(patsubst %.c,$(B)/san/obj/%.o,$(CORE_SRC) $(SIM_SRC))
$(B)/san/obj/%.o: %.c $(CORE_HDR) $(SIM_HDR)
	@mkdir -p $(@D)
	$(CC) $(WARN) $(SAN) $(HOST_CPPFLAGS) -c $< -o $@
$(B)/san/%: tests/%.c $(wildcard tests/*.h) $(SAN_OBJ) $(CORE_HDR) $(SIM_HDR) | $(B)/san
	$(CC) $(WARN) $(SAN) $(HOST_CPPFLAGS) $< $(SAN_OBJ) -lm -o $@

# Everything with clang too, warnings as errors (a compile check).
clang-build: | $(B)/clang
	@for f in $(CORE_SRC); do \
	  $(CLANG) $(WARN) -O2 $(CPPFLAGS_CORE) -c $$f -o $(B)/clang/$$(basename $$f .c).o || exit 1; done
	$(CLANG) $(WARN) -fsyntax-only $(HOST_CPPFLAGS) $(SIM_SRC) sim/bloom_demo.c sim/bloom_info.c sim/gen_tables.c tests/*.c

# Cortex-M4, freestanding: the core objects may reference memcpy/memset only.
# The compile-time switch combinations must build too (warnings as errors).
ARM_VARIANTS := "-DBLOOM_USE_RGB888=0 -DBLOOM_USE_XRGB8888=0 -DBLOOM_USE_RGBQ16=0" \
  "-DBLOOM_USE_RGB888=0 -DBLOOM_USE_XRGB8888=0 -DBLOOM_USE_RGBQ16=0 -DBLOOM_SMALL=1 -DBLOOM_USE_SKIP=0 -DBLOOM_CHECK_RINGS=0" \
  "-DBLOOM_USE_RGB565=0 -DBLOOM_USE_RGBQ16=0 -DBLOOM_SMALL=1" \
  "-DBLOOM_USE_GAMEDEV=0 -DBLOOM_USE_XNA=0 -DBLOOM_USE_ATTENUATION=0 -DBLOOM_USE_ARM=0 -DBLOOM_USE_COD=0" \
  "-DBLOOM_DARK_COPY=1"
freestanding: | $(B)/arm
	@for v in $(ARM_VARIANTS); do for f in $(CORE_SRC); do \
	  $(ARM_CC) $(WARN) -Os -mcpu=cortex-m4 -mthumb -ffreestanding $(CPPFLAGS_CORE) $$v \
	    -c $$f -o $(B)/arm/variant.o || { echo "freestanding: $$f fails with $$v"; exit 1; }; done; done
	@for f in $(CORE_SRC); do \
	  $(ARM_CC) $(WARN) -Os -mcpu=cortex-m4 -mthumb -ffreestanding $(CPPFLAGS_CORE) \
	    -c $$f -o $(B)/arm/$$(basename $$f .c).o || exit 1; done
	@$(ARM_CC) -r -nostdlib -o $(B)/arm/bloom_core.o $(patsubst %.c,$(B)/arm/%.o,$(notdir $(CORE_SRC)))
	@undef=$$($(ARM_NM) -u $(B)/arm/bloom_core.o | awk '{print $$NF}' | sort -u); \
	bad=$$(echo "$$undef" | grep -vx 'memcpy\|memset' | grep .); \
	if [ -n "$$bad" ]; then echo "freestanding: the core needs more than memcpy/memset:" $$bad; exit 1; fi; \
	echo "freestanding: Cortex-M4 core references only:" $$undef

# clang's sanitizers check more than gcc's (an offset on a null pointer, ...).
CLANGSAN_OBJ := $(patsubst %.c,$(B)/clangsan/obj/%.o,$(CORE_SRC) $(SIM_SRC))
$(B)/clangsan/obj/%.o: %.c $(CORE_HDR) $(SIM_HDR)
	@mkdir -p $(@D)
	$(CLANG) $(WARN) $(SAN) $(HOST_CPPFLAGS) -c $< -o $@
$(B)/clangsan/%: tests/%.c $(wildcard tests/*.h) $(CLANGSAN_OBJ) $(CORE_HDR) $(SIM_HDR)
	@mkdir -p $(B)/clangsan
	$(CLANG) $(WARN) $(SAN) $(HOST_CPPFLAGS) $< $(CLANGSAN_OBJ) -lm -o $@
test-clang-san: $(B)/clangsan/test_core $(B)/clangsan/test_extreme
	@for t in test_core test_extreme; do \
	  sh tests/runbin.sh "clang -fsanitize=address,undefined: $$t" '^$$' -- \
	    env BLOOM_DATA_DIR=tests/data $(B)/clangsan/$$t || st=1; done; exit $${st:-0}

# The size-optimized core (BLOOM_SMALL) must compute the same bits.
$(B)/small/%: tests/%.c $(wildcard tests/*.h) $(CORE_SRC) $(CORE_HDR) $(SIM_SRC) $(SIM_HDR)
	@mkdir -p $(B)/small
	$(CC) $(WARN) -O2 -DBLOOM_SMALL=1 $(HOST_CPPFLAGS) $< $(CORE_SRC) $(SIM_SRC) -lm -o $@
test-small: $(B)/small/test_conformance $(B)/small/test_core
	@sh tests/runbin.sh "BLOOM_SMALL=1 (binary-search encoder, no per-format copies): test_conformance" '^$$' -- \
	  env BLOOM_DATA_DIR=tests/data $(B)/small/test_conformance; a=$$?; \
	sh tests/runbin.sh "BLOOM_SMALL=1: test_core" '^$$' -- $(B)/small/test_core && exit $$a

# Fewer internal fraction bits (BLOOM_LIN_BITS = F): tables generated for F,
# and the conformance test must stay bit-exact with the bit-true model at F.
PRECISIONS := 16 18
$(B)/f%/bloom_tables.c: $(B)/gen_tables
	@mkdir -p $(dir $@)
	$(B)/gen_tables $* > $@
$(B)/f%/test_conformance: tests/test_conformance.c tests/conform.h tests/testutil.h $(CORE_SRC) $(CORE_HDR) $(SIM_SRC) $(SIM_HDR) $(B)/f%/bloom_tables.c
	$(CC) $(WARN) -O2 -DBLOOM_LIN_BITS=$* $(HOST_CPPFLAGS) $< $(filter-out src/pixel/bloom_tables.c,$(CORE_SRC)) \
	  $(B)/f$*/bloom_tables.c $(SIM_SRC) -lm -o $@
test-precision: $(foreach f,$(PRECISIONS),$(B)/f$(f)/test_conformance)
	@for f in $(PRECISIONS); do \
	  sh tests/runbin.sh "BLOOM_LIN_BITS=$$f:" "bit-true|vs float" -- \
	    env BLOOM_DATA_DIR=tests/data $(B)/f$$f/test_conformance || st=1; done; exit $${st:-0}

tables: $(B)/gen_tables
	$(B)/gen_tables > src/pixel/bloom_tables.c
check-tables: $(B)/gen_tables
	$(B)/gen_tables | cmp -s - src/pixel/bloom_tables.c || { echo "src/pixel/bloom_tables.c is stale: run make tables"; exit 1; }

deps:
	sh tests/deps.sh

# The C sources follow .clang-format (generated tables switch it off for
# their data); make format applies it.
FORMAT_SRC = $(shell git ls-files '*.c' '*.h' '*.cpp' 2>/dev/null)
check-layout:
	sh tests/check_layout.sh
check-format:
	@command -v clang-format >/dev/null 2>&1 || \
	  { echo "skipped: check-format: clang-format not installed (Debian clang-format)"; exit 0; }; \
	bad=""; for f in $(FORMAT_SRC); do clang-format --dry-run -Werror "$$f" >/dev/null 2>&1 || bad="$$bad $$f"; done; \
	if [ -n "$$bad" ]; then echo "not formatted (make format):$$bad"; exit 1; fi; \
	echo "check-format: $(words $(FORMAT_SRC)) files follow .clang-format"
format:
	clang-format -i $(FORMAT_SRC)

# The runner's self-test: stand-ins that crash, fail or miscount, through
# the same machinery, must each be reported as a failure.
test-runner:
	@B=$(B) sh tests/selftest/selftest.sh

# The test binaries build two at a time (one make, so no races); the
# checks then run one after another.
test: deps
	$(MAKE) -j2 $(addprefix $(B)/san/,$(TESTS))
	BLOOM_DATA_DIR=tests/data sh tests/run.sh $(B)/san $(TESTS) -- $(CHECKS)

demo: deps $(B)/bloom_demo
	$(B)/bloom_demo tests/data/rocket_floodlights.ppm $(B)/demo/rocket --threshold 0.6 --intensity 1.5
	$(B)/bloom_demo tests/data/studio_lamps.pfm $(B)/demo/studio --threshold 2

$(B) $(B)/obj $(B)/san $(B)/clang $(B)/arm:
	mkdir -p $@

clean:
	rm -rf $(B)

# Ports, cross builds and host tools keep their rules in their own fragments.
-include $(wildcard port/*/*.mk sim/*.mk tests/*.mk)
