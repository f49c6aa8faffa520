/* SPDX-License-Identifier: MIT */
/* fixel — cross-hatching by intensity (contract in fill.h). */
#include "fixel/fill.h"

int fx_hatch_level(uint8_t intensity) { return (255 - intensity) * FX_HATCH_LEVELS / 256; }

/* Whether pixel (x, y) of the 16 x 16 tile is ink at level l; the lines
 * of a level are those of the level below plus one more set. */
static int ink(int l, int x, int y)
{
    int sp = l == 7 ? 2 : 4;
    int d = 0;
    /* "/" runs where x + y is constant, "\" where x - y is; a direction
     * starts at 8 px and halves its spacing a level later */
    d |= l >= 1 && (x + y) % (l == 1 ? 8 : sp) == 0;
    d |= l >= 3 && (x - y + 16) % (l == 3 ? 8 : sp) == 0;
    d |= l >= 5 && y % sp == 0;
    d |= l >= 6 && x % sp == 0;
    return d;
}

int fx_hatch_style(fx_fill_style *s, uint8_t *bits, uint8_t intensity)
{
    int l = fx_hatch_level(intensity);
    for (int y = 0; y < 16; y++)
        for (int b = 0; b < 2; b++) {
            uint8_t v = 0;
            for (int i = 0; i < 8; i++)
                v = (uint8_t)(v << 1 | ink(l, b * 8 + i, y));
            bits[y * 2 + b] = v;
        }
    s->kind = FX_FILL_PATTERN;
    s->bits = bits;
    s->w = s->h = 16;
    s->stride = 2;
    s->ax = s->ay = 0;
    s->bg = 0;
    s->bg_transparent = 1;
    s->shade = 0;
    s->user = 0;
    return l == 0 ? 0 : l < 3 ? 1 : l < 5 ? 2 : l < 6 ? 3 : 4;
}

int32_t fx_hatch_ink(int level)
{
    if (level < 0 || level >= FX_HATCH_LEVELS)
        return 0;
    int32_t n = 0;
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 16; x++)
            n += ink(level, x, y);
    return n;
}
