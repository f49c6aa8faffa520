/* fixel — scene commands of the clip module: clip windows and their stack,
 * the line clipper, exterior clipping.
 *
 * Script windows are given by two corner pixels, both inclusive, in either
 * order (the course's xwmin..xwmax): "clip 10 10 50 40" keeps pixels 10..50
 * and 10..40. The context stores the half-open fx_rect {10, 10, 51, 41}. */
#include "fixel/clip.h"
#include "fixel/error.h"
#include "fixel/scene.h"
#include "fx_internal.h"

#define TRY(x)                   \
    do {                         \
        int r_ = (x);            \
        if (r_ < 0)              \
            return r_;           \
    } while (0)

#define CLIP_DEPTH 32

typedef struct clip_state {
    fx_rect saved[CLIP_DEPTH];
    fx_clip_stack stack;
    fx_rect ext;
    int have_ext;
} clip_state;

static clip_state *state(fx_scene *sc)
{
    clip_state *st = sc->mod[FX_SCENE_MOD_CLIP];
    if (!st) {
        st = fx_scene_alloc(sc, sizeof *st);
        if (!st)
            return 0;
        fx_clip_stack_init(&st->stack, st->saved, CLIP_DEPTH);
        sc->mod[FX_SCENE_MOD_CLIP] = st;
    }
    return st;
}

#define STATE(st)                                                      \
    clip_state *st = state(sc);                                        \
    if (!st)                                                           \
        return fx_scene_error(sc, "scene arena full (clip state)")

/* Four integers: two inclusive corner pixels -> half-open rectangle. */
static int arg_window(fx_scene *sc, fx_rect *r)
{
    int32_t v[4];
    for (int i = 0; i < 4; i++)
        TRY(fx_scene_arg_int(sc, &v[i]));
    int64_t x0 = FX_MIN(v[0], v[2]), x1 = (int64_t)FX_MAX(v[0], v[2]) + 1;
    int64_t y0 = FX_MIN(v[1], v[3]), y1 = (int64_t)FX_MAX(v[1], v[3]) + 1;
    r->x0 = (int32_t)x0;
    r->y0 = (int32_t)y0;
    r->x1 = fx_sat32(x1);
    r->y1 = fx_sat32(y1);
    return 0;
}

/* A leading keyword, or -1 (and nothing consumed) when the next token is not
 * one of them. */
static int keyword(fx_scene *sc, const char *const *words)
{
    int save = sc->pos;
    char w[16];
    if (!fx_scene_more(sc) || fx_scene_arg_word(sc, w, sizeof w) < 0) {
        sc->pos = save;
        return -1;
    }
    for (int i = 0; words[i]; i++) {
        const char *a = words[i], *b = w;
        while (*a && *a == *b)
            a++, b++;
        if (!*a && !*b)
            return i;
    }
    sc->pos = save;
    return -1;
}

static int cmd_clip(fx_scene *sc)
{
    static const char *const words[] = {"off", "push", "pop", 0};
    STATE(st);
    fx_rect r;
    int k = keyword(sc, words);
    if (k == 0 || k == 2) {
        TRY(fx_scene_end(sc));
        if (k == 0) {
            fx_ctx_reset_clip(&sc->ctx);
            st->stack.n = 0;
            return 0;
        }
        if (fx_clip_pop(&st->stack, &sc->ctx) < 0)
            return fx_scene_error(sc, "'clip pop' without a matching 'clip push'");
        return 0;
    }
    TRY(arg_window(sc, &r));
    TRY(fx_scene_end(sc));
    if (k == 1) {
        if (fx_clip_push(&st->stack, &sc->ctx, r) < 0)
            return fx_scene_error(sc, "clip stack full (%d windows)", CLIP_DEPTH);
        return 0;
    }
    fx_ctx_set_clip(&sc->ctx, r);
    if (fx_rect_empty(sc->ctx.clip))
        sc->ctx.clip.x1 = sc->ctx.clip.x0, sc->ctx.clip.y1 = sc->ctx.clip.y0;
    return 0;
}

static int cmd_cliplines(fx_scene *sc)
{
    static const char *const names[] = {"direct", "cohen", "liang", "nln", 0};
    int k = fx_scene_arg_choice(sc, names);
    TRY(k);
    TRY(fx_scene_end(sc));
    sc->ctx.line_clipper = (uint8_t)k;
    return 0;
}

static int cmd_exterior(fx_scene *sc)
{
    static const char *const words[] = {"on", "off", 0};
    STATE(st);
    int k = keyword(sc, words);
    if (k >= 0) {
        TRY(fx_scene_end(sc));
        if (k == 1) {
            fx_ctx_exterior_off(&sc->ctx);
            return 0;
        }
        if (!st->have_ext)
            return fx_scene_error(sc, "'exterior on' needs a window first: exterior X0 Y0 X1 Y1");
        fx_ctx_exterior(&sc->ctx, st->ext);
        return 0;
    }
    TRY(arg_window(sc, &st->ext));
    TRY(fx_scene_end(sc));
    st->have_ext = 1;
    fx_ctx_exterior(&sc->ctx, st->ext);
    return 0;
}

const fx_scene_cmd fx_scene_cmds_clip[] = {
    {"clip", cmd_clip, "clip X0 Y0 X1 Y1 (inclusive corners) | clip off | clip push X0 Y0 X1 Y1 | clip pop",
     FX_SCENE_DRAWS},
    {"cliplines", cmd_cliplines, "cliplines direct|cohen|liang|nln", FX_SCENE_DRAWS},
    {"exterior", cmd_exterior, "exterior X0 Y0 X1 Y1 (draw only outside; inclusive corners) | exterior on|off",
     FX_SCENE_DRAWS},
    {0, 0, 0, 0},
};
