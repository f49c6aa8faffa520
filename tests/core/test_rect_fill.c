/* SPDX-License-Identifier: MIT */
/* Solid rectangles through every fill path this machine has (the portable
 * 16-byte loops and, on x86-64, the AVX / AVX-512 ones) against a plain
 * per-pixel fill: every width 1..300 at every alignment within a cache line,
 * rows of differing alignment, negative strides, and nothing written
 * outside the rectangle. */
#include <stdlib.h>
#include <string.h>

#include "../../kernel-free-src/base/fx_internal.h"
#include "fixel/surface.h"
#include "fx_test.h"

#define MAXW 300
#define ROWS 4

static uint32_t rng = 2463534242u;
static uint32_t next(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 17;
    rng ^= rng << 5;
    return rng;
}

static void plain_fill(uint8_t *row0, int32_t stride, int bytes, fx_rect r, uint32_t v)
{
    for (int32_t y = r.y0; y < r.y1; y++)
        for (int32_t x = r.x0; x < r.x1; x++) {
            uint8_t *p = row0 + (ptrdiff_t)y * stride + (ptrdiff_t)x * bytes;
            if (bytes == 4)
                memcpy(p, &v, 4);
            else {
                uint16_t h = (uint16_t)v;
                memcpy(p, &h, 2);
            }
        }
}

/* The levels to try: the portable one always, the x86 ones this CPU has. */
static int levels(uint8_t out[3])
{
    int n = 0;
    out[n++] = FX_FILL_PORTABLE;
    uint8_t have = fx_x86_fill_level();
    if (have >= FX_FILL_AVX)
        out[n++] = FX_FILL_AVX;
    if (have >= FX_FILL_AVX512)
        out[n++] = FX_FILL_AVX512;
    return n;
}

/* A w x ROWS surface in a buffer of its own (64-byte aligned), rows
 * stride_pad bytes apart beyond the pixels, row 0 last in memory when flip;
 * ref is the reference copy. */
typedef struct {
    uint8_t *mem, *ref, *row0;
    size_t size;
    int32_t stride;
    int bytes;
    fx_surface s;
} buffer;

static int buffer_make(buffer *b, int32_t w, fx_format f, int bytes, int stride_pad, int flip)
{
    int32_t stride = w * bytes + stride_pad;
    b->size = (size_t)stride * ROWS;
    b->mem = aligned_alloc(64, (b->size + 63) & ~(size_t)63);
    b->ref = malloc(b->size);
    FX_CHECK(b->mem && b->ref);
    if (!b->mem || !b->ref) {
        free(b->mem);
        free(b->ref);
        return 0;
    }
    b->row0 = flip ? b->mem + (size_t)stride * (ROWS - 1) : b->mem;
    b->stride = flip ? -stride : stride;
    b->bytes = bytes;
    FX_CHECK_EQ(fx_surface_init(&b->s, b->row0, w, ROWS, b->stride, f), 0);
    return 1;
}

static void buffer_drop(buffer *b)
{
    free(b->mem);
    free(b->ref);
}

/* Columns [x0, x1) of random rows filled at the buffer's fill level over
 * random bytes, against the plain loop; 0 (and a message) on a difference. */
static int fill_matches(buffer *b, int32_t x0, int32_t x1, const char *what, int pad, int flip)
{
    for (size_t i = 0; i < b->size; i++)
        b->mem[i] = (uint8_t)next();
    memcpy(b->ref, b->mem, b->size);
    int32_t y0 = (int32_t)(next() % 2), y1 = y0 + 1 + (int32_t)(next() % (ROWS - y0));
    fx_rect r = {x0, y0, x1, y1};
    uint32_t v = b->bytes == 4 ? next() : next() & 0xFFFF;
    fx_rect_fill_native(&b->s, r, v);
    plain_fill(b->ref + (b->row0 - b->mem), b->stride, b->bytes, r, v);
    if (memcmp(b->mem, b->ref, b->size) == 0)
        return 1;
    FX_CHECK_MSG(0, "%s: level %d bpp %d pad %d flip %d: columns %d..%d of surface width %d, rows %d..%d",
                 what, b->s.fill_isa, b->bytes * 8, pad, flip, x0, x1, b->s.w, y0, y1);
    return 0;
}

/* Fills every width and start column at each level; stride_pad shifts the
 * alignment from row to row, flip walks rows backwards in memory. */
static void check_widths(fx_format f, int bytes, int stride_pad, int flip, int32_t n_lo, int32_t n_hi)
{
    buffer b;
    if (!buffer_make(&b, n_hi + 64 / bytes + 1, f, bytes, stride_pad, flip))
        return;
    uint8_t lv[3];
    int nl = levels(lv), ok = 1;
    for (int l = 0; l < nl && ok; l++) {
        b.s.fill_isa = lv[l];
        for (int32_t x0 = 0; x0 < 64 / bytes && ok; x0++)
            for (int32_t n = n_lo; n <= n_hi && ok; n++)
                ok = fill_matches(&b, x0, x0 + n, "widths", stride_pad, flip);
    }
    buffer_drop(&b);
}

static void check_format(fx_format f, int bytes, int stride_pad, int flip)
{
    check_widths(f, bytes, stride_pad, flip, 1, MAXW);
}

FX_TEST(rect_fill_matches_plain_loop_32bit)
{
    check_format(FX_FMT_XRGB8888, 4, 0, 0);
    check_format(FX_FMT_ARGB8888, 4, 4, 0);
    check_format(FX_FMT_XRGB8888, 4, 20, 1);
}

FX_TEST(rect_fill_matches_plain_loop_16bit)
{
    check_format(FX_FMT_RGB565, 2, 0, 0);
    check_format(FX_FMT_RGB565, 2, 2, 0);
    check_format(FX_FMT_BGR565, 2, 6, 1);
}

/* Rectangles the full width of the surface: an unpadded surface's rows
 * merge into one run (the general path), a padded one's stay rows (the
 * vector path on x86-64); every surface width 1..MAXW at each level. */
static void check_full_width(fx_format f, int bytes, int stride_pad, int flip)
{
    uint8_t lv[3];
    int nl = levels(lv), ok = 1;
    for (int32_t w = 1; w <= MAXW && ok; w++) {
        buffer b;
        if (!buffer_make(&b, w, f, bytes, stride_pad, flip))
            return;
        for (int l = 0; l < nl && ok; l++) {
            b.s.fill_isa = lv[l];
            ok = fill_matches(&b, 0, w, "full width", stride_pad, flip);
        }
        buffer_drop(&b);
    }
}

FX_TEST(rect_fill_full_width_rows_padded_and_not)
{
    check_full_width(FX_FMT_XRGB8888, 4, 0, 0);
    check_full_width(FX_FMT_XRGB8888, 4, 12, 1);
    check_full_width(FX_FMT_RGB565, 2, 0, 1);
    check_full_width(FX_FMT_RGB565, 2, 6, 0);
}

/* Rows of FX_STOS_MIN_BYTES and more leave the vector path for rep stosq. */
FX_TEST(rect_fill_matches_plain_loop_around_the_long_run_switch)
{
    check_widths(FX_FMT_XRGB8888, 4, 4, 0, 2048 / 4 - 3, 2048 / 4 + 3);
    check_widths(FX_FMT_RGB565, 2, 2, 0, 2048 / 2 - 5, 2048 / 2 + 5);
}

/* fx_surface_init records what the CPU offers; the compiler's own CPU model
 * (which also asks the OS through XCR0) must agree with it. */
FX_TEST(surface_init_records_the_fill_level)
{
    uint32_t px[16];
    fx_surface s;
    FX_CHECK_EQ(fx_surface_init(&s, px, 4, 4, 16, FX_FMT_XRGB8888), 0);
    FX_CHECK_EQ(s.fill_isa, fx_x86_fill_level());
#if FX_X86_FILL
    __builtin_cpu_init();
    int want = __builtin_cpu_supports("avx512f") ? FX_FILL_AVX512
               : __builtin_cpu_supports("avx")   ? FX_FILL_AVX
                                                 : FX_FILL_PORTABLE;
    FX_CHECK_EQ(fx_x86_fill_level(), want);
#else
    FX_CHECK_EQ(fx_x86_fill_level(), FX_FILL_PORTABLE);
#endif
    /* a sub-surface keeps the answer */
    fx_rect r = {1, 1, 3, 3};
    FX_CHECK_EQ(fx_surface_sub(s, r).fill_isa, s.fill_isa);
}
