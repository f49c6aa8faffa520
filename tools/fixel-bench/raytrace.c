/* SPDX-License-Identifier: MIT */
/* TABLE 5: the ray tracer (issue #22, docs/RAYTRACE.md). The CSG scenes
 * (lens, bowl, rocket) and the glass and mirror spheres over a marble floor
 * at 800x480, rendered by fixel's fixed-point tracer on one thread and on
 * every core (boards/posix rt_mt: bands of rows), and by the
 * double-precision reference tracer of the same scene written for the
 * benchmark (rtref.c, one thread); the fraction of pixels where the two
 * pictures differ. Rays are counted by the reference (primary, reflected,
 * refracted and shadow feelers: the same ray tree the fixed-point tracer
 * walks, to the odd pixel); rays per second is that count over each
 * renderer's time. One frame per cell: a frame takes seconds. */
#include "bench.h"
#include "rtref.h"

#include <fixel/rt_mt.h>
#include <fixel/surface.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define RW 800
#define RH 480

struct rtrow {
    const char *name;
    long rays;
    double t1, tn, tref;
    long differ2, differ_any;
    int same_mt;
};

static struct rtrow RT[4];
static int NRT, NTHREADS;

void raytrace_run(int quiet)
{
    NTHREADS = fx_rt_cpu_count();
    uint32_t *a = malloc((size_t)RW * RH * 4), *b = malloc((size_t)RW * RH * 4);
    if (!a || !b) {
        free(a);
        free(b);
        return;
    }
    fx_surface sa, sb;
    fx_surface_init(&sa, a, RW, RH, RW * 4, FX_FMT_XRGB8888);
    fx_surface_init(&sb, b, RW, RH, RW * 4, FX_FMT_XRGB8888);
    for (int k = 0; k < 4; k++) {
        fx_rt_object mem[16];
        fx_rt_scene s;
        struct rtrow *r = &RT[NRT];
        memset(r, 0, sizeof *r);
        r->name = rtref_scene_names[k];
        if (rtref_scene(&s, mem, 16, k) < 0)
            continue;
        if (!quiet)
            fprintf(stderr, "\rfixel-bench: raytrace %-8s", r->name);
        double t0 = bench_secs();
        fx_rt_render(&s, &sa, 0, 0, RW, RH);
        r->t1 = bench_secs() - t0;
        t0 = bench_secs();
        fx_rt_render_mt(&s, &sb, NTHREADS, 4, 0, 0);
        r->tn = bench_secs() - t0;
        r->same_mt = !memcmp(a, b, (size_t)RW * RH * 4);
        t0 = bench_secs();
        for (int y = 0; y < RH; y++)
            for (int x = 0; x < RW; x++)
                b[y * RW + x] = rtref_pixel(&s, RW, RH, x, y, &r->rays);
        r->tref = bench_secs() - t0;
        for (int i = 0; i < RW * RH; i++) {
            uint32_t p = a[i] & 0xFFFFFF, q = b[i] & 0xFFFFFF;
            int d = 0;
            for (int c = 0; c < 24; c += 8) {
                int e = abs((int)((p >> c) & 255) - (int)((q >> c) & 255));
                d = e > d ? e : d;
            }
            r->differ_any += d > 0;
            r->differ2 += d > 2;
        }
        NRT++;
    }
    if (!quiet)
        fprintf(stderr, "\n");
    free(a);
    free(b);
}

void raytrace_print(FILE *o)
{
    if (!NRT)
        return;
    fprintf(o, "TABLE 5: ray tracing at %dx%d (docs/RAYTRACE.md): rays/s = rays of the frame (primary,\n"
               "reflected, refracted, shadow feelers; counted by the reference) / seconds; 1 frame per cell\n\n",
            RW, RH);
    fprintf(o, "| scene | rays/frame | fixel 1 thread | fixel %d threads | double reference | fixel 1t / double "
               "| pixels > 2 levels off | pixels not equal |\n",
            NTHREADS);
    fprintf(o, "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    for (int i = 0; i < NRT; i++) {
        const struct rtrow *r = &RT[i];
        double n = (double)RW * RH;
        fprintf(o, "| %s | %ld | %.2f Mrays/s (%.2f s) | %.2f Mrays/s (%.2f s)%s | %.2f Mrays/s (%.2f s) | %.2f | %.3f %% "
                   "| %.3f %% |\n",
                r->name, r->rays, r->rays / r->t1 / 1e6, r->t1, r->rays / r->tn / 1e6, r->tn,
                r->same_mt ? "" : " DIFFERENT PICTURE", r->rays / r->tref / 1e6, r->tref, r->tref / r->t1,
                100.0 * r->differ2 / n, 100.0 * r->differ_any / n);
    }
    fprintf(o, "\n");
}
