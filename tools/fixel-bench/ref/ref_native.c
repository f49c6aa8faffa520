/* SPDX-License-Identifier: MIT */
/* The same reference loops, built at -O3 -march=native (peer "ref-native"). */
#define REF_NATIVE
#include "ref.c"
