/* SPDX-License-Identifier: MIT */
/* fixel — smooth text: FreeType + HarfBuzz + FriBiDi + fontconfig +
 * libunibreak (face.h). Glyph masks go to the core's fx_mask_blend. */
#include <ctype.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include <ft2build.h>
#include FT_FREETYPE_H
#include <fontconfig/fontconfig.h>
#include <fribidi.h>
#include <hb-ft.h>
#include <hb.h>
#include <linebreak.h>

#include "fixel/error.h"
#include "fixel/face.h"

/* ---- the glyph cache: a hash table of chains and an LRU list ---- */
typedef struct gent {
    struct gent *hnext, *prev, *next;
    uint32_t gid;
    uint16_t font;
    uint16_t px;
    int32_t left, top, w, h; /* top: rows above the origin */
    size_t bytes;
    uint8_t cov[]; /* w * h */
} gent;

#define NBUCKET 1024

typedef struct font {
    char *file;
    FT_Face ft;     /* NULL until opened (fallbacks open lazily) */
    hb_font_t *hb;
    int failed;     /* could not be opened: skipped */
} fontrec;

struct fx_face {
    FT_Library lib;
    fontrec fonts[FX_FACE_MAX_FONTS];
    int nfonts;
    int32_t px;
    unsigned mask_flags;
    hb_feature_t *feats;
    unsigned nfeats;
    hb_buffer_t *buf;
    /* cache */
    gent *bucket[NBUCKET];
    gent *head, *tail; /* head = most recent */
    size_t bytes, limit;
    uint32_t entries;
    uint64_t hits, misses, evictions;
    /* scratch, grown as needed */
    uint32_t *cps, *cpbyte;
    FriBidiCharType *types;
    FriBidiBracketType *brackets;
    FriBidiLevel *levels;
    uint8_t *cpfont;
    size_t cap;
    fx_glyph *glyphs;
    size_t gcap, ng;
    char err[320];
};

static void set_err(fx_face *f, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void set_err(fx_face *f, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(f->err, sizeof f->err, fmt, ap);
    va_end(ap);
}

int fx_face_available(void) { return 1; }

static pthread_once_t once = PTHREAD_ONCE_INIT;
static void init_libs(void) { init_linebreak(); }

static int is_file_name(const char *n)
{
    if (strchr(n, '/'))
        return 1;
    static const char *const ext[] = {".ttf", ".otf", ".ttc", ".otc", ".pfb", ".pcf", ".bdf", ".woff", ".pcf.gz"};
    size_t l = strlen(n);
    for (size_t i = 0; i < sizeof ext / sizeof ext[0]; i++) {
        size_t e = strlen(ext[i]);
        if (l > e && !strcasecmp(n + l - e, ext[i]))
            return 1;
    }
    return 0;
}

/* Open font i at the face's size. */
static int font_open(fx_face *f, int i)
{
    fontrec *fo = &f->fonts[i];
    if (fo->ft)
        return 0;
    if (fo->failed)
        return -FX_EBADMSG;
    FT_Face ft;
    FT_Error e = FT_New_Face(f->lib, fo->file, 0, &ft);
    if (e) {
        fo->failed = 1;
        FILE *probe = fopen(fo->file, "rb");
        if (!probe) {
            set_err(f, "%s: cannot open the font file", fo->file);
            return -FX_ENOENT;
        }
        fclose(probe);
        set_err(f, "%s: not a font FreeType can read (FreeType error 0x%02x: truncated or corrupt?)", fo->file, e);
        return -FX_EBADMSG;
    }
    if (ft->num_glyphs <= 0 || (!FT_IS_SCALABLE(ft) && ft->num_fixed_sizes <= 0)) {
        FT_Done_Face(ft);
        fo->failed = 1;
        set_err(f, "%s: the font has no usable glyphs", fo->file);
        return -FX_EBADMSG;
    }
    if (FT_IS_SCALABLE(ft))
        e = FT_Set_Pixel_Sizes(ft, 0, (FT_UInt)f->px);
    else {
        /* A bitmap font: the strike nearest the asked size. */
        int best = 0;
        for (int k = 1; k < ft->num_fixed_sizes; k++)
            if (abs(ft->available_sizes[k].height - f->px) < abs(ft->available_sizes[best].height - f->px))
                best = k;
        e = FT_Select_Size(ft, best);
    }
    if (e) {
        FT_Done_Face(ft);
        fo->failed = 1;
        set_err(f, "%s: cannot set size %d px (FreeType error 0x%02x)", fo->file, (int)f->px, e);
        return -FX_EBADMSG;
    }
    fo->ft = ft;
    fo->hb = hb_ft_font_create_referenced(ft);
    hb_ft_font_set_load_flags(fo->hb, FT_LOAD_DEFAULT);
    return 0;
}

static void font_close(fontrec *fo)
{
    if (fo->hb)
        hb_font_destroy(fo->hb);
    if (fo->ft)
        FT_Done_Face(fo->ft);
    fo->hb = NULL;
    fo->ft = NULL;
}

/* Fill the chain from fontconfig: the sorted list for pattern p. */
static int chain_from_fc(fx_face *f, const char *family, const fx_face_opts *o, int skip_first_file)
{
    FcConfig *cfg = FcConfigGetCurrent();
    if (!cfg && !FcInit())
        return -FX_ENOENT;
    FcPattern *p = FcNameParse((const FcChar8 *)family);
    if (!p)
        return -FX_ENOMEM;
    if (o->weight)
        FcPatternAddInteger(p, FC_WEIGHT, FcWeightFromOpenType(o->weight));
    if (o->italic)
        FcPatternAddInteger(p, FC_SLANT, FC_SLANT_ITALIC);
    FcPatternAddBool(p, FC_SCALABLE, FcTrue);
    FcConfigSubstitute(NULL, p, FcMatchPattern);
    FcDefaultSubstitute(p);
    FcResult res;
    FcFontSet *set = FcFontSort(NULL, p, FcTrue, NULL, &res);
    FcPatternDestroy(p);
    if (!set)
        return -FX_ENOENT;
    for (int i = 0; i < set->nfont && f->nfonts < FX_FACE_MAX_FONTS; i++) {
        FcChar8 *file;
        if (FcPatternGetString(set->fonts[i], FC_FILE, 0, &file) != FcResultMatch)
            continue;
        if (skip_first_file && f->nfonts > 0 && !strcmp((const char *)file, f->fonts[0].file))
            continue;
        int dup = 0;
        for (int k = 0; k < f->nfonts; k++)
            dup |= !strcmp(f->fonts[k].file, (const char *)file);
        if (dup)
            continue;
        f->fonts[f->nfonts].file = strdup((const char *)file);
        if (!f->fonts[f->nfonts].file)
            break;
        f->nfonts++;
    }
    FcFontSetDestroy(set);
    return f->nfonts ? 0 : -FX_ENOENT;
}

int fx_face_set_features(fx_face *f, const char *list)
{
    hb_feature_t tmp[32];
    unsigned n = 0;
    const char *p = list ? list : "";
    while (*p) {
        while (*p == ',' || isspace((unsigned char)*p))
            p++;
        if (!*p)
            break;
        const char *e = p;
        while (*e && *e != ',' && !isspace((unsigned char)*e))
            e++;
        if (n == sizeof tmp / sizeof tmp[0]) {
            set_err(f, "features: more than %u", (unsigned)(sizeof tmp / sizeof tmp[0]));
            return -FX_EINVAL;
        }
        if (!hb_feature_from_string(p, (int)(e - p), &tmp[n])) {
            set_err(f, "features: '%.*s' is not an OpenType feature (e.g. tnum, -liga, ss01=1)", (int)(e - p), p);
            return -FX_EINVAL;
        }
        n++;
        p = e;
    }
    hb_feature_t *nf = NULL;
    if (n) {
        nf = malloc(n * sizeof *nf);
        if (!nf)
            return -FX_ENOMEM;
        memcpy(nf, tmp, n * sizeof *nf);
    }
    free(f->feats);
    f->feats = nf;
    f->nfeats = n;
    return 0;
}

int fx_face_open(const char *name, int32_t px, const fx_face_opts *opts, fx_face **out, char *err, size_t errsz)
{
    static const fx_face_opts defaults;
    const fx_face_opts *o = opts ? opts : &defaults;
    if (out)
        *out = NULL;
    if (err && errsz)
        err[0] = 0;
#define FAIL(code, ...)                             \
    do {                                            \
        if (err && errsz)                           \
            snprintf(err, errsz, __VA_ARGS__);      \
        return code;                                \
    } while (0)
    if (!name || !out)
        FAIL(-FX_EINVAL, "font: no name given");
    if (!*name)
        FAIL(-FX_EINVAL, "font: empty name");
    if (px < 1 || px > FX_FACE_MAX_PX)
        FAIL(-FX_ERANGE, "%s: size %ld px is out of range 1..%d", name, (long)px, FX_FACE_MAX_PX);
    if (o->weight < 0 || o->weight > 1000)
        FAIL(-FX_ERANGE, "%s: weight %ld is out of range 1..1000", name, (long)o->weight);
    if (o->mask_flags & ~FX_MASK_GAMMA)
        FAIL(-FX_EINVAL, "%s: unknown mask flags 0x%x", name, o->mask_flags);
    pthread_once(&once, init_libs);
    fx_face *f = calloc(1, sizeof *f);
    if (!f)
        FAIL(-FX_ENOMEM, "%s: out of memory", name);
    f->px = px;
    f->mask_flags = o->mask_flags;
    f->limit = o->cache_bytes ? o->cache_bytes : FX_FACE_CACHE_DEFAULT;
    int r = 0;
    if (FT_Init_FreeType(&f->lib)) {
        free(f);
        FAIL(-FX_ENOMEM, "%s: FreeType did not start", name);
    }
    if (is_file_name(name)) {
        f->fonts[0].file = strdup(name);
        f->nfonts = f->fonts[0].file ? 1 : 0;
        r = f->nfonts ? font_open(f, 0) : -FX_ENOMEM;
        if (!r && !o->no_fallback)
            chain_from_fc(f, "sans-serif", o, 1); /* no fallback is not an error */
    } else {
        r = chain_from_fc(f, name, o, 0);
        if (r)
            set_err(f, "%s: fontconfig finds no font for this family", name);
        else {
            if (o->no_fallback)
                for (; f->nfonts > 1; f->nfonts--)
                    free(f->fonts[f->nfonts - 1].file);
            r = font_open(f, 0);
        }
    }
    if (!r)
        r = fx_face_set_features(f, o->features);
    if (!r && !(f->buf = hb_buffer_create(), hb_buffer_allocation_successful(f->buf))) {
        set_err(f, "%s: out of memory", name);
        r = -FX_ENOMEM;
    }
    if (r) {
        if (err && errsz)
            snprintf(err, errsz, "%s", f->err[0] ? f->err : "font: out of memory");
        fx_face_close(f);
        return r;
    }
    f->err[0] = 0;
    *out = f;
    return 0;
#undef FAIL
}

static void cache_clear(fx_face *f)
{
    for (gent *g = f->head, *n; g; g = n) {
        n = g->next;
        free(g);
    }
    memset(f->bucket, 0, sizeof f->bucket);
    f->head = f->tail = NULL;
    f->bytes = 0;
    f->entries = 0;
}

void fx_face_close(fx_face *f)
{
    if (!f)
        return;
    cache_clear(f);
    for (int i = 0; i < f->nfonts; i++) {
        font_close(&f->fonts[i]);
        free(f->fonts[i].file);
    }
    if (f->buf)
        hb_buffer_destroy(f->buf);
    FT_Done_FreeType(f->lib);
    free(f->feats);
    free(f->cps);
    free(f->cpbyte);
    free(f->types);
    free(f->brackets);
    free(f->levels);
    free(f->cpfont);
    free(f->glyphs);
    free(f);
}

int fx_face_set_size(fx_face *f, int32_t px)
{
    if (!f)
        return -FX_EINVAL;
    if (px < 1 || px > FX_FACE_MAX_PX) {
        set_err(f, "size %ld px is out of range 1..%d", (long)px, FX_FACE_MAX_PX);
        return -FX_ERANGE;
    }
    if (px == f->px)
        return 0;
    f->px = px;
    /* Reopen at the new size: hb_ft caches the scale. */
    for (int i = 0; i < f->nfonts; i++) {
        int was = f->fonts[i].ft != NULL;
        font_close(&f->fonts[i]);
        if (was && font_open(f, i) && i == 0)
            return -FX_EBADMSG;
    }
    return 0;
}

void fx_face_shutdown(void) { FcFini(); }

int32_t fx_face_size(const fx_face *f) { return f ? f->px : 0; }
const char *fx_face_error(const fx_face *f) { return f ? f->err : "no face"; }
const char *fx_face_file(const fx_face *f, int i) { return f && i >= 0 && i < f->nfonts ? f->fonts[i].file : NULL; }

void fx_face_cache_stats(const fx_face *f, fx_face_stats *st)
{
    if (!st)
        return;
    memset(st, 0, sizeof *st);
    if (!f)
        return;
    st->hits = f->hits;
    st->misses = f->misses;
    st->evictions = f->evictions;
    st->bytes = f->bytes;
    st->limit = f->limit;
    st->entries = f->entries;
}

static unsigned hash_key(uint32_t gid, unsigned font, unsigned px)
{
    uint32_t h = gid * 2654435761u ^ (font * 40503u) ^ (px * 97u);
    return (h ^ (h >> 15)) & (NBUCKET - 1);
}

static void lru_unlink(fx_face *f, gent *g)
{
    if (g->prev)
        g->prev->next = g->next;
    else
        f->head = g->next;
    if (g->next)
        g->next->prev = g->prev;
    else
        f->tail = g->prev;
    g->prev = g->next = NULL;
}

static void lru_front(fx_face *f, gent *g)
{
    g->next = f->head;
    g->prev = NULL;
    if (f->head)
        f->head->prev = g;
    f->head = g;
    if (!f->tail)
        f->tail = g;
}

static void evict(fx_face *f, gent *g)
{
    lru_unlink(f, g);
    gent **pp = &f->bucket[hash_key(g->gid, g->font, g->px)];
    while (*pp != g)
        pp = &(*pp)->hnext;
    *pp = g->hnext;
    f->bytes -= g->bytes;
    f->entries--;
    f->evictions++;
    free(g);
}

/* The rendered glyph, from the cache or FreeType. A glyph bigger than the
 * whole bound is returned uncached in *tmp (the caller frees it). NULL when
 * FreeType cannot render it (the caller draws nothing for it). */
static const gent *glyph_get(fx_face *f, unsigned fi, uint32_t gid, gent **tmp)
{
    *tmp = NULL;
    unsigned hk = hash_key(gid, fi, (unsigned)f->px);
    for (gent *g = f->bucket[hk]; g; g = g->hnext)
        if (g->gid == gid && g->font == fi && g->px == f->px) {
            f->hits++;
            lru_unlink(f, g);
            lru_front(f, g);
            return g;
        }
    f->misses++;
    FT_Face ft = f->fonts[fi].ft;
    if (!ft || FT_Load_Glyph(ft, gid, FT_LOAD_DEFAULT) || FT_Render_Glyph(ft->glyph, FT_RENDER_MODE_NORMAL))
        return NULL;
    FT_Bitmap *bm = &ft->glyph->bitmap;
    if (bm->pixel_mode != FT_PIXEL_MODE_GRAY && bm->pixel_mode != FT_PIXEL_MODE_MONO)
        return NULL;
    size_t w = bm->width, h = bm->rows, n = w * h;
    gent *g = malloc(sizeof *g + n);
    if (!g)
        return NULL;
    memset(g, 0, sizeof *g);
    g->gid = gid;
    g->font = (uint16_t)fi;
    g->px = (uint16_t)f->px;
    g->left = ft->glyph->bitmap_left;
    g->top = ft->glyph->bitmap_top;
    g->w = (int32_t)w;
    g->h = (int32_t)h;
    g->bytes = sizeof *g + n;
    for (size_t y = 0; y < h; y++) {
        const uint8_t *row = bm->buffer + (ptrdiff_t)y * bm->pitch;
        if (bm->pixel_mode == FT_PIXEL_MODE_GRAY) {
            /* 8-bit grey in FreeType has 256 levels (num_grays 256). */
            memcpy(g->cov + y * w, row, w);
        } else {
            for (size_t x = 0; x < w; x++)
                g->cov[y * w + x] = (row[x >> 3] >> (7 - (x & 7))) & 1 ? 255 : 0;
        }
    }
    if (g->bytes > f->limit) {
        *tmp = g;
        return g;
    }
    while (f->tail && f->bytes + g->bytes > f->limit)
        evict(f, f->tail);
    g->hnext = f->bucket[hk];
    f->bucket[hk] = g;
    lru_front(f, g);
    f->bytes += g->bytes;
    f->entries++;
    return g;
}

/* ---- shaping ---- */

static int grow(fx_face *f, size_t n)
{
    if (n <= f->cap)
        return 0;
    size_t c = f->cap ? f->cap : 256;
    while (c < n)
        c *= 2;
#define GROW(p)                                              \
    do {                                                     \
        void *q = realloc(p, c * sizeof *(p));               \
        if (!q)                                              \
            return -FX_ENOMEM;                               \
        p = q;                                               \
    } while (0)
    GROW(f->cps);
    GROW(f->cpbyte);
    GROW(f->types);
    GROW(f->brackets);
    GROW(f->levels);
    GROW(f->cpfont);
#undef GROW
    f->cap = c;
    return 0;
}

/* UTF-8 to code points; each byte of an invalid sequence becomes U+FFFD.
 * Overlong forms, surrogates and values past U+10FFFF are invalid. */
static size_t decode(const uint8_t *s, size_t len, uint32_t *cp, uint32_t *at, int keep_breaks)
{
    size_t n = 0;
    for (size_t i = 0; i < len;) {
        uint32_t c = s[i];
        size_t k = c < 0x80 ? 1 : (c & 0xE0) == 0xC0 ? 2 : (c & 0xF0) == 0xE0 ? 3 : (c & 0xF8) == 0xF0 ? 4 : 0;
        uint32_t v = k == 2 ? c & 0x1F : k == 3 ? c & 0x0F : c & 0x07;
        int ok = k != 0 && i + k <= len;
        for (size_t j = 1; ok && j < k; j++) {
            ok = (s[i + j] & 0xC0) == 0x80;
            v = v << 6 | (s[i + j] & 0x3F);
        }
        if (k == 1)
            v = c;
        if (ok && ((k == 2 && v < 0x80) || (k == 3 && (v < 0x800 || (v >= 0xD800 && v < 0xE000))) ||
                   (k == 4 && (v < 0x10000 || v > 0x10FFFF))))
            ok = 0;
        at[n] = (uint32_t)i;
        if (!ok) {
            cp[n++] = 0xFFFD;
            i++;
            continue;
        }
        /* Line breaks in a single line shape as spaces. */
        cp[n++] = (!keep_breaks && (v == '\n' || v == '\r')) ? ' ' : v;
        i += k;
    }
    return n;
}

static int is_mark(uint32_t c)
{
    hb_unicode_general_category_t g = hb_unicode_general_category(hb_unicode_funcs_get_default(), c);
    return g == HB_UNICODE_GENERAL_CATEGORY_NON_SPACING_MARK || g == HB_UNICODE_GENERAL_CATEGORY_ENCLOSING_MARK ||
           g == HB_UNICODE_GENERAL_CATEGORY_SPACING_MARK || c == 0x200D || c == 0x200C ||
           (c >= 0xFE00 && c <= 0xFE0F);
}

static unsigned font_for(fx_face *f, uint32_t c)
{
    for (int i = 0; i < f->nfonts; i++) {
        if (f->fonts[i].failed)
            continue;
        if (!f->fonts[i].ft && font_open(f, i))
            continue;
        if (FT_Get_Char_Index(f->fonts[i].ft, c))
            return (unsigned)i;
    }
    return 0;
}

typedef struct run {
    size_t a, b;   /* code points [a, b) */
    uint8_t level, font;
    hb_script_t script;
} run;

static int push_glyphs(fx_face *f, const run *r, size_t len)
{
    hb_buffer_t *buf = f->buf;
    hb_buffer_clear_contents(buf);
    hb_buffer_add_utf32(buf, f->cps, (int)len, (unsigned)r->a, (int)(r->b - r->a));
    hb_buffer_set_direction(buf, (r->level & 1) ? HB_DIRECTION_RTL : HB_DIRECTION_LTR);
    hb_buffer_set_script(buf, r->script);
    hb_buffer_guess_segment_properties(buf);
    hb_shape(f->fonts[r->font].hb, buf, f->feats, f->nfeats);
    unsigned n;
    hb_glyph_info_t *gi = hb_buffer_get_glyph_infos(buf, &n);
    hb_glyph_position_t *gp = hb_buffer_get_glyph_positions(buf, &n);
    if (f->ng + n > f->gcap) {
        size_t c = f->gcap ? f->gcap : 256;
        while (c < f->ng + n)
            c *= 2;
        fx_glyph *q = realloc(f->glyphs, c * sizeof *q);
        if (!q)
            return -FX_ENOMEM;
        f->glyphs = q;
        f->gcap = c;
    }
    for (unsigned i = 0; i < n; i++) {
        fx_glyph *g = &f->glyphs[f->ng++];
        g->id = gi[i].codepoint;
        g->cluster = f->cpbyte[gi[i].cluster];
        g->x_advance = gp[i].x_advance;
        g->y_advance = gp[i].y_advance;
        g->x_offset = gp[i].x_offset;
        g->y_offset = gp[i].y_offset;
        g->font = r->font;
        g->level = r->level;
    }
    return 0;
}

int fx_face_shape(fx_face *f, const char *s, size_t len, const fx_glyph **out)
{
    if (!f || (!s && len) || !out)
        return -FX_EINVAL;
    *out = NULL;
    f->ng = 0;
    if (len > FX_FACE_MAX_TEXT) {
        set_err(f, "text of %zu bytes is longer than %u", len, FX_FACE_MAX_TEXT);
        return -FX_E2BIG;
    }
    if (grow(f, len + 1)) {
        set_err(f, "text of %zu bytes: out of memory", len);
        return -FX_ENOMEM;
    }
    size_t n = decode((const uint8_t *)s, len, f->cps, f->cpbyte, 0);
    f->cpbyte[n] = (uint32_t)len;
    if (!n) {
        *out = f->glyphs;
        return 0;
    }
    /* Levels (UAX #9 with brackets), the paragraph's direction from its
     * first strong character. */
    FriBidiParType pdir = FRIBIDI_PAR_ON;
    fribidi_get_bidi_types(f->cps, (FriBidiStrIndex)n, f->types);
    fribidi_get_bracket_types(f->cps, (FriBidiStrIndex)n, f->types, f->brackets);
    if (!fribidi_get_par_embedding_levels_ex(f->types, f->brackets, (FriBidiStrIndex)n, &pdir, f->levels)) {
        set_err(f, "bidi: FriBiDi failed on %zu code points", n);
        return -FX_ENOMEM;
    }
    /* Fonts: the first of the chain with the code point; marks stay on
     * their base's font when it has them. */
    for (size_t i = 0; i < n; i++) {
        unsigned fi = font_for(f, f->cps[i]);
        if (i && is_mark(f->cps[i]) && f->fonts[f->cpfont[i - 1]].ft &&
            FT_Get_Char_Index(f->fonts[f->cpfont[i - 1]].ft, f->cps[i]))
            fi = f->cpfont[i - 1];
        f->cpfont[i] = (uint8_t)fi;
    }
    /* Runs of one level, font and script (Common and Inherited join the
     * run they are in). Counted first, then walked in visual order. */
    hb_unicode_funcs_t *uf = hb_unicode_funcs_get_default();
    size_t nruns = 0, rcap = 64;
    run *runs = malloc(rcap * sizeof *runs);
    if (!runs)
        return -FX_ENOMEM;
    for (size_t i = 0; i < n;) {
        size_t j = i + 1;
        hb_script_t sc = hb_unicode_script(uf, f->cps[i]);
        while (j < n && f->levels[j] == f->levels[i] && f->cpfont[j] == f->cpfont[i]) {
            hb_script_t sj = hb_unicode_script(uf, f->cps[j]);
            if (sj != HB_SCRIPT_COMMON && sj != HB_SCRIPT_INHERITED && sj != HB_SCRIPT_UNKNOWN) {
                if (sc == HB_SCRIPT_COMMON || sc == HB_SCRIPT_INHERITED || sc == HB_SCRIPT_UNKNOWN)
                    sc = sj;
                else if (sj != sc)
                    break;
            }
            j++;
        }
        if (nruns == rcap) {
            run *q = realloc(runs, 2 * rcap * sizeof *runs);
            if (!q) {
                free(runs);
                return -FX_ENOMEM;
            }
            runs = q;
            rcap *= 2;
        }
        runs[nruns++] = (run){i, j, (uint8_t)f->levels[i], f->cpfont[i],
                              (sc == HB_SCRIPT_COMMON || sc == HB_SCRIPT_INHERITED) ? HB_SCRIPT_INVALID : sc};
        i = j;
    }
    /* L2: from the highest level down to the lowest odd one, reverse every
     * maximal sequence of runs at that level or higher. */
    uint8_t hi = 0, lo_odd = 255;
    for (size_t k = 0; k < nruns; k++) {
        hi = runs[k].level > hi ? runs[k].level : hi;
        if ((runs[k].level & 1) && runs[k].level < lo_odd)
            lo_odd = runs[k].level;
    }
    for (int lv = hi; lv >= (int)lo_odd && lv > 0; lv--)
        for (size_t k = 0; k < nruns;) {
            if (runs[k].level < lv) {
                k++;
                continue;
            }
            size_t e = k;
            while (e < nruns && runs[e].level >= lv)
                e++;
            for (size_t a = k, b = e - 1; a < b; a++, b--) {
                run t = runs[a];
                runs[a] = runs[b];
                runs[b] = t;
            }
            k = e;
        }
    int r = 0;
    for (size_t k = 0; k < nruns && !r; k++)
        r = push_glyphs(f, &runs[k], n);
    free(runs);
    if (r) {
        set_err(f, "shaping: out of memory");
        return r;
    }
    *out = f->glyphs;
    return (int)f->ng;
}

/* ---- drawing and measuring ---- */

static int32_t round64(int64_t v) { return (int32_t)((v + 32) >> 6); }

static void font_metrics(fx_face *f, fx_text_metrics *m)
{
    FT_Size_Metrics *sm = &f->fonts[0].ft->size->metrics;
    m->ascent = round64(sm->ascender);
    m->descent = round64(-sm->descender);
    m->line_height = round64(sm->height);
    if (m->line_height < m->ascent + m->descent)
        m->line_height = m->ascent + m->descent;
}

/* Walk the glyphs of s: draw them through c (when not NULL) and/or gather
 * the ink box. Pen positions are 26.6 from the origin, rounded per glyph. */
static int run_line(fx_face *f, const fx_ctx *c, int32_t x, int32_t y, const char *s, size_t len, unsigned rot,
                    fx_text_metrics *m)
{
    const fx_glyph *g;
    int n = fx_face_shape(f, s, len, &g);
    if (n < 0)
        return n;
    int64_t pen_x = 0, pen_y = 0;
    int64_t ix0 = INT32_MAX, iy0 = INT32_MAX, ix1 = INT32_MIN, iy1 = INT32_MIN;
    for (int i = 0; i < n; i++) {
        int64_t ox = round64(pen_x + g[i].x_offset), oy = round64(pen_y - g[i].y_offset);
        pen_x += g[i].x_advance;
        pen_y -= g[i].y_advance;
        if (pen_x > INT32_MAX * 16LL || pen_x < INT32_MIN * 16LL)
            break; /* past any surface */
        if (!c && !m)
            continue;
        gent *tmp;
        const gent *e = glyph_get(f, g[i].font, g[i].id, &tmp);
        if (!e || !e->w || !e->h) {
            free(tmp);
            continue;
        }
        int64_t dx = ox + e->left, dy = oy - e->top;
        if (m) {
            ix0 = dx < ix0 ? dx : ix0;
            iy0 = dy < iy0 ? dy : iy0;
            ix1 = dx + e->w > ix1 ? dx + e->w : ix1;
            iy1 = dy + e->h > iy1 ? dy + e->h : iy1;
        }
        if (c) {
            int64_t X, Y;
            switch (rot) {
            case FX_ROT_0: X = x + dx, Y = y + dy; break;
            case FX_ROT_90: X = x - (dy + e->h), Y = y + dx; break;
            case FX_ROT_180: X = x - (dx + e->w), Y = y - (dy + e->h); break;
            default: X = x + dy, Y = y - (dx + e->w); break;
            }
            if (X >= INT32_MIN && X <= INT32_MAX && Y >= INT32_MIN && Y <= INT32_MAX) {
                fx_mask mk = {e->cov, e->w, e->h, e->w};
                fx_mask_blend(c, (int32_t)X, (int32_t)Y, &mk, rot, f->mask_flags);
            }
        }
        free(tmp);
    }
    if (m) {
        memset(m, 0, sizeof *m);
        font_metrics(f, m);
        m->advance = round64(pen_x);
        m->glyphs = n;
        if (ix0 <= ix1)
            m->ink = (fx_rect){(int32_t)ix0, (int32_t)iy0, (int32_t)ix1, (int32_t)iy1};
    }
    return round64(pen_x);
}

int fx_face_measure(fx_face *f, const char *s, size_t len, fx_text_metrics *m)
{
    if (!f || !m || (!s && len))
        return -FX_EINVAL;
    int r = run_line(f, NULL, 0, 0, s, len, 0, m);
    return r < 0 ? r : 0;
}

int fx_face_draw(fx_face *f, const fx_ctx *c, int32_t x, int32_t y, const char *s, size_t len, unsigned rot)
{
    if (!f || !c || (!s && len) || rot > 3)
        return -FX_EINVAL;
    return run_line(f, c, x, y, s, len, rot, NULL);
}

/* The advance of s[a, b) without trailing white space and line breaks. */
static int advance_of(fx_face *f, const char *s, size_t a, size_t b, int32_t *adv)
{
    while (b > a && (s[b - 1] == ' ' || s[b - 1] == '\n' || s[b - 1] == '\r' || s[b - 1] == '\t'))
        b--;
    const fx_glyph *g;
    int n = fx_face_shape(f, s + a, b - a, &g);
    if (n < 0)
        return n;
    int64_t p = 0;
    for (int i = 0; i < n; i++)
        p += g[i].x_advance;
    *adv = round64(p);
    return 0;
}

static size_t next_cp(const char *s, size_t i, size_t len)
{
    i++;
    while (i < len && ((uint8_t)s[i] & 0xC0) == 0x80)
        i++;
    return i;
}

static int draw_one(fx_face *f, const fx_ctx *c, const fx_textbox *b, int32_t base, const char *s, size_t len)
{
    int32_t adv;
    int r = advance_of(f, s, 0, len, &adv);
    if (r < 0 || !c)
        return r;
    int32_t w = b->box.x1 - b->box.x0, x = b->box.x0;
    if (b->align == FX_ALIGN_CENTRE)
        x += (w - adv) / 2;
    else if (b->align == FX_ALIGN_RIGHT)
        x = b->box.x1 - adv;
    size_t e = len;
    while (e && (s[e - 1] == ' ' || s[e - 1] == '\n' || s[e - 1] == '\r'))
        e--;
    r = run_line(f, c, x, base, s, e, 0, NULL);
    return r < 0 ? r : 0;
}

/* The longest prefix of s[a, e) that, followed by the ellipsis, fits w. */
static int draw_ellipsized(fx_face *f, const fx_ctx *c, const fx_textbox *b, int32_t base, const char *s, size_t a,
                           size_t e, int32_t w)
{
    const char *ell = "\xE2\x80\xA6";
    if (!FT_Get_Char_Index(f->fonts[0].ft, 0x2026))
        ell = "...";
    size_t el = strlen(ell);
    /* Bisection over byte positions snapped to code point starts. */
    size_t lo = a, hi = e;
    char *tmp = malloc((e - a) + el + 1);
    if (!tmp)
        return -FX_ENOMEM;
    while (lo < hi) {
        size_t mid = lo + (hi - lo + 1) / 2;
        while (mid > lo && ((uint8_t)s[mid] & 0xC0) == 0x80 && mid < e)
            mid--;
        if (mid == lo)
            mid = next_cp(s, lo, e);
        memcpy(tmp, s + a, mid - a);
        memcpy(tmp + (mid - a), ell, el);
        int32_t adv;
        int r = advance_of(f, tmp, 0, mid - a + el, &adv);
        if (r < 0) {
            free(tmp);
            return r;
        }
        if (adv <= w)
            lo = mid;
        else
            hi = mid - 1;
        while (hi > lo && ((uint8_t)s[hi < e ? hi : e - 1] & 0xC0) == 0x80)
            hi--;
    }
    size_t k = lo - a;
    while (k && tmp && (s[a + k - 1] == ' '))
        k--;
    memcpy(tmp, s + a, k);
    memcpy(tmp + k, ell, el);
    int r = draw_one(f, c, b, base, tmp, k + el);
    free(tmp);
    return r;
}

int fx_face_draw_box(fx_face *f, const fx_ctx *c, const fx_textbox *b, const char *s, size_t len, int32_t *lines,
                     int *overflow)
{
    if (lines)
        *lines = 0;
    if (overflow)
        *overflow = 0;
    if (!f || !b || (!s && len))
        return -FX_EINVAL;
    if (len > FX_FACE_MAX_TEXT) {
        set_err(f, "text of %zu bytes is longer than %u", len, FX_FACE_MAX_TEXT);
        return -FX_E2BIG;
    }
    int64_t w = (int64_t)b->box.x1 - b->box.x0, h = (int64_t)b->box.y1 - b->box.y0;
    if (w <= 0 || h <= 0)
        return 0;
    fx_text_metrics fm;
    font_metrics(f, &fm);
    int64_t step = ((int64_t)fm.line_height * (b->line_spacing ? b->line_spacing : FX16_ONE) + 0x8000) >> 16;
    if (step < 1)
        step = 1;
    /* Break opportunities per byte (after it). libunibreak's own UTF-8
     * reader asserts on some invalid input (1.1: a truncated sequence at the
     * end, found by fuzz_face), so it gets the code points decoded here
     * (each invalid byte U+FFFD), and each code point's answer goes to its
     * last byte. */
    char *brk = malloc(len ? len : 1), *b32 = malloc(len ? len : 1);
    uint32_t *cp = malloc((len ? len : 1) * sizeof *cp), *at = malloc((len + 1) * sizeof *at);
    if (!brk || !b32 || !cp || !at) {
        free(brk), free(b32), free(cp), free(at);
        set_err(f, "text of %zu bytes: out of memory", len);
        return -FX_ENOMEM;
    }
    size_t ncp = decode((const uint8_t *)s, len, cp, at, 1);
    at[ncp] = (uint32_t)len;
    memset(brk, LINEBREAK_INSIDEACHAR, len);
    if (ncp) {
        set_linebreaks_utf32((const utf32_t *)cp, ncp, NULL, b32);
        for (size_t i = 0; i < ncp; i++)
            brk[at[i + 1] - 1] = b32[i];
    }
    free(b32), free(cp), free(at);
    /* A line of more than this many bytes would need glyphs narrower than a
     * quarter pixel on average: not measured, taken as too wide (bounds the
     * work of one enormous word). */
    size_t max_bytes = (size_t)w * 16 + 256;
    int32_t nl = 0;
    int64_t base = b->box.y0 + fm.ascent;
    size_t pos = 0;
    int r = 0, cut = 0;
    while (pos < len) {
        if (base + fm.descent > b->box.y1) {
            cut = 1;
            break;
        }
        /* The line: up to the last break opportunity that fits. */
        size_t best = 0, end = pos;
        int must = 0;
        for (size_t i = pos; i < len; i++) {
            if (brk[i] != LINEBREAK_ALLOWBREAK && brk[i] != LINEBREAK_MUSTBREAK && i + 1 != len)
                continue;
            size_t cand = i + 1;
            int32_t adv = 0;
            int fits = cand - pos <= max_bytes;
            if (fits && !b->no_wrap) {
                if ((r = advance_of(f, s, pos, cand, &adv)) < 0)
                    goto out;
                fits = adv <= w;
            }
            if (b->no_wrap && brk[i] != LINEBREAK_MUSTBREAK && i + 1 != len)
                continue;
            if (!fits && !b->no_wrap)
                break;
            best = cand;
            if (brk[i] == LINEBREAK_MUSTBREAK || b->no_wrap) {
                must = 1;
                break;
            }
        }
        (void)must;
        int wordcut = 0;
        if (!best) {
            /* Nothing fits: as many code points as fit, at least one. */
            end = next_cp(s, pos, len);
            for (size_t i = end; i < len && i - pos <= max_bytes;) {
                size_t nx = next_cp(s, i, len);
                int32_t adv;
                if ((r = advance_of(f, s, pos, nx, &adv)) < 0)
                    goto out;
                if (adv > w)
                    break;
                end = i = nx;
            }
            best = end;
            wordcut = 1;
        }
        int last = base + step + fm.descent > b->box.y1 && best < len;
        if (b->no_wrap && best - pos) {
            int32_t adv;
            if ((r = advance_of(f, s, pos, best, &adv)) < 0)
                goto out;
            if (adv > w) {
                wordcut = 1;
                if (b->ellipsis)
                    r = draw_ellipsized(f, c, b, (int32_t)base, s, pos, best, (int32_t)w);
                else
                    r = draw_one(f, c, b, (int32_t)base, s + pos, best - pos);
                if (r < 0)
                    goto out;
                nl++;
                pos = best;
                base += step;
                cut = 1;
                continue;
            }
        }
        if (last && b->ellipsis) {
            /* The rest of the paragraph (up to the next hard break, at most
             * a box's worth) ellipsized into this line. */
            size_t e = best;
            while (e < len && e - pos <= max_bytes && brk[e - 1] != LINEBREAK_MUSTBREAK)
                e++;
            r = draw_ellipsized(f, c, b, (int32_t)base, s, pos, e, (int32_t)w);
        } else
            r = draw_one(f, c, b, (int32_t)base, s + pos, best - pos);
        if (r < 0)
            goto out;
        nl++;
        if (wordcut)
            cut |= 2;
        pos = best;
        base += step;
        if (last) {
            cut = 1;
            break;
        }
    }
out:
    free(brk);
    if (lines)
        *lines = nl;
    if (overflow)
        *overflow = cut & 1 ? 1 : (cut & 2 ? 2 : 0);
    return r < 0 ? r : 0;
}

int32_t fx_face_fit(fx_face *f, const fx_textbox *b, const char *s, size_t len, int32_t min_px, int32_t max_px)
{
    if (!f || !b || (!s && len) || min_px < 1 || max_px > FX_FACE_MAX_PX || min_px > max_px)
        return -FX_EINVAL;
    int32_t lo = min_px, hi = max_px, good = 0;
    while (lo <= hi) {
        int32_t mid = lo + (hi - lo) / 2;
        int ov = 0;
        int r = fx_face_set_size(f, mid);
        if (!r)
            r = fx_face_draw_box(f, NULL, b, s, len, NULL, &ov);
        if (r < 0)
            return r;
        if (!ov) {
            good = mid;
            lo = mid + 1;
        } else
            hi = mid - 1;
    }
    fx_face_set_size(f, good ? good : min_px);
    if (!good) {
        set_err(f, "text does not fit the box even at %ld px", (long)min_px);
        return -FX_ERANGE;
    }
    return good;
}
