/* SPDX-License-Identifier: MIT */
/* fixel-demo — the gallery of everything fixel draws (`make run`).
 *
 * With a display it is interactive (keys, mouse, touch, GPIO buttons); on a
 * machine without one it renders every page into OUT/<page>.png. --golden
 * compares those renders with committed pictures for `make test`. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "demo.h"
#include "fixel/par.h"
#include "fixel/app.h"
#include "fixel/display.h"
#include "fixel/env.h"
#include "fixel/files.h"
#include "fixel/memfb.h"

#define HEADLESS_W 800
#define HEADLESS_H 480

static void usage(FILE *f)
{
    fprintf(f,
            "usage: fixel-demo [--headless] [--out DIR] [--page NAME] [--list] [--flight FILE]\n"
            "       fixel-demo --display OUTPUT=PAGE [--display OUTPUT=PAGE...]\n"
            "       fixel-demo --golden DIR [--update]\n"
            "  --headless    render pages to PNG files instead of opening a display\n"
            "                (the default when no display is found)\n"
            "  --out DIR     where headless pictures go (default out)\n"
            "  --page NAME   only this page (headless) or start on it (interactive)\n"
            "  --list        print the page names\n"
            "  --flight FILE the Animation page's camera flight: loaded from FILE, and each\n"
            "                key recorded (k) appended to it (docs/ANIMATION.md)\n"
            "  --time-pages WxH FORMAT THREADS REPS  time every page (fixel-bench --frames)\n"
            "  -j N          draw headless and --golden pages on N threads, in bands of rows\n"
            "                (pages that cannot be cut draw on one, the ray tracer traces on N;\n"
            "                the same pixels)\n"
            "  --display OUTPUT=PAGE  show PAGE on OUTPUT (a connector: HDMI-A-2,\n"
            "                vc4:HDMI-A-1, DSI-1; empty: the next free output); repeat it\n"
            "                for one page per output, each with its own state; input\n"
            "                bound to an output (FIXEL_INPUT_BIND, or guessed) drives its\n"
            "                page, other input the first; with FIXEL_BACKEND=memory the\n"
            "                outputs are 800x480 memory displays (FIXEL_OUT saves each)\n"
            "  --golden DIR  render every page at 800x480 and compare with DIR/<page>.png;\n"
            "                mismatches write DIR/<page>.actual.png; --update rewrites them\n"
            "keys: right/left, PageDown/PageUp, n/p, Down/Up (GPIO buttons): next/previous page;\n"
            "      tab bar: click or touch; r reset the page, q/Esc quit\n"
            "clipping: drag the line's ends or the window; c/l/n Cohen-Sutherland/Liang-Barsky/NLN\n"
            "fills: click to flood-fill   colour: click the wheel\n"
            "fractals: click zooms in, right click out, the Julia set and the orbit of 0 follow the pointer,\n"
            "        o orbit overlay on/off, 0-6 Koch order\n"
            "3d: s shading; camera u/d up/down, f/b forward/back, h/j left/right, y/Y yaw, t/T pitch, o/O roll\n"
            "hidden: 1-9 z-buffer/painter/Newell/BSP/scan-line/Warnock/ray casting/A-buffer/octree,\n"
            "        [ ] move the traced scan line, m torus / course scene, +/- triangles or turn\n"
            "anim (no tab: n/p or --page anim): camera u/d f/b h/j y/Y t/T, k record a key,\n"
            "        g fly the recorded keys, x clear\n");
}

static int find_page(const char *name)
{
    for (int i = 0; i < demo_npages; i++)
        if (!strcmp(demo_pages[i].name, name))
            return i;
    return -1;
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static int g_threads = 1; /* -j: headless pages and --golden in bands */
static int g_threads_given; /* without -j the ray tracer takes every core */

static int render_page(fx_memfb *fb, int page)
{
    demo_state st;
    demo_state_init(&st, fb->surf.w, fb->surf.h);
    st.page = page;
    fx_ctx c;
    fx_ctx_init(&c, &fb->surf);
    st.threads = g_threads_given ? g_threads : 0;
    demo_draw_threads(&c, &st, g_threads);
    return 0;
}

/* --time-pages WxH FORMAT THREADS REPS (fixel-bench --frames reads it):
 * per page "NAME MS1 CPU1 MSN CPUN BANDS CPU0/CPU1/...", the median wall
 * and process CPU ms of REPS frames after a warm-up on one thread and in
 * bands on THREADS threads, and each band's thread CPU ms. */
enum { TIME_MAXB = 8 };

typedef struct time_job {
    const demo_state *st;
    double cpu[TIME_MAXB];
} time_job;

static double clock_ms(clockid_t id)
{
    struct timespec t;
    clock_gettime(id, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec / 1e6;
}

static void time_band(void *u, fx_ctx *c, int band)
{
    time_job *j = u;
    double t0 = clock_ms(CLOCK_THREAD_CPUTIME_ID);
    demo_state st = *j->st; /* each band its own state, as demo_draw_threads */
    demo_draw(c, &st);
    if (band < TIME_MAXB)
        j->cpu[band] = clock_ms(CLOCK_THREAD_CPUTIME_ID) - t0;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double median_of(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

/* one page on nthreads: median wall and CPU ms; bands' CPU into bc */
static void time_one(fx_memfb *fb, int page, int nthreads, int reps, double *ms, double *cpu, double *bc, int *bands)
{
    double wall[64], pc[64], b[TIME_MAXB][64];
    demo_state st;
    demo_state_init(&st, fb->surf.w, fb->surf.h);
    st.page = page;
    st.threads = nthreads; /* a page with threads of its own (the ray tracer) starts this many */
    *bands = nthreads > 1 && demo_pages[page].bands ? (nthreads < TIME_MAXB ? nthreads : TIME_MAXB) : 1;
    for (int k = -1; k < reps; k++) {
        fx_ctx c;
        fx_ctx_init(&c, &fb->surf);
        time_job j;
        memset(&j, 0, sizeof j);
        j.st = &st;
        double t0 = clock_ms(CLOCK_MONOTONIC), c0 = clock_ms(CLOCK_PROCESS_CPUTIME_ID);
        if (*bands > 1)
            fx_par_bands(&c, *bands, *bands, time_band, &j);
        else
            time_band(&j, &c, 0);
        if (k < 0)
            continue;
        wall[k] = clock_ms(CLOCK_MONOTONIC) - t0;
        pc[k] = clock_ms(CLOCK_PROCESS_CPUTIME_ID) - c0;
        for (int i = 0; i < *bands; i++)
            b[i][k] = j.cpu[i];
    }
    *ms = median_of(wall, reps);
    *cpu = median_of(pc, reps);
    for (int i = 0; i < *bands; i++)
        bc[i] = median_of(b[i], reps);
}

static int time_pages(const char *size, const char *format, const char *threads, const char *reps_s)
{
    int w, h, nthreads, reps;
    char extra;
    fx_format f = fx_format_from_name(format);
    if (sscanf(size, "%dx%d%c", &w, &h, &extra) != 2 || w < 1 || h < 1 || w > 8192 || h > 8192 ||
        f == FX_FMT_COUNT || sscanf(threads, "%d%c", &nthreads, &extra) != 1 || nthreads < 1 || nthreads > 64 ||
        sscanf(reps_s, "%d%c", &reps, &extra) != 1 || reps < 1 || reps > 64) {
        fprintf(stderr, "fixel-demo: --time-pages WxH FORMAT THREADS REPS\n");
        return 2;
    }
    fx_memfb fb;
    if (fx_memfb_create(&fb, w, h, f) < 0)
        return 1;
    for (int p = 0; p < demo_npages; p++) {
        double ms1, cpu1, msn, cpun, bc1[TIME_MAXB], bc[TIME_MAXB];
        int b1, bn;
        time_one(&fb, p, 1, reps, &ms1, &cpu1, bc1, &b1);
        time_one(&fb, p, nthreads, reps, &msn, &cpun, bc, &bn);
        if (demo_pages[p].threads && nthreads > 1) {
            /* a page on threads of its own: N threads, no bands; on two,
             * this thread's CPU and the other's (the rest of the process's) */
            printf("%s %.3f %.3f %.3f %.3f %d ", demo_pages[p].name, ms1, cpu1, msn, cpun, nthreads);
            if (nthreads == 2)
                printf("%.3f/%.3f", bc[0], cpun - bc[0]);
        } else {
            printf("%s %.3f %.3f %.3f %.3f %d ", demo_pages[p].name, ms1, cpu1, msn, cpun, bn);
            for (int i = 0; i < bn; i++)
                printf("%s%.3f", i ? "/" : "", bc[i]);
        }
        printf("\n");
        fflush(stdout);
    }
    fx_memfb_destroy(&fb);
    return 0;
}

static int headless(const char *out, int only)
{
    fx_memfb fb;
    if (fx_memfb_create(&fb, HEADLESS_W, HEADLESS_H, FX_FMT_XRGB8888) < 0) {
        fprintf(stderr, "fixel-demo: out of memory\n");
        return 1;
    }
    if (fx_mkdir_parents(out) < 0) {
        fprintf(stderr, "fixel-demo: cannot create %s: %s\n", out, strerror(errno));
        fx_memfb_destroy(&fb);
        return 1;
    }
    double t0 = now_s();
    int n = 0, rc = 0;
    for (int i = 0; i < demo_npages; i++) {
        if (only >= 0 && i != only)
            continue;
        double t = now_s();
        render_page(&fb, i);
        double dt = now_s() - t;
        char path[4096];
        snprintf(path, sizeof path, "%s/%s.png", out, demo_pages[i].name);
        int e = fx_write_image(path, &fb.surf);
        if (e < 0) {
            fprintf(stderr, "fixel-demo: cannot write %s: %s%s\n", path, strerror(-e), fx_built_without_hint(e));
            rc = 1;
            continue;
        }
        printf("fixel-demo: %-10s -> %s (%.1f ms)\n", demo_pages[i].name, path, dt * 1e3);
        n++;
    }
    printf("fixel-demo: no display here; rendered %d page%s headless (%dx%d) into %s/ in %.2f s\n", n,
           n == 1 ? "" : "s", HEADLESS_W, HEADLESS_H, out, now_s() - t0);
    fx_memfb_destroy(&fb);
    return rc;
}

static int golden(const char *dir, int update)
{
    fx_memfb fb;
    if (fx_memfb_create(&fb, HEADLESS_W, HEADLESS_H, FX_FMT_XRGB8888) < 0)
        return 1;
    int pass = 0, fail = 0;
    uint8_t *row = malloc((size_t)HEADLESS_W * 3);
    for (int i = 0; i < demo_npages && row; i++) {
        render_page(&fb, i);
        char path[4096];
        snprintf(path, sizeof path, "%s/%s.png", dir, demo_pages[i].name);
        if (update) {
            if (fx_write_png(path, &fb.surf) < 0) {
                printf("FAIL %s: cannot write\n", path);
                fail++;
            } else {
                printf("wrote %s\n", path);
                pass++;
            }
            continue;
        }
        uint8_t *rgb = NULL;
        int32_t w = 0, h = 0;
        int ok = fx_read_png_rgb(path, &rgb, &w, &h) == 0 && w == fb.surf.w && h == fb.surf.h;
        int32_t bad = 0;
        for (int32_t y = 0; ok && y < h; y++) {
            fx_surface_row_to_rgb(&fb.surf, y, row);
            for (int32_t x = 0; x < w * 3; x++)
                bad += row[x] != rgb[(size_t)y * w * 3 + x];
        }
        free(rgb);
        if (ok && !bad) {
            pass++;
            continue;
        }
        fail++;
        char apath[4096];
        snprintf(apath, sizeof apath, "%s/%s.actual.png", dir, demo_pages[i].name);
        int we = fx_write_png(apath, &fb.surf);
        printf("FAIL demo page %s: %s (%s %s%s%s)\n", demo_pages[i].name,
               ok ? "pixels differ" : "golden missing or wrong size",
               we < 0 ? "could not write" : "wrote", apath, we < 0 ? ": " : "",
               we < 0 ? strerror(-we) : "");
    }
    free(row);
    /* The ray-traced page as a display builds it (a few bands a frame on
     * every core) must end as the headless picture, and show part of it
     * on the way. */
    int rp = find_page("raytrace");
    if (!update && rp >= 0) {
        render_page(&fb, rp);
        static uint32_t want[DEMO_RT_W * DEMO_RT_H];
        for (int32_t y = 0; y < DEMO_RT_H; y++)
            memcpy(want + (size_t)y * DEMO_RT_W, fb.surf.pixels + (size_t)(DEMO_RT_Y + y) * fb.surf.stride + DEMO_RT_X * 4,
                   DEMO_RT_W * 4);
        demo_state st;
        demo_state_init(&st, fb.surf.w, fb.surf.h);
        st.page = rp;
        st.interactive = 1;
        demo_key(&st, 'g');
        fx_ctx c;
        fx_ctx_init(&c, &fb.surf);
        int frames = 0, partial = 0;
        do {
            demo_draw(&c, &st);
            frames++;
            /* the picture's last row is still dark while it builds */
            const uint32_t *last = (const uint32_t *)(fb.surf.pixels +
                                                      (size_t)(DEMO_RT_Y + DEMO_RT_H - 1) * fb.surf.stride) + DEMO_RT_X;
            partial += frames == 1 && (last[DEMO_RT_W / 2] & 0xFFFFFF) == 0;
        } while (demo_rt_busy(&st) && frames < 10000);
        int same = 1;
        for (int32_t y = 0; y < DEMO_RT_H; y++)
            same &= !memcmp(want + (size_t)y * DEMO_RT_W,
                            fb.surf.pixels + (size_t)(DEMO_RT_Y + y) * fb.surf.stride + DEMO_RT_X * 4, DEMO_RT_W * 4);
        if (same && partial && frames > 2) {
            pass++;
        } else {
            fail++;
            printf("FAIL demo page raytrace built progressively: %s after %d frames%s\n",
                   same ? "same picture" : "a different picture", frames,
                   partial ? "" : ", the first frame was not partial");
        }
    }
    /* The clipping page honours the c / l / n it advertises: each key is
     * taken, the readout (the chosen clipper's trace) changes with it, and
     * the playground's pixels do not (every clipper lights the same). */
    int cp = find_page("clipping");
    if (!update && cp >= 0) {
        static uint32_t shot[3][HEADLESS_W * HEADLESS_H];
        const char keys[3] = {'c', 'l', 'n'};
        int taken = 1;
        for (int k = 0; k < 3; k++) {
            demo_state st;
            demo_state_init(&st, fb.surf.w, fb.surf.h);
            st.page = cp;
            taken &= demo_key(&st, keys[k]) == 1;
            fx_ctx c;
            fx_ctx_init(&c, &fb.surf);
            demo_draw(&c, &st);
            for (int32_t y = 0; y < HEADLESS_H; y++)
                memcpy(shot[k] + (size_t)y * HEADLESS_W, fb.surf.pixels + (size_t)y * fb.surf.stride,
                       HEADLESS_W * 4);
        }
        int play_same = 1, read_differ = 1;
        for (int k = 1; k < 3; k++)
            for (int j = 0; j < k; j++) {
                int rd = 0;
                for (int32_t y = 0; y < HEADLESS_H; y++) {
                    const uint32_t *a = shot[k] + (size_t)y * HEADLESS_W, *b = shot[j] + (size_t)y * HEADLESS_W;
                    play_same &= !memcmp(a, b, 576 * 4);
                    rd |= memcmp(a + 580, b + 580, (HEADLESS_W - 580) * 4) != 0;
                }
                read_differ &= rd;
            }
        if (taken && play_same && read_differ) {
            pass++;
        } else {
            fail++;
            printf("FAIL demo page clipping keys c/l/n: %s%s%s\n", taken ? "" : "a key was not taken; ",
                   play_same ? "" : "the playground changed with the clipper; ",
                   read_differ ? "" : "two clippers show the same readout");
        }
    }
    fx_memfb_destroy(&fb);
    printf("demo: %d passed, %d failed\n", pass, fail);
    return fail ? 1 : 0;
}

/* ---- interactive ---- */
typedef struct demo_app {
    fx_app *app;
    fx_display *disp;   /* the display this page is on */
    int fps_box;        /* 0 on memory displays: their frames are compared */
    demo_state st;
    double last, frame_ms, fps_t0;
    int frames;
    double fps;
    int pressed;
} demo_app;

static void redisplay(demo_app *d) { fx_app_post_redisplay_on(d->app, d->disp); }

static void on_display(void *user)
{
    demo_app *d = user;
    double t0 = now_s();
    fx_surface s = fx_display_surface(d->disp);
    fx_ctx c;
    fx_ctx_init(&c, &s);
    d->st.w = s.w;
    d->st.h = s.h;
    demo_draw(&c, &d->st);
    d->frame_ms = (now_s() - t0) * 1e3;
    if (d->fps_box) {
        /* on its own dark box so it stays legible over any page */
        fx_ctx_set_color(&c, 0xFF000000u);
        fx_fill_rect(&c, s.w - 156, DEMO_TAB_H, 156, 13);
        demo_text(&c, s.w - 152, DEMO_TAB_H + 2, 0xFFFFFF80u, "%5.1f fps %6.2f ms", d->fps, d->frame_ms);
    }
    fx_display_present(d->disp, NULL, 0);
    d->frames++;
    double t = now_s();
    if (t - d->fps_t0 >= 1.0) {
        d->fps = d->frames / (t - d->fps_t0);
        d->frames = 0;
        d->fps_t0 = t;
    }
}

static void page_step(demo_app *d, int dir)
{
    d->st.page = (d->st.page + dir + demo_npages) % demo_npages;
    redisplay(d);
}

static void on_key(void *user, unsigned char key, int x, int y)
{
    demo_app *d = user;
    (void)x;
    (void)y;
    if (key == 'q' || key == 27) {
        fx_app_quit(d->app);
        return;
    }
    if (key == 'n' && d->st.page != find_page("clipping"))
        page_step(d, 1);
    else if (key == 'p' || key == ' ')
        page_step(d, key == ' ' ? 1 : -1);
    else if (key == 'r') {
        int p = d->st.page;
        demo_state_init(&d->st, d->st.w, d->st.h);
        d->st.page = p;
        d->st.interactive = 1;
        d->st.nseeds = 0;
    } else if (key == '\r' || key == '\n')
        page_step(d, 1);
    else
        demo_key(&d->st, key);
    redisplay(d);
}

static void on_special(void *user, int key, int x, int y)
{
    demo_app *d = user;
    (void)x;
    (void)y;
    if (key == FX_KEY_RIGHT || key == FX_KEY_PAGE_DOWN || key == FX_KEY_DOWN)
        page_step(d, 1);
    else if (key == FX_KEY_LEFT || key == FX_KEY_PAGE_UP || key == FX_KEY_UP)
        page_step(d, -1);
}

static void pointer(demo_app *d, int x, int y, int down)
{
    if (down == 1 && y < DEMO_TAB_H) {
        int p = demo_tab_at(d->st.w, x);
        if (p >= 0)
            d->st.page = p;
    } else {
        demo_pointer(&d->st, x, y, down);
    }
    redisplay(d);
}

static void on_mouse(void *user, int button, int state, int x, int y)
{
    demo_app *d = user;
    if (button == FX_BUTTON_RIGHT && state == FX_DOWN) {
        demo_pointer(&d->st, x, y, 2);
        redisplay(d);
        return;
    }
    if (button != FX_BUTTON_LEFT)
        return;
    d->pressed = state == FX_DOWN;
    pointer(d, x, y, state == FX_DOWN ? 1 : -1);
}

static void on_motion(void *user, int x, int y) { pointer(user, x, y, 0); }

static void on_passive(void *user, int x, int y)
{
    demo_app *d = user;
    d->st.mx = x;
    d->st.my = y;
    demo_pointer(&d->st, x, y, 3);
    redisplay(d);
}

static void on_touch(void *user, int id, int x, int y, int phase)
{
    if (id != 0)
        return;
    pointer(user, x, y, phase == FX_TOUCH_DOWN ? 1 : phase == FX_TOUCH_UP ? -1 : 0);
}

static void on_draw(fx_app *app, fx_display *disp, void *user)
{
    (void)app, (void)disp;
    on_display(user);
}

#define DEMO_MAX_OUT FX_APP_MAX_DISPLAYS
typedef struct demo_set {
    demo_app page[DEMO_MAX_OUT];
    int n;
} demo_set;

/* One page per output; page[0] is on the app's own display. */
static demo_set outputs;

static void tick(void *user, int value)
{
    demo_app *first = user;
    (void)value;
    for (int i = 0; i < outputs.n; i++) {
        demo_app *d = &outputs.page[i];
        d->st.frame++;
        /* only the animated pages need a frame on every tick */
        const char *n = demo_pages[d->st.page].name;
        if (!strcmp(n, "3d") || !strcmp(n, "transforms") || !strcmp(n, "anim") ||
            (!strcmp(n, "raytrace") && demo_rt_busy(&d->st)))
            redisplay(d);
    }
    fx_app_timer(first->app, 33, tick, 0);
}

static void page_init(demo_app *d, fx_app *app, fx_display *disp, int page)
{
    memset(d, 0, sizeof *d);
    d->app = app;
    d->disp = disp;
    fx_display_info info;
    fx_display_get_info(disp, &info);
    d->fps_box = info.backend != FX_BACKEND_MEMORY;
    int turned = info.rotation == 90 || info.rotation == 270;
    demo_state_init(&d->st, turned ? info.height : info.width, turned ? info.width : info.height);
    d->st.interactive = 1;
    d->st.nseeds = 0;
    d->st.page = page < 0 ? 0 : page;
    d->fps_t0 = now_s();
}

/* pages[i] on the app's display (i = 0) and the added ones. */
static int interactive(fx_app *app, fx_display *const *disp, const int *pages, int n)
{
    demo_set *set = &outputs;
    set->n = n;
    fx_callbacks cb;
    memset(&cb, 0, sizeof cb);
    cb.keyboard = on_key;
    cb.special = on_special;
    cb.mouse = on_mouse;
    cb.motion = on_motion;
    cb.passive_motion = on_passive;
    cb.touch = on_touch;
    for (int i = 0; i < n; i++) {
        page_init(&set->page[i], app, disp[i], pages[i]);
        if (i == 0) {
            fx_callbacks c0 = cb;
            c0.display = on_display;
            fx_app_set_callbacks(app, &c0, &set->page[0]);
        } else {
            fx_app_set_display_callbacks(app, disp[i], &cb, &set->page[i]);
        }
        redisplay(&set->page[i]);
    }
    fx_app_timer(app, 33, tick, 0);
    int rc = fx_app_main_loop(app);
    return rc < 0 ? 1 : 0;
}

/* --display OUTPUT=PAGE...: every output must open (no headless fallback);
 * memory displays are the headless pictures' size. */
static int outputs_run(fx_app_options *o, char outs[][64], const int *pages, int n)
{
    if (o->display.backend == FX_BACKEND_MEMORY) {
        o->display.memory_w = HEADLESS_W;
        o->display.memory_h = HEADLESS_H;
    }
    if (outs[0][0])
        o->display.connector = outs[0];
    fx_app *app;
    if (fx_app_open(&app, o) < 0) {
        fprintf(stderr, "fixel-demo: cannot open output '%s' (reason above)\n", outs[0]);
        return 1;
    }
    fx_display *disp[DEMO_MAX_OUT] = {fx_app_display(app)};
    for (int i = 1; i < n; i++) {
        fx_display_options d = o->display;
        /* empty: the next output not yet shown (not FIXEL_CONNECTOR's again) */
        d.connector = outs[i][0] ? outs[i] : NULL;
        if (fx_app_add_display(app, &d, on_draw, &outputs.page[i], &disp[i]) < 0) {
            fprintf(stderr, "fixel-demo: cannot open output '%s' (reason above)\n", outs[i]);
            fx_app_close(app);
            return 1;
        }
    }
    if (fx_app_bind_inputs_from_env(app) < 0) {
        fx_app_close(app);
        return 1;
    }
    int rc = interactive(app, disp, pages, n);
    fx_app_close(app);
    return rc;
}

/* For the automatic choice: a display device node exists. */
static int display_nodes(void)
{
    return access("/dev/dri", F_OK) == 0 || access("/dev/fb0", F_OK) == 0;
}

int main(int argc, char **argv)
{
    const char *out = "out", *gold = NULL, *page = NULL;
    int force_headless = 0, update = 0;
    char outs[DEMO_MAX_OUT][64];
    int out_page[DEMO_MAX_OUT], nout = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            usage(stdout);
            return 0;
        } else if (!strcmp(a, "--headless")) {
            force_headless = 1;
        } else if (!strcmp(a, "--update")) {
            update = 1;
        } else if (!strcmp(a, "--time-pages") && i + 4 < argc) {
            return time_pages(argv[i + 1], argv[i + 2], argv[i + 3], argv[i + 4]);
        } else if (!strcmp(a, "-j") && i + 1 < argc) {
            char extra;
            if (sscanf(argv[++i], "%d%c", &g_threads, &extra) != 1 || g_threads < 1 || g_threads > 64) {
                fprintf(stderr, "fixel-demo: bad thread count '%s' (expected 1..64)\n", argv[i]);
                return 2;
            }
            g_threads_given = 1;
        } else if (!strcmp(a, "--list")) {
            for (int k = 0; k < demo_npages; k++)
                printf("%s\n", demo_pages[k].name);
            return 0;
        } else if (!strcmp(a, "--display") && i + 1 < argc) {
            const char *v = argv[++i], *eq = strrchr(v, '=');
            if (!eq || (size_t)(eq - v) >= sizeof outs[0]) {
                fprintf(stderr, "fixel-demo: --display %s: give OUTPUT=PAGE (OUTPUT a connector such as "
                        "HDMI-A-1, or empty)\n", v);
                return 2;
            }
            if (nout == DEMO_MAX_OUT) {
                fprintf(stderr, "fixel-demo: --display %s: at most %d outputs\n", v, DEMO_MAX_OUT);
                return 2;
            }
            if ((out_page[nout] = find_page(eq + 1)) < 0) {
                fprintf(stderr, "fixel-demo: --display %s: no page '%s' (try --list)\n", v, eq + 1);
                return 2;
            }
            snprintf(outs[nout], sizeof outs[0], "%.*s", (int)(eq - v), v);
            nout++;
        } else if (!strcmp(a, "--flight") && i + 1 < argc) {
            /* read at start and written by 'k' and 'x': a FIFO hung the
             * read, a device would be truncated (issue #40) */
            char why[160];
            if (fx_check_replaceable(argv[i + 1], why, sizeof why) < 0) {
                fprintf(stderr, "fixel-demo: --flight %s: %s\n", argv[i + 1], why);
                return 2;
            }
            demo_anim_set_file(argv[++i]);
        } else if ((!strcmp(a, "--out") || !strcmp(a, "--page") || !strcmp(a, "--golden")) && i + 1 < argc) {
            const char *v = argv[++i];
            if (a[2] == 'o')
                out = v;
            else if (a[2] == 'p')
                page = v;
            else
                gold = v;
        } else {
            fprintf(stderr, "fixel-demo: unknown or incomplete option '%s'\n", a);
            usage(stderr);
            return 2;
        }
    }
    int only = -1;
    if (page && (only = find_page(page)) < 0) {
        fprintf(stderr, "fixel-demo: no page '%s' (try --list)\n", page);
        return 2;
    }
    if (nout && (gold || force_headless || page)) {
        fprintf(stderr, "fixel-demo: --display shows pages on outputs; it does not go with %s\n",
                gold ? "--golden" : force_headless ? "--headless" : "--page");
        return 2;
    }
    if (gold)
        return golden(gold, update);
    if (force_headless)
        return headless(out, only);
    fx_app_options o;
    fx_app_options_init(&o);
    if (fx_app_options_from_env(&o) < 0)
        return 1; /* a FIXEL_BACKEND that names no backend: logged */
    if (nout)
        return outputs_run(&o, outs, out_page, nout);
    /* A display asked for (FIXEL_BACKEND=drm|fbdev) must open or the run
     * fails; memory means headless; only the automatic choice falls back,
     * and the headless summary line says so. */
    if (o.display.backend == FX_BACKEND_MEMORY ||
        (o.display.backend == FX_BACKEND_AUTO && !display_nodes()))
        return headless(out, only);
    fx_app *app;
    if (fx_app_open(&app, &o) < 0) {
        if (o.display.backend != FX_BACKEND_AUTO) {
            fprintf(stderr, "fixel-demo: cannot open the %s display asked for (reason above)\n",
                    fx_backend_name(o.display.backend));
            return 1;
        }
        return headless(out, only);
    }
    fx_display_info info;
    fx_display_get_info(fx_app_display(app), &info);
    if (info.backend == FX_BACKEND_MEMORY) { /* the automatic order ended in memory */
        fx_app_close(app);
        return headless(out, only);
    }
    fx_display *disp = fx_app_display(app);
    int rc = interactive(app, &disp, &only, 1);
    fx_app_close(app);
    return rc;
}
