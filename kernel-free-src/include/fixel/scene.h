/* SPDX-License-Identifier: MIT */
/* fixel — the scene-script language: parser and interpreter on a surface.
 *
 * One command per line; '#' starts a comment; integers are decimal (a sign
 * is allowed); fixed-point values are decimal fractions parsed exactly;
 * colours are #RRGGBB (opaque) or #AARRGGBB; strings are double-quoted with
 * \" and \\ escapes. Errors carry the line and column of the offending token.
 *
 * The interpreter is pure: the host (fixel-draw, the kiosk, tests) supplies
 * the surface, file loading, tracing and presentation through fx_scene_host,
 * and all memory through an arena it hands over at init.
 *
 * Each module adds its commands in its own file (scene_<module>.c) as a
 * NULL-terminated fx_scene_cmd table, listed once in scene.c.
 */
#ifndef FIXEL_SCENE_H
#define FIXEL_SCENE_H

#include <stddef.h>
#include <stdint.h>
#include "fixel/draw.h"
#include "fixel/fixed.h"

struct fx_rt_scene; /* fixel/rt.h */

#ifdef __cplusplus
extern "C" {
#endif

typedef struct fx_scene fx_scene;

typedef struct fx_scene_host {
    void *user;
    /* Create the drawing surface (called once, before the first command that
     * draws). Returns 0 or a negative error. */
    int (*make_surface)(void *user, int32_t w, int32_t h, fx_format f, fx_surface *out);
    /* Read a whole file named by the script; the data stays valid until the
     * scene ends. NULL: file commands fail with "files not available". */
    int (*load_file)(void *user, const char *path, const uint8_t **data, size_t *len);
    /* Show the surface now ('present' command; live displays). May be NULL. */
    int (*present)(void *user);
    /* Receives --trace lines; NULL: tracing off. */
    fx_trace_fn trace;
    /* Decode an image file named by the script ('texture image PATH') into
     * a surface whose pixels the host owns until the scene ends. NULL:
     * image commands fail with "images not available". */
    int (*load_image)(void *user, const char *path, fx_surface *out);
} fx_scene_host;

/* Render the ray-traced rectangle [x, x + w) x [y, y + h) of surf (the
 * 'raytrace' command; clipped to surf) with the pixels fx_rt_render would
 * leave, but where the host likes: on several threads, showing rows as
 * they finish. user is the host's. Returns 0 or a negative error. */
typedef int (*fx_scene_raytrace_fn)(void *user, const struct fx_rt_scene *s, const fx_surface *surf, int32_t x,
                                    int32_t y, int32_t w, int32_t h);

/* Smooth text from real fonts (fixel/face.h) lives on the boards side, so
 * the host lends it to the scene ('font FAMILY|FILE SIZE ...', and 'text' /
 * 'textbox' while such a font is current). Set sc->text_host after
 * fx_scene_init; NULL: those forms fail with "smooth fonts are not
 * available". Banded scenes (fx_scene_run_mt) call it from several
 * threads at once: the host serialises what needs it. */
typedef struct fx_scene_text_host {
    void *user;
    /* Open (or find) the font: name a file or fontconfig family, px its size,
     * weight 0 (regular) or 1..1000, features HarfBuzz feature strings
     * separated by commas or spaces ("" for none). *face is the host's
     * handle, valid until the scene ends. 0, or a negative error with a
     * message in err. */
    int (*open)(void *user, const char *name, int32_t px, int32_t weight, const char *features, void **face,
                char *err, size_t errsz);
    /* Draw s[0, len) (UTF-8) through c: w <= 0 draws one unwrapped line per
     * '\n' paragraph from the top-left corner (x, y) (the first baseline at
     * y + the font's ascent); w > 0 wraps it into the box (x, y, w, h),
     * aligned 0 left, 1 centre, 2 right, ending in an ellipsis when cut
     * and ellipsis is set. 0, or a negative error with a message in err. */
    int (*draw)(void *user, void *face, const fx_ctx *c, int32_t x, int32_t y, int32_t w, int32_t h, int align,
                int ellipsis, const char *s, size_t len, char *err, size_t errsz);
} fx_scene_text_host;

/* Per-module state lives in the arena, found through these slots. */
enum {
    FX_SCENE_MOD_RASTER,
    FX_SCENE_MOD_CONIC,
    FX_SCENE_MOD_TEXT,
    FX_SCENE_MOD_CLIP,
    FX_SCENE_MOD_FILL,
    FX_SCENE_MOD_3D,
    FX_SCENE_MOD_FRACTAL,
    FX_SCENE_MOD_VIZ,
    FX_SCENE_MOD_INPUT,
    FX_SCENE_MOD_APP,
    FX_SCENE_MOD_RT,
    FX_SCENE_MOD_VSD,
    FX_SCENE_MOD_OBJECTS,
    FX_SCENE_MOD_ANIM,
    FX_SCENE_MOD_COUNT
};

struct fx_scene {
    fx_scene_host host;
    fx_ctx ctx;
    int have_surface;
    int32_t w, h;
    fx_format format;
    uint8_t size_fixed, format_fixed; /* set by the host: script 'size'/'format' ignored */
    /* set by the host after fx_scene_init (kept out of fx_scene_host so
     * its initialisers stay as they are); NULL: the core ray traces on the
     * calling thread (in a banded scene: only the band's part). A banded
     * scene hands it the whole rectangle */
    fx_scene_raytrace_fn raytrace;
    /* arena */
    uint8_t *arena;
    size_t arena_size, arena_used;
    void *mod[FX_SCENE_MOD_COUNT];
    /* the line being run */
    const char *text;
    int len, pos, lineno, tok_col, cmd_col;
    /* the first error */
    int err_line, err_col;
    char err[200];
    /* banded rendering (fx_scene_set_band): every clip this scene draws
     * through is intersected with band; set by a parallel player */
    int banded;
    fx_rect band;
    /* smooth text, the host's (fx_scene_text_host); NULL: not available */
    const fx_scene_text_host *text_host;
};

typedef struct fx_scene_cmd {
    const char *name;
    int (*run)(fx_scene *sc);
    const char *usage; /* e.g. "line X0 Y0 X1 Y1" */
    unsigned flags;    /* FX_SCENE_DRAWS: needs the surface */
} fx_scene_cmd;
#define FX_SCENE_DRAWS 1u
/* The command cannot be drawn in bands (fx_scene_set_band): it reads pixels
 * other than the ones it writes (seed fills), writes outside the clip, or
 * shows the surface mid-frame. A parallel player runs a script holding one
 * on a single thread. */
#define FX_SCENE_SERIAL 2u

/* Set up a scene: default size 320x240 XRGB8888, colour white. The arena
 * (any size and alignment; 0 is allowed) holds module state such as depth
 * buffers; the scene uses it from its first 8-byte boundary, in whole
 * 8-byte units (sc->arena, sc->arena_size say what it uses). */
void fx_scene_init(fx_scene *sc, const fx_scene_host *host, void *arena, size_t arena_size);
/* Force size/format regardless of the script (command-line overrides). */
void fx_scene_fix_size(fx_scene *sc, int32_t w, int32_t h);
void fx_scene_fix_format(fx_scene *sc, fx_format f);

/* Run a whole script (lines separated by \n; \r\n accepted). Returns 0, or a
 * negative error with sc->err, sc->err_line and sc->err_col set. A script that
 * drew nothing still gets its surface (cleared to black by the host). */
int fx_scene_run(fx_scene *sc, const char *text, size_t len);
/* Run one line (without its newline) as line number lineno. */
int fx_scene_exec_line(fx_scene *sc, const char *line, size_t len, int lineno);
/* Make sure the surface exists (commands flagged FX_SCENE_DRAWS get it for free). */
int fx_scene_surface(fx_scene *sc);
/* After the last line of a script run line by line (fx_scene_run does it):
 * 0, or the error of a block left open ('blur' without 'endblur'). */
int fx_scene_end_script(fx_scene *sc);
/* The animation clock (Q16.16 seconds) the script's tracks, morphs and
 * balls are drawn at: a host rendering frame k at F frames a second sets
 * k / F before running the script, and the script's 'time' lines are then
 * ignored (as 'size' is after fx_scene_fix_size). 0, or -FX_ENOMEM when the
 * arena cannot hold the animation state. */
int fx_scene_set_clock(fx_scene *sc, fx16 t);

/* Banded rendering, for running one script on several threads (the
 * boards side's fx_scene_run_mt, fixel/par.h): every pixel the scene
 * writes is then inside band (surface coordinates; the 3D pipeline's and
 * the ray tracer's targets included), while every primitive still steps
 * exactly as on the whole surface, so scenes on disjoint bands of one
 * surface together draw the one-band picture. Call before the first
 * command; a script clip is intersected with the band. */
void fx_scene_set_band(fx_scene *sc, fx_rect band);
/* 0 when every command of the script can be drawn in bands; else the line
 * number of the first command flagged FX_SCENE_SERIAL (unknown commands
 * count as bandable: running the script reports them). */
int fx_scene_script_serial(const char *text, size_t len);

/* ---- for command implementations ---- */
/* Record an error at the current token and return -FX_EINVAL. */
int fx_scene_error(fx_scene *sc, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* 1 when more arguments follow on the line. */
int fx_scene_more(fx_scene *sc);
/* Error unless the line has no more arguments; later errors then point at
 * the command itself. */
int fx_scene_end(fx_scene *sc);
int fx_scene_arg_int(fx_scene *sc, int32_t *v);
int fx_scene_arg_color(fx_scene *sc, fx_color *v);
int fx_scene_arg_fx16(fx_scene *sc, fx16 *v);
int fx_scene_arg_fx56(fx_scene *sc, fx56 *v);
/* A bare word (letters, digits, '_', '-', '.', '/'), copied NUL-terminated. */
int fx_scene_arg_word(fx_scene *sc, char *buf, size_t size);
/* A double-quoted string, unescaped, NUL-terminated. */
int fx_scene_arg_string(fx_scene *sc, char *buf, size_t size);
/* One of the given words (NULL-terminated list): returns its index. */
int fx_scene_arg_choice(fx_scene *sc, const char *const *choices);
/* Narrow a clip rectangle on the scene's surface to the band (nothing when
 * the scene is not banded): for targets of their own, such as the 3D
 * pipeline's context. */
void fx_scene_band_clip(const fx_scene *sc, fx_rect *clip);
/* Take size bytes (8-byte aligned, zeroed) from the arena; NULL when full. */
void *fx_scene_alloc(fx_scene *sc, size_t size);
/* The same, not zeroed: for buffers the caller fills before reading (a
 * depth buffer, which fx3d clears; in a band only the band's rows). */
void *fx_scene_alloc_raw(fx_scene *sc, size_t size);

/* ---- the argument table (kernel-free-src/scene/scene_args.c) ----
 * Every command declares the type and range of each argument, once. Before a
 * command runs, its line is matched against its entry: a number of the right
 * type outside its declared range, or a repetition beyond its count, is an
 * error at that token naming the range ("expected 0..65535"); anything else
 * (a missing or malformed argument) is left to the command's own messages.
 * fixel-draw --commands prints the table; tests/corners generates its cases
 * from it. */
enum {
    FX_ARG_END,    /* end of the entry */
    FX_ARG_INT,    /* decimal integer, min..max */
    FX_ARG_FX16,   /* decimal fraction as Q16.16; min/max are raw Q16.16 */
    FX_ARG_FX56,   /* decimal fraction as Q8.56; min/max are raw Q8.56 */
    FX_ARG_COLOR,  /* #RRGGBB or #AARRGGBB */
    FX_ARG_WORD,   /* a bare word; name lists the choices, e.g. "evenodd|nonzero" */
    FX_ARG_STRING, /* a double-quoted string */
    FX_ARG_OPT,    /* the arguments after this mark may be left out */
    FX_ARG_FORM,   /* starts an alternative form: name is its keyword, or NULL
                    * for the form taken when the token is no keyword */
    FX_ARG_REPEAT, /* the rest of the form repeats min..max times (max bounds the work) */
};
#define FX_ARG_WORK 1u     /* this argument bounds the work of the command */
#define FX_ARG_OPEN_MIN 2u /* min itself is excluded: min < value <= max */

typedef struct fx_scene_arg {
    uint8_t type;
    uint8_t flags;
    const char *name;
    int64_t min, max;
} fx_scene_arg;

typedef struct fx_scene_argspec {
    const char *cmd;
    const fx_scene_arg *args; /* FX_ARG_END-terminated */
    const char *pre;          /* script lines a test must run first (state the command needs), or NULL */
    const char *work;         /* the bound on the work no single argument sets, or NULL */
} fx_scene_argspec;
/* 3D commands (meshes, OBJ files) draw at most this many triangles each. */
#define FX_SCENE_MAX_TRIANGLES 262144

/* The whole table, NULL-terminated (cmd == NULL). */
extern const fx_scene_argspec fx_scene_argspecs[];
/* The entry of one command, or NULL. */
const fx_scene_argspec *fx_scene_args_find(const char *cmd);
/* "0..65535" or "-32768..32767.99998" for a numeric argument; the length. */
int fx_scene_arg_range(const fx_scene_arg *a, char *buf, size_t size);
/* Check the rest of the line against the command's entry (done by
 * fx_scene_exec_line): 0, or the range error. */
int fx_scene_check_args(fx_scene *sc, const fx_scene_argspec *spec);

/* Every command, for --help and docs; NULL-terminated tables. */
extern const fx_scene_cmd *const fx_scene_tables[];
const fx_scene_cmd *fx_scene_find(const char *name, size_t len);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
