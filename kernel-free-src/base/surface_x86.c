/* SPDX-License-Identifier: MIT */
/* fixel — solid rectangles with AVX / AVX-512 stores, for x86-64 CPUs that
 * have them (see fx_internal.h for why this is decided at run time). */
#include "fx_internal.h"

#if FX_X86_FILL

static void cpuid(uint32_t leaf, uint32_t r[4])
{
    __asm__ volatile("cpuid" : "=a"(r[0]), "=b"(r[1]), "=c"(r[2]), "=d"(r[3]) : "a"(leaf), "c"(0));
}

uint8_t fx_x86_fill_level(void)
{
    uint32_t r[4];
    cpuid(0, r);
    uint32_t max = r[0];
    if (max < 1)
        return FX_FILL_PORTABLE;
    cpuid(1, r);
    /* AVX instructions need the CPU (ECX bit 28) and the OS saving the
     * ymm state (OSXSAVE, bit 27, then XCR0 bits 1-2). */
    if (!(r[2] >> 27 & 1) || !(r[2] >> 28 & 1))
        return FX_FILL_PORTABLE;
    uint32_t xcr0, hi;
    __asm__ volatile("xgetbv" : "=a"(xcr0), "=d"(hi) : "c"(0));
    if ((xcr0 & 0x6) != 0x6)
        return FX_FILL_PORTABLE;
    if (max >= 7) {
        cpuid(7, r);
        /* AVX512F (EBX bit 16) and the opmask/zmm state (XCR0 bits 5-7). */
        if ((r[1] >> 16 & 1) && (xcr0 & 0xE0) == 0xE0)
            return FX_FILL_AVX512;
    }
    return FX_FILL_AVX;
}

static void cpuid_sub(uint32_t leaf, uint32_t sub, uint32_t r[4])
{
    __asm__ volatile("cpuid" : "=a"(r[0]), "=b"(r[1]), "=c"(r[2]), "=d"(r[3]) : "a"(leaf), "c"(sub));
}

/* The bytes of the last-level cache: Intel's deterministic cache leaf 4
 * (AMD's reads as empty), else AMD's 0x80000006 (L3 in 512 KiB units);
 * 0 when neither says. */
static uint64_t llc_bytes(void)
{
    uint32_t r[4];
    cpuid(0, r);
    uint64_t best = 0;
    if (r[0] >= 4) {
        for (uint32_t sub = 0; sub < 16; sub++) {
            cpuid_sub(4, sub, r);
            if ((r[0] & 31) == 0)
                break;
            uint64_t b = (uint64_t)((r[1] >> 22) + 1) * (((r[1] >> 12) & 0x3FF) + 1) * ((r[1] & 0xFFF) + 1) *
                         ((uint64_t)r[2] + 1);
            if (b > best)
                best = b;
        }
    }
    if (best)
        return best;
    cpuid(0x80000000u, r);
    if (r[0] >= 0x80000006u) {
        cpuid(0x80000006u, r);
        best = (uint64_t)(r[3] >> 18) * (512u << 10);
    }
    return best;
}

/* CPUID traps to the hypervisor in a VM, and surfaces are made per image
 * and per band: read once (a race only repeats the same answer). 0 here
 * means not read yet, so a "no threshold" answer is kept as 1. */
uint8_t fx_x86_stream_mib(void)
{
    static uint8_t known;
    uint8_t v = __atomic_load_n(&known, __ATOMIC_RELAXED);
    if (!v) {
        uint64_t mib = llc_bytes() / 4 * 3 >> 20;
        v = mib < (FX_STREAM_MIN_BYTES >> 20) ? 1 : mib > 255 ? 255 : (uint8_t)mib;
        __atomic_store_n(&known, v, __ATOMIC_RELAXED);
    }
    return v == 1 ? 0 : v;
}

typedef uint32_t v4u32 __attribute__((vector_size(16)));
typedef uint32_t v8u32 __attribute__((vector_size(32)));
typedef uint32_t v16u32 __attribute__((vector_size(64)));

/* Rows narrower than one wide store: two stores of the largest size that
 * fits, overlapping in the middle (every row has the same width, so the
 * choice is made once per rectangle). */
#define NARROW_ROWS(row, nb, h, stride, p)                                   \
    do {                                                                     \
        if (nb >= 16) {                                                      \
            v4u32 q4 = {p, p, p, p};                                         \
            for (; h--; row += stride) {                                     \
                fx_memcpy(row, &q4, 16);                                     \
                fx_memcpy(row + nb - 16, &q4, 16);                           \
            }                                                                \
        } else if (nb >= 8) {                                                \
            uint64_t p8 = p * 0x100000001ull;                                \
            for (; h--; row += stride) {                                     \
                fx_memcpy(row, &p8, 8);                                      \
                fx_memcpy(row + nb - 8, &p8, 8);                             \
            }                                                                \
        } else if (nb >= 4) {                                                \
            for (; h--; row += stride) {                                     \
                fx_memcpy(row, &p, 4);                                       \
                fx_memcpy(row + nb - 4, &p, 4);                              \
            }                                                                \
        } else {                                                             \
            uint16_t p2 = (uint16_t)p;                                       \
            for (; h--; row += stride)                                       \
                fx_memcpy(row, &p2, 2);                                      \
        }                                                                    \
    } while (0)

/* Wide rows (nb >= W): an unaligned store of the W-byte vector q at each
 * end, aligned ones in between (a store that crosses a cache line costs
 * two). A macro, because each body must be compiled for its own target. */
#define WIDE_ROWS(row, nb, h, stride, q, W)                                  \
    for (; h--; row += stride) {                                             \
        uint8_t *e_ = row + nb - (W);                                        \
        uint8_t *a_ = (uint8_t *)(((uintptr_t)row + (W)) & ~(uintptr_t)((W)-1)); \
        fx_memcpy(row, &q, W);                                               \
        for (; a_ < e_; a_ += (W))                                           \
            fx_memcpy(__builtin_assume_aligned(a_, W), &q, W);               \
        fx_memcpy(e_, &q, W);                                                \
    }

/* The arguments of the row loops from fx_rect_fill_avx*'s: the first
 * pixel, the bytes per row and the pattern (a 16-bit pixel twice). */
#define RECT_ROWS_ARGS(s, r, v)                                                    \
    size_t bytes_ = fx_format_table[(s)->format].bits_per_pixel / 8u;             \
    uint8_t *row = fx_row((s), (r).y0) + (size_t)(r).x0 * bytes_;                 \
    size_t nb = (size_t)((r).x1 - (r).x0) * bytes_;                               \
    int32_t h = (r).y1 - (r).y0;                                                   \
    ptrdiff_t stride = (s)->stride;                                                \
    uint32_t p = bytes_ == 4 ? (v) : ((v)&0xFFFF) * 0x10001u

__attribute__((target("avx"))) void fx_rect_fill_avx(const fx_surface *s, fx_rect r, uint32_t v)
{
    RECT_ROWS_ARGS(s, r, v);
    if (nb < 32) {
        NARROW_ROWS(row, nb, h, stride, p);
        return;
    }
    v8u32 q = {p, p, p, p, p, p, p, p};
    WIDE_ROWS(row, nb, h, stride, q, 32);
}

__attribute__((target("avx512f"))) void fx_rect_fill_avx512(const fx_surface *s, fx_rect r, uint32_t v)
{
    RECT_ROWS_ARGS(s, r, v);
    if (nb < 32) {
        NARROW_ROWS(row, nb, h, stride, p);
        return;
    }
    if (nb < 64) {
        v8u32 q8 = {p, p, p, p, p, p, p, p};
        for (; h--; row += stride) {
            fx_memcpy(row, &q8, 32);
            fx_memcpy(row + nb - 32, &q8, 32);
        }
        return;
    }
    v16u32 q = {p, p, p, p, p, p, p, p, p, p, p, p, p, p, p, p};
    WIDE_ROWS(row, nb, h, stride, q, 64);
}

/* ---- streaming (non-temporal) stores for whole frames ----
 * movntdq writes a full line to memory without reading it first and without
 * keeping it: a cached store of a line that is not in the cache costs a
 * read for ownership, then the write-back. That wins only for blocks the
 * last-level cache cannot keep (fx_stream_min: three quarters of it, as
 * glibc decides); a frame that fits stays cached for the drawing that
 * follows. SDL2's SDL_BlitCopy and SDL_FillRect stream every size
 * (SDL_memcpySSE, _mm_stream_ps), which beat memcpy only while neighbours
 * kept evicting a shared L3. SSE2 is part of x86-64, so no run-time check
 * is needed. The sfence orders the weakly ordered streaming stores before
 * whatever the caller does next (a present by another thread, a DMA). */
/* Non-temporal stores: GCC names the instructions' builtins; clang (the
 * fuzz build) has only its generic form. */
#if defined(__clang__)
#define FX_STREAM16(p, v) __builtin_nontemporal_store((v), (p))
#define FX_STREAM32(p, v) __builtin_nontemporal_store((v), (p))
#else
#define FX_STREAM16(p, v) __builtin_ia32_movntdq((p), (v))
#define FX_STREAM32(p, v) __builtin_ia32_movntdq256((p), (v))
#endif
typedef long long v2i64 __attribute__((vector_size(16)));

void fx_stream_fill(uint8_t *p, size_t n, uint64_t pattern)
{
    v2i64 q = {(long long)pattern, (long long)pattern};
    size_t head = (size_t)(-(uintptr_t)p & 15);
    /* p is pixel-aligned and 16 is a multiple of the pixel size, so the
     * head is whole pixels and the body starts on a pixel of the pattern */
    fx_memcpy(p, &q, head);
    p += head;
    n -= head;
    uint8_t *e = p + (n & ~(size_t)63);
    for (; p < e; p += 64) {
        FX_STREAM16((v2i64 *)(void *)p, q);
        FX_STREAM16((v2i64 *)(void *)(p + 16), q);
        FX_STREAM16((v2i64 *)(void *)(p + 32), q);
        FX_STREAM16((v2i64 *)(void *)(p + 48), q);
    }
    n &= 63;
    for (; n >= 16; n -= 16, p += 16)
        FX_STREAM16((v2i64 *)(void *)p, q);
    __builtin_ia32_sfence();
    fx_memcpy(p, &q, n);
}

/* The same with 32-byte streaming stores where the CPU has AVX: half the
 * store instructions for the same lines. */
typedef long long v4i64 __attribute__((vector_size(32)));
__attribute__((target("avx"))) void fx_stream_fill_avx(uint8_t *p, size_t n, uint64_t pattern)
{
    v4i64 q = {(long long)pattern, (long long)pattern, (long long)pattern, (long long)pattern};
    size_t head = (size_t)(-(uintptr_t)p & 31);
    fx_memcpy(p, &q, head);
    p += head;
    n -= head;
    uint8_t *e = p + (n & ~(size_t)63);
    for (; p < e; p += 64) {
        FX_STREAM32((v4i64 *)(void *)p, q);
        FX_STREAM32((v4i64 *)(void *)(p + 32), q);
    }
    n &= 63;
    if (n >= 32) {
        FX_STREAM32((v4i64 *)(void *)p, q);
        p += 32;
        n -= 32;
    }
    __builtin_ia32_sfence();
    fx_memcpy(p, &q, n);
}

void fx_stream_copy(uint8_t *d, const uint8_t *s, size_t n)
{
    size_t head = (size_t)(-(uintptr_t)d & 15);
    fx_memcpy(d, s, head);
    d += head;
    s += head;
    n -= head;
    uint8_t *e = d + (n & ~(size_t)63);
    for (; d < e; d += 64, s += 64) {
        v2i64 a, b, c, x;
        fx_memcpy(&a, s, 16);
        fx_memcpy(&b, s + 16, 16);
        fx_memcpy(&c, s + 32, 16);
        fx_memcpy(&x, s + 48, 16);
        FX_STREAM16((v2i64 *)(void *)d, a);
        FX_STREAM16((v2i64 *)(void *)(d + 16), b);
        FX_STREAM16((v2i64 *)(void *)(d + 32), c);
        FX_STREAM16((v2i64 *)(void *)(d + 48), x);
    }
    __builtin_ia32_sfence();
    fx_memcpy(d, s, n & 63);
}

#else

uint8_t fx_x86_fill_level(void) { return FX_FILL_PORTABLE; }
uint8_t fx_x86_stream_mib(void) { return 0; }

#endif
