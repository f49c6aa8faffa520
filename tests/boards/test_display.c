/* SPDX-License-Identifier: MIT */
/* The pure logic of the display backends (boards/display/present.c and
 * boards/linux/display/formats.c) on fake
 * device state: pixel format from fbdev bitfields, mode strings, damage
 * merging, software rotation in every format; and the presentation path of
 * the display object on the memory backend (shadow, rotation, damage). */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../../boards/display/display_int.h"
#include "fixel/env.h"
#include "fixel/scanout.h" /* public: fx_fb_format_from_bitfields, fx_copy_rotated are tested here */
#include "fixel/display.h"
#include "fixel/error.h"
#include "fixel/surface.h"
#include "fx_test.h"

static const fx_format all_formats[] = {FX_FMT_XRGB8888, FX_FMT_ARGB8888, FX_FMT_XBGR8888,
                                        FX_FMT_RGB565,   FX_FMT_BGR565,   FX_FMT_RGB888,
                                        FX_FMT_BGR888,   FX_FMT_GRAY8,    FX_FMT_MONO1};
static const int rotations[] = {0, 90, 180, 270};

/* ---- fbdev bitfields ---------------------------------------------------- */

struct fb_case {
    fx_fb_bitfields bf;
    fx_format want;
};

/* Layouts as real drivers report them (bochs/virtio/vc4 32 bpp, SPI panels
 * 16 bpp, simplefb 24 bpp, e-paper gray, SSD1306 mono). */
static const struct fb_case fb_cases[] = {
    {{32, 0, 16, 8, 8, 8, 0, 8, 0, 0, 0}, FX_FMT_XRGB8888},
    {{32, 0, 16, 8, 8, 8, 0, 8, 24, 8, 0}, FX_FMT_ARGB8888},
    {{32, 0, 0, 8, 8, 8, 16, 8, 0, 0, 0}, FX_FMT_XBGR8888},
    {{24, 0, 16, 8, 8, 8, 0, 8, 0, 0, 0}, FX_FMT_RGB888},
    {{24, 0, 0, 8, 8, 8, 16, 8, 0, 0, 0}, FX_FMT_BGR888},
    {{16, 0, 11, 5, 5, 6, 0, 5, 0, 0, 0}, FX_FMT_RGB565},
    {{16, 0, 0, 5, 5, 6, 11, 5, 0, 0, 0}, FX_FMT_BGR565},
    {{8, 1, 0, 8, 0, 8, 0, 8, 0, 0, 0}, FX_FMT_GRAY8},
    {{1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 0}, FX_FMT_MONO1},
    /* refused: palette, inverted mono, RGB555, odd 32-bit orders, 12 bpp */
    {{8, 0, 0, 8, 0, 8, 0, 8, 0, 0, 0}, FX_FMT_COUNT},
    {{1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1}, FX_FMT_COUNT},
    {{16, 0, 10, 5, 5, 5, 0, 5, 0, 0, 0}, FX_FMT_COUNT},
    {{32, 0, 24, 8, 16, 8, 8, 8, 0, 0, 0}, FX_FMT_COUNT},
    {{32, 1, 16, 8, 8, 8, 0, 8, 0, 0, 0}, FX_FMT_COUNT},
    {{12, 0, 8, 4, 4, 4, 0, 4, 0, 0, 0}, FX_FMT_COUNT},
};

FX_TEST(fbdev_bitfields_map_to_formats)
{
    for (size_t i = 0; i < sizeof fb_cases / sizeof fb_cases[0]; i++)
        FX_CHECK_MSG(fx_fb_format_from_bitfields(&fb_cases[i].bf) == fb_cases[i].want,
                     "case %zu: got %d want %d", i, fx_fb_format_from_bitfields(&fb_cases[i].bf),
                     fb_cases[i].want);
}

static uint32_t field_mask(uint32_t off, uint32_t len)
{
    return ((len >= 32 ? 0u : 1u << len) - 1u) << off;
}

FX_TEST(fbdev_format_packs_channels_where_the_bitfields_say)
{
    /* Independent of the table above: the chosen format's pack rule must put
     * pure red, green and blue exactly into the fields the driver reported. */
    for (size_t i = 0; i < sizeof fb_cases / sizeof fb_cases[0]; i++) {
        const fx_fb_bitfields *b = &fb_cases[i].bf;
        fx_format f = fx_fb_format_from_bitfields(b);
        if (f == FX_FMT_COUNT || b->bits_per_pixel < 16)
            continue;
        FX_CHECK_EQ_HEX(fx_pack(f, 0xFFFF0000) & ~field_mask(b->transp_offset, b->transp_length),
                        field_mask(b->red_offset, b->red_length));
        FX_CHECK_EQ_HEX(fx_pack(f, 0xFF00FF00) & ~field_mask(b->transp_offset, b->transp_length),
                        field_mask(b->green_offset, b->green_length));
        FX_CHECK_EQ_HEX(fx_pack(f, 0xFF0000FF) & ~field_mask(b->transp_offset, b->transp_length),
                        field_mask(b->blue_offset, b->blue_length));
        FX_CHECK_EQ(fx_format_get(f)->bits_per_pixel, b->bits_per_pixel);
    }
}

/* ---- mode strings -------------------------------------------------------- */

FX_TEST(mode_strings_parse_or_are_refused)
{
    int32_t w = -1, h = -1, hz = -1;
    FX_CHECK_EQ(fx_mode_parse("800x480", &w, &h, &hz), 0);
    FX_CHECK(w == 800 && h == 480 && hz == 0);
    FX_CHECK_EQ(fx_mode_parse("1920X1080@60", &w, &h, &hz), 0);
    FX_CHECK(w == 1920 && h == 1080 && hz == 60);
    FX_CHECK_EQ(fx_mode_parse("320x240@144", &w, &h, &hz), 0);
    FX_CHECK(w == 320 && h == 240 && hz == 144);

    static const char *bad[] = {"", "x480", "800x", "800x480@", "800x480@0", "800*480", "0x480",
                                "800x0", "800x480 ", " 800x480", "-1x2", "9999999x1", "80a0x480",
                                "800x480@60Hz", "800x480x2"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        w = h = hz = 7;
        FX_CHECK_MSG(fx_mode_parse(bad[i], &w, &h, &hz) == -FX_EINVAL, "'%s' accepted", bad[i]);
        FX_CHECK_MSG(w == 7 && h == 7 && hz == 7, "'%s' wrote outputs", bad[i]);
    }
    FX_CHECK_EQ(fx_mode_parse(NULL, &w, &h, &hz), -FX_EINVAL);
}

/* ---- damage -------------------------------------------------------------- */

static fx_rect R(int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
    fx_rect r = {x0, y0, x1, y1};
    return r;
}

FX_TEST(damage_merges_overlaps_and_free_neighbours_only)
{
    fx_damage d;
    fx_rect b = R(0, 0, 100, 100);
    fx_damage_reset(&d);
    fx_damage_add(&d, R(10, 10, 20, 20), b);
    fx_damage_add(&d, R(15, 15, 30, 25), b); /* overlaps: one union */
    FX_CHECK_EQ(d.n, 1);
    FX_CHECK(d.r[0].x0 == 10 && d.r[0].y0 == 10 && d.r[0].x1 == 30 && d.r[0].y1 == 25);
    fx_damage_add(&d, R(30, 10, 40, 25), b); /* touching, same rows: free to join */
    FX_CHECK_EQ(d.n, 1);
    FX_CHECK_EQ(d.r[0].x1, 40);
    fx_damage_add(&d, R(80, 80, 90, 90), b); /* far apart: kept separate */
    FX_CHECK_EQ(d.n, 2);
    FX_CHECK_EQ(fx_damage_area(&d), 30 * 15 + 100);
    fx_damage_add(&d, R(50, 50, 50, 60), b); /* empty */
    fx_damage_add(&d, R(-20, -20, -1, -1), b); /* outside */
    FX_CHECK_EQ(d.n, 2);
    fx_damage_add(&d, R(95, -5, 120, 3), b); /* clipped to the bounds */
    FX_CHECK_EQ(d.n, 3);
    FX_CHECK(d.r[2].x0 == 95 && d.r[2].y0 == 0 && d.r[2].x1 == 100 && d.r[2].y1 == 3);
}

FX_TEST(damage_list_covers_everything_added_without_overlap)
{
    enum { W = 64, H = 48 };
    static uint8_t want[H][W];
    uint32_t seed = 0x1234567u;
    fx_rect b = R(0, 0, W, H);
    for (int round = 0; round < 300; round++) {
        fx_damage d;
        fx_damage_reset(&d);
        memset(want, 0, sizeof want);
        int n = 1 + (int)(fx_test_rand(&seed) % 30);
        for (int k = 0; k < n; k++) {
            int32_t x0 = (int32_t)(fx_test_rand(&seed) % (W + 20)) - 10;
            int32_t y0 = (int32_t)(fx_test_rand(&seed) % (H + 20)) - 10;
            fx_rect r = R(x0, y0, x0 + (int32_t)(fx_test_rand(&seed) % 20),
                          y0 + (int32_t)(fx_test_rand(&seed) % 20));
            fx_damage_add(&d, r, b);
            for (int32_t y = r.y0; y < r.y1; y++)
                for (int32_t x = r.x0; x < r.x1; x++)
                    if (x >= 0 && y >= 0 && x < W && y < H)
                        want[y][x] = 1;
        }
        FX_CHECK(d.n >= 0 && d.n <= FX_DAMAGE_MAX);
        int64_t covered = 0;
        for (int i = 0; i < d.n; i++) {
            FX_CHECK(!fx_rect_empty(d.r[i]));
            FX_CHECK(d.r[i].x0 >= 0 && d.r[i].y0 >= 0 && d.r[i].x1 <= W && d.r[i].y1 <= H);
            for (int j = i + 1; j < d.n; j++)
                FX_CHECK_MSG(fx_rect_empty(fx_rect_intersect(d.r[i], d.r[j])),
                             "round %d: rects %d and %d overlap", round, i, j);
        }
        for (int32_t y = 0; y < H; y++)
            for (int32_t x = 0; x < W; x++) {
                int in = 0;
                for (int i = 0; i < d.n; i++)
                    in |= x >= d.r[i].x0 && x < d.r[i].x1 && y >= d.r[i].y0 && y < d.r[i].y1;
                covered += in;
                if (want[y][x] && !in) {
                    FX_CHECK_MSG(0, "round %d: pixel (%d,%d) lost", round, x, y);
                    return;
                }
            }
        /* disjoint rectangles: their areas add up to what they cover */
        FX_CHECK_EQ(fx_damage_area(&d), covered);
        if (fx_test_failed())
            return;
    }
}

/* ---- rotation ------------------------------------------------------------ */

/* Where logical pixel (x, y) lands, written out independently of present.c. */
static void land(int rot, int32_t x, int32_t y, int32_t W, int32_t H, int32_t *px, int32_t *py)
{
    switch (rot) {
    case 90: *px = W - 1 - y; *py = x; break;
    case 180: *px = W - 1 - x; *py = H - 1 - y; break;
    case 270: *px = y; *py = H - 1 - x; break;
    default: *px = x; *py = y; break;
    }
}

static uint32_t native_mask(fx_format f)
{
    int bpp = fx_format_get(f)->bits_per_pixel;
    return bpp == 32 ? 0xFFFFFFFFu : (1u << bpp) - 1u;
}

/* A surface with padded stride (and a bit offset for MONO1) full of random
 * native values. */
static fx_surface make_surface(fx_format f, int32_t w, int32_t h, uint32_t *seed, int fill, void **mem)
{
    int32_t stride = ((fx_format_min_stride(f, w + 3) + 3) & ~3) + 8;
    *mem = calloc((size_t)h, (size_t)stride);
    fx_surface s;
    memset(&s, 0, sizeof s);
    FX_CHECK_EQ(fx_surface_init(&s, *mem, w, h, stride, f), 0);
    if (f == FX_FMT_MONO1)
        s.bit_offset = 3;
    for (int32_t y = 0; y < h; y++)
        for (int32_t x = 0; x < w; x++)
            fx_surface_put_native(&s, x, y, fill ? fx_test_rand(seed) & native_mask(f) : 0);
    return s;
}

FX_TEST(rotated_copies_land_every_pixel_in_every_format)
{
    uint32_t seed = 99;
    /* The second size spans several of the copy's 16 x 16 tiles, with
     * partial tiles on every side of the rectangle. */
    static const struct {
        int32_t lw, lh;
        fx_rect r;
    } sizes[] = {{13, 7, {2, 1, 11, 5}}, {53, 41, {3, 2, 50, 39}}};
    for (size_t n = 0; n < sizeof all_formats / sizeof all_formats[0] * 2; n++) {
        size_t fi = n / 2, si = n % 2;
        const int32_t lw = sizes[si].lw, lh = sizes[si].lh;
        fx_format f = all_formats[fi];
        for (size_t ri = 0; ri < 4; ri++) {
            int rot = rotations[ri];
            int32_t pw, ph;
            fx_rotated_size(rot, lw, lh, &pw, &ph);
            FX_CHECK_EQ(pw, rot % 180 ? lh : lw);
            void *sm, *dm;
            fx_surface src = make_surface(f, lw, lh, &seed, 1, &sm);
            fx_surface dst = make_surface(f, pw, ph, &seed, 1, &dm);
            /* remember the destination to prove pixels outside r are untouched */
            uint32_t *old = malloc(sizeof(uint32_t) * (size_t)(pw * ph));
            for (int32_t y = 0; y < ph; y++)
                for (int32_t x = 0; x < pw; x++)
                    old[y * pw + x] = fx_surface_get_native(&dst, x, y);

            fx_rect r = sizes[si].r;
            fx_copy_rotated(&dst, &src, r, rot);
            fx_rect pr = fx_rect_rotate(r, rot, pw, ph);
            int64_t changed_area = 0;
            for (int32_t y = 0; y < lh; y++)
                for (int32_t x = 0; x < lw; x++) {
                    int32_t px, py;
                    land(rot, x, y, pw, ph, &px, &py);
                    int inside = x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1;
                    int in_pr = px >= pr.x0 && px < pr.x1 && py >= pr.y0 && py < pr.y1;
                    FX_CHECK_MSG(inside == in_pr, "%s rot %d: rect mapping disagrees at (%d,%d)",
                                 fx_format_get(f)->name, rot, x, y);
                    uint32_t got = fx_surface_get_native(&dst, px, py);
                    uint32_t want = inside ? fx_surface_get_native(&src, x, y) : old[py * pw + px];
                    changed_area += inside;
                    if (got != want) {
                        FX_CHECK_MSG(0, "%s rot %d: logical (%d,%d) -> (%d,%d) got %x want %x",
                                     fx_format_get(f)->name, rot, x, y, px, py, got, want);
                        x = lw, y = lh;
                    }
                }
            FX_CHECK_EQ(changed_area, (int64_t)(pr.x1 - pr.x0) * (pr.y1 - pr.y0));
            free(old);
            free(sm);
            free(dm);
        }
    }
}

FX_TEST(rotating_by_90_then_270_is_the_identity)
{
    uint32_t seed = 7;
    for (size_t fi = 0; fi < sizeof all_formats / sizeof all_formats[0]; fi++) {
        fx_format f = all_formats[fi];
        void *am, *bm, *cm;
        fx_surface a = make_surface(f, 17, 9, &seed, 1, &am);
        fx_surface b = make_surface(f, 9, 17, &seed, 0, &bm);
        fx_surface c = make_surface(f, 17, 9, &seed, 0, &cm);
        fx_copy_rotated(&b, &a, fx_surface_rect(&a), 90);
        fx_copy_rotated(&c, &b, fx_surface_rect(&b), 270);
        for (int32_t y = 0; y < 9; y++)
            for (int32_t x = 0; x < 17; x++)
                FX_CHECK_MSG(fx_surface_get_native(&a, x, y) == fx_surface_get_native(&c, x, y),
                             "%s (%d,%d)", fx_format_get(f)->name, x, y);
        free(am);
        free(bm);
        free(cm);
    }
}

/* ---- the display object on the memory backend -------------------------- */

static char last_log[512];
static int log_lines;

static void test_log(fx_log_priority p, void *user, const char *fmt, va_list ap)
{
    (void)p;
    *(int *)user += 1;
    log_lines++;
    vsnprintf(last_log, sizeof last_log, fmt, ap);
}

FX_TEST(memory_display_presents_only_damage_rotated)
{
    for (size_t ri = 0; ri < 4; ri++) {
        int rot = rotations[ri], calls = 0;
        fx_display_options o;
        fx_display_options_init(&o);
        o.backend = FX_BACKEND_MEMORY;
        o.present = FX_PRESENT_SHADOW;
        o.rotation = rot;
        o.memory_w = 40;
        o.memory_h = 24;
        o.log = test_log;
        o.log_user = &calls;
        o.log_priority = FX_LOG_INFO;
        fx_display *d;
        FX_CHECK_EQ(fx_display_open(&d, &o), 0);
        if (!d)
            return;
        FX_CHECK_EQ(calls, 1); /* the one line saying what was chosen and why */
        FX_CHECK(strstr(last_log, "memory") && strstr(last_log, "requested by the program"));
        FX_CHECK_EQ(fx_display_fd(d), -1);
        fx_surface s = fx_display_surface(d);
        FX_CHECK_EQ(s.w, rot % 180 ? 24 : 40);
        FX_CHECK_EQ(s.h, rot % 180 ? 40 : 24);

        fx_surface_clear(&s, 0xFF102030);
        FX_CHECK_EQ(fx_display_present(d, NULL, 0), 0);
        const fx_surface *scan = &d->scan[0];
        for (int32_t y = 0; y < 24; y++)
            for (int32_t x = 0; x < 40; x++)
                if (fx_surface_get(scan, x, y) != 0xFF102030) {
                    FX_CHECK_MSG(0, "rot %d: full present missed (%d,%d)", rot, x, y);
                    y = 24;
                    break;
                }
        /* Draw everywhere, declare one rectangle: only it may reach the screen. */
        fx_surface_clear(&s, 0xFFFFFFFF);
        fx_rect dmg = R(3, 5, 9, 8);
        FX_CHECK_EQ(fx_display_present(d, &dmg, 1), 0);
        fx_rect pr = fx_rect_rotate(dmg, rot, 40, 24);
        int64_t white = 0;
        for (int32_t y = 0; y < 24; y++)
            for (int32_t x = 0; x < 40; x++) {
                int in = x >= pr.x0 && x < pr.x1 && y >= pr.y0 && y < pr.y1;
                fx_color c = fx_surface_get(scan, x, y);
                white += c == 0xFFFFFFFF;
                FX_CHECK_MSG(c == (in ? 0xFFFFFFFFu : 0xFF102030u), "rot %d (%d,%d) %08x", rot, x, y, c);
                if (fx_test_failed())
                    break;
            }
        FX_CHECK_EQ(white, 6 * 3);
        fx_display_info info;
        fx_display_get_info(d, &info);
        FX_CHECK(info.backend == FX_BACKEND_MEMORY && info.present == FX_PRESENT_SHADOW);
        FX_CHECK(info.width == 40 && info.height == 24 && info.rotation == rot);
        fx_display_close(d);
    }
}

FX_TEST(display_options_from_env_fills_unset_fields)
{
    static const char *vars[] = {"FIXEL_PRESENT", "FIXEL_DRM_DEVICE", "FIXEL_FB_DEVICE", "FIXEL_CONNECTOR",
                                 "FIXEL_MODE", "FIXEL_DRM_FORMAT", "FIXEL_SW_ROTATION", "FIXEL_VT_SWITCH",
                                 "FIXEL_LOG"};
    static const char *vals[] = {"shadow", "/dev/dri/card7", "/dev/fb7", "DSI-1", "800x480",
                                 "rgb565", "1", "deny", "none"};
    for (int i = 0; i < 9; i++)
        setenv(vars[i], vals[i], 1);
    fx_display_options o;
    fx_display_options_init(&o);
    FX_CHECK_EQ(fx_display_options_from_env(&o), 0);
    FX_CHECK(o.present == FX_PRESENT_SHADOW && !strcmp(o.drm_device, "/dev/dri/card7") &&
             !strcmp(o.fb_device, "/dev/fb7") && !strcmp(o.connector, "DSI-1") && !strcmp(o.mode, "800x480"));
    /* FIXEL_DRM_FORMAT is for DRM only: the memory backend keeps format */
    FX_CHECK(o.format == FX_FMT_COUNT && o.drm_format == FX_FMT_RGB565 && o.sw_rotation == 1);
    FX_CHECK(o.vt_switch == FX_VT_SWITCH_DENY && o.log_priority < 0 && !o.device);
    /* set by the program: kept */
    fx_display_options_init(&o);
    o.present = FX_PRESENT_DIRECT;
    o.connector = "HDMI-A-1";
    o.format = FX_FMT_XRGB8888;
    o.log_priority = FX_LOG_DEBUG;
    FX_CHECK_EQ(fx_display_options_from_env(&o), 0);
    FX_CHECK(o.present == FX_PRESENT_DIRECT && !strcmp(o.connector, "HDMI-A-1") &&
             o.drm_format == FX_FMT_COUNT && o.log_priority == FX_LOG_DEBUG);
    for (int i = 0; i < 9; i++)
        unsetenv(vars[i]);
    /* nothing set: nothing changes */
    fx_display_options a, b;
    fx_display_options_init(&a);
    fx_display_options_init(&b);
    FX_CHECK_EQ(fx_display_options_from_env(&a), 0);
    FX_CHECK(memcmp(&a, &b, sizeof a) == 0);
}

FX_TEST(display_backend_choice_from_environment_and_bad_options)
{
    int calls = 0;
    fx_display_options o;
    fx_display *d = NULL;
    fx_display_options_init(&o);
    o.log = test_log;
    o.log_user = &calls;
    o.log_priority = FX_LOG_INFO;
    o.memory_w = 8;
    o.memory_h = 8;

    /* The library never reads the environment: only from_env does. */
    setenv("FIXEL_BACKEND", "vga", 1);
    setenv("FIXEL_ROTATION", "180", 1);
    fx_display_options p = o;
    p.backend = FX_BACKEND_MEMORY;
    FX_CHECK_EQ(fx_display_open(&d, &p), 0);
    if (d) {
        fx_display_info info;
        fx_display_get_info(d, &info);
        FX_CHECK(info.rotation == 0 && strstr(last_log, "requested by the program"));
    }
    fx_display_close(d);
    /* A value the program set wins over the environment, which fills the rest. */
    p.rotation = 90;
    FX_CHECK_EQ(fx_display_options_from_env(&p), 0);
    FX_CHECK(p.rotation == 90 && p.backend == FX_BACKEND_MEMORY && !p.backend_from_env);
    p = o;
    FX_CHECK_EQ(fx_display_options_from_env(&p), -FX_EINVAL);
    FX_CHECK(p.rotation == 180 && p.backend == FX_BACKEND_AUTO);
    unsetenv("FIXEL_BACKEND");
    /* Only the four angles, as whole words; anything else is named and ignored. */
    static const char *const bad_rot[] = {"xyz", "1x1", "2147483648", "-90", "45", "90 ", "0x5A"};
    for (size_t i = 0; i < sizeof bad_rot / sizeof bad_rot[0]; i++) {
        setenv("FIXEL_ROTATION", bad_rot[i], 1);
        p = o;
        last_log[0] = 0;
        FX_CHECK_EQ(fx_display_options_from_env(&p), 0);
        FX_CHECK_MSG(p.rotation == o.rotation && strstr(last_log, "FIXEL_ROTATION") &&
                         strstr(last_log, "ignored"),
                     "FIXEL_ROTATION=%s gave rotation %d, log '%s'", bad_rot[i], p.rotation, last_log);
    }
    setenv("FIXEL_ROTATION", "270", 1);
    p = o;
    FX_CHECK_EQ(fx_display_options_from_env(&p), 0);
    FX_CHECK_EQ(p.rotation, 270);
    unsetenv("FIXEL_ROTATION");
    setenv("FIXEL_BACKEND", "vga", 1);

    setenv("FIXEL_BACKEND", "memory", 1);
    FX_CHECK_EQ(fx_display_options_from_env(&o), 0);
    FX_CHECK(o.backend == FX_BACKEND_MEMORY && o.backend_from_env);
    FX_CHECK_EQ(fx_display_open(&d, &o), 0);
    FX_CHECK(d && strstr(last_log, "FIXEL_BACKEND"));
    if (d) {
        fx_display_info info;
        fx_display_get_info(d, &info);
        /* memory has one buffer: direct drawing needs no copy there */
        FX_CHECK(info.backend == FX_BACKEND_MEMORY && info.present == FX_PRESENT_DIRECT);
    }
    fx_display_close(d);

    setenv("FIXEL_BACKEND", "vga", 1);
    o.backend = FX_BACKEND_AUTO;
    o.backend_from_env = 0;
    FX_CHECK_EQ(fx_display_options_from_env(&o), -FX_EINVAL);
    FX_CHECK(o.backend == FX_BACKEND_AUTO && strstr(last_log, "drm, fbdev, memory or auto"));
    unsetenv("FIXEL_BACKEND");

    o.backend = FX_BACKEND_MEMORY;
    o.rotation = 45;
    FX_CHECK_EQ(fx_display_open(&d, &o), -FX_EINVAL);
    FX_CHECK(d == NULL && strstr(last_log, "rotation 45"));
    fx_display_close(NULL);
}

/* ---- blocking calls with a timeout ---------------------------------------- */

static int read_one(void *arg)
{
    char c;
    return (int)read(*(int *)arg, &c, 1);
}

FX_TEST(waiter_times_out_on_a_call_that_blocks_and_recovers_when_it_returns)
{
    int p[2];
    FX_CHECK_EQ(pipe(p), 0);
    fx_waiter *w;
    FX_CHECK_EQ(fx_waiter_create(&w, read_one, &p[0]), 0);
    if (!w)
        return;
    int result = -7;
    /* nothing to read: the call blocks, the caller gets control back */
    FX_CHECK_EQ(fx_waiter_run(w, 30, &result), 1);
    FX_CHECK_EQ(result, -7);
    /* still stuck: a second run waits for the same call, not a new one */
    FX_CHECK_EQ(fx_waiter_run(w, 10, &result), 1);
    FX_CHECK_EQ(write(p[1], "ab", 2), 2);
    usleep(20000); /* whether the stuck call ends before or during the run, */
    FX_CHECK_EQ(fx_waiter_run(w, 2000, &result), 0); /* it is the one collected */
    FX_CHECK_EQ(result, 1); /* the first call read 'a' */
    FX_CHECK_EQ(fx_waiter_run(w, 2000, &result), 0); /* a new call reads 'b' */
    FX_CHECK_EQ(result, 1);
    fx_waiter_destroy(w);
    close(p[0]);
    close(p[1]);
}

FX_TEST(waiter_destroyed_while_stuck_cleans_up_when_the_call_returns)
{
    static int p[2];
    FX_CHECK_EQ(pipe(p), 0);
    fx_waiter *w;
    FX_CHECK_EQ(fx_waiter_create(&w, read_one, &p[0]), 0);
    if (!w)
        return;
    FX_CHECK_EQ(fx_waiter_run(w, 20, NULL), 1);
    fx_waiter_destroy(w); /* must return at once although the call is stuck */
    FX_CHECK_EQ(write(p[1], "x", 1), 1);
    /* the orphaned thread frees the waiter; LeakSanitizer/valgrind check it */
    usleep(50000);
    close(p[0]);
    close(p[1]);
}
