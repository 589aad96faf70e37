# make report (issue 3, sections 2-4): error against run time over the
# precision knob (BLOOM_LIN_BITS F = 16..20), the level count and the row
# sample width (issue 21: 32 or 16 bits, also on the targets from
# sim/docs/targets.csv, make target-cost), the stability matrix, the skip
# savings; memory and run time against tile width (issue 14). Writes sim/docs/report.md,
# sim/docs/report_*.png and sim/docs/report_*.csv (sim/report/run.sh).
# Not a test: nothing here joins CHECKS, nothing asserts a time.
# Installs gnuplot-nox (and valgrind, through sim/bench/deps.sh) if missing.
# Knobs: REPORT_CFLAGS (default CFLAGS), REPORT_SIZES, REPORT_RUNS,
# REPORT_RUNS_BIG (see sim/report/run.sh).

REPORT_DIR := $(B)/report
REPORT_F := 16 17 18 19 20
REPORT_CFLAGS ?= $(CFLAGS)
REPORT_CPP := $(HOST_CPPFLAGS) -Isim/bench -Isim/report
# Objects that do not depend on F, built once; the core and each tool's
# main per F (the mains print F).
REPORT_SHARED := sim/report/common.c sim/report/inputs.c sim/bench/scene.c $(SIM_SRC)
REPORT_SHARED_OBJ := $(addprefix $(REPORT_DIR)/obj/,$(notdir $(REPORT_SHARED:.c=.o)))
REPORT_HDR := sim/report/report.h sim/report/stab.h sim/bench/timing.h sim/bench/scene.h sim/bench/variants.h sim/bench/tile_strips.h \
              $(SIM_HDR) $(sort $(CORE_HDR) $(wildcard src/*.h src/*/*.h include/*.h))
REPORT_BINS := $(foreach f,$(REPORT_F),$(REPORT_DIR)/f$(f)/report_sweep $(REPORT_DIR)/f$(f)/report_icount) \
               $(REPORT_DIR)/f16/report_stab $(REPORT_DIR)/f20/report_stab $(REPORT_DIR)/f20/report_skip \
               $(REPORT_DIR)/f20/report_tiles

$(REPORT_DIR)/obj/%.o: sim/report/%.c $(REPORT_HDR)
	@mkdir -p $(@D)
	$(CC) $(WARN) $(REPORT_CFLAGS) $(REPORT_CPP) -c $< -o $@
$(REPORT_DIR)/obj/%.o: sim/bench/%.c $(REPORT_HDR)
	@mkdir -p $(@D)
	$(CC) $(WARN) $(REPORT_CFLAGS) $(REPORT_CPP) -c $< -o $@
$(REPORT_DIR)/obj/%.o: sim/%.c $(REPORT_HDR)
	@mkdir -p $(@D)
	$(CC) $(WARN) $(REPORT_CFLAGS) $(REPORT_CPP) -c $< -o $@
# the models moved to sim/model/: without this a fresh build dir has no rule
$(REPORT_DIR)/obj/%.o: sim/model/%.c $(REPORT_HDR)
	@mkdir -p $(@D)
	$(CC) $(WARN) $(REPORT_CFLAGS) $(REPORT_CPP) -c $< -o $@

# The core for F ($(1)): src/pixel/bloom_tables.c is generated for 20 only.
report_tables = $(if $(filter 20,$(1)),src/pixel/bloom_tables.c,$(B)/f$(1)/bloom_tables.c)
define REPORT_CORE
$(REPORT_DIR)/f$(1)/core/%.o: src/%.c $(REPORT_HDR)
	@mkdir -p $$(@D)
	$$(CC) $$(WARN) $$(REPORT_CFLAGS) -DBLOOM_LIN_BITS=$(1) $$(CPPFLAGS_CORE) -c $$< -o $$@
$(REPORT_DIR)/f$(1)/core/tables.o: $(call report_tables,$(1)) $(REPORT_HDR)
	@mkdir -p $$(@D)
	$$(CC) $$(WARN) $$(REPORT_CFLAGS) -DBLOOM_LIN_BITS=$(1) $$(CPPFLAGS_CORE) -c $$< -o $$@
REPORT_CORE_OBJ_$(1) := $(patsubst src/%.c,$(REPORT_DIR)/f$(1)/core/%.o,$(filter-out src/pixel/bloom_tables.c,$(CORE_SRC))) \
                        $(REPORT_DIR)/f$(1)/core/tables.o
endef
$(foreach f,$(REPORT_F),$(eval $(call REPORT_CORE,$(f))))

# report_<tool> for F: $(1) = F, $(2) = tool, $(3) = its own sources.
define REPORT_BIN
$(REPORT_DIR)/f$(1)/report_$(2): $(3) $(REPORT_SHARED_OBJ) $$(REPORT_CORE_OBJ_$(1)) $(REPORT_HDR)
	@mkdir -p $$(@D)
	$$(CC) $$(WARN) $$(REPORT_CFLAGS) -DBLOOM_LIN_BITS=$(1) $$(REPORT_CPP) $(3) $$(REPORT_SHARED_OBJ) \
	  $$(REPORT_CORE_OBJ_$(1)) -lm -o $$@
endef
$(foreach f,$(REPORT_F),$(eval $(call REPORT_BIN,$(f),sweep,sim/report/sweep.c)))
$(foreach f,$(REPORT_F),$(eval $(call REPORT_BIN,$(f),icount,sim/report/icount.c)))
$(foreach f,16 20,$(eval $(call REPORT_BIN,$(f),stab,sim/report/stab.c sim/report/stab_cases.c)))
$(eval $(call REPORT_BIN,20,skip,sim/report/skip.c))
$(eval $(call REPORT_BIN,20,tiles,sim/report/tiles.c))

.PHONY: report report-deps report-build report-clang

report-deps:
	@sh sim/bench/deps.sh icount
	@command -v gnuplot >/dev/null 2>&1 || { \
	  echo "report: installing gnuplot-nox"; \
	  SUDO=""; [ "$$(id -u)" -ne 0 ] && SUDO="sudo"; \
	  export DEBIAN_FRONTEND=noninteractive; \
	  apt-cache show gnuplot-nox >/dev/null 2>&1 || $$SUDO apt-get update -qq; \
	  $$SUDO apt-get install -y -qq --no-install-recommends gnuplot-nox >/dev/null; }

report-build: $(REPORT_BINS)

# The build on two jobs (the ~10-minute budget is for 2 cores), then the run.
report: report-deps
	@$(MAKE) --no-print-directory -j2 report-build
	REPORT_CC="$(CC)" REPORT_FLAGS="$(REPORT_CFLAGS)" sh sim/report/run.sh $(REPORT_DIR) sim/docs

# The report tools with clang, warnings as errors (a compile check).
report-clang:
	$(CLANG) $(WARN) -fsyntax-only $(REPORT_CPP) sim/report/*.c
