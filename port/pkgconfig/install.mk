# make install / make uninstall: the static and the shared library (soname
# libbloom.so.$(BLOOM_MAJOR), exporting only the public API of
# include/bloom.h), the headers, bloom.pc for pkg-config, the tools, and the
# GStreamer element into $(GSTPLUGINDIR) when GStreamer's development
# packages are there (make deps installs them; else it says it left it out).
# Included by the top Makefile.
#   make install [PREFIX=/usr/local] [DESTDIR=staging] [LIBDIR=...]
#   make uninstall (the same variables: removes exactly what install put)
#   make test-install  (a CHECKS target of make test: install into a scratch
#                       prefix, build and run a program with pkg-config only)

BLOOM_VERSION := 1.0.0
BLOOM_MAJOR := $(firstword $(subst ., ,$(BLOOM_VERSION)))
PREFIX ?= /usr/local
LIBDIR ?= $(PREFIX)/lib
INCLUDEDIR ?= $(PREFIX)/include
BINDIR ?= $(PREFIX)/bin
PKGCONFIGDIR ?= $(LIBDIR)/pkgconfig
GSTPLUGINDIR ?= $(LIBDIR)/gstreamer-1.0
INSTALL_TOOLS := $(B)/bloom_sim $(B)/bloom_demo $(B)/bloom_info $(B)/bloom_cam
SO := libbloom.so.$(BLOOM_VERSION)

CHECKS += test-install
.PHONY: install uninstall test-install shared

# Position-independent objects of the core for the shared library.
$(B)/pic/obj/%.o: src/%.c $(CORE_HDR)
	@mkdir -p $(@D)
	$(CC) $(WARN) $(CFLAGS) -fPIC $(CPPFLAGS_CORE) -c $< -o $@
# The exported symbols: the functions include/bloom.h declares, nothing else
# (the row kernels and tables are bloom_* too, but internal).
$(B)/pic/bloom.map: include/bloom.h
	@mkdir -p $(@D)
	{ echo '{ global:'; grep -o '^[a-z_][a-z_0-9 *]*[ *]bloom_[a-z0-9_]*(' $< | \
	  sed 's/.*\(bloom_[a-z0-9_]*\)(/  \1;/' | sort -u; echo 'local: *; };'; } > $@
$(B)/pic/$(SO): $(patsubst src/%.c,$(B)/pic/obj/%.o,$(CORE_SRC)) $(B)/pic/bloom.map
	$(CC) -shared -Wl,-soname,libbloom.so.$(BLOOM_MAJOR) -Wl,--version-script=$(B)/pic/bloom.map \
	  -Wl,-z,defs -o $@ $(filter %.o,$^)
$(B)/pic/bloom.pc: port/pkgconfig/bloom.pc.in Makefile port/pkgconfig/install.mk
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@LIBDIR@|$(LIBDIR)|' -e 's|@INCLUDEDIR@|$(INCLUDEDIR)|' \
	  -e 's|@VERSION@|$(BLOOM_VERSION)|' $< > $@
# the prefix is baked into bloom.pc: rebuild it whenever install runs
.PHONY: $(B)/pic/bloom.pc
shared: $(B)/pic/$(SO)

install: $(B)/libbloom.a $(B)/pic/$(SO) $(B)/pic/bloom.pc $(INSTALL_TOOLS)
	install -d $(DESTDIR)$(LIBDIR) $(DESTDIR)$(INCLUDEDIR) $(DESTDIR)$(BINDIR) $(DESTDIR)$(PKGCONFIGDIR)
	install -m 644 $(B)/libbloom.a $(DESTDIR)$(LIBDIR)/libbloom.a
	install -m 755 $(B)/pic/$(SO) $(DESTDIR)$(LIBDIR)/$(SO)
	ln -sf $(SO) $(DESTDIR)$(LIBDIR)/libbloom.so.$(BLOOM_MAJOR)
	ln -sf libbloom.so.$(BLOOM_MAJOR) $(DESTDIR)$(LIBDIR)/libbloom.so
	install -m 644 include/bloom.h include/bloom_config.h $(DESTDIR)$(INCLUDEDIR)/
	install -m 644 $(B)/pic/bloom.pc $(DESTDIR)$(PKGCONFIGDIR)/bloom.pc
	install -m 755 $(INSTALL_TOOLS) $(DESTDIR)$(BINDIR)/
	@if pkg-config --exists gstreamer-1.0 gstreamer-base-1.0 gstreamer-video-1.0 2>/dev/null; then \
	  $(MAKE) --no-print-directory -s $(B)/gst/libgstbloom.so && \
	  install -d $(DESTDIR)$(GSTPLUGINDIR) && \
	  install -m 644 $(B)/gst/libgstbloom.so $(DESTDIR)$(GSTPLUGINDIR)/libgstbloom.so && \
	  echo "install: the GStreamer element in $(DESTDIR)$(GSTPLUGINDIR)"; \
	else echo "install: the GStreamer element left out: GStreamer's development packages are missing (make deps)"; fi

uninstall:
	rm -f $(DESTDIR)$(LIBDIR)/libbloom.a $(DESTDIR)$(LIBDIR)/$(SO) \
	  $(DESTDIR)$(LIBDIR)/libbloom.so.$(BLOOM_MAJOR) $(DESTDIR)$(LIBDIR)/libbloom.so \
	  $(DESTDIR)$(INCLUDEDIR)/bloom.h $(DESTDIR)$(INCLUDEDIR)/bloom_config.h \
	  $(DESTDIR)$(PKGCONFIGDIR)/bloom.pc $(addprefix $(DESTDIR)$(BINDIR)/,$(notdir $(INSTALL_TOOLS))) \
	  $(DESTDIR)$(GSTPLUGINDIR)/libgstbloom.so

test-install:
	@B=$(B) MAKE='$(MAKE)' CC='$(CC)' sh port/pkgconfig/test_install.sh
