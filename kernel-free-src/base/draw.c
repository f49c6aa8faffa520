/* SPDX-License-Identifier: MIT */
/* fixel — drawing context, clipped pixels/spans/rectangles, blending, and the
 * small printf-style formatter behind tracing. */
#include "fixel/draw.h"
#include "fixel/fixed.h"
#include "fixel/error.h"
#include "fx_internal.h"
#include "fx_span.h"

void fx_ctx_init(fx_ctx *c, const fx_surface *s)
{
    if (!c)
        return;
    fx_memset(c, 0, sizeof *c);
    if (!s)
        return; /* an empty context: no surface, an empty clip, draws nothing */
    c->surf = *s;
    c->clip = fx_surface_rect(s);
    fx_ctx_set_color(c, 0xFFFFFFFFu);
}

void fx_ctx_set_color(fx_ctx *c, fx_color color)
{
    c->color = color;
    c->native = fx_pack_inline(c->surf.format, color);
}

void fx_ctx_set_clip(fx_ctx *c, fx_rect r) { c->clip = fx_rect_intersect(r, fx_surface_rect(&c->surf)); }
void fx_ctx_reset_clip(fx_ctx *c) { c->clip = fx_surface_rect(&c->surf); }

static fx_rect mirror_rows(fx_rect r, int32_t h)
{
    fx_rect m = {r.x0, fx_sat32((int64_t)h - r.y1), r.x1, fx_sat32((int64_t)h - r.y0)};
    return m;
}

int fx_ctx_set_coords(fx_ctx *c, fx_coords mode)
{
    if (!c || (mode != FX_COORDS_SCREEN && mode != FX_COORDS_COURSE))
        return -FX_EINVAL;
    if (c->coords == (uint8_t)mode)
        return 0;
    /* Both directions are the same reflection: the view's row 0 becomes its
     * last row. An empty context (no pixels) has nothing to turn. */
    if (c->surf.pixels && c->surf.h > 0) {
        if (c->surf.stride == INT32_MIN)
            return -FX_EINVAL; /* cannot be negated; fx_surface_init never makes one */
        c->surf.pixels += (intptr_t)(c->surf.h - 1) * (intptr_t)c->surf.stride;
        c->surf.stride = -c->surf.stride;
    }
    c->clip = mirror_rows(c->clip, c->surf.h);
    c->exterior_rect = mirror_rows(c->exterior_rect, c->surf.h);
    c->coords = (uint8_t)mode;
    return 0;
}

static uint32_t div255(uint32_t x) { return (x + 128 + ((x + 128) >> 8)) >> 8; }

uint32_t fx_blend_over(fx_format f, uint32_t dst, fx_color c)
{
    uint32_t a = c >> 24;
    if (a == 255)
        return fx_pack(f, c);
    if (a == 0)
        return dst;
    fx_color d = fx_unpack(f, dst);
    uint32_t out = 0;
    for (int sh = 0; sh < 24; sh += 8) {
        uint32_t s = (c >> sh) & 0xFF, t = (d >> sh) & 0xFF;
        out |= div255(s * a + t * (255 - a)) << sh;
    }
    uint32_t da = d >> 24;
    out |= (a + div255(da * (255 - a))) << 24;
    return fx_pack(f, out);
}

/* [x0, x1) already inside the clip rectangle. */
static void span_in_clip(const fx_ctx *c, int32_t y, int32_t x0, int32_t x1)
{
    if (c->blend == FX_BLEND_OVER && (c->color >> 24) != 255) {
        for (int32_t x = x0; x < x1; x++)
            fx_surface_put_native(&c->surf, x, y,
                                  fx_blend_over(c->surf.format,
                                                fx_surface_get_native(&c->surf, x, y), c->color));
        return;
    }
    fx_span_fill(&c->surf, y, x0, x1, c->native);
}

void fx_hspan(const fx_ctx *c, int32_t y, int32_t x0, int32_t x1) { fx_clip_span(c, y, x0, x1, span_in_clip); }

void fx_plot(const fx_ctx *c, int32_t x, int32_t y)
{
    if (x < c->clip.x0 || x >= c->clip.x1 || y < c->clip.y0 || y >= c->clip.y1)
        return;
    if (c->exterior && x >= c->exterior_rect.x0 && x < c->exterior_rect.x1 &&
        y >= c->exterior_rect.y0 && y < c->exterior_rect.y1)
        return;
    if (c->blend == FX_BLEND_OVER && (c->color >> 24) != 255)
        fx_surface_put_native(
            &c->surf, x, y,
            fx_blend_over(c->surf.format, fx_surface_get_native(&c->surf, x, y), c->color));
    else
        fx_surface_put_native(&c->surf, x, y, c->native);
}

static fx_rect rect_from(int32_t x, int32_t y, int32_t w, int32_t h)
{
    fx_rect r = {x, y, fx_sat32((int64_t)x + w), fx_sat32((int64_t)y + h)};
    return r;
}

/* Apart, so that fx_fill_rect needs no stack frame: fx_rect_fill_native
 * says why that matters. */
__attribute__((noinline)) static void fill_rect_spans(const fx_ctx *c, fx_rect r)
{
    for (int32_t yy = r.y0; yy < r.y1; yy++)
        fx_hspan(c, yy, r.x0, r.x1);
}

void fx_fill_rect(const fx_ctx *c, int32_t x, int32_t y, int32_t w, int32_t h)
{
    if (w <= 0 || h <= 0)
        return;
    fx_rect r = fx_rect_meet(rect_from(x, y, w, h), c->clip);
    if (fx_rect_empty(r))
        return;
    if (c->exterior || (c->blend != FX_BLEND_SRC && (c->color >> 24) != 255))
        fill_rect_spans(c, r);
    else
        fx_rect_fill_native(&c->surf, r, c->native);
}

void fx_rect_outline(const fx_ctx *c, int32_t x, int32_t y, int32_t w, int32_t h)
{
    if (w <= 0 || h <= 0)
        return;
    fx_rect r = rect_from(x, y, w, h);
    if (fx_rect_empty(r)) /* saturated at INT32_MAX: nothing representable */
        return;
    int32_t top = r.y0, bottom = r.y1 - 1;
    fx_hspan(c, top, r.x0, r.x1);
    if (bottom != top)
        fx_hspan(c, bottom, r.x0, r.x1);
    /* Only the visible rows of the sides: bounded by the clip, not by h. */
    int32_t y0 = (int32_t)FX_MAX((int64_t)top + 1, c->clip.y0), y1 = FX_MIN(bottom, c->clip.y1);
    for (int32_t yy = y0; yy < y1; yy++) {
        fx_plot(c, r.x0, yy);
        if (r.x1 - 1 != r.x0)
            fx_plot(c, r.x1 - 1, yy);
    }
}

void fx_clear(const fx_ctx *c) { fx_fill_rect(c, c->clip.x0, c->clip.y0, c->clip.x1 - c->clip.x0, c->clip.y1 - c->clip.y0); }

/* ---- formatter ---- */

typedef struct {
    char *buf;
    size_t size, len;
} out_t;

static void put(out_t *o, char ch)
{
    if (o->len + 1 < o->size)
        o->buf[o->len] = ch;
    o->len++;
}

static void put_field(out_t *o, const char *s, size_t n, int width, int left, char pad)
{
    int fill = width > (int)n ? width - (int)n : 0;
    if (!left && pad == '0' && n && (*s == '-')) { /* sign before zero padding */
        put(o, *s++);
        n--;
    }
    if (!left)
        while (fill-- > 0)
            put(o, pad);
    while (n--)
        put(o, *s++);
    if (left)
        while (fill-- > 0)
            put(o, ' ');
}

int fx_vfmt(char *buf, size_t size, const char *fmt, va_list ap)
{
    out_t o = {buf, size, 0};
    for (; *fmt; fmt++) {
        if (*fmt != '%') {
            put(&o, *fmt);
            continue;
        }
        fmt++;
        int left = 0, width = 0, lng = 0;
        char pad = ' ';
        for (;; fmt++) {
            if (*fmt == '-')
                left = 1;
            else if (*fmt == '0')
                pad = '0';
            else
                break;
        }
        while (*fmt >= '0' && *fmt <= '9')
            width = width * 10 + (*fmt++ - '0');
        int prec = -1;
        if (*fmt == '.') {
            fmt++;
            prec = 0;
            if (*fmt == '*') {
                prec = va_arg(ap, int);
                fmt++;
            } else {
                while (*fmt >= '0' && *fmt <= '9')
                    prec = prec * 10 + (*fmt++ - '0');
            }
        }
        while (*fmt == 'l')
            lng++, fmt++;
        char tmp[24];
        int n = 0;
        switch (*fmt) {
        case 'd':
        case 'i': {
            long long v = lng >= 2 ? va_arg(ap, long long) : lng ? va_arg(ap, long) : va_arg(ap, int);
            unsigned long long u = v < 0 ? 0ull - (unsigned long long)v : (unsigned long long)v;
            char rev[24];
            int k = 0;
            do
                rev[k++] = (char)('0' + u % 10);
            while (u /= 10);
            if (v < 0)
                tmp[n++] = '-';
            while (k)
                tmp[n++] = rev[--k];
            put_field(&o, tmp, (size_t)n, width, left, pad);
            break;
        }
        case 'u':
        case 'x':
        case 'X': {
            unsigned long long u = lng >= 2 ? va_arg(ap, unsigned long long)
                                   : lng    ? va_arg(ap, unsigned long)
                                            : va_arg(ap, unsigned);
            unsigned base = *fmt == 'u' ? 10 : 16;
            const char *dig = *fmt == 'X' ? "0123456789ABCDEF" : "0123456789abcdef";
            char rev[24];
            int k = 0;
            do
                rev[k++] = dig[u % base];
            while (u /= base);
            while (k)
                tmp[n++] = rev[--k];
            put_field(&o, tmp, (size_t)n, width, left, pad);
            break;
        }
        case 's': {
            const char *s = va_arg(ap, const char *);
            if (!s)
                s = "(null)";
            size_t len = 0;
            while ((prec < 0 || len < (size_t)prec) && s[len])
                len++;
            put_field(&o, s, len, width, left, ' ');
            break;
        }
        case 'c': tmp[0] = (char)va_arg(ap, int); put_field(&o, tmp, 1, width, left, ' '); break;
        case '%': put(&o, '%'); break;
        case '\0': fmt--; break;
        default: put(&o, '%'); put(&o, *fmt); break;
        }
    }
    if (size)
        buf[o.len < size ? o.len : size - 1] = '\0';
    return (int)o.len;
}

int fx_fmt(char *buf, size_t size, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = fx_vfmt(buf, size, fmt, ap);
    va_end(ap);
    return n;
}

void fx_trace(const fx_ctx *c, const char *fmt, ...)
{
    if (!c->trace)
        return;
    char line[256];
    va_list ap;
    va_start(ap, fmt);
    fx_vfmt(line, sizeof line, fmt, ap);
    va_end(ap);
    c->trace(c->trace_user, line);
}
