/* SPDX-License-Identifier: MIT */
/* fixel — seed fills: flood fill and boundary fill, 4- and 8-connected.
 *
 * A scan-line seed fill over spans, never recursive per pixel: a span is
 * grown to its full run on its row, painted, marked visited and pushed; a
 * popped span scans the rows above and below over its extent (one pixel
 * wider for 8-connectivity) for runs to grow next. Each pixel is tested a
 * bounded number of times, so time is proportional to the region's area.
 *
 * The visited bitmap (one bit per pixel of the clip rectangle) decides what
 * is done, not the pixel colours, so patterned, blended or same-colour fills
 * terminate and never leak through what they paint. When the span stack is
 * full a span is painted but its neighbours are left for later: once the
 * stack drains, the visited runs are rescanned and the fill goes on, so any
 * stack size gives the same pixels (a small one only costs time). */
#include "fixel/error.h"
#include "fixel/fill.h"
#include "../base/fx_internal.h"

typedef struct {
    int32_t y, x0, x1; /* inclusive run */
} seed_span;

typedef struct {
    const fx_ctx *c;
    fx_rect r;         /* clip */
    int bpp;
    uint32_t mask;     /* native bits that count (the X byte does not) */
    uint32_t key;      /* flood: the seed's value; boundary: the boundary's */
    int boundary;      /* 1: inside = not key; 0: inside = key */
    int diag;          /* 8-connected */
    uint64_t *vis;
    int32_t vstride;   /* words per row */
    seed_span *stack;
    int32_t cap, top;
    int overflow;
} seed_t;

static inline uint32_t get_px(const seed_t *s, const uint8_t *row, int32_t x)
{
    switch (s->bpp) {
    case 32: return ((const uint32_t *)row)[x];
    case 16: return ((const uint16_t *)row)[x];
    case 24: row += x * 3; return row[0] | ((uint32_t)row[1] << 8) | ((uint32_t)row[2] << 16);
    case 8: return row[x];
    default: {
        int32_t bit = s->c->surf.bit_offset + x;
        return (row[bit >> 3] >> (bit & 7)) & 1;
    }
    }
}

static inline int visited(const seed_t *s, int32_t x, int32_t y)
{
    int32_t i = x - s->r.x0;
    return (int)((s->vis[(size_t)(y - s->r.y0) * (size_t)s->vstride + (size_t)(i >> 6)] >> (i & 63)) & 1);
}

static inline int inside(const seed_t *s, const uint8_t *row, int32_t x, int32_t y)
{
    if (visited(s, x, y))
        return 0;
    uint32_t v = get_px(s, row, x) & s->mask;
    return s->boundary ? v != s->key : v == s->key;
}

static void mark(seed_t *s, int32_t y, int32_t x0, int32_t x1) /* inclusive */
{
    uint64_t *w = s->vis + (size_t)(y - s->r.y0) * (size_t)s->vstride;
    for (int32_t i = x0 - s->r.x0, e = x1 - s->r.x0; i <= e;) {
        if ((i & 63) == 0 && e - i >= 63) {
            w[i >> 6] = ~(uint64_t)0;
            i += 64;
        } else {
            w[i >> 6] |= (uint64_t)1 << (i & 63);
            i++;
        }
    }
}

/* Grow the run through (x, y) (known inside), paint, mark, push. */
static int32_t grow(seed_t *s, const uint8_t *row, int32_t x, int32_t y)
{
    int32_t a = x, b = x;
    while (a > s->r.x0 && inside(s, row, a - 1, y))
        a--;
    while (b + 1 < s->r.x1 && inside(s, row, b + 1, y))
        b++;
    mark(s, y, a, b);
    fx_fill_span(s->c, y, a, b + 1);
    if (s->top < s->cap) {
        seed_span sp = {y, a, b};
        s->stack[s->top++] = sp;
    } else {
        s->overflow = 1;
    }
    return b;
}

/* Look for runs on row ny next to the run [x0, x1] of another row. */
static void scan_row(seed_t *s, int32_t ny, int32_t x0, int32_t x1)
{
    if (ny < s->r.y0 || ny >= s->r.y1)
        return;
    if (s->diag) {
        x0--;
        x1++;
    }
    x0 = FX_MAX(x0, s->r.x0);
    x1 = FX_MIN(x1, s->r.x1 - 1);
    const uint8_t *row = fx_row(&s->c->surf, ny);
    for (int32_t x = x0; x <= x1; x++)
        if (inside(s, row, x, ny))
            x = grow(s, row, x, ny);
}

static void drain(seed_t *s)
{
    while (s->top > 0) {
        seed_span sp = s->stack[--s->top];
        scan_row(s, sp.y - 1, sp.x0, sp.x1);
        scan_row(s, sp.y + 1, sp.x0, sp.x1);
    }
}

size_t fx_seed_work_size(const fx_ctx *c)
{
    size_t w = (size_t)(c->clip.x1 - c->clip.x0), h = (size_t)(c->clip.y1 - c->clip.y0);
    if (fx_rect_empty(c->clip))
        w = h = 0;
    return ((w + 63) / 64) * 8 * h + FX_SEED_STACK_DEFAULT * sizeof(seed_span);
}

static int seed_fill(const fx_ctx *c, int32_t x, int32_t y, int boundary, fx_color bcol, int conn, void *work,
                     size_t size)
{
    if (conn != 4 && conn != 8)
        return -FX_EINVAL;
    fx_rect r = c->clip;
    if (fx_rect_empty(r) || x < r.x0 || x >= r.x1 || y < r.y0 || y >= r.y1)
        return 0;
    seed_t s;
    s.c = c;
    s.r = r;
    s.bpp = fx_format_get(c->surf.format)->bits_per_pixel;
    s.mask = (c->surf.format == FX_FMT_XRGB8888 || c->surf.format == FX_FMT_XBGR8888) ? 0xFFFFFFu : 0xFFFFFFFFu;
    s.boundary = boundary;
    s.diag = conn == 8;
    s.vstride = (r.x1 - r.x0 + 63) / 64;
    size_t vbytes = (size_t)s.vstride * 8 * (size_t)(r.y1 - r.y0);
    uintptr_t base = ((uintptr_t)work + 7) & ~(uintptr_t)7;
    size_t skew = (size_t)(base - (uintptr_t)work);
    if (!work || size < skew + vbytes + FX_SEED_STACK_MIN * sizeof(seed_span))
        return -FX_ENOSPC;
    s.vis = (uint64_t *)base;
    fx_memset(s.vis, 0, vbytes);
    s.stack = (seed_span *)(base + vbytes);
    s.cap = (int32_t)FX_MIN((size - skew - vbytes) / sizeof(seed_span), (size_t)INT32_MAX);
    s.top = 0;
    s.overflow = 0;
    const uint8_t *row = fx_row(&c->surf, y);
    s.key = boundary ? fx_pack(c->surf.format, bcol) & s.mask : get_px(&s, row, x) & s.mask;
    if (!inside(&s, row, x, y))
        return 0;
    grow(&s, row, x, y);
    drain(&s);
    /* Spans that found a full stack were painted but not explored: rescan
     * the visited runs until a pass finds nothing new. */
    while (s.overflow) {
        s.overflow = 0;
        for (int32_t yy = r.y0; yy < r.y1; yy++) {
            for (int32_t xx = r.x0; xx < r.x1; xx++) {
                if (!visited(&s, xx, yy))
                    continue;
                int32_t b = xx;
                while (b + 1 < r.x1 && visited(&s, b + 1, yy))
                    b++;
                scan_row(&s, yy - 1, xx, b);
                scan_row(&s, yy + 1, xx, b);
                drain(&s);
                xx = b;
            }
        }
    }
    return 0;
}

int fx_flood_fill(const fx_ctx *c, int32_t x, int32_t y, int conn, void *work, size_t size)
{
    return seed_fill(c, x, y, 0, 0, conn, work, size);
}

int fx_boundary_fill(const fx_ctx *c, int32_t x, int32_t y, fx_color boundary, int conn, void *work,
                     size_t size)
{
    return seed_fill(c, x, y, 1, boundary, conn, work, size);
}
