/* The ceilings: libc's memset (W1) and memcpy (W10) of the very buffer the
 * libraries draw into, and the plain reference loops (W1 store loop, W9
 * double-precision Mandelbrot). */
#include "bench.h"

#include <string.h>

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
    .fn = {[W1_CLEAR] = libc_clear, [W10_BLIT] = libc_blit},
};

/* W9 is defined for XRGB8888 only; the harness never asks for RGB565. */
const struct peer peer_ref = {
    .name = "ref",
    .fmt_mask = 3,
    .open = open_target,
    .close = close_nothing,
    .fn = {[W1_CLEAR] = ref_w1, [W9_MANDEL] = ref_w9},
};

const struct peer peer_ref_native = {
    .name = "ref-native",
    .fmt_mask = 3,
    .open = open_target,
    .close = close_nothing,
    .fn = {[W1_CLEAR] = ref_native_w1, [W9_MANDEL] = ref_native_w9},
};
