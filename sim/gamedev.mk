# The gamedev preset's generated output thresholds (sim/gen_gamedev.c).
# Included by the top Makefile.
#   make gamedev-tables        regenerate src/presets/bloom_preset_gamedev_tables.c
#   make check-gamedev-tables  fail if it is stale (a CHECKS target of make test)
.PHONY: gamedev-tables check-gamedev-tables
$(B)/gen_gamedev: sim/gen_gamedev.c | $(B)
	$(CC) $(WARN) -O2 $< -lm -o $@
gamedev-tables: $(B)/gen_gamedev
	$(B)/gen_gamedev > src/presets/bloom_preset_gamedev_tables.c
check-gamedev-tables: $(B)/gen_gamedev
	@$(B)/gen_gamedev | cmp -s - src/presets/bloom_preset_gamedev_tables.c || \
	  { echo "src/presets/bloom_preset_gamedev_tables.c is stale: run make gamedev-tables"; exit 1; }
	@echo "gamedev tables: up to date"

CHECKS += check-gamedev-tables
