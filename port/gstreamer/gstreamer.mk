# GStreamer 1.x element "bloom" (port/gstreamer/README.md). Included by the
# top Makefile.
#   make gst        build/gst/libgstbloom.so (the plugin: the element and the
#                   core's position-independent objects of install.mk)
#   make test-gst   GStreamer's check library (gstcheck-1.0) against the
#                   engine itself and build/bloom_sim (a CHECKS target of
#                   make test); the registry is build/gst/registry.bin
#   gst-inspect-1.0 build/gst/libgstbloom.so   the element's page
#
# Debian packages (tests/deps.sh installs them): libgstreamer1.0-dev,
# libgstreamer-plugins-base1.0-dev, gstreamer1.0-tools,
# gstreamer1.0-plugins-base. Without them test-gst says it skipped.

GST_DIR := port/gstreamer
GST_B := $(B)/gst
GST_PKGS := gstreamer-1.0 gstreamer-video-1.0
GST_TEST_PKGS := $(GST_PKGS) gstreamer-check-1.0 gstreamer-app-1.0 gstreamer-controller-1.0
# Recursive: pkg-config runs only when a GStreamer rule is made.
GST_CFLAGS = $(shell pkg-config --cflags $(GST_PKGS))
GST_LIBS = $(shell pkg-config --libs $(GST_PKGS))
GST_TEST_CFLAGS = $(shell pkg-config --cflags $(GST_TEST_PKGS))
GST_TEST_LIBS = $(shell pkg-config --libs $(GST_TEST_PKGS))
GST_SRC := $(GST_DIR)/gstbloom.c $(GST_DIR)/gstbloom_props.c $(GST_DIR)/gstbloom_conf.c
GST_HDR := $(GST_DIR)/gstbloom.h
GST_PIC_CORE = $(patsubst src/%.c,$(B)/pic/obj/%.o,$(CORE_SRC))
# The project's warnings (-std=c11 -Wall -Wextra -Werror -Wshadow ...) on
# the element and the tests too: bookworm's GStreamer 1.22 / GLib 2.74
# headers need no -Wno-... (gcc 12; clang 14 too, checked by hand).
GST_WARN = $(WARN)
GST_CPPFLAGS = $(CPPFLAGS_CORE) -I$(GST_DIR) -Iport/linux -Iport/threads
# YUY2 goes through the camera tool's row converters, built here from their
# own source (port/linux/cam_conv.c, the flags of linux.mk's CAM_CPPFLAGS):
# one object in the plugin and in the test, which decodes and encodes its
# expected frames with the same functions.
GST_CONV_OBJ = $(GST_B)/obj/cam_conv.o
# n-threads runs the frame's tiles on port/threads' pool (bloom_mt.c, built
# here from its own source with threads.mk's MT_CPPFLAGS; linked with
# MT_LIBS, -lpthread). Its bloom_mt_* symbols stay local to the plugin
# (gstbloom.map), as the engine's do. The paths are spelt here: threads.mk
# is included after this file, and a rule's prerequisites are expanded as
# it is read.
GST_MT_SRC := port/threads/bloom_mt.c
GST_MT_HDR := port/threads/bloom_mt.h
GST_MT_OBJ = $(GST_B)/obj/bloom_mt.o

CHECKS += test-gst
.PHONY: gst test-gst

gst: $(GST_B)/libgstbloom.so

$(GST_B)/obj/%.o: $(GST_DIR)/%.c $(GST_HDR) port/linux/cam_conv.h $(GST_MT_HDR) $(CORE_HDR) $(GST_DIR)/gstreamer.mk
	@mkdir -p $(@D)
	$(CC) $(GST_WARN) $(CFLAGS) -fPIC $(GST_CPPFLAGS) -DGST_BLOOM_VERSION='"$(BLOOM_VERSION)"' \
	  $(GST_CFLAGS) -c $< -o $@

$(GST_CONV_OBJ): port/linux/cam_conv.c port/linux/cam.h port/linux/cam_conv.h $(CORE_HDR) $(GST_DIR)/gstreamer.mk
	@mkdir -p $(@D)
	$(CC) $(WARN) $(CFLAGS) -fPIC $(CPPFLAGS_CORE) -D_POSIX_C_SOURCE=200809L -c $< -o $@

$(GST_MT_OBJ): $(GST_MT_SRC) $(GST_MT_HDR) $(CORE_HDR) $(GST_DIR)/gstreamer.mk
	@mkdir -p $(@D)
	$(CC) $(WARN) $(CFLAGS) -fPIC $(CPPFLAGS_CORE) $(MT_CPPFLAGS) -c $< -o $@

$(GST_B)/libgstbloom.so: $(patsubst $(GST_DIR)/%.c,$(GST_B)/obj/%.o,$(GST_SRC)) $(GST_CONV_OBJ) $(GST_MT_OBJ) \
                         $(GST_PIC_CORE) $(GST_DIR)/gstbloom.map
	$(CC) -shared -Wl,-z,defs -Wl,--version-script=$(GST_DIR)/gstbloom.map -o $@ \
	  $(filter %.o,$^) $(GST_LIBS) $(MT_LIBS)

# The test links the engine itself (build/libbloom.a) to hold the element
# to bloom_process; the element runs from the plugin, loaded by GStreamer.
GST_TEST_SRC := $(GST_DIR)/test_gst.c $(GST_DIR)/test_gst_frames.c $(GST_DIR)/test_gst_stream.c \
                $(GST_DIR)/test_gst_util.c $(GST_DIR)/test_gst_yuy2.c $(GST_DIR)/test_gst_threads.c
$(GST_B)/test_gst: $(GST_TEST_SRC) $(GST_DIR)/test_gst.h port/linux/cam_conv.h $(GST_CONV_OBJ) $(CORE_HDR) \
                   $(B)/libbloom.a $(GST_DIR)/gstreamer.mk
	@mkdir -p $(@D)
	$(CC) $(GST_WARN) $(CFLAGS) $(GST_CPPFLAGS) $(GST_TEST_CFLAGS) \
	  $(GST_TEST_SRC) $(GST_CONV_OBJ) $(B)/libbloom.a $(GST_TEST_LIBS) -o $@

# The plugin path and the registry are the build's own: the user's
# registry is never read or written. The check binary prints its closing
# line itself (and exits non-zero on any failure); never piped.
test-gst:
	@if ! pkg-config --exists $(GST_TEST_PKGS) 2>/dev/null || \
	    ! command -v gst-inspect-1.0 >/dev/null 2>&1; then \
	  echo "skipped: test-gst: GStreamer not installed (libgstreamer1.0-dev," \
	    "libgstreamer-plugins-base1.0-dev, gstreamer1.0-tools, gstreamer1.0-plugins-base: make deps)"; \
	  echo "0 passed, 0 failed, 1 skipped"; exit 0; fi; \
	if ! $(MAKE) --no-print-directory $(GST_B)/libgstbloom.so $(GST_B)/test_gst $(B)/bloom_sim; then \
	  echo "test-gst: the build failed"; echo "0 passed, 1 failed, 0 skipped"; exit 1; fi; \
	env GST_PLUGIN_PATH_1_0=$(GST_B) GST_PLUGIN_PATH=$(GST_B) \
	  GST_REGISTRY_1_0=$(GST_B)/registry.bin GST_REGISTRY=$(GST_B)/registry.bin \
	  BLOOM_GST_PLUGIN=$(GST_B)/libgstbloom.so BLOOM_SIM=$(B)/bloom_sim \
	  BLOOM_DATA_DIR=tests/data BLOOM_GST_TMP=$(GST_B)/tmp $(GST_B)/test_gst
