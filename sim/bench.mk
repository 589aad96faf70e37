# Benchmarks (issue 7): not tests, so nothing here joins CHECKS.
#   make bench    the engine against a cold memcpy, OpenCV 4 and the float
#                 model at 640x480, 1280x720, 1920x1080: prints the table,
#                 writes build/bench.csv, sim/docs/bench.csv, sim/docs/bench.md
#                 (installs libopencv-dev, g++, pkg-config if missing)
#   make icount   instructions per output pixel of one bloom_process call
#                 under callgrind, per engine row and stage: sim/docs/icount.md
#                 (installs valgrind if missing)
#   make bench-peers  (run by make bench too) the GStreamer element against
#                 frei0r's glow and videoconvert, the engine against ffmpeg's
#                 gblur glow and GEGL's gegl:bloom, 1920x1080, one thread,
#                 ratios of paired rounds: sim/docs/bench-peers.md
#                 (sim/bench/peers.sh; installs ffmpeg, frei0r-plugins,
#                 gstreamer1.0-plugins-bad, libgegl-dev: peers_deps.sh)
#   make profile  where the time goes per stage: perf samples of the same
#                 binary repeating the frame call, sim/docs/profile.md
#                 (installs linux-perf if missing; skips if perf may not sample)
# Knobs: BENCH_CFLAGS (engine and harness for bench; default CFLAGS),
# BENCH_ARGS (options of bloom_bench, e.g. --quick or --sizes 640x480),
# ICOUNT_SIZES (default 640x480 1920x1080).

BENCH_DIR := $(B)/bench
ICOUNT_DIR := $(B)/icount
BENCH_CFLAGS ?= $(CFLAGS)
BENCH_CXXFLAGS ?= $(BENCH_CFLAGS)
BENCH_ARGS ?=
ICOUNT_CFLAGS := -O2 -g
ICOUNT_SIZES ?= 640x480 1920x1080
BENCH_CXXWARN := -std=c++17 -Wall -Wextra -Werror -Wshadow -Wpointer-arith -Wcast-align -Wvla

BENCH_HDR := sim/bench/bench.h sim/bench/bench_cv.h sim/bench/scene.h sim/bench/variants.h sim/bench/timing.h
# Every core header, also ones added to src/ after CORE_HDR was written.
BENCH_CORE_HDR := $(sort $(CORE_HDR) $(wildcard src/*.h src/*/*.h include/*.h))
BENCH_CORE_OBJ := $(patsubst src/%.c,$(BENCH_DIR)/core/%.o,$(CORE_SRC))
BENCH_SIM_OBJ := $(patsubst sim/%.c,$(BENCH_DIR)/sim/%.o,$(SIM_SRC))
BENCH_OBJ := $(addprefix $(BENCH_DIR)/obj/,bench.o bench_time.o bench_out.o bench_machine.o scene.o variants.o bench_opencv.o)
ICOUNT_CORE_OBJ := $(patsubst src/%.c,$(ICOUNT_DIR)/core/%.o,$(CORE_SRC))
ICOUNT_SRC := sim/bench/icount.c sim/bench/scene.c sim/bench/variants.c sim/imgio.c

# Read when a recipe runs, that is after bench-deps has installed OpenCV.
BENCH_CV_CFLAGS = $(patsubst -I%,-isystem %,$(shell pkg-config --cflags opencv4))
BENCH_CV_LIBS = $(filter-out -lopencv_%,$(shell pkg-config --libs opencv4)) -lopencv_imgproc -lopencv_core

.PHONY: bench icount profile bench-deps icount-deps profile-deps bench-force bench-peers bench-threads

bench-deps:
	@sh sim/bench/deps.sh bench
icount-deps:
	@sh sim/bench/deps.sh icount

# Rebuild when the compiler or the flags change.
$(BENCH_DIR)/cflags: bench-force
	@mkdir -p $(@D)
	@echo '$(CC) $(CXX) $(BENCH_CFLAGS) $(BENCH_CXXFLAGS)' | cmp -s - $@ || \
	  echo '$(CC) $(CXX) $(BENCH_CFLAGS) $(BENCH_CXXFLAGS)' > $@

$(BENCH_DIR)/core/%.o: src/%.c $(BENCH_CORE_HDR) $(BENCH_DIR)/cflags
	@mkdir -p $(@D)
	$(CC) $(WARN) $(BENCH_CFLAGS) $(CPPFLAGS_CORE) -c $< -o $@
$(BENCH_DIR)/sim/%.o: sim/%.c $(SIM_HDR) $(BENCH_DIR)/cflags
	@mkdir -p $(@D)
	$(CC) $(WARN) $(BENCH_CFLAGS) $(HOST_CPPFLAGS) -c $< -o $@
$(BENCH_DIR)/obj/%.o: sim/bench/%.c $(BENCH_HDR) $(BENCH_CORE_HDR) $(BENCH_DIR)/cflags
	@mkdir -p $(@D)
	$(CC) $(WARN) $(BENCH_CFLAGS) $(HOST_CPPFLAGS) \
	  -DBENCH_CC='"$(CC)"' -DBENCH_FLAGS='"$(BENCH_CFLAGS)"' -c $< -o $@
$(BENCH_DIR)/obj/bench_opencv.o: sim/bench/bench_opencv.cpp sim/bench/bench_cv.h $(BENCH_DIR)/cflags | bench-deps
	@mkdir -p $(@D)
	$(CXX) $(BENCH_CXXWARN) $(BENCH_CXXFLAGS) $(BENCH_CV_CFLAGS) -c $< -o $@
$(BENCH_DIR)/bloom_bench: $(BENCH_OBJ) $(BENCH_SIM_OBJ) $(BENCH_CORE_OBJ) | bench-deps
	$(CXX) $(BENCH_CXXFLAGS) $^ $(BENCH_CV_LIBS) -lm -o $@

bench: bench-deps $(BENCH_DIR)/bloom_bench
	$(BENCH_DIR)/bloom_bench --csv $(B)/bench.csv --md $(BENCH_DIR)/results.md $(BENCH_ARGS)
	cp $(B)/bench.csv sim/docs/bench.csv
	cat $(BENCH_DIR)/results.md sim/bench/method.md > sim/docs/bench.md
	@echo "bench: wrote sim/docs/bench.md and sim/docs/bench.csv"
	$(MAKE) --no-print-directory bench-peers
	$(MAKE) --no-print-directory bench-threads

# The peers (issue 15): peers.sh installs them, builds the element (make gst)
# and the GEGL driver itself, so that a peer that cannot be had is named on
# the page with its reason instead of stopping the target.
$(BENCH_DIR)/peers_drv: sim/bench/peers_drv.c $(BENCH_DIR)/obj/scene.o $(BENCH_SIM_OBJ) $(BENCH_CORE_OBJ)
	$(CC) $(WARN) $(BENCH_CFLAGS) $(HOST_CPPFLAGS) $^ -lm -o $@
bench-peers: $(BENCH_DIR)/peers_drv
	MAKE='$(MAKE)' CC='$(CC)' PEERS_CFLAGS='$(BENCH_CFLAGS)' \
	  bash sim/bench/peers.sh $(BENCH_DIR)/peers_drv $(BENCH_DIR)/peers sim/docs/bench-peers.md

# Threads (issue 14): 1 vs 2 threads in paired rounds and the halo's
# instructions for 4 strips (callgrind), port/threads/bench_threads.sh;
# the helper and its flags are port/threads/threads.mk's.
$(BENCH_DIR)/bench_threads: port/threads/bench_threads.c sim/bench/timing.h $(MT_SRC) $(MT_HDR) $(BENCH_DIR)/obj/scene.o $(BENCH_DIR)/sim/imgio.o \
                            $(BENCH_CORE_OBJ)
	$(CC) $(WARN) $(BENCH_CFLAGS) $(HOST_CPPFLAGS) -Isim/bench $(MT_CPPFLAGS) port/threads/bench_threads.c $(MT_SRC) \
	  $(BENCH_DIR)/obj/scene.o $(BENCH_DIR)/sim/imgio.o $(BENCH_CORE_OBJ) -lm $(MT_LIBS) -o $@
bench-threads: icount-deps $(BENCH_DIR)/bench_threads
	sh port/threads/bench_threads.sh $(BENCH_DIR)/bench_threads sim/docs/threads.md

# Instruction counts: the core without -march=native, plain -O2.
$(ICOUNT_DIR)/core/%.o: src/%.c $(BENCH_CORE_HDR)
	@mkdir -p $(@D)
	$(CC) $(WARN) $(ICOUNT_CFLAGS) $(CPPFLAGS_CORE) -c $< -o $@
$(ICOUNT_DIR)/bloom_icount: $(ICOUNT_SRC) $(BENCH_HDR) $(SIM_HDR) $(ICOUNT_CORE_OBJ)
	$(CC) $(WARN) $(ICOUNT_CFLAGS) $(HOST_CPPFLAGS) $(ICOUNT_SRC) $(ICOUNT_CORE_OBJ) -lm -o $@

icount: icount-deps $(ICOUNT_DIR)/bloom_icount
	sh sim/bench/icount.sh $(ICOUNT_DIR)/bloom_icount sim/docs/icount.md $(ICOUNT_SIZES)

# Where the time goes per stage: perf samples of the icount binary.
profile-deps:
	@sh sim/bench/deps.sh profile
profile: profile-deps $(ICOUNT_DIR)/bloom_icount
	sh sim/bench/profile.sh $(ICOUNT_DIR)/bloom_icount sim/docs/profile.md
