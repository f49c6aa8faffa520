/* SPDX-License-Identifier: MIT */
/* fixel — scene commands of the conic module: circles, discs, arcs, pie
 * slices, antialiased circles and ellipses. Angles are degrees in the script
 * (decimals allowed), counter-clockwise with y up. */
#include "fixel/circle.h"
#include "fixel/error.h"
#include "fixel/scene.h"

#define TRY(x)                   \
    do {                         \
        int r_ = (x);            \
        if (r_ < 0)              \
            return r_;           \
    } while (0)

static int args(fx_scene *sc, int32_t *v, int n)
{
    for (int i = 0; i < n; i++)
        TRY(fx_scene_arg_int(sc, &v[i]));
    return fx_scene_end(sc);
}

static int radius_ok(fx_scene *sc, int32_t r)
{
    return r < 0 ? fx_scene_error(sc, "radius %d is negative", r) : 0;
}

static int cmd_circle(fx_scene *sc)
{
    int32_t v[3];
    TRY(args(sc, v, 3));
    TRY(radius_ok(sc, v[2]));
    fx_circle(&sc->ctx, v[0], v[1], v[2]);
    return 0;
}

static int cmd_disc(fx_scene *sc)
{
    int32_t v[3];
    TRY(args(sc, v, 3));
    TRY(radius_ok(sc, v[2]));
    fx_disc(&sc->ctx, v[0], v[1], v[2]);
    return 0;
}

static int cmd_aacircle(fx_scene *sc)
{
    int32_t v[3];
    TRY(args(sc, v, 3));
    TRY(radius_ok(sc, v[2]));
    fx_aacircle(&sc->ctx, v[0], v[1], v[2]);
    return 0;
}

/* CX CY R START END: a sweep of 360 degrees or more is the whole circle, a
 * negative sweep runs clockwise (the same pixels as END -> START), zero draws
 * nothing. */
static int sector_args(fx_scene *sc, int32_t *v, fx_angle *a0, fx_angle *a1, int *full)
{
    fx16 s, e;
    for (int i = 0; i < 3; i++)
        TRY(fx_scene_arg_int(sc, &v[i]));
    TRY(fx_scene_arg_fx16(sc, &s));
    TRY(fx_scene_arg_fx16(sc, &e));
    TRY(fx_scene_end(sc));
    TRY(radius_ok(sc, v[2]));
    int64_t sweep = (int64_t)e - s;
    if (sweep == 0)
        return 0;
    *full = sweep >= (int64_t)360 * FX16_ONE || sweep <= -(int64_t)360 * FX16_ONE;
    if (sweep < 0) {
        fx16 t = s;
        s = e;
        e = t;
    }
    *a0 = fx_angle_from_deg16(s);
    *a1 = *full ? *a0 : fx_angle_from_deg16(e);
    return 1;
}

static int cmd_arc(fx_scene *sc)
{
    int32_t v[3];
    fx_angle a0 = 0, a1 = 0;
    int full = 0, r = sector_args(sc, v, &a0, &a1, &full);
    if (r > 0)
        fx_arc(&sc->ctx, v[0], v[1], v[2], a0, a1);
    return r < 0 ? r : 0;
}

static int cmd_pie(fx_scene *sc)
{
    int32_t v[3];
    fx_angle a0 = 0, a1 = 0;
    int full = 0, r = sector_args(sc, v, &a0, &a1, &full);
    if (r > 0)
        fx_pie(&sc->ctx, v[0], v[1], v[2], a0, a1);
    return r < 0 ? r : 0;
}

static int ellipse_args(fx_scene *sc, int32_t *v)
{
    TRY(args(sc, v, 4));
    if (v[2] < 0 || v[3] < 0)
        return fx_scene_error(sc, "semi-axes %d, %d must not be negative", v[2], v[3]);
    return 0;
}

static int cmd_ellipse(fx_scene *sc)
{
    int32_t v[4];
    TRY(ellipse_args(sc, v));
    fx_ellipse(&sc->ctx, v[0], v[1], v[2], v[3]);
    return 0;
}

static int cmd_fillellipse(fx_scene *sc)
{
    int32_t v[4];
    TRY(ellipse_args(sc, v));
    fx_fill_ellipse(&sc->ctx, v[0], v[1], v[2], v[3]);
    return 0;
}

const fx_scene_cmd fx_scene_cmds_conic[] = {
    {"circle", cmd_circle, "circle CX CY R", FX_SCENE_DRAWS},
    {"disc", cmd_disc, "disc CX CY R", FX_SCENE_DRAWS},
    {"arc", cmd_arc, "arc CX CY R START END   (degrees, turning as 'rotate' does: clockwise on screen, counter-clockwise after 'coords course')", FX_SCENE_DRAWS},
    {"pie", cmd_pie, "pie CX CY R START END   (degrees, turning as 'rotate' does: clockwise on screen, counter-clockwise after 'coords course')", FX_SCENE_DRAWS},
    {"aacircle", cmd_aacircle, "aacircle CX CY R", FX_SCENE_DRAWS},
    {"ellipse", cmd_ellipse, "ellipse CX CY RX RY", FX_SCENE_DRAWS},
    {"fillellipse", cmd_fillellipse, "fillellipse CX CY RX RY", FX_SCENE_DRAWS},
    {0, 0, 0, 0},
};
