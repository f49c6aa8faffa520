/* SPDX-License-Identifier: MIT */
/* fixel — scene commands of animation (issue #23): key frames on named
 * tracks and the in-betweens at the clock, ease-in/ease-out, motion along a
 * path for objects and the 3D camera, morphing named outlines, the bouncing
 * ball, and motion blur over a recorded block of lines. State lives in the
 * arena (sc->mod[FX_SCENE_MOD_ANIM]). docs/ANIMATION.md has the language.
 *
 * Everything is drawn at one time, the clock: 'time T' in the script, or
 * the host's fx_scene_set_clock (fixel-draw --frames), which wins. A script
 * is a description of every frame; the frame at the clock is what it draws. */
#include "fixel/anim.h"
#include "fixel/circle.h"
#include "fixel/error.h"
#include "fixel/fill.h"
#include "fixel/kinematics.h"
#include "fixel/line.h"
#include "fixel/scene.h"
#include "fixel/xform.h"
#include "../base/fx_internal.h"
#include "scene_frame.h"
#include "scene_shared.h"

#define TRY(x)                   \
    do {                         \
        int r_ = (x);            \
        if (r_ < 0)              \
            return r_;           \
    } while (0)

#define TRACKS 16
#define KEYS 64
#define SHAPES 8
#define SHAPE_MAX 256
#define NAME_MAX 24
#define REC_BYTES 65536
#define REC_LINES 1024
#define ARM_SWEEPS 256 /* CCD sweeps per solve of 'arm' and per step of 'armgoal' */
#define ARM_STEPS 4096

typedef struct track {
    char name[NAME_MAX];
    int32_t n, nch;
    uint8_t interp, ease, color;
    fx_anim_key keys[KEYS];
} track;

typedef struct shape {
    char name[NAME_MAX];
    int32_t n;
    fx16 xy[2 * SHAPE_MAX];
} shape;

typedef struct anim_state {
    fx16 clock;
    int clock_fixed;
    track tr[TRACKS];
    int32_t ntr;
    shape sh[SHAPES];
    int32_t nsh;
    /* the blur block: its lines, kept while recording, run at 'endblur' */
    int recording, replaying;
    int32_t blur_n;
    fx16 shutter;
    char *rec;
    int32_t rec_len, nlines;
    int32_t line_at[REC_LINES], line_len[REC_LINES], line_no[REC_LINES];
} anim_state;

static anim_state *state(fx_scene *sc)
{
    anim_state *st = sc->mod[FX_SCENE_MOD_ANIM];
    if (!st) {
        st = fx_scene_alloc(sc, sizeof *st);
        sc->mod[FX_SCENE_MOD_ANIM] = st;
    }
    return st;
}

#define STATE(st)                                                           \
    anim_state *st = state(sc);                                             \
    if (!st)                                                                \
        return fx_scene_error(sc, "out of scene memory for the animation state")

int fx_scene_set_clock(fx_scene *sc, fx16 t)
{
    anim_state *st = state(sc);
    if (!st)
        return -FX_ENOMEM;
    st->clock = t;
    st->clock_fixed = 1;
    return 0;
}

static int same(const char *a, const char *b)
{
    while (*a && *a == *b)
        a++, b++;
    return *a == *b;
}

static track *find_track(anim_state *st, const char *name)
{
    for (int32_t i = 0; i < st->ntr; i++)
        if (same(st->tr[i].name, name))
            return &st->tr[i];
    return 0;
}

/* The track named by the next word; made (empty, spline) when make is set. */
static int arg_track(fx_scene *sc, anim_state *st, int make, track **out)
{
    char name[NAME_MAX];
    TRY(fx_scene_arg_word(sc, name, sizeof name));
    track *t = find_track(st, name);
    if (!t && make) {
        if (st->ntr == TRACKS)
            return fx_scene_error(sc, "too many tracks (at most %d)", TRACKS);
        t = &st->tr[st->ntr++];
        fx_memcpy(t->name, name, sizeof name);
        t->interp = FX_ANIM_SPLINE;
    }
    if (!t)
        return fx_scene_error(sc, "no track '%s' (give it keys with 'key' first)", name);
    *out = t;
    return 0;
}

static fx_anim_track view(const track *t)
{
    fx_anim_track v = {t->keys, t->n, t->nch, t->interp, t->ease};
    return v;
}

/* The track's values at the clock; an empty track is an error. */
static int track_at(fx_scene *sc, const anim_state *st, const track *t, fx16 *v)
{
    if (!t->n)
        return fx_scene_error(sc, "track '%s' has no keys", t->name);
    fx_anim_track a = view(t);
    fx_anim_eval(&a, st->clock, v);
    return 0;
}

static const char *const eases[] = {"none", "in", "out", "inout", "smooth", 0};

/* ---- the clock and the keys ---- */

static int cmd_time(fx_scene *sc)
{
    STATE(st);
    fx16 t;
    TRY(fx_scene_arg_fx16(sc, &t));
    TRY(fx_scene_end(sc));
    if (t < 0)
        return fx_scene_error(sc, "time must not be negative");
    if (!st->clock_fixed)
        st->clock = t;
    return 0;
}

static int add_key(fx_scene *sc, track *t, fx16 when, const fx16 *v, int nch, int color)
{
    if (t->n && (t->nch != nch || t->color != color))
        return fx_scene_error(sc, "track '%s' has %d %s per key, not %d", t->name, t->nch,
                              t->color ? "colour channels" : t->nch == 1 ? "value" : "values", nch);
    if (t->n && when <= t->keys[t->n - 1].t)
        return fx_scene_error(sc, "keys of track '%s' must come in increasing time", t->name);
    if (t->n == KEYS)
        return fx_scene_error(sc, "track '%s' is full (at most %d keys)", t->name, KEYS);
    fx_anim_key *k = &t->keys[t->n++];
    fx_memset(k, 0, sizeof *k);
    k->t = when;
    for (int c = 0; c < nch; c++)
        k->v[c] = v[c];
    t->nch = nch;
    t->color = (uint8_t)color;
    return 0;
}

static int cmd_key(fx_scene *sc)
{
    STATE(st);
    track *t;
    TRY(arg_track(sc, st, 1, &t));
    fx16 when, v[FX_ANIM_MAX_CH];
    TRY(fx_scene_arg_fx16(sc, &when));
    int n = 0;
    while (fx_scene_more(sc)) {
        if (n == FX_ANIM_MAX_CH)
            return fx_scene_error(sc, "at most %d values per key", FX_ANIM_MAX_CH);
        TRY(fx_scene_arg_fx16(sc, &v[n++]));
    }
    if (!n)
        return fx_scene_error(sc, "missing value (key NAME T V...)");
    TRY(fx_scene_end(sc));
    if (when < 0)
        return fx_scene_error(sc, "key time must not be negative");
    return add_key(sc, t, when, v, n, 0);
}

static int cmd_keycolor(fx_scene *sc)
{
    STATE(st);
    track *t;
    TRY(arg_track(sc, st, 1, &t));
    fx16 when;
    fx_color c;
    TRY(fx_scene_arg_fx16(sc, &when));
    TRY(fx_scene_arg_color(sc, &c));
    TRY(fx_scene_end(sc));
    if (when < 0)
        return fx_scene_error(sc, "key time must not be negative");
    fx16 v[4];
    for (int i = 0; i < 4; i++)
        v[i] = fx16_from_int((int32_t)(c >> (24 - 8 * i) & 255));
    return add_key(sc, t, when, v, 4, 1);
}

static int cmd_interp(fx_scene *sc)
{
    static const char *const modes[] = {"linear", "spline", "step", 0};
    STATE(st);
    track *t;
    TRY(arg_track(sc, st, 1, &t));
    int m = fx_scene_arg_choice(sc, modes);
    TRY(m);
    TRY(fx_scene_end(sc));
    t->interp = (uint8_t)m;
    return 0;
}

static int cmd_ease(fx_scene *sc)
{
    STATE(st);
    track *t;
    TRY(arg_track(sc, st, 1, &t));
    int e = fx_scene_arg_choice(sc, eases);
    TRY(e);
    TRY(fx_scene_end(sc));
    t->ease = (uint8_t)e;
    return 0;
}

/* ---- using a track ---- */

static int32_t chan8(fx16 v)
{
    int32_t c = fx16_round(v);
    return c < 0 ? 0 : c > 255 ? 255 : c;
}

static int need(fx_scene *sc, const track *t, int n, const char *what)
{
    if (t->nch < n)
        return fx_scene_error(sc, "track '%s' has %d value%s per key; %s needs %d", t->name, t->nch,
                              t->nch == 1 ? "" : "s", what, n);
    return 0;
}

static int cmd_tween(fx_scene *sc)
{
    static const char *const uses[] = {"translate", "rotate", "scale",  "color",   "follow",
                                       "translate3d", "rotatex", "rotatey", "rotatez", "camera", 0};
    STATE(st);
    track *t;
    TRY(arg_track(sc, st, 0, &t));
    int use = fx_scene_arg_choice(sc, uses);
    TRY(use);
    TRY(fx_scene_end(sc));
    fx16 v[FX_ANIM_MAX_CH];
    TRY(track_at(sc, st, t, v));
    fx_xform2 m;
    fx_mat4 m3;
    switch (use) {
    case 0: /* translate */
    case 4: /* follow: translate, then turn to the direction of motion */
        TRY(need(sc, t, 2, uses[use]));
        fx_xform2_translation(&m, v[0], v[1]);
        break;
    case 1: /* rotate DEG about (v1, v2) when given */
        fx_xform2_rotation(&m, fx_angle_from_deg16(v[0]), t->nch >= 3 ? v[1] : 0, t->nch >= 3 ? v[2] : 0);
        break;
    case 2:
        fx_xform2_scaling(&m, v[0], t->nch >= 2 ? v[1] : v[0], 0, 0);
        break;
    case 3: { /* color: a colour track (A R G B) or numbers R G B [A] */
        fx_color c;
        if (t->color)
            c = (fx_color)chan8(v[0]) << 24 | (fx_color)chan8(v[1]) << 16 | (fx_color)chan8(v[2]) << 8 |
                (fx_color)chan8(v[3]);
        else {
            TRY(need(sc, t, 3, "color"));
            c = (fx_color)(t->nch >= 4 ? chan8(v[3]) : 255) << 24 | (fx_color)chan8(v[0]) << 16 |
                (fx_color)chan8(v[1]) << 8 | (fx_color)chan8(v[2]);
        }
        fx_ctx_set_color(&sc->ctx, c);
        return 0;
    }
    case 5:
        TRY(need(sc, t, 3, "translate3d"));
        fx_mat4_translate(&m3, v[0], v[1], v[2]);
        return fx_scene_3d_model(sc, &m3);
    case 6:
    case 7:
    case 8:
        (use == 6 ? fx_mat4_rotate_x : use == 7 ? fx_mat4_rotate_y : fx_mat4_rotate_z)(&m3,
                                                                                      fx_angle_from_deg16(v[0]));
        return fx_scene_3d_model(sc, &m3);
    default: { /* camera: eye (and look) from the track, up +y */
        TRY(need(sc, t, 3, "camera"));
        fx_vec3 eye = fx_vec3_make(v[0], v[1], v[2]), look;
        if (t->nch >= 6) {
            look = fx_vec3_make(v[3], v[4], v[5]);
        } else { /* look along the path */
            fx16 d[FX_ANIM_MAX_CH];
            fx_anim_track a = view(t);
            fx_anim_tangent(&a, st->clock, d);
            if (!d[0] && !d[1] && !d[2])
                return fx_scene_error(sc, "camera: track '%s' does not move, so it has no direction", t->name);
            look = fx_vec3_make(fx_sat32((int64_t)v[0] + d[0]), fx_sat32((int64_t)v[1] + d[1]),
                                fx_sat32((int64_t)v[2] + d[2]));
        }
        return fx_scene_3d_camera(sc, eye, look, fx_vec3_make(0, FX16_ONE, 0));
    }
    }
    fx_xform2 *ctm = fx_scene_ctm(sc);
    if (!ctm)
        return -FX_ENOMEM;
    fx_xform2_pre(ctm, &m);
    if (use == 4) {
        fx16 d[FX_ANIM_MAX_CH];
        fx_anim_track a = view(t);
        fx_anim_tangent(&a, st->clock, d);
        if (d[0] || d[1]) {
            fx_xform2_rotation(&m, fx_atan2(d[1], d[0]), 0, 0); /* y down: the heading measured clockwise */
            fx_xform2_pre(ctm, &m);
        }
    }
    return 0;
}

/* A Q16.16 point through the current transform, rounded to a pixel. */
static void map(fx_scene *sc, fx16 x, fx16 y, int32_t *ox, int32_t *oy)
{
    fx_pt16 p = {x, y};
    if (sc->ctx.xform)
        p = fx_xform2_apply(sc->ctx.xform, p);
    *ox = fx16_round(p.x);
    *oy = fx16_round(p.y);
}

static int cmd_path(fx_scene *sc)
{
    STATE(st);
    track *t;
    TRY(arg_track(sc, st, 0, &t));
    int32_t steps = 64;
    if (fx_scene_more(sc))
        TRY(fx_scene_arg_int(sc, &steps));
    TRY(fx_scene_end(sc));
    if (steps < 1 || steps > 4096)
        return fx_scene_error(sc, "STEPS %d out of range, expected 1..4096", steps);
    if (!t->n)
        return fx_scene_error(sc, "track '%s' has no keys", t->name);
    TRY(need(sc, t, 2, "path"));
    /* the path itself, without the ease: where the object goes, not when */
    fx_anim_track a = view(t);
    a.ease = FX_EASE_NONE;
    int64_t t0 = t->keys[0].t, span = (int64_t)t->keys[t->n - 1].t - t0;
    int32_t px = 0, py = 0;
    for (int32_t i = 0; i <= steps; i++) {
        fx16 v[FX_ANIM_MAX_CH];
        fx_anim_eval(&a, (fx16)(t0 + span * i / steps), v);
        int32_t x, y;
        map(sc, v[0], v[1], &x, &y);
        if (i)
            fx_line(&sc->ctx, px, py, x, y);
        else if (!span)
            fx_plot(&sc->ctx, x, y);
        px = x, py = y;
    }
    return 0;
}

/* ---- morphing ---- */

static int cmd_shape(fx_scene *sc)
{
    STATE(st);
    char name[NAME_MAX];
    TRY(fx_scene_arg_word(sc, name, sizeof name));
    shape *s = 0;
    for (int32_t i = 0; i < st->nsh && !s; i++)
        if (same(st->sh[i].name, name))
            s = &st->sh[i];
    if (!s) {
        if (st->nsh == SHAPES)
            return fx_scene_error(sc, "too many shapes (at most %d)", SHAPES);
        s = &st->sh[st->nsh++];
        fx_memcpy(s->name, name, sizeof name);
    }
    int32_t n = 0;
    while (fx_scene_more(sc)) {
        if (n == SHAPE_MAX)
            return fx_scene_error(sc, "at most %d vertices", SHAPE_MAX);
        TRY(fx_scene_arg_fx16(sc, &s->xy[2 * n]));
        TRY(fx_scene_arg_fx16(sc, &s->xy[2 * n + 1]));
        n++;
    }
    TRY(fx_scene_end(sc));
    if (n < 3)
        return fx_scene_error(sc, "a shape needs at least 3 vertices");
    s->n = n;
    return 0;
}

static int arg_shape(fx_scene *sc, anim_state *st, shape **out)
{
    char name[NAME_MAX];
    TRY(fx_scene_arg_word(sc, name, sizeof name));
    for (int32_t i = 0; i < st->nsh; i++)
        if (same(st->sh[i].name, name) && st->sh[i].n) {
            *out = &st->sh[i];
            return 0;
        }
    return fx_scene_error(sc, "no shape '%s' (define it with 'shape' first)", name);
}

/* s = ease((clock - t0) / (t1 - t0)), clamped to [0, 1]. */
static fx16 progress(fx16 clock, fx16 t0, fx16 t1, int ease)
{
    int64_t span = (int64_t)t1 - t0, d = (int64_t)clock - t0;
    fx16 s = d <= 0 ? 0 : d >= span ? FX16_ONE : (fx16)((d * FX16_ONE + span / 2) / span);
    return fx_anim_ease_apply((fx_anim_ease)ease, s);
}

static int cmd_morph(fx_scene *sc)
{
    static const char *const modes[] = {"fill", "outline", "vertices", 0};
    STATE(st);
    shape *a, *b;
    TRY(arg_shape(sc, st, &a));
    TRY(arg_shape(sc, st, &b));
    int mode = fx_scene_arg_choice(sc, modes);
    TRY(mode);
    fx16 t0, t1;
    TRY(fx_scene_arg_fx16(sc, &t0));
    TRY(fx_scene_arg_fx16(sc, &t1));
    int e = FX_EASE_NONE;
    if (fx_scene_more(sc))
        TRY(e = fx_scene_arg_choice(sc, eases));
    TRY(fx_scene_end(sc));
    if (t1 <= t0)
        return fx_scene_error(sc, "morph: T1 must be after T0");
    fx16 *ma = fx_scene_alloc(sc, sizeof(fx16) * 6 * SHAPE_MAX);
    if (!ma)
        return fx_scene_error(sc, "out of scene memory for the morph");
    fx16 *mb = ma + 2 * SHAPE_MAX, *mid = mb + 2 * SHAPE_MAX;
    int32_t n = fx_anim_morph_match(a->xy, a->n, b->xy, b->n, 2, 1, ma, mb, SHAPE_MAX);
    sc->arena_used -= sizeof(fx16) * 6 * SHAPE_MAX; /* scratch: given back (the last allocation) */
    if (n < 0)
        return fx_scene_error(sc, "morph failed: %s", fx_strerror(n));
    fx_anim_morph_at(ma, mb, 2 * n, progress(st->clock, t0, t1, e), mid);
    fx_pt16 *p = (fx_pt16 *)mid;
    if (sc->ctx.xform)
        fx_xform2_apply_pts(sc->ctx.xform, p, p, n);
    if (mode == 0) {
        int starts[2] = {0, n};
        return fx_poly_fill16(&sc->ctx, p, starts, 1);
    }
    for (int32_t i = 0; i < n; i++) {
        int32_t x0 = fx16_round(p[i].x), y0 = fx16_round(p[i].y);
        int32_t x1 = fx16_round(p[(i + 1) % n].x), y1 = fx16_round(p[(i + 1) % n].y);
        fx_line(&sc->ctx, x0, y0, x1, y1);
        if (mode == 2) /* every vertex, the added ones included, as a 3x3 mark */
            fx_fill_rect(&sc->ctx, x0 - 1, y0 - 1, 3, 3);
    }
    return 0;
}

/* ---- the bouncing ball ---- */

static int cmd_bounce(fx_scene *sc)
{
    STATE(st);
    int32_t box[4], r, trail = 0;
    fx16 v[6];
    for (int i = 0; i < 4; i++)
        TRY(fx_scene_arg_int(sc, &box[i]));
    for (int i = 0; i < 6; i++)
        TRY(fx_scene_arg_fx16(sc, &v[i]));
    TRY(fx_scene_arg_int(sc, &r));
    if (fx_scene_more(sc))
        TRY(fx_scene_arg_int(sc, &trail));
    TRY(fx_scene_end(sc));
    if (r < 0 || r > 1024)
        return fx_scene_error(sc, "R %d out of range, expected 0..1024", r);
    if ((int64_t)box[2] - box[0] < 2 * r || (int64_t)box[3] - box[1] < 2 * r)
        return fx_scene_error(sc, "bounce: the box is smaller than the ball");
    fx_anim_ball b = {v[0], v[1], v[2], v[3], v[4], v[5], fx16_from_int(box[0] + r), fx16_from_int(box[2] - r),
                      fx16_from_int(box[3] - r)};
    fx_anim_ball_state s;
    if (fx_anim_ball_at(&b, 0, &s) < 0)
        return fx_scene_error(sc, "bounce: the ball must start inside the box, and values within the limits "
                                  "of docs/ANIMATION.md");
    int32_t px = 0, py = 0;
    for (int32_t i = 0; i <= trail && trail; i++) { /* the path from 0 to the clock */
        fx_anim_ball_at(&b, (fx16)((int64_t)st->clock * i / trail), &s);
        int32_t x, y;
        map(sc, s.x, s.y, &x, &y);
        if (i)
            fx_line(&sc->ctx, px, py, x, y);
        px = x, py = y;
    }
    fx_anim_ball_at(&b, st->clock, &s);
    int32_t x, y;
    map(sc, s.x, s.y, &x, &y);
    fx_disc(&sc->ctx, x, y, r);
    return 0;
}

/* ---- kinematics (issue #44): an arm reaching a target ---- */

/* X Y and the lengths L... of an arm command; the chain from the base along
 * +x with every joint at 0 (the straight arm) as the starting pose. */
static int arm_args(fx_scene *sc, int32_t *xy, int nxy, fx16 *speed, int32_t *steps, fx16 *len, int32_t *n)
{
    for (int i = 0; i < nxy; i++)
        TRY(fx_scene_arg_int(sc, &xy[i]));
    if (speed) {
        TRY(fx_scene_arg_fx16(sc, speed));
        TRY(fx_scene_arg_int(sc, steps));
    }
    int64_t sum = 0;
    *n = 0;
    while (fx_scene_more(sc)) {
        int32_t l;
        if (*n == FX_KIN_MAX_JOINTS)
            return fx_scene_error(sc, "at most %d links (FX_KIN_MAX_JOINTS)", FX_KIN_MAX_JOINTS);
        TRY(fx_scene_arg_int(sc, &l));
        sum += l;
        len[(*n)++] = fx16_from_int(l);
    }
    TRY(fx_scene_end(sc));
    if (!*n)
        return fx_scene_error(sc, "an arm needs at least one link length");
    if (sum > FX_KIN_REACH)
        return fx_scene_error(sc, "the links' total length %lld is over %d (FX_KIN_REACH)", (long long)sum,
                              FX_KIN_REACH);
    return 0;
}

/* The chain (links, a ring at each joint, a dot at the end) and the target
 * (a ringed cross). */
static void draw_arm(fx_scene *sc, const fx_kin_chain *c, const fx_angle *theta, fx16 tx, fx16 ty)
{
    fx16 p[2 * (FX_KIN_MAX_JOINTS + 1)];
    int32_t x[FX_KIN_MAX_JOINTS + 1], y[FX_KIN_MAX_JOINTS + 1];
    fx_kin_forward(c, theta, p);
    for (int32_t i = 0; i <= c->n; i++)
        map(sc, p[2 * i], p[2 * i + 1], &x[i], &y[i]);
    for (int32_t i = 0; i < c->n; i++)
        fx_line(&sc->ctx, x[i], y[i], x[i + 1], y[i + 1]);
    for (int32_t i = 0; i < c->n; i++)
        fx_circle(&sc->ctx, x[i], y[i], 4);
    fx_disc(&sc->ctx, x[c->n], y[c->n], 3);
    int32_t gx, gy;
    map(sc, tx, ty, &gx, &gy);
    fx_line(&sc->ctx, gx - 6, gy, gx + 6, gy);
    fx_line(&sc->ctx, gx, gy - 6, gx, gy + 6);
    fx_circle(&sc->ctx, gx, gy, 6);
}

static int cmd_arm(fx_scene *sc)
{
    int32_t v[4], n;
    fx16 len[FX_KIN_MAX_JOINTS];
    fx_angle theta[FX_KIN_MAX_JOINTS] = {0};
    TRY(arm_args(sc, v, 4, 0, 0, len, &n));
    fx_kin_chain c = {fx16_from_int(v[0]), fx16_from_int(v[1]), 0, n, len};
    fx16 tx = fx16_from_int(v[2]), ty = fx16_from_int(v[3]);
    if (fx_kin_ccd(&c, theta, tx, ty, FX16_ONE / 64, ARM_SWEEPS, 0) < 0)
        return fx_scene_error(sc, "arm: a coordinate is past +-%d (FX_KIN_COORD)", FX_KIN_COORD);
    draw_arm(sc, &c, theta, tx, ty);
    return 0;
}

static int cmd_armgoal(fx_scene *sc)
{
    int32_t v[4], n, steps;
    fx16 len[FX_KIN_MAX_JOINTS], speed, trail[2 * ARM_STEPS];
    fx_angle theta[FX_KIN_MAX_JOINTS] = {0};
    TRY(arm_args(sc, v, 4, &speed, &steps, len, &n));
    if (steps < 0 || steps > ARM_STEPS)
        return fx_scene_error(sc, "STEPS %d out of range, expected 0..%d", steps, ARM_STEPS);
    fx_kin_chain c = {fx16_from_int(v[0]), fx16_from_int(v[1]), 0, n, len};
    fx16 px, py, gx = fx16_from_int(v[2]), gy = fx16_from_int(v[3]);
    fx16 p[2 * (FX_KIN_MAX_JOINTS + 1)];
    fx_kin_forward(&c, theta, p); /* the aim starts at the straight arm's end */
    px = p[2 * n], py = p[2 * n + 1];
    if (fx_kin_follow(&c, theta, &px, &py, gx, gy, speed, steps, FX16_ONE / 64, ARM_SWEEPS, trail) < 0)
        return fx_scene_error(sc, "armgoal: the straight arm's end, where the aim starts, is past +-%d "
                                  "(FX_KIN_COORD)", FX_KIN_COORD);
    int32_t ox, oy;
    map(sc, p[2 * n], p[2 * n + 1], &ox, &oy);
    for (int32_t f = 0; f < steps; f++) { /* the end's path, frame by frame */
        int32_t x, y;
        map(sc, trail[2 * f], trail[2 * f + 1], &x, &y);
        fx_line(&sc->ctx, ox, oy, x, y);
        ox = x, oy = y;
    }
    draw_arm(sc, &c, theta, gx, gy);
    return 0;
}

/* ---- motion blur ---- */

int fx_scene_anim_recording(const fx_scene *sc)
{
    const anim_state *st = sc->mod[FX_SCENE_MOD_ANIM];
    return st && st->recording;
}

int fx_scene_anim_record(fx_scene *sc, const char *line, size_t len, int lineno)
{
    anim_state *st = sc->mod[FX_SCENE_MOD_ANIM];
    if (st->nlines == REC_LINES)
        return fx_scene_error(sc, "blur block too long (at most %d lines)", REC_LINES);
    if (len > (size_t)(REC_BYTES - st->rec_len))
        return fx_scene_error(sc, "blur block too long (at most %d bytes)", REC_BYTES);
    fx_memcpy(st->rec + st->rec_len, line, len);
    st->line_at[st->nlines] = st->rec_len;
    st->line_len[st->nlines] = (int32_t)len;
    st->line_no[st->nlines++] = lineno;
    st->rec_len += (int32_t)len;
    return 0;
}

static int cmd_blur(fx_scene *sc)
{
    STATE(st);
    int32_t n;
    fx16 shutter;
    TRY(fx_scene_arg_int(sc, &n));
    TRY(fx_scene_arg_fx16(sc, &shutter));
    TRY(fx_scene_end(sc));
    if (n < 1 || n > 64)
        return fx_scene_error(sc, "N %d out of range, expected 1..64", n);
    if (shutter < 0)
        return fx_scene_error(sc, "SHUTTER must not be negative");
    if (st->replaying)
        return fx_scene_error(sc, "blur blocks do not nest");
    if (!st->rec && !(st->rec = fx_scene_alloc(sc, REC_BYTES)))
        return fx_scene_error(sc, "out of scene memory for the blur block");
    st->recording = 1;
    st->blur_n = n;
    st->shutter = shutter;
    st->rec_len = st->nlines = 0;
    return 0;
}

/* Each sub-frame starts from the state 'blur' left (the arena, the context
 * and the pixels are put back), is drawn at its time, and is added to the
 * accumulation buffer; the average is the picture, and the state after
 * 'endblur' is the state before 'blur' (the block's colours and transforms
 * end with it). */
static int cmd_endblur(fx_scene *sc)
{
    STATE(st);
    TRY(fx_scene_end(sc));
    if (!st->recording)
        return fx_scene_error(sc, "'endblur' without 'blur'");
    st->recording = 0;
    st->replaying = 1;
    /* the snapshot and the accumulation in the surface's own rows: after
     * 'coords course' the context's view has a negative stride */
    fx_surface scr = fx_scene_screen_surf(&sc->ctx);
    const fx_surface *s = &scr;
    size_t used0 = sc->arena_used, pix = (size_t)s->h * (size_t)s->stride;
    uint8_t *snap = fx_scene_alloc(sc, used0), *pixels = fx_scene_alloc(sc, pix);
    void *acc_mem = fx_scene_alloc(sc, fx_accum_size(s->w, s->h));
    fx_accum acc;
    if (!snap || !pixels || !acc_mem || fx_accum_init(&acc, acc_mem, fx_accum_size(s->w, s->h), s->w, s->h) < 0) {
        sc->arena_used = used0;
        st->replaying = 0;
        return fx_scene_error(sc, "out of scene memory for motion blur (%llu bytes)",
                              (unsigned long long)(used0 + pix + fx_accum_size(s->w, s->h)));
    }
    fx_memcpy(snap, sc->arena, used0);
    fx_memcpy(pixels, scr.pixels, pix);
    fx_ctx ctx = sc->ctx;
    void *mod[FX_SCENE_MOD_COUNT];
    fx_memcpy(mod, sc->mod, sizeof mod);
    size_t used1 = sc->arena_used;
    int32_t n = st->blur_n, lines = st->nlines;
    fx16 t0 = st->clock, shutter = st->shutter;
    int r = 0;
    for (int32_t k = 0; k < n && r >= 0; k++) {
        fx_memcpy(sc->arena, snap, used0);
        fx_memcpy(sc->mod, mod, sizeof mod);
        sc->ctx = ctx;
        sc->arena_used = used1;
        fx_memcpy(scr.pixels, pixels, pix);
        st->clock = fx_sat32((int64_t)t0 + (int64_t)shutter * k / n);
        for (int32_t i = 0; i < lines && r >= 0; i++)
            r = fx_scene_exec_line(sc, st->rec + st->line_at[i], (size_t)st->line_len[i], st->line_no[i]);
        if (r >= 0)
            r = fx_accum_add(&acc, &scr);
    }
    fx_memcpy(sc->arena, snap, used0);
    fx_memcpy(sc->mod, mod, sizeof mod);
    sc->ctx = ctx;
    if (r >= 0)
        fx_accum_resolve(&acc, &scr);
    else
        fx_memcpy(scr.pixels, pixels, pix);
    sc->arena_used = used0;
    st->replaying = 0;
    return r;
}

int fx_scene_end_script(fx_scene *sc)
{
    const anim_state *st = sc->mod[FX_SCENE_MOD_ANIM];
    if (st && st->recording)
        return fx_scene_error(sc, "'blur' block without 'endblur' at the end of the script");
    return 0;
}

#define D FX_SCENE_DRAWS
const fx_scene_cmd fx_scene_cmds_anim[] = {
    {"time", cmd_time, "time T (the clock, seconds; a host's --frames sets it instead)", 0},
    {"key", cmd_key, "key NAME T V... (a key of track NAME at time T: up to 8 values)", 0},
    {"keycolor", cmd_keycolor, "keycolor NAME T #AARRGGBB (a colour key)", 0},
    {"interp", cmd_interp, "interp NAME linear|spline|step (in-betweens of the track; default spline)", 0},
    {"ease", cmd_ease, "ease NAME none|in|out|inout|smooth (time warp over the track's keys)", 0},
    {"tween", cmd_tween,
     "tween NAME translate|rotate|scale|color|follow|translate3d|rotatex|rotatey|rotatez|camera (the track at the "
     "clock applied)",
     D},
    {"path", cmd_path, "path NAME [STEPS] (the track's path through channels 0 and 1, drawn)", D},
    {"shape", cmd_shape, "shape NAME X0 Y0 X1 Y1 X2 Y2 ... (an outline for 'morph')", 0},
    {"morph", cmd_morph, "morph A B fill|outline|vertices T0 T1 [none|in|out|inout|smooth] (A at T0 to B at T1)", D},
    {"bounce", cmd_bounce, "bounce X0 Y0 X1 Y1 X Y VX VY G E R [TRAIL] (a ball in the box at the clock)", D},
    /* the accumulation reads and writes the whole clip rectangle, not a band's rows */
    {"arm", cmd_arm, "arm X Y TX TY L1 [L2 ...] (a chain of links from X Y reaching for TX TY by CCD)", D},
    {"armgoal", cmd_armgoal,
     "armgoal X Y GX GY SPEED STEPS L1 [L2 ...] (the arm's end moving toward GX GY, SPEED a step, for STEPS steps)",
     D},
    {"blur", cmd_blur, "blur N SHUTTER (the lines up to 'endblur' drawn at N times across SHUTTER, averaged)",
     D | FX_SCENE_SERIAL},
    {"endblur", cmd_endblur, "endblur", D | FX_SCENE_SERIAL},
    {0, 0, 0, 0},
};
