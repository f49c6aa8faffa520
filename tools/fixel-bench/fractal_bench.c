/* SPDX-License-Identifier: MIT */
/* TABLE 7: issue #23's fractals, one call each (median of the trials):
 * J_c by inverse iteration (random branches and the both-branch tree),
 * the basins of the rabbit's 3-cycle over a frame, box counting over a
 * frame at six box sizes, the turtle's Koch curve, grass and fire, the
 * terrain mesh, the collage search and fractal coding and decoding. The
 * work of each row is in its name, so the times can be compared with the
 * bounds of docs/FRACTALS.md. */
#include "bench.h"

#include <fixel/boxdim.h>
#include <fixel/collage.h>
#include <fixel/julia.h>
#include <fixel/koch.h>
#include <fixel/randfract.h>
#include <fixel/turtle.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define FW 400
#define FH 300
#define NROWS 10

static const char *const row_name[NROWS] = {
    "juliaset random, 2^20 points",  "juliaset tree, depth 18",       "juliabasins 400x300, 256 it",
    "boxdim 400x300, boxes 2..64",   "turtle koch, order 7 (16384)",  "grass, 1000 blades",
    "fire 400x300",                  "terrain mesh K=7 (32768 tri)",  "collage 96 px, up to 8 maps",
    "fic 64 px code + 10 decodes",
};
static double med_ms[NROWS];
static int fractal_ran;

typedef struct fb {
    uint32_t *px;
    fx_surface s;
    fx_ctx c;
    fx_fractal_view v;
    int32_t h[129 * 129];
    fx_vec3 pos[129 * 129], nrm[129 * 129];
    uint32_t tri[3 * 32768], col[129 * 129];
    uint8_t t[96 * 96], work[96 * 96], img[64 * 64], out[64 * 64], tmp[64 * 64];
    fx_fic_code codes[16 * 16];
} fb;

static void one(fb *b, int r)
{
    fx_surface_clear(&b->s, 0xFF000000u);
    switch (r) {
    case 0: fx_julia_inverse_random(&b->c, &b->v, 1u << 20, 1); break;
    case 1: fx_julia_inverse_tree(&b->c, &b->v, 18); break;
    case 2: {
        static uint32_t lut[2] = {0x202020, 0x404040};
        fx_dwell_pal pal = {lut, 2, 65536, 1, 0};
        static const fx_color basin[3] = {0xFFFFC040u, 0xFF40B0FFu, 0xFFFF5A5Au};
        fx_julia_basins(&b->s, (fx_rect){0, 0, FW, FH}, &b->v, &pal, basin, 3);
        break;
    }
    case 3: {
        fx_koch(&b->c, 10, 280, 390, 280, 6);
        fx16 d;
        fx_boxdim_surface(&b->s, (fx_rect){0, 0, FW, FH}, fx_pack(b->s.format, 0xFF000000u), 2, 64, &d, NULL, NULL);
        break;
    }
    case 4: {
        fx_turtle t;
        fx_turtle_init(&t, &b->c, 10 << 16, 280 << 16, 0);
        fx_turtle_koch(&t, 380 << 16, 7);
        break;
    }
    case 5: fx_grass(&b->c, (fx_rect){0, 100, FW, FH}, 1000, 3); break;
    case 6: fx_fire(&b->c, (fx_rect){0, 0, FW, FH}, 39322, 5); break;
    case 7: {
        fx_mesh m = {b->pos, b->nrm, b->tri, 0, 0, 129 * 129, 32768, NULL, b->col};
        fx_terrain(b->h, 129, 7, 1 << 20, 39322, 11);
        fx_terrain_mesh(&m, b->h, 129, 7, 7 << 16, 2 << 16, 19661);
        break;
    }
    case 8: {
        fx_collage_result res;
        fx_collage_search(b->t, 96, 96, 8, b->work, &res);
        break;
    }
    case 9:
        fx_fic_encode(b->img, 64, b->codes);
        fx_fic_decode(b->codes, 64, 10, b->out, b->tmp);
        break;
    }
}

void fractal_bench_run(int trials, double min_s, int quiet)
{
    fb *b = calloc(1, sizeof *b);
    if (!b)
        return;
    b->px = calloc((size_t)FW * FH, 4);
    if (!b->px || fx_surface_init(&b->s, b->px, FW, FH, FW * 4, FX_FMT_XRGB8888) < 0) {
        free(b->px);
        free(b);
        return;
    }
    fx_ctx_init(&b->c, &b->s);
    fx_ctx_set_color(&b->c, 0xFFFFFFFFu);
    /* the rabbit, c = -0.123 + 0.745i, 3.2 wide */
    b->v = fx_julia_view(0, 0, -(FX56_ONE / 1000) * 123, (FX56_ONE / 1000) * 745, FX56_ONE / 10 * 32, FW, FH, 256);
    for (int y = 0; y < 96; y++)
        for (int x = 0; x < 96; x++)
            b->t[y * 96 + x] = ((x * 64 / 96) & ((95 - y) * 64 / 96)) == 0;
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 64; x++)
            b->img[y * 64 + x] = (uint8_t)((x * 3 + y * 2) ^ (x * y >> 4));
    if (!quiet)
        fprintf(stderr, "fractal ");
    if (trials < 3)
        trials = 3;
    for (int r = 0; r < NROWS; r++) {
        double *ts = malloc(sizeof *ts * (size_t)trials);
        if (!ts)
            break;
        for (int k = 0; k < trials; k++) {
            /* at least min_s per trial: repeat the call, report per call */
            int reps = 0;
            double t0 = bench_secs(), t1;
            do {
                one(b, r);
                reps++;
                t1 = bench_secs();
            } while (t1 - t0 < min_s / 10);
            ts[k] = (t1 - t0) * 1e3 / reps;
        }
        qsort(ts, (size_t)trials, sizeof *ts, bench_cmp_double);
        med_ms[r] = ts[trials / 2];
        free(ts);
        if (!quiet)
            fprintf(stderr, ".");
    }
    fractal_ran = 1;
    free(b->px);
    free(b);
}

void fractal_bench_print(FILE *o)
{
    if (!fractal_ran)
        return;
    fprintf(o, "\nTABLE 7: fractals of issue #23, one call, %dx%d XRGB8888 where a frame (docs/FRACTALS.md)\n", FW, FH);
    fprintf(o, "%-32s %10s\n", "call", "ms");
    for (int r = 0; r < NROWS; r++)
        fprintf(o, "%-32s %10.3f\n", row_name[r], med_ms[r]);
}
