/* SPDX-License-Identifier: MIT */
/* fixel-bench --w3-classes: W3's own lines split by how they meet memory,
 * each class timed for every peer, interleaved. A steep line (|dy| > |dx|)
 * writes one pixel per row, so every pixel is a new cache line (and, in
 * XRGB8888, nearly every one a new 4 KiB page); an x-major line with fewer
 * than 4 pixels per row ("mid") starts a new line every 1-3 pixels; one
 * with 4 or more ("shallow", fixel's run path) writes runs. The whole-W3
 * ratio is the classes' ratios weighted by their time, so this says which
 * class holds it back and whether that class is at the machine's store
 * floor: "floor" is a plain C loop storing the same pixels of the steep
 * and the mid lines, one store a pixel (the DDA with nothing else; no
 * library): what a per-pixel writer pays for them here
 * (docs/PERFORMANCE.md). */
#include "bench.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { C_STEEP, C_MID, C_SHALLOW, C_COUNT };
static const char *const FMT_NAME_W3[FMT_COUNT] = {"xrgb8888", "rgb565"};
static const int BPP_W3[FMT_COUNT] = {4, 2};
static const char *const CLASS_NAME[C_COUNT] = {"steep", "mid (x, 1-3/row)", "shallow (x, 4+/row)"};

static int class_of(const struct wl_line *l)
{
    unsigned dx = (unsigned)abs(l->x1 - l->x0), dy = (unsigned)abs(l->y1 - l->y0);
    if (dy > dx)
        return C_STEEP;
    return dy == 0 || dx / dy >= 4 ? C_SHALLOW : C_MID;
}

/* The steep lines' pixels by the same exact DDA as fixel's walk (ties
 * and all: the same cache lines in the same order), stored from a plain
 * loop: the store floor, not a library. */
static void floor_steep(const struct target *t, const struct workloads *w, int n)
{
    for (int i = 0; i < n; i++) {
        const struct wl_line *l = &w->lines[i];
        int x0 = l->x0, y0 = l->y0, x1 = l->x1, y1 = l->y1;
        if (y1 < y0) {
            int s = x0; x0 = x1; x1 = s;
            s = y0; y0 = y1; y1 = s;
        }
        unsigned dy = (unsigned)(y1 - y0), adx = (unsigned)abs(x1 - x0);
        int sx = x1 < x0 ? -1 : 1;
        uint32_t S = (uint32_t)((((uint64_t)adx << 32) + dy - 1) / dy), f = 1u << 31;
        uint8_t *row = t->pixels + (size_t)y0 * (size_t)t->stride;
        long m = 0;
        if (t->fmt == FMT_XRGB8888) {
            for (unsigned j = 0; j <= dy; j++, row += j <= dy ? t->stride : 0) {
                ((uint32_t *)(void *)row)[x0 + m] = l->c;
                uint32_t g = f + S;
                m += g < f ? sx : 0;
                f = g;
            }
        } else {
            for (unsigned j = 0; j <= dy; j++, row += j <= dy ? t->stride : 0) {
                ((uint16_t *)(void *)row)[x0 + m] = (uint16_t)l->c;
                uint32_t g = f + S;
                m += g < f ? sx : 0;
                f = g;
            }
        }
    }
}

/* The mid lines' pixels likewise: x-major, the row moves on the carry. */
static void floor_mid(const struct target *t, const struct workloads *w, int n)
{
    for (int i = 0; i < n; i++) {
        const struct wl_line *l = &w->lines[i];
        int x0 = l->x0, y0 = l->y0, x1 = l->x1, y1 = l->y1;
        if (x1 < x0) {
            int s = x0; x0 = x1; x1 = s;
            s = y0; y0 = y1; y1 = s;
        }
        unsigned dx = (unsigned)(x1 - x0), ady = (unsigned)abs(y1 - y0);
        long st = y1 < y0 ? -(long)t->stride : (long)t->stride;
        uint32_t S = (uint32_t)((((uint64_t)ady << 32) + dx - 1) / dx), f = 1u << 31;
        uint8_t *row = t->pixels + (size_t)y0 * (size_t)t->stride;
        for (unsigned j = 0; j <= dx; j++) {
            if (t->fmt == FMT_XRGB8888)
                ((uint32_t *)(void *)row)[x0 + (int)j] = l->c;
            else
                ((uint16_t *)(void *)row)[x0 + (int)j] = (uint16_t)l->c;
            uint32_t g = f + S;
            if (g < f && j < dx)
                row += st;
            f = g;
        }
    }
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
        struct target tg = {buf, f, BW * BPP_W3[f]};
        void *ctx[64] = {0};
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
                    (k == C_STEEP ? floor_steep : floor_mid)(&tg, &cls[k], n[k]);
                    T(k, npeers, r) = bench_secs() - t0;
                }
            }
        for (int p = 0; p < npeers; p++)
            if (ctx[p])
                peers[p]->close(ctx[p]);
        fprintf(o, "%s\n%-22s %7s %6s", FMT_NAME_W3[f], "class", "lines", "px%");
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
        if (fx > 0 && pb > 0 && med[C_STEEP][npeers] > 0)
            fprintf(o, "; with fixel's steep and mid lines at the floor: %.2f x",
                    pb / (fx - med[C_STEEP][0] - med[C_MID][0] + med[C_STEEP][npeers] + med[C_MID][npeers]));
        fprintf(o, "\n\n");
    }
#undef T
    free(t);
    return 0;
}
