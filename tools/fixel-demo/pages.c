/* SPDX-License-Identifier: MIT */
/* fixel-demo pages: each draws a whole page from demo_state alone, so the
 * headless pictures are a pure function of the state. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "demo.h"
#include "fixel/circle.h"
#include "fixel/colormap.h"
#include "fixel/colour.h"
#include "fixel/fill.h"
#include "fixel/fixed.h"
#include "fixel/font.h"
#include "fixel/fractal.h"
#include "fixel/boxdim.h"
#include "fixel/julia.h"
#include "fixel/randfract.h"
#include "fixel/turtle.h"
#include "fixel/ifs.h"
#include "fixel/koch.h"
#include "fixel/line.h"
#include "fixel/mat3d.h"
#include "fixel/mesh.h"
#include "fixel/par.h"
#include "fixel/render3d.h"
#include "fixel/rt.h"
#include "fixel/texture.h"
#include "fixel/viz.h"
#include "fixel/xform.h"

#define BG      0xFF101820u
#define PANEL   0xFF18263Au
#define INK     0xFFE8E8E8u
#define DIM     0xFF7A8AA0u
#define ACCENT  0xFFF2C14Eu
#define ORANGE  0xFFF78154u
#define BLUE    0xFF4D9DE0u
#define GREEN   0xFF7BC96Fu
#define RED     0xFFE15554u

void demo_text(const fx_ctx *c, int32_t x, int32_t y, fx_color col, const char *fmt, ...)
{
    char buf[256];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    fx_ctx t = *c;
    fx_ctx_set_color(&t, col);
    fx_text(&t, x, y, buf);
}

void demo_text_big(const fx_ctx *c, int32_t x, int32_t y, fx_color col, int scale, const char *s)
{
    fx_text_style ts;
    memset(&ts, 0, sizeof ts);
    ts.scale = scale;
    fx_ctx t = *c;
    t.text_style = &ts;
    fx_ctx_set_color(&t, col);
    fx_text(&t, x, y, s);
}

static void color(fx_ctx *c, fx_color col) { fx_ctx_set_color(c, col); }

static void panel(fx_ctx *c, int32_t x, int32_t y, int32_t w, int32_t h, const char *label)
{
    color(c, PANEL);
    fx_fill_rect(c, x, y, w, h);
    color(c, 0xFF2E4A6Bu);
    fx_rect_outline(c, x, y, w, h);
    if (label)
        demo_text(c, x + 6, y + 5, ACCENT, "%s", label);
}

/* ---- lines ---- */
static void page_lines(fx_ctx *c, demo_state *st)
{
    (void)st;
    int32_t top = DEMO_TAB_H + 8;
    panel(c, 8, top, 300, 260, "Bresenham fan, every octant");
    static const fx_color fan[8] = {ORANGE, ACCENT, GREEN, BLUE, 0xFFC77DFFu, RED, 0xFF5CE1E6u, INK};
    int32_t cx = 158, cy = top + 140;
    for (int i = 0; i < 48; i++) {
        fx_angle a = (fx_angle)((uint32_t)i * (0x100000000ull / 48));
        int32_t ex = cx + fx16_round(fx16_mul(fx_cos(a), fx16_from_int(110)));
        int32_t ey = cy - fx16_round(fx16_mul(fx_sin(a), fx16_from_int(110)));
        color(c, fan[i / 6]);
        fx_line(c, cx, cy, ex, ey);
    }
    /* a clipped line whose ends are far outside the surface */
    panel(c, 8, top + 268, 300, 176, "Clipped from +-100000, exactly");
    fx_ctx k = *c;
    fx_ctx_set_clip(&k, fx_rect_intersect((fx_rect){9, top + 286, 307, top + 443}, c->clip));
    for (int i = 0; i < 24; i++) {
        fx_angle a = (fx_angle)((uint32_t)i * (0x80000000u / 24));
        int32_t dx = fx16_round(fx16_mul(fx_cos(a), fx16_from_int(100000)));
        int32_t dy = fx16_round(fx16_mul(fx_sin(a), fx16_from_int(100000)));
        color(&k, fx_cmap_color(FX_CMAP_VIRIDIS, (uint32_t)(i * 2600 + 4000)));
        fx_line(&k, 158 - dx, top + 364 - dy, 158 + dx, top + 364 + dy);
    }

    /* the course's example: (10,12) -> (15,15), each pixel a 30-px cell */
    int32_t gx = 320, gy = top, cell = 30;
    panel(c, gx, gy, 240, 260, "Zoomed: (10,12) -> (15,15)");
    int32_t ox = gx + 15, oy = gy + 40;
    fx_bres b;
    fx_bres_init(&b, 10, 12, 15, 15);
    for (int32_t yy = 11; yy <= 16; yy++)
        for (int32_t xx = 9; xx <= 15; xx++) {
            color(c, 0xFF22364Fu);
            fx_fill_rect(c, ox + (xx - 9) * cell, oy + (yy - 11) * cell, cell - 1, cell - 1);
        }
    for (int32_t xx = 9; xx <= 15; xx++)
        demo_text(c, ox + (xx - 9) * cell + 9, oy + 6 * cell + 4, DIM, "%d", xx);
    for (int32_t yy = 11; yy <= 16; yy++)
        demo_text(c, ox + 7 * cell + 4, oy + (yy - 11) * cell + 10, DIM, "%d", yy);
    fx_bres it = b;
    for (uint32_t k2 = 0; k2 <= b.major; k2++) {
        color(c, ORANGE);
        fx_fill_rect(c, ox + (it.x - 9) * cell + 2, oy + (it.y - 11) * cell + 2, cell - 5, cell - 5);
        if (k2 < b.major)
            fx_bres_step(&it);
    }
    /* the ideal line through the pixel centres */
    color(c, INK);
    fx_line(c, ox + 1 * cell + cell / 2, oy + 1 * cell + cell / 2, ox + 6 * cell + cell / 2,
            oy + 4 * cell + cell / 2);

    /* the decision table */
    int32_t tx = 572;
    panel(c, tx, top, 220, 260, "Decision table");
    demo_text(c, tx + 8, top + 24, DIM, "dx=%u dy=%u", b.major, b.minor);
    demo_text(c, tx + 8, top + 36, DIM, "p0=2dy-dx=%lld", (long long)b.p);
    demo_text(c, tx + 8, top + 48, DIM, "2dy=%u 2dy-2dx=%d", 2 * b.minor,
              (int)(2 * (int32_t)b.minor - 2 * (int32_t)b.major));
    demo_text(c, tx + 8, top + 68, ACCENT, " k   p_k   next pixel");
    it = b;
    for (uint32_t k2 = 0; k2 < b.major; k2++) {
        long long p = (long long)it.p;
        fx_bres_step(&it);
        demo_text(c, tx + 8, top + 84 + (int32_t)k2 * 14, INK, "%2u  %4lld   (%d,%d)", k2, p, it.x,
                  it.y);
    }
    demo_text(c, tx + 8, top + 84 + (int32_t)b.major * 14 + 8, DIM, "p<0: keep y   p>=0: y+1");

    /* line widths from parallel strokes, and colours */
    panel(c, 320, top + 268, 472, 176, "Slopes and colours");
    for (int i = 0; i < 16; i++) {
        color(c, fx_cmap_color(FX_CMAP_HSV, (uint32_t)(i * 4096)));
        fx_line(c, 352 + i * 27, top + 430, 352 + i * 27 + (i - 8) * 2, top + 300);
    }
    for (int i = 0; i < 8; i++) {
        color(c, fx_cmap_color(FX_CMAP_HOT, (uint32_t)(20000 + i * 6000)));
        fx_line(c, 336, top + 296 + i * 2, 776, top + 296 + i * 2 + i * 17);
    }
}

/* ---- circles ---- */
static void page_circles(fx_ctx *c, demo_state *st)
{
    (void)st;
    int32_t top = DEMO_TAB_H + 8;
    panel(c, 8, top, 256, 220, "Midpoint circles");
    for (int r = 6; r <= 96; r += 10) {
        color(c, fx_cmap_color(FX_CMAP_VIRIDIS, (uint32_t)(r * 650)));
        fx_circle(c, 136, top + 118, r);
    }
    panel(c, 272, top, 256, 220, "Discs and anti-aliased");
    color(c, BLUE);
    fx_disc(c, 340, top + 110, 50);
    color(c, ACCENT);
    fx_disc(c, 380, top + 140, 30);
    color(c, INK);
    for (int r = 20; r <= 80; r += 20)
        fx_aacircle(c, 460, top + 120, r / 2 + 10);
    panel(c, 536, top, 256, 220, "Ellipses");
    for (int i = 0; i < 6; i++) {
        color(c, fx_cmap_color(FX_CMAP_HOT, (uint32_t)(16000 + i * 8000)));
        fx_ellipse(c, 664, top + 120, 110 - i * 16, 20 + i * 14);
    }
    panel(c, 8, top + 228, 384, 216, "Arcs: +angle turns clockwise, y down");
    for (int i = 0; i < 8; i++) {
        color(c, fx_cmap_color(FX_CMAP_HSV, (uint32_t)(i * 8192)));
        fx_arc(c, 200, top + 340, 20 + i * 11, fx_angle_from_deg(-(i * 30 + 200)), fx_angle_from_deg(-(i * 30)));
    }
    panel(c, 400, top + 228, 392, 216, "Pies (+angle clockwise), filled ellipses");
    static const int32_t share[5] = {90, 70, 100, 60, 40};
    uint32_t a = 0;
    for (int i = 0; i < 5; i++) {
        color(c, fx_cmap_color(FX_CMAP_VIRIDIS, (uint32_t)(i * 15000 + 3000)));
        fx_pie(c, 500, top + 340, 80, fx_angle_from_deg(-(int32_t)a - share[i]), fx_angle_from_deg(-(int32_t)a));
        a += (uint32_t)share[i];
    }
    color(c, ORANGE);
    fx_fill_ellipse(c, 690, top + 310, 80, 30);
    color(c, BLUE);
    fx_fill_ellipse(c, 690, top + 375, 40, 25);
}

/* ---- clipping playground ---- */
static const char *clipper_name(int k)
{
    return k == FX_CLIP_COHEN ? "Cohen-Sutherland" : k == FX_CLIP_LIANG ? "Liang-Barsky" : "Nicholl-Lee-Nicholl";
}

static void code_str(unsigned code, char *s)
{
    /* TBRL, as in the course */
    for (int i = 0; i < 4; i++)
        s[i] = (code >> (3 - i)) & 1 ? '1' : '0';
    s[4] = 0;
}

/* The chosen clipper's trace, collected for the readout: each line without
 * the decimal forms "(0.250000)" the narrow panel has no room for. */
typedef struct clip_log {
    char line[24][96];
    int n;
} clip_log;

static void clip_log_line(void *user, const char *line)
{
    clip_log *l = user;
    if (l->n >= 24)
        return;
    char *o = l->line[l->n++];
    size_t k = 0;
    for (const char *p = line; *p && k + 1 < sizeof l->line[0]; p++) {
        if (*p == ' ' && p[1] == '(' && p[2] >= '0' && p[2] <= '9') {
            while (*p && *p != ')')
                p++;
            if (!*p)
                break;
            continue;
        }
        if (*p == ' ' && (k == 0 || o[k - 1] == ' '))
            continue; /* leading and doubled blanks */
        o[k++] = *p;
    }
    o[k] = 0;
}

/* The playground is drawn in the course's frame (fx_ctx_set_coords: origin
 * bottom-left, y up), so the region codes sit where the notes draw them,
 * 1000 (top) above the window, and the numbers are the notes'. The state
 * keeps the pointer's screen coordinates; cy() turns them. */
static void page_clipping(fx_ctx *c, demo_state *st)
{
    int32_t top = DEMO_TAB_H + 8, H = c->surf.h;
#define cy(y) (H - 1 - (y))
    fx_rect area = {8, top, 572, st->h - 8};
    panel(c, area.x0, area.y0, area.x1 - area.x0, area.y1 - area.y0, NULL);
    fx_ctx a = *c;
    fx_ctx_set_clip(&a, fx_rect_intersect((fx_rect){area.x0 + 1, area.y0 + 1, area.x1 - 1, area.y1 - 1}, c->clip));
    fx_ctx_set_coords(&a, FX_COORDS_COURSE);
    fx_rect w = {st->win.x0, H - st->win.y1, st->win.x1, H - st->win.y0};
    fx_rect ar = {area.x0, H - area.y1, area.x1, H - area.y0};
    int32_t lx0 = st->lx0, ly0 = cy(st->ly0), lx1 = st->lx1, ly1 = cy(st->ly1);
#undef cy
    /* the nine regions: the window's edges extended */
    color(&a, 0xFF2E4A6Bu);
    fx_line(&a, w.x0, ar.y0, w.x0, ar.y1);
    fx_line(&a, w.x1 - 1, ar.y0, w.x1 - 1, ar.y1);
    fx_line(&a, ar.x0, w.y0, ar.x1, w.y0);
    fx_line(&a, ar.x0, w.y1 - 1, ar.x1, w.y1 - 1);
    int32_t xs[3] = {(ar.x0 + w.x0) / 2, (w.x0 + w.x1) / 2, (w.x1 + ar.x1) / 2};
    int32_t ys[3] = {(ar.y0 + w.y0) / 2, (w.y0 + w.y1) / 2, (w.y1 + ar.y1) / 2};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            char s[5];
            code_str(fx_clip_region_code(w, xs[j], ys[i]), s);
            demo_text(&a, xs[j] - 12, ys[i] + 4, 0xFF3F5F85u, "%s", s); /* text: top-left corner, upright */
        }
    color(&a, 0xFF1E3A5Fu);
    fx_fill_rect(&a, w.x0, w.y0, w.x1 - w.x0, w.y1 - w.y0);
    color(&a, ACCENT);
    fx_rect_outline(&a, w.x0, w.y0, w.x1 - w.x0, w.y1 - w.y0);
    /* the whole line faint, the clipped part bright */
    color(&a, 0xFF5A6478u);
    fx_line(&a, lx0, ly0, lx1, ly1);
    fx_ctx k = a;
    k.line_clipper = (uint8_t)st->clipper;
    fx_ctx_set_clip(&k, fx_rect_intersect(w, a.clip));
    color(&k, ORANGE);
    fx_line(&k, lx0, ly0, lx1, ly1);
    color(&a, GREEN);
    fx_disc(&a, lx0, ly0, 4);
    color(&a, BLUE);
    fx_disc(&a, lx1, ly1, 4);

    /* the readouts, in the course's coordinates */
    int32_t px = 580, ty = top + 24;
    panel(c, px, top, 212, st->h - 8 - top, "Clipping");
    demo_text(c, px + 8, ty, INK, "%s", clipper_name(st->clipper));
    demo_text(c, px + 8, ty += 12, DIM, "keys c / l / n switch");
    demo_text(c, px + 8, ty += 12, DIM, "y up, origin bottom-left");
    demo_text(c, px + 8, ty += 16, DIM, "window (%d,%d)-(%d,%d)", w.x0, w.y0, w.x1 - 1, w.y1 - 1);
    char s0[5], s1[5];
    unsigned c0 = fx_clip_region_code(w, lx0, ly0), c1 = fx_clip_region_code(w, lx1, ly1);
    code_str(c0, s0);
    code_str(c1, s1);
    demo_text(c, px + 8, ty += 16, GREEN, "P0 (%d,%d) code %s", lx0, ly0, s0);
    demo_text(c, px + 8, ty += 12, BLUE, "P1 (%d,%d) code %s", lx1, ly1, s1);
    demo_text(c, px + 8, ty += 14, DIM, "codes: top bottom right left");
    const char *verdict = (c0 | c1) == 0 ? "trivially accepted" : (c0 & c1) ? "trivially rejected" : "needs clipping";
    demo_text(c, px + 8, ty += 12, INK, "%s", verdict);
    /* the chosen algorithm at work: its own trace, the notes' numbers */
    static clip_log log;
    log.n = 0;
    fx_ctx t = a;
    t.trace = clip_log_line;
    t.trace_user = &log;
    fx_clip_param p;
    fx_clip_line_param(&t, (fx_line_clipper)st->clipper, w, lx0, ly0, lx1, ly1, &p);
    ty += 16;
    const int cols = 25;
    for (int i = 0; i < log.n && ty < st->h - 60; i++) {
        const char *l = log.line[i];
        for (size_t o = 0, n = strlen(l); o < n && ty < st->h - 60;) {
            size_t len = (size_t)(o ? cols - 2 : cols); /* continuation rows indented */
            if (n - o > len) { /* break at the last blank that fits */
                size_t b = len;
                while (b > 0 && l[o + b] != ' ')
                    b--;
                if (b > 0)
                    len = b;
            } else {
                len = n - o;
            }
            demo_text(c, px + 8 + (o ? 16 : 0), ty, o ? DIM : INK, "%.*s", (int)len, l + o);
            o += len;
            while (l[o] == ' ')
                o++;
            ty += 11;
        }
    }
    uint32_t k0, k1;
    if (fx_clip_line_steps(NULL, (fx_line_clipper)st->clipper, w, lx0, ly0, lx1, ly1, &k0, &k1))
        demo_text(c, px + 8, st->h - 56, ACCENT, "visible steps %u..%u", k0, k1);
    else
        demo_text(c, px + 8, st->h - 56, ACCENT, "no visible steps");
    demo_text(c, px + 8, st->h - 40, DIM, "drag the dots or the window");
}

/* Styled fills (patterns, shaders) go through fx_fill_span, which the
 * polygon fills use; rectangles and discs are built from it here. */
static void styled_rect(const fx_ctx *c, int32_t x, int32_t y, int32_t w, int32_t h)
{
    for (int32_t r = y; r < y + h; r++)
        fx_fill_span(c, r, x, x + w);
}

/* A copy of c that fills through shade(user), with fs as its fill style. */
static fx_ctx shader_ctx(const fx_ctx *c, fx_fill_style *fs, fx_shade_fn shade, const void *user)
{
    memset(fs, 0, sizeof *fs);
    fs->kind = FX_FILL_SHADER;
    fs->shade = shade;
    fs->user = user;
    fx_ctx s = *c;
    s.fill_style = fs;
    return s;
}

static void styled_disc(const fx_ctx *c, int32_t cx, int32_t cy, int32_t r)
{
    for (int32_t dy = -r; dy <= r; dy++) {
        int32_t hw = (int32_t)fx_isqrt32((uint32_t)(r * r - dy * dy));
        fx_fill_span(c, cy + dy, cx - hw, cx + hw + 1);
    }
}

/* ---- fills ---- */
static const uint8_t pat_brick[8] = {0xFF, 0x80, 0x80, 0x80, 0xFF, 0x08, 0x08, 0x08};

static void fill_shapes(fx_ctx *c, int32_t top)
{
    /* outlines the flood fill runs inside */
    color(c, INK);
    fx_circle(c, 110, top + 120, 80);
    fx_circle(c, 110, top + 120, 40);
    fx_line(c, 30, top + 120, 190, top + 120);
    fx_rect_outline(c, 220, top + 40, 160, 160);
    fx_line(c, 220, top + 40, 379, top + 199);
    fx_line(c, 379, top + 40, 220, top + 199);
}

static void page_fills(fx_ctx *c, demo_state *st)
{
    int32_t top = DEMO_TAB_H + 8;
    panel(c, 8, top, 392, 230, "Flood fill: click inside a region");
    fill_shapes(c, top);
    size_t need = fx_seed_work_size(c);
    void *work = malloc(need);
    static const fx_color seedcol[6] = {ORANGE, BLUE, GREEN, ACCENT, 0xFFC77DFFu, RED};
    if (work)
        for (int i = 0; i < st->nseeds; i++) {
            fx_ctx f = *c;
            fx_ctx_set_clip(&f, (fx_rect){9, top + 1, 399, top + 229});
            color(&f, seedcol[i % 6]);
            fx_flood_fill(&f, st->seedx[i], st->seedy[i], 4, work, need);
        }
    free(work);

    panel(c, 408, top, 384, 230, "Even-odd and nonzero");
    int32_t star[10];
    for (int s = 0; s < 2; s++) {
        int32_t cx = 500 + s * 196, cy = top + 125;
        for (int i = 0; i < 5; i++) {
            fx_angle a = (fx_angle)(FX_ANGLE_90 + (uint32_t)(i * 2) * (0x100000000ull / 5));
            star[2 * i] = cx + fx16_round(fx16_mul(fx_cos(a), fx16_from_int(85)));
            star[2 * i + 1] = cy - fx16_round(fx16_mul(fx_sin(a), fx16_from_int(85)));
        }
        color(c, s ? GREEN : BLUE);
        fx_fill_poly(c, star, 5, s ? FX_FILL_NONZERO : FX_FILL_EVENODD);
        demo_text(c, cx - 30, top + 214, DIM, "%s", s ? "nonzero" : "even-odd");
    }

    panel(c, 8, top + 238, 392, 206, "Gouraud triangles");
    int32_t tri[6] = {30, top + 430, 200, top + 260, 380, top + 430};
    fx_color tc[3] = {0xFFFF3030u, 0xFF30FF30u, 0xFF3030FFu};
    fx_fill_tri_gouraud(c, tri, tc);

    panel(c, 408, top + 238, 384, 206, "Pattern fills");
    fx_fill_style fs;
    memset(&fs, 0, sizeof fs);
    fs.kind = FX_FILL_PATTERN;
    fs.bits = pat_brick;
    fs.w = 8;
    fs.h = 8;
    fs.stride = 1;
    fs.bg = 0xFF5A2A1Eu;
    fx_ctx p = *c;
    p.fill_style = &fs;
    color(&p, 0xFFC8B8A0u);
    int32_t hex[12];
    for (int i = 0; i < 6; i++) {
        fx_angle a = (fx_angle)((uint32_t)i * (0x100000000ull / 6));
        hex[2 * i] = 510 + fx16_round(fx16_mul(fx_cos(a), fx16_from_int(80)));
        hex[2 * i + 1] = top + 345 - fx16_round(fx16_mul(fx_sin(a), fx16_from_int(80)));
    }
    fx_fill_poly(&p, hex, 6, FX_FILL_EVENODD);
    static const uint8_t pat_dots[4] = {0x88, 0x00, 0x22, 0x00};
    fs.bits = pat_dots;
    fs.w = 8;
    fs.h = 4;
    fs.bg_transparent = 1;
    color(&p, ACCENT);
    styled_disc(&p, 690, top + 345, 80);
    color(c, ACCENT);
    fx_circle(c, 690, top + 345, 80);
}


/* ---- textures ---- */
static fx_rect clip_in(const fx_ctx *c, fx_rect r);

/* A Phong-shaded sphere in r, bump mapped (bump > 0) or frame mapped
 * (frame: FX_RT_FRAME_*), lit from the upper left: the two perturbations
 * of the local frame that the notes name among the texturing methods. */
static void draw_mapped_sphere(fx_ctx *c, fx_rect r, fx_color col, fx16 bump, int frame)
{
    fx_surface s = fx_surface_sub(c->surf, r);
    fx_rect band = clip_in(c, r);
    if (fx_rect_empty(band))
        return;
    fx_mesh_params mp = {FX_MESH_SPHERE, FX16_ONE, 0, 0, 40, 20};
    int32_t nv, nt;
    if (fx_mesh_size(&mp, &nv, &nt) < 0)
        return;
    fx_mesh m;
    memset(&m, 0, sizeof m);
    m.pos = malloc((size_t)nv * 2 * sizeof(fx_vec3));
    m.tri = malloc((size_t)nt * 3 * sizeof(uint32_t));
    void *z = malloc(fx3d_depth_bytes(&s, 32));
    fx3d *rd = malloc(sizeof *rd);
    fx_mat4 ms[2], ps[2];
    if (m.pos && m.tri && z && rd) {
        m.nrm = m.pos + nv;
        m.cap_verts = nv;
        m.cap_tris = nt;
        if (fx_mesh_make(&m, &mp) == 0 && fx3d_init(rd, &s, ms, 2, ps, 2) == 0) {
            rd->ctx.clip = fx_rect_intersect(rd->ctx.clip, band);
            fx3d_set_depth(rd, z, 32);
            fx3d_perspective(rd, fx_angle_from_deg(40), fx16_from_ratio(s.w, s.h), FX16_ONE / 2, 50 * FX16_ONE);
            rd->light[0].type = FX3D_LIGHT_DIRECTIONAL;
            rd->light[0].pos = fx_vec3_make(-FX16_ONE, FX16_ONE, 2 * FX16_ONE);
            rd->ambient = fx3d_rgb_from_color(0x303030);
            rd->mat.ambient = rd->mat.diffuse = fx3d_rgb_from_color(col);
            rd->mat.specular = fx3d_rgb_from_color(0xFFFFFF);
            rd->mat.shininess = 40;
            rd->shading = FX3D_PHONG;
            if (bump > 0)
                fx3d_bump(rd, bump, FX16_ONE / 4);
            if (frame)
                fx3d_frame(rd, frame, FX16_ONE, FX16_ONE / 16);
            fx_mat4 *top = fx_mat_stack_top(&rd->model), tilt;
            fx_mat4_translate(top, 0, 0, -4 * FX16_ONE);
            fx_mat4_rotate_x(&tilt, frame == FX_RT_FRAME_SPUN ? FX_ANGLE_90 * 2 / 3 : 0);
            fx_mat4_mul(top, top, &tilt);
            fx3d_draw(rd, &m);
        }
    }
    free(rd);
    free(z);
    free(m.tri);
    free(m.pos);
}

static void page_textures(fx_ctx *c, demo_state *st)
{
    (void)st;
    int32_t top = DEMO_TAB_H + 8;
    static const char *names[5] = {"fake sphere", "noise", "turbulence", "wood", "marble"};
    static const fx_color c0[5] = {0xFF102040u, 0xFF000000u, 0xFF200818u, 0xFF5A3414u, 0xFF303038u};
    static const fx_color c1[5] = {0xFF9FD0FFu, 0xFFFFFFFFu, 0xFFFFB040u, 0xFFD8A060u, 0xFFF0F0F0u};
    for (int i = 0; i < 5; i++) {
        int32_t x = 8 + i * 157;
        panel(c, x, top, 150, 170, names[i]);
        fx_proc_map m;
        memset(&m, 0, sizeof m);
        m.kind = i;
        m.seed = 7;
        m.x0 = i == 0 ? x + 75 - 100 : x + 7;
        m.y0 = i == 0 ? top + 92 - 100 : top + 22;
        m.size = i == 0 ? 200 : 68; /* the sphere has radius 0.3 units */
        m.c0 = c0[i];
        m.c1 = c1[i];
        fx_fill_style fs;
        fx_ctx s = shader_ctx(c, &fs, fx_proc_shade, &m);
        styled_rect(&s, x + 7, top + 22, 136, 140);
    }
    /* a checkerboard texture mapped onto a quad */
    uint32_t texels[64 * 64]; /* per call: bands draw at once (fixel/par.h) */
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 64; x++)
            texels[y * 64 + x] = ((x / 8 + y / 8) & 1) ? 0xFFF2C14Eu : 0xFF1E3A5Fu;
    fx_texture tx;
    memset(&tx, 0, sizeof tx);
    fx_surface_init(&tx.img, texels, 64, 64, 64 * 4, FX_FMT_XRGB8888);
    tx.wrap = FX_TEX_REPEAT;
    tx.filter = FX_TEX_BILINEAR;
    panel(c, 8, top + 178, 236, 266, "Texture mapped (bilinear)");
    int32_t quad[8] = {28, top + 420, 70, top + 220, 200, top + 240, 232, top + 430};
    fx16 st4[8] = {0, FX16_ONE * 2, 0, 0, FX16_ONE * 2, 0, FX16_ONE * 2, FX16_ONE * 2};
    fx_fill_poly_tex(c, quad, st4, 4, &tx);

    panel(c, 252, top + 178, 160, 266, "Linear gradient");
    fx_gradient g;
    memset(&g, 0, sizeof g);
    g.x0 = 266;
    g.y0 = top + 200;
    g.x1 = 400;
    g.y1 = top + 430;
    g.nstops = 4;
    g.stops[0] = 0xFF1E3A5Fu;
    g.stops[1] = 0xFF4D9DE0u;
    g.stops[2] = 0xFFF2C14Eu;
    g.stops[3] = 0xFFF78154u;
    fx_fill_style gs;
    fx_ctx s = shader_ctx(c, &gs, fx_gradient_shade, &g);
    styled_rect(&s, 260, top + 200, 144, 236);

    panel(c, 420, top + 178, 160, 266, "Radial gradient");
    fx_gradient r;
    memset(&r, 0, sizeof r);
    r.radial = 1;
    r.x0 = 480;
    r.y0 = top + 290;
    r.r = 80;
    r.nstops = 3;
    r.stops[0] = 0xFFFFFFFFu;
    r.stops[1] = 0xFFE15554u;
    r.stops[2] = 0xFF18263Au;
    gs.user = &r;
    styled_disc(&s, 500, top + 316, 72);

    /* bump mapping tilts the normal; frame mapping turns the whole frame,
     * so the highlight runs across the grain (Kajiya-Kay, fixel/rt.h) */
    panel(c, 588, top + 178, 204, 266, "Bump / frame mapping");
    static const char *mname[4] = {"plain", "bumped", "brushed", "spun"};
    for (int i = 0; i < 4; i++) {
        int32_t x = 592 + (i & 1) * 100, y = top + 196 + (i >> 1) * 124;
        draw_mapped_sphere(c, (fx_rect){x, y, x + 96, y + 112}, i < 2 ? 0xFFD07030u : 0xFF506070u,
                           i == 1 ? FX16_ONE / 16 : 0, i == 2 ? FX_RT_FRAME_BRUSHED : i == 3 ? FX_RT_FRAME_SPUN : 0);
        demo_text(c, x + 4, y + 112, INK, "%s", mname[i]);
    }
}

/* ---- transforms ---- */
/* a house with a chimney on the right, so reflections show */
static const int32_t house[] = {-30, 40, 30, 40, 30, -10, 20, -20, 20, -36, 12, -36, 12, -28, 0, -40, -30, -10};
#define HOUSE_N 9

static void draw_xformed(fx_ctx *c, const fx_xform2 *m, int32_t cx, int32_t cy, fx_color fill)
{
    int32_t p[2 * HOUSE_N];
    for (int i = 0; i < HOUSE_N; i++) {
        fx_xform2_apply_int(m, house[2 * i], house[2 * i + 1], &p[2 * i], &p[2 * i + 1]);
        p[2 * i] += cx;
        p[2 * i + 1] += cy;
    }
    color(c, fill);
    fx_fill_poly(c, p, HOUSE_N, FX_FILL_EVENODD);
    color(c, INK);
    fx_polygon(c, p, HOUSE_N);
}

static void page_transforms(fx_ctx *c, demo_state *st)
{
    int32_t top = DEMO_TAB_H + 8;
    static const char *names[8] = {"original", "rotate 30: clockwise", "scale 1.5 x 0.7", "shear x 0.5",
                                   "reflect y axis", "rotate+scale", "reflect y=x", "animated"};
    for (int i = 0; i < 8; i++) {
        int32_t x = 8 + (i % 4) * 197, y = top + (i / 4) * 222;
        panel(c, x, y, 189, 214, names[i]);
        int32_t cx = x + 95, cy = y + 120;
        /* the axes through the reference point */
        color(c, 0xFF2E4A6Bu);
        fx_line(c, x + 10, cy, x + 179, cy);
        fx_line(c, cx, y + 24, cx, y + 204);
        fx_xform2 m, t;
        fx_xform2_identity(&m);
        switch (i) {
        case 1: fx_xform2_rotation(&m, fx_angle_from_deg(30), 0, 0); break;
        case 2: fx_xform2_scaling(&m, FX16_ONE * 3 / 2, FX16_ONE * 7 / 10, 0, 0); break;
        case 3: fx_xform2_shear_x(&m, FX16_ONE / 2, 0); break;
        case 4: fx_xform2_reflection(&m, FX_REFLECT_Y_AXIS); break;
        case 5:
            fx_xform2_rotation(&m, fx_angle_from_deg(-45), 0, 0);
            fx_xform2_scaling(&t, FX16_ONE * 6 / 5, FX16_ONE * 6 / 5, 0, 0);
            fx_xform2_then(&m, &t);
            break;
        case 6: fx_xform2_reflection(&m, FX_REFLECT_DIAGONAL); break;
        case 7: fx_xform2_rotation(&m, (fx_angle)(st->frame * 0x01000000u + FX_ANGLE_45 / 3), 0, 0); break;
        default: break;
        }
        fx_xform2 id;
        fx_xform2_identity(&id);
        if (i)
            draw_xformed(c, &id, cx, cy, 0xFF22364Fu);
        draw_xformed(c, &m, cx, cy, i ? 0xC0F78154u : 0xFF4D9DE0u);
    }
}

/* ---- colour models ---- */
#define WHEEL_R 104
#define WHEEL_CX (8 + 130)
#define WHEEL_CY (DEMO_TAB_H + 8 + 132)

/* The RGB cube, HSV hexcone and HLS double cone (mesh.h colour solids)
 * side by side in r. They stand still: the colour page is a function of
 * the picked colour alone (tests/tools/demo-outputs.sh compares a live
 * output of it with the headless picture). */
static void draw_colour_solids(fx_ctx *c, fx_rect r)
{
    fx_surface s = fx_surface_sub(c->surf, r);
    void *z = malloc(fx3d_depth_bytes(&s, 32));
    fx3d *rd = malloc(sizeof *rd);
    fx_mat4 ms[4], ps[2];
    if (z && rd && fx3d_init(rd, &s, ms, 4, ps, 2) == 0) {
        fx3d_set_depth(rd, z, 32);
        fx_camera cam;
        fx_camera_set(&cam, fx_vec3_make(0, 2 * FX16_ONE, 6 * FX16_ONE), fx_vec3_make(0, 0, 0),
                      fx_vec3_make(0, FX16_ONE, 0));
        fx_camera_view(&cam, &rd->view);
        fx3d_perspective(rd, fx_angle_from_deg(20), fx16_from_ratio(s.w, s.h), FX16_ONE / 2, 50 * FX16_ONE);
        rd->light[0].type = FX3D_LIGHT_DIRECTIONAL;
        rd->light[0].pos = fx_vec3_make(FX16_ONE, 2 * FX16_ONE, 3 * FX16_ONE);
        rd->ambient = fx3d_rgb_from_color(0x707070);
        rd->mat.ambient = rd->mat.diffuse = fx3d_rgb_from_color(0xFFFFFF);
        rd->mat.specular = fx3d_rgb_from_color(0);
        rd->shading = FX3D_GOURAUD;
        for (int k = 0; k < FX_SOLID_COUNT; k++) {
            fx_vec3 pos[FX_COLOUR_SOLID_VERTS];
            uint32_t col[FX_COLOUR_SOLID_VERTS], tri[3 * FX_COLOUR_SOLID_TRIS];
            fx_mesh m = {pos, NULL, tri, 0, 0, FX_COLOUR_SOLID_VERTS, FX_COLOUR_SOLID_TRIS, NULL, col};
            fx16 size = k == FX_SOLID_RGB_CUBE ? FX16_ONE * 7 / 5 : FX16_ONE * 17 / 10;
            if (fx_colour_solid_make(&m, (fx_colour_solid)k, size) < 0)
                continue;
            /* the builders write whole matrices: model = T Rx Ry */
            fx_mat4 t, rx, ry;
            fx_mat4_translate(&t, (k - 1) * FX16_ONE * 3, 0, 0);
            fx_mat4_rotate_x(&rx, k == FX_SOLID_RGB_CUBE ? fx_angle_from_deg(25) : 0);
            fx_mat4_rotate_y(&ry, fx_angle_from_deg(k == FX_SOLID_RGB_CUBE ? -40 : 20));
            fx_mat4 *top = fx_mat_stack_top(&rd->model);
            fx_mat4_mul(top, &t, &rx);
            fx_mat4_mul(top, top, &ry);
            fx3d_draw(rd, &m);
        }
    }
    free(rd);
    free(z);
}

/* Eight intensities from white to black as cross-hatching. */
static void draw_hatching(fx_ctx *c, int32_t x, int32_t y, int32_t w, int32_t h)
{
    color(c, 0xFFFFFFFFu);
    fx_fill_rect(c, x, y, 8 * w + 7 * 4 + 8, h + 8);
    for (int i = 0; i < 8; i++) {
        fx_fill_style fs;
        uint8_t bits[FX_HATCH_BYTES];
        fx_hatch_style(&fs, bits, (uint8_t)(255 - i * 255 / 7));
        fx_ctx t = *c;
        fx_ctx_set_color(&t, 0xFF000000u);
        t.fill_style = &fs;
        int32_t x0 = x + 4 + i * (w + 4), sq[8] = {x0, y + 4, x0 + w, y + 4, x0 + w, y + 4 + h, x0, y + 4 + h};
        fx_fill_poly(&t, sq, 4, FX_FILL_EVENODD);
    }
}

static void page_colour(fx_ctx *c, demo_state *st)
{
    int32_t top = DEMO_TAB_H + 8;
    panel(c, 8, top, 260, 270, "HSV wheel (click to pick)");
    int32_t cx = WHEEL_CX, cy = WHEEL_CY, R = WHEEL_R;
    /* only the rows of the clip (a band draws its own; fixel/par.h) */
    int32_t ya = c->clip.y0 - cy > -R ? c->clip.y0 - cy : -R, yb = c->clip.y1 - 1 - cy < R ? c->clip.y1 - 1 - cy : R;
    for (int32_t y = ya; y <= yb; y++)
        for (int32_t x = -R; x <= R; x++) {
            uint32_t d = fx_hypot(x, y);
            if (d > (uint32_t)R)
                continue;
            fx_hsv h;
            h.h = fx_angle_to_deg16(fx_atan2(-y, x));
            h.s = (fx16)((int64_t)d * FX16_ONE / R);
            h.v = FX16_ONE;
            if (cx + x >= c->clip.x0 && cx + x < c->clip.x1 && cy + y >= c->clip.y0 && cy + y < c->clip.y1)
                fx_surface_put(&c->surf, cx + x, cy + y, fx_hsv_to_rgb(h));
        }
    int32_t px = st->pick_x - cx, py = st->pick_y - cy;
    if (fx_hypot(px, py) > (uint32_t)R)
        px = py = 0;
    fx_hsv h;
    uint32_t d = fx_hypot(px, py);
    h.h = fx_angle_to_deg16(fx_atan2(-py, px));
    h.s = (fx16)((int64_t)d * FX16_ONE / R);
    h.v = FX16_ONE;
    fx_color col = fx_hsv_to_rgb(h);
    color(c, 0xFF000000u);
    fx_circle(c, cx + px, cy + py, 7);
    color(c, 0xFFFFFFFFu);
    fx_circle(c, cx + px, cy + py, 6);

    /* CIE 1931: the chromaticity diagram and the spectrum */
    panel(c, 276, top, 260, 270, "CIE 1931 xy, spectrum 380-780 nm");
    color(c, 0xFFFFFFFFu);
    fx_chromaticity_diagram(c, (fx_rect){306, top + 22, 306 + 200, top + 22 + 214}, FX_CHROMA_FILL | FX_CHROMA_LOCUS |
                                                                                      FX_CHROMA_GAMUT | FX_CHROMA_TICKS);
    for (int32_t x = 0; x < 240; x++) {
        /* 380 + 400 (x + 1/2) / 240 nm */
        color(c, fx_wavelength_to_rgb((fx16)(380 * 65536 + (int64_t)(2 * x + 1) * 400 * 65536 / 480)));
        fx_fill_rect(c, 286 + x, top + 246, 1, 16);
    }

    int32_t x0 = 544, w0 = 248;
    panel(c, x0, top, w0, 444, "The chosen colour");
    color(c, col);
    fx_fill_rect(c, x0 + 12, top + 24, w0 - 24, 56);
    uint32_t r = (col >> 16) & 255, g = (col >> 8) & 255, b = col & 255;
    int32_t y = top + 92;
    demo_text(c, x0 + 12, y, ACCENT, "RGB");
    demo_text(c, x0 + 48, y, INK, "%3u %3u %3u  #%02X%02X%02X", r, g, b, r, g, b);
    fx_cmy m = fx_rgb_to_cmy(col);
    demo_text(c, x0 + 12, y + 18, ACCENT, "CMY");
    demo_text(c, x0 + 48, y + 18, INK, "%3u %3u %3u", m.c, m.m, m.y);
    fx_hsv hv = fx_rgb_to_hsv(col);
    demo_text(c, x0 + 12, y + 36, ACCENT, "HSV");
    demo_text(c, x0 + 48, y + 36, INK, "h %3d  s %3d%%  v %3d%%", fx16_round(hv.h), fx16_round(hv.s * 100),
              fx16_round(hv.v * 100));
    fx_hls hl = fx_rgb_to_hls(col);
    demo_text(c, x0 + 12, y + 54, ACCENT, "HLS");
    demo_text(c, x0 + 48, y + 54, INK, "h %3d  l %3d%%  s %3d%%", fx16_round(hl.h), fx16_round(hl.l * 100),
              fx16_round(hl.s * 100));
    fx_yiq q = fx_rgb_to_yiq(col);
    demo_text(c, x0 + 12, y + 72, ACCENT, "YIQ");
    demo_text(c, x0 + 48, y + 72, INK, "%4d %4d %4d /1000", (int)((int64_t)q.y * 1000 >> 16),
              (int)((int64_t)q.i * 1000 / 65536), (int)((int64_t)q.q * 1000 / 65536));
    fx_xyz xyz = fx_rgb_to_xyz(col);
    fx16 cxx = 0, cyy = 0;
    fx_xyz_to_xy(xyz, &cxx, &cyy);
    demo_text(c, x0 + 12, y + 90, ACCENT, "xyY");
    demo_text(c, x0 + 48, y + 90, INK, "%4d %4d %4d /1000", (int)((int64_t)cxx * 1000 >> 16),
              (int)((int64_t)cyy * 1000 >> 16), (int)((int64_t)xyz.y * 1000 >> 16));
    /* the chosen colour on the diagram */
    int32_t dx = 306 + (int32_t)(((int64_t)cxx * 199 + 26214) / 52429);
    int32_t dy = top + 22 + 213 - (int32_t)(((int64_t)cyy * 213 + 29491) / 58982);
    color(c, 0xFF000000u);
    fx_circle(c, dx, dy, 4);
    color(c, 0xFFFFFFFFu);
    fx_circle(c, dx, dy, 3);
    /* bars of the model's channels */
    int32_t bw = w0 - 24;
    demo_text(c, x0 + 12, y + 116, DIM, "value ramps at this hue");
    for (int32_t i = 0; i < bw; i++) {
        fx_hsv t = hv;
        t.v = (fx16)(i * FX16_ONE / (bw - 1));
        t.s = hv.s;
        color(c, fx_hsv_to_rgb(t));
        fx_fill_rect(c, x0 + 12 + i, y + 132, 1, 20);
        fx_hls l2 = hl;
        l2.l = (fx16)(i * FX16_ONE / (bw - 1));
        color(c, fx_hls_to_rgb(l2));
        fx_fill_rect(c, x0 + 12 + i, y + 156, 1, 20);
    }
    demo_text(c, x0 + 12, y + 182, DIM, "HSV value, HLS lightness");
    demo_text(c, x0 + 12, y + 206, DIM, "colour maps");
    static const fx_cmap maps[4] = {FX_CMAP_GREY, FX_CMAP_HOT, FX_CMAP_VIRIDIS, FX_CMAP_HSV};
    for (int k = 0; k < 4; k++) {
        for (int32_t i = 0; i < 160; i++) {
            color(c, fx_cmap_color(maps[k], (uint32_t)(i * 65536 / 159)));
            fx_fill_rect(c, x0 + 12 + i, y + 222 + k * 22, 1, 18);
        }
        demo_text(c, x0 + 178, y + 226 + k * 22, INK, "%s", fx_cmap_name(maps[k]));
    }

    panel(c, 8, top + 278, 528, 166, "RGB cube, HSV hexcone, HLS double cone; hatching by intensity");
    draw_colour_solids(c, (fx_rect){9, top + 294, 535, top + 392});
    draw_hatching(c, 16, top + 396, 56, 36);
}

/* c's clip (the whole surface, or a band: fixel/par.h) inside the
 * rectangle r, in the coordinates of r's sub-surface */
static fx_rect clip_in(const fx_ctx *c, fx_rect r)
{
    fx_rect k = fx_rect_intersect(c->clip, r);
    if (fx_rect_empty(k))
        return (fx_rect){0, 0, 0, 0};
    return (fx_rect){k.x0 - r.x0, k.y0 - r.y0, k.x1 - r.x0, k.y1 - r.y0};
}

/* ---- 3D: the mesh renderer on two objects, one camera ---- */
static const char *shading_name(int s)
{
    return s == FX3D_FLAT ? "flat" : s == FX3D_GOURAUD ? "Gouraud" : "Phong";
}

static void draw_object(fx_ctx *c, demo_state *st, fx_rect r, fx_mesh_kind kind, fx_color col, fx_angle spin)
{
    fx_surface s = fx_surface_sub(c->surf, r);
    fx_rect band = clip_in(c, r);
    if (fx_rect_empty(band))
        return;
    fx_mesh_params mp = {kind, FX16_ONE * 7 / 10, 0, 0, 8, 0};
    if (kind == FX_MESH_TORUS)
        mp = (fx_mesh_params){kind, FX16_ONE + FX16_HALF, FX16_ONE / 2 + FX16_ONE / 8, 0, 20, 32};
    int32_t nv, nt;
    if (fx_mesh_size(&mp, &nv, &nt) < 0)
        return;
    fx_mesh m = {0};
    memset(&m, 0, sizeof m);
    m.pos = malloc((size_t)nv * 2 * sizeof(fx_vec3));
    m.tri = malloc((size_t)nt * 3 * sizeof(uint32_t));
    /* The teapot is textured: each Bezier patch has its own (u, v) square
     * (fx_mesh_make fills uv), here a 4 x 4 checker per patch, modulated
     * by the lighting. */
    uint32_t teximg[64 * 64]; /* per call: bands draw at once */
    fx_texture tx;
    memset(&tx, 0, sizeof tx);
    if (kind == FX_MESH_TEAPOT) {
        m.uv = malloc((size_t)nv * 2 * sizeof(fx16));
        fx_surface_init(&tx.img, teximg, 64, 64, 64 * 4, FX_FMT_XRGB8888);
        fx_tex_checker(&tx.img, 16, 0xFFFFFFFFu, col);
        tx.wrap = FX_TEX_REPEAT;
        tx.filter = FX_TEX_NEAREST;
    }
    void *z = malloc(fx3d_depth_bytes(&s, 32));
    fx3d *rd = malloc(sizeof *rd);
    fx_mat4 ms[4], ps[2];
    if (m.pos && m.tri && z && rd) {
        m.nrm = m.pos + nv;
        m.cap_verts = nv;
        m.cap_tris = nt;
        if (fx_mesh_make(&m, &mp) == 0 && fx3d_init(rd, &s, ms, 4, ps, 2) == 0) {
            rd->ctx.clip = fx_rect_intersect(rd->ctx.clip, band);
            fx3d_set_depth(rd, z, 32);
            fx_camera_view(&st->cam, &rd->view);
            fx3d_perspective(rd, fx_angle_from_deg(40), fx16_from_ratio(s.w, s.h), FX16_ONE / 2, 50 * FX16_ONE);
            rd->light[0].type = FX3D_LIGHT_DIRECTIONAL;
            rd->light[0].pos = fx_vec3_make(FX16_ONE, FX16_ONE, FX16_ONE);
            rd->light[1].type = FX3D_LIGHT_POINT;
            rd->light[1].pos = fx_vec3_make(-4 * FX16_ONE, 5 * FX16_ONE, 3 * FX16_ONE);
            rd->light[1].diffuse = rd->light[1].specular = fx3d_rgb_from_color(0x6080FF);
            rd->mat.ambient = rd->mat.diffuse = fx3d_rgb_from_color(m.uv ? 0xFFFFFFFFu : col);
            if (m.uv)
                fx3d_texture(rd, &tx, FX3D_TEX_MODULATE);
            rd->mat.specular = fx3d_rgb_from_color(0xFFFFFF);
            rd->mat.shininess = 40;
            rd->shading = (fx3d_shading)st->shading;
            fx_mat4 *top = fx_mat_stack_top(&rd->model);
            if (kind == FX_MESH_TORUS) {
                fx_mat4_translate(top, 0, FX16_ONE + FX16_HALF, 0);
                fx_mat4_rotate_x(top, (fx_angle)(FX_ANGLE_90 / 3 + spin));
                fx_mat4_rotate_y(top, spin);
            } else {
                fx_mat4_rotate_y(top, spin);
                fx_mat4_translate(top, 0, -FX16_ONE / 8, 0);
            }
            fx3d_draw(rd, &m);
        }
    }
    free(rd);
    free(z);
    free(m.tri);
    free(m.pos);
    free(m.uv);
}

static void page_3d(fx_ctx *c, demo_state *st)
{
    int32_t top = DEMO_TAB_H + 8;
    panel(c, 8, top, 388, 400, NULL);
    panel(c, 404, top, 388, 400, NULL);
    fx_angle spin = (fx_angle)(st->frame * 0x00800000u);
    draw_object(c, st, (fx_rect){9, top + 1, 395, top + 399}, FX_MESH_TEAPOT, 0xFFD05028u, spin);
    draw_object(c, st, (fx_rect){405, top + 1, 791, top + 399}, FX_MESH_TORUS, 0xFF2080C0u, spin);
    demo_text(c, 14, top + 5, ACCENT, "Textured teapot, %s shading", shading_name(st->shading));
    demo_text(c, 410, top + 5, ACCENT, "Torus, %s shading", shading_name(st->shading));
    panel(c, 8, top + 408, 784, 36, NULL);
    demo_text(c, 16, top + 414, INK, "s: flat / Gouraud / Phong    camera: u/d slide up/down, f/b forward/back,");
    demo_text(c, 16, top + 428, INK, "h/j slide left/right, y/Y yaw, t/T pitch, o/O roll    eye (%d.%02d, %d.%02d, %d.%02d)",
              st->cam.eye.x >> 16, (st->cam.eye.x & 0xFFFF) * 100 >> 16, st->cam.eye.y >> 16,
              (st->cam.eye.y & 0xFFFF) * 100 >> 16, st->cam.eye.z >> 16, (st->cam.eye.z & 0xFFFF) * 100 >> 16);
}

/* ---- fractals ---- */
static void dwell_lut(uint32_t *lut, int n, fx_format f, fx_cmap m)
{
    /* a triangle wave over the map, so wrapping dwell bands meet smoothly;
     * the darkest tenth is left out to keep the outside apart from the set */
    for (int i = 0; i < n; i++) {
        int32_t tri = i < n / 2 ? i : n - i;
        lut[i] = fx_pack(f, fx_cmap_color(m, (uint32_t)(6554 + tri * 2 * 58982 / n)));
    }
}

static const fx_ifs_map fern_maps[4] = {
    {0, 0, 0, 10486, 0, 0, 655},
    {55706, 2621, -2621, 55706, 0, 104858, 55706},
    {13107, -17039, 15073, 14418, 0, 104858, 4588},
    {-9830, 18350, 17039, 15729, 0, 28835, 4587},
};

/* Box-counting dimension of what was drawn in r (boxes of smin..16 smin px over
 * the panel's colour), as "D = 1.27 (1.2619)". */
static void measure_dim(fx_ctx *c, fx_rect r, int32_t smin, char *buf, size_t n, const char *known)
{
    fx16 d;
    if (fx_boxdim_surface(&c->surf, r, fx_pack(c->surf.format, PANEL), smin, 16 * smin, &d, NULL, NULL) < 0) {
        snprintf(buf, n, "D: nothing drawn");
        return;
    }
    snprintf(buf, n, "box dim %.3f (%s)", d / 65536.0, known);
}

/* The diamond-square terrain raised into a mountain, as a lit mesh
 * coloured by height (the scene's 'mountain' command, in C). */
static void draw_mountain(fx_ctx *c, fx_rect r)
{
    enum { K = 5, N = (1 << K) + 1 };
    static int32_t h[N * N];
    static fx_vec3 pos[N * N], nrm[N * N];
    static uint32_t tri[3 * 2 * (N - 1) * (N - 1)], col[N * N];
    fx_surface s = fx_surface_sub(c->surf, r);
    fx_mesh m = {pos, nrm, tri, 0, 0, N * N, 2 * (N - 1) * (N - 1), NULL, col};
    fx_terrain(h, N, K, 1 << 20, 36045, 11);
    fx_terrain_peak(h, N, K, 3 << 19);
    if (fx_terrain_mesh(&m, h, N, K, 7 * FX16_ONE, FX16_ONE * 9 / 5, 19661) < 0)
        return;
    void *z = malloc(fx3d_depth_bytes(&s, 32));
    fx3d *rd = malloc(sizeof *rd);
    fx_mat4 ms[2], ps[2];
    fx_camera cam;
    if (z && rd && fx3d_init(rd, &s, ms, 2, ps, 2) == 0 &&
        fx_camera_set(&cam, fx_vec3_make(0, 4 * FX16_ONE, 7 * FX16_ONE), fx_vec3_make(0, FX16_ONE / 4, 0),
                      fx_vec3_make(0, FX16_ONE, 0)) == 0) {
        fx3d_set_depth(rd, z, 32);
        fx_camera_view(&cam, &rd->view);
        fx3d_perspective(rd, fx_angle_from_deg(45), fx16_from_ratio(s.w, s.h), FX16_ONE / 10, 50 * FX16_ONE);
        rd->light[0].type = FX3D_LIGHT_DIRECTIONAL;
        rd->light[0].pos = fx_vec3_make(-FX16_ONE, 2 * FX16_ONE, FX16_ONE);
        rd->ambient = fx3d_rgb_from_color(0x505050);
        rd->mat.ambient = rd->mat.diffuse = fx3d_rgb_from_color(0xFFFFFF);
        rd->mat.specular = fx3d_rgb_from_color(0);
        rd->shading = FX3D_GOURAUD;
        fx3d_draw(rd, &m);
    }
    free(rd);
    free(z);
}

/* Text with a one-pixel black shadow, readable over any colour of the set. */
static void shadow_text(const fx_ctx *c, int32_t x, int32_t y, fx_color col, const char *s)
{
    demo_text(c, x + 1, y + 1, 0xFF000000u, "%s", s);
    demo_text(c, x, y, col, "%s", s);
}

/* The orbit of 0 under z^2 + c over the Mandelbrot frame r of view v: its
 * points joined in order (the first ORBIT_SHOW), z0..z3 marked with their
 * index, and two lines at ty: c with fx_orbit0's classification, and the
 * first values. */
#define ORBIT_N 2000
#define ORBIT_SHOW 200

/* The frame pixel of an orbit value, 0 when it is past what
 * fx_julia_to_pixel takes (parts above 16) or lands over 2^20 px out (an
 * escaping value, or a deep zoom away from 0): the line stops there rather
 * than run off towards a saturated, overflowing coordinate. */
static int orbit_pixel(const fx_fractal_view *v, fx56 re, fx56 im, int32_t *x, int32_t *y)
{
    if (re > 16 * FX56_ONE || re < -16 * FX56_ONE || im > 16 * FX56_ONE || im < -16 * FX56_ONE)
        return 0;
    fx_julia_to_pixel(v, re, im, x, y);
    return *x > -(1 << 20) && *x < (1 << 20) && *y > -(1 << 20) && *y < (1 << 20);
}
static void draw_orbit(const fx_ctx *c, const fx_fractal_view *v, fx_rect r, fx56 cre, fx56 cim, int32_t ty)
{
    fx56 *zre = malloc(2 * ORBIT_N * sizeof *zre);
    if (!zre)
        return;
    fx56 *zim = zre + ORBIT_N;
    fx_orbit0_info info;
    char head[96], vals[96];
    if (demo_orbit_text(cre, cim, zre, zim, ORBIT_N, &info, head, sizeof head, vals, sizeof vals) < 0) {
        free(zre);
        return;
    }
    fx_surface s = fx_surface_sub(c->surf, r);
    fx_ctx oc;
    fx_ctx_init(&oc, &s);
    /* fx_julia_to_pixel maps in Q4.28: below a width of 2^-16 its pixels
     * grow coarse, so deeper zooms print the orbit without plotting it */
    int plot = v->width >= (FX56_ONE >> 16);
    fx_ctx_set_color(&oc, 0xFF5CE1E6u);
    int32_t px = 0, py = 0, have = 0;
    for (uint32_t k = 0; plot && k <= info.steps && k < ORBIT_SHOW; k++) {
        int32_t x, y;
        if (!orbit_pixel(v, zre[k], zim[k], &x, &y))
            break;
        if (have)
            for (int32_t d = 0; d <= 1; d++) /* two pixels wide, to show on the set's black */
                fx_line(&oc, px + d, py, x + d, y);
        fx_disc(&oc, x, y, 2);
        px = x, py = y, have = 1;
    }
    int32_t lx[4], ly[4];
    for (uint32_t k = 0; plot && k <= info.steps && k < 4; k++) {
        int32_t x, y, seen = 0;
        if (!orbit_pixel(v, zre[k], zim[k], &x, &y))
            break;
        lx[k] = x, ly[k] = y;
        for (uint32_t j = 0; j < k; j++) /* a value back on an earlier one (a cycle) keeps that label */
            seen |= x - lx[j] < 8 && lx[j] - x < 8 && y - ly[j] < 8 && ly[j] - y < 8;
        if (seen)
            continue;
        fx_ctx_set_color(&oc, 0xFFFFFFFFu);
        fx_disc(&oc, x, y, 3);
        fx_ctx_set_color(&oc, 0xFF000000u);
        fx_circle(&oc, x, y, 3);
        char lab[4] = {'z', (char)('0' + k), 0, 0};
        shadow_text(&oc, x + 5, y - 12, 0xFFFFFFFFu, lab);
    }
    /* the text on a dark strip: the set's edge behind it is too busy */
    fx_ctx_set_color(&oc, 0xFF101820u);
    fx_fill_rect(&oc, 0, ty - 3 - r.y0, s.w, 28);
    demo_text(c, r.x0 + 6, ty, 0xFFFFFFFFu, "%s", head);
    demo_text(c, r.x0 + 6, ty + 13, 0xFF5CE1E6u, "%s", vals);
    free(zre);
}

static void page_fractals(fx_ctx *c, demo_state *st)
{
    int32_t top = DEMO_TAB_H + 8;
    uint32_t lut[64];
    dwell_lut(lut, 64, c->surf.format, FX_CMAP_HOT);
    fx_dwell_pal pal = {lut, 64, 65536, 1, fx_pack(c->surf.format, 0xFF000000u)};
    /* Mandelbrot */
    panel(c, 8, top, 388, 250, "Mandelbrot: click zooms, right click out, o orbit");
    fx_rect mr = {14, top + 20, 390, top + 244};
    /* deeper zooms need more iterations before points near the set escape */
    uint32_t maxiter = 192;
    for (int64_t w = 3 * FX56_ONE; w > st->mwidth && maxiter < 2048; w /= 4)
        maxiter += 96;
    fx_fractal_view mv = fx_mandel_view(st->mcre, st->mcim, st->mwidth, mr.x1 - mr.x0, mr.y1 - mr.y0, maxiter);
    fx_surface ms = fx_surface_sub(c->surf, mr);
    fx_fractal_render(&ms, clip_in(c, mr), &mv, &pal);
    /* Julia of the pointer's point in the Mandelbrot frame */
    panel(c, 404, top, 388, 250, NULL);
    int32_t jx = st->julia_x - mr.x0, jy = st->julia_y - mr.y0;
    fx56 jre = fx_fractal_re(&mv, jx), jim = fx_fractal_im(&mv, jy);
    fx_rect jr = {410, top + 20, 786, top + 244};
    fx_fractal_view jv = fx_julia_view(0, 0, jre, jim, 3 * FX56_ONE, jr.x1 - jr.x0, jr.y1 - jr.y0, 192);
    uint32_t lut2[64];
    dwell_lut(lut2, 64, c->surf.format, FX_CMAP_VIRIDIS);
    fx_dwell_pal pal2 = {lut2, 64, 65536, 1, fx_pack(c->surf.format, 0xFF000000u)};
    fx_surface js = fx_surface_sub(c->surf, jr);
    /* K_c with the basins of its attracting cycle coloured, J_c itself by
     * inverse iteration on top, and the fixed points (ring: repelling,
     * disc: attracting, square: neutral) -- where |c| fits (parts <= 2) */
    int period = -1;
    if (fx_julia_check(&jv) == 0) {
        static const fx_color basin[4] = {0xFFFFC040u, 0xFF40B0FFu, 0xFFFF5A5Au, 0xFF60E060u};
        period = fx_julia_basins(&js, (fx_rect){0, 0, js.w, js.h}, &jv, &pal2, basin, 4);
        fx_ctx jc;
        fx_ctx_init(&jc, &js);
        fx_ctx_set_color(&jc, 0xFFFFFFFFu);
        fx_julia_inverse_random(&jc, &jv, 30000, 1);
        fx_julia_fixed fp[2];
        fx_julia_fixed_points(jre, jim, fp);
        fx_ctx_set_color(&jc, 0xFFFF40FFu);
        for (int k = 0; k < 2; k++) {
            int32_t x, y;
            fx_julia_to_pixel(&jv, fp[k].re, fp[k].im, &x, &y);
            if (fp[k].kind == FX_FIXED_ATTRACTING)
                fx_disc(&jc, x, y, 3);
            else if (fp[k].kind == FX_FIXED_REPELLING)
                fx_circle(&jc, x, y, 4);
            else
                fx_rect_outline(&jc, x - 3, y - 3, 7, 7);
        }
    } else {
        fx_fractal_render(&js, (fx_rect){0, 0, js.w, js.h}, &jv, &pal2);
    }
    demo_text(c, 410, top + 5, ACCENT, "Julia c = %+.4f %+.4fi (follows the pointer)",
              (double)jre / (double)FX56_ONE, (double)jim / (double)FX56_ONE);
    if (period > 0)
        demo_text(c, 416, top + 230, 0xFFFFFFFFu, "J_c, basins of the period-%d cycle, fixed points", period);
    else if (period == 0)
        demo_text(c, 416, top + 230, 0xFFFFFFFFu, "J_c by inverse iteration, fixed points");
    if (st->mwidth != 3 * FX56_ONE)
        demo_text(c, 20, top + 230, 0xFFFFFFFFu, "width %.3g, %u iterations", (double)st->mwidth / (double)FX56_ONE,
                  maxiter);
    color(c, 0xFFFFFFFFu);
    fx_circle(c, st->julia_x, st->julia_y, 3);
    if (!st->orbit_off)
        draw_orbit(c, &mv, mr, jre, jim, top + 204);

    /* the bottom row: five panels of 152 px */
    int32_t by = top + 258, bh = 186;
    char dim[48];
    /* Koch snowflake drawn by the turtle, its box-counting dimension */
    panel(c, 8, by, 152, bh, NULL);
    demo_text(c, 14, by + 5, ACCENT, "Koch (turtle), n=%d", st->koch_order);
    color(c, 0xFF5CE1E6u);
    fx_turtle t;
    /* The turtle turns from +x towards +y (clockwise on this y-down page),
     * so the flake is walked counter-clockwise on the triangle pointing
     * down: top side right to left, then -120 twice. By its six-fold
     * symmetry it is the flake on the triangle pointing up, same centre. */
    fx_turtle_init(&t, c, 146 << 16, (by + 118 - 72) << 16, 180 << 16);
    for (int i = 0; i < 3; i++) {
        fx_turtle_koch(&t, 124 << 16, (uint32_t)st->koch_order);
        fx_turtle_turn(&t, -120 * 65536);
    }
    measure_dim(c, (fx_rect){10, by + 20, 158, by + bh - 22}, 2, dim, sizeof dim, "1.2619");
    demo_text(c, 14, by + bh - 16, INK, "%s", dim);
    panel(c, 166, by, 152, bh, "Barnsley fern (IFS)");
    fx_ifs fern = {fern_maps, 4, -3 * FX16_ONE, 0, 3 * FX16_ONE, 10 * FX16_ONE};
    color(c, GREEN);
    fx_ifs_chaos(c, (fx_rect){182, by + 20, 302, by + bh - 4}, &fern, 30000, 1);
    panel(c, 324, by, 152, bh, "Hilbert curve, order 5");
    color(c, ORANGE);
    fx_hilbert(c, 336, by + 22, 128, 5);
    /* boxes from the curve's own 4-px cells up: below them it is lines */
    measure_dim(c, (fx_rect){336, by + 22, 464, by + 150}, 4, dim, sizeof dim, "2");
    demo_text(c, 330, by + bh - 16, INK, "%s", dim);
    /* random fractals: fire behind grass */
    panel(c, 482, by, 152, bh, "Fire and grass");
    fx_fire(c, (fx_rect){540, by + 30, 630, by + bh - 2}, 39322, 5);
    color(c, 0xFF3CB030u);
    fx_grass(c, (fx_rect){486, by + 120, 630, by + bh - 2}, 110, 3);
    panel(c, 640, by, 152, bh, NULL);
    draw_mountain(c, (fx_rect){641, by + 1, 791, by + bh - 1});
    demo_text(c, 646, by + 5, ACCENT, "Terrain, diamond-square");
}

/* ---- visualization ---- */
#define GW 41
#define GH 31

static int32_t field(int32_t x, int32_t y)
{
    /* two bumps and a dip, in integers (exp approximated by a rational bump) */
    int32_t v = 0;
    static const int32_t b[3][3] = {{12, 10, 1000}, {28, 20, 800}, {30, 8, -600}};
    for (int i = 0; i < 3; i++) {
        int32_t dx = x - b[i][0], dy = y - b[i][1];
        v += b[i][2] * 64 / (64 + dx * dx + dy * dy);
    }
    return v;
}

static void page_viz(fx_ctx *c, demo_state *st)
{
    (void)st;
    int32_t top = DEMO_TAB_H + 8;
    int32_t g[GW * GH], u[GW * GH], vv[GW * GH]; /* per call: bands draw at once */
    for (int y = 0; y < GH; y++)
        for (int x = 0; x < GW; x++)
            g[y * GW + x] = field(x, y);
    for (int y = 0; y < GH; y++)
        for (int x = 0; x < GW; x++) {
            int xa = x > 0 ? x - 1 : x, xb = x < GW - 1 ? x + 1 : x;
            int ya = y > 0 ? y - 1 : y, yb = y < GH - 1 ? y + 1 : y;
            /* the gradient turned 90 degrees: flow along the contours */
            u[y * GW + x] = -(g[yb * GW + x] - g[ya * GW + x]);
            vv[y * GW + x] = g[y * GW + xb] - g[y * GW + xa];
        }
    fx_grid grid = {g, GW, GH, GW};
    int32_t lo, hi;
    fx_grid_range(&grid, &lo, &hi);

    panel(c, 8, top, 388, 300, "Heat map and contours");
    fx_rect hr = {16, top + 22, 356, top + 292};
    fx_heatmap(c, hr, &grid, lo, hi, FX_CMAP_VIRIDIS);
    color(c, 0xFFFFFFFFu);
    for (int k = 1; k < 10; k++)
        fx_contour(c, hr, &grid, lo + (hi - lo) * k / 10);
    fx_colorbar(c, (fx_rect){364, top + 22, 388, top + 292}, FX_CMAP_VIRIDIS, 5);

    panel(c, 404, top, 388, 300, "Vector field and streamlines");
    fx_rect vr = {412, top + 22, 784, top + 292};
    color(c, 0xFF2E4A6Bu);
    fx_rect_outline(c, vr.x0, vr.y0, vr.x1 - vr.x0, vr.y1 - vr.y0);
    fx_vgrid vg = {u, vv, GW, GH, GW};
    color(c, DIM);
    fx_quiver(c, vr, &vg, 2);
    for (int i = 0; i < 8; i++) {
        color(c, fx_cmap_color(FX_CMAP_HOT, (uint32_t)(20000 + i * 5000)));
        fx_streamline(c, vr, &vg, vr.x0 + 20 + i * 44, vr.y0 + 30 + (i % 3) * 90, FX16_ONE, 600);
    }

    /* the field's Hessian as tensor glyphs: red over the peaks (both
     * curvatures negative), blue in the dip, green on the saddles */
    panel(c, 8, top + 308, 388, 136, "Hessian as tensor glyphs (scale compressed)");
    int32_t ta[GW * GH], tb[GW * GH], tc[GW * GH]; /* per call, like g: bands draw at once */
    for (int y = 0; y < GH; y++)
        for (int x = 0; x < GW; x++) {
            int xa = x > 0 ? x - 1 : x, xb = x < GW - 1 ? x + 1 : x;
            int ya = y > 0 ? y - 1 : y, yb = y < GH - 1 ? y + 1 : y;
            int32_t f = g[y * GW + x];
            ta[y * GW + x] = g[y * GW + xb] - 2 * f + g[y * GW + xa];
            tc[y * GW + x] = g[yb * GW + x] - 2 * f + g[ya * GW + x];
            /* y up: d/dy = -d/drow */
            tb[y * GW + x] = -(g[yb * GW + xb] - g[ya * GW + xb] - g[yb * GW + xa] + g[ya * GW + xa]) / 4;
            /* compress the scale (n -> 1000 n / (n + 10)): the peaks' curvature
             * is a hundred times the plains', whose glyphs would vanish */
            int32_t n = abs(ta[y * GW + x]);
            n = abs(tb[y * GW + x]) > n ? abs(tb[y * GW + x]) : n;
            n = abs(tc[y * GW + x]) > n ? abs(tc[y * GW + x]) : n;
            ta[y * GW + x] = ta[y * GW + x] * 1000 / (n + 10);
            tb[y * GW + x] = tb[y * GW + x] * 1000 / (n + 10);
            tc[y * GW + x] = tc[y * GW + x] * 1000 / (n + 10);
        }
    fx_tgrid tg = {ta, tb, tc, GW, GH, GW};
    static const fx_tensor_style ts = {0xFF3070D0u, 0xFFD04040u, 0xFF90C070u};
    color(c, 0xFFE8E8E8u);
    fx_tensor_glyphs(c, (fx_rect){24, top + 332, 380, top + 436}, &tg, 5, &ts);

    /* multi-part glyphs: arrow = flow, disc = value, bar = slope */
    panel(c, 404, top + 308, 388, 136, "Glyphs: flow arrow, value disc, slope bar");
    int32_t vmax = 1, smax = 1;
    for (int i = 0; i < GW * GH; i++) {
        int32_t m = (int32_t)fx_hypot(u[i], vv[i]);
        vmax = m > vmax ? m : vmax;
        smax = m > smax ? m : smax;
    }
    color(c, 0xFFF0E0A0u);
    for (int y = 4; y < GH; y += 10)
        for (int x = 2; x <= 26; x += 6) {
            int i = y * GW + x;
            uint32_t sl = fx_hypot(u[i], vv[i]);
            fx_multi_glyph(c, 432 + (x - 2) * 10, top + 346 + (y - 4) * 4, 34, (fx16)((int64_t)u[i] * 65536 / vmax),
                           (fx16)((int64_t)vv[i] * 65536 / vmax), (fx16)((int64_t)(g[i] - lo) * 65536 / (hi - lo ? hi - lo : 1)),
                           (fx16)((int64_t)sl * 65536 / smax), FX_CMAP_VIRIDIS);
        }
    /* a star glyph of six heights along the field's diagonal */
    fx16 sv[6];
    for (int k = 0; k < 6; k++)
        sv[k] = (fx16)((int64_t)(g[(3 + 5 * k) * GW + 3 + 7 * k] - lo) * 65536 / (hi - lo ? hi - lo : 1));
    color(c, 0xFF4D9DE0u);
    fx_star_glyph(c, 742, top + 386, 40, sv, 6, 0xFFFFFFFFu);
}

static void page_vsd(fx_ctx *c, demo_state *st) { demo_vsd_page(c, st, DEMO_TAB_H + 8); }

static void page_rt(fx_ctx *c, demo_state *st) { demo_rt_page(c, st, DEMO_RT_Y); }

static void page_objects(fx_ctx *c, demo_state *st) { demo_objects_page(c, st, DEMO_TAB_H + 8); }
static void page_anim(fx_ctx *c, demo_state *st) { demo_anim_page(c, st, DEMO_TAB_H + 8); }

const demo_page demo_pages[] = {
    {"lines", "Lines", page_lines, 1, 0},
    {"circles", "Circles", page_circles, 1, 0},
    {"clipping", "Clipping", page_clipping, 0, 0},     /* drawn in the course frame (mirrored rows) */
    {"fills", "Fills", page_fills, 0, 0},              /* flood fills read the picture */
    {"textures", "Textures", page_textures, 1, 0},
    {"transforms", "Transform", page_transforms, 1, 0},
    {"colour", "Colour", page_colour, 1, 0},
    {"3d", "3D", page_3d, 1, 0},
    {"vsd", "Hidden", page_vsd, 0, 0},                 /* static buffers, painted unclipped */
    {"objects", "Objects", page_objects, 0, 0},        /* scene scripts into sub-surfaces, unclipped */
    {"fractals", "Fractals", page_fractals, 0, 0},     /* the Julia panel is drawn whole into its sub-surface */
    {"viz", "Viz", page_viz, 1, 0},
    {"glut", "GLUT", demo_page_glut, 0, 0},            /* one GL context, blitted */
    {"raytrace", "Ray trace", page_rt, 0, 1},         /* traced on st->threads, blitted */
    {"anim", "Animation", page_anim, 0, 0},            /* the camera flight keeps state between frames */
};
const int demo_npages = (int)(sizeof demo_pages / sizeof demo_pages[0]);
/* Fourteen tabs hold their labels (522 px of text) at 800 px with room to
 * spare; a fifteenth would leave too little, so the pages after the
 * fourteenth (Animation) are reached with n/p and --page, without a tab. */
const int demo_ntabs = 14;

/* Tab i spans [*x0, *x1): its label's width plus an equal share of the
 * room left. Equal 57-pixel tabs left 1.5 px either side of "Textures" and
 * "Transform", which ran together; a surface too narrow for the labels gets
 * equal tabs. */
void demo_tab_span(int32_t w, int i, int32_t *x0, int32_t *x1)
{
    int64_t text = 0, ww, hh, mine = 0, before = 0;
    for (int k = 0; k < demo_ntabs; k++) {
        fx_text_extent(NULL, demo_pages[k].title, &ww, &hh);
        if (k < i)
            before += ww;
        if (k == i)
            mine = ww;
        text += ww;
    }
    int64_t spare = w - text;
    if (spare < 2 * demo_ntabs) {
        *x0 = (int32_t)(w / demo_ntabs * i);
        *x1 = (int32_t)(w / demo_ntabs * (i + 1));
        return;
    }
    /* the first spare % ntabs tabs get one pixel more */
    int64_t share = spare / demo_ntabs, extra = spare % demo_ntabs;
    *x0 = (int32_t)(before + share * i + (i < extra ? i : extra));
    *x1 = (int32_t)(*x0 + mine + share + (i < extra));
}

int demo_tab_at(int32_t w, int32_t x)
{
    for (int i = 0; i < demo_ntabs; i++) {
        int32_t x0, x1;
        demo_tab_span(w, i, &x0, &x1);
        if (x >= x0 && x < x1)
            return i;
    }
    return -1;
}

void demo_state_init(demo_state *st, int32_t w, int32_t h)
{
    memset(st, 0, sizeof *st);
    st->w = w;
    st->h = h;
    st->win = (fx_rect){180, 150, 420, 330};
    st->lx0 = 60;
    st->ly0 = 400;
    st->lx1 = 520;
    st->ly1 = 90;
    st->clipper = FX_CLIP_LIANG;
    /* headless pictures show a few fills already made */
    st->nseeds = 6;
    int32_t top = DEMO_TAB_H + 8;
    int32_t sx[6] = {110, 60, 300, 240, 360, 300};
    int32_t sy[6] = {top + 60, top + 140, top + 60, top + 120, top + 120, top + 185};
    memcpy(st->seedx, sx, sizeof sx);
    memcpy(st->seedy, sy, sizeof sy);
    st->mcre = -FX56_ONE / 2;
    st->mcim = 0;
    st->mwidth = 3 * FX56_ONE;
    /* c = -0.12 + 0.75i: Douady's rabbit, whose basins of the attracting
     * 3-cycle the Julia panel colours */
    st->julia_x = 14 + 235;
    st->julia_y = top + 20 + 18;
    st->koch_order = 4;
    st->pick_x = WHEEL_CX + 66;
    st->pick_y = WHEEL_CY + 32;
    fx_camera_set(&st->cam, fx_vec3_make(0, 3 * FX16_ONE, 7 * FX16_ONE), fx_vec3_make(0, FX16_ONE, 0),
                  fx_vec3_make(0, FX16_ONE, 0));
    st->shading = FX3D_GOURAUD;
    st->vsd_method = 5; /* Warnock: the picture shows its regions */
    st->vsd_row = 80;
    demo_anim_init(st);
}

void demo_draw(fx_ctx *c, demo_state *st)
{
    /* c's clip stays: the whole surface, or the band being drawn */
    color(c, BG);
    fx_clear(c);
    /* the tab bar */
    for (int i = 0; i < demo_ntabs; i++) {
        int32_t x0, x1;
        demo_tab_span(st->w, i, &x0, &x1);
        int32_t tw = x1 - x0;
        color(c, i == st->page ? 0xFF2E4A6Bu : 0xFF16202Eu);
        fx_fill_rect(c, x0, 0, tw - 1, DEMO_TAB_H);
        int64_t ww, hh;
        fx_text_extent(NULL, demo_pages[i].title, &ww, &hh);
        demo_text(c, x0 + (tw - (int32_t)ww) / 2, (DEMO_TAB_H - (int32_t)hh) / 2,
                  i == st->page ? ACCENT : DIM, "%s", demo_pages[i].title);
    }
    demo_pages[st->page].draw(c, st);
}

typedef struct demo_band_job {
    const demo_state *st;
} demo_band_job;

static void draw_band(void *user, fx_ctx *c, int band)
{
    (void)band;
    demo_state st = *((demo_band_job *)user)->st; /* a page may touch its state: each band its own */
    demo_draw(c, &st);
}

int demo_draw_threads(fx_ctx *c, demo_state *st, int nthreads)
{
    if (nthreads <= 1 || !demo_pages[st->page].bands) {
        demo_draw(c, st);
        return 1;
    }
    demo_band_job j = {st};
    if (fx_par_bands(c, nthreads, nthreads, draw_band, &j) < 0) {
        demo_draw(c, st);
        return 1;
    }
    return nthreads;
}

static int near(int32_t x, int32_t y, int32_t px, int32_t py)
{
    return fx_hypot(x - px, y - py) <= 10;
}

void demo_pointer(demo_state *st, int32_t x, int32_t y, int down)
{
    const char *name = demo_pages[st->page].name;
    int32_t top = DEMO_TAB_H + 8;
    st->mx = x;
    st->my = y;
    if (!strcmp(name, "clipping")) {
        if (down == 1) {
            st->drag = near(x, y, st->lx0, st->ly0) ? 1 : near(x, y, st->lx1, st->ly1) ? 2 : x < 572 ? 3 : 0;
            st->dragx = x;
            st->dragy = y;
        } else if (down == 0 && st->drag) {
            int32_t dx = x - st->dragx, dy = y - st->dragy;
            st->dragx = x;
            st->dragy = y;
            if (st->drag == 1) {
                st->lx0 = x;
                st->ly0 = y;
            } else if (st->drag == 2) {
                st->lx1 = x;
                st->ly1 = y;
            } else {
                st->win.x0 += dx;
                st->win.x1 += dx;
                st->win.y0 += dy;
                st->win.y1 += dy;
            }
        } else if (down == -1) {
            st->drag = 0;
        }
    } else if (!strcmp(name, "fills")) {
        if (down == 1 && x > 8 && x < 400 && y > top && y < top + 230) {
            if (st->nseeds == 16) {
                memmove(st->seedx, st->seedx + 1, 15 * sizeof st->seedx[0]);
                memmove(st->seedy, st->seedy + 1, 15 * sizeof st->seedy[0]);
                st->nseeds--;
            }
            st->seedx[st->nseeds] = x;
            st->seedy[st->nseeds++] = y;
        }
    } else if (!strcmp(name, "colour")) {
        if (down >= 0 && down <= 1) {
            st->pick_x = x;
            st->pick_y = y;
        }
    } else if (!strcmp(name, "fractals")) {
        fx_rect mr = {14, top + 20, 390, top + 244};
        int inside = x >= mr.x0 && x < mr.x1 && y >= mr.y0 && y < mr.y1;
        if (inside && (down == 0 || down == 3)) {
            st->julia_x = x;
            st->julia_y = y;
        }
        if (inside && (down == 1 || down == 2)) {
            fx_fractal_view v = fx_mandel_view(st->mcre, st->mcim, st->mwidth, mr.x1 - mr.x0, mr.y1 - mr.y0, 192);
            st->mcre = fx_fractal_re(&v, x - mr.x0);
            st->mcim = fx_fractal_im(&v, y - mr.y0);
            if (down == 1 && st->mwidth > (FX56_ONE >> 40))
                st->mwidth /= 4;
            else if (down == 2 && st->mwidth < 4 * FX56_ONE)
                st->mwidth *= 4;
            st->julia_x = (mr.x0 + mr.x1) / 2;
            st->julia_y = (mr.y0 + mr.y1) / 2;
        }
    }
}

int demo_key(demo_state *st, int key)
{
    const char *name = demo_pages[st->page].name;
    if (!strcmp(name, "clipping")) {
        if (key == 'c')
            st->clipper = FX_CLIP_COHEN;
        else if (key == 'l')
            st->clipper = FX_CLIP_LIANG;
        else if (key == 'n')
            st->clipper = FX_CLIP_NLN;
        else
            return 0;
        return 1;
    }
    if (!strcmp(name, "vsd"))
        return demo_vsd_key(st, key);
    if (!strcmp(name, "raytrace"))
        return demo_rt_key(st, key);
    if (!strcmp(name, "anim"))
        return demo_anim_key(st, key);
    if (!strcmp(name, "3d")) {
        if (key == 's') {
            st->shading = (st->shading + 1) % 3;
            return 1;
        }
        return demo_camera_key(&st->cam, key, FX16_ONE / 4);
    }
    if (!strcmp(name, "fractals") && key >= '0' && key <= '6') {
        st->koch_order = key - '0';
        return 1;
    }
    if (!strcmp(name, "fractals") && key == 'o') {
        st->orbit_off = !st->orbit_off;
        return 1;
    }
    return 0;
}
