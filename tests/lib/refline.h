/* SPDX-License-Identifier: MIT */
/* Shared test helper: the definition a Bresenham line is checked against,
 * pixel by pixel (test_line.c's clipped lines, test_clip.c's clippers). */
#ifndef FX_TEST_REFLINE_H
#define FX_TEST_REFLINE_H

#include <stdint.h>

/* Whether the line from (x0,y0) to (x1,y1), any int32 endpoints, lights
 * pixel (x, y): step k along the major axis (0 <= k <= major) is at minor
 * offset m(k) = round_half_up(k * minor / major). */
int refline_lights(int32_t x0, int32_t y0, int32_t x1, int32_t y1, int64_t x, int64_t y);

#endif
