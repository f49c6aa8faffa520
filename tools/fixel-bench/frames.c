/* SPDX-License-Identifier: MIT */
/* fixel-bench --frames: the frames a user sees (issue #27, docs/PERFORMANCE.md).
 * Milliseconds per frame of every fixel-demo page, of the 3D and ray-traced
 * golden scripts and of every examples/kiosk-*.conf, at 800x480 and
 * 1920x1080 in XRGB8888 and RGB565, on one thread, on two (past two cores)
 * and on every core (bands: fixel/par.h), and what presenting a whole frame or a 10% damage rectangle
 * costs. Each figure is the median of several frames; the table says the
 * machine's load, and for banded runs the CPU time each band took, which
 * shows the split when the wall time is noisy (a shared machine). */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <dirent.h>
#include <fcntl.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "fixel/memfb.h"
#include "fixel/par.h"
#include "fixel/scene.h"
#include "bench.h"
#include "frames.h"

extern char **environ;

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec / 1e6;
}

static double thread_cpu_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec / 1e6;
}

static double process_cpu_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec / 1e6;
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, bench_cmp_double);
    return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

enum { MAXB = 64 }; /* fx_scene_run_mt's limit */
static int REPS = 5; /* -t */
/* 2 when the N-thread column is more than 2 threads: a "2 thr" column
 * then shows the scaling at two cores too (a Pi 4 or 5 has four) */
static int MID;

typedef struct cell {
    double ms;           /* median wall ms per frame */
    double cpu_ms;       /* median process CPU ms per frame */
    double band_cpu[MAXB]; /* median CPU ms of each band (pages) */
    int bands;           /* 1: one thread */
} cell;

static void row(FILE *o, const char *what, int w, int h, fx_format f, cell a, cell m, cell b);

/* ---- demo pages (fixel-demo --time-pages draws and times them) ---- */

/* Run "DEMO --time-pages WxH FORMAT THREADS REPS": per page (at most
 * maxp) its name, the one-thread cell a and the banded cell b. Returns the
 * pages read, -1 when the demo failed. */
enum { MAXPAGES = 32 };
static int demo_time(const char *demo, int w, int h, fx_format f, int nthreads, char (*name)[64], cell *a,
                     cell *b)
{
    char cmd[4400];
    snprintf(cmd, sizeof cmd, "'%s' --time-pages %dx%d %s %d %d", demo, w, h, fx_format_get(f)->name, nthreads,
             REPS);
    FILE *p = popen(cmd, "r");
    if (!p)
        return -1;
    char line[512];
    int n = 0;
    while (n < MAXPAGES && fgets(line, sizeof line, p)) {
        /* NAME MS1 CPU1 MSN CPUN BANDS BANDCPU/BANDCPU... */
        char bc[256] = "";
        memset(&a[n], 0, sizeof a[n]);
        memset(&b[n], 0, sizeof b[n]);
        if (sscanf(line, "%63s %lf %lf %lf %lf %d %255s", name[n], &a[n].ms, &a[n].cpu_ms, &b[n].ms, &b[n].cpu_ms,
                   &b[n].bands, bc) < 6)
            continue;
        a[n].bands = 1;
        char *q = bc;
        for (int k = 0; k < b[n].bands && k < MAXB && *q; k++) {
            b[n].band_cpu[k] = strtod(q, &q);
            if (*q == '/')
                q++;
        }
        n++;
    }
    return pclose(p) != 0 || !n ? -1 : n;
}

/* A row per demo page, on 1, (2,) and nthreads threads. */
static int demo_rows(FILE *o, const char *demo, int w, int h, fx_format f, int nthreads)
{
    static char name[MAXPAGES][64], name2[MAXPAGES][64];
    static cell a[MAXPAGES], b[MAXPAGES], a2[MAXPAGES], m[MAXPAGES];
    int n = demo_time(demo, w, h, f, nthreads, name, a, b);
    if (n < 0)
        return 1;
    int n2 = MID ? demo_time(demo, w, h, f, MID, name2, a2, m) : 0;
    if (n2 < 0)
        return 1;
    for (int k = 0; k < n; k++) {
        cell none;
        memset(&none, 0, sizeof none);
        char what[80];
        snprintf(what, sizeof what, "demo %s", name[k]);
        /* the same pages in the same order; a page missing in one run has
         * no 2-thread cell */
        row(o, what, w, h, f, a[k], k < n2 && !strcmp(name[k], name2[k]) ? m[k] : none, b[k]);
    }
    return 0;
}

/* ---- scene scripts ---- */

typedef struct shost {
    fx_memfb *fb;
} shost;

static int make_surface(void *u, int32_t w, int32_t h, fx_format f, fx_surface *out)
{
    shost *H = u;
    if (w != H->fb->surf.w || h != H->fb->surf.h || f != H->fb->surf.format)
        return -1;
    memset(H->fb->surf.pixels, 0, (size_t)H->fb->surf.stride * (size_t)h);
    *out = H->fb->surf;
    return 0;
}

static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    char *b = malloc(1 << 20);
    size_t n = b ? fread(b, 1, (1 << 20) - 1, f) : 0;
    fclose(f);
    if (b)
        b[n] = 0;
    *len = n;
    return b;
}

static cell time_script(fx_memfb *fb, const char *text, size_t len, int nthreads, void *arena, size_t arena_size,
                        int *ok)
{
    cell r;
    memset(&r, 0, sizeof r);
    double wall[64], cpu[64], c0cpu[64];
    *ok = 1;
    for (int k = -1; k < REPS; k++) {
        shost H = {fb};
        fx_scene_host hs = {&H, make_surface, NULL, NULL, NULL, NULL};
        static fx_scene sc;
        fx_scene_init(&sc, &hs, arena, arena_size);
        fx_scene_fix_size(&sc, fb->surf.w, fb->surf.h);
        fx_scene_fix_format(&sc, fb->surf.format);
        int bands = 1;
        double t0 = now_ms(), c0 = process_cpu_ms(), b0 = thread_cpu_ms();
        if (fx_scene_run_mt(&sc, text, len, nthreads, &bands) < 0)
            *ok = 0;
        r.bands = bands;
        if (k < 0)
            continue;
        wall[k] = now_ms() - t0;
        cpu[k] = process_cpu_ms() - c0;
        c0cpu[k] = thread_cpu_ms() - b0; /* band 0 runs on this thread */
    }
    r.ms = median(wall, REPS);
    r.cpu_ms = median(cpu, REPS);
    if (r.bands == 2) { /* the other band: the rest of the process's CPU */
        r.band_cpu[0] = median(c0cpu, REPS);
        r.band_cpu[1] = r.cpu_ms - r.band_cpu[0];
    }
    return r;
}

/* ---- kiosk configs (fixel-kiosk --headless, a process per run) ---- */

static double run_kiosk(const char *kiosk, const char *conf, int w, int h, const char *fmt, int frames,
                        int nthreads, double *cpu)
{
    char size[32], nf[16], nt[16];
    snprintf(size, sizeof size, "%dx%d", w, h);
    snprintf(nf, sizeof nf, "%d", frames);
    snprintf(nt, sizeof nt, "%d", nthreads);
    char *argv[] = {(char *)kiosk, "--headless", "--full", "--frames", nf,        "--size", size, "--format",
                    (char *)fmt,   "--threads",  nt,       "--data",   "/dev/null", (char *)conf, NULL};
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
    pid_t pid;
    double t0 = now_ms();
    int e = posix_spawn(&pid, kiosk, &fa, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    if (e)
        return -1;
    int st;
    struct rusage ru;
    if (wait4(pid, &st, 0, &ru) < 0 || !WIFEXITED(st) || WEXITSTATUS(st))
        return -1;
    *cpu = (double)(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) * 1e3 +
           (double)(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec) / 1e3;
    return now_ms() - t0;
}

/* ms per frame: (N frames - 1 frame) / (N - 1), which takes out the
 * process start and the config's parse; the median of -t runs (at least
 * three). cpu: the process's CPU ms per frame, every thread's. */
static double time_kiosk(const char *kiosk, const char *conf, int w, int h, const char *fmt, int nthreads,
                         double *cpu)
{
    enum { N = 31 };
    double v[64], c[64];
    int reps = REPS < 3 ? 3 : REPS;
    for (int k = 0; k < reps; k++) {
        double ca, cb, a = run_kiosk(kiosk, conf, w, h, fmt, 1, nthreads, &ca),
                       b = run_kiosk(kiosk, conf, w, h, fmt, N, nthreads, &cb);
        if (a < 0 || b < 0)
            return -1;
        v[k] = (b - a) / (N - 1);
        c[k] = (cb - ca) / (N - 1);
    }
    double m = median(v, reps);
    *cpu = median(c, reps);
    return m < 0 ? 0 : m;
}

/* ---- present ---- */

static double time_present(fx_memfb *src, fx_memfb *dst, int damage)
{
    int32_t w = src->surf.w, h = src->surf.h;
    /* 10% of the area: a rectangle of sqrt(0.1) of each side, in the middle */
    int32_t dw = damage ? w * 316 / 1000 : w, dh = damage ? h * 316 / 1000 : h;
    int32_t x = (w - dw) / 2, y = (h - dh) / 2;
    fx_surface part = fx_surface_sub(src->surf, (fx_rect){x, y, x + dw, y + dh});
    enum { N = 21 };
    double v[N];
    for (int k = 0; k < N; k++) {
        double t0 = now_ms();
        fx_blit(&dst->surf, x, y, &part);
        v[k] = now_ms() - t0;
    }
    return median(v, N);
}

/* ---- the table ---- */

static const int sizes[2][2] = {{800, 480}, {1920, 1080}};
static const fx_format fmts[2] = {FX_FMT_XRGB8888, FX_FMT_RGB565};

static void row(FILE *o, const char *what, int w, int h, fx_format f, cell a, cell m, cell b)
{
    fprintf(o, "%-24s %4dx%-4d %-8s %9.2f", what, w, h, fx_format_get(f)->name, a.ms);
    if (MID && m.bands > 1 && m.ms > 0)
        fprintf(o, " %9.2f %5.2fx", m.ms, a.ms / m.ms);
    else if (MID && m.bands > 1)
        fprintf(o, " %9.2f %6s", m.ms, "-"); /* too short to time */
    else if (MID)
        fprintf(o, " %9s %6s", "-", "-");
    fprintf(o, " %9.2f", b.ms);
    if (b.bands > 1) {
        if (b.ms > 0)
            fprintf(o, " %5.2fx", a.ms / b.ms);
        else
            fprintf(o, " %6s", "-"); /* too short to time */
        fprintf(o, " %8.2f %8.2f", a.cpu_ms, b.cpu_ms);
        /* none for the kiosk (a process: its CPU in all) */
        for (int k = 0; k < b.bands && k < MAXB && b.band_cpu[0] > 0; k++)
            fprintf(o, "%s%.2f", k ? "/" : "  ", b.band_cpu[k]);
        fprintf(o, "\n");
    } else {
        fprintf(o, "     one thread %8.2f\n", a.cpu_ms);
    }
}

static void load(char *buf, size_t n)
{
    double l[3] = {0, 0, 0};
    if (getloadavg(l, 3) < 0)
        snprintf(buf, n, "unknown");
    else
        snprintf(buf, n, "%.2f %.2f %.2f", l[0], l[1], l[2]);
}

/* Whether a row labelled what is asked for: only is NULL (every row) or a
 * comma-separated list of which one is part of what. */
static int wanted(const char *only, const char *what)
{
    if (!only)
        return 1;
    for (const char *p = only; *p;) {
        size_t n = strcspn(p, ",");
        for (const char *q = what; n && *q; q++)
            if (!strncmp(q, p, n))
                return 1;
        p += n + (p[n] == ',');
    }
    return 0;
}

int frames_run(FILE *o, const char *self, int nthreads, int reps, const char *only)
{
    REPS = reps < 1 ? 1 : reps > 64 ? 64 : reps;
    int ncpu = fx_par_cpu_count();
    if (nthreads == 1 || nthreads < 0 || nthreads > MAXB) {
        fprintf(stderr, "fixel-bench: --frames -j wants 2..%d threads for the N-thread column (0: every core), not %d\n",
                MAXB, nthreads);
        return 2;
    }
    if (nthreads == 0)
        nthreads = ncpu > 1 ? ncpu : 2;
    MID = nthreads > 2 ? 2 : 0;
    char la[64], lb[64];
    load(la, sizeof la);
    fprintf(o, "TABLE 8  frames a user sees: ms per frame, median of %d (after one warm-up frame)\n", REPS);
    fprintf(o, "  1 thr: one thread; %d thr: %d bands of rows on %d threads (fixel/par.h), same pixels;\n",
            nthreads, nthreads, nthreads);
    fprintf(o, "  x: speed-up; cpu 1/cpu N: process CPU ms per frame (cpu N > cpu 1 is the set-up each band\n"
               "  repeats); band cpu: CPU ms of each band's thread (an even split shows despite a noisy wall)\n");
    fprintf(o, "  %d online cores; load average at the start %s\n\n", ncpu, la);
    if (MID)
        fprintf(o, "  2 thr, x2: the same on 2 threads and its speed-up\n");
    fprintf(o, "%-24s %-9s %-8s %9s", "what", "size", "format", "1 thr");
    if (MID)
        fprintf(o, " %9s %6s", "2 thr", "x2");
    fprintf(o, " %9s %6s %8s %8s  %s\n", "N thr", "x", "cpu 1", "cpu N", "band cpu");
    fx_memfb fb, dst;
    int bad = 0;
    char demo[4096], kiosk[4096];
    const char *slash = strrchr(self, '/');
    snprintf(demo, sizeof demo, "%.*sfixel-demo", slash ? (int)(slash - self + 1) : 0, self);
    snprintf(kiosk, sizeof kiosk, "%.*sfixel-kiosk", slash ? (int)(slash - self + 1) : 0, self);
    for (int s = 0; s < 2; s++)
        for (int f = 0; f < 2; f++)
            if (!wanted(only, "demo"))
                continue;
            else if (access(demo, X_OK) || demo_rows(o, demo, sizes[s][0], sizes[s][1], fmts[f], nthreads)) {
                fprintf(o, "demo pages %dx%d %s: %s --time-pages failed or is missing\n", sizes[s][0], sizes[s][1],
                        fx_format_get(fmts[f])->name, demo);
                bad = 1;
            }
    /* the 3D and ray-traced golden scripts at frame size: the pipelines'
     * scaling (the demo's ray-traced page is a fixed 784x408 picture); the ray
     * tracer at a quarter of 800x480 (a whole frame takes seconds) */
    static const struct {
        const char *name;
        int w, h;
    } scripts[] = {{"3d-teapot-phong", 800, 480},     {"3d-teapot-gouraud", 800, 480},
                   {"3d-teapot-flat", 800, 480},      {"3d-torus-phong", 800, 480},
                   {"3d-teapot-phong", 1920, 1080},   {"3d-teapot-gouraud", 1920, 1080},
                   {"3d-teapot-flat", 1920, 1080},    {"3d-torus-phong", 1920, 1080},
                   {"rt-spheres", 400, 240},          {"rt-torus", 400, 240},
                   {0, 0, 0}};
    size_t arena_size = (size_t)64 << 20;
    void *arena = malloc(arena_size);
    for (int i = 0; scripts[i].name && arena; i++)
        for (int f = 0; f < 2; f++) {
            int w = scripts[i].w, h = scripts[i].h;
            char path[256];
            snprintf(path, sizeof path, "script %s", scripts[i].name);
            if (!wanted(only, path))
                continue;
            snprintf(path, sizeof path, "tests/golden/scripts/%s.fxs", scripts[i].name);
            size_t len;
            char *text = slurp(path, &len);
            if (!text) { /* the scripts are read from the source tree */
                fprintf(o, "script %s: %s not found (run fixel-bench from the source tree)\n", scripts[i].name,
                        path);
                bad = 1;
                continue;
            }
            if (fx_memfb_create(&fb, w, h, fmts[f]) < 0)
                return 1;
            int ok1, ok2, okm = 1;
            cell a = time_script(&fb, text, len, 1, arena, arena_size, &ok1);
            cell m;
            memset(&m, 0, sizeof m);
            if (MID)
                m = time_script(&fb, text, len, MID, arena, arena_size, &okm);
            cell b = time_script(&fb, text, len, nthreads, arena, arena_size, &ok2);
            free(text);
            char what[48];
            snprintf(what, sizeof what, "script %s%s", scripts[i].name, ok1 && ok2 && okm ? "" : " FAILED");
            bad |= !(ok1 && ok2 && okm);
            row(o, what, w, h, fmts[f], a, m, b);
            fflush(o);
            fx_memfb_destroy(&fb);
        }
    free(arena);
    /* the kiosk: one process per run, every widget redrawn (--full), on
     * one thread and on nthreads (--threads: bands of rows, same pixels) */
    DIR *d = opendir("examples");
    char *confs[32];
    int nconf = 0;
    struct dirent *e;
    while (d && (e = readdir(d)) && nconf < 32) {
        size_t l = strlen(e->d_name);
        if (!strncmp(e->d_name, "kiosk-", 6) && l > 5 && !strcmp(e->d_name + l - 5, ".conf"))
            confs[nconf++] = strdup(e->d_name);
    }
    if (d)
        closedir(d);
    qsort(confs, (size_t)nconf, sizeof *confs, (int (*)(const void *, const void *))strcmp);
    for (int c = 0; c < nconf; c++) {
        char path[300];
        snprintf(path, sizeof path, "kiosk %.*s", (int)(strlen(confs[c]) - 5), confs[c]);
        int want = wanted(only, path);
        snprintf(path, sizeof path, "examples/%s", confs[c]);
        for (int s = 0; s < 2 && want; s++)
            for (int f = 0; f < 2; f++) {
                int w = sizes[s][0], h = sizes[s][1];
                cell a, m, b;
                memset(&a, 0, sizeof a);
                memset(&m, 0, sizeof m);
                memset(&b, 0, sizeof b);
                const char *fn = fx_format_get(fmts[f])->name;
                int ok = !access(kiosk, X_OK);
                if (ok)
                    a.ms = time_kiosk(kiosk, path, w, h, fn, 1, &a.cpu_ms);
                if (ok && a.ms >= 0 && MID) {
                    m.ms = time_kiosk(kiosk, path, w, h, fn, MID, &m.cpu_ms);
                    m.bands = MID;
                }
                if (ok && a.ms >= 0 && m.ms >= 0)
                    b.ms = time_kiosk(kiosk, path, w, h, fn, nthreads, &b.cpu_ms);
                char what[48];
                snprintf(what, sizeof what, "kiosk %.*s", (int)(strlen(confs[c]) - 5), confs[c]);
                if (!ok || a.ms < 0 || m.ms < 0 || b.ms < 0) {
                    fprintf(o, "%-24s %4dx%-4d %-8s  (fixel-kiosk failed or missing: %s)\n", what, w, h, fn, kiosk);
                    bad |= ok; /* a kiosk that is there and fails; none built is only said */
                } else {
                    a.bands = 1;
                    b.bands = nthreads; /* no per-band CPU: the process's, every thread's */
                    row(o, what, w, h, fmts[f], a, m, b);
                }
                fflush(o);
            }
        free(confs[c]);
    }
    /* presenting: a copy into a second buffer, as the shadow path copies
     * into the scanout buffer (a real framebuffer is uncached or
     * write-combined memory and slower) */
    fprintf(o, "\n%-24s %-9s %-8s %9s %9s\n", "present (copy)", "size", "format", "full", "10% dmg");
    for (int s = 0; s < 2 && wanted(only, "present"); s++)
        for (int f = 0; f < 2; f++) {
            int w = sizes[s][0], h = sizes[s][1];
            if (fx_memfb_create(&fb, w, h, fmts[f]) < 0 || fx_memfb_create(&dst, w, h, fmts[f]) < 0)
                return 1;
            fprintf(o, "%-24s %4dx%-4d %-8s %9.3f %9.3f\n", "present", w, h, fx_format_get(fmts[f])->name,
                    time_present(&fb, &dst, 0), time_present(&fb, &dst, 1));
            fx_memfb_destroy(&fb);
            fx_memfb_destroy(&dst);
        }
    load(lb, sizeof lb);
    fprintf(o, "\nload average at the end %s\n", lb);
    return bad;
}
