/* SPDX-License-Identifier: MIT */
/* fixel GLUT layer — GLUT's fonts on fixel's built-in 6x10 font.
 * Bitmap fonts: 8_BY_13, 9_BY_15, TIMES_ROMAN_10, HELVETICA_10/12 draw the
 * 6x10 glyphs at scale 1, TIMES_ROMAN_24 and HELVETICA_18 at scale 2; the
 * baseline is two font rows above the cell's bottom. The two fixed-width
 * fonts keep their cell width as advance (8 and 9 pixels, the glyph centred
 * in it), so text laid out with glutBitmapWidth spans what it spans under
 * freeglut; the proportional fonts advance by the 6x10 glyph width. The
 * glyphs themselves are fixel's, not freeglut's (tests/glut compares
 * bitmaptext as 3d for that reason). Stroke fonts trace
 * the same glyphs with GL lines through the lit pixels' centres, in GLUT's
 * stroke units (104.76 wide, 119.05 above the baseline for ROMAN). */
#include <string.h>

#include "fixel/font.h"
#include "glut_int.h"

const int fx_glut_font_ids[9] = {0, 1, 2, 3, 4, 5, 6, 7, 8};

static int font_index(const void *font)
{
    const int *p = (const int *)font;
    if (p >= fx_glut_font_ids && p < fx_glut_font_ids + 9)
        return (int)(p - fx_glut_font_ids);
    return 3;
}
static int font_scale(const void *font)
{
    int i = font_index(font);
    return (i == 5 || i == 8) ? 2 : 1;
}
/* The advance of a glyph, pixels. */
static int font_advance(const void *font)
{
    int i = font_index(font);
    return i == 2 ? 9 : i == 3 ? 8 : (int)fx_font_builtin()->width * font_scale(font);
}

void glutBitmapCharacter(void *font, int ch)
{
    const fx_font *f = fx_font_builtin();
    int s = font_scale(font);
    if (ch == '\n')
        return;
    uint32_t g = fx_font_glyph(f, (uint32_t)(ch & 0xFF));
    int adv = font_advance(font);
    fxg_bitmap((int32_t)f->width, (int32_t)f->height, -(adv - (int)f->width * s) / 2, 2 * s, adv,
               fx_font_row(f, g, 0), (int32_t)f->row_bytes, s);
}
void glutBitmapString(void *font, const unsigned char *s)
{
    int64_t x0 = fxg.rx;
    for (; s && *s; s++) {
        if (*s == '\n') {
            fxg.rx = x0;
            fxg.ry -= (int64_t)glutBitmapHeight(font) * 256;
        } else {
            glutBitmapCharacter(font, *s);
        }
    }
}
int glutBitmapWidth(void *font, int ch)
{
    (void)ch;
    return font_advance(font);
}
int glutBitmapLength(void *font, const unsigned char *s)
{
    int n = 0;
    for (; s && *s; s++)
        n += glutBitmapWidth(font, *s);
    return n;
}
int glutBitmapHeight(void *font) { return (int)fx_font_builtin()->height * font_scale(font) + 3; }

#define STROKE_W 104.76
#define STROKE_H 119.05
void glutStrokeCharacter(void *font, int ch)
{
    (void)font;
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
void glutStrokeString(void *font, const unsigned char *s)
{
    for (; s && *s; s++)
        glutStrokeCharacter(font, *s);
}
int glutStrokeWidth(void *font, int ch)
{
    (void)font, (void)ch;
    return (int)(STROKE_W + 0.5);
}
GLfloat glutStrokeWidthf(void *font, int ch)
{
    (void)font, (void)ch;
    return (GLfloat)STROKE_W;
}
int glutStrokeLength(void *font, const unsigned char *s)
{
    return (int)(glutStrokeLengthf(font, s) + 0.5f);
}
GLfloat glutStrokeLengthf(void *font, const unsigned char *s)
{
    (void)font;
    return s ? (GLfloat)(STROKE_W * (double)strlen((const char *)s)) : 0.0f;
}
GLfloat glutStrokeHeight(void *font)
{
    (void)font;
    return (GLfloat)STROKE_H;
}
