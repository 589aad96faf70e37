# The FPGA twin (issue 23): the default pipeline in Verilog-2005,
# port/fpga/rtl/, held byte for byte to the C library. Included by the
# top Makefile. Tools from Debian (tests/deps.sh installs them): verilator,
# iverilog, yosys, nextpnr-ice40, fpga-icestorm.
#   make test-fpga         Verilator: every output byte against bloom_process
#                          (RGB888 with the one-pixel-per-clock knee, up to
#                          1920x1080 and 8 levels; RGB565 with the 3-clock knee)
#   make test-fpga-icarus  Icarus, four-state: the same, smaller, and no X out
#   make check-fpga-synth  lint (verilator -Wall), yosys elaboration, and the
#                          per-level units through synth_ice40 (syn/check.sh)
#   make fpga              the resource and Fmax table of port/fpga/README.md
#                          (iCE40 UP5K/HX8K place and route, Xilinx and ECP5 estimates)

FPGA := port/fpga
FPGA_B := $(B)/fpga
FPGA_RTL := $(addprefix $(FPGA)/rtl/,bloom_top.v bloom_box.v bloom_knee.v bloom_up.v bloom_out.v bloom_fifo.v)
FPGA_ROM := $(FPGA_B)/bloom_rom.vh
# -Wall but three: WIDTH (Verilog's zero extension, relied on throughout),
# UNUSEDSIGNAL (bits a unit leaves unused on purpose) and BLKSEQ (blocking
# temporaries inside clocked loops); the rest of -Wall is clean.
FPGA_VFLAGS := --default-language 1364-2005 -Wall -Wno-WIDTH -Wno-UNUSEDSIGNAL -Wno-BLKSEQ
VERILATOR ?= verilator

CHECKS += test-fpga test-fpga-icarus check-fpga-synth
.PHONY: test-fpga test-fpga-icarus check-fpga-synth fpga fpga-lint

$(FPGA_B)/gen_rom: $(FPGA)/gen_rom.c $(B)/libbloom.a
	@mkdir -p $(@D)
	$(CC) $(WARN) -O2 $(CPPFLAGS_CORE) $< $(B)/libbloom.a -o $@
$(FPGA_ROM): $(FPGA_B)/gen_rom
	$< > $@
$(FPGA_B)/imgio.o: sim/imgio.c sim/imgio.h
	@mkdir -p $(@D)
	$(CC) $(WARN) -O2 -D_POSIX_C_SOURCE=200809L -Isim -c $< -o $@
$(FPGA_B)/gen_vectors: $(FPGA)/tb/gen_vectors.c $(B)/libbloom.a
	@mkdir -p $(@D)
	$(CC) $(WARN) -O2 -Iinclude $< $(B)/libbloom.a -o $@

# One Verilator model per pixel format. RGB888: 1920x1080 at most, 8
# levels, the knee at one pixel per clock; RGB565: the iCE40 build that
# make fpga synthesizes, 320x240, 5 levels, the knee every 3 clocks.
FPGA_TB_888 := -GWMAX=1920 -GHMAX=1080 -GLMAX=8 -GFMT888=1 -GKNEE_II=1 -CFLAGS "-DTB_FMT888=1 -DTB_LMAX=8 -DTB_WMAX=1920 -DTB_HMAX=1080"
FPGA_TB_565 := -GWMAX=320 -GHMAX=240 -GLMAX=5 -GFMT888=0 -GKNEE_II=3 -CFLAGS "-DTB_FMT888=0 -DTB_LMAX=5 -DTB_WMAX=320 -DTB_HMAX=240 -DTB_KNEE_II=3"
$(FPGA_B)/v%/tb_bloom: $(FPGA_RTL) $(FPGA_ROM) $(FPGA)/tb/tb_bloom.cpp $(FPGA_B)/imgio.o $(B)/libbloom.a include/bloom.h
	@rm -rf $(FPGA_B)/v$*
	$(VERILATOR) --cc --exe --build -j 2 -O3 --x-assign fast --x-initial fast $(FPGA_VFLAGS) -Wno-fatal \
	  --top-module bloom_top $(FPGA_TB_$*) -I$(FPGA_B) --Mdir $(FPGA_B)/v$* \
	  -CFLAGS "-O2 -I$(CURDIR)/include -I$(CURDIR)/sim" -LDFLAGS "$(CURDIR)/$(FPGA_B)/imgio.o $(CURDIR)/$(B)/libbloom.a" \
	  $(FPGA_RTL) $(CURDIR)/$(FPGA)/tb/tb_bloom.cpp -o tb_bloom >$(FPGA_B)/verilator_$*.log 2>&1 || \
	  { tail -30 $(FPGA_B)/verilator_$*.log; exit 1; }

# --quick: the 1920x1080 cases keep their back-to-back frames, fewer
# random cases (make test-fpga FPGA_TB_ARGS= runs them all)
FPGA_TB_ARGS ?= --quick
test-fpga: $(FPGA_B)/v888/tb_bloom $(FPGA_B)/v565/tb_bloom
	@sh tests/runbin.sh "fpga, Verilator, RGB565 (the iCE40 build's 3-clock knee):" \
	  'FAIL|latency|qvga_L5|noblank|registers|clocks simulated' -- $(FPGA_B)/v565/tb_bloom -v $(FPGA_TB_ARGS) >$(FPGA_B)/tb565.out 2>&1 & \
	sh tests/runbin.sh "fpga, Verilator, RGB888 (every output byte against bloom_process):" \
	  'FAIL|latency|hd_|noblank|bad_|registers|clocks simulated' -- $(FPGA_B)/v888/tb_bloom -v $(FPGA_TB_ARGS); a=$$?; \
	wait $$!; b=$$?; cat $(FPGA_B)/tb565.out; [ $$a -eq 0 ] && [ $$b -eq 0 ]

test-fpga-icarus: $(FPGA_RTL) $(FPGA_ROM) $(FPGA)/tb/tb_icarus.v $(FPGA)/tb/icarus.sh $(FPGA_B)/gen_vectors
	@sh tests/runbin.sh "fpga, Icarus (four-state; no X may reach an output):" '' -- \
	  sh $(FPGA)/tb/icarus.sh $(FPGA_B)/icarus $(FPGA_B)/gen_vectors

fpga-lint: $(FPGA_RTL) $(FPGA_ROM)
	$(VERILATOR) --lint-only $(FPGA_VFLAGS) -I$(FPGA_B) --top-module bloom_top $(FPGA_RTL)
	$(VERILATOR) --lint-only $(FPGA_VFLAGS) -I$(FPGA_B) --top-module bloom_top -GFMT888=0 -GKNEE_II=3 $(FPGA_RTL)

check-fpga-synth: fpga-lint $(FPGA_RTL) $(FPGA_ROM) $(FPGA)/syn/check.sh $(FPGA)/syn/bloom_harness.v
	@sh tests/runbin.sh "fpga: verilator -Wall lint clean; yosys (elaboration, the per-level units for the iCE40):" '' -- \
	  env FPGA_RTL="$(FPGA_RTL)" sh $(FPGA)/syn/check.sh $(FPGA_B)/check

fpga: $(FPGA_RTL) $(FPGA_ROM) $(FPGA)/syn/synth.sh $(FPGA)/syn/bloom_board.v $(FPGA_B)/gen_vectors
	FPGA_RTL="$(FPGA_RTL)" sh $(FPGA)/syn/synth.sh table $(FPGA_B)/syn $(FPGA)/README.md
