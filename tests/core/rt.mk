# SPDX-License-Identifier: MIT
# tests/core/test_rt.c measures the ray tracer against the benchmark's
# double-precision reference tracer and scenes (tools/fixel-bench/rtref.c).
TEST_OBJ += $(BUILD)/obj/tools/fixel-bench/rtref.o
