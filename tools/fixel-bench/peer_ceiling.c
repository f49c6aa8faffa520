/* SPDX-License-Identifier: MIT */
/* The ceilings: libc's memset (W1, and per row of each W2 rectangle) and
 * memcpy (W10) of the very buffer the libraries draw into, and the plain
 * reference loops (W1 and W2 store loops, W9 double-precision Mandelbrot). */
#include "bench.h"

#include <string.h>
#include <wchar.h>

static struct target T[FMT_COUNT];

static void *open_target(const struct target *t)
{
    T[t->fmt] = *t;
    return &T[t->fmt];
}
static void close_nothing(void *ctx) { (void)ctx; }

static size_t bytes(const struct target *t) { return (size_t)t->stride * BH; }

static void libc_clear(void *ctx, int n)
{
    const struct target *t = ctx;
    (void)n;
    memset(t->pixels, 0x20, bytes(t));
}

static void libc_blit(void *ctx, int n)
{
    const struct target *t = ctx;
    (void)n;
    memcpy(t->pixels, WL->blit_src[t->fmt], bytes(t));
}

/* Clipped once, then one libc call per row: wmemset stores the true 32-bit
 * pixel; for RGB565 libc has no 16-bit fill, so memset stores the low byte
 * twice (the wrong colour, the right traffic, as memset in W1). */
static void libc_rects(void *ctx, int n)
{
    const struct target *t = ctx;
    for (int i = 0; i < n; i++) {
        const struct wl_rect *r = &WL->rects[i];
        int x1 = r->x + r->w < BW ? r->x + r->w : BW, y1 = r->y + r->h < BH ? r->y + r->h : BH;
        uint8_t *row = t->pixels + (size_t)r->y * (size_t)t->stride;
        if (t->fmt == FMT_XRGB8888)
            for (int y = r->y; y < y1; y++, row += t->stride)
                wmemset((wchar_t *)(void *)row + r->x, (wchar_t)r->c, (size_t)(x1 - r->x));
        else
            for (int y = r->y; y < y1; y++, row += t->stride)
                memset(row + (size_t)r->x * 2, (int)(r->c & 0xFF), (size_t)(x1 - r->x) * 2);
    }
}

static void ref_w2(void *ctx, int n) { ref_rects(ctx, n); }
static void ref_native_w2(void *ctx, int n) { ref_native_rects(ctx, n); }

static uint32_t native_of(const struct target *t, uint32_t c)
{
    return t->fmt == FMT_XRGB8888 ? c : pack565(c);
}

static void ref_w1(void *ctx, int n)
{
    const struct target *t = ctx;
    (void)n;
    ref_clear(t, native_of(t, W1_COLOUR));
}

static void ref_native_w1(void *ctx, int n)
{
    const struct target *t = ctx;
    (void)n;
    ref_native_clear(t, native_of(t, W1_COLOUR));
}

static void ref_w9(void *ctx, int n)
{
    const struct target *t = ctx;
    (void)n;
    ref_mandel((uint32_t *)t->pixels);
}

static void ref_native_w9(void *ctx, int n)
{
    const struct target *t = ctx;
    (void)n;
    ref_native_mandel((uint32_t *)t->pixels);
}

const struct peer peer_libc = {
    .name = "libc",
    .fmt_mask = 3,
    .open = open_target,
    .close = close_nothing,
    .fn = {[W1_CLEAR] = libc_clear, [W2_RECTS] = libc_rects, [W10_BLIT] = libc_blit},
};

/* W9 is defined for XRGB8888 only; the harness never asks for RGB565. */
const struct peer peer_ref = {
    .name = "ref",
    .fmt_mask = 3,
    .open = open_target,
    .close = close_nothing,
    .fn = {[W1_CLEAR] = ref_w1, [W2_RECTS] = ref_w2, [W9_MANDEL] = ref_w9},
};

const struct peer peer_ref_native = {
    .name = "ref-native",
    .fmt_mask = 3,
    .open = open_target,
    .close = close_nothing,
    .fn = {[W1_CLEAR] = ref_native_w1, [W2_RECTS] = ref_native_w2, [W9_MANDEL] = ref_native_w9},
};
