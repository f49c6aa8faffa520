/* SPDX-License-Identifier: MIT */
/* fixel — the foundation's scene commands: surface set-up, colour, pixels,
 * rectangles and the Bresenham line. */
#include "../base/fx_internal.h"
#include "fixel/error.h"
#include "fixel/fill.h"
#include "fixel/fixed.h"
#include "fixel/line.h"
#include "fixel/scene.h"
#include "fixel/xform.h"

#define TRY(x)                   \
    do {                         \
        int r_ = (x);            \
        if (r_ < 0)              \
            return r_;           \
    } while (0)

static int cmd_size(fx_scene *sc)
{
    int32_t w, h;
    TRY(fx_scene_arg_int(sc, &w));
    TRY(fx_scene_arg_int(sc, &h));
    TRY(fx_scene_end(sc));
    if (w < 1 || h < 1 || w > 16384 || h > 16384)
        return fx_scene_error(sc, "size %dx%d out of range (1..16384)", w, h);
    if (sc->have_surface)
        return fx_scene_error(sc, "'size' must come before the first drawing command");
    if (!sc->size_fixed) {
        sc->w = w;
        sc->h = h;
    }
    return 0;
}

static int cmd_format(fx_scene *sc)
{
    char name[32];
    TRY(fx_scene_arg_word(sc, name, sizeof name));
    fx_format f = fx_format_from_name(name);
    if (f == FX_FMT_COUNT)
        return fx_scene_error(sc, "unknown pixel format '%s'", name);
    TRY(fx_scene_end(sc));
    if (sc->have_surface)
        return fx_scene_error(sc, "'format' must come before the first drawing command");
    if (!sc->format_fixed)
        sc->format = f;
    return 0;
}

static int cmd_clear(fx_scene *sc)
{
    fx_color c;
    TRY(fx_scene_arg_color(sc, &c));
    TRY(fx_scene_end(sc));
    fx_ctx t = sc->ctx;
    fx_ctx_set_color(&t, c);
    fx_clear(&t);
    return 0;
}

static int cmd_color(fx_scene *sc)
{
    fx_color c;
    TRY(fx_scene_arg_color(sc, &c));
    TRY(fx_scene_end(sc));
    if (sc->have_surface)
        fx_ctx_set_color(&sc->ctx, c);
    else
        sc->ctx.color = c;
    return 0;
}

static int args(fx_scene *sc, int32_t *v, int n)
{
    for (int i = 0; i < n; i++)
        TRY(fx_scene_arg_int(sc, &v[i]));
    return fx_scene_end(sc);
}

static int cmd_pixel(fx_scene *sc)
{
    int32_t v[2];
    TRY(args(sc, v, 2));
    fx_ctx_map(&sc->ctx, v[0], v[1], &v[0], &v[1]); /* the current transform, if any */
    fx_plot(&sc->ctx, v[0], v[1]);
    return 0;
}

static int cmd_rect(fx_scene *sc)
{
    int32_t v[4];
    TRY(args(sc, v, 4));
    fx_xform_rect_outline(&sc->ctx, v[0], v[1], v[2], v[3]); /* a polygon when transformed */
    return 0;
}

static int cmd_fillrect(fx_scene *sc)
{
    int32_t v[4];
    TRY(args(sc, v, 4));
    const fx_ctx *c = &sc->ctx;
    /* fx_fill_rect is the solid fast path; a pattern, gradient or texture
     * set for fillpoly must fill rectangles too (issue #23), through the
     * same styled spans. Transformed rectangles are polygons already. */
    if (c->fill_style && c->fill_style->kind != FX_FILL_SOLID && !fx_ctx_transformed(c)) {
        if (v[2] <= 0 || v[3] <= 0)
            return 0;
        int64_t y0 = FX_MAX((int64_t)v[1], (int64_t)c->clip.y0);
        int64_t y1 = FX_MIN((int64_t)v[1] + v[3], (int64_t)c->clip.y1);
        int32_t x1 = fx_sat32((int64_t)v[0] + v[2]);
        for (int64_t y = y0; y < y1; y++) /* at most the clip's height */
            fx_fill_span(c, (int32_t)y, v[0], x1);
        return 0;
    }
    fx_xform_fill_rect(c, v[0], v[1], v[2], v[3]);
    return 0;
}

static int cmd_line(fx_scene *sc)
{
    int32_t v[4];
    TRY(args(sc, v, 4));
    fx_ctx_map(&sc->ctx, v[0], v[1], &v[0], &v[1]);
    fx_ctx_map(&sc->ctx, v[2], v[3], &v[2], &v[3]);
    fx_line(&sc->ctx, v[0], v[1], v[2], v[3]);
    return 0;
}

/* 'coords course' turns the 2D commands to the notes' frame (fx_ctx_set_coords):
 * origin at the bottom-left pixel, y up, rotations and arcs counter-clockwise. */
static int cmd_coords(fx_scene *sc)
{
    static const char *const modes[] = {"screen", "course", 0};
    int m = fx_scene_arg_choice(sc, modes);
    TRY(m);
    TRY(fx_scene_end(sc));
    return fx_ctx_set_coords(&sc->ctx, m ? FX_COORDS_COURSE : FX_COORDS_SCREEN);
}

static int cmd_present(fx_scene *sc)
{
    TRY(fx_scene_end(sc));
    return sc->host.present ? sc->host.present(sc->host.user) : 0;
}

const fx_scene_cmd fx_scene_cmds_core[] = {
    {"size", cmd_size, "size W H", 0},
    {"format", cmd_format, "format XRGB8888|ARGB8888|XBGR8888|RGB565|BGR565|RGB888|BGR888|GRAY8|MONO1", 0},
    {"clear", cmd_clear, "clear #RRGGBB", FX_SCENE_DRAWS},
    {"color", cmd_color, "color #RRGGBB|#AARRGGBB", 0},
    {"pixel", cmd_pixel, "pixel X Y", FX_SCENE_DRAWS},
    {"rect", cmd_rect, "rect X Y W H", FX_SCENE_DRAWS},
    {"fillrect", cmd_fillrect, "fillrect X Y W H", FX_SCENE_DRAWS},
    {"line", cmd_line, "line X0 Y0 X1 Y1", FX_SCENE_DRAWS},
    {"coords", cmd_coords,
     "coords screen|course (course: origin bottom-left, y up, +angles counter-clockwise, as the notes and GLUT)",
     FX_SCENE_DRAWS | FX_SCENE_SERIAL}, /* bands are cut in the surface's rows, not the mirrored frame's */
    {"present", cmd_present, "present", FX_SCENE_DRAWS | FX_SCENE_SERIAL},
    {0, 0, 0, 0},
};
