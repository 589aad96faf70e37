# Threads outside the core (issue 14 item 3): port/threads/bloom_mt.[ch]
# cuts a frame into tile engines carved from one caller buffer and runs
# them on a pool of POSIX threads. Included by the top Makefile.
#   make test-threads   the helper's tests, sanitized (a CHECKS target of
#                       make test): 1 .. 4 threads against one, every preset
#   make bench-threads  (sim/bench.mk; run by make bench) 1920x1080, 1 vs 2 threads in
#                       paired rounds, and the halo's instructions for 4
#                       strips under callgrind: sim/docs/threads.md
# Callers compile port/threads/bloom_mt.c with -Iport/threads and link -lpthread.

MT_DIR := port/threads
MT_SRC := $(MT_DIR)/bloom_mt.c
MT_HDR := $(MT_DIR)/bloom_mt.h
MT_CPPFLAGS := -I$(MT_DIR) -D_POSIX_C_SOURCE=200809L
MT_LIBS := -lpthread

CHECKS += test-threads
.PHONY: test-threads bench-threads

$(B)/threads/test_mt: $(MT_DIR)/test_mt.c $(MT_SRC) $(MT_HDR) tests/harness.h tests/testutil.h $(SAN_OBJ) \
                      $(CORE_HDR)
	@mkdir -p $(@D)
	$(CC) $(WARN) $(SAN) $(HOST_CPPFLAGS) $(MT_CPPFLAGS) $(MT_DIR)/test_mt.c $(MT_SRC) $(SAN_OBJ) -lm \
	  $(MT_LIBS) -o $@

# clang -Werror over the helper too (a compile check), then the sanitized run.
test-threads: $(B)/threads/test_mt
	@$(CLANG) $(WARN) -fsyntax-only $(HOST_CPPFLAGS) $(MT_CPPFLAGS) $(MT_SRC) $(MT_DIR)/test_mt.c
	@$(B)/threads/test_mt
# bench-threads lives in sim/bench.mk, beside the objects of make bench it links.
