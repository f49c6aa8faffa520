/* SPDX-License-Identifier: MIT */
/* The course's coordinate mode (issue #23): a course-mode context draws every
 * primitive exactly as screen mode does, mirrored top to bottom; arcs and
 * rotations agree about which way is positive in both modes; the clip trace
 * prints the notes' parameters; non-square pixels in window-to-viewport and
 * in the 3D projection. */
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/circle.h"
#include "fixel/clip.h"
#include "fixel/curve.h"
#include "fixel/error.h"
#include "fixel/fill.h"
#include "fixel/font.h"
#include "fixel/line.h"
#include "fixel/mat3d.h"
#include "fixel/render3d.h"
#include "fixel/turtle.h"
#include "fixel/scene.h"
#include "fixel/xform.h"
#include "canvas.h"
#include "fx_test.h"
#include "scenebuf.h"
#include "trace.h"

#define W 96
#define H 80

static uint32_t rng = 12345;
static int32_t rnd(int32_t lo, int32_t hi)
{
    rng = rng * 1103515245u + 12345u;
    return lo + (int32_t)((rng >> 8) % (uint32_t)(hi - lo + 1));
}

/* One random primitive with random arguments, the same ones each call for
 * the same seed. Coordinates reach beyond the surface so clipping is
 * exercised too. */
static void draw_one(const fx_ctx *c, int kind, uint32_t seed)
{
    rng = seed;
    int32_t v[8];
    for (int i = 0; i < 8; i++)
        v[i] = rnd(-30, i & 1 ? H + 30 : W + 30);
    int32_t r = rnd(0, 50), r2 = rnd(0, 40);
    fx_angle a0 = (fx_angle)rnd(0, 0xFFFFFF) << 8, a1 = (fx_angle)rnd(0, 0xFFFFFF) << 8;
    switch (kind) {
    case 0: fx_plot(c, v[0], v[1]); break;
    case 1: fx_hspan(c, v[1], v[0], v[2]); break;
    case 2: fx_fill_rect(c, v[0], v[1], r, r2); break;
    case 3: fx_rect_outline(c, v[0], v[1], r, r2); break;
    case 4: fx_line(c, v[0], v[1], v[2], v[3]); break;
    case 5: fx_circle(c, v[0], v[1], r); break;
    case 6: fx_disc(c, v[0], v[1], r); break;
    case 7: fx_arc(c, v[0], v[1], r, a0, a1); break;
    case 8: fx_pie(c, v[0], v[1], r, a0, a1); break;
    case 9: fx_ellipse(c, v[0], v[1], r, r2); break;
    case 10: fx_fill_ellipse(c, v[0], v[1], r, r2); break;
    case 11: fx_aacircle(c, v[0], v[1], r); break;
    case 12: fx_fill_tri(c, v[0], v[1], v[2], v[3], v[4], v[5]); break;
    case 13: fx_fill_poly(c, v, 4, (fx_fill_rule)(seed & 1)); break;
    case 14: fx_polygon(c, v, 4); break;
    case 15: fx_aaline(c, v[0], v[1], v[2], v[3]); break;
    case 16: fx_dda(c, v[0], v[1], v[2], v[3]); break;
    case 17: fx_bezier(c, v, 4, 64); break;
    case 18: {
        fx_ctx t = *c;
        t.line_clipper = (uint8_t)(1 + seed % 3); /* Cohen-Sutherland, Liang-Barsky, NLN */
        fx_line(&t, v[0], v[1], v[2], v[3]);
        break;
    }
    case 19: {
        fx_line_style st;
        fx_line_style_init(&st);
        st.width = 1 + (int32_t)(seed % 7);
        fx_ctx t = *c;
        t.line_style = &st;
        fx_polyline(&t, v, 4);
        break;
    }
    }
}
#define KINDS 20

static int mirrored(const fx_surface *a, const fx_surface *b)
{
    for (int y = 0; y < a->h; y++)
        for (int x = 0; x < a->w; x++)
            if (fx_surface_get_native(a, x, y) != fx_surface_get_native(b, x, a->h - 1 - y))
                return 0;
    return 1;
}

/* The property the mode is defined by, over many primitives, both pixel
 * formats of the goldens, with a clip window, exterior clipping and
 * translucent blending (which reads the pixels back). */
FX_TEST(coords_course_is_screen_mirrored)
{
    static uint32_t ma[W * H], mb[W * H];
    const fx_format fmts[2] = {FX_FMT_XRGB8888, FX_FMT_RGB565};
    int tried = 0;
    for (int f = 0; f < 2; f++)
        for (int kind = 0; kind < KINDS; kind++)
            for (uint32_t seed = 1; seed <= 40; seed++) {
                fx_surface sa, sb;
                memset(ma, 0x11, sizeof ma);
                memset(mb, 0x11, sizeof mb);
                FX_CHECK_EQ(fx_surface_init(&sa, ma, W, H, W * 4, fmts[f]), 0);
                FX_CHECK_EQ(fx_surface_init(&sb, mb, W, H, W * 4, fmts[f]), 0);
                fx_ctx a, b;
                fx_ctx_init(&a, &sa);
                fx_ctx_init(&b, &sb);
                FX_CHECK_EQ(fx_ctx_set_coords(&b, FX_COORDS_COURSE), 0);
                FX_CHECK_EQ(fx_ctx_coords(&b), FX_COORDS_COURSE);
                fx_color col = 0x80000000u | (seed * 0x9E3779u & 0xFFFFFFu);
                fx_ctx_set_color(&a, col);
                fx_ctx_set_color(&b, col);
                a.blend = b.blend = (uint8_t)(seed % 3 == 0 ? FX_BLEND_OVER : FX_BLEND_SRC);
                if (seed % 4 == 1) {
                    fx_rect r = {7, 5, 70, 61};
                    fx_ctx_set_clip(&a, r);
                    fx_ctx_set_clip(&b, r);
                }
                if (seed % 5 == 2) {
                    fx_rect e = {20, 15, 50, 40};
                    fx_ctx_exterior(&a, e);
                    fx_ctx_exterior(&b, e);
                }
                draw_one(&a, kind, seed);
                draw_one(&b, kind, seed);
                int ok = mirrored(&sa, &sb);
                FX_CHECK_MSG(ok, "primitive %d seed %u format %d: course mode is not the mirror", kind, seed, f);
                if (!ok)
                    return;
                tried++;
            }
    FX_CHECK_EQ(tried, 2 * KINDS * 40);
}

/* A mode-independent drawing really does move: the mirror is not the
 * identity (a non-symmetric line lands on other rows). */
FX_TEST(coords_course_origin_is_bottom_left)
{
    canvas cv = canvas_make(W, H);
    fx_ctx c;
    fx_ctx_init(&c, &cv.s);
    FX_CHECK_EQ(fx_ctx_set_coords(&c, FX_COORDS_COURSE), 0);
    fx_plot(&c, 0, 0);
    fx_plot(&c, 3, 10);
    FX_CHECK_EQ_HEX(cv.mem[(H - 1) * W + 0], 0xFFFFFFu);
    FX_CHECK_EQ_HEX(cv.mem[(H - 11) * W + 3], 0xFFFFFFu);
    FX_CHECK_EQ_HEX(cv.mem[0], 0u);
    /* switching keeps the clip window on the same pixels, and back again */
    fx_ctx s;
    fx_ctx_init(&s, &cv.s);
    fx_rect r = {2, 3, 12, 20};
    fx_ctx_set_clip(&s, r);
    FX_CHECK_EQ(fx_ctx_set_coords(&s, FX_COORDS_COURSE), 0);
    FX_CHECK_EQ(s.clip.y0, H - 20);
    FX_CHECK_EQ(s.clip.y1, H - 3);
    FX_CHECK_EQ(fx_ctx_set_coords(&s, FX_COORDS_COURSE), 0); /* no-op */
    FX_CHECK_EQ(s.clip.y0, H - 20);
    FX_CHECK_EQ(fx_ctx_set_coords(&s, FX_COORDS_SCREEN), 0);
    FX_CHECK(s.clip.y0 == 3 && s.clip.y1 == 20 && s.surf.pixels == cv.s.pixels && s.surf.stride == cv.s.stride);
    FX_CHECK_EQ(fx_ctx_set_coords(&s, (fx_coords)7), -FX_EINVAL);
    FX_CHECK_EQ(fx_ctx_set_coords(NULL, FX_COORDS_COURSE), -FX_EINVAL);
    fx_ctx e;
    fx_ctx_init(&e, NULL); /* an empty context switches without touching memory */
    FX_CHECK_EQ(fx_ctx_set_coords(&e, FX_COORDS_COURSE), 0);
    free(cv.mem);
}

/* Text stays readable: a course-mode label is the screen-mode label at the
 * mirrored anchor row, not mirrored glyphs. */
FX_TEST(coords_course_text_is_upright)
{
    canvas a = canvas_make(W, H), b = canvas_make(W, H);
    fx_ctx ca, cb;
    fx_ctx_init(&ca, &a.s);
    fx_ctx_init(&cb, &b.s);
    fx_ctx_set_coords(&cb, FX_COORDS_COURSE);
    FX_CHECK(fx_text(&ca, 5, H - 1 - 60, "Fy") > 0);
    FX_CHECK(fx_text(&cb, 5, 60, "Fy") > 0);
    FX_CHECK(memcmp(a.mem, b.mem, sizeof(uint32_t) * W * H) == 0);
    int lit = 0;
    for (int i = 0; i < W * H; i++)
        lit += a.mem[i] != 0;
    FX_CHECK(lit > 10);
    free(a.mem);
    free(b.mem);
}

/* Arcs and rotations agree: the arc from 0 to 90 degrees covers the quadrant
 * a point at angle 0 ends in when rotated by 90 degrees, in both modes; on
 * the screen that is the lower-right quadrant in screen mode (clockwise) and
 * the upper-right one in course mode (counter-clockwise). */
FX_TEST(coords_arc_and_rotation_agree)
{
    for (int mode = 0; mode < 2; mode++) {
        canvas cv = canvas_make(W, H);
        fx_ctx c;
        fx_ctx_init(&c, &cv.s);
        fx_ctx_set_coords(&c, mode ? FX_COORDS_COURSE : FX_COORDS_SCREEN);
        const int32_t cx = 40, cy = 40, r = 20;
        for (int pie = 0; pie < 2; pie++) {
            memset(cv.mem, 0, sizeof(uint32_t) * W * H);
            if (pie)
                fx_pie(&c, cx, cy, r, 0, FX_ANGLE_90);
            else
                fx_arc(&c, cx, cy, r, 0, FX_ANGLE_90);
            fx_xform2 rot;
            fx_xform2_rotation(&rot, FX_ANGLE_90, fx16_from_int(cx), fx16_from_int(cy));
            int32_t px, py;
            fx_xform2_apply_int(&rot, cx + r, cy, &px, &py);
            FX_CHECK(px == cx && py == cy + r); /* +90 takes +x to +y of the frame */
            int sy = py > cy ? 1 : -1;      /* the quadrant, in the context's frame */
            /* read back through the context's own view of the surface */
            FX_CHECK_MSG(fx_surface_get_native(&c.surf, px, py) != 0, "mode %d pie %d: rotated point not on the arc",
                         mode, pie);
            int outside = 0, inside = 0;
            for (int y = 0; y < H; y++)
                for (int x = 0; x < W; x++)
                    if (fx_surface_get_native(&c.surf, x, y)) {
                        inside++;
                        if (x < cx || (y - cy) * sy < 0)
                            outside++;
                    }
            FX_CHECK_MSG(outside == 0 && inside > r, "mode %d pie %d: %d of %d pixels outside the quadrant", mode,
                         pie, outside, inside);
            /* and on the screen: below the centre in screen mode, above it in course mode */
            int below = 0, above = 0;
            for (int y = 0; y < H; y++)
                for (int x = 0; x < W; x++)
                    if (cv.mem[y * W + x]) {
                        int phys_cy = mode ? H - 1 - cy : cy;
                        below += y > phys_cy;
                        above += y < phys_cy;
                    }
            FX_CHECK_MSG(mode ? (above > 0 && below == 0) : (below > 0 && above == 0),
                         "mode %d: above %d below %d", mode, above, below);
        }
        free(cv.mem);
    }
}

/* What arcs were before the rule (counter-clockwise on the screen) is
 * course mode's arc now, and the screen-mode arc with the angles mirrored,
 * pixel for pixel (the sine table is odd exactly). */
FX_TEST(coords_old_arc_is_mirrored_angles)
{
    canvas a = canvas_make(W, H), b = canvas_make(W, H);
    for (uint32_t seed = 1; seed < 200; seed++) {
        rng = seed;
        /* whole-turn angles (rnd gives 24 bits), multiples of 45 degrees among them */
        fx_angle a0 = (fx_angle)rnd(0, 0xFFFFFF) << 8 | (fx_angle)(seed & 0xFF), a1 = (fx_angle)rnd(0, 0xFFFFFF) << 8;
        if (seed % 8 == 0) {
            a0 = (fx_angle)(seed / 8 % 8) * FX_ANGLE_45;
            a1 = (fx_angle)(seed / 64 % 8) * FX_ANGLE_45 + FX_ANGLE_45 * 3;
        }
        int32_t r = rnd(1, 38);
        memset(a.mem, 0, sizeof(uint32_t) * W * H);
        memset(b.mem, 0, sizeof(uint32_t) * W * H);
        fx_ctx ca, cb;
        fx_ctx_init(&ca, &a.s);
        fx_ctx_init(&cb, &b.s);
        fx_ctx_set_coords(&cb, FX_COORDS_COURSE);
        if (seed & 2) {
            fx_pie(&ca, 48, 40, r, 0u - a1, 0u - a0);
            fx_pie(&cb, 48, H - 1 - 40, r, a0, a1);
        } else {
            fx_arc(&ca, 48, 40, r, 0u - a1, 0u - a0);
            fx_arc(&cb, 48, H - 1 - 40, r, a0, a1);
        }
        int same = memcmp(a.mem, b.mem, sizeof(uint32_t) * W * H) == 0;
        FX_CHECK_MSG(same, "seed %u: a0 %u a1 %u r %d", seed, a0, a1, r);
        if (!same)
            break;
    }
    free(a.mem);
    free(b.mem);
}

/* Course mode's region codes sit where the notes draw them: 1000 (above) for
 * a point drawn above the window on the screen. */
FX_TEST(coords_course_region_codes_on_screen)
{
    canvas cv = canvas_make(W, H);
    fx_ctx c;
    fx_ctx_init(&c, &cv.s);
    fx_ctx_set_coords(&c, FX_COORDS_COURSE);
    fx_rect win = {10, 10, 31, 21}; /* xw 10..30, yw 10..20 */
    int32_t x = 20, y = 25;         /* above, in the notes' frame */
    FX_CHECK_EQ(fx_clip_region_code(win, x, y), FX_CODE_ABOVE);
    fx_plot(&c, x, y);
    /* on the screen, the point is on a row above (smaller y than) the window's top row */
    int row = -1;
    for (int yy = 0; yy < H; yy++)
        if (cv.mem[yy * W + x])
            row = yy;
    FX_CHECK_EQ(row, H - 1 - y);
    FX_CHECK(row < H - 1 - (win.y1 - 1));
    free(cv.mem);
}

/* The trace of a course-mode context prints the notes' Liang-Barsky numbers:
 * window x 0..10, line (-5,5)-(15,5): p1 = -20, q1 = -5, u1 = 1/4; p2 = 20,
 * q2 = 15, u2 = 3/4; then the pixel-border range the pixels use. */
FX_TEST(coords_course_clip_trace_has_the_notes_numbers)
{
    canvas a = canvas_make(W, H), b = canvas_make(W, H);
    fx_ctx c;
    fx_ctx_init(&c, &b.s);
    fx_ctx_set_coords(&c, FX_COORDS_COURSE);
    fx_rect win = {0, 0, 11, 11};
    fx_ctx_set_clip(&c, win);
    c.line_clipper = FX_CLIP_LIANG;
    c.trace = trace_collect;
    trace_clear();
    fx_line(&c, -5, 5, 15, 5);
    FX_CHECK(trace_has("p_k, q_k in pixels"));
    FX_CHECK(trace_has("k=1 left  p=-20 q=-5 r=1/4 (0.250000)"));
    FX_CHECK(trace_has("k=2 right p=20 q=15 r=3/4 (0.750000)"));
    FX_CHECK(trace_has("notes' window: u1=1/4 (0.250000) u2=3/4 (0.750000)"));
    FX_CHECK(trace_has("pixel borders (half a pixel outside): u1=9/40 (0.225000) u2=31/40 (0.775000)"));
    FX_CHECK(trace_has("steps k=5..15 of 20"));
    /* Cohen-Sutherland names the edges the notes' way and clips at them */
    c.line_clipper = FX_CLIP_COHEN;
    trace_clear();
    fx_line(&c, 5, -5, 5, 15);
    FX_CHECK(trace_has("clip at below boundary: u=1/4 (0.250000)"));
    FX_CHECK(trace_has("clip at above boundary: u=3/4 (0.750000)"));
    /* screen mode keeps its half-pixel trace */
    fx_ctx s;
    fx_ctx_init(&s, &a.s);
    fx_ctx_set_clip(&s, win);
    s.line_clipper = FX_CLIP_LIANG;
    s.trace = trace_collect;
    trace_clear();
    fx_line(&s, -5, 5, 15, 5);
    FX_CHECK(trace_has("p_k, q_k in half pixels"));
    FX_CHECK(!trace_has("notes' window"));
    /* a one-pixel window in the notes has zero width: the trace copes */
    fx_rect one = {4, 4, 5, 5};
    fx_ctx_set_clip(&c, one);
    for (int al = 1; al <= 3; al++) {
        c.line_clipper = (uint8_t)al;
        trace_clear();
        fx_line(&c, 0, 0, 9, 9);
        FX_CHECK(trace_n > 0);
    }
    /* the notes' Bresenham example (20,10)-(30,18), drawn bottom-up */
    fx_ctx_reset_clip(&c);
    c.line_clipper = FX_CLIP_DIRECT;
    trace_clear();
    fx_line(&c, 20, 10, 30, 18);
    FX_CHECK(trace_has("p0=2dy-dx=6"));
    FX_CHECK(trace_has("(21, 11)") && trace_has("(23, 12)") && trace_has("(30, 18)"));
    FX_CHECK_EQ_HEX(b.mem[(H - 1 - 11) * W + 21], 0xFFFFFFu); /* (21, 11) is 11 rows up from the bottom */
    trace_clear();
    free(a.mem);
    free(b.mem);
}

/* Non-square pixels in window-to-viewport: a world circle of radius 40 in
 * a square window is 60 pixels across in x and 80 in y at 3/4. */
FX_TEST(coords_pixel_aspect_window_viewport)
{
    fx_xform2 m;
    const fx16 o = FX16_ONE;
    FX_CHECK_EQ(fx_xform2_window_viewport_par(&m, -100 * o, -100 * o, 100 * o, 100 * o, 0, 0, 400 * o, 400 * o, 1,
                                              3, 4),
                0);
    fx_pt16 c = fx_xform2_apply(&m, (fx_pt16){0, 0});
    fx_pt16 px = fx_xform2_apply(&m, (fx_pt16){40 * o, 0});
    fx_pt16 py = fx_xform2_apply(&m, (fx_pt16){0, 40 * o});
    FX_CHECK_EQ(px.x - c.x, 60 * o);
    FX_CHECK_EQ(py.y - c.y, 80 * o);
    FX_CHECK_EQ(c.x, 200 * o); /* centred */
    FX_CHECK_EQ(c.y, 200 * o);
    /* drawn: the polygon of the circle has pixel extents 121 x 161 (+-60, +-80) */
    canvas cv = canvas_make(420, 420);
    fx_ctx ctx;
    fx_ctx_init(&ctx, &cv.s);
    ctx.xform = &m;
    int32_t xy[2 * 64];
    for (int i = 0; i < 64; i++) {
        fx_angle a = (fx_angle)i << 26;
        fx_ctx_map(&ctx, (int32_t)((40 * (int64_t)fx_cos(a)) >> 16), (int32_t)((40 * (int64_t)fx_sin(a)) >> 16),
                   &xy[2 * i], &xy[2 * i + 1]);
    }
    fx_polygon(&ctx, xy, 64);
    int x0 = 999, x1 = -1, y0 = 999, y1 = -1;
    for (int y = 0; y < 420; y++)
        for (int x = 0; x < 420; x++)
            if (cv.mem[y * 420 + x]) {
                x0 = x < x0 ? x : x0;
                x1 = x > x1 ? x : x1;
                y0 = y < y0 ? y : y0;
                y1 = y > y1 ? y : y1;
            }
    FX_CHECK_EQ(x1 - x0, 120);
    FX_CHECK_EQ(y1 - y0, 160);
    free(cv.mem);
    /* 1/1 is the plain mapping; bad ratios are refused */
    fx_xform2 a, b;
    FX_CHECK_EQ(fx_xform2_window_viewport_par(&a, 0, 0, 7 * o, 3 * o, 0, 0, 90 * o, 50 * o, 1, 1, 1), 0);
    FX_CHECK_EQ(fx_xform2_window_viewport(&b, 0, 0, 7 * o, 3 * o, 0, 0, 90 * o, 50 * o, 1), 0);
    FX_CHECK(memcmp(&a, &b, sizeof a) == 0);
    FX_CHECK_EQ(fx_xform2_window_viewport_par(&a, 0, 0, o, o, 0, 0, o, o, 1, 0, 1), -FX_EINVAL);
    FX_CHECK_EQ(fx_xform2_window_viewport_par(&a, 0, 0, o, o, 0, 0, o, o, 1, 3, 70000), -FX_EINVAL);
    /* a wide window limited by x: x still gets 3/4 of y's scale */
    FX_CHECK_EQ(fx_xform2_window_viewport_par(&a, 0, 0, 400 * o, 100 * o, 0, 0, 300 * o, 300 * o, 1, 3, 4), 0);
    FX_CHECK_EQ(a.m[0][0], 3 * o / 4);
    FX_CHECK_EQ(a.m[1][1], o);
}

/* The 3D projection with pixel aspect 3/4 scales x by 3/4 exactly. */
FX_TEST(coords_pixel_aspect_projection)
{
    fx_mat4 p, q;
    FX_CHECK_EQ(fx_mat4_ortho(&p, -2 * FX16_ONE, 2 * FX16_ONE, -2 * FX16_ONE, 2 * FX16_ONE, FX16_ONE, 10 * FX16_ONE),
                0);
    q = p;
    FX_CHECK_EQ(fx_mat4_pixel_aspect(&q, 3, 4), 0);
    FX_CHECK_EQ(q.m[0][0], p.m[0][0] * 3 / 4);
    for (int r = 1; r < 4; r++)
        for (int k = 0; k < 4; k++)
            FX_CHECK_EQ(q.m[r][k], p.m[r][k]);
    fx_vec4 a = fx_mat4_apply(&p, (fx_vec4){FX16_ONE, FX16_ONE / 2, -3 * FX16_ONE, FX16_ONE});
    fx_vec4 b = fx_mat4_apply(&q, (fx_vec4){FX16_ONE, FX16_ONE / 2, -3 * FX16_ONE, FX16_ONE});
    FX_CHECK_EQ(b.x * 4, a.x * 3);
    FX_CHECK_EQ(b.y, a.y);
    /* perspective: every x entry is 3/4 of the old, rounded to nearest */
    FX_CHECK_EQ(fx_mat4_perspective(&p, fx_angle_from_deg(60), FX16_ONE, FX16_ONE / 10, 100 * FX16_ONE), 0);
    q = p;
    FX_CHECK_EQ(fx_mat4_pixel_aspect(&q, 3, 4), 0);
    for (int k = 0; k < 4; k++)
        FX_CHECK(llabs((int64_t)q.m[0][k] * 4 - (int64_t)p.m[0][k] * 3) <= 2);
    FX_CHECK_EQ(fx_mat4_pixel_aspect(&q, 0, 4), -FX_EINVAL);
    /* through the pipeline: the current projection's x row */
    static uint32_t mem[64 * 64];
    fx_surface s;
    fx_surface_init(&s, mem, 64, 64, 64 * 4, FX_FMT_XRGB8888);
    static fx_mat4 ms[4], ps[4];
    fx3d r;
    FX_CHECK_EQ(fx3d_init(&r, &s, ms, 4, ps, 4), 0);
    FX_CHECK_EQ(fx3d_ortho(&r, -2 * FX16_ONE, 2 * FX16_ONE, -2 * FX16_ONE, 2 * FX16_ONE, FX16_ONE, 10 * FX16_ONE),
                0);
    FX_CHECK_EQ(fx3d_pixel_aspect(&r, 3, 4), 0);
    FX_CHECK_EQ(fx_mat_stack_top(&r.proj)->m[0][0], FX16_ONE / 2 * 3 / 4);
}

/* The script commands: 'coords course' mirrors what follows, 'pixelaspect'
 * reaches 'viewport ... aspect'. */
static uint32_t smem[2][48 * 40];
static int run_into(int i, const char *text, char *err, size_t n)
{
    static uint64_t arena[4096];
    scene_buf buf = {smem[i], 48 * 40};
    fx_scene sc;
    fx_scene_host h = {&buf, scene_buf_make, NULL, NULL, NULL, NULL};
    fx_scene_init(&sc, &h, arena, sizeof arena);
    int e = fx_scene_run(&sc, text, strlen(text));
    if (err)
        snprintf(err, n, "%s", sc.err);
    return e;
}

FX_TEST(coords_scene_commands)
{
    const char *body = "line 2 3 40 20\ncircle 20 12 7\narc 30 25 9 0 90\nrotate 30 10 10\nfillrect 5 5 12 4\n";
    char a[512], b[512], err[256];
    snprintf(a, sizeof a, "size 48 40\n%s", body);
    snprintf(b, sizeof b, "size 48 40\ncoords course\n%s", body);
    FX_CHECK_EQ(run_into(0, a, NULL, 0), 0);
    FX_CHECK_EQ(run_into(1, b, NULL, 0), 0);
    int ok = 1, lit = 0;
    for (int y = 0; y < 40; y++)
        for (int x = 0; x < 48; x++) {
            ok &= smem[0][y * 48 + x] == smem[1][(39 - y) * 48 + x];
            lit += smem[0][y * 48 + x] != 0;
        }
    FX_CHECK(ok);
    FX_CHECK(lit > 50);
    FX_CHECK_EQ(run_into(0, "size 48 40\ncoords upwards\n", err, sizeof err), -FX_EINVAL);
    FX_CHECK(strstr(err, "screen|course") != NULL || strstr(err, "upwards") != NULL);
    /* pixelaspect 3 4: a square world box is 3/4 as wide as tall */
    FX_CHECK_EQ(run_into(0,
                         "size 48 40\npixelaspect 3 4\nwindow -10 -10 10 10\nviewport 0 0 47 39 aspect\n"
                         "fillrect -10 -10 20 20\n",
                         err, sizeof err),
                0);
    int x0 = 99, x1 = -1, y0 = 99, y1 = -1;
    for (int y = 0; y < 40; y++)
        for (int x = 0; x < 48; x++)
            if (smem[0][y * 48 + x]) {
                x0 = x < x0 ? x : x0;
                x1 = x > x1 ? x : x1;
                y0 = y < y0 ? y : y0;
                y1 = y > y1 ? y : y1;
            }
    /* y scale 39/20, x scale 3/4 of it: 20 world units = 39 pixels tall, 29.25 wide */
    FX_CHECK_EQ(y1 - y0 + 1, 39);
    FX_CHECK(x1 - x0 + 1 >= 29 && x1 - x0 + 1 <= 30);
    FX_CHECK_EQ(run_into(0, "size 48 40\npixelaspect 0 4\n", err, sizeof err), -FX_EINVAL);
    FX_CHECK(strstr(err, "NUM") != NULL || strstr(err, "1..65536") != NULL);
}

/* The mode lives in what was padding: fx_ctx keeps its size and every other
 * field its offset (docs/ABI.md: a layout change would be a new major). */
FX_TEST(coords_field_fills_padding)
{
    FX_CHECK_EQ(offsetof(fx_ctx, coords), offsetof(fx_ctx, exterior) + 1);
    FX_CHECK_EQ(offsetof(fx_ctx, exterior_rect), (offsetof(fx_ctx, exterior) + 1 + 3) / 4 * 4);
    FX_CHECK_EQ(offsetof(fx_ctx, exterior_rect), offsetof(fx_ctx, coords) + 1);
}

/* Found by the review of this round: the 3D module copied the script's
 * context (the mirrored view after 'coords course') over its own, so meshes
 * came out upside down; 'blur' sized its snapshot from the negative stride;
 * 'pixelaspect' multiplied a 2^48 scale by 2^16 in 64 bits. */
static uint32_t bmem[2][64 * 48];
static uint64_t barena[2][(4u << 20) / 8];
static int run_big(int i, const char *text, char *err, size_t n)
{
    scene_buf buf = {bmem[i], 64 * 48};
    fx_scene sc;
    fx_scene_host h = {&buf, scene_buf_make, NULL, NULL, NULL, NULL};
    fx_scene_init(&sc, &h, barena[i], sizeof barena[i]);
    int e = fx_scene_run(&sc, text, strlen(text));
    if (err)
        snprintf(err, n, "%s", sc.err);
    return e;
}

FX_TEST(coords_course_3d_draws_the_same_picture)
{
    /* an asymmetric scene, so a flip shows: a cube low, a sphere high */
    const char *body = "depth 32\ncamera 0 1 6 0 0 0 0 1 0\nlight 0 directional 1 2 3 #FFFFFF\n"
                       "color #FF8040\ntranslate3d -1 -1 0\ncube 1\n"
                       "identity3d\ncolor #40A0FF\ntranslate3d 1 1.2 0\nsphere 0.6 12 8\n";
    char a[1024], b[1024], err[256];
    snprintf(a, sizeof a, "size 64 48\n%s", body);
    snprintf(b, sizeof b, "size 64 48\ncoords course\n%s", body);
    FX_CHECK_MSG(run_big(0, a, err, sizeof err) == 0, "%s", err);
    FX_CHECK_MSG(run_big(1, b, err, sizeof err) == 0, "%s", err);
    int lit = 0;
    FX_CHECK(!memcmp(bmem[0], bmem[1], sizeof bmem[0]));
    for (int i = 0; i < 64 * 48; i++)
        lit += bmem[0][i] != 0;
    FX_CHECK(lit > 200);
}

FX_TEST(coords_course_blur_is_the_screen_blur_mirrored)
{
    const char *body = "clear #000000\nkey m 0 0 0\nkey m 1 30 0\ninterp m linear\n"
                       "blur 8 1\ncolor #FFFFFF\ntween m translate\nfillrect 5 10 10 6\nendblur\n";
    char a[512], b[512], err[256];
    snprintf(a, sizeof a, "size 64 48\n%s", body);
    snprintf(b, sizeof b, "size 64 48\ncoords course\n%s", body);
    int ea = run_big(0, a, err, sizeof err);
    FX_CHECK_MSG(ea == 0, "screen: %s", err);
    int eb = run_big(1, b, err, sizeof err);
    FX_CHECK_MSG(eb == 0, "course: %s", err);
    int ok = 1, grey = 0;
    for (int y = 0; y < 48; y++)
        for (int x = 0; x < 64; x++) {
            uint32_t p = bmem[0][y * 64 + x] & 0xFFFFFF;
            ok &= p == (bmem[1][(47 - y) * 64 + x] & 0xFFFFFF);
            grey += p != 0 && p != 0xFFFFFF; /* blurred edges */
        }
    FX_CHECK(ok);
    FX_CHECK(grey > 0);
}

FX_TEST(coords_pixel_aspect_extreme_window_is_defined)
{
    /* a 2^-16-wide window onto a 65533-px viewport at 1/65536: the x scale
     * saturates instead of overflowing (UBSan build: no report) */
    fx_xform2 o;
    FX_CHECK_EQ(fx_xform2_window_viewport_par(&o, 0, 0, 1, 1, -32767 * FX16_ONE, -32767 * FX16_ONE,
                                              32766 * FX16_ONE, 32766 * FX16_ONE, 1, 1, 65536),
                0);
    FX_CHECK_EQ(fx_xform2_window_viewport_par(&o, 0, 0, 1, 1, -32767 * FX16_ONE, -32767 * FX16_ONE,
                                              32766 * FX16_ONE, 32766 * FX16_ONE, 1, 65536, 1),
                0);
    char err[256];
    FX_CHECK_MSG(run_big(0,
                         "size 64 48\npixelaspect 1 65536\nwindow 0 0 0.00002 0.00002\n"
                         "viewport -32767 -32767 32766 32766 aspect\nline 0 0 1 1\n",
                         err, sizeof err) == 0,
                 "%s", err);
}

/* More from the same review: 'hatch' before the surface existed was lost
 * when the surface was made; the chromaticity diagram was skipped when only
 * its wavelength labels reached into the clip; a light pass under the
 * painter's sort (no depth buffer) is refused. */
FX_TEST(review_hatch_before_the_surface_is_kept)
{
    char err[256];
    FX_CHECK_MSG(run_big(0, "size 64 48\nhatch 50\ncolor #FFFFFF\nfillrect 0 0 40 40\n", err, sizeof err) == 0, "%s",
                 err);
    FX_CHECK_MSG(run_big(1, "size 64 48\ncolor #FFFFFF\nfillrect 0 0 40 40\n", err, sizeof err) == 0, "%s", err);
    int ink = 0, solid = 0;
    for (int y = 0; y < 40; y++)
        for (int x = 0; x < 40; x++) {
            ink += bmem[0][y * 64 + x] != 0;
            solid += bmem[1][y * 64 + x] != 0;
        }
    FX_CHECK_EQ(solid, 1600);
    FX_CHECK(ink > 0 && ink < 1600); /* hatched, not solid */
}

FX_TEST(review_chromaticity_labels_below_the_diagram_are_drawn)
{
    char err[256];
    /* the whole diagram, and the same with the clip on the rows below it */
    FX_CHECK_MSG(run_big(0, "size 64 48\nchromaticity 0 0 40 34\n", err, sizeof err) == 0, "%s", err);
    FX_CHECK_MSG(run_big(1, "size 64 48\nclip 0 35 63 47\nchromaticity 0 0 40 34\n", err, sizeof err) == 0, "%s",
                 err);
    int below = 0, same = 1;
    for (int y = 35; y < 48; y++)
        for (int x = 0; x < 64; x++) {
            below += bmem[0][y * 64 + x] != 0;
            same &= bmem[0][y * 64 + x] == bmem[1][y * 64 + x];
        }
    FX_CHECK(below > 0); /* the labels do reach below the diagram */
    FX_CHECK(same);
}

FX_TEST(review_light_pass_needs_the_depth_buffer)
{
    char err[256];
    FX_CHECK_EQ(run_big(0, "size 64 48\npainter 64\npass3d light 0\n", err, sizeof err), -FX_EINVAL);
    FX_CHECK(strstr(err, "depth") != NULL);
    FX_CHECK_MSG(run_big(0, "size 64 48\ndepth 32\npass3d light 0\n", err, sizeof err) == 0, "%s", err);
}

/* Issue #44: the turtle and the Koch curves turn as 'rotate' does, from +x
 * towards +y of the frame, so in course mode turn(+60) is a left turn and the
 * bumps stand above the base line, as in the notes. */
static int rows_lit(int i, int y0, int y1) /* lit pixels in screen rows y0..y1 */
{
    int n = 0;
    for (int y = y0; y <= y1; y++)
        for (int x = 0; x < 48; x++)
            n += smem[i][y * 48 + x] != 0;
    return n;
}

FX_TEST(coords_turtle_turns_as_rotate)
{
    /* the numbers: home (100, 100) heading 0, turn 60, forward 50 */
    fx_turtle t;
    fx_turtle_init(&t, NULL, 100 << 16, 100 << 16, 0);
    fx_turtle_turn(&t, 60 << 16);
    fx_turtle_forward(&t, 50 << 16, 1);
    fx16 x, y;
    fx_turtle_pos(&t, &x, &y);
    FX_CHECK(abs(x - 125 * 65536) <= 2);
    FX_CHECK(abs(y - 9391392) <= 2); /* 143.30127 = 100 + 25 sqrt 3 */
    /* 'turtle forward' at heading 90 ends where 'rotate 90' takes +x */
    fx_xform2 rot;
    fx_xform2_rotation(&rot, FX_ANGLE_90, 0, 0);
    int32_t rx, ry;
    fx_xform2_apply_int(&rot, 10, 0, &rx, &ry);
    fx_turtle_init(&t, NULL, 0, 0, 90 << 16);
    fx_turtle_forward(&t, 10 << 16, 0);
    fx_turtle_pos(&t, &x, &y);
    FX_CHECK(abs(x - rx * 65536) <= 2 && abs(y - ry * 65536) <= 2);

    /* the base line is frame row 10: screen row 29 in course mode, 10 on the screen */
    const char *koch[] = {"koch 4 10 44 10 2\n", "turtle home 4 10 0\nturtle koch 40 2\n"};
    for (int k = 0; k < 2; k++) {
        char a[256], b[256], err[256];
        snprintf(a, sizeof a, "size 48 40\n%s", koch[k]);
        snprintf(b, sizeof b, "size 48 40\ncoords course\n%s", koch[k]);
        FX_CHECK_EQ(run_into(0, a, err, sizeof err), 0);
        FX_CHECK_EQ(run_into(1, b, err, sizeof err), 0);
        /* course: nothing below the base line on the screen, the bump (11.5 px
         * at order 2's middle third) above it */
        FX_CHECK_MSG(rows_lit(1, 30, 39) == 0 && rows_lit(1, 18, 21) > 0, "%s: %d below, %d at the tip", koch[k],
                     rows_lit(1, 30, 39), rows_lit(1, 18, 21));
        /* screen: the same frame picture, so the same pixels mirrored */
        int same = 1;
        for (int yy = 0; yy < 40; yy++)
            for (int xx = 0; xx < 48; xx++)
                same &= smem[0][yy * 48 + xx] == smem[1][(39 - yy) * 48 + xx];
        FX_CHECK_MSG(same, "%s: screen mode is not course mode mirrored", koch[k]);
    }
    /* a snowflake's bumps still point outward: its order-1 star reaches r
     * from the centre along six directions, the triangle alone only three */
    FX_CHECK_EQ(run_into(0, "size 48 40\nsnowflake 24 20 15 1\n", NULL, 0), 0);
    FX_CHECK(rows_lit(0, 5, 5) > 0 && rows_lit(0, 35, 35) > 0 && smem[0][20 * 48 + 24] == 0);
    /* grass grows up the picture in both modes, rooted on its bottom row */
    FX_CHECK_EQ(run_into(0, "size 48 40\ngrass 0 0 48 40 12 7\n", NULL, 0), 0);
    FX_CHECK_EQ(run_into(1, "size 48 40\ncoords course\ngrass 0 0 48 40 12 7\n", NULL, 0), 0);
    FX_CHECK_MSG(rows_lit(0, 39, 39) >= 6 && rows_lit(1, 39, 39) >= 6 && rows_lit(1, 20, 30) > 12,
                 "grass roots %d / %d, course stems %d", rows_lit(0, 39, 39), rows_lit(1, 39, 39),
                 rows_lit(1, 20, 30));
}
