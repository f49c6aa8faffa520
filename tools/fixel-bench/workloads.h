/* SPDX-License-Identifier: MIT */
/* fixel-bench — workload frames built from the public API only (the
 * definitions of docs/BENCHMARK.md). They were once library entry points;
 * they are benchmark code, so they live here, and the tests that check them
 * (tests/core/test_3d.c, test_fractal.c) compile workloads.c in. */
#ifndef FIXEL_BENCH_WORKLOADS_H
#define FIXEL_BENCH_WORKLOADS_H

#include <stddef.h>

#include <fixel/fractal.h>
#include <fixel/render3d.h>
#include <fixel/surface.h>

/* One frame of the 3D scene: a Gouraud-shaded Utah teapot (8 x 8 per
 * patch, 4096 triangles) with a 32-bit depth buffer, two lights and a
 * camera turned by `angle` about the teapot, drawn on s (any size; the
 * bench uses 1920 x 1080). mem must hold bench_teapot_bytes(s) bytes
 * (8-byte aligned). Returns 0 or a negative error. */
size_t bench_teapot_bytes(const fx_surface *s);
int bench_teapot(const fx_surface *s, void *mem, size_t bytes, fx_angle angle);

/* The W9 picture on the whole of s: centre -0.5 + 0i, width 3.0, 256
 * iterations, the W9 palette (fx_dwell_pal_w9), pixel centres. Returns 0
 * or -FX_EINVAL. The _mt form draws it with fx_fractal_render_mt on
 * nthreads threads (the same picture). */
int bench_mandel_w9(const fx_surface *s);
int bench_mandel_w9_mt(const fx_surface *s, int nthreads);

#endif
