# ARM Linux (the SBC case): the core, every unit test and the tools
# cross-built for aarch64 and 32-bit ARM hard-float, run under qemu-user;
# tests/cross.sh runs them and diffs tests/corpus_hash's listing against the
# host's. Included by the top Makefile.
#   make test-cross                      both architectures (installs the
#                                        toolchains and qemu-user if missing)
#   make test-cross CROSS_ARCHS=armhf    one of them
#   make test-cross CROSS_SKIP_TESTS=    every unit test under emulation
#                                        (about 10 min on 2 cores)
#   make cross-build                     only build build/cross/<arch>/

CROSS_ARCHS ?= aarch64 armhf
CROSS_CC_aarch64 ?= aarch64-linux-gnu-gcc
CROSS_CC_armhf ?= arm-linux-gnueabihf-gcc
# -static: qemu-user runs the binaries without a target sysroot.
CROSS_CFLAGS ?= -O2
# Unit tests built but not run under emulation by default: bound by the
# double-precision model, 280-470 s each under qemu. corpus_hash runs their
# frames through the engine and diffs with the host instead. test_tiles runs
# on aarch64 (about 95 s): the NEON twins meet the tiles' row views nowhere
# else.
CROSS_SKIP_TESTS ?= test_conformance test_extreme test_budget test_s16_budget $(filter test_preset_%,$(TESTS))
# armhf has no SIMD twins: its test_tiles would run the C kernels, which
# the host's test_tiles runs too (BLOOM_FLAG_NO_SIMD), in over 5 minutes.
CROSS_SKIP_armhf ?= test_tiles
CROSS_BINS := $(TESTS) corpus_hash bloom_demo bloom_info
CROSS_TEST_HDR := $(wildcard tests/*.h)
CROSS_CORE_HDR := $(CORE_HDR) $(wildcard include/*.h src/*.h)

CHECKS += test-cross
.PHONY: test-cross cross-build

# The host listing the ARM ones must equal (x86-64 on CI).
$(B)/corpus_hash: tests/corpus_hash.c tests/testutil.h $(SIM_SRC) $(SIM_HDR) $(B)/libbloom.a
	$(CC) $(WARN) $(CFLAGS) $(HOST_CPPFLAGS) $< $(SIM_SRC) $(B)/libbloom.a -lm -o $@

# $(1) = arch. Core and sim objects once per arch, linked into each binary.
define CROSS_RULES
$(B)/cross/$(1)/obj/%.o: src/%.c $(CROSS_CORE_HDR)
	@mkdir -p $$(@D)
	$(CROSS_CC_$(1)) $(WARN) $(CROSS_CFLAGS) $(CPPFLAGS_CORE) -c $$< -o $$@
$(B)/cross/$(1)/sim/%.o: sim/%.c $(SIM_HDR) $(CROSS_CORE_HDR)
	@mkdir -p $$(@D)
	$(CROSS_CC_$(1)) $(WARN) $(CROSS_CFLAGS) $(HOST_CPPFLAGS) -c $$< -o $$@
$(B)/cross/$(1)/%: tests/%.c $(CROSS_TEST_HDR) $(patsubst src/%.c,$(B)/cross/$(1)/obj/%.o,$(CORE_SRC)) \
                   $(patsubst sim/%.c,$(B)/cross/$(1)/sim/%.o,$(SIM_SRC))
	$(CROSS_CC_$(1)) $(WARN) $(CROSS_CFLAGS) -static $(HOST_CPPFLAGS) $$< \
	  $(patsubst src/%.c,$(B)/cross/$(1)/obj/%.o,$(CORE_SRC)) \
	  $(patsubst sim/%.c,$(B)/cross/$(1)/sim/%.o,$(SIM_SRC)) -lm -o $$@
$(B)/cross/$(1)/bloom_demo: $(B)/cross/$(1)/sim/bloom_demo.o \
                            $(patsubst src/%.c,$(B)/cross/$(1)/obj/%.o,$(CORE_SRC)) \
                            $(patsubst sim/%.c,$(B)/cross/$(1)/sim/%.o,$(SIM_SRC))
	$(CROSS_CC_$(1)) $(CROSS_CFLAGS) -static $$^ -lm -o $$@
$(B)/cross/$(1)/bloom_info: $(B)/cross/$(1)/sim/bloom_info.o \
                            $(patsubst src/%.c,$(B)/cross/$(1)/obj/%.o,$(CORE_SRC))
	$(CROSS_CC_$(1)) $(CROSS_CFLAGS) -static $$^ -o $$@
cross-build-$(1): $(addprefix $(B)/cross/$(1)/,$(CROSS_BINS))
.PHONY: cross-build-$(1)
endef
$(foreach a,$(CROSS_ARCHS),$(eval $(call CROSS_RULES,$(a))))

cross-build: $(addprefix cross-build-,$(CROSS_ARCHS))

test-cross:
	@B='$(B)' CROSS_ARCHS='$(CROSS_ARCHS)' CROSS_CC_aarch64='$(CROSS_CC_aarch64)' \
	  CROSS_CC_armhf='$(CROSS_CC_armhf)' MAKE='$(MAKE)' \
	  CROSS_TESTS='$(filter-out $(CROSS_SKIP_TESTS),$(TESTS))' CROSS_SKIP_TESTS='$(CROSS_SKIP_TESTS)' \
	  CROSS_SKIP_armhf='$(CROSS_SKIP_armhf)' \
	  sh tests/cross.sh
