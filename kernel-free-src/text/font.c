/* SPDX-License-Identifier: MIT */
/* fixel — PSF1/PSF2 parsing, glyph lookup and text drawing.
 *
 * The parser validates once and stores only in-bounds pointers and sizes;
 * the unicode-table walks are bounded by utab_len and by the glyph count,
 * so no later call can read outside the caller's buffer. */
#include "fixel/font.h"
#include "fixel/error.h"
#include "font_builtin.h"
#include "../base/fx_internal.h"

#define PSF1_MAGIC0 0x36
#define PSF1_MAGIC1 0x04
#define PSF1_MODE512    0x01
#define PSF1_MODEHASTAB 0x02
#define PSF1_MODESEQ    0x04
#define PSF2_MAGIC 0x864ab572u
#define PSF2_HAS_UNICODE_TABLE 0x01u
#define NO_GLYPH 0xFFFFFFFFu

static const fx_font builtin = {
    fx_font_builtin_bits, FX_BUILTIN_GLYPHS, FX_BUILTIN_W, FX_BUILTIN_H, 1, FX_BUILTIN_H,
    0, 0, 0, {0}, FX_BUILTIN_GLYPHS - 1, 0, 0, 0,
};

const fx_font *fx_font_builtin(void) { return &builtin; }

static uint32_t rd32(const uint8_t *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* One UTF-8 character from s[0..n) (n >= 1): returns the bytes used and the
 * code point, or 1 and U+FFFD for anything malformed (overlong forms,
 * surrogates, beyond U+10FFFF, truncated). */
static size_t utf8_next(const uint8_t *s, size_t n, uint32_t *cp)
{
    uint8_t b = s[0];
    *cp = 0xFFFD;
    if (b < 0x80) {
        *cp = b;
        return 1;
    }
    size_t k;
    uint32_t v, min;
    if ((b & 0xE0) == 0xC0)
        k = 2, v = b & 0x1F, min = 0x80;
    else if ((b & 0xF0) == 0xE0)
        k = 3, v = b & 0x0F, min = 0x800;
    else if ((b & 0xF8) == 0xF0)
        k = 4, v = b & 0x07, min = 0x10000;
    else
        return 1;
    if (k > n)
        return 1;
    for (size_t i = 1; i < k; i++) {
        if ((s[i] & 0xC0) != 0x80)
            return 1;
        v = v << 6 | (s[i] & 0x3F);
    }
    if (v < min || v > 0x10FFFF || (v >= 0xD800 && v <= 0xDFFF))
        return 1;
    *cp = v;
    return k;
}

/* Calls fn(user, cp, glyph) for every single-character entry of the table,
 * in table order (glyphs ascending); one walk, bounded by utab_len. */
/* always inlined: each caller gets its own loop with the callback inlined */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void walk_table(const fx_font *f, void (*fn)(void *, uint32_t, uint32_t), void *user)
{
    uint32_t glyph = 0;
    int seq = 0;
    if (f->version == 1) {
        for (size_t i = 0; i + 1 < f->utab_len; i += 2) {
            uint32_t v = (uint32_t)f->utab[i] | (uint32_t)f->utab[i + 1] << 8;
            if (v == 0xFFFF) {
                if (++glyph >= f->count)
                    return;
                seq = 0;
            } else if (v == 0xFFFE) {
                seq = 1;
            } else if (!seq) {
                fn(user, v, glyph);
            }
        }
        return;
    }
    for (size_t i = 0; i < f->utab_len;) {
        uint8_t b = f->utab[i];
        if (b == 0xFF) {
            i++;
            if (++glyph >= f->count)
                return;
            seq = 0;
        } else if (b == 0xFE) {
            i++;
            seq = 1;
        } else {
            uint32_t v;
            i += utf8_next(f->utab + i, f->utab_len - i, &v);
            if (!seq)
                fn(user, v, glyph);
        }
    }
}

#define CP_LIMIT 0x110000u
#define IX_WORDS (CP_LIMIT / 64)

static uint32_t popcount64(uint64_t x)
{
    x = x - ((x >> 1) & 0x5555555555555555u);
    x = (x & 0x3333333333333333u) + ((x >> 2) & 0x3333333333333333u);
    x = (x + (x >> 4)) & 0x0F0F0F0F0F0F0F0Fu;
    return (uint32_t)((x * 0x0101010101010101u) >> 56);
}

static uint32_t ix_lookup(const fx_font *f, uint32_t cp)
{
    if (cp >= CP_LIMIT)
        return NO_GLYPH;
    uint64_t w = f->ix_bits[cp / 64], bit = (uint64_t)1 << (cp % 64);
    if (!(w & bit))
        return NO_GLYPH;
    return f->ix_glyph[f->ix_rank[cp / 64] + popcount64(w & (bit - 1))];
}

static uint32_t lookup(const fx_font *f, uint32_t cp)
{
    if (f->version == 0)
        return cp >= 32 && cp <= 126 ? cp - 32 : NO_GLYPH;
    if (!f->utab)
        return cp < f->count ? cp : NO_GLYPH;
    if (f->ix_bits)
        return ix_lookup(f, cp);
    uint32_t glyph = 0;
    int seq = 0; /* after 0xFE / 0xFFFE: combining sequences, not single characters */
    if (f->version == 1) {
        for (size_t i = 0; i + 1 < f->utab_len; i += 2) {
            uint32_t v = (uint32_t)f->utab[i] | (uint32_t)f->utab[i + 1] << 8;
            if (v == 0xFFFF) {
                if (++glyph >= f->count)
                    break;
                seq = 0;
            } else if (v == 0xFFFE) {
                seq = 1;
            } else if (!seq && v == cp) {
                return glyph;
            }
        }
        return NO_GLYPH;
    }
    for (size_t i = 0; i < f->utab_len;) {
        uint8_t b = f->utab[i];
        if (b == 0xFF) {
            i++;
            if (++glyph >= f->count)
                break;
            seq = 0;
        } else if (b == 0xFE) {
            i++;
            seq = 1;
        } else {
            uint32_t v;
            i += utf8_next(f->utab + i, f->utab_len - i, &v);
            if (!seq && v == cp)
                return glyph;
        }
    }
    return NO_GLYPH;
}

uint32_t fx_font_glyph(const fx_font *f, uint32_t cp)
{
    if (f->version && cp < 128)
        return f->ascii[cp];
    uint32_t g = lookup(f, cp);
    return g == NO_GLYPH ? f->fallback : g;
}

/* ASCII glyphs: the first entry of each code below 128, in one walk (129
 * walks of the whole table before). */
static void ascii_entry(void *user, uint32_t cp, uint32_t glyph)
{
    uint32_t *first = user;
    if (cp < 128 && first[cp] == NO_GLYPH)
        first[cp] = glyph;
}

static int finish(fx_font *f)
{
    uint32_t first[128];
    for (uint32_t cp = 0; cp < 128; cp++)
        first[cp] = f->utab ? NO_GLYPH : lookup(f, cp);
    if (f->utab)
        walk_table(f, ascii_entry, first);
    uint32_t q = first['?'];
    f->fallback = q == NO_GLYPH ? 0 : q;
    for (uint32_t cp = 0; cp < 128; cp++)
        f->ascii[cp] = (uint16_t)(first[cp] == NO_GLYPH ? f->fallback : first[cp]);
    return 0;
}

typedef struct ix_build {
    uint64_t *bits;
    uint32_t *rank;
    uint16_t *glyph;
    size_t n, cap;
} ix_build;

static void ix_mark(void *user, uint32_t cp, uint32_t glyph)
{
    ix_build *b = user;
    (void)glyph;
    if (cp < CP_LIMIT)
        b->bits[cp / 64] |= (uint64_t)1 << (cp % 64);
}

static void ix_fill(void *user, uint32_t cp, uint32_t glyph)
{
    ix_build *b = user;
    if (cp >= CP_LIMIT)
        return;
    uint64_t w = b->bits[cp / 64], bit = (uint64_t)1 << (cp % 64);
    uint32_t k = b->rank[cp / 64] + popcount64(w & (bit - 1));
    if (glyph < b->glyph[k]) /* the first entry (lowest glyph) wins, as the linear walk */
        b->glyph[k] = (uint16_t)glyph;
}

size_t fx_font_index_bytes(const fx_font *f)
{
    if (!f || !f->utab || f->version == 0)
        return 0;
    size_t entries = f->utab_len < CP_LIMIT ? f->utab_len : CP_LIMIT;
    return IX_WORDS * 8 + IX_WORDS * 4 + entries * 2;
}

int fx_font_index(fx_font *f, void *mem, size_t size)
{
    size_t need = fx_font_index_bytes(f);
    if (!f || !mem || !need || (uintptr_t)mem % 8)
        return -FX_EINVAL;
    if (size < IX_WORDS * 12)
        return -FX_ENOSPC;
    ix_build b = {mem, (uint32_t *)((uint8_t *)mem + IX_WORDS * 8), 0, 0, 0};
    fx_memset(b.bits, 0, IX_WORDS * 8);
    walk_table(f, ix_mark, &b);
    uint32_t n = 0;
    for (uint32_t i = 0; i < IX_WORDS; i++) {
        b.rank[i] = n;
        n += popcount64(b.bits[i]);
    }
    if (size - IX_WORDS * 12 < (size_t)n * 2)
        return -FX_ENOSPC;
    b.glyph = (uint16_t *)((uint8_t *)mem + IX_WORDS * 12);
    for (uint32_t i = 0; i < n; i++)
        b.glyph[i] = 0xFFFF;
    walk_table(f, ix_fill, &b);
    f->ix_bits = b.bits;
    f->ix_rank = b.rank;
    f->ix_glyph = b.glyph;
    return 0;
}

int fx_font_load(fx_font *f, const void *data, size_t len)
{
    if (!f || !data)
        return -FX_EINVAL;
    const uint8_t *d = data;
    fx_memset(f, 0, sizeof *f);
    if (len >= 4 && rd32(d) == PSF2_MAGIC) {
        if (len < 32)
            return -FX_EBADMSG;
        uint32_t version = rd32(d + 4), hsize = rd32(d + 8), flags = rd32(d + 12);
        uint32_t count = rd32(d + 16), gbytes = rd32(d + 20), h = rd32(d + 24), w = rd32(d + 28);
        if (version != 0)
            return -FX_ENOTSUP;
        if (hsize < 32 || !count || !w || !h)
            return -FX_EBADMSG;
        if (w > FX_FONT_MAX_DIM || h > FX_FONT_MAX_DIM || count > FX_FONT_MAX_GLYPHS)
            return -FX_ERANGE;
        uint32_t rb = (w + 7) / 8;
        if (gbytes != rb * h)
            return -FX_EBADMSG;
        uint64_t need = (uint64_t)count * gbytes; /* <= 2^16 * 2^13: no overflow */
        if (hsize > len || need > len - hsize)
            return -FX_EOVERFLOW;
        f->glyphs = d + hsize;
        f->count = count;
        f->width = w;
        f->height = h;
        f->row_bytes = rb;
        f->glyph_bytes = gbytes;
        f->version = 2;
        if (flags & PSF2_HAS_UNICODE_TABLE) {
            f->utab = d + hsize + need;
            f->utab_len = len - hsize - (size_t)need;
        }
        return finish(f);
    }
    if (len >= 2 && d[0] == PSF1_MAGIC0 && d[1] == PSF1_MAGIC1) {
        if (len < 4)
            return -FX_EBADMSG;
        uint8_t mode = d[2], h = d[3];
        if (mode & ~(PSF1_MODE512 | PSF1_MODEHASTAB | PSF1_MODESEQ))
            return -FX_ENOTSUP;
        if (!h)
            return -FX_EBADMSG;
        uint32_t count = (mode & PSF1_MODE512) ? 512 : 256;
        size_t need = (size_t)count * h;
        if (need > len - 4)
            return -FX_EOVERFLOW;
        f->glyphs = d + 4;
        f->count = count;
        f->width = 8;
        f->height = h;
        f->row_bytes = 1;
        f->glyph_bytes = h;
        f->version = 1;
        if (mode & (PSF1_MODEHASTAB | PSF1_MODESEQ)) {
            f->utab = d + 4 + need;
            f->utab_len = len - 4 - need;
        }
        return finish(f);
    }
    return -FX_EBADMSG;
}

/* ---- drawing ---- */

static const fx_text_style default_style = {0, 1, 0, 0, FX_TEXT_CLIP_PIXEL};

static int64_t style_scale(const fx_text_style *st)
{
    return st->scale < 1 ? 1 : st->scale > 256 ? 256 : st->scale;
}

void fx_text_extent(const fx_text_style *st, const char *utf8, int64_t *w, int64_t *h)
{
    int64_t dummy;
    if (!w)
        w = &dummy;
    if (!h)
        h = &dummy;
    if (!utf8)
        utf8 = "";
    if (!st)
        st = &default_style;
    const fx_font *f = st->font ? st->font : &builtin;
    int64_t sc = style_scale(st), line = 0, widest = 0, lines = 0;
    const uint8_t *s = (const uint8_t *)utf8;
    size_t n = 0;
    while (s[n])
        n++;
    if (n)
        lines = 1;
    for (size_t i = 0; i < n;) {
        uint32_t cp;
        i += utf8_next(s + i, n - i, &cp);
        if (cp == '\n') {
            lines++;
            line = 0;
        } else {
            line++;
            widest = FX_MAX(widest, line);
        }
    }
    *w = widest * f->width * sc;
    *h = lines * f->height * sc;
}

static void hspan64(const fx_ctx *c, int64_t y, int64_t x0, int64_t x1)
{
    /* half-open [x0, x1); clamp before narrowing to int32 */
    x0 = FX_MAX(x0, (int64_t)c->clip.x0);
    x1 = FX_MIN(x1, (int64_t)c->clip.x1);
    if (x0 < x1 && y >= c->clip.y0 && y < c->clip.y1)
        fx_hspan(c, (int32_t)y, (int32_t)x0, (int32_t)x1);
}

/* One glyph cell at (px, py): runs of equal bits per font row become spans,
 * only for the screen rows inside the clip. */
static void draw_glyph(const fx_ctx *fg, const fx_ctx *bg, const fx_font *f, uint32_t g, int64_t px,
                       int64_t py, int64_t sc)
{
    const fx_rect *cl = &fg->clip;
    int64_t r0 = 0, r1 = f->height;
    if (py < cl->y0)
        r0 = (cl->y0 - py) / sc;
    r1 = FX_MIN(r1, (cl->y1 - py + sc - 1) / sc);
    for (int64_t r = r0; r < r1; r++) {
        const uint8_t *row = fx_font_row(f, g, (uint32_t)r);
        int64_t y0 = FX_MAX(py + r * sc, (int64_t)cl->y0), y1 = FX_MIN(py + (r + 1) * sc, (int64_t)cl->y1);
        for (uint32_t j = 0; j < f->width;) {
            int bit = (row[j >> 3] >> (7 - (j & 7))) & 1;
            uint32_t k = j + 1;
            while (k < f->width && ((row[k >> 3] >> (7 - (k & 7))) & 1) == bit)
                k++;
            const fx_ctx *c = bit ? fg : bg;
            if (c)
                for (int64_t y = y0; y < y1; y++)
                    hspan64(c, y, px + j * sc, px + k * sc);
            j = k;
        }
    }
}

static int cell_inside(const fx_rect *cl, int64_t x, int64_t y, int64_t w, int64_t h)
{
    return x >= cl->x0 && y >= cl->y0 && x + w <= cl->x1 && y + h <= cl->y1;
}

int fx_text(const fx_ctx *c, int32_t x, int32_t y, const char *utf8)
{
    if (!c || !utf8)
        return -FX_EINVAL;
    if (c->coords == FX_COORDS_COURSE) {
        /* Glyphs stay upright (draw.h): the anchor is mapped, the text is
         * drawn in the surface's own frame from there. */
        fx_ctx s = *c;
        fx_ctx_set_coords(&s, FX_COORDS_SCREEN);
        return fx_text(&s, x, fx_sat32((int64_t)s.surf.h - 1 - y), utf8);
    }
    const fx_text_style *st = c->text_style ? c->text_style : &default_style;
    const fx_font *f = st->font ? st->font : &builtin;
    const fx_rect *cl = &c->clip;
    int64_t sc = style_scale(st), cw = f->width * sc, ch = f->height * sc;
    if (fx_rect_empty(*cl))
        return 0;
    if (st->clip == FX_TEXT_CLIP_STRING) {
        int64_t w, h;
        fx_text_extent(st, utf8, &w, &h);
        if (!cell_inside(cl, x, y, w, h))
            return 0;
    }
    fx_ctx bgc;
    if (st->has_bg) {
        bgc = *c;
        fx_ctx_set_color(&bgc, st->bg);
    }
    const uint8_t *s = (const uint8_t *)utf8;
    size_t n = 0;
    while (s[n])
        n++;
    int64_t px = x, py = y;
    int drawn = 0;
    for (size_t i = 0; i < n && py < cl->y1;) {
        uint32_t cp;
        i += utf8_next(s + i, n - i, &cp);
        if (cp == '\n') {
            px = x;
            py += ch;
            continue;
        }
        int visible = px < cl->x1 && px + cw > cl->x0 && py + ch > cl->y0;
        if (visible && (st->clip != FX_TEXT_CLIP_CHAR || cell_inside(cl, px, py, cw, ch))) {
            draw_glyph(c, st->has_bg ? &bgc : 0, f, fx_font_glyph(f, cp), px, py, sc);
            drawn++;
        }
        px += cw;
    }
    return drawn;
}
