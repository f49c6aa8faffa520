/* SPDX-License-Identifier: MIT */
/* The huge primitives of the bounded-work tests, shared by the unit test
 * (tests/core/test_bounded.c: each case under a CPU-time limit) and the
 * instruction counter (tests/bounded/: each case's instructions counted
 * under valgrind's lackey). */
#ifndef FX_BOUNDED_CASES_H
#define FX_BOUNDED_CASES_H

#include <stdint.h>

#include "fixel/circle.h"
#include "fixel/clip.h"
#include "fixel/fill.h"
#include "fixel/font.h"
#include "fixel/koch.h"
#include "fixel/line.h"

enum { W = 16, H = 16 };
static const int32_t BIG = 1 << 30, MAXI = INT32_MAX, MINI = INT32_MIN;

static void run_case(int k, const fx_ctx *c) __attribute__((unused));
static void run_case(int k, const fx_ctx *c)
{
    int32_t sq[8] = {MINI, MINI, MAXI, MINI + 7, MAXI - 3, MAXI, -BIG, BIG};
    int32_t tri[6] = {-BIG, -BIG, BIG, 3, 5, BIG};
    switch (k) {
    case 0: fx_line(c, MINI + 1, MINI + 1, MAXI, MAXI); break;
    case 1: fx_line(c, MINI, 7, MAXI, 8); break;
    case 2: fx_circle(c, BIG, 8, BIG - 8); break;              /* crosses the surface */
    case 3: fx_circle(c, 8, 8, MAXI); break;                   /* encloses it */
    case 4: fx_disc(c, -BIG + 20, 8, BIG); break;
    case 5: fx_ellipse(c, 8, BIG, 5, BIG - 4); break;
    case 6: fx_fill_ellipse(c, BIG, BIG, BIG, BIG); break;
    case 7: fx_arc(c, 8, MAXI - 100, MAXI - 92, 0, FX_ANGLE_270); break;
    case 8: fx_pie(c, MINI + 5, 8, MAXI, FX_ANGLE_90, FX_ANGLE_270); break;
    case 9: fx_aacircle(c, BIG, 0, BIG); break;
    case 10: fx_fill_poly(c, sq, 4, FX_FILL_EVENODD); break;
    case 11: fx_fill_poly(c, sq, 4, FX_FILL_NONZERO); break;
    case 12: fx_fill_tri(c, tri[0], tri[1], tri[2], tri[3], tri[4], tri[5]); break;
    case 13: fx_polygon(c, sq, 4); break;
    case 14: fx_koch(c, -BIG, 8, BIG, 8, 14); break;
    case 15: fx_koch_snowflake(c, 8, 8, BIG, 12); break;
    case 16: fx_hilbert(c, -BIG, -BIG, MAXI, 30); break;
    case 17: fx_rect_outline(c, MINI, MINI, MAXI, MAXI); break;
    case 18: fx_fill_rect(c, MINI, MINI, MAXI, MAXI); break;
    default: {
        fx_ctx d = *c;
        d.line_clipper = (uint8_t)(k - 19 + 1); /* Cohen, Liang, NLN */
        fx_clip_draw_line(&d, MINI, MINI + 3, MAXI, MAXI - 9);
        break;
    }
    }
}
#define NCASES 22

#endif
