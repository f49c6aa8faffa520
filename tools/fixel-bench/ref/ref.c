/* SPDX-License-Identifier: MIT */
/* The double-precision reference of W9 (and plain store loops for W1 and W2),
 * compiled twice by bench.mk: as-is at -O2 -fno-tree-vectorize (peer "ref",
 * the baseline docs/BENCHMARK.md names) and with -DREF_NATIVE at -O3
 * -march=native (peer "ref-native"). Kept in its own file so that the
 * project's flags never change what the baseline measures. */
#include "../bench.h"

#ifdef REF_NATIVE
#define REF(name) ref_native_##name
#else
#define REF(name) ref_##name
#endif

void REF(mandel)(uint32_t *dst)
{
    uint32_t pal[257];
    for (int n = 0; n < 256; n++)
        pal[n] = (uint32_t)(4 * n < 255 ? 4 * n : 255) * 0x010101u;
    pal[256] = 0;

    const double s = 3.0 / 1920;
    for (int y = 0; y < BH; y++) {
        double ci = (540.0 - (y + 0.5)) * s;
        uint32_t *row = dst + (size_t)y * BW;
        for (int x = 0; x < BW; x++) {
            double cr = -0.5 + ((x + 0.5) - 960.0) * s;
            double zr = 0, zi = 0;
            int n = 0;
            while (n < 256) {
                double zr2 = zr * zr, zi2 = zi * zi;
                if (zr2 + zi2 > 4.0)
                    break;
                zi = 2 * zr * zi + ci;
                zr = zr2 - zi2 + cr;
                n++;
            }
            row[x] = pal[n];
        }
    }
}

void REF(clear)(const struct target *t, uint32_t native)
{
    if (t->fmt == FMT_XRGB8888) {
        uint32_t *p = (uint32_t *)t->pixels;
        for (size_t i = 0; i < (size_t)BW * BH; i++)
            p[i] = native;
    } else {
        uint16_t *p = (uint16_t *)t->pixels;
        for (size_t i = 0; i < (size_t)BW * BH; i++)
            p[i] = (uint16_t)native;
    }
}

/* W2's ceiling: each rectangle clipped once, then nothing but stores per
 * row. At -O2 -fno-tree-vectorize ("ref") one store per pixel; the native
 * build ("ref-native") uses the widest vector the machine has, unaligned at
 * both ends of a row and aligned in between, the best hand loop we know for
 * rows of ~65 pixels. */
#if defined(REF_NATIVE) && defined(__GNUC__) && (defined(__AVX512F__) || defined(__AVX__) || defined(__SSE2__))
#include <string.h>
#if defined(__AVX512F__)
#define VB 64
#elif defined(__AVX__)
#define VB 32
#else
#define VB 16
#endif
typedef uint32_t vec __attribute__((vector_size(VB)));
typedef uint32_t v4 __attribute__((vector_size(16)));
typedef uint32_t v8 __attribute__((vector_size(32)));

static void rows(uint8_t *row, size_t nb, int h, size_t stride, uint32_t p)
{
    vec q;
    for (unsigned i = 0; i < VB / 4; i++)
        q[i] = p;
    if (nb >= VB) {
        for (; h--; row += stride) {
            uint8_t *e = row + nb - VB, *a = (uint8_t *)(((uintptr_t)row + VB) & ~(uintptr_t)(VB - 1));
            memcpy(row, &q, VB);
            for (; a < e; a += VB)
                memcpy(__builtin_assume_aligned(a, VB), &q, VB);
            memcpy(e, &q, VB);
        }
#if VB > 32
    } else if (nb >= 32) {
        v8 q8 = {p, p, p, p, p, p, p, p};
        for (; h--; row += stride) {
            memcpy(row, &q8, 32);
            memcpy(row + nb - 32, &q8, 32);
        }
#endif
#if VB > 16
    } else if (nb >= 16) {
        v4 q4 = {p, p, p, p};
        for (; h--; row += stride) {
            memcpy(row, &q4, 16);
            memcpy(row + nb - 16, &q4, 16);
        }
#endif
    } else if (nb >= 8) {
        uint64_t p8 = p * 0x100000001ull;
        for (; h--; row += stride) {
            memcpy(row, &p8, 8);
            memcpy(row + nb - 8, &p8, 8);
        }
    } else if (nb >= 4) {
        for (; h--; row += stride) {
            memcpy(row, &p, 4);
            memcpy(row + nb - 4, &p, 4);
        }
    } else {
        uint16_t p2 = (uint16_t)p;
        for (; h--; row += stride)
            memcpy(row, &p2, 2);
    }
}

void REF(rects)(const struct target *t, int n)
{
    size_t bpp = t->fmt == FMT_XRGB8888 ? 4 : 2;
    for (int i = 0; i < n; i++) {
        const struct wl_rect *r = &WL->rects[i];
        int x1 = r->x + r->w < BW ? r->x + r->w : BW, y1 = r->y + r->h < BH ? r->y + r->h : BH;
        uint32_t p = t->fmt == FMT_XRGB8888 ? r->c : pack565(r->c) * 0x10001u;
        rows(t->pixels + (size_t)r->y * (size_t)t->stride + (size_t)r->x * bpp,
             (size_t)(x1 - r->x) * bpp, y1 - r->y, (size_t)t->stride, p);
    }
}
#else
void REF(rects)(const struct target *t, int n)
{
    for (int i = 0; i < n; i++) {
        const struct wl_rect *r = &WL->rects[i];
        int x1 = r->x + r->w < BW ? r->x + r->w : BW, y1 = r->y + r->h < BH ? r->y + r->h : BH;
        if (t->fmt == FMT_XRGB8888) {
            for (int y = r->y; y < y1; y++) {
                uint32_t *p = (uint32_t *)(t->pixels + (size_t)y * (size_t)t->stride);
                for (int x = r->x; x < x1; x++)
                    p[x] = r->c;
            }
        } else {
            uint16_t v = (uint16_t)pack565(r->c);
            for (int y = r->y; y < y1; y++) {
                uint16_t *p = (uint16_t *)(t->pixels + (size_t)y * (size_t)t->stride);
                for (int x = r->x; x < x1; x++)
                    p[x] = v;
            }
        }
    }
}
#endif
