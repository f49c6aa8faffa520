/* SPDX-License-Identifier: MIT */
/* The software pointer through the app and the display on the memory
 * backend: recorded mouse and touch streams (tests/input/pointer/NAME.txt)
 * replayed through fx_app_feed as the evdev reader would, with a program
 * that marks clicks. After each "frame" statement the screen must be the
 * program's picture plus the sprite (and the golden PNG), and the program's
 * surface must be exactly what it drew: the pointer is never part of it.
 *
 * Stream statements (plus '#' comments):
 *   screen W H ROT                physical size and display rotation
 *   device N CLASS [abs X0 X1 Y0 Y1]   CLASS: mouse touch tablet keyboard
 *   ev N TYPE CODE VALUE / syn N  raw events, as in the tests/input streams
 *   frame NAME                    one pass of the loop, then the checks; NAME
 *                                 is the golden tests/input/pointer/STREAM-NAME.png
 *                                 ("-": no golden)
 *   visible 0|1                   the pointer policy's state
 * FIXEL_POINTER_GOLDEN_UPDATE=1 rewrites the goldens (look at them). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../boards/app/app_int.h"
#include "fixel/env.h"
#include "../../boards/display/display_int.h"
#include "fixel/draw.h"
#include "fixel/error.h"
#include "fixel/memfb.h"
#include "fx_test.h"

#define GOLDEN_DIR "tests/input/pointer"

/* ---- the program ---- */

typedef struct prog {
    fx_app *app;
    fx_memfb ref; /* what the program drew, kept on the side */
    int marks[16][2], nmarks, frames;
    int dirty_reads; /* frames whose surface did not hold the previous picture */
} prog;

static void picture(const fx_surface *s, const prog *p)
{
    fx_ctx c;
    fx_ctx_init(&c, s);
    for (int32_t y = 0; y < s->h; y += 8)
        for (int32_t x = 0; x < s->w; x += 8) {
            fx_ctx_set_color(&c, ((x ^ y) & 8) ? 0xFF3060A0u : 0xFF80C0E0u);
            fx_fill_rect(&c, x, y, 8, 8);
        }
    fx_ctx_set_color(&c, 0xFFF0D020u);
    fx_fill_rect(&c, 10, 10, s->w / 3, s->h / 4);
    fx_ctx_set_color(&c, 0xFFE02020u);
    for (int i = 0; i < p->nmarks; i++)
        fx_fill_rect(&c, p->marks[i][0] - 3, p->marks[i][1] - 3, 7, 7);
}

static int surf_equal(const fx_surface *a, const fx_surface *b);

static void on_display(void *u)
{
    prog *p = u;
    fx_surface s = fx_app_surface(p->app);
    /* Reading back before drawing gives exactly the last frame drawn. */
    p->dirty_reads += !surf_equal(&s, &p->ref.surf);
    picture(&s, p);
    picture(&p->ref.surf, p);
    /* After the first frame only the newest mark changes: presenting just
     * it makes the display add the pointer's rectangles itself. */
    if (p->frames == 0 || p->nmarks == 0) {
        fx_app_present(p->app, NULL, 0);
    } else {
        const int *m = p->marks[p->nmarks - 1];
        fx_rect r = {m[0] - 3, m[1] - 3, m[0] + 4, m[1] + 4};
        fx_app_present(p->app, &r, 1);
    }
    p->frames++;
}

static void on_mouse(void *u, int button, int state, int x, int y)
{
    prog *p = u;
    if (button == FX_BUTTON_LEFT && state == FX_DOWN && p->nmarks < 16) {
        p->marks[p->nmarks][0] = x;
        p->marks[p->nmarks][1] = y;
        p->nmarks++;
        fx_app_post_redisplay(p->app);
    }
}

/* ---- checks ---- */

static int surf_equal(const fx_surface *a, const fx_surface *b)
{
    if (a->w != b->w || a->h != b->h || a->format != b->format)
        return 0;
    for (int32_t y = 0; y < a->h; y++)
        for (int32_t x = 0; x < a->w; x++)
            if (fx_surface_get_native(a, x, y) != fx_surface_get_native(b, x, y))
                return 0;
    return 1;
}

/* The expected screen: the program's picture rotated onto the physical
 * buffer, then the sprite (drawn by the core routine the unit tests cover). */
static void expected_screen(fx_memfb *out, const prog *p, fx_display *d, int rot)
{
    fx_display_info info;
    fx_display_get_info(d, &info);
    fx_memfb_create(out, info.width, info.height, info.format);
    fx_copy_rotated(&out->surf, &p->ref.surf, fx_surface_rect(&p->ref.surf), rot);
    if (d->ptr.visible) {
        uint32_t mem[FX_SPRITE_MAX * FX_SPRITE_MAX];
        fx_sprite_save sv = {{0, 0, 0, 0}, mem, FX_SPRITE_MAX * FX_SPRITE_MAX};
        fx_sprite_draw(&out->surf, rot, &d->ptr.sprite, d->ptr.x, d->ptr.y, &sv);
    }
}

static int golden(const char *name, const fx_surface *s)
{
    char path[256];
    snprintf(path, sizeof path, GOLDEN_DIR "/%s.png", name);
    if (getenv("FIXEL_POINTER_GOLDEN_UPDATE")) {
        FX_CHECK_EQ(fx_write_png(path, s), 0);
        return 1;
    }
    uint8_t *rgb = NULL;
    int32_t w, h;
    int r = fx_read_png_rgb(path, &rgb, &w, &h);
    if (r == -FX_ENOTSUP)
        return 1; /* a build without libpng checks everything but the files */
    FX_CHECK_MSG(r == 0, "cannot read %s", path);
    if (r < 0)
        return 0;
    int ok = w == s->w && h == s->h;
    uint8_t *row = malloc((size_t)s->w * 3);
    for (int32_t y = 0; ok && y < h; y++) {
        fx_surface_row_to_rgb(s, y, row);
        ok = memcmp(row, rgb + (size_t)y * (size_t)w * 3, (size_t)w * 3) == 0;
    }
    free(row);
    free(rgb);
    if (!ok) {
        char out[256];
        snprintf(out, sizeof out, "build/pointer-%s.actual.png", name);
        fx_write_png(out, s);
        FX_CHECK_MSG(0, "%s differs from its golden (actual in %s)", name, out);
    }
    return ok;
}

/* ---- replay ---- */

static const struct {
    const char *name;
    int value;
} names[] = {
    {"SYN", 0}, {"KEY", 1}, {"REL", 2}, {"ABS", 3}, {"REL_X", 0}, {"REL_Y", 1},
    {"REL_WHEEL", 8}, {"ABS_X", 0}, {"ABS_Y", 1}, {"BTN_LEFT", 0x110}, {"BTN_RIGHT", 0x111},
    {"BTN_TOUCH", 0x14a},
};

static int value_of(const char *w)
{
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        if (!strcmp(names[i].name, w))
            return names[i].value;
    return (int)strtol(w, NULL, 0);
}

typedef struct config {
    fx_format format;
    fx_present_mode present;
    int buffers; /* 2: a second memory buffer stands in for a flipping scanout */
    int goldens;
} config;

/* The backend's show calls, recorded: which buffer and which physical
 * rectangles a present or a pointer move reported (DIRTYFB's clip list). */
static struct {
    const struct fx_backend_ops *real;
    struct fx_backend_ops ops;
    int calls, buf, n;
    fx_rect r[FX_DAMAGE_MAX];
} shows;

static int record_show(fx_display *d, int buf, const fx_rect *phys, int n)
{
    shows.calls++;
    shows.buf = buf;
    shows.n = n;
    memcpy(shows.r, phys, (size_t)n * sizeof *phys);
    return shows.real->show(d, buf, phys, n);
}

/* 1 when every pixel of want lies in one of the shown rectangles. */
static int shown_covers(fx_rect want)
{
    for (int32_t y = want.y0; y < want.y1; y++)
        for (int32_t x = want.x0; x < want.x1; x++) {
            int in = 0;
            for (int i = 0; i < shows.n && !in; i++)
                in = x >= shows.r[i].x0 && x < shows.r[i].x1 && y >= shows.r[i].y0 && y < shows.r[i].y1;
            if (!in)
                return 0;
        }
    return 1;
}

static void quiet(fx_log_priority p, void *u, const char *fmt, va_list ap)
{
    (void)p, (void)u, (void)fmt, (void)ap;
}

static fx_app *open_app(int32_t w, int32_t h, int rot, const config *cf, fx_pointer_mode mode,
                        void **second)
{
    fx_app_options o;
    fx_app_options_init(&o);
    o.input = 0;
    o.pointer = mode;
    o.display.backend = FX_BACKEND_MEMORY;
    o.display.memory_w = w;
    o.display.memory_h = h;
    o.display.rotation = rot;
    o.display.format = cf->format;
    o.display.present = cf->present;
    o.display.log = quiet;
    fx_app *a = NULL;
    if (fx_app_open(&a, &o) < 0)
        return NULL;
    fx_display *disp = fx_app_display(a);
    shows.real = disp->ops;
    shows.ops = *disp->ops;
    shows.ops.show = record_show;
    disp->ops = &shows.ops;
    *second = NULL;
    if (cf->buffers == 2) {
        fx_display *d = fx_app_display(a);
        *second = calloc((size_t)h, (size_t)d->scan[0].stride);
        d->scan[1] = d->scan[0];
        d->scan[1].pixels = *second;
        d->nbuf = 2;
    }
    return a;
}

static void close_app(fx_app *a, void *second)
{
    while (a->ev.ndevs)
        free(a->ev.devs[--a->ev.ndevs]); /* ours, without fds */
    fx_app_close(a);
    free(second);
}

static unsigned class_of(const char *w)
{
    unsigned c = 0;
    if (strstr(w, "mouse")) c |= FX_DEV_MOUSE;
    if (strstr(w, "touch")) c |= FX_DEV_TOUCH;
    if (strstr(w, "tablet")) c |= FX_DEV_TABLET;
    if (strstr(w, "keyboard")) c |= FX_DEV_KEYBOARD;
    return c;
}

/* One pass of the main loop after input: the pointer follows, then a frame
 * if one was asked for (the order of fx_app_main_loop). */
static void step(prog *p, const char *where)
{
    fx_app *a = p->app;
    fx_display *d = fx_app_display(a);
    int redraw = a->redisplay;
    fx_display_info before, after;
    fx_display_get_info(d, &before);
    fx_surface scr = fx_display_screen(d);
    fx_memfb snap;
    fx_memfb_create(&snap, scr.w, scr.h, scr.format);
    fx_blit(&snap.surf, 0, 0, &scr);
    int shown = d->shown;
    fx_rect old = shown >= 0 ? d->ptr.save[shown].r : (fx_rect){0, 0, 0, 0};
    int frames = p->frames, calls = shows.calls;

    fx_app_pointer_sync(a);
    if (!redraw && shown >= 0) {
        /* A pointer-only pass: no frame, and nothing outside the old and new
         * sprite rectangles changed on screen. */
        fx_rect now = d->ptr.save[d->shown].r;
        int outside = 0, changed = 0;
        for (int32_t y = 0; y < scr.h; y++)
            for (int32_t x = 0; x < scr.w; x++) {
                if (fx_surface_get_native(&scr, x, y) == fx_surface_get_native(&snap.surf, x, y))
                    continue;
                changed++;
                int in_old = x >= old.x0 && x < old.x1 && y >= old.y0 && y < old.y1;
                int in_new = x >= now.x0 && x < now.x1 && y >= now.y0 && y < now.y1;
                outside += !in_old && !in_new;
            }
        fx_display_get_info(d, &after);
        FX_CHECK_MSG(outside == 0, "%s: %d pixels changed outside the sprite rectangles", where,
                     outside);
        FX_CHECK_MSG(!changed || after.pointer_updates == before.pointer_updates + 1,
                     "%s: the move was not one pointer update", where);
        /* Shown as the old and new rectangles of the buffer on screen. */
        if (changed) {
            FX_CHECK_MSG(shows.calls == calls + 1 && shows.buf == d->shown, "%s: %d show calls",
                         where, shows.calls - calls);
            FX_CHECK_MSG(shows.n <= 2 && shown_covers(old) && shown_covers(now),
                         "%s: damage misses a sprite rectangle", where);
            int64_t area = 0, want = 0;
            for (int i = 0; i < shows.n; i++)
                area += (int64_t)(shows.r[i].x1 - shows.r[i].x0) * (shows.r[i].y1 - shows.r[i].y0);
            want = (int64_t)(old.x1 - old.x0) * (old.y1 - old.y0) +
                   (int64_t)(now.x1 - now.x0) * (now.y1 - now.y0);
            FX_CHECK_MSG(area <= want, "%s: damage %lld pixels for sprites of %lld", where,
                         (long long)area, (long long)want);
        }
    }
    if (a->redisplay && a->cb.display) {
        /* On screen before the frame (after this pass's move). */
        fx_rect before_frame = d->shown >= 0 ? d->ptr.save[d->shown].r : (fx_rect){0, 0, 0, 0};
        a->redisplay = 0;
        a->cb.display(a->user);
        /* The frame's damage names where the pointer was and is. */
        fx_rect now = d->ptr.save[d->shown].r;
        FX_CHECK_MSG(shown_covers(before_frame) && shown_covers(now),
                     "%s: the frame's damage misses a pointer rectangle", where);
    }
    FX_CHECK_MSG(p->frames == frames + redraw, "%s: frames %d -> %d", where, frames, p->frames);
    fx_memfb_destroy(&snap);
}

static void replay(const char *stream, const config *cf)
{
    char path[256], line[256];
    snprintf(path, sizeof path, GOLDEN_DIR "/%s.txt", stream);
    FILE *f = fopen(path, "r");
    FX_CHECK_MSG(f != NULL, "cannot open %s", path);
    if (!f)
        return;
    prog p;
    memset(&p, 0, sizeof p);
    void *second = NULL;
    fx_evdev *dev[4] = {0};
    int rot = 0, lineno = 0;
    while (fgets(line, sizeof line, f)) {
        lineno++;
        char *w[12];
        int n = 0;
        char *hash = strchr(line, '#');
        if (hash)
            *hash = 0;
        for (char *t = strtok(line, " \t\r\n"); t && n < 12; t = strtok(NULL, " \t\r\n"))
            w[n++] = t;
        if (n == 0)
            continue;
        char where[200];
        snprintf(where, sizeof where, "%s:%d (%s %s%s)", stream, lineno,
                 fx_format_get(cf->format)->name,
                 cf->present == FX_PRESENT_SHADOW ? "shadow" : "direct",
                 cf->buffers == 2 ? ", 2 buffers" : "");
        if (!strcmp(w[0], "screen") && n >= 4) {
            rot = atoi(w[3]);
            p.app = open_app(atoi(w[1]), atoi(w[2]), rot, cf, FX_POINTER_AUTO, &second);
            FX_CHECK_MSG(p.app != NULL, "%s: cannot open the app", where);
            if (!p.app)
                break;
            int32_t lw, lh;
            fx_app_size(p.app, &lw, &lh);
            fx_memfb_create(&p.ref, lw, lh, cf->format);
            fx_callbacks cb = {.display = on_display, .mouse = on_mouse};
            fx_app_set_callbacks(p.app, &cb, &p);
            p.app->redisplay = 1; /* the loop's first frame */
        } else if (!strcmp(w[0], "device") && n >= 3 && p.app) {
            int N = atoi(w[1]) & 3;
            dev[N] = calloc(1, sizeof *dev[N]);
            dev[N]->fd = -1;
            fx_input_dev_init(&dev[N]->st, class_of(w[2]));
            if (n >= 8 && !strcmp(w[3], "abs")) {
                dev[N]->st.abs_min[0] = atoi(w[4]);
                dev[N]->st.abs_max[0] = atoi(w[5]);
                dev[N]->st.abs_min[1] = atoi(w[6]);
                dev[N]->st.abs_max[1] = atoi(w[7]);
            }
            p.app->ev.devs[p.app->ev.ndevs++] = dev[N];
        } else if ((!strcmp(w[0], "ev") && n >= 5) || (!strcmp(w[0], "syn") && n >= 2)) {
            int N = atoi(w[1]) & 3;
            fx_raw_event ev = {0, 0, 0, 0};
            if (w[0][0] == 'e') {
                ev.type = (uint16_t)value_of(w[2]);
                ev.code = (uint16_t)value_of(w[3]);
                ev.value = value_of(w[4]);
            }
            if (dev[N])
                fx_app_feed(p.app, &dev[N]->st, &ev);
        } else if (!strcmp(w[0], "visible") && n >= 2) {
            fx_app_pointer_sync(p.app);
            FX_CHECK_MSG(fx_app_pointer_visible(p.app) == atoi(w[1]), "%s: visible %d", where,
                         fx_app_pointer_visible(p.app));
        } else if (!strcmp(w[0], "frame") && n >= 2 && p.app) {
            step(&p, where);
            fx_display *d = fx_app_display(p.app);
            fx_surface scr = fx_display_screen(d);
            fx_memfb want;
            expected_screen(&want, &p, d, rot);
            FX_CHECK_MSG(surf_equal(&scr, &want.surf), "%s: screen is not picture + pointer", where);
            fx_memfb_destroy(&want);
            if (cf->goldens && strcmp(w[1], "-")) {
                char name[128];
                snprintf(name, sizeof name, "%s-%s", stream, w[1]);
                golden(name, &scr);
            }
            /* The program reads back exactly its own drawing. With one direct
             * buffer that takes the pointer off the screen until the next
             * present, so there it is checked in the display callback only. */
            if (!(cf->present == FX_PRESENT_DIRECT && cf->buffers == 1)) {
                fx_surface s = fx_app_surface(p.app);
                FX_CHECK_MSG(surf_equal(&s, &p.ref.surf), "%s: the program's surface has changed",
                             where);
            }
            FX_CHECK_MSG(p.dirty_reads == 0, "%s: %d frames read back a changed surface", where,
                         p.dirty_reads);
        } else {
            FX_CHECK_MSG(0, "%s: cannot parse", where);
        }
    }
    fclose(f);
    if (p.app)
        close_app(p.app, second);
    fx_memfb_destroy(&p.ref);
}

static const config configs[] = {
    {FX_FMT_XRGB8888, FX_PRESENT_DIRECT, 1, 1}, {FX_FMT_XRGB8888, FX_PRESENT_DIRECT, 2, 1},
    {FX_FMT_XRGB8888, FX_PRESENT_SHADOW, 1, 1}, {FX_FMT_XRGB8888, FX_PRESENT_SHADOW, 2, 1},
    {FX_FMT_RGB565, FX_PRESENT_DIRECT, 2, 0},   {FX_FMT_RGB888, FX_PRESENT_SHADOW, 2, 0},
    {FX_FMT_GRAY8, FX_PRESENT_DIRECT, 1, 0},    {FX_FMT_MONO1, FX_PRESENT_SHADOW, 1, 0},
};

FX_TEST(pointer_mouse_stream_frames)
{
    for (unsigned i = 0; i < sizeof configs / sizeof configs[0]; i++)
        replay("mouse", &configs[i]);
}

FX_TEST(pointer_rotated_stream_frames)
{
    /* Rotation always presents through the shadow. */
    for (unsigned i = 0; i < sizeof configs / sizeof configs[0]; i++)
        if (configs[i].present == FX_PRESENT_SHADOW)
            replay("mouse-rot90", &configs[i]);
}

/* ---- policy ---- */

static fx_evdev *add_dev(fx_app *a, unsigned cls)
{
    fx_evdev *e = calloc(1, sizeof *e);
    e->fd = -1;
    fx_input_dev_init(&e->st, cls);
    a->ev.devs[a->ev.ndevs++] = e;
    return e;
}

FX_TEST(pointer_policy_auto_env_and_api)
{
    const config cf = {FX_FMT_XRGB8888, FX_PRESENT_SHADOW, 1, 0};
    void *second;
    fx_app *a = open_app(64, 48, 0, &cf, FX_POINTER_AUTO, &second);
    FX_CHECK(a != NULL);
    if (!a)
        return;
    FX_CHECK_EQ(fx_app_pointer_visible(a), 0); /* no devices */
    add_dev(a, FX_DEV_TOUCH | FX_DEV_MT);
    FX_CHECK_EQ(fx_app_pointer_visible(a), 0); /* touch only */
    add_dev(a, FX_DEV_KEYBOARD);
    FX_CHECK_EQ(fx_app_pointer_visible(a), 0);
    fx_evdev *tab = add_dev(a, FX_DEV_TABLET);
    FX_CHECK_EQ(fx_app_pointer_visible(a), 1);
    tab->st.cls = FX_DEV_MOUSE;
    FX_CHECK_EQ(fx_app_pointer_visible(a), 1);
    fx_app_set_pointer(a, FX_POINTER_OFF);
    FX_CHECK_EQ(fx_app_pointer_visible(a), 0);
    FX_CHECK_EQ(fx_app_display(a)->ptr.visible, 0);
    fx_app_set_pointer(a, FX_POINTER_ON);
    FX_CHECK_EQ(fx_app_display(a)->ptr.visible, 1);
    close_app(a, second);

    /* FIXEL_POINTER reaches the app through fx_app_options_from_env. */
    fx_app_options eo;
    setenv("FIXEL_POINTER", "on", 1);
    fx_app_options_init(&eo);
    FX_CHECK_EQ(fx_app_options_from_env(&eo), 0);
    FX_CHECK_EQ(eo.pointer, FX_POINTER_ON);
    a = open_app(64, 48, 0, &cf, eo.pointer, &second);
    FX_CHECK_EQ(fx_app_pointer_visible(a), 1); /* on without any device */
    close_app(a, second);
    setenv("FIXEL_POINTER", "off", 1);
    fx_app_options_init(&eo);
    FX_CHECK_EQ(fx_app_options_from_env(&eo), 0);
    FX_CHECK_EQ(eo.pointer, FX_POINTER_OFF);
    a = open_app(64, 48, 0, &cf, eo.pointer, &second);
    add_dev(a, FX_DEV_MOUSE);
    FX_CHECK_EQ(fx_app_pointer_visible(a), 0);
    close_app(a, second);
    /* The program's explicit choice wins over the environment. */
    fx_app_options_init(&eo);
    eo.pointer = FX_POINTER_ON;
    FX_CHECK_EQ(fx_app_options_from_env(&eo), 0);
    FX_CHECK_EQ(eo.pointer, FX_POINTER_ON);
    /* ... and the library itself does not look (AUTO stays the rule). */
    a = open_app(64, 48, 0, &cf, FX_POINTER_AUTO, &second);
    FX_CHECK_EQ(fx_app_pointer_visible(a), 0);
    close_app(a, second);
    /* an unknown value is logged and ignored */
    setenv("FIXEL_POINTER", "maybe", 1);
    fx_app_options_init(&eo);
    eo.display.log = quiet;
    FX_CHECK_EQ(fx_app_options_from_env(&eo), 0);
    FX_CHECK_EQ(eo.pointer, FX_POINTER_AUTO);
    unsetenv("FIXEL_POINTER");
}

FX_TEST(pointer_custom_sprite)
{
    const config cf = {FX_FMT_XRGB8888, FX_PRESENT_SHADOW, 1, 0};
    void *second;
    fx_app *a = open_app(40, 30, 0, &cf, FX_POINTER_ON, &second);
    FX_CHECK(a != NULL);
    if (!a)
        return;
    fx_display *d = fx_app_display(a);
    fx_surface s = fx_app_surface(a);
    fx_surface_clear(&s, 0xFF000000u);
    fx_app_present(a, NULL, 0);
    /* A 3x3 cross with its hotspot in the middle, given in a buffer that is
     * gone afterwards: the display keeps its own copy. */
    uint32_t *px = malloc(9 * sizeof *px);
    const uint32_t img[9] = {0, 0xFFFF0000u, 0, 0xFFFF0000u, 0xFF00FF00u, 0xFFFF0000u,
                             0, 0xFFFF0000u, 0};
    memcpy(px, img, sizeof img);
    fx_sprite cross = {px, 3, 3, 1, 1};
    FX_CHECK_EQ(fx_app_set_pointer_sprite(a, &cross), 0);
    memset(px, 0, sizeof img);
    free(px);
    fx_surface scr = fx_display_screen(d);
    /* The pointer starts at the centre (20, 15). */
    FX_CHECK_EQ_HEX(fx_surface_get(&scr, 20, 15), 0xFF00FF00u);
    FX_CHECK_EQ_HEX(fx_surface_get(&scr, 19, 15), 0xFFFF0000u);
    FX_CHECK_EQ_HEX(fx_surface_get(&scr, 19, 14), 0xFF000000u);
    FX_CHECK_EQ_HEX(fx_surface_get(&scr, 21, 16), 0xFF000000u);
    fx_sprite bad = {img, 3, 3, 3, 0};
    FX_CHECK_EQ(fx_app_set_pointer_sprite(a, &bad), -FX_EINVAL);
    FX_CHECK_EQ(fx_app_set_pointer_sprite(a, NULL), 0); /* back to the arrow */
    FX_CHECK_EQ_HEX(fx_surface_get(&scr, 20, 15), 0xFF000000u); /* arrow tip: black */
    FX_CHECK_EQ_HEX(fx_surface_get(&scr, 21, 17), 0xFFFFFFFFu); /* white body */
    FX_CHECK_EQ_HEX(fx_surface_get(&scr, 19, 15), 0xFF000000u); /* no cross left */
    close_app(a, second);
}

/* One direct buffer: the program's surface is the scanout itself. Taking it
 * takes the pointer off; a move meanwhile waits for the present, which
 * reports both the rectangle the pointer left and the one it entered even
 * when the program's own damage is elsewhere. */
FX_TEST(pointer_single_direct_buffer_defers_and_reports_damage)
{
    const config cf = {FX_FMT_XRGB8888, FX_PRESENT_DIRECT, 1, 0};
    void *second;
    fx_app *a = open_app(80, 60, 0, &cf, FX_POINTER_OFF, &second);
    FX_CHECK(a != NULL);
    if (!a)
        return;
    fx_display *d = fx_app_display(a);
    fx_surface s = fx_display_surface(d);
    fx_surface_clear(&s, 0xFF204060u);
    FX_CHECK_EQ(fx_display_present(d, NULL, 0), 0);
    int calls = shows.calls;
    fx_display_set_pointer(d, 1, 20, 20);
    fx_rect at20 = fx_sprite_phys_rect(&s, 0, fx_sprite_arrow(), 20, 20);
    FX_CHECK_EQ(shows.calls, calls + 1);
    FX_CHECK(shown_covers(at20));
    FX_CHECK_EQ_HEX(fx_surface_get(&s, 20, 20), 0xFF000000u);

    s = fx_display_surface(d); /* the program draws: pointer out */
    FX_CHECK_EQ_HEX(fx_surface_get(&s, 20, 20), 0xFF204060u);
    calls = shows.calls;
    fx_display_set_pointer(d, 1, 50, 30);
    FX_CHECK_EQ(shows.calls, calls); /* deferred: nothing drawn into the program's surface */
    FX_CHECK_EQ_HEX(fx_surface_get(&s, 50, 30), 0xFF204060u);
    fx_rect mine = {0, 50, 10, 60};
    fx_surface_fill(&s, mine, 0xFFFFFFFFu);
    FX_CHECK_EQ(fx_display_present(d, &mine, 1), 0);
    fx_rect at50 = fx_sprite_phys_rect(&s, 0, fx_sprite_arrow(), 50, 30);
    FX_CHECK(shown_covers(mine));
    FX_CHECK(shown_covers(at20)); /* where it was taken out */
    FX_CHECK(shown_covers(at50)); /* where it is now */
    FX_CHECK_EQ_HEX(fx_surface_get(&s, 20, 20), 0xFF204060u);
    FX_CHECK_EQ_HEX(fx_surface_get(&s, 50, 30), 0xFF000000u);
    close_app(a, second);
}
