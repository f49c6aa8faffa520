# SPDX-License-Identifier: MIT
# fixel-bench: the ten workloads of docs/BENCHMARK.md.
#
#   make bench        fixel with the memset/memcpy and double-reference ceilings
#   make bench-peers  the same, in one process with cairo, pixman, SDL2 and
#                     SDL2_gfx, and a fixel / best-peer ratio column
#   make test         runs `fixel-bench --check` (checksums, W9 agreement; ~2 s)
#
# Built by the generic tools rule (tools/fixel-bench/main.c). Without the peer
# libraries (before `make deps`) it still builds and measures fixel against
# the ceilings, and bench-peers says so.

# The peers: `make bench-peers` installs them (root) or names them first;
# `make test` too, as `fixel-bench --check` verifies the peers' checksums.
BENCH_DEB_PKGS += libcairo2-dev libpixman-1-dev libsdl2-dev libsdl2-gfx-dev
TEST_DEB_PKGS += $(BENCH_DEB_PKGS)

BENCH_PKGS := cairo pixman-1 sdl2 SDL2_gfx
BENCH_HAVE_PEERS := $(shell $(PKG_CONFIG) --exists $(BENCH_PKGS) 2>/dev/null && echo yes)
ifeq ($(BENCH_HAVE_PEERS),yes)
$(BUILD)/obj/tools/fixel-bench/%.o: PKG_CFLAGS += -DBENCH_PEERS $(shell $(PKG_CONFIG) --cflags $(BENCH_PKGS))
TOOL_LIBS_fixel-bench := $(shell $(PKG_CONFIG) --libs $(BENCH_PKGS)) -lm
else
$(BUILD)/obj/tools/fixel-bench/%.o: PKG_CFLAGS += -DBENCH_NO_PEERS
TOOL_LIBS_fixel-bench := -lm
endif

# The W9 reference is measured at exactly the flags docs/BENCHMARK.md names, whatever
# OPT and CPU_FLAGS the project is built with; ref-native is the same source at
# -O3 -march=native. Both are plain C (no fixel), so sanitizers stay off here.
# The user's CPPFLAGS/CFLAGS come before the fixed optimisation flags, so
# they cannot change what the reference is measured at.
TOOL_SRC_fixel-bench := tools/fixel-bench/ref/ref.c tools/fixel-bench/ref/ref_native.c
BENCH_REF_FLAGS := $(CSTD) $(WARN) -g -fPIC -MMD -MP $(INCLUDES)
$(BUILD)/obj/tools/fixel-bench/ref/ref.o: tools/fixel-bench/ref/ref.c
	@mkdir -p $(dir $@)
	@$(if $(Q),echo "  CC      $<")
	$(Q)$(CC) $(BENCH_REF_FLAGS) $(CPPFLAGS) $(CFLAGS) -O2 -fno-tree-vectorize -c $< -o $@
$(BUILD)/obj/tools/fixel-bench/ref/ref_native.o: tools/fixel-bench/ref/ref_native.c
	@mkdir -p $(dir $@)
	@$(if $(Q),echo "  CC      $<")
	$(Q)$(CC) $(BENCH_REF_FLAGS) $(CPPFLAGS) $(CFLAGS) -O3 $(if $(CROSS_COMPILE),$(CPU_FLAGS),-march=native) -c $< -o $@

bench: $(BUILD)/bin/fixel-bench $(BUILD)/bin/fixel-kiosk $(BUILD)/bin/fixel-demo
	$(BUILD)/bin/fixel-bench -o $(BUILD)/bench.txt
	$(BUILD)/bin/fixel-bench --frames -o $(BUILD)/bench-frames.txt

# A new make after the install, so that BENCH_HAVE_PEERS sees the peers.
bench-peers:
	@sh tests/deps.sh --for "make bench-peers" $(sort $(DEB_PKGS) $(BENCH_DEB_PKGS))
	@$(MAKE) --no-print-directory bench-peers-nodeps

bench-peers-nodeps: $(BUILD)/bin/fixel-bench
	$(BUILD)/bin/fixel-bench --peers -o $(BUILD)/bench-peers.txt
	$(BUILD)/bin/fixel-bench --w3-classes --peers -t 9 -o $(BUILD)/bench-w3-classes.txt

TEST_SUITES += "$(BUILD)/bin/fixel-bench --check"
# the frames table (TABLE 8) runs, with its 2-thread column past 2 threads
TEST_SUITES += "sh tools/fixel-bench/frames-check.sh $(BUILD)/bin $(BUILD)/frames-check"
# W3 split by line class (--w3-classes): every line in one class, the floor row
TEST_SUITES += "sh tools/fixel-bench/w3classes-check.sh $(BUILD)/bin $(BUILD)/w3classes-check"


.PHONY: bench bench-peers bench-peers-nodeps

# The workload frames (workloads.c) are benchmark code, not library API; the
# unit tests that check them (tests/core/test_3d.c, test_fractal.c) link them in.
TEST_OBJ += $(BUILD)/obj/tools/fixel-bench/workloads.o

# The fixel-api peer (tools/fixel-bench/api/): a user's program. Its object
# is compiled against the headers copied as `make install` lays them out and
# with a user's flags only (-O2, no -march, no -fPIC, none of the project's
# CFLAGS), then linked with the rest of fixel-bench to libfixel.a.
BENCH_API_INC := $(BUILD)/api-include
BENCH_API_HDRS := $(wildcard kernel-free-src/include/fixel/*.h boards/include/fixel/*.h)
$(BENCH_API_INC)/.stamp: $(BENCH_API_HDRS)
	@rm -rf $(BENCH_API_INC) && mkdir -p $(BENCH_API_INC)/fixel
	@$(if $(Q),echo "  CP      $(BENCH_API_INC)/fixel/")
	$(Q)cp $(BENCH_API_HDRS) $(BENCH_API_INC)/fixel/
	@touch $@
TOOL_SRC_fixel-bench += tools/fixel-bench/api/peer_fixel_api.c
$(BUILD)/obj/tools/fixel-bench/api/peer_fixel_api.o: tools/fixel-bench/api/peer_fixel_api.c tools/fixel-bench/bench.h $(BENCH_API_INC)/.stamp
	@mkdir -p $(dir $@)
	@$(if $(Q),echo "  CC      $<")
	$(Q)$(CC) -std=c11 -O2 -I$(BENCH_API_INC) -c $< -o $@

# The same program linked to libfixel.so instead of libfixel.a (calls
# through the PLT into -fPIC code, only the exported API), as a program
# built with `pkg-config --libs fixel` meets the library:
#   make bench-shared; sh tools/fixel-bench/spread.sh 5 build/bin/fixel-bench-shared --peers ...
.PHONY: bench-shared
bench-shared: $(BUILD)/bin/fixel-bench-shared
$(BUILD)/bin/fixel-bench-shared: $(patsubst %.c,$(BUILD)/obj/%.o,$(wildcard tools/fixel-bench/*.c) $(TOOL_SRC_fixel-bench)) $(LIB_SO)
	@mkdir -p $(dir $@)
	@$(if $(Q),echo "  LD      $@")
	$(Q)$(CC) $(SANFLAGS) $(LDFLAGS) -o $@ $(filter %.o,$^) -L$(BUILD) -Wl,-rpath,$(abspath $(BUILD)) -lfixel \
	  $(TOOL_LIBS_fixel-bench) $(LDLIBS)
TEST_SUITES += "$(MAKE) --no-print-directory -s $(BUILD)/bin/fixel-bench-shared && $(BUILD)/bin/fixel-bench-shared --check"
