# bloom_sim: recorded frames through the engine and the float model
# (sim/docs/simulator.md). Included by the top Makefile.
#   make sim        build/bloom_sim (installs libpng/libjpeg/OpenEXR headers if missing)
#   make test-sim   the simulator's tests (a CHECKS target of make test)
#
# Debian packages: libpng-dev, libjpeg62-turbo-dev (libjpeg-dev), libopenexr-dev,
# pkg-config. Without the OpenEXR headers the tool builds without EXR input.

SIMTOOL_SRC := sim/bloom_sim.c sim/sim_opts.c sim/sim_usage.c sim/sim_source.c sim/sim_convert.c \
               sim/sim_out.c sim/sim_png.c sim/sim_jpeg.c sim/sim_exr.c sim/sim_aux.c \
               port/threads/bloom_mt.c
SIMTOOL_HDR := sim/sim.h port/threads/bloom_mt.h
SIMTEST_SRC := tests/sim/simtest.c tests/sim/simtest_formats.c tests/sim/simtest_errors.c \
               tests/sim/simtest_gen.c tests/sim/simtest_util.c tests/sim/simtest_presets.c
SIMTEST_HDR := tests/sim/simtest.h tests/sim/simtest_cases.h

SIMTOOL_PNG_CFLAGS := $(shell pkg-config --cflags libpng 2>/dev/null)
SIMTOOL_PNG_LIBS := $(or $(shell pkg-config --libs libpng 2>/dev/null),-lpng)
SIMTOOL_EXR_INC := $(shell pkg-config --variable=OpenEXR_includedir OpenEXR 2>/dev/null)
SIMTOOL_EXR_SUFFIX := $(shell pkg-config --variable=libsuffix OpenEXR 2>/dev/null)
ifneq ($(wildcard $(SIMTOOL_EXR_INC)/openexr.h),)
SIMTOOL_EXR_CFLAGS := -I$(SIMTOOL_EXR_INC)
SIMTOOL_EXR_LIBS := -lOpenEXRCore$(SIMTOOL_EXR_SUFFIX)
else
SIMTOOL_EXR_CFLAGS := -DSIM_NO_EXR
SIMTOOL_EXR_LIBS :=
endif
# --threads: the strip helper of port/threads (POSIX threads).
SIMTOOL_CFLAGS := $(HOST_CPPFLAGS) -Iport/threads $(SIMTOOL_PNG_CFLAGS) $(SIMTOOL_EXR_CFLAGS)
SIMTOOL_LIBS := $(SIMTOOL_PNG_LIBS) -ljpeg $(SIMTOOL_EXR_LIBS) -lm -lpthread

CHECKS += test-sim
.PHONY: sim test-sim sim-deps sim-check

# Installs what is missing (apt-get, as root or through sudo), quietly when
# everything is there.
sim-deps:
	@need=""; \
	[ -f /usr/include/png.h ] || [ -f /usr/include/libpng16/png.h ] || need="$$need libpng-dev"; \
	[ -f /usr/include/jpeglib.h ] || [ -f /usr/include/$$(gcc -print-multiarch 2>/dev/null)/jpeglib.h ] || need="$$need libjpeg62-turbo-dev"; \
	[ -f /usr/include/OpenEXR/openexr.h ] || need="$$need libopenexr-dev"; \
	command -v pkg-config >/dev/null 2>&1 || need="$$need pkg-config"; \
	if [ -n "$$need" ]; then \
	  echo "sim-deps: installing$$need"; \
	  SUDO=""; [ "$$(id -u)" -ne 0 ] && SUDO="sudo"; \
	  export DEBIAN_FRONTEND=noninteractive; \
	  $$SUDO apt-get update -qq && $$SUDO apt-get install -y -qq --no-install-recommends $$need >/dev/null; \
	fi

# A fresh make after sim-deps, so that the pkg-config look-ups above see
# the packages it may just have installed.
sim: sim-deps
	@$(MAKE) --no-print-directory $(B)/bloom_sim

test-sim: sim-deps
	@$(MAKE) --no-print-directory sim-check

$(B)/bloom_sim: $(SIMTOOL_SRC) $(SIMTOOL_HDR) $(SIM_SRC) $(SIM_HDR) $(B)/libbloom.a
	$(CC) $(WARN) $(CFLAGS) $(SIMTOOL_CFLAGS) $(SIMTOOL_SRC) $(SIM_SRC) $(B)/libbloom.a $(SIMTOOL_LIBS) -o $@

# Sanitized tool and test program (the tests run the sanitized tool).
$(B)/sim/bloom_sim: $(SIMTOOL_SRC) $(SIMTOOL_HDR) $(SIM_SRC) $(SIM_HDR) $(CORE_SRC) $(CORE_HDR)
	@mkdir -p $(@D)
	$(CC) $(WARN) $(SAN) $(SIMTOOL_CFLAGS) $(SIMTOOL_SRC) $(SIM_SRC) $(CORE_SRC) $(SIMTOOL_LIBS) -o $@
$(B)/sim/simtest: $(SIMTEST_SRC) $(SIMTEST_HDR) tests/harness.h $(SIM_SRC) $(SIM_HDR) $(CORE_SRC) $(CORE_HDR)
	@mkdir -p $(@D)
	$(CC) $(WARN) $(SAN) $(SIMTOOL_CFLAGS) -Itests/sim $(SIMTEST_SRC) $(SIM_SRC) $(CORE_SRC) $(SIMTOOL_LIBS) -o $@

# clang -Werror over the simulator and its tests, then the tests against the
# sanitized tool and the optimised build/bloom_sim.
sim-check: $(B)/bloom_sim $(B)/sim/bloom_sim $(B)/sim/simtest
	$(CLANG) $(WARN) -fsyntax-only $(SIMTOOL_CFLAGS) -Itests/sim $(SIMTOOL_SRC) $(SIMTEST_SRC)
	$(B)/sim/simtest $(B)/sim/bloom_sim $(B)/bloom_sim
