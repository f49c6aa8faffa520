/* SPDX-License-Identifier: MIT */
/* fixel-bench --w3-classes: W3's own lines split by how they meet memory,
 * each class timed for every peer, interleaved. A steep line (|dy| > |dx|)
 * writes one pixel per row, so every pixel is a new cache line (and, in
 * XRGB8888, nearly every one a new 4 KiB page); an x-major line with fewer
 * than 4 pixels per row ("mid") starts a new line every 1-3 pixels; one
 * with 4 or more ("shallow") writes runs. (fixel draws x-major lines of 2
 * or more pixels a row as runs, so most "mid" lines too.) The whole-W3
 * ratio is the classes' ratios weighted by their time, so this says which
 * class holds it back and whether that class is at the machine's store
 * floor: "floor" is a plain C loop storing the same pixels of the steep
 * and the mid lines, one store a pixel (the DDA with nothing else; no
 * library): what a per-pixel writer pays for them here. For the steep
 * lines, one pixel a cache line, that is the least anyone pays; on the mid
 * lines fixel's DDA (independent steps) and its runs beat the chained
 * loop (docs/PERFORMANCE.md). */
#include "bench.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { C_STEEP, C_MID, C_SHALLOW, C_COUNT };
static const char *const CLASS_NAME[C_COUNT] = {"steep", "mid (x, 1-3/row)", "shallow (x, 4+/row)"};

static int class_of(const struct wl_line *l)
{
    unsigned dx = (unsigned)abs(l->x1 - l->x0), dy = (unsigned)abs(l->y1 - l->y0);
    if (dy > dx)
        return C_STEEP;
    return dy == 0 || dx / dy >= 4 ? C_SHALLOW : C_MID;
}

/* The lines' pixels by the same exact DDA as fixel's walk, from (x0, y0)
 * to (x1, y1) as given (the direction decides the ties), so the same
 * cache lines in the same order, stored from a plain loop: a step along
 * the major axis each pixel, one along the minor axis on the carry of the
 * 32-bit fraction (a 45-degree line, minor == major, on every pixel: its
 * slope 2^32 does not fit the 32-bit step). T is the pixel type, chosen
 * once for all the lines, not in the loop. */
#define FLOOR_LINES(T)                                                                           \
    for (int i = 0; i < n; i++) {                                                                \
        const struct wl_line *l = &w->lines[i];                                                  \
        unsigned adx = (unsigned)abs(l->x1 - l->x0), ady = (unsigned)abs(l->y1 - l->y0);         \
        long sx = l->x1 < l->x0 ? -(long)sizeof(T) : (long)sizeof(T);                           \
        long sy = l->y1 < l->y0 ? -(long)t->stride : (long)t->stride;                            \
        int ymajor = ady > adx;                                                                  \
        unsigned major = ymajor ? ady : adx, minor = ymajor ? adx : ady, diag = minor == major;  \
        long step_major = ymajor ? sy : sx, step_minor = ymajor ? sx : sy;                       \
        uint32_t S = diag ? 0 : (uint32_t)((((uint64_t)minor << 32) + major - 1) / major);       \
        uint32_t f = 1u << 31;                                                                   \
        uint8_t *p = t->pixels + (size_t)l->y0 * (size_t)t->stride + (size_t)l->x0 * sizeof(T); \
        for (unsigned j = 0;; j++) {                                                             \
            *(T *)(void *)p = (T)l->c;                                                           \
            if (j == major)                                                                      \
                break;                                                                           \
            uint32_t g = f + S;                                                                  \
            p += step_major + (g < f || diag ? step_minor : 0);                                  \
            f = g;                                                                               \
        }                                                                                        \
    }

static void floor_lines(const struct target *t, const struct workloads *w, int n)
{
    if (t->fmt == FMT_XRGB8888) {
        FLOOR_LINES(uint32_t)
    } else {
        FLOOR_LINES(uint16_t)
    }
}

/* The floor must store exactly fixel's pixels, or it is no floor: the
 * class's lines, all white, by fixel (peers[0], through its W3 call) and
 * by the floor loop onto two black frames; the same pixels must be lit.
 * Returns 1 when they differ or cannot be compared. */
static int floor_same_pixels(const struct peer *fixel, const struct workloads *w, int n, int f, uint8_t *buf)
{
    static struct workloads white;
    size_t bytes = (size_t)BW * BH * (size_t)BPP[f];
    uint8_t *mine = malloc(bytes);
    if (!mine)
        return 1;
    for (int i = 0; i < n; i++) {
        white.lines[i] = w->lines[i];
        white.lines[i].c = 0xFFFFFF;
    }
    struct target tg = {buf, f, BW * BPP[f]}, tm = {mine, f, BW * BPP[f]};
    memset(buf, 0, bytes);
    memset(mine, 0, bytes);
    const struct workloads *all = WL;
    void *ctx = fixel->open(&tg);
    if (!ctx) {
        free(mine);
        return 1;
    }
    WL = &white;
    fixel->fn[W3_LINES](ctx, n);
    WL = all;
    fixel->close(ctx);
    floor_lines(&tm, &white, n);
    int differ = 0;
    for (size_t i = 0; i < bytes; i += (size_t)BPP[f]) {
        int a = BPP[f] == 4 ? (buf[i] | buf[i + 1] | buf[i + 2]) != 0 : (buf[i] | buf[i + 1]) != 0;
        int b = BPP[f] == 4 ? (mine[i] | mine[i + 1] | mine[i + 2]) != 0 : (mine[i] | mine[i + 1]) != 0;
        differ += a != b;
    }
    free(mine);
    return differ != 0;
}

int w3_classes(FILE *o, const struct peer *const *peers, int npeers, uint8_t *buf, int rounds, unsigned fmts)
{
    static struct workloads cls[C_COUNT];
    int n[C_COUNT] = {0};
    int64_t px[C_COUNT] = {0}, total = 0;
    const struct workloads *all = WL;
    for (int i = 0; i < N_LINES; i++) {
        const struct wl_line *l = &all->lines[i];
        int k = class_of(l), dx = abs(l->x1 - l->x0), dy = abs(l->y1 - l->y0);
        cls[k].lines[n[k]++] = *l;
        px[k] += (dx > dy ? dx : dy) + 1;
        total += (dx > dy ? dx : dy) + 1;
    }
    int bad = 0;
    if (rounds < 3)
        rounds = 3;
    double *t = calloc((size_t)C_COUNT * (size_t)(npeers + 1) * (size_t)rounds, sizeof *t);
    if (!t)
        return 1;
#define T(k, p, r) t[((size_t)(k) * (size_t)(npeers + 1) + (size_t)(p)) * (size_t)rounds + (size_t)(r)]
    fprintf(o, "W3 BY CLASS  ns per pixel, median [range] of %d interleaved rounds; "
               "fixel/peer = the peer's time over fixel's\n", rounds);
    for (int f = 0; f < FMT_COUNT; f++) {
        if (!(fmts & (1u << f)))
            continue;
        struct target tg = {buf, f, BW * BPP[f]};
        void *ctx[64] = {0};
        int same[C_COUNT] = {0};
        if (peers[0]->fn[W3_LINES] && (peers[0]->fmt_mask & (1u << f)))
            for (int k = 0; k < C_SHALLOW; k++)
                same[k] = !floor_same_pixels(peers[0], &cls[k], n[k], f, buf);
        memset(buf, 0, (size_t)BW * BH * 4);
        for (int p = 0; p < npeers && p < 64; p++)
            if (peers[p]->fn[W3_LINES] && (peers[p]->fmt_mask & (1u << f)))
                ctx[p] = peers[p]->open(&tg);
        for (int r = 0; r < rounds; r++)
            for (int k = 0; k < C_COUNT; k++) {
                for (int p = 0; p < npeers; p++) {
                    if (!ctx[p])
                        continue;
                    WL = &cls[k];
                    double t0 = bench_secs();
                    peers[p]->fn[W3_LINES](ctx[p], n[k]);
                    T(k, p, r) = bench_secs() - t0;
                    WL = all;
                }
                if (k != C_SHALLOW) {
                    double t0 = bench_secs();
                    floor_lines(&tg, &cls[k], n[k]);
                    T(k, npeers, r) = bench_secs() - t0;
                }
            }
        for (int p = 0; p < npeers; p++)
            if (ctx[p])
                peers[p]->close(ctx[p]);
        fprintf(o, "%s\n%-22s %7s %6s", FMT_NAME[f], "class", "lines", "px%");
        for (int p = 0; p < npeers; p++)
            if (ctx[p])
                fprintf(o, " %21s", peers[p]->name);
        fprintf(o, " %21s  fixel/best peer\n", "floor");
        double med[C_COUNT][65] = {{0}};
        for (int k = 0; k < C_COUNT; k++) {
            fprintf(o, "%-22s %7d %5.1f%%", CLASS_NAME[k], n[k], 100.0 * (double)px[k] / (double)total);
            for (int p = 0; p <= npeers; p++) {
                if (p < npeers ? !ctx[p] : k == C_SHALLOW) {
                    if (p == npeers)
                        fprintf(o, " %21s", "-");
                    continue;
                }
                qsort(&T(k, p, 0), (size_t)rounds, sizeof(double), bench_cmp_double);
                double s = 1e9 / (double)px[k];
                med[k][p] = T(k, p, rounds / 2);
                fprintf(o, "   %5.2f [%5.2f-%5.2f]", med[k][p] * s, T(k, p, 0) * s, T(k, p, rounds - 1) * s);
            }
            double best = 0;
            const char *bn = "-";
            for (int p = 1; p < npeers; p++)
                if (ctx[p] && strncmp(peers[p]->name, "fixel", 5) && (best == 0 || med[k][p] < best)) {
                    best = med[k][p];
                    bn = peers[p]->name;
                }
            if (best > 0 && ctx[0])
                fprintf(o, "  %.2f x %s", best / med[k][0], bn);
            fprintf(o, "\n");
        }
        /* The whole of W3 is the sum of the classes: the ratio they make. */
        double fx = 0, pb = 0;
        for (int k = 0; k < C_COUNT; k++)
            fx += med[k][0];
        for (int p = 1; p < npeers; p++) {
            double s = 0;
            if (!ctx[p] || !strncmp(peers[p]->name, "fixel", 5))
                continue;
            for (int k = 0; k < C_COUNT; k++)
                s += med[k][p];
            if (pb == 0 || s < pb)
                pb = s;
        }
        fprintf(o, "%-22s %7d %5.1f%%  fixel %.2f ns per pixel", "all of W3", N_LINES, 100.0,
                fx * 1e9 / (double)total);
        if (fx > 0 && pb > 0)
            fprintf(o, "; the sum of the classes: %.2f x the best peer", pb / fx);
        /* The steep floor is what any writer pays for those pixels: the
         * ratio if fixel's steep lines cost exactly that (the mid floor,
         * one chained store a pixel, is no bound: fixel's mid walk beats it) */
        if (fx > 0 && pb > 0 && med[C_STEEP][npeers] > 0)
            fprintf(o, "; with fixel's steep lines at the floor: %.2f x",
                    pb / (fx - med[C_STEEP][0] + med[C_STEEP][npeers]));
        fprintf(o, "\n");
        for (int k = 0; k < C_SHALLOW; k++) {
            fprintf(o, "floor of the %s lines: %s\n", k == C_STEEP ? "steep" : "mid",
                    same[k] ? "the same pixels as fixel's" : "NOT the same pixels as fixel's");
            bad |= !same[k];
        }
        fprintf(o, "\n");
    }
#undef T
    free(t);
    return bad;
}
