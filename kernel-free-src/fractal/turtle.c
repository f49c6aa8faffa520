/* SPDX-License-Identifier: MIT */
/* fixel — turtle graphics (contracts in turtle.h). */
#include "fixel/turtle.h"
#include "fixel/line.h"
#include "../base/fx_internal.h"

static inline int32_t px(fx16 v) { return (int32_t)(((int64_t)v + 0x8000) >> 16); }

void fx_turtle_init(fx_turtle *t, const fx_ctx *c, fx16 x, fx16 y, fx16 deg)
{
    t->ctx = c;
    t->x = x;
    t->y = y;
    t->heading = 0;
    fx_turtle_turn_to(t, deg);
    t->segs = 0;
}

void fx_turtle_pos(const fx_turtle *t, fx16 *x, fx16 *y)
{
    *x = t->x;
    *y = t->y;
}

fx16 fx_turtle_heading(const fx_turtle *t) { return t->heading; }

void fx_turtle_move_to(fx_turtle *t, fx16 x, fx16 y)
{
    t->x = x;
    t->y = y;
}

void fx_turtle_line_to(fx_turtle *t, fx16 x, fx16 y)
{
    if (t->ctx) {
        fx_line(t->ctx, px(t->x), px(t->y), px(x), px(y));
        t->segs++;
    }
    t->x = x;
    t->y = y;
}

void fx_turtle_move_rel(fx_turtle *t, fx16 dx, fx16 dy)
{
    fx_turtle_move_to(t, fx_sat32((int64_t)t->x + dx), fx_sat32((int64_t)t->y + dy));
}

void fx_turtle_line_rel(fx_turtle *t, fx16 dx, fx16 dy)
{
    fx_turtle_line_to(t, fx_sat32((int64_t)t->x + dx), fx_sat32((int64_t)t->y + dy));
}

#define FULL ((int64_t)360 << 16)

/* Degrees, not binary angles: the notes' turns (60, -120, 90) add up
 * exactly, so a closed figure returns to its heading bit for bit. */
void fx_turtle_turn_to(fx_turtle *t, fx16 deg)
{
    int64_t h = (int64_t)deg % FULL;
    t->heading = (fx16)(h < 0 ? h + FULL : h);
}

void fx_turtle_turn(fx_turtle *t, fx16 deg) { fx_turtle_turn_to(t, (fx16)(((int64_t)t->heading + deg) % FULL)); }

void fx_turtle_forward(fx_turtle *t, fx16 dist, int visible)
{
    /* 30-bit sine and cosine: the step's rounding stays under 2^-16 px */
    fx_angle a = fx_angle_from_deg16(t->heading);
    int64_t dx = fx_mul64_shift(dist, fx_cos30(a), 30);
    /* from +x towards +y of the frame, as fx_rotate and fx_arc turn
     * (CONVENTIONS.md "Angles"): left, as in the notes, after 'coords course' */
    int64_t dy = fx_mul64_shift(dist, fx_sin30(a), 30);
    if (visible)
        fx_turtle_line_rel(t, (fx16)dx, (fx16)dy);
    else
        fx_turtle_move_rel(t, (fx16)dx, (fx16)dy);
}

static void koch(fx_turtle *t, fx16 len, uint32_t n)
{
    if (n == 0) {
        fx_turtle_forward(t, len, 1);
        return;
    }
    /* thirds rounded to nearest: at order 10 the pieces drift by at most
     * 10 * 2^-17 of the length from exact thirds */
    fx16 l3 = (fx16)(len >= 0 ? ((int64_t)len + 1) / 3 : -((-(int64_t)len + 1) / 3));
    koch(t, l3, n - 1);
    fx_turtle_turn(t, 60 << 16);
    koch(t, l3, n - 1);
    fx_turtle_turn(t, -120 * 65536);
    koch(t, l3, n - 1);
    fx_turtle_turn(t, 60 << 16);
    koch(t, l3, n - 1);
}

uint64_t fx_turtle_koch(fx_turtle *t, fx16 len, uint32_t order)
{
    if (order > FX_TURTLE_MAX_ORDER)
        return 0;
    uint64_t s0 = t->segs;
    koch(t, len, order);
    return t->segs - s0;
}

static void hilbert(fx_turtle *t, fx16 step, uint32_t n, int par)
{
    if (n == 0)
        return;
    fx16 a = par * (90 << 16);
    fx_turtle_turn(t, a);
    hilbert(t, step, n - 1, -par);
    fx_turtle_forward(t, step, 1);
    fx_turtle_turn(t, -a);
    hilbert(t, step, n - 1, par);
    fx_turtle_forward(t, step, 1);
    hilbert(t, step, n - 1, par);
    fx_turtle_turn(t, -a);
    fx_turtle_forward(t, step, 1);
    hilbert(t, step, n - 1, -par);
    fx_turtle_turn(t, a);
}

uint64_t fx_turtle_hilbert(fx_turtle *t, fx16 step, uint32_t order, int parity)
{
    if (order > FX_TURTLE_MAX_ORDER)
        return 0;
    uint64_t s0 = t->segs;
    hilbert(t, step, order, parity < 0 ? -1 : 1);
    return t->segs - s0;
}
