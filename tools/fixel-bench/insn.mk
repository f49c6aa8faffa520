# SPDX-License-Identifier: MIT
# fixel-insn (tools/fixel-bench/insn/): one workload of docs/BENCHMARK.md
# drawn between markers, for instruction counters (`make bench-insn`,
# docs/PERFORMANCE.md). It draws through fixel-bench's fixel peer with
# fixel-bench's generator, and needs no peer library, so it cross-builds
# (fixel-bench itself does not).
INSN_SRC := tools/fixel-bench/insn/insn_main.c tools/fixel-bench/gen.c tools/fixel-bench/peer_fixel.c \
            tools/fixel-bench/workloads.c
$(BUILD)/bin/fixel-insn: $(INSN_SRC:%.c=$(BUILD)/obj/%.o) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(SANFLAGS) $(LDFLAGS) -o $@ $(filter %.o,$^) $(LIB_A) $(LDLIBS)

# The counter of qemu's trace runs on the build machine.
$(PLAIN_BUILD)/qemu-count: tools/fixel-bench/insn/qemu-count.c
	@mkdir -p $(dir $@)
	$(if $(CROSS_COMPILE),cc,$(CC)) $(CSTD) $(WARN) -O2 -o $@ $<

# x86-64 next to aarch64 (the rpi4 profile, static, under qemu-user).
bench-insn: $(PLAIN_BUILD)/bin/fixel-insn $(PLAIN_BUILD)/qemu-count
	@$(MAKE) --no-print-directory -j2 BOARD=rpi4 STATIC=1 build/rpi4/static/bin/fixel-insn > $(PLAIN_BUILD)/bench-insn-rpi4.log 2>&1 || \
	  echo "bench-insn: the rpi4 build failed (see $(PLAIN_BUILD)/bench-insn-rpi4.log); x86-64 only"
	sh tools/fixel-bench/insn/bench-insn.sh $(PLAIN_BUILD)/bin/fixel-insn build/rpi4/static/bin/fixel-insn \
	  $(PLAIN_BUILD)/qemu-count $(PLAIN_BUILD)/bench-insn.txt

.PHONY: bench-insn
