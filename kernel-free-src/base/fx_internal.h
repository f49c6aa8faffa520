/* SPDX-License-Identifier: MIT */
/* Internal helpers shared by core files; not installed. */
#ifndef FIXEL_INTERNAL_H
#define FIXEL_INTERNAL_H

#include <stddef.h>
#include <stdint.h>
#include "fixel/fixed.h"
#include "fixel/surface.h"

/* The core may call only the mem* functions of libc; the builtins make that
 * explicit and let the compiler inline small constant-size cases. */
#define fx_memset  __builtin_memset
#define fx_memcpy  __builtin_memcpy
#define fx_memmove __builtin_memmove

#define FX_MIN(a, b) ((a) < (b) ? (a) : (b))
#define FX_MAX(a, b) ((a) > (b) ? (a) : (b))
/* Internal data shared between the core's files: not exported from the
 * shared library, and reached without a GOT load from position-independent
 * code. */
#define FX_HIDDEN __attribute__((visibility("hidden")))
#define FX_ARRAY_LEN(a) (sizeof(a) / sizeof((a)[0]))

/* Return a negative error code from the enclosing function: the one TRY of
 * the core. Token for token the copies in the scene files, so a file may include
 * this header and keep its own copy while those are being removed. */
#define TRY(x)                   \
    do {                         \
        int r_ = (x);            \
        if (r_ < 0)              \
            return r_;           \
    } while (0)

/* x^n for x in [0, 1] by square-and-multiply, each product fx16_mul
 * (the Phong highlights of render3d and the ray tracer). */
static inline fx16 fx16_powi(fx16 x, int32_t n)
{
    fx16 r = FX16_ONE;
    while (n > 0) {
        if (n & 1)
            r = fx16_mul(r, x);
        x = fx16_mul(x, x);
        n >>= 1;
    }
    return r;
}

static inline uint32_t fx_luma(fx_color c)
{
    uint32_t r = (c >> 16) & 0xFF, g = (c >> 8) & 0xFF, b = c & 0xFF;
    return (77 * r + 150 * g + 29 * b + 128) >> 8;
}

/* fx_pack, inline for fx_ctx_set_color: a program that sets the colour
 * before every primitive pays no call for it. No default case: -Wswitch
 * (in -Wall, an error under -Werror) then names a format left out here,
 * which used to pack to 0 and draw black without a word (issue #42). */
static inline uint32_t fx_pack_inline(fx_format f, fx_color c)
{
    uint32_t r = (c >> 16) & 0xFF, g = (c >> 8) & 0xFF, b = c & 0xFF;
    switch (f) {
    case FX_FMT_XRGB8888: return c & 0xFFFFFF;
    case FX_FMT_ARGB8888: return c;
    case FX_FMT_XBGR8888: return (b << 16) | (g << 8) | r;
    case FX_FMT_RGB565: return ((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3);
    case FX_FMT_BGR565: return ((b >> 3) << 11) | ((g >> 2) << 5) | (r >> 3);
    case FX_FMT_RGB888: return c & 0xFFFFFF;
    case FX_FMT_BGR888: return (b << 16) | (g << 8) | r;
    case FX_FMT_GRAY8: return fx_luma(c);
    case FX_FMT_MONO1: return fx_luma(c) >= 128;
    case FX_FMT_COUNT: break; /* no format */
    }
    return 0;
}

/* fx_rect_intersect, inline for the per-primitive entry points. */
static inline fx_rect fx_rect_meet(fx_rect a, fx_rect b)
{
    fx_rect r = {FX_MAX(a.x0, b.x0), FX_MAX(a.y0, b.y0), FX_MIN(a.x1, b.x1), FX_MIN(a.y1, b.y1)};
    if (fx_rect_empty(r))
        r.x1 = r.x0, r.y1 = r.y0;
    return r;
}

static inline uint8_t *fx_row(const struct fx_surface *s, int32_t y)
{
    return s->pixels + (ptrdiff_t)y * s->stride;
}

/* ---- solid runs of 32- and 16-bit pixels ----
 * 16-byte stores through GCC's generic vectors (SSE2/NEON registers where
 * the target has them, pairs of 64-bit stores under -mgeneral-regs-only):
 * -O2 leaves a plain loop at one store per pixel. The unaligned head and
 * tail stores overlap the aligned body, which is harmless for a solid fill
 * and saves the byte-wise edges. p must be aligned to its pixel size;
 * anything else takes the plain loop. */
typedef uint32_t fx_v4u32 __attribute__((vector_size(16)));
typedef uint16_t fx_v8u16 __attribute__((vector_size(16)));

/* Long runs on x86-64 go to the string-store microcode: with ERMS/FSRM it
 * writes whole cache lines at the widest store the core has (AVX-512 on
 * recent parts), which a 16-byte loop cannot reach and -mgeneral-regs-only
 * cannot name. rep stosq repeats any 64-bit pattern, so it serves 16- and
 * 32-bit pixels alike. Below about 2 KiB its start-up cost loses to the
 * vector loop (glibc's memset picks the same threshold). The vector loop
 * stays the reference on every other architecture and for short runs. */
#if defined(__x86_64__)
#define FX_STOS_MIN_BYTES 2048
/* In pieces of 512 KiB: one rep stos over a whole 8 MB frame ran at 41
 * GB/s instead of 105 in some processes here (libc memset too; per
 * process, so it is where the buffer landed), as if the microcode had
 * switched to streaming stores for a long count; pieces never did, and
 * 4 MB frames never did either. */
#define FX_STOS_CHUNK_WORDS (512 * 1024 / 8)
static inline void fx_stosq(void *p, size_t words, uint64_t pattern)
{
    while (words) {
        size_t c = words < FX_STOS_CHUNK_WORDS ? words : FX_STOS_CHUNK_WORDS;
        words -= c;
        __asm__ volatile("rep stosq" : "+D"(p), "+c"(c) : "a"(pattern) : "memory");
    }
}

/* nbytes of pixels from a pixel-aligned p, pattern holding whole pixels
 * (2 or 4 bytes, which divide 8): the head up to an 8-byte boundary and the
 * tail are the pattern's first bytes, which start on a pixel (x86 is
 * little-endian), so one helper serves both sizes. */
static inline void fx_stos_run(void *dst, size_t nbytes, uint64_t pattern)
{
    uint8_t *p = (uint8_t *)dst;
    size_t head = (size_t)(-(uintptr_t)p & 7);
    fx_memcpy(p, &pattern, head);
    p += head;
    nbytes -= head;
    fx_stosq(p, nbytes / 8, pattern);
    fx_memcpy(p + (nbytes & ~(size_t)7), &pattern, nbytes & 7);
}
#endif

static inline void fx_run32(uint32_t *p, int32_t n, uint32_t v)
{
    if (n < 4 || ((uintptr_t)p & 3)) {
        while (n-- > 0)
            *p++ = v;
        return;
    }
#if defined(__x86_64__)
    if ((size_t)n * 4 >= FX_STOS_MIN_BYTES) {
        fx_stos_run(p, (size_t)n * 4, v | (uint64_t)v << 32);
        return;
    }
#endif
    fx_v4u32 q = {v, v, v, v};
    fx_memcpy(p, &q, 16);
    fx_memcpy(p + n - 4, &q, 16);
    uint32_t *a = (uint32_t *)(((uintptr_t)p + 16) & ~(uintptr_t)15), *e = p + n - 4;
    for (; a + 8 <= e; a += 8) {
        *(fx_v4u32 *)(void *)a = q;
        *(fx_v4u32 *)(void *)(a + 4) = q;
    }
    for (; a < e; a += 4)
        *(fx_v4u32 *)(void *)a = q;
}

static inline void fx_run16(uint16_t *p, int32_t n, uint16_t v)
{
    if (n < 8 || ((uintptr_t)p & 1)) {
        while (n-- > 0)
            *p++ = v;
        return;
    }
#if defined(__x86_64__)
    if ((size_t)n * 2 >= FX_STOS_MIN_BYTES) {
        fx_stos_run(p, (size_t)n * 2, v * 0x0001000100010001ull);
        return;
    }
#endif
    fx_v8u16 q = {v, v, v, v, v, v, v, v};
    fx_memcpy(p, &q, 16);
    fx_memcpy(p + n - 8, &q, 16);
    uint16_t *a = (uint16_t *)(((uintptr_t)p + 16) & ~(uintptr_t)15), *e = p + n - 8;
    for (; a + 16 <= e; a += 16) {
        *(fx_v8u16 *)(void *)a = q;
        *(fx_v8u16 *)(void *)(a + 8) = q;
    }
    for (; a < e; a += 8)
        *(fx_v8u16 *)(void *)a = q;
}

/* ---- x86 rectangle fills chosen at run time ----
 * A plain x86-64 build may only assume SSE2, yet solid rectangles are bound
 * by the number of stores per row: 32- and 64-byte stores fill ~1.3x faster
 * than the 16-byte loop above. The core has no mutable globals to cache a
 * CPU check in, and cpuid traps to the hypervisor in a VM, so
 * fx_surface_init asks once and keeps the answer in the surface (fill_isa).
 * Builds without SSE (-mgeneral-regs-only, i.e. kernel-style code that must
 * not touch vector state) and other architectures keep the portable path. */
#if defined(__x86_64__) && defined(__SSE2__) && defined(__GNUC__)
#define FX_X86_FILL 1
#else
#define FX_X86_FILL 0
#endif
enum { FX_FILL_PORTABLE = 0, FX_FILL_AVX = 1, FX_FILL_AVX512 = 2 };
/* The level this CPU and OS support (always FX_FILL_PORTABLE without FX_X86_FILL). */
uint8_t fx_x86_fill_level(void);
/* The clipped, non-empty rectangle r of the 32- or 16-bit surface s (pixels
 * and stride pixel-aligned) filled with the native value v. They take the
 * surface, not a row pointer, so that their callers pass their own
 * arguments on (fx_rect_fill_native). */
void fx_rect_fill_avx(const fx_surface *s, fx_rect r, uint32_t v);
void fx_rect_fill_avx512(const fx_surface *s, fx_rect r, uint32_t v);

/* The format table (surface.c); callers index it with a valid format. */
extern FX_HIDDEN const fx_format_info fx_format_table[FX_FMT_COUNT];

/* Whole frames with streaming stores (surface_x86.c): fill n bytes at the
 * pixel-aligned p with the 8-byte pattern of whole pixels; copy n bytes
 * between blocks that do not overlap. The same bytes as the cached paths.
 * Taken when the bytes an operation touches (a fill n, a copy 2n) reach
 * fx_stream_min(s): three quarters of the CPU's last-level cache
 * (fx_x86_stream_mib, read once), never below FX_STREAM_MIN_BYTES; like
 * glibc's memset and memcpy, which stream only above a large fraction of
 * the L3, so a frame that fits stays cached. Below that a frame is
 * left in the cache, where the drawing that follows a clear finds it:
 * measured on a 2-core Zen 3 with a 32 MB L3, an 8 MB XRGB8888 clear
 * streamed ran at 0.42x memset on a quiet machine (the cached fill
 * stays in the L3) and a kiosk's panels drawn over a streamed clear took
 * twice the CPU; only when other tenants keep evicting the L3 did streaming
 * win (1.1-1.4x memcpy, SDL2's speed). */
#define FX_STREAM_MIN_BYTES (6u << 20)
uint8_t fx_x86_stream_mib(void);
static inline size_t fx_stream_min(const fx_surface *s)
{
    return s->stream_mib ? (size_t)s->stream_mib << 20 : FX_STREAM_MIN_BYTES;
}
void fx_stream_fill(uint8_t *p, size_t n, uint64_t pattern);
void fx_stream_fill_avx(uint8_t *p, size_t n, uint64_t pattern);
void fx_stream_copy(uint8_t *d, const uint8_t *s, size_t n);

#endif
