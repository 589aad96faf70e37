# make dual-vs-gauss: the Arm guide's "dual filtering is about 14x cheaper
# than a Gaussian of similar reach at 1080p", measured (sim/dual_vs_gauss.c,
# sim/docs/presets/arm.md). Not a test: nothing here joins CHECKS.
# Knobs: DVG_ARGS (e.g. --size 1280x720 --levels 4 --repeats 11).
DVG_ARGS ?=

$(B)/dual_vs_gauss: sim/dual_vs_gauss.c sim/bench/scene.c sim/bench/scene.h sim/imgio.c $(CORE_SRC) $(CORE_HDR)
	@mkdir -p $(B)
	$(CC) $(WARN) -O2 -g $(HOST_CPPFLAGS) -Isim/bench sim/dual_vs_gauss.c sim/bench/scene.c sim/imgio.c \
	  $(CORE_SRC) -lm -o $@

.PHONY: dual-vs-gauss
dual-vs-gauss: $(B)/dual_vs_gauss
	$(B)/dual_vs_gauss $(DVG_ARGS)
	@if command -v valgrind >/dev/null 2>&1; then \
	  for p in arm gauss default; do \
	    n=$$(valgrind --tool=callgrind --callgrind-out-file=/dev/null "--toggle-collect=run_$$p*" \
	      $(B)/dual_vs_gauss --once $$p $(DVG_ARGS) 2>&1 | sed -n 's/.*Collected : *\([0-9]*\).*/\1/p'); \
	    echo "$$p $$n"; done | awk '{n[$$1] = $$2; printf "callgrind %-8s %14.0f instructions\n", $$1, $$2} \
	    END { if (n["arm"] > 0) printf "instruction ratio Gaussian / arm: %.1f x (arm / default preset: %.2f)\n", \
	      n["gauss"] / n["arm"], n["arm"] / n["default"] }'; \
	else echo "valgrind not installed: no instruction counts"; fi
