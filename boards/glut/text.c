/* SPDX-License-Identifier: MIT */
/* fixel GLUT layer — GLUT's fonts.
 *
 * Bitmap fonts: freeglut's are the X11 core fonts, which Debian ships as PCF
 * in xfonts-base (misc-fixed 8x13, 9x15) and xfonts-75dpi (Adobe Times and
 * Helvetica, 75 dpi). They are read here at first use with FreeType, loaded
 * at run time (dlopen of libfreetype.so.6, so programs link as before and a
 * system without it still runs), from the known X11 font directories. Each
 * glyph is drawn as freeglut draws its own: one glBitmap of the advance's
 * width and the font's cell height (glutBitmapHeight), the cell's
 * lower-left corner at the raster position minus the font's origin, the
 * raster position moved by the advance; ink outside that cell is not drawn
 * (freeglut's data hold only the cell). Characters 1-255 (ISO 8859-1); a
 * code the font lacks is a blank cell as wide as the space, as in
 * freeglut's data. tests/glut/self.sh compares every glyph with freeglut +
 * Mesa (50 of 1,792 differ: today's fonts redrew them), and the fonts*
 * programs of the corpus whole frames.
 *
 * When FreeType or a font file is absent: one log line naming what is
 * missing, then fixel's 6x10 font (scale 2 for TIMES_ROMAN_24 and
 * HELVETICA_18; the two fixed fonts keep their 8/9 pixel advance).
 *
 * Stroke fonts trace the 6x10 glyphs with GL lines through the lit pixels'
 * centres, in GLUT's stroke units (104.762 wide, 119.05 above the baseline);
 * glutStrokeHeight, MONO_ROMAN's advance and the newline of
 * glutStrokeString are freeglut's. freeglut's glyphs and ROMAN's advances
 * are a table of its own: its advances are no one scale of the Hershey
 * simplex Roman's widths (hershey-fonts-data), so they are not derived from
 * it, and not copied. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/font.h"
#include "glut_int.h"

#if defined(FXG_HAVE_FREETYPE)
#include <dlfcn.h>
#include <ft2build.h>
#include FT_FREETYPE_H
#endif

const int fx_glut_font_ids[9] = {0, 1, 2, 3, 4, 5, 6, 7, 8};

static int font_index(const void *font)
{
    const int *p = (const int *)font;
    if (p >= fx_glut_font_ids && p < fx_glut_font_ids + 9)
        return (int)(p - fx_glut_font_ids);
    return -1;
}

/* The seven bitmap fonts (index 2..8 of fx_glut_font_ids): the X font each
 * is, and freeglut's cell for it: height (glutBitmapHeight) and the origin
 * of the cell's lower-left corner below/left of the raster position. */
typedef struct xfont {
    const char *name, *dir, *file; /* FILE-ISO8859-1.pcf.gz, and FILE.pcf.gz (ISO 10646) */
    int height, xorig, yorig;
} xfont;
static const xfont XFONTS[9] = {
    [2] = {"GLUT_BITMAP_9_BY_15", "misc", "9x15", 16, 0, 4},
    [3] = {"GLUT_BITMAP_8_BY_13", "misc", "8x13", 14, 0, 3},
    [4] = {"GLUT_BITMAP_TIMES_ROMAN_10", "75dpi", "timR10", 14, 0, 3},
    [5] = {"GLUT_BITMAP_TIMES_ROMAN_24", "75dpi", "timR24", 29, 0, 7},
    [6] = {"GLUT_BITMAP_HELVETICA_10", "75dpi", "helvR10", 14, 0, 3},
    [7] = {"GLUT_BITMAP_HELVETICA_12", "75dpi", "helvR12", 16, 0, 4},
    [8] = {"GLUT_BITMAP_HELVETICA_18", "75dpi", "helvR18", 23, 0, 5},
};

/* A loaded font: every glyph cut to freeglut's cell (adv x height, rows top
 * first, 1 bit a pixel, MSB left). */
typedef struct cellfont {
    int state; /* 0: not tried, 1: loaded, -1: fall back */
    int height, row_bytes;
    uint8_t adv[256];
    uint8_t *bits; /* 256 * height * row_bytes */
} cellfont;
static cellfont CF[9];

#if defined(FXG_HAVE_FREETYPE)
/* Where Debian, Fedora and old X11 installations keep them. */
static const char *const XFONT_ROOTS[] = {
    "/usr/share/fonts/X11", "/usr/share/X11/fonts", "/usr/X11R6/lib/X11/fonts", "/usr/lib/X11/fonts",
};

typedef struct ftapi {
    FT_Error (*init)(FT_Library *);
    FT_Error (*done)(FT_Library);
    FT_Error (*new_face)(FT_Library, const char *, FT_Long, FT_Face *);
    FT_Error (*done_face)(FT_Face);
    FT_Error (*select_size)(FT_Face, FT_Int);
    FT_UInt (*char_index)(FT_Face, FT_ULong);
    FT_Error (*load_glyph)(FT_Face, FT_UInt, FT_Int32);
} ftapi;

static int ft_open(ftapi *api, void **lib, char *why, size_t n)
{
    void *h = dlopen("libfreetype.so.6", RTLD_NOW | RTLD_LOCAL);
    if (!h) {
        snprintf(why, n, "libfreetype.so.6 not found (install libfreetype6)");
        return -1;
    }
    api->init = (FT_Error(*)(FT_Library *))dlsym(h, "FT_Init_FreeType");
    api->done = (FT_Error(*)(FT_Library))dlsym(h, "FT_Done_FreeType");
    api->new_face = (FT_Error(*)(FT_Library, const char *, FT_Long, FT_Face *))dlsym(h, "FT_New_Face");
    api->done_face = (FT_Error(*)(FT_Face))dlsym(h, "FT_Done_Face");
    api->select_size = (FT_Error(*)(FT_Face, FT_Int))dlsym(h, "FT_Select_Size");
    api->char_index = (FT_UInt(*)(FT_Face, FT_ULong))dlsym(h, "FT_Get_Char_Index");
    api->load_glyph = (FT_Error(*)(FT_Face, FT_UInt, FT_Int32))dlsym(h, "FT_Load_Glyph");
    if (!api->init || !api->done || !api->new_face || !api->done_face || !api->select_size ||
        !api->char_index || !api->load_glyph) {
        snprintf(why, n, "libfreetype.so.6 lacks the functions needed");
        dlclose(h);
        return -1;
    }
    *lib = h; /* kept open: the fonts load one by one, at first use */
    return 0;
}

/* Cuts character c (code point u of face) into the cell of font xf; 0 or
 * -1 (why). A code the font does not have is a blank cell as wide as the
 * space, as in freeglut's data (not X's default character). */
static int cut_glyph(const ftapi *api, FT_Face face, const xfont *xf, cellfont *cf, int c,
                     unsigned long u, char *why, size_t n)
{
    FT_UInt gi = api->char_index(face, (FT_ULong)u);
    if (gi == 0) {
        gi = api->char_index(face, ' ');
        if (gi == 0 || api->load_glyph(face, gi, 0) != 0) {
            snprintf(why, n, "no space character");
            return -1;
        }
        long adv = face->glyph->advance.x >> 6;
        cf->adv[c] = (uint8_t)(adv < 0 ? 0 : adv > 255 ? 255 : adv);
        return 0;
    }
    if (api->load_glyph(face, gi, FT_LOAD_RENDER | FT_LOAD_TARGET_MONO | FT_LOAD_MONOCHROME) != 0) {
        snprintf(why, n, "character %d does not load", c);
        return -1;
    }
    FT_GlyphSlot s = face->glyph;
    long adv = s->advance.x >> 6;
    if (adv < 0 || adv > 255 || s->bitmap.pixel_mode != FT_PIXEL_MODE_MONO ||
        (s->bitmap.rows && s->bitmap.pitch < (int)((s->bitmap.width + 7) / 8))) {
        snprintf(why, n, "character %d: advance %ld, pixel mode %d or pitch %d unusable", c, adv,
                 (int)s->bitmap.pixel_mode, (int)s->bitmap.pitch);
        return -1;
    }
    cf->adv[c] = (uint8_t)adv;
    uint8_t *cell = cf->bits + (size_t)c * (size_t)cf->height * (size_t)cf->row_bytes;
    /* cell pixel (x, row): x from 0 at the raster position minus xorig,
     * row 0 at the top, height - 1 - row - yorig pixels above the baseline */
    for (unsigned r = 0; r < s->bitmap.rows; r++) {
        int y = s->bitmap_top - 1 - (int)r; /* above the baseline */
        int row = xf->height - 1 - xf->yorig - y;
        if (row < 0 || row >= xf->height)
            continue;
        const uint8_t *src = s->bitmap.buffer + (long)r * s->bitmap.pitch;
        for (unsigned col = 0; col < s->bitmap.width; col++) {
            if (!((src[col / 8] >> (7 - col % 8)) & 1))
                continue;
            int x = s->bitmap_left + (int)col + xf->xorig;
            if (x < 0 || x >= adv)
                continue;
            cell[row * cf->row_bytes + x / 8] |= (uint8_t)(0x80u >> (x % 8));
        }
    }
    return 0;
}

static int find_file(const xfont *xf, const char *suffix, char *path, size_t n)
{
    for (size_t k = 0; k < sizeof XFONT_ROOTS / sizeof XFONT_ROOTS[0]; k++) {
        snprintf(path, n, "%s/%s/%s%s.pcf.gz", XFONT_ROOTS[k], xf->dir, xf->file, suffix);
        FILE *fp = fopen(path, "rb");
        if (fp) {
            fclose(fp);
            return 0;
        }
    }
    return -1;
}

static int load_xfont(int i, char *why, size_t n)
{
    static ftapi api;
    static void *lib;
    static int lib_state; /* 0 untried, 1 open, -1 failed */
    static char lib_why[128];
    if (lib_state == 0) {
        lib_state = ft_open(&api, &lib, lib_why, sizeof lib_why) == 0 ? 1 : -1;
    }
    if (lib_state < 0) {
        snprintf(why, n, "%s", lib_why);
        return -1;
    }
    const xfont *xf = &XFONTS[i];
    char path[256], upath[256];
    if (find_file(xf, "-ISO8859-1", path, sizeof path) < 0) {
        snprintf(why, n, "%s/%s/%s-ISO8859-1.pcf.gz not found (Debian: %s)", XFONT_ROOTS[0], xf->dir,
                 xf->file, !strcmp(xf->dir, "misc") ? "xfonts-base" : "xfonts-75dpi");
        return -1;
    }
    int have_u = find_file(xf, "", upath, sizeof upath) == 0;
    FT_Library ft;
    FT_Face face, uface = NULL;
    if (api.init(&ft) != 0) {
        snprintf(why, n, "FreeType does not initialise");
        return -1;
    }
    int rc = -1;
    if (api.new_face(ft, path, 0, &face) != 0) {
        snprintf(why, n, "FreeType cannot read %.200s", path);
    } else {
        if (have_u && (api.new_face(ft, upath, 0, &uface) != 0 || uface->num_fixed_sizes < 1 ||
                       api.select_size(uface, 0) != 0)) {
            if (uface)
                api.done_face(uface);
            uface = NULL;
        }
        cellfont *cf = &CF[i];
        cf->height = xf->height;
        cf->row_bytes = 256 / 8;
        if (face->num_fixed_sizes < 1 || api.select_size(face, 0) != 0) {
            snprintf(why, n, "%.200s has no bitmap strike", path);
        } else if (!(cf->bits = calloc(256, (size_t)cf->height * (size_t)cf->row_bytes))) {
            snprintf(why, n, "out of memory");
        } else {
            char w2[96];
            rc = 0;
            for (int c = 1; c < 256 && rc == 0; c++) {
                /* freeglut's data come from the X11R6-era fonts, whose
                 * ISO 8859-1 encoding put the typographic quotes at 39 and
                 * 96 and the minus sign at 45; today's files have them at
                 * their ISO 10646 code points */
                unsigned long u = c == 39 ? 0x2019 : c == 96 ? 0x2018 : c == 45 ? 0x2212 : 0;
                int r = u && uface ? cut_glyph(&api, uface, xf, cf, c, u, w2, sizeof w2)
                                   : cut_glyph(&api, face, xf, cf, c, (unsigned long)c, w2, sizeof w2);
                if (r < 0) {
                    snprintf(why, n, "%.200s: %.90s", path, w2);
                    rc = -1;
                }
            }
            if (rc < 0) {
                free(cf->bits);
                cf->bits = NULL;
            }
        }
        if (uface)
            api.done_face(uface);
        api.done_face(face);
    }
    api.done(ft);
    return rc;
}
#endif

/* The loaded font for a GLUT_BITMAP_* id, or NULL: fixel's 6x10 glyphs. */
static const cellfont *bitmap_font(int i)
{
    if (i < 2 || i > 8)
        return NULL;
    cellfont *cf = &CF[i];
    if (cf->state == 0) {
        char why[320] = "built without FreeType headers";
#if defined(FXG_HAVE_FREETYPE)
        cf->state = load_xfont(i, why, sizeof why) == 0 ? 1 : -1;
#else
        cf->state = -1;
#endif
        if (cf->state < 0)
            fx_glut_log("%s: %s; drawing fixel's built-in 6x10 glyphs instead of freeglut's", XFONTS[i].name,
                    why);
    }
    return cf->state > 0 ? cf : NULL;
}

/* ---- the fall-back: fixel's 6x10 font ---- */
static int fb_scale(int i) { return (i == 5 || i == 8) ? 2 : 1; }
static int fb_advance(int i)
{
    return i == 2 ? 9 : i == 3 ? 8 : (int)fx_font_builtin()->width * fb_scale(i);
}

void glutBitmapCharacter(void *font, int ch)
{
    int i = font_index(font);
    if (i < 2 || ch < 1 || ch > 255)
        return; /* freeglut: a stroke font or a code outside 1..255 draws nothing */
    const cellfont *cf = bitmap_font(i);
    if (cf) {
        fx_glut_bitmap(cf->adv[ch], cf->height, XFONTS[i].xorig, XFONTS[i].yorig, cf->adv[ch],
                   cf->bits + (size_t)ch * (size_t)cf->height * (size_t)cf->row_bytes, cf->row_bytes, 1);
        return;
    }
    const fx_font *f = fx_font_builtin();
    int s = fb_scale(i);
    uint32_t g = fx_font_glyph(f, (uint32_t)ch);
    int adv = fb_advance(i);
    fx_glut_bitmap((int32_t)f->width, (int32_t)f->height, -(adv - (int)f->width * s) / 2, 2 * s, adv,
               fx_font_row(f, g, 0), (int32_t)f->row_bytes, s);
}
/* As freeglut: a newline goes back by what this call drew and down one
 * cell height (a glBitmap move, so it applies only to a valid raster
 * position). */
void glutBitmapString(void *font, const unsigned char *s)
{
    int i = font_index(font);
    if (i < 2)
        return;
    int64_t x = 0;
    for (; s && *s; s++) {
        if (*s == '\n') {
            if (fx_gl.raster_valid) {
                fx_gl.rx -= x * 256;
                fx_gl.ry -= (int64_t)glutBitmapHeight(font) * 256;
            }
            x = 0;
        } else {
            glutBitmapCharacter(font, *s);
            x += glutBitmapWidth(font, *s);
        }
    }
}
int glutBitmapWidth(void *font, int ch)
{
    int i = font_index(font);
    if (i < 2 || ch < 1 || ch > 255)
        return 0;
    const cellfont *cf = bitmap_font(i);
    return cf ? cf->adv[ch] : fb_advance(i);
}
/* The widest line, as freeglut. */
int glutBitmapLength(void *font, const unsigned char *s)
{
    int n = 0, line = 0;
    for (; s && *s; s++) {
        if (*s == '\n') {
            if (line > n)
                n = line;
            line = 0;
        } else {
            line += glutBitmapWidth(font, *s);
        }
    }
    return line > n ? line : n;
}
int glutBitmapHeight(void *font)
{
    int i = font_index(font);
    return i >= 2 ? XFONTS[i].height : 0;
}

/* freeglut's advance of every MONO_ROMAN character (and of the space in
 * ROMAN), its glutStrokeHeight (the line spacing of glutStrokeString) for
 * both fonts, measured; the glyphs' own height, ROMAN's capitals. */
#define STROKE_W 104.762
#define STROKE_LINE 152.381
#define STROKE_H 119.05
void glutStrokeCharacter(void *font, int ch)
{
    if (font_index(font) < 0 || font_index(font) > 1 || ch < 32 || ch > 127)
        return; /* freeglut has glyphs for 32-127 only */
    const fx_font *f = fx_font_builtin();
    uint32_t g = fx_font_glyph(f, (uint32_t)(ch & 0xFF));
    double sx = STROKE_W / f->width, sy = STROKE_H / 8.0; /* rows 0..7 above the baseline */
    int W = (int)f->width, H = (int)f->height;
#define LIT(c, r) ((c) >= 0 && (c) < W && (r) >= 0 && (r) < H && \
                   ((fx_font_row(f, g, (uint32_t)(r))[(c) / 8] >> (7 - (c) % 8)) & 1))
    glBegin(GL_LINES);
    for (int r = 0; r < H; r++)
        for (int c = 0; c < W; c++) {
            if (!LIT(c, r))
                continue;
            double x = (c + 0.5) * sx, y = (7.5 - r) * sy;
            int any = 0;
            if (LIT(c + 1, r)) {
                glVertex2d(x, y), glVertex2d(x + sx, y), any = 1;
            }
            if (LIT(c, r + 1)) {
                glVertex2d(x, y), glVertex2d(x, y - sy), any = 1;
            }
            if (LIT(c + 1, r + 1) && !LIT(c + 1, r) && !LIT(c, r + 1)) {
                glVertex2d(x, y), glVertex2d(x + sx, y - sy), any = 1;
            }
            if (LIT(c - 1, r + 1) && !LIT(c - 1, r) && !LIT(c, r + 1)) {
                glVertex2d(x, y), glVertex2d(x - sx, y - sy), any = 1;
            }
            if (!any && !LIT(c - 1, r) && !LIT(c, r - 1))
                glVertex2d(x - sx / 4, y), glVertex2d(x + sx / 4, y);
        }
    glEnd();
#undef LIT
    glTranslated(STROKE_W, 0, 0);
}
/* As freeglut: a newline goes back by the line's advance and down by
 * glutStrokeHeight. */
void glutStrokeString(void *font, const unsigned char *s)
{
    if (font_index(font) < 0 || font_index(font) > 1)
        return;
    double x = 0;
    for (; s && *s; s++) {
        if (*s == '\n') {
            glTranslated(-x, -STROKE_LINE, 0);
            x = 0;
        } else if (*s >= 32 && *s <= 127) {
            glutStrokeCharacter(font, *s);
            x += STROKE_W;
        }
    }
}
int glutStrokeWidth(void *font, int ch) { return (int)(glutStrokeWidthf(font, ch) + 0.5f); }
GLfloat glutStrokeWidthf(void *font, int ch)
{
    if (font_index(font) < 0 || font_index(font) > 1 || ch < 32 || ch > 127)
        return 0;
    return (GLfloat)STROKE_W;
}
int glutStrokeLength(void *font, const unsigned char *s)
{
    return (int)(glutStrokeLengthf(font, s) + 0.5f);
}
/* The widest line, as freeglut. */
GLfloat glutStrokeLengthf(void *font, const unsigned char *s)
{
    double n = 0, line = 0;
    for (; s && *s; s++) {
        if (*s == '\n') {
            if (line > n)
                n = line;
            line = 0;
        } else {
            line += glutStrokeWidthf(font, *s);
        }
    }
    return (GLfloat)(line > n ? line : n);
}
GLfloat glutStrokeHeight(void *font)
{
    return font_index(font) == 0 || font_index(font) == 1 ? (GLfloat)STROKE_LINE : 0.0f;
}
