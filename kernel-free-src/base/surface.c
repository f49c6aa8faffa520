/* SPDX-License-Identifier: MIT */
/* fixel — surfaces, the format table, pack/unpack and the span loops. */
#include "fixel/surface.h"
#include "fixel/error.h"
#include "fx_internal.h"

/* Pixel words are stored little-endian (DRM fourcc order); the span fills
 * build byte patterns on that assumption. */
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "fixel supports little-endian targets only"
#endif

#define FOURCC(a, b, c, d) \
    ((uint32_t)(a) | ((uint32_t)(b) << 8) | ((uint32_t)(c) << 16) | ((uint32_t)(d) << 24))

FX_HIDDEN const fx_format_info fx_format_table[FX_FMT_COUNT] = {
    [FX_FMT_XRGB8888] = {"XRGB8888", FOURCC('X', 'R', '2', '4'), 32, 0},
    [FX_FMT_ARGB8888] = {"ARGB8888", FOURCC('A', 'R', '2', '4'), 32, 1},
    [FX_FMT_XBGR8888] = {"XBGR8888", FOURCC('X', 'B', '2', '4'), 32, 0},
    [FX_FMT_RGB565] = {"RGB565", FOURCC('R', 'G', '1', '6'), 16, 0},
    [FX_FMT_BGR565] = {"BGR565", FOURCC('B', 'G', '1', '6'), 16, 0},
    [FX_FMT_RGB888] = {"RGB888", FOURCC('R', 'G', '2', '4'), 24, 0},
    [FX_FMT_BGR888] = {"BGR888", FOURCC('B', 'G', '2', '4'), 24, 0},
    [FX_FMT_GRAY8] = {"GRAY8", FOURCC('R', '8', ' ', ' '), 8, 0},
    [FX_FMT_MONO1] = {"MONO1", 0, 1, 0},
};

const fx_format_info *fx_format_get(fx_format f)
{
    return (unsigned)f < FX_FMT_COUNT ? &fx_format_table[f] : 0;
}

static int lower(int c) { return c >= 'A' && c <= 'Z' ? c + 32 : c; }

/* A row without a name or with an empty one (a format added to the enum but
 * not to the table) is skipped rather than read through NULL; the unit test
 * format_table_rows_are_named_and_unique fails on such a row. */
fx_format fx_format_from_name(const char *name)
{
    if (!name)
        return FX_FMT_COUNT;
    for (int f = 0; f < FX_FMT_COUNT; f++) {
        const char *a = fx_format_table[f].name, *b = name;
        if (!a || !*a)
            continue;
        while (*a && lower(*a) == lower(*b))
            a++, b++;
        if (!*a && !*b)
            return (fx_format)f;
    }
    return FX_FMT_COUNT;
}

/* Saturates at INT32_MAX: 2^30 XRGB8888 pixels wrapped to 0 (issue #26). */
int32_t fx_format_min_stride(fx_format f, int32_t w)
{
    if ((unsigned)f >= FX_FMT_COUNT || w < 0) /* the table is indexed by f */
        return 0;
    int64_t b = ((int64_t)w * fx_format_table[f].bits_per_pixel + 7) / 8;
    return b > INT32_MAX ? INT32_MAX : (int32_t)b;
}

int fx_surface_init(fx_surface *s, void *pixels, int32_t w, int32_t h, int32_t stride,
                    fx_format format)
{
    if (!s || (unsigned)format >= FX_FMT_COUNT || !pixels || w <= 0 || h <= 0)
        return -FX_EINVAL;
    /* the whole row in 64 bits: a width of 2^30 with stride 4 was accepted */
    int64_t need = ((int64_t)w * fx_format_table[format].bits_per_pixel + 7) / 8;
    int64_t mag = stride < 0 ? -(int64_t)stride : stride;
    unsigned bpp = fx_format_table[format].bits_per_pixel;
    unsigned align = bpp == 32 ? 4 : bpp == 16 ? 2 : 1;
    /* Word formats are accessed as aligned words: misaligned memory would be
     * undefined behaviour (and a fault on older ARM cores). */
    if (mag < need || mag % align || (uintptr_t)pixels % align)
        return -FX_EINVAL;
    s->pixels = pixels;
    s->w = w;
    s->h = h;
    s->stride = stride;
    s->format = format;
    s->bit_offset = 0;
    s->fill_isa = fx_x86_fill_level();
    s->stream_mib = fx_x86_stream_mib();
    return 0;
}

fx_rect fx_rect_intersect(fx_rect a, fx_rect b) { return fx_rect_meet(a, b); }

fx_rect fx_rect_rotate(fx_rect r, int rotation, int32_t W, int32_t H)
{
    fx_rect o;
    switch (rotation) {
    case 90:
        o.x0 = W - r.y1; o.x1 = W - r.y0; o.y0 = r.x0; o.y1 = r.x1;
        break;
    case 180:
        o.x0 = W - r.x1; o.x1 = W - r.x0; o.y0 = H - r.y1; o.y1 = H - r.y0;
        break;
    case 270:
        o.x0 = r.y0; o.x1 = r.y1; o.y0 = H - r.x1; o.y1 = H - r.x0;
        break;
    default:
        o = r;
        break;
    }
    return o;
}

fx_surface fx_surface_sub(fx_surface s, fx_rect r)
{
    r = fx_rect_intersect(r, fx_surface_rect(&s));
    fx_surface t = s;
    t.w = r.x1 - r.x0;
    t.h = r.y1 - r.y0;
    if (t.w <= 0 || t.h <= 0) {
        t.w = t.h = 0;
        return t;
    }
    t.pixels = fx_row(&s, r.y0);
    if (s.format == FX_FMT_MONO1) {
        int32_t bit = s.bit_offset + r.x0;
        t.pixels += bit >> 3;
        t.bit_offset = (uint8_t)(bit & 7);
    } else {
        t.pixels += (ptrdiff_t)r.x0 * (fx_format_table[s.format].bits_per_pixel / 8);
    }
    return t;
}

uint32_t fx_pack(fx_format f, fx_color c) { return fx_pack_inline(f, c); }

/* No default case, as in fx_pack_inline: -Wswitch names a missing format. */
fx_color fx_unpack(fx_format f, uint32_t v)
{
    uint32_t r, g, b;
    switch (f) {
    case FX_FMT_XRGB8888:
    case FX_FMT_RGB888: return 0xFF000000u | (v & 0xFFFFFF);
    case FX_FMT_ARGB8888: return v;
    case FX_FMT_XBGR8888:
    case FX_FMT_BGR888:
        return 0xFF000000u | ((v & 0xFF) << 16) | (v & 0xFF00) | ((v >> 16) & 0xFF);
    case FX_FMT_RGB565:
    case FX_FMT_BGR565:
        r = (v >> 11) & 0x1F;
        g = (v >> 5) & 0x3F;
        b = v & 0x1F;
        if (f == FX_FMT_BGR565) {
            uint32_t t = r;
            r = b;
            b = t;
        }
        r = (r << 3) | (r >> 2);
        g = (g << 2) | (g >> 4);
        b = (b << 3) | (b >> 2);
        return 0xFF000000u | (r << 16) | (g << 8) | b;
    case FX_FMT_GRAY8: v &= 0xFF; return 0xFF000000u | (v << 16) | (v << 8) | v;
    case FX_FMT_MONO1: return v & 1 ? 0xFFFFFFFFu : 0xFF000000u;
    case FX_FMT_COUNT: break; /* no format */
    }
    return 0;
}

uint32_t fx_surface_get_native(const fx_surface *s, int32_t x, int32_t y)
{
    const uint8_t *row = fx_row(s, y);
    switch (fx_format_table[s->format].bits_per_pixel) {
    case 32: return ((const uint32_t *)row)[x];
    case 16: return ((const uint16_t *)row)[x];
    case 24: row += x * 3; return row[0] | ((uint32_t)row[1] << 8) | ((uint32_t)row[2] << 16);
    case 8: return row[x];
    default: {
        int32_t bit = s->bit_offset + x;
        return (row[bit >> 3] >> (bit & 7)) & 1;
    }
    }
}

void fx_surface_put_native(const fx_surface *s, int32_t x, int32_t y, uint32_t v)
{
    uint8_t *row = fx_row(s, y);
    switch (fx_format_table[s->format].bits_per_pixel) {
    case 32: ((uint32_t *)row)[x] = v; break;
    case 16: ((uint16_t *)row)[x] = (uint16_t)v; break;
    case 24:
        row += x * 3;
        row[0] = (uint8_t)v;
        row[1] = (uint8_t)(v >> 8);
        row[2] = (uint8_t)(v >> 16);
        break;
    case 8: row[x] = (uint8_t)v; break;
    default: {
        int32_t bit = s->bit_offset + x;
        uint8_t m = (uint8_t)(1u << (bit & 7));
        if (v & 1)
            row[bit >> 3] |= m;
        else
            row[bit >> 3] &= (uint8_t)~m;
    }
    }
}

void fx_surface_put(const fx_surface *s, int32_t x, int32_t y, fx_color c)
{
    if ((uint32_t)x < (uint32_t)s->w && (uint32_t)y < (uint32_t)s->h)
        fx_surface_put_native(s, x, y, fx_pack(s->format, c));
}

fx_color fx_surface_get(const fx_surface *s, int32_t x, int32_t y)
{
    if ((uint32_t)x < (uint32_t)s->w && (uint32_t)y < (uint32_t)s->h)
        return fx_unpack(s->format, fx_surface_get_native(s, x, y));
    return 0;
}

static void mono_span(uint8_t *row, int32_t b0, int32_t b1, int on)
{
    /* bits [b0, b1) of the row */
    while (b0 < b1 && (b0 & 7)) {
        uint8_t m = (uint8_t)(1u << (b0 & 7));
        row[b0 >> 3] = on ? row[b0 >> 3] | m : row[b0 >> 3] & (uint8_t)~m;
        b0++;
    }
    if (b1 - b0 >= 8) {
        fx_memset(row + (b0 >> 3), on ? 0xFF : 0, (size_t)((b1 - b0) >> 3));
        b0 += (b1 - b0) & ~7;
    }
    while (b0 < b1) {
        uint8_t m = (uint8_t)(1u << (b0 & 7));
        row[b0 >> 3] = on ? row[b0 >> 3] | m : row[b0 >> 3] & (uint8_t)~m;
        b0++;
    }
}

void fx_span_fill(const fx_surface *s, int32_t y, int32_t x0, int32_t x1, uint32_t v)
{
    uint8_t *row = fx_row(s, y);
    int32_t n = x1 - x0;
    if (n <= 0)
        return;
    switch (fx_format_table[s->format].bits_per_pixel) {
    case 32: fx_run32((uint32_t *)(void *)row + x0, n, v); break;
    case 16: fx_run16((uint16_t *)(void *)row + x0, n, (uint16_t)v); break;
    case 24: {
        uint8_t *p = row + (size_t)x0 * 3, b0 = (uint8_t)v, b1 = (uint8_t)(v >> 8), b2 = (uint8_t)(v >> 16);
        /* eight pixels are 24 bytes: three words of a fixed pattern */
        uint8_t pat[24];
        for (int i = 0; i < 24; i += 3)
            pat[i] = b0, pat[i + 1] = b1, pat[i + 2] = b2;
        for (; n >= 8; n -= 8, p += 24)
            fx_memcpy(p, pat, 24);
        while (n--) {
            p[0] = b0;
            p[1] = b1;
            p[2] = b2;
            p += 3;
        }
        break;
    }
    case 8: fx_memset(row + x0, (int)(v & 0xFF), (size_t)n); break;
    default: mono_span(row, s->bit_offset + x0, s->bit_offset + x1, v & 1); break;
    }
}

/* Whole rows of an unpadded buffer (pixels of bytes >= 1) are one run: a
 * clear is a single loop with no per-row head and tail. */
static inline int whole_rows(const fx_surface *s, fx_rect r, unsigned bytes)
{
    return bytes && r.x0 == 0 && r.x1 == s->w && s->stride == (int64_t)s->w * bytes;
}

/* The common rectangle of fx_rect_fill_native: 32- or 16-bit pixels, rows
 * shorter than a rep-stos run and not merged into one run, on a CPU with
 * the AVX fills. Inline, so that fx_rect_fill_native stays frameless on
 * its way to the vector loop. 0 when it is not that case (nothing
 * written); r is clipped. */
static inline int rect_fill_short(const fx_surface *s, fx_rect r, uint32_t v)
{
#if FX_X86_FILL
    unsigned bytes = fx_format_table[s->format].bits_per_pixel / 8u;
    if (r.x0 >= r.x1 || r.y0 >= r.y1 || !s->fill_isa || (bytes != 4 && bytes != 2) ||
        (size_t)(r.x1 - r.x0) * bytes >= FX_STOS_MIN_BYTES || whole_rows(s, r, bytes) ||
        (((uintptr_t)s->pixels | (uintptr_t)(intptr_t)s->stride) & (bytes - 1)))
        return 0;
    if (s->fill_isa == FX_FILL_AVX512)
        fx_rect_fill_avx512(s, r, v);
    else
        fx_rect_fill_avx(s, r, v);
    return 1;
#else
    (void)s, (void)r, (void)v;
    return 0;
#endif
}

__attribute__((noinline)) static void rect_fill_general(const fx_surface *s, fx_rect r, uint32_t v)
{
    int bpp = fx_format_table[s->format].bits_per_pixel;
    int32_t w = r.x1 - r.x0, h = r.y1 - r.y0;
    if (w <= 0 || h <= 0)
        return;
    if (whole_rows(s, r, (unsigned)bpp / 8) && (int64_t)w * h <= INT32_MAX) { /* a run's length is an int32_t */
        w *= h;
        h = 1;
    }
    /* The format is chosen once per rectangle; rows advance by the stride. */
    uint8_t *row = fx_row(s, r.y0);
#if FX_X86_FILL
    if (h == 1 && (bpp == 32 || bpp == 16) && (size_t)w * (size_t)bpp / 8 >= fx_stream_min(s) &&
        !((uintptr_t)row & (size_t)(bpp / 8 - 1))) {
        uint64_t pat = bpp == 32 ? (v & 0xFFFFFFFFull) * 0x100000001ull : (v & 0xFFFF) * 0x0001000100010001ull;
        (s->fill_isa ? fx_stream_fill_avx : fx_stream_fill)(row + (size_t)r.x0 * (size_t)(bpp / 8),
                                                           (size_t)w * (size_t)(bpp / 8), pat);
        return;
    }
#endif
    switch (bpp) {
    case 32:
        for (row += (size_t)r.x0 * 4; h--; row += s->stride)
            fx_run32((uint32_t *)(void *)row, w, v);
        break;
    case 16:
        for (row += (size_t)r.x0 * 2; h--; row += s->stride)
            fx_run16((uint16_t *)(void *)row, w, (uint16_t)v);
        break;
    default:
        for (int32_t y = r.y0; y < r.y1; y++)
            fx_span_fill(s, y, r.x0, r.x1, v);
        break;
    }
}

/* The common rectangle (rect_fill_short) goes straight to the vector
 * loop, everything else to the general function: kept apart so that this
 * entry, and fx_fill_rect before it, need no stack frame. Register saves
 * and spills are stack stores, queued behind the previous rectangle's
 * stores to lines not in the cache; they cost W2 6-8 % against the same
 * loop called directly. */
void fx_rect_fill_native(const fx_surface *s, fx_rect r, uint32_t v)
{
    if (!rect_fill_short(s, r, v))
        rect_fill_general(s, r, v);
}

void fx_surface_fill(const fx_surface *s, fx_rect r, fx_color c)
{
    r = fx_rect_intersect(r, fx_surface_rect(s));
    if (!fx_rect_empty(r))
        fx_rect_fill_native(s, r, fx_pack(s->format, c));
}

void fx_surface_clear(const fx_surface *s, fx_color c) { fx_surface_fill(s, fx_surface_rect(s), c); }

void fx_blit(const fx_surface *dst, int32_t dx, int32_t dy, const fx_surface *src)
{
    if (!dst || !src)
        return;
    fx_rect r = {dx, dy, dx, dy};
    r.x1 = (int32_t)FX_MIN((int64_t)dx + src->w, INT32_MAX);
    r.y1 = (int32_t)FX_MIN((int64_t)dy + src->h, INT32_MAX);
    r = fx_rect_intersect(r, fx_surface_rect(dst));
    if (fx_rect_empty(r))
        return;
    int32_t sx = r.x0 - dx, sy = r.y0 - dy, w = r.x1 - r.x0, h = r.y1 - r.y0;
    /* Walk rows bottom-up when the destination lies after the source in
     * memory, so overlapping views of one buffer copy correctly. */
    const uint8_t *s_first = fx_row(src, sy), *d_first = fx_row(dst, r.y0);
    int up = d_first > s_first;
    unsigned bpp = fx_format_table[dst->format].bits_per_pixel;
    if (src->format == dst->format && bpp >= 8) {
        size_t bytes = (size_t)w * (bpp / 8), off_s = (size_t)sx * (bpp / 8),
               off_d = (size_t)r.x0 * (bpp / 8);
        /* Unpadded whole rows on both sides are one block: a single memmove
         * runs at libc's full-buffer speed (and keeps the overlap rule)
         * instead of paying its per-call set-up on every row. */
        if (dst->stride == (int64_t)bytes && src->stride == (int64_t)bytes) {
            uint8_t *d = fx_row(dst, r.y0) + off_d;
            const uint8_t *sp = s_first + off_s;
            size_t n = bytes * (size_t)h;
#if FX_X86_FILL
            if (2 * n >= fx_stream_min(dst) && (d + n <= sp || sp + n <= d)) {
                fx_stream_copy(d, sp, n);
                return;
            }
#endif
            fx_memmove(d, sp, n);
            return;
        }
        for (int32_t i = 0; i < h; i++) {
            int32_t k = up ? h - 1 - i : i;
            fx_memmove(fx_row(dst, r.y0 + k) + off_d, fx_row(src, sy + k) + off_s, bytes);
        }
        return;
    }
    int same = src->format == dst->format;
    for (int32_t i = 0; i < h; i++) {
        int32_t k = up ? h - 1 - i : i;
        for (int32_t j = 0; j < w; j++) {
            int32_t m = up ? w - 1 - j : j;
            uint32_t v = fx_surface_get_native(src, sx + m, sy + k);
            if (!same)
                v = fx_pack(dst->format, fx_unpack(src->format, v));
            fx_surface_put_native(dst, r.x0 + m, r.y0 + k, v);
        }
    }
}

void fx_surface_row_to_rgb(const fx_surface *s, int32_t y, uint8_t *rgb)
{
    for (int32_t x = 0; x < s->w; x++) {
        fx_color c = fx_unpack(s->format, fx_surface_get_native(s, x, y));
        *rgb++ = (uint8_t)(c >> 16);
        *rgb++ = (uint8_t)(c >> 8);
        *rgb++ = (uint8_t)c;
    }
}
