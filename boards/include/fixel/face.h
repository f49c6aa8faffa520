/* SPDX-License-Identifier: MIT */
/* fixel — smooth text from real fonts (issue #37): TrueType/OpenType read
 * by FreeType, UTF-8 shaped by HarfBuzz, mixed directions ordered by
 * FriBiDi, fonts found by fontconfig, lines broken by libunibreak (UAX #14).
 * Boards side: it opens files and allocates; the core only blends the
 * coverage masks (fixel/mask.h, which has the blend rule).
 *
 * Built without those libraries (boards/text/absent), every function that
 * can fail returns -FX_ENOTSUP with an error text saying which packages
 * are missing; fx_face_available() says so up front.
 *
 * Units: sizes are pixels per em; positions and advances are pixels, except
 * fx_glyph's, which are HarfBuzz's 26.6 fixed point (1/64 px). y grows down
 * on screen; a baseline y is the row the glyphs sit on.
 *
 * Pixels are exact and the same on every board: FreeType's rasterizer and
 * hinting and HarfBuzz's positioning are integer (26.6); each glyph is
 * rendered at a whole-pixel origin (pen positions round to nearest, ties
 * up) so a glyph is one cache entry whatever its position. The versions the
 * goldens were made with are in docs/TEXT.md.
 *
 * A face is not thread-safe: one thread at a time per face. */
#ifndef FIXEL_FACE_H
#define FIXEL_FACE_H

#include <stddef.h>
#include <stdint.h>
#include "fixel/draw.h"
#include "fixel/fixed.h"
#include "fixel/mask.h"
#include "fixel/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct fx_face fx_face;

#define FX_FACE_MAX_PX 1024            /* sizes 1..FX_FACE_MAX_PX pixels per em */
#define FX_FACE_CACHE_DEFAULT (256u << 10) /* glyph cache bound when opts say 0 */
#define FX_FACE_MAX_FONTS 8            /* the font and its fallbacks */
#define FX_FACE_MAX_TEXT (16u << 20)   /* longest string a call takes, bytes */

typedef struct fx_face_opts {
    int32_t weight;       /* OpenType weight: 400 regular, 700 bold; 0 = 400 */
    uint8_t italic;       /* 1: ask fontconfig for an italic/oblique style */
    uint8_t no_fallback;  /* 1: only the named font (no fontconfig chain) */
    uint32_t cache_bytes; /* glyph cache bound in bytes; 0 = FX_FACE_CACHE_DEFAULT */
    unsigned mask_flags;  /* passed to fx_mask_blend: FX_MASK_GAMMA or 0 */
    const char *features; /* OpenType features, e.g. "tnum,-liga"; NULL: none */
} fx_face_opts;

/* 1 when fixel was built with FreeType, HarfBuzz, FriBiDi, fontconfig and
 * libunibreak; 0 otherwise (every call then fails with -FX_ENOTSUP). */
int fx_face_available(void);

/* Open a face: name is a file (it contains a '/' or ends in .ttf, .otf,
 * .ttc, .pfb, .pcf, .bdf; an OpenType collection's first face) or a
 * fontconfig family ("DejaVu Sans", "sans-serif", "monospace:bold"). px is
 * the size in pixels per em (1..FX_FACE_MAX_PX). Unless opts->no_fallback,
 * fontconfig's sorted list for the family (or for "sans-serif" after a
 * file) gives up to FX_FACE_MAX_FONTS - 1 fallbacks, opened when a code
 * point first needs one. opts may be NULL (the defaults). On failure
 * returns a negative code, *out is NULL and err (when not NULL) holds a
 * message naming the file or family and the cause: -FX_ENOENT (no such
 * file, no font for the family), -FX_EBADMSG (FreeType cannot read it:
 * truncated or not a font), -FX_ERANGE (size out of range), -FX_EINVAL
 * (bad features), -FX_ENOMEM, -FX_ENOTSUP (built without the libraries). */
int fx_face_open(const char *name, int32_t px, const fx_face_opts *opts, fx_face **out, char *err, size_t errsz);
void fx_face_close(fx_face *f);
/* Release fontconfig's process-wide configuration (FcFini) so that leak
 * checkers see a clean exit. Only after every face is closed, and only when
 * nothing else in the process still uses fontconfig; a later fx_face_open
 * loads it again. */
void fx_face_shutdown(void);

/* Change the size (1..FX_FACE_MAX_PX, else -FX_ERANGE, size unchanged).
 * Cached glyphs of other sizes stay until the LRU evicts them. */
int fx_face_set_size(fx_face *f, int32_t px);
int32_t fx_face_size(const fx_face *f);
/* Replace the OpenType features: comma- or space-separated HarfBuzz feature
 * strings ("tnum", "-liga", "ss01=1", "kern[3:5]=0"). -FX_EINVAL naming
 * the bad one (features unchanged); NULL or "" clears them. */
int fx_face_set_features(fx_face *f, const char *list);
/* The last error's text (never NULL; "" when none). */
const char *fx_face_error(const fx_face *f);
/* The file of font i of the chain (0: the primary), NULL past the end. */
const char *fx_face_file(const fx_face *f, int i);

/* ---- the glyph cache ---- */
typedef struct fx_face_stats {
    uint64_t hits, misses, evictions;
    size_t bytes, limit; /* in use (masks + entries) and the bound */
    uint32_t entries;
} fx_face_stats;
void fx_face_cache_stats(const fx_face *f, fx_face_stats *st);

/* ---- shaping ----
 * One line of text: UTF-8 (an invalid byte becomes U+FFFD), its levels
 * resolved by FriBiDi (paragraph direction from its first strong character),
 * cut into runs of one level, one font (the first of the chain with the code
 * point; combining marks stay with their base; a code point no font has
 * takes the primary font's .notdef box) and one script, each shaped by
 * HarfBuzz, the runs in visual order (UAX #9 rule L2). Line breaks in s are
 * treated as spaces here; fx_face_draw_box splits paragraphs. */
typedef struct fx_glyph {
    uint32_t id;       /* glyph index in its font */
    uint32_t cluster;  /* byte offset in s of the cluster it belongs to */
    int32_t x_advance, y_advance, x_offset, y_offset; /* 26.6, y up (HarfBuzz's) */
    uint8_t font;      /* index in the chain (fx_face_file) */
    uint8_t level;     /* bidi embedding level: odd = right to left */
} fx_glyph;
/* Shape s[0, len); *out points to the glyphs in visual order, valid until
 * the next call on f. Returns the glyph count or a negative code
 * (-FX_E2BIG over FX_FACE_MAX_TEXT, -FX_ENOMEM). */
int fx_face_shape(fx_face *f, const char *s, size_t len, const fx_glyph **out);

/* ---- layout ---- */
typedef struct fx_text_metrics {
    int32_t advance;      /* pen advance in pixels (rounded 26.6 sum) */
    int32_t ascent;       /* font's ascent above the baseline, > 0 */
    int32_t descent;      /* font's descent below it, > 0 */
    int32_t line_height;  /* baseline to baseline */
    fx_rect ink;          /* inked pixels relative to the origin on the
                           * baseline (y down); empty (all 0) for no ink */
    int32_t glyphs;
} fx_text_metrics;
/* Measure one line. Returns 0 or a negative code. */
int fx_face_measure(fx_face *f, const char *s, size_t len, fx_text_metrics *m);

/* Draw one line with its origin (pen start, baseline) at (x, y), turned by
 * rot quarter turns clockwise around that point (fx_rot: text on a panel
 * mounted sideways; each glyph is rendered upright and its mask rotated,
 * not a bitmap of the line). Colour, clip and blend mode are c's. Returns
 * the advance in pixels or a negative code. */
int fx_face_draw(fx_face *f, const fx_ctx *c, int32_t x, int32_t y, const char *s, size_t len, unsigned rot);

enum fx_text_align { FX_ALIGN_LEFT = 0, FX_ALIGN_CENTRE = 1, FX_ALIGN_RIGHT = 2 };

typedef struct fx_textbox {
    fx_rect box;          /* half-open; text is wrapped to its width */
    uint8_t align;        /* fx_text_align, for every line */
    uint8_t ellipsis;     /* 1: a text longer than the box ends in "…" */
    uint8_t no_wrap;      /* 1: one line per paragraph, cut (or ellipsized) */
    fx16 line_spacing;    /* times the font's line height; 0 = 1.0 */
} fx_textbox;

/* Lay s out in b->box and draw it through c (c NULL: lay out only, for
 * measuring). Paragraphs split at '\n'; lines break at UAX #14 opportunities
 * (libunibreak), a word wider than the box at code points. Lines whose
 * baseline-to-descent band does not fit the box's height are not drawn;
 * with ellipsis the last drawn line ends in U+2026 (or "..." when the font
 * lacks it). *lines (may be NULL) gets the number of lines drawn and
 * *overflow (may be NULL) 1 when text was left out, else 2 when a word was
 * cut at code points, else 0. Work is bounded by the
 * box: text past the last line that fits is not shaped. Returns 0 or a
 * negative code. */
int fx_face_draw_box(fx_face *f, const fx_ctx *c, const fx_textbox *b, const char *s, size_t len, int32_t *lines,
                     int *overflow);

/* The largest size in [min_px, max_px] at which s fits b (every line
 * drawn, no word cut at code points: fx_face_draw_box's overflow 0), found by bisection (fits is taken
 * as monotonic in the size); the face is left at that size. Returns it, or
 * -FX_ERANGE when even min_px does not fit (size left at min_px). */
int32_t fx_face_fit(fx_face *f, const fx_textbox *b, const char *s, size_t len, int32_t min_px, int32_t max_px);

/* ---- scene scripts ----
 * The fx_scene_text_host behind 'font FAMILY|FILE SIZE ...', 'text' and
 * 'textbox' (fixel/scene.h): set sc->text_host = fx_face_scene_host(fs)
 * after fx_scene_init. Faces are opened once per name, size, weight and
 * features and shared by every scene using fs (and the bands of a banded
 * one, under a lock) until fx_face_scene_free. fx_face_scene_new returns
 * NULL when out of memory; built without the libraries it returns a host
 * whose 'font' fails naming the packages. */
typedef struct fx_face_scene fx_face_scene;
fx_face_scene *fx_face_scene_new(void);
const fx_scene_text_host *fx_face_scene_host(const fx_face_scene *fs);
void fx_face_scene_free(fx_face_scene *fs);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
