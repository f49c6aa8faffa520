/* SPDX-License-Identifier: MIT */
/* fixel-bench — the workload arrays of docs/BENCHMARK.md section 2, shared by
 * fixel-bench and fixel-insn (the instruction counts of `make bench-insn`),
 * so both draw the very same primitives. */
#include "bench.h"

#include <stdlib.h>

const char *const FMT_NAME[FMT_COUNT] = {"xrgb8888", "rgb565"};
const int BPP[FMT_COUNT] = {4, 2};

/* ---- generation (section 2) --------------------------------------------- */

static inline uint32_t xorshift32(uint32_t *s)
{
    uint32_t x = *s;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    return *s = x;
}
static inline int rnd(uint32_t *s, uint32_t n) { return (int)(xorshift32(s) % n); }

static void generate(struct workloads *w)
{
    uint32_t s = 12345;
    for (int i = 0; i < N_RECTS; i++) {
        struct wl_rect *r = &w->rects[i];
        r->x = rnd(&s, 1920);
        r->y = rnd(&s, 1080);
        r->w = 1 + rnd(&s, 128);
        r->h = 1 + rnd(&s, 128);
        r->c = xorshift32(&s) & 0xFFFFFF;
    }
    s = 12345;
    for (int i = 0; i < N_LINES; i++) {
        struct wl_line *l = &w->lines[i];
        l->x0 = rnd(&s, 1920);
        l->y0 = rnd(&s, 1080);
        l->x1 = rnd(&s, 1920);
        l->y1 = rnd(&s, 1080);
        l->c = xorshift32(&s) & 0xFFFFFF;
    }
    s = 12345;
    for (int i = 0; i < N_CIRCLES; i++) {
        struct wl_circle *c = &w->circles[i];
        c->cx = rnd(&s, 1920);
        c->cy = rnd(&s, 1080);
        c->r = 1 + rnd(&s, 200);
        c->c = xorshift32(&s) & 0xFFFFFF;
    }
    s = 12345;
    for (int i = 0; i < N_POLYS; i++) {
        struct wl_poly *p = &w->polys[i];
        int bx = rnd(&s, 1620), by = rnd(&s, 780);
        for (int k = 0; k < POLY_N; k++) {
            p->x[k] = bx + rnd(&s, 300);
            p->y[k] = by + rnd(&s, 300);
        }
        p->c = xorshift32(&s) & 0xFFFFFF;
    }
    s = 12345;
    for (int i = 0; i < N_TRIS; i++) {
        struct wl_tri *t = &w->tris[i];
        int bx = rnd(&s, 1820), by = rnd(&s, 980);
        for (int k = 0; k < 3; k++) {
            t->x[k] = bx + rnd(&s, 100);
            t->y[k] = by + rnd(&s, 100);
        }
        for (int k = 0; k < 3; k++)
            t->c[k] = xorshift32(&s) & 0xFFFFFF;
    }
}

void *bench_alloc64(size_t n)
{
    void *p = aligned_alloc(64, (n + 63) & ~(size_t)63);
    if (!p) {
        fprintf(stderr, "fixel-bench: out of memory\n");
        exit(2);
    }
    return p;
}

static void make_blit_sources(struct workloads *w)
{
    uint32_t *x = bench_alloc64((size_t)BW * BH * 4);
    uint16_t *r = bench_alloc64((size_t)BW * BH * 2);
    for (int y = 0; y < BH; y++)
        for (int i = 0; i < BW; i++) {
            uint32_t c = (uint32_t)((i ^ y) & 0xFF) << 16 | (uint32_t)(i * 255 / 1920) << 8 |
                         (uint32_t)(y * 255 / 1080);
            x[(size_t)y * BW + i] = c;
            r[(size_t)y * BW + i] = (uint16_t)pack565(c);
        }
    w->blit_src[FMT_XRGB8888] = x;
    w->blit_src[FMT_RGB565] = r;
}

void bench_generate(struct workloads *w)
{
    generate(w);
    make_blit_sources(w);
}
