# Linux SBC port: build/bloom_cam (V4L2 camera -> bloom -> framebuffer, GPIO
# through libgpiod v1). Included by the top Makefile.
#   make bloom_cam          build/bloom_cam (with GPIO when libgpiod 1.x is installed)
#   make bloom_cam_static   build/linux/bloom_cam.static (for an initramfs or a board)
#   make test-linux-host    pure parts and the --threads frame path, no device needed
#                           (a CHECKS target of make test)
#   make test-linux         against the kernel's own vivid/bochs-drm/vfb drivers
#                           under qemu-system-x86_64 (port/linux/kernel/run.sh),
#                           also a CHECKS target of make test
#   make soak-cam           20 000 frames under qemu with faults injected at
#                           random intervals; RSS, descriptors and mappings
#                           compared (a short soak is part of test-linux)
#   make bench-cam          row by row against --threads, this machine, no device
#
# Debian packages: libjpeg62-turbo-dev (MJPEG capture: required, as for
# bloom_sim); libgpiod-dev (optional: without it --gpio-* are refused);
# for test-linux also qemu-system-x86, busybox-static (installed by run.sh
# when missing), gcc-12 (the kernel's compiler, for gpio-sim) and the packages
# run.sh downloads (never installs) into build/linux/kernel: linux-image-KVER,
# linux-headers-KVER with its -common and linux-kbuild, linux-source.

CAM_DIR := port/linux
# --threads: port/threads' pool (bloom_mt.c, -pthread). The paths are spelt
# here: threads.mk is included after this file, and a rule's prerequisites
# are expanded as it is read.
CAM_MT_SRC := port/threads/bloom_mt.c
CAM_MT_HDR := port/threads/bloom_mt.h
CAM_SRC := $(CAM_DIR)/main.c $(CAM_DIR)/cam_opts.c $(CAM_DIR)/cam_conv.c $(CAM_DIR)/cam_fmt.c $(CAM_DIR)/v4l2.c $(CAM_DIR)/v4l2_fmt.c \
           $(CAM_DIR)/cam_aux.c $(CAM_DIR)/cam_mjpeg.c $(CAM_DIR)/cam_stats.c $(CAM_DIR)/cam_engines.c $(CAM_DIR)/drm.c $(CAM_DIR)/drm_pick.c \
           $(CAM_DIR)/fbdev.c $(CAM_DIR)/gpio.c $(CAM_DIR)/cam_mt.c $(CAM_MT_SRC)
CAM_HDR := $(CAM_DIR)/cam.h $(CAM_DIR)/cam_conv.h $(CAM_DIR)/test_jpeg.h $(CAM_MT_HDR)
CAM_CPPFLAGS := $(CPPFLAGS_CORE) -Iport/threads -D_POSIX_C_SOURCE=200809L
CAM_THREAD_LIBS := -pthread
# libgpiod: the v1 API (1.x) only; v2 or none compiles the GPIO module out.
CAM_GPIOD_VER := $(shell pkg-config --modversion libgpiod 2>/dev/null)
ifneq ($(filter 1.%,$(CAM_GPIOD_VER)),)
CAM_GPIO_CFLAGS := $(shell pkg-config --cflags libgpiod 2>/dev/null)
CAM_GPIO_LIBS := $(or $(shell pkg-config --libs libgpiod 2>/dev/null),-lgpiod)
else
CAM_GPIO_CFLAGS := -DCAM_NO_GPIOD
CAM_GPIO_LIBS :=
endif

# MJPEG capture: libjpeg's scanline API (Debian libjpeg62-turbo-dev, as
# bloom_sim; tests/deps.sh): required. The package ships libjpeg.a too, for
# the static build.
CAM_JPEG_LIBS := -ljpeg

# libdrm (Debian libdrm-dev, tests/deps.sh): the DRM/KMS output (drm.c);
# without it --display drm is refused. The static build links libdrm.a
# (libdrm-dev ships it) when it is there, else builds the DRM output out.
CAM_DRM_CFLAGS := $(or $(shell pkg-config --cflags libdrm 2>/dev/null),-DCAM_NO_DRM)
CAM_DRM_LIBS := $(if $(filter -DCAM_NO_DRM,$(CAM_DRM_CFLAGS)),,$(or $(shell pkg-config --libs libdrm 2>/dev/null),-ldrm))
CAM_DRM_A := $(wildcard $(shell pkg-config --variable=libdir libdrm 2>/dev/null)/libdrm.a)
CAM_DRM_STATIC_CFLAGS := $(if $(CAM_DRM_A),$(CAM_DRM_CFLAGS),-DCAM_NO_DRM)
CAM_DRM_STATIC_LIBS := $(if $(CAM_DRM_A),$(CAM_DRM_LIBS) -lm)

CHECKS += test-linux-host
# Under qemu TCG, about 30 s on 2 cores (the first run also downloads the
# kernel, headers and source packages and builds gpio-sim: about 25 s more;
# their versions are resolved from apt's lists when it runs, see run.sh);
# it installs qemu-system-x86 and busybox-static itself when run as root, and
# prints "skipped: test-linux ...: why" (counted, in "N passed, N failed,
# N skipped") for each case it cannot run where they, the kernel packages or
# gpio-sim cannot be had; under CI=true those are failures instead.
CHECKS += test-linux
.PHONY: bloom_cam bloom_cam_static test-linux-host test-linux soak-cam linux-clang bench-cam

bloom_cam: $(B)/bloom_cam
bloom_cam_static: $(B)/linux/bloom_cam.static

$(B)/bloom_cam: $(CAM_SRC) $(CAM_HDR) $(B)/libbloom.a
	$(CC) $(WARN) $(CFLAGS) $(CAM_CPPFLAGS) $(CAM_GPIO_CFLAGS) $(CAM_DRM_CFLAGS) $(CAM_SRC) $(B)/libbloom.a \
	  $(CAM_GPIO_LIBS) $(CAM_DRM_LIBS) $(CAM_JPEG_LIBS) $(CAM_THREAD_LIBS) -o $@

# Static, for the test initramfs (and boards without the shared libraries).
$(B)/linux/bloom_cam.static: $(CAM_SRC) $(CAM_HDR) $(CORE_SRC) $(CORE_HDR)
	@mkdir -p $(@D)
	$(CC) $(WARN) -O2 -static $(CAM_CPPFLAGS) $(CAM_GPIO_CFLAGS) $(CAM_DRM_STATIC_CFLAGS) $(CAM_SRC) $(CORE_SRC) \
	  $(CAM_GPIO_LIBS) $(CAM_DRM_STATIC_LIBS) $(CAM_JPEG_LIBS) $(CAM_THREAD_LIBS) -o $@

# Host tests of the pure parts, sanitized, against the simulator's own
# Y'CbCr rule (sim/sim_convert.c) and a double reference, and of
# cam_v4l2_dequeue's faults through the ioctl/poll seam in cam_v4l2_t (a
# scripted fake, no device). The GPIO module is
# built out here so the refusal of --gpio-* is what is tested.
# test_cam_mt: the --threads frame path (cam_mt.c on the real pool) against
# the untiled engine, every format, placement and mode, under the sanitizers.
CAM_TEST_SRC := $(CAM_DIR)/test_host.c $(CAM_DIR)/test_conv.c $(CAM_DIR)/test_dequeue.c $(CAM_DIR)/cam_opts.c $(CAM_DIR)/cam_conv.c \
                $(CAM_DIR)/cam_fmt.c $(CAM_DIR)/gpio.c \
                $(CAM_DIR)/cam_aux.c \
                $(CAM_DIR)/v4l2.c $(CAM_DIR)/v4l2_fmt.c $(CAM_DIR)/drm_pick.c $(CAM_DIR)/cam_mjpeg.c
# (test_conv.c reads its frames back through bloom_sim's own raw reader:
# sim_source.c and the decoders it links, with sim.mk's flags and libraries.)
CAM_TEST_SIM := sim/sim_convert.c sim/sim_source.c sim/sim_png.c sim/sim_jpeg.c sim/sim_exr.c
$(B)/linux/test_cam_host: $(CAM_TEST_SRC) $(CAM_HDR) $(CORE_SRC) $(CORE_HDR) $(CAM_TEST_SIM) sim/sim.h \
                          $(SIM_SRC) $(SIM_HDR)
	@mkdir -p $(@D)
	$(CC) $(WARN) $(SAN) $(HOST_CPPFLAGS) -Iport/threads -DCAM_NO_GPIOD -DCAM_NO_DRM $(SIMTOOL_PNG_CFLAGS) \
	  $(SIMTOOL_EXR_CFLAGS) $(CAM_TEST_SRC) $(CAM_TEST_SIM) $(SIM_SRC) $(CORE_SRC) $(SIMTOOL_LIBS) -o $@

# test_cam_mjpeg: MJPEG capture (cam_mjpeg.c) against bloom_sim's JPEG
# reader (sim/sim_jpeg.c) on frames it encodes with libjpeg; corrupt,
# truncated, DHT-less and wrongly sized frames.
CAM_MJPEG_TEST_SRC := $(CAM_DIR)/test_mjpeg.c $(CAM_DIR)/cam_mjpeg.c $(CAM_DIR)/cam_fmt.c $(CAM_DIR)/cam_conv.c \
                      $(CAM_DIR)/cam_opts.c $(CAM_DIR)/gpio.c $(CAM_DIR)/drm_pick.c
$(B)/linux/test_cam_mjpeg: $(CAM_MJPEG_TEST_SRC) $(CAM_HDR) $(CORE_SRC) $(CORE_HDR) $(CAM_TEST_SIM) sim/sim.h \
                           $(SIM_SRC) $(SIM_HDR) tests/harness.h
	@mkdir -p $(@D)
	$(CC) $(WARN) $(SAN) $(HOST_CPPFLAGS) -Iport/threads -DCAM_NO_GPIOD -DCAM_NO_DRM $(SIMTOOL_PNG_CFLAGS) \
	  $(SIMTOOL_EXR_CFLAGS) $(CAM_MJPEG_TEST_SRC) $(CAM_TEST_SIM) $(SIM_SRC) $(CORE_SRC) $(SIMTOOL_LIBS) -o $@

# test_drm: the DRM output's pure rules (drm_pick.c: mode and format
# choice, auto's rule) and the display options (no device is opened).
CAM_DRM_TEST_SRC := $(CAM_DIR)/test_drm.c $(CAM_DIR)/cam_opts.c $(CAM_DIR)/cam_fmt.c $(CAM_DIR)/cam_conv.c \
                    $(CAM_DIR)/drm_pick.c $(CAM_DIR)/gpio.c
$(B)/linux/test_cam_drm: $(CAM_DRM_TEST_SRC) $(CAM_HDR) $(CORE_SRC) $(CORE_HDR) tests/harness.h
	@mkdir -p $(@D)
	$(CC) $(WARN) $(SAN) $(HOST_CPPFLAGS) -Iport/threads -DCAM_NO_GPIOD $(CAM_DRM_CFLAGS) $(CAM_DRM_TEST_SRC) \
	  $(CORE_SRC) -lm -o $@

CAM_MT_TEST_SRC := $(CAM_DIR)/test_cam_mt.c $(CAM_DIR)/cam_mt.c $(CAM_DIR)/cam_conv.c $(CAM_DIR)/cam_fmt.c \
                   $(CAM_DIR)/cam_mjpeg.c $(CAM_MT_SRC)
$(B)/linux/test_cam_mt: $(CAM_MT_TEST_SRC) $(CAM_HDR) $(CORE_SRC) $(CORE_HDR) tests/harness.h
	@mkdir -p $(@D)
	$(CC) $(WARN) $(SAN) $(HOST_CPPFLAGS) -Iport/threads $(CAM_MT_TEST_SRC) $(CORE_SRC) -lm \
	  $(CAM_JPEG_LIBS) $(CAM_THREAD_LIBS) -o $@

# make bench-cam: the two frame paths on this machine (port/linux/bench_cam.c),
# 640x480 and 1920x1080 by default; BENCH_CAM_ARGS='1280x720 -t 3' for others.
BENCH_CAM_SRC := $(CAM_DIR)/bench_cam.c $(CAM_DIR)/cam_mt.c $(CAM_DIR)/cam_conv.c $(CAM_DIR)/cam_fmt.c \
                 $(CAM_DIR)/cam_mjpeg.c
$(B)/linux/bench_cam: $(BENCH_CAM_SRC) $(CAM_MT_SRC) $(CAM_HDR) \
                      sim/bench/timing.h $(B)/libbloom.a
	@mkdir -p $(@D)
	$(CC) $(WARN) $(CFLAGS) $(CAM_CPPFLAGS) -Isim/bench $(BENCH_CAM_SRC) \
	  $(CAM_MT_SRC) $(B)/libbloom.a $(CAM_JPEG_LIBS) $(CAM_THREAD_LIBS) -o $@
bench-cam: $(B)/linux/bench_cam
	@$(B)/linux/bench_cam $(BENCH_CAM_ARGS)

# clang, warnings as errors, both GPIO variants (a compile check).
linux-clang:
	$(CLANG) $(WARN) -fsyntax-only $(CAM_CPPFLAGS) $(CAM_GPIO_CFLAGS) $(CAM_DRM_CFLAGS) $(CAM_SRC)
	$(CLANG) $(WARN) -fsyntax-only $(CAM_CPPFLAGS) -DCAM_NO_GPIOD -DCAM_NO_DRM $(CAM_SRC)
	$(CLANG) $(WARN) -fsyntax-only $(CAM_CPPFLAGS) -Isim/bench -DCAM_NO_GPIOD $(CAM_DIR)/bench_cam.c
	$(CLANG) $(WARN) -fsyntax-only $(HOST_CPPFLAGS) -Iport/threads $(CAM_DIR)/test_host.c $(CAM_DIR)/test_conv.c $(CAM_DIR)/test_dequeue.c \
	  $(CAM_DIR)/test_cam_mt.c $(CAM_DIR)/test_drm.c $(CAM_DIR)/test_mjpeg.c

test-linux-host: $(B)/linux/test_cam_host $(B)/linux/test_cam_mt $(B)/linux/test_cam_drm \
                 $(B)/linux/test_cam_mjpeg $(B)/bloom_cam
	@$(MAKE) --no-print-directory linux-clang >/dev/null
	@$(B)/linux/test_cam_host
	@$(B)/linux/test_cam_mt
	@$(B)/linux/test_cam_drm
	@$(B)/linux/test_cam_mjpeg
	@sh $(CAM_DIR)/test_cli.sh $(B)/bloom_cam

test-linux: $(B)/linux/bloom_cam.static $(B)/bloom_sim
	@B='$(B)' sh $(CAM_DIR)/kernel/run.sh

# The soak alone, 20 000 frames (860 s of them in the last run, about 20
# minutes in all under TCG); SOAK_FRAMES
# and SOAK_SEED override.
soak-cam: $(B)/linux/bloom_cam.static $(B)/bloom_sim
	@B='$(B)' SOAK_FRAMES=$${SOAK_FRAMES:-20000} SOAK_ONLY=1 LINUX_TEST_TIMEOUT=$${LINUX_TEST_TIMEOUT:-5400} \
	  sh $(CAM_DIR)/kernel/run.sh
