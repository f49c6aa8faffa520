/* SPDX-License-Identifier: MIT */
/* Reference pictures for the workloads that have no published checksum:
 * the pixel-centre definitions of docs/BENCHMARK.md (reference pictures) drawn literally
 * (even-odd spans with ceil(xa) <= x < ceil(xb), discs as
 * (x-cx)^2 + (y-cy)^2 <= r^2, the midpoint circle, a plain Bresenham line).
 * The harness reports how many pixels each peer draws differently; that
 * number is information about edge rules, not a pass/fail verdict, because
 * the specification leaves line and circle tie-breaking open. */
#include "bench.h"

#include <stdlib.h>
#include <string.h>

static void put(const struct target *t, int x, int y, uint32_t c)
{
    if (x < 0 || x >= BW || y < 0 || y >= BH)
        return;
    if (t->fmt == FMT_XRGB8888)
        ((uint32_t *)t->pixels)[(size_t)y * BW + x] = c;
    else
        ((uint16_t *)t->pixels)[(size_t)y * BW + x] = (uint16_t)pack565(c);
}

static void span(const struct target *t, int y, int x0, int x1, uint32_t c)
{
    for (int x = x0 < 0 ? 0 : x0; x < x1 && x < BW; x++)
        put(t, x, y, c);
}

static int64_t floor_div(int64_t a, int64_t b)
{
    int64_t q = a / b;
    return (a % b != 0 && ((a < 0) != (b < 0))) ? q - 1 : q;
}

static void polygon(const struct target *t, const int *xs, const int *ys, int nv, uint32_t c)
{
    int miny = ys[0], maxy = ys[0];
    for (int i = 1; i < nv; i++) {
        miny = ys[i] < miny ? ys[i] : miny;
        maxy = ys[i] > maxy ? ys[i] : maxy;
    }
    for (int y = miny; y < maxy; y++) {
        int64_t xc[16];
        int k = 0;
        for (int i = 0; i < nv; i++) {
            int j = (i + 1) % nv;
            int lo = ys[i] < ys[j] ? ys[i] : ys[j], hi = ys[i] < ys[j] ? ys[j] : ys[i];
            if (!(lo <= y && y < hi))
                continue;
            int64_t num = (int64_t)(y - ys[i]) * (xs[j] - xs[i]), den = ys[j] - ys[i];
            int64_t v = xs[i] - floor_div(-num, den), m = k++;
            while (m > 0 && xc[m - 1] > v) {
                xc[m] = xc[m - 1];
                m--;
            }
            xc[m] = v;
        }
        for (int i = 0; i + 1 < k; i += 2)
            span(t, y, (int)xc[i], (int)xc[i + 1], c);
    }
}

static void circle(const struct target *t, const struct wl_circle *q)
{
    int x = q->r, y = 0, d = 1 - q->r, cx = q->cx, cy = q->cy;
    while (y <= x) {
        put(t, cx + x, cy + y, q->c);
        put(t, cx - x, cy + y, q->c);
        put(t, cx + x, cy - y, q->c);
        put(t, cx - x, cy - y, q->c);
        put(t, cx + y, cy + x, q->c);
        put(t, cx - y, cy + x, q->c);
        put(t, cx + y, cy - x, q->c);
        put(t, cx - y, cy - x, q->c);
        midpoint_circle_step(&x, &y, &d);
    }
}

static void disc(const struct target *t, const struct wl_circle *q)
{
    int64_t r2 = (int64_t)q->r * q->r;
    for (int dy = -q->r; dy <= q->r; dy++) {
        int h = 0;
        while ((int64_t)(h + 1) * (h + 1) + (int64_t)dy * dy <= r2)
            h++;
        span(t, q->cy + dy, q->cx - h, q->cx + h + 1, q->c);
    }
}

static void line(const struct target *t, const struct wl_line *l)
{
    int x = l->x0, y = l->y0, dx = abs(l->x1 - l->x0), dy = -abs(l->y1 - l->y0);
    int sx = l->x0 < l->x1 ? 1 : -1, sy = l->y0 < l->y1 ? 1 : -1, e = dx + dy;
    for (;;) {
        put(t, x, y, l->c);
        if (x == l->x1 && y == l->y1)
            break;
        int e2 = 2 * e;
        if (e2 >= dy) {
            e += dy;
            x += sx;
        }
        if (e2 <= dx) {
            e += dx;
            y += sy;
        }
    }
}

int reference_draw(const struct target *t, int w)
{
    switch (w) {
    case W3_LINES:
        for (int i = 0; i < N_LINES; i++)
            line(t, &WL->lines[i]);
        return 1;
    case W5_CIRCLES:
        for (int i = 0; i < N_CIRCLES; i++)
            circle(t, &WL->circles[i]);
        return 1;
    case W6_DISCS:
        for (int i = 0; i < N_DISCS; i++)
            disc(t, &WL->circles[i]);
        return 1;
    case W7_POLYS:
        for (int i = 0; i < N_POLYS; i++)
            polygon(t, WL->polys[i].x, WL->polys[i].y, POLY_N, WL->polys[i].c);
        return 1;
    case W8_TRIS:
        for (int i = 0; i < N_TRIS; i++)
            polygon(t, WL->tris[i].x, WL->tris[i].y, 3, WL->tris[i].c[0]);
        return 1;
    default: return 0;
    }
}
