/* SPDX-License-Identifier: MIT */
/* TABLE 4: what issue 13 asks beyond the ten workloads. Presentation of a
 * 1920x1080 frame from the back buffer to scanout memory (whole frame and a
 * 10 % damage rectangle, with and without 90-degree rotation, shadow and
 * direct), the Gouraud teapot frame, a deep-zoom Mandelbrot frame on the
 * Q8.56 path, and the CPU an idle event loop uses.
 *
 * The display is the memory backend of boards/memory: the same
 * fx_display_present code a DRM or fbdev display runs, with ordinary memory
 * standing in for scanout memory (real scanout memory is often uncached or
 * write-combined, so a board's copy is slower than this one). The memory
 * backend has one buffer, so its direct mode copies nothing at all; what
 * direct costs on a double-buffered device is the repair copy of the
 * previous frame's damage between the two scanout buffers
 * (fx_display_surface), measured here as that copy (fx_copy_rotated with no
 * rotation, buffer to buffer).
 *
 * Rows of one group run interleaved (trial k runs every row once, order
 * rotated by k), like the workload peers. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include "bench.h"
#include "workloads.h"

#include <fixel/app.h>
#include <fixel/display.h>
#include <fixel/env.h>
#include <fixel/scanout.h>
#include <fixel/fractal.h>
#include <fixel/fractal_mt.h>
#include <fixel/render3d.h>
#include <fixel/surface.h>

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include <sys/resource.h>


#define XMAX 24

struct xrow {
    char name[48];
    char unit[16]; /* of the primary value */
    double ops;    /* frames (or calls) per rep, for the primary metric */
    double bytes;  /* scanout bytes written per rep, 0: no GB/s column */
    double vals[64];
    int nv;
    double med, spread; /* seconds per rep */
    char note[96];
};

static struct xrow ROWS[XMAX];
static int NROWS;

typedef void (*rep_fn)(void *arg, int rep);

struct xjob {
    struct xrow *row;
    rep_fn fn;
    void *arg;
    int reps; /* reps per trial, from calibration */
};

static struct xrow *new_row(const char *unit, double bytes, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
static struct xrow *new_row(const char *unit, double bytes, const char *fmt, ...)
{
    if (NROWS >= XMAX) abort();
    struct xrow *r = &ROWS[NROWS++];
    memset(r, 0, sizeof *r);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(r->name, sizeof r->name, fmt, ap);
    va_end(ap);
    snprintf(r->unit, sizeof r->unit, "%s", unit);
    r->ops = 1;
    r->bytes = bytes;
    return r;
}

/* Calibrate every job to >= min_s per trial, then trials interleaved. */
static void run_jobs(struct xjob *j, int n, int trials, double min_s, int quiet)
{
    for (int i = 0; i < n; i++) {
        /* calibration doubles as the warm-up: trials come after it */
        double t0 = bench_secs();
        int k = 0;
        do j[i].fn(j[i].arg, ++k);
        while (bench_secs() - t0 < min_s / 4);
        double per = (bench_secs() - t0) / k;
        j[i].reps = per > 0 ? (int)(min_s / per) + 1 : 1;
    }
    for (int t = 0; t < trials; t++) {
        for (int q = 0; q < n; q++) {
            struct xjob *x = &j[(q + t) % n];
            double t0 = bench_secs();
            for (int k = 0; k < x->reps; k++) x->fn(x->arg, k);
            x->row->vals[x->row->nv++] = (bench_secs() - t0) / x->reps;
        }
        if (!quiet) fprintf(stderr, ".");
    }
    for (int i = 0; i < n; i++) {
        struct xrow *r = j[i].row;
        qsort(r->vals, (size_t)r->nv, sizeof r->vals[0], bench_cmp_double);
        r->med = r->nv & 1 ? r->vals[r->nv / 2] : (r->vals[r->nv / 2 - 1] + r->vals[r->nv / 2]) / 2;
        r->spread = r->med > 0 ? (r->vals[r->nv - 1] - r->vals[0]) / r->med : 0;
    }
}

/* ---- presentation ---- */

struct present_arg {
    fx_display *d;
    fx_rect damage; /* logical; x1 == 0: whole frame */
};

static void rep_present(void *arg, int rep)
{
    struct present_arg *p = arg;
    (void)rep;
    fx_display_surface(p->d);
    fx_display_present(p->d, p->damage.x1 ? &p->damage : NULL, p->damage.x1 ? 1 : 0);
}

struct copy_arg {
    fx_surface dst, src;
    fx_rect r;
};

static void rep_copy(void *arg, int rep)
{
    struct copy_arg *c = arg;
    (void)rep;
    fx_copy_rotated(&c->dst, &c->src, c->r, 0);
}

static void rep_memcpy(void *arg, int rep)
{
    struct copy_arg *c = arg;
    (void)rep;
    memcpy(c->dst.pixels, c->src.pixels, (size_t)c->src.stride * (size_t)c->src.h);
}

static void quiet_log(fx_log_priority pr, void *user, const char *fmt, va_list ap)
{
    (void)pr, (void)user, (void)fmt, (void)ap;
}

static fx_display *open_memory(fx_format f, fx_present_mode m, int rotation)
{
    fx_display_options o;
    fx_display_options_init(&o);
    o.backend = FX_BACKEND_MEMORY;
    o.present = m;
    o.format = f;
    o.rotation = rotation;
    o.memory_w = BW;
    o.memory_h = BH;
    o.console = 0;
    o.signals = 0;
    o.log = quiet_log;
    fx_display *d = NULL;
    if (fx_display_options_from_env(&o) < 0 || fx_display_open(&d, &o) < 0) return NULL;
    return d;
}

/* A 10 % damage rectangle: 607 x 342 = 10.01 % of 1920 x 1080, centred on
 * the logical surface (1080 x 1920 when rotated: the same rectangle turned). */
static fx_rect damage10(int rotation)
{
    int32_t w = 607, h = 342, lw = BW, lh = BH;
    if (rotation == 90) {
        w = 342, h = 607, lw = BH, lh = BW;
    }
    fx_rect r = {(lw - w) / 2, (lh - h) / 2, (lw - w) / 2 + w, (lh - h) / 2 + h};
    return r;
}

static void present_group(int fmt, int trials, double min_s, int quiet)
{
    fx_format f = fmt == FMT_XRGB8888 ? FX_FMT_XRGB8888 : FX_FMT_RGB565;
    int bpp = fmt == FMT_XRGB8888 ? 4 : 2;
    double full = (double)BW * BH * bpp, part = 607.0 * 342 * bpp;
    struct present_arg pa[5];
    struct xjob jobs[8];
    int n = 0;
    fx_display *ds[5] = {0};
    static const struct {
        fx_present_mode m;
        int rot, dmg;
        const char *label;
    } cases[5] = {
        {FX_PRESENT_SHADOW, 0, 0, "shadow.full"},
        {FX_PRESENT_SHADOW, 0, 1, "shadow.dmg10"},
        {FX_PRESENT_SHADOW, 90, 0, "shadow.full.rot90"},
        {FX_PRESENT_SHADOW, 90, 1, "shadow.dmg10.rot90"},
        {FX_PRESENT_DIRECT, 0, 0, "direct.full.1buf"},
    };
    for (int i = 0; i < 5; i++) {
        ds[i] = open_memory(f, cases[i].m, cases[i].rot);
        if (!ds[i]) {
            fprintf(stderr, "fixel-bench: memory display %s did not open\n", cases[i].label);
            continue;
        }
        fx_display_info info;
        fx_display_get_info(ds[i], &info);
        if (info.present != cases[i].m) {
            fprintf(stderr, "fixel-bench: memory display %s: wrong presentation mode\n",
                    cases[i].label);
            continue;
        }
        pa[i].d = ds[i];
        fx_rect none = {0, 0, 0, 0};
        pa[i].damage = cases[i].dmg ? damage10(cases[i].rot) : none;
        double b = cases[i].m == FX_PRESENT_DIRECT ? 0 : cases[i].dmg ? part : full;
        struct xrow *r = new_row("frames/s", b, "present.%s.%s", cases[i].label, FMT_NAME[fmt]);
        if (cases[i].m == FX_PRESENT_DIRECT)
            snprintf(r->note, sizeof r->note, "memory backend, 1 buffer: no copy");
        else if (cases[i].rot)
            snprintf(r->note, sizeof r->note, "copy turning 90 deg");
        jobs[n++] = (struct xjob){r, rep_present, &pa[i], 0};
    }
    /* direct presentation with two scanout buffers: the repair copy of the
     * previous frame's damage, buffer to buffer (no rotation in direct mode) */
    size_t sz = (size_t)BW * BH * (size_t)bpp;
    uint8_t *m0 = aligned_alloc(64, sz), *m1 = aligned_alloc(64, sz);
    memset(m0, 0x5A, sz);
    memset(m1, 0, sz);
    struct copy_arg ca[3];
    for (int i = 0; i < 3; i++) {
        fx_surface_init(&ca[i].dst, m1, BW, BH, BW * bpp, f);
        fx_surface_init(&ca[i].src, m0, BW, BH, BW * bpp, f);
    }
    ca[0].r = fx_surface_rect(&ca[0].src);
    ca[1].r = damage10(0);
    struct xrow *r = new_row("frames/s", full, "present.direct.full.2buf.%s", FMT_NAME[fmt]);
    snprintf(r->note, sizeof r->note, "repair copy of last frame's damage");
    jobs[n++] = (struct xjob){r, rep_copy, &ca[0], 0};
    r = new_row("frames/s", part, "present.direct.dmg10.2buf.%s", FMT_NAME[fmt]);
    snprintf(r->note, sizeof r->note, "repair copy of last frame's damage");
    jobs[n++] = (struct xjob){r, rep_copy, &ca[1], 0};
    r = new_row("frames/s", full, "memcpy.full.%s", FMT_NAME[fmt]);
    snprintf(r->note, sizeof r->note, "ceiling: libc memcpy of the frame");
    jobs[n++] = (struct xjob){r, rep_memcpy, &ca[2], 0};
    run_jobs(jobs, n, trials, min_s, quiet);
    for (int i = 0; i < 5; i++) fx_display_close(ds[i]);
    free(m0);
    free(m1);
}

/* ---- teapot ---- */

struct teapot_arg {
    fx_surface s;
    void *mem;
    size_t bytes;
};

static void rep_teapot(void *arg, int rep)
{
    struct teapot_arg *t = arg;
    /* the camera moves 1/64 turn per frame, as a spinning demo would */
    if (bench_teapot(&t->s, t->mem, t->bytes, (fx_angle)((uint32_t)rep << 26)) < 0) abort();
}

static void teapot_group(int trials, double min_s, int quiet, int fmt_mask)
{
    struct teapot_arg ta[FMT_COUNT];
    struct xjob jobs[FMT_COUNT];
    int n = 0;
    for (int f = 0; f < FMT_COUNT; f++) {
        if (!(fmt_mask & (1 << f))) continue;
        int bpp = f == FMT_XRGB8888 ? 4 : 2;
        void *px = aligned_alloc(64, (size_t)BW * BH * 4);
        fx_surface_init(&ta[f].s, px, BW, BH, BW * bpp,
                        f == FMT_XRGB8888 ? FX_FMT_XRGB8888 : FX_FMT_RGB565);
        ta[f].bytes = bench_teapot_bytes(&ta[f].s);
        ta[f].mem = aligned_alloc(64, (ta[f].bytes + 63) & ~(size_t)63);
        struct xrow *r =
            new_row("frames/s", 0, "teapot.gouraud.1920x1080.%s", f ? "rgb565" : "xrgb8888");
        snprintf(r->note, sizeof r->note, "clear + z-buffer + mesh + Gouraud, 1 thread");
        jobs[n++] = (struct xjob){r, rep_teapot, &ta[f], 0};
    }
    run_jobs(jobs, n, trials, min_s, quiet);
    for (int i = 0; i < FMT_COUNT; i++)
        if (fmt_mask & (1 << i)) {
            free(ta[i].s.pixels);
            free(ta[i].mem);
        }
}

/* ---- deep-zoom Mandelbrot ---- */

struct mandel_arg {
    fx_surface s;
    fx_fractal_view v;
    fx_dwell_pal pal;
    uint32_t lut[256];
    int threads;
};

static void rep_mandel(void *arg, int rep)
{
    struct mandel_arg *m = arg;
    (void)rep;
    fx_rect r = fx_surface_rect(&m->s);
    if ((m->threads > 1 ? fx_fractal_render_mt(&m->s, r, &m->v, &m->pal, m->threads)
                        : fx_fractal_render(&m->s, r, &m->v, &m->pal)) < 0)
        abort();
}

static void mandel_group(int trials, double min_s, int quiet)
{
    static struct mandel_arg ma[2];
    struct xjob jobs[2];
    int ncpu = (int)sysconf(_SC_NPROCESSORS_ONLN);
    void *px = aligned_alloc(64, (size_t)BW * BH * 4);
    for (int i = 0; i < 2; i++) {
        fx_surface_init(&ma[i].s, px, BW, BH, BW * 4, FX_FMT_XRGB8888);
        /* Seahorse valley, -0.743643887037151 + 0.131825904205330i, a
         * frame 2^-16 (1.5e-5) wide, 196608 times narrower than W9's:
         * pixel steps of 2^-27, far below the 2^-12 the Q4.28 path takes,
         * so the Q8.56 path runs. About 288 iterations per pixel (6 % of
         * the frame inside the set at maxiter 1024); deeper frames here are
         * nearly all inside at this maxiter and only measure the cap. */
        ma[i].v =
            fx_mandel_view(-53585189320909768, 9499057488910446, FX56_ONE >> 16, BW, BH, 1024);
        for (int k = 0; k < 256; k++)
            ma[i].lut[k] = (uint32_t)(k * 0x010101) ^ (uint32_t)((k & 7) << 21);
        ma[i].pal = (fx_dwell_pal){ma[i].lut, 256, 65536, 1, 0};
        ma[i].threads = i ? ncpu : 1;
    }
    int prec = fx_fractal_precision(&ma[0].v);
    struct xrow *r = new_row("frames/s", 0, "mandel.deep.2^-16.xrgb8888");
    snprintf(r->note, sizeof r->note, "path Q%s, maxiter 1024, 1 thread",
             prec == 64 ? "8.56" : "4.28 (!)");
    jobs[0] = (struct xjob){r, rep_mandel, &ma[0], 0};
    r = new_row("frames/s", 0, "mandel.deep.2^-16.mt.xrgb8888");
    snprintf(r->note, sizeof r->note, "fx_fractal_render_mt, %d threads", ncpu);
    jobs[1] = (struct xjob){r, rep_mandel, &ma[1], 0};
    /* a frame takes seconds: fewer, single-rep trials */
    run_jobs(jobs, 2, trials < 3 ? trials : 3, min_s / 4, quiet);
    free(px);
}

/* ---- idle event loop ---- */

static void idle_quit(void *user, int value)
{
    (void)value;
    fx_app_quit(user);
}

static void idle_group(void)
{
    fx_app_options o;
    fx_app_options_init(&o);
    o.display.backend = FX_BACKEND_MEMORY;
    o.display.memory_w = BW;
    o.display.memory_h = BH;
    o.display.console = 0;
    o.display.signals = 0;
    o.display.log = quiet_log;
    o.input = 0; /* no devices: the bench may run where /dev/input is readable */
    fx_app *a = NULL;
    struct xrow *r = new_row("CPU %", 0, "idle.main_loop.3s");
    if (fx_app_options_from_env(&o) < 0 || fx_app_open(&a, &o) < 0) {
        snprintf(r->note, sizeof r->note, "fx_app_open failed");
        return;
    }
    const double secs = 3.0;
    fx_app_timer(a, (unsigned)(secs * 1000), idle_quit, 0);
    /* fx_app_timer's callback gets the app's user pointer: set it to a */
    fx_callbacks cb;
    memset(&cb, 0, sizeof cb);
    fx_app_set_callbacks(a, &cb, a);
    struct rusage u0, u1;
    getrusage(RUSAGE_SELF, &u0);
    double t0 = bench_secs();
    fx_app_main_loop(a);
    double wall = bench_secs() - t0;
    getrusage(RUSAGE_SELF, &u1);
    fx_app_close(a);
    double cpu = (double)(u1.ru_utime.tv_sec - u0.ru_utime.tv_sec) +
                 (double)(u1.ru_stime.tv_sec - u0.ru_stime.tv_sec) +
                 1e-6 * (double)(u1.ru_utime.tv_usec - u0.ru_utime.tv_usec) +
                 1e-6 * (double)(u1.ru_stime.tv_usec - u0.ru_stime.tv_usec);
    r->med = wall;
    r->vals[0] = cpu;
    r->nv = -1; /* marks the idle row */
    snprintf(r->note, sizeof r->note, "%.3f ms CPU in %.2f s wall (getrusage, user+sys)", cpu * 1e3,
             wall);
}

/* ---- driver and table ---- */

void extras_run(const char *only, int fmt_mask, int trials, double min_s, int quiet,
                int (*listed)(const char *, const char *))
{
    if (!quiet) fprintf(stderr, "extras ");
    for (int f = 0; f < FMT_COUNT; f++)
        if ((fmt_mask & (1 << f)) && (!only || listed(only, "present")))
            present_group(f, trials, min_s, quiet);
    if (!only || listed(only, "teapot")) teapot_group(trials, min_s, quiet, fmt_mask);
    if ((fmt_mask & 1) && (!only || listed(only, "deepzoom"))) mandel_group(trials, min_s, quiet);
    if (!only || listed(only, "idle")) idle_group();
    if (!quiet) fprintf(stderr, "\n");
}

static void num(char *o, size_t sz, double v)
{
    if (v >= 1e6)
        snprintf(o, sz, "%.3gM", v / 1e6);
    else if (v >= 1e3)
        snprintf(o, sz, "%.3gk", v / 1e3);
    else
        snprintf(o, sz, "%.3g", v);
}

void extras_print(FILE *o)
{
    if (!NROWS) return;
    fprintf(
        o,
        "\nTABLE 4  presentation, 3D and deep-zoom frames, idle loop  (median; ~ spread>15%%)\n");
    fprintf(o, "%-40s %10s %10s %9s %7s  %s\n", "measurement", "frames/s", "ms/frame", "GB/s",
            "spread", "note");
    fprintf(o, "%.*s\n", 120,
            "----------------------------------------------------------------------------"
            "--------------------------------------------");
    for (int i = 0; i < NROWS; i++) {
        const struct xrow *r = &ROWS[i];
        if (r->nv < 0) {
            fprintf(o, "%-40s %10s %10s %9s %7s  idle CPU %.3f %% of one core: %s\n", r->name, "-",
                    "-", "-", "-", r->med > 0 ? 100.0 * r->vals[0] / r->med : 0.0, r->note);
            continue;
        }
        if (r->nv == 0) {
            fprintf(o, "%-40s %10s %10s %9s %7s  %s\n", r->name, "-", "-", "-", "-", r->note);
            continue;
        }
        char fps[32], ms[32], gbs[32];
        num(fps, sizeof fps, r->ops / r->med);
        snprintf(ms, sizeof ms, "%.3g", r->med * 1e3);
        if (r->bytes > 0)
            snprintf(gbs, sizeof gbs, "%.3g", r->bytes / r->med / 1e9);
        else
            snprintf(gbs, sizeof gbs, "-");
        fprintf(o, "%-40s %9s%s %10s %9s %6.0f%%  %s\n", r->name, fps, r->spread > 0.15 ? "~" : " ",
                ms, gbs, 100 * r->spread, r->note);
    }
}
