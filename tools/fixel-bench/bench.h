/* SPDX-License-Identifier: MIT */
/* fixel-bench — shared declarations of the harness and its peers.
 *
 * The workloads are the ten of docs/BENCHMARK.md. The
 * harness generates them once, owns one 64-byte-aligned 1920x1080 buffer and
 * hands it to every peer; a peer only knows how to draw the first n
 * primitives of a workload into that buffer in one of the two formats.
 */
#ifndef FIXEL_BENCH_H
#define FIXEL_BENCH_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#define BW 1920
#define BH 1080

enum { FMT_XRGB8888, FMT_RGB565, FMT_COUNT };

enum {
    W1_CLEAR,
    W2_RECTS,
    W3_LINES,
    W4_AALINES,
    W5_CIRCLES,
    W6_DISCS,
    W7_POLYS,
    W8_TRIS,
    W8G_TRIS_GOURAUD,
    W9_MANDEL,
    W10_BLIT,
    W_COUNT
};

#define N_RECTS 10000
#define N_LINES 100000
#define N_AALINES 20000
#define N_CIRCLES 20000
#define N_DISCS 5000
#define N_POLYS 2000
#define N_TRIS 20000
#define POLY_N 8

#define W1_COLOUR 0x2060A0u

struct wl_rect { int x, y, w, h; uint32_t c; };
struct wl_line { int x0, y0, x1, y1; uint32_t c; };
struct wl_circle { int cx, cy, r; uint32_t c; };
struct wl_poly { int x[POLY_N], y[POLY_N]; uint32_t c; };
struct wl_tri { int x[3], y[3]; uint32_t c[3]; };

struct workloads {
    struct wl_rect rects[N_RECTS];
    struct wl_line lines[N_LINES];       /* W4 uses the first N_AALINES */
    struct wl_circle circles[N_CIRCLES]; /* W6 uses the first N_DISCS */
    struct wl_poly polys[N_POLYS];
    struct wl_tri tris[N_TRIS];
    /* W10 sources, one per format, 64-byte aligned, stride = BW * bpp */
    void *blit_src[FMT_COUNT];
};

/* gen.c: each format's name (as -f and the tables spell it) and bytes a pixel. */
extern const char *const FMT_NAME[FMT_COUNT];
extern const int BPP[FMT_COUNT];

/* Generated once before anything is timed; read-only afterwards. */
extern const struct workloads *WL;
/* gen.c: fills w by section 2 (and the W10 sources); bench_alloc64 exits
 * the program when memory runs out. */
void bench_generate(struct workloads *w);
void *bench_alloc64(size_t n);

/* The destination every peer draws into for the current format. */
struct target {
    uint8_t *pixels; /* 64-byte aligned */
    int fmt;         /* FMT_* */
    int stride;      /* BW * bytes per pixel */
};

typedef void (*draw_fn)(void *ctx, int n);

/* A peer: one library (or ceiling) under test. open() prepares whatever the
 * library needs to draw into t (not timed); fn[w] draws the first n
 * primitives of workload w, or is NULL when the peer has no such operation
 * (the table shows "-"). fmt_mask says which formats open() accepts. */
struct peer {
    const char *name;
    unsigned fmt_mask;
    void *(*open)(const struct target *t);
    void (*close)(void *ctx);
    draw_fn fn[W_COUNT];
};

extern const struct peer peer_fixel, peer_fixel_api, peer_fixel_mt, peer_libc, peer_ref, peer_ref_native;
#ifdef BENCH_PEERS
extern const struct peer peer_cairo, peer_pixman, peer_sdl2, peer_sdlgfx;
#endif

/* timing.c: the monotonic clock in seconds, and qsort's order for doubles. */
double bench_secs(void);
int bench_cmp_double(const void *a, const void *b);

/* w3classes.c, fixel-bench --w3-classes: W3 split by slope class, each
 * class timed for peers[0] (fixel) and the others, interleaved, with the
 * store floor of the steep and mid lines; the formats in the mask fmts. */
int w3_classes(FILE *o, const struct peer *const *peers, int npeers, uint8_t *buf, int rounds, unsigned fmts);

/* Draws the full workload w onto t (black beforehand) by the literal
 * definitions of docs/BENCHMARK.md; returns 0 when w has no such reference. */
int reference_draw(const struct target *t, int w);

/* "cairo 1.16.0, pixman 0.42.2, ..." for the table header. */
const char *peer_versions(void);

/* The double-precision W9 loop of docs/BENCHMARK.md, writing XRGB8888 into dst
 * (stride BW*4). ref_mandel is built at -O2 -fno-tree-vectorize (the
 * baseline), ref_native_mandel at -O3 -march=native. */
void ref_mandel(uint32_t *dst);
void ref_native_mandel(uint32_t *dst);
/* A plain scalar store loop filling the surface, built like ref_mandel. */
void ref_clear(const struct target *t, uint32_t native);
void ref_native_clear(const struct target *t, uint32_t native);
/* W2 with nothing but clipping and stores: ref one store per pixel, ref-native
 * the widest vector stores of the build machine (the access pattern's ceiling). */
void ref_rects(const struct target *t, int n);
void ref_native_rects(const struct target *t, int n);

static inline uint32_t pack565(uint32_t c)
{
    return ((c >> 19 & 0x1F) << 11) | ((c >> 10 & 0x3F) << 5) | (c >> 3 & 0x1F);
}

/* One step of the midpoint circle from (r, 0) with d = 1 - r, the walk both
 * the nominal W5 pixel count (main.c) and the W5 reference picture
 * (reference.c) take: y advances, x steps in when the midpoint is outside. */
static inline void midpoint_circle_step(int *x, int *y, int *d)
{
    ++*y;
    if (*d < 0) {
        *d += 2 * *y + 1;
    } else {
        --*x;
        *d += 2 * (*y - *x) + 1;
    }
}

/* TABLE 4 (extras.c): presentation, teapot, deep zoom, idle loop. only:
 * the -w list (NULL: all); fmt_mask: bit per FMT_*. */
void extras_run(const char *only, int fmt_mask, int trials, double min_s, int quiet,
                int (*listed)(const char *, const char *));
void extras_print(FILE *o);
/* TABLE 5 (raytrace.c): the ray tracer against its double reference. */
void raytrace_run(int quiet);
void raytrace_print(FILE *o);
/* TABLE 6 (vsd_bench.c): the visible-surface methods at two scene sizes. */
void vsd_bench_run(int trials, double min_s, int quiet);
void vsd_bench_print(FILE *o);
/* TABLE 7 (fractal_bench.c): issue #23's fractals, one call each. */
void fractal_bench_run(int trials, double min_s, int quiet);
void fractal_bench_print(FILE *o);

#endif
