/* SPDX-License-Identifier: MIT */
/* fixel — area fills: polygons (even-odd and nonzero), triangles, Gouraud
 * shading, fill styles (patterns, shaders) and the 2D triangle set-up.
 * Every polygon filler of the core is here (fill/fill.c): fx_fill_path's
 * edge table and fx_poly_fill16 for clipped Q16.16 pieces.
 *
 * Coverage rule (the pixel model and coverage rule of docs/CONVENTIONS.md;
 * the benchmark's workloads, docs/BENCHMARK.md, are defined with it).
 * Integer vertices are pixel centres: vertex (X, Y) lies on the
 * centre of pixel (X, Y), so pixel (x, y) is sampled at vertex coordinates
 * (x, y). 24.8 vertices (fx8) use the same frame scaled by 256. On row y an
 * edge counts iff min(y0, y1) <= y < max(y0, y1) (so horizontal edges never
 * count, and a vertex row belongs to the edge below it); its crossing is the
 * exact rational xc = x0 + (y - y0)(x1 - x0)/(y1 - y0); the sorted crossings
 * make spans ceil(xa) <= x < ceil(xb). Even-odd fills a pixel when an odd
 * number of crossings have ceil(xc) <= x; nonzero when the signed count (+1
 * for downward edges) is not 0. This is the top-left rule: a centre exactly
 * on a left or top edge is in, on a right or bottom edge is out, so polygons
 * sharing an edge cover every pixel along it exactly once. For integer
 * vertices the pixels are exactly those of the benchmark's reference.
 *
 * Crossings are stepped exactly (integer quotient and remainder, set up with
 * 128-bit products), so any int32 vertex works and the pixels never drift.
 * Work is bounded by the visible rows and the edges active on them.
 *
 * Fast paths, same pixels: triangles walk their two sides in registers; any
 * single contour whose vertical direction changes exactly twice (every
 * convex polygon, and y-monotone self-crossing ones) is walked as two
 * chains from its top vertex, with no edge table and no sorting.
 *
 * Memory: the edge table lives in caller memory (fx_fill_path) or, for the
 * convenience calls, in a stack array of FX_FILL_STACK_EDGES entries (about
 * 3 KiB); a polygon with more edges than that makes them return -FX_E2BIG.
 *
 * Every fill ends in fx_fill_span, which honours c->fill_style (NULL: solid
 * c->color), c->blend (FX_BLEND_OVER blends each pixel's colour with its own
 * alpha, exactly as fx_blend_over), the clip rectangle and exterior clipping.
 */
#ifndef FIXEL_FILL_H
#define FIXEL_FILL_H

#include <stddef.h>
#include <stdint.h>
#include "fixel/draw.h"
#include "fixel/fixed.h"
#include "fixel/xform.h" /* fx_pt16 */

#ifdef __cplusplus
extern "C" {
#endif

typedef enum fx_fill_rule { FX_FILL_EVENODD = 0, FX_FILL_NONZERO = 1 } fx_fill_rule;

/* ---- fill styles ---- */

/* Colours n pixels of row y starting at column x (surface coordinates) into
 * out[0..n-1] (0xAARRGGBB; the alpha matters under FX_BLEND_OVER). */
typedef void (*fx_shade_fn)(const void *user, int32_t y, int32_t x, int32_t n, fx_color *out);

typedef enum fx_fill_kind {
    FX_FILL_SOLID = 0,   /* c->color */
    FX_FILL_PATTERN = 1, /* bitmap pattern, see below */
    FX_FILL_SHADER = 2   /* colours from shade(user, ...): gradients, textures */
} fx_fill_kind;

/* Pattern: a w x h bitmap tiled from the anchor (ax, ay): pixel (x, y) takes
 * bit ((x - ax) mod w, (y - ay) mod h); bit (i, j) is
 * (bits[j * stride + i / 8] >> (7 - i % 8)) & 1, MSB first as patterns are
 * written (0x80 is the leftmost pixel). Set bits get c->color; clear bits get
 * bg, or are left untouched when bg_transparent is set. */
typedef struct fx_fill_style {
    fx_fill_kind kind;
    const uint8_t *bits;
    int32_t w, h, stride; /* 1 <= w, h; stride >= (w + 7) / 8 */
    int32_t ax, ay;
    fx_color bg;
    uint8_t bg_transparent;
    fx_shade_fn shade;
    const void *user;
} fx_fill_style;

/* Fill [x0, x1) of row y with the context's fill style, clipped, honouring
 * blending and exterior clipping: the building block of every fill. */
void fx_fill_span(const fx_ctx *c, int32_t y, int32_t x0, int32_t x1);

/* ---- polygons ---- */

#define FX_FILL_STACK_EDGES 64

/* An edge walker: x = ceil(crossing) on the current row in pixels, and
 * e = x*d - numerator in [0, d); each row adds the step d*qs + rs. */
typedef struct fx_tri_edge {
    int64_t x, e, d, qs, rs;
} fx_tri_edge;

/* One edge of the edge table (sized here so callers can provide memory). */
typedef struct fx_fill_edge {
    fx_tri_edge g;
    int32_t ystart, yend; /* visible rows [ystart, yend) */
    int32_t dir;          /* +1 downward, -1 upward (nonzero rule) */
    int32_t pad_;
} fx_fill_edge;

/* Filled polygon with n vertices xy[2i], xy[2i+1] (closed implicitly).
 * fx_fill_poly: integer pixel-centre vertices, any int32. fx_fill_poly8: fx8.
 * Returns 0, -FX_EINVAL (n < 0, NULL xy with n > 0) or -FX_E2BIG (more than
 * FX_FILL_STACK_EDGES non-horizontal edges: use fx_fill_path). */
int fx_fill_poly(const fx_ctx *c, const int32_t *xy, int32_t n, fx_fill_rule rule);
int fx_fill_poly8(const fx_ctx *c, const fx8 *xy, int32_t n, fx_fill_rule rule);
/* Alias of fx_fill_poly under its long name. */
static inline int fx_fill_polygon(const fx_ctx *c, const int32_t *xy, int32_t n, fx_fill_rule rule)
{
    return fx_fill_poly(c, xy, n, rule);
}

/* Fill pieces (npieces polygons, piece i = pts[starts[i] .. starts[i+1]-1])
 * as one even-odd region: the pixels whose centres are inside, top-left rule
 * on ties (a centre on a left or top edge is in, on a right or bottom edge
 * out), through c's clip and exterior. Work is bounded by the visible rows.
 * At most FX_POLY_FILL_MAX vertices in all (-FX_E2BIG beyond).
 *
 * Why a second entry beside fx_fill_path: it fills the clipped or
 * transformed Q16.16 pieces (clip.h's fx_clip_poly_pieces, xform.h's
 * rectangles, the scene's clipped polygons) with the coverage rule above on
 * Q16.16 vertices, in the context's colour only (fx_hspan: fill style
 * ignored), for up to FX_POLY_FILL_MAX vertices in 4 KB of stack. The edge
 * table holds every edge at once at 56 bytes each (28 KB for 512), too much
 * for a kernel-sized stack, so it walks rows and divides per crossing. */
#define FX_POLY_FILL_MAX 512
int fx_poly_fill16(const fx_ctx *c, const fx_pt16 *pts, const int *starts, int npieces);

/* Several closed contours filled together (holes, glyphs): contour k has
 * counts[k] vertices, taken in order from xy. frac_bits is 0 (integer
 * vertices) or 8 (fx8). The edge table is edges[0..max_edges-1]. Returns 0,
 * -FX_EINVAL or -FX_E2BIG when the table is too small. */
int fx_fill_path(const fx_ctx *c, const int32_t *xy, const int32_t *counts, int32_t ncontours,
                 unsigned frac_bits, fx_fill_rule rule, fx_fill_edge *edges, int32_t max_edges);

/* Outline: the closed chain of Bresenham lines through the vertices, each
 * vertex lit once (an edge lights its start pixel, not its end pixel). */
void fx_polygon(const fx_ctx *c, const int32_t *xy, int32_t n);

/* ---- triangles ---- */

/* Flat triangle with integer pixel-centre vertices: exactly the pixels of the
 * 3-vertex polygon (both rules agree). Vertices beyond +-2^22 take the general
 * polygon path; nearer ones the two-edge fast path. */
void fx_fill_tri(const fx_ctx *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1, int32_t x2,
                 int32_t y2);
/* Alias of fx_fill_tri under its long name. */
static inline void fx_fill_triangle(const fx_ctx *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1,
                                    int32_t x2, int32_t y2)
{
    fx_fill_tri(c, x0, y0, x1, y1, x2, y2);
}
/* The same with fx8 vertices xy[0..5], |coordinate| < 2^30. */
void fx_fill_tri8(const fx_ctx *c, const fx8 *xy);

/* Gouraud: colours col[i] (ARGB, alpha included) at the vertices, each
 * channel interpolated linearly and rounded to nearest; a pixel centre on a
 * vertex gets exactly that vertex's colour. Coverage as fx_fill_tri. The fill
 * style is ignored (the colours are the style); blending is honoured.
 * c, xy or col NULL: nothing is drawn. */
void fx_fill_tri_gouraud(const fx_ctx *c, const int32_t *xy, const fx_color *col);
void fx_fill_tri_gouraud8(const fx_ctx *c, const fx8 *xy, const fx_color *col);
/* Convex polygon, Gouraud-shaded as the fan (v0, vi, vi+1): the fan's
 * triangles share edges, so every pixel is covered once. c, xy or col NULL,
 * or n > INT32_MAX / 2: nothing is drawn. */
void fx_fill_poly_gouraud(const fx_ctx *c, const int32_t *xy, const fx_color *col, int32_t n);
/* The notes' scan-line Gouraud (gouraud_scan.c): on each row the colours
 * are interpolated along the two edges the row crosses, then across the
 * span between them, for any convex polygon at once. It differs from the
 * fan above for four or more vertices: the notes' quad with red, green,
 * blue and white corners has centre (128,128,128) here and (128,0,128) in
 * the fan, whose first triangle cuts along the red-blue diagonal. Same
 * coverage (fill.h's rule; pixel for pixel fx_fill_poly's for a convex
 * polygon), rounding to nearest per channel (alpha too), blending
 * honoured, fill style ignored. n 3..FX_GOURAUD_SCAN_MAX, coordinates within
 * +-FX_GOURAUD_SCAN_COORD (the products stay in int64); else -FX_EINVAL and
 * nothing drawn. Work bounded by the visible rows and columns. */
#define FX_GOURAUD_SCAN_MAX 1024
#define FX_GOURAUD_SCAN_COORD (1 << 20)
int fx_fill_poly_gouraud_scan(const fx_ctx *c, const int32_t *xy, const fx_color *col, int32_t n);

/* ---- seed fills (seedfill.c) ----
 *
 * Flood fill replaces the connected region of pixels whose native value
 * equals the seed's (the X byte of XRGB8888/XBGR8888 ignored); boundary fill
 * covers the connected region of pixels that are not the boundary colour
 * (compared packed, so on RGB565 colours that pack alike are alike).
 * conn is 4 or 8. The region is confined to the clip rectangle and painted
 * with fx_fill_span (fill style, blending and exterior clipping apply).
 *
 * Scan-line span fill, never recursive; time proportional to the region's
 * area. work/size is caller memory: a visited bitmap of one bit per pixel of
 * the clip rectangle (rows rounded up to 64 bits) and a span stack of 12-byte
 * entries after it. fx_seed_work_size gives the bitmap plus
 * FX_SEED_STACK_DEFAULT entries; at least FX_SEED_STACK_MIN are required. A
 * stack that fills up costs rescans, never pixels. Returns 0, -FX_EINVAL
 * (conn) or -FX_ENOSPC (work too small). */
#define FX_SEED_STACK_DEFAULT 16384
#define FX_SEED_STACK_MIN 4
size_t fx_seed_work_size(const fx_ctx *c);
int fx_flood_fill(const fx_ctx *c, int32_t x, int32_t y, int conn, void *work, size_t size);
int fx_boundary_fill(const fx_ctx *c, int32_t x, int32_t y, fx_color boundary, int conn, void *work,
                     size_t size);

/* ---- triangle set-up and span stepping ----
 *
 * The one 2D triangle set-up: fx_fill_tri*, the Gouraud fills and the
 * textured triangles (texture.h) all walk it, and a caller with its own
 * per-pixel work can use it too. The 3D renderer has its own rasterizer
 * (render3d.c), for reasons render3d.h gives under "Why a second
 * triangle rasterizer".
 *
 * fx_tri_begin sets up a triangle with fx8 vertices (|coordinate| < 2^30) and
 * up to FX_TRI_MAX_ATTR int32 attributes per vertex (|value| < 2^30), clipped
 * to clip. fx_tri_next_span then yields the covered spans row by row, top to
 * bottom, with the coverage rule above. Attribute k is an affine function of
 * the pixel centre, kept in Q32.32:
 *   value(x, y) = fx_tri_attr_at(t, k, x, y)     (int64, Q32.32)
 * and along a span it steps by t->gx[k] per pixel. Arithmetic is modulo 2^64
 * (values are exact whenever the true value fits, which it does inside the
 * triangle), so callers step with uint64_t and convert with
 * fx_tri_attr_round. Gradients are exact to 2^-32 per pixel, so at a vertex's
 * own pixel centre the rounded value is that vertex's attribute exactly. */
#define FX_TRI_MAX_ATTR 8

typedef struct fx_tri {
    fx_rect clip;
    int32_t y, ymid, yend; /* next row; row where the short edge changes; end */
    int32_t nattr;
    int32_t long_left;     /* 1 when the long edge is on the left */
    fx_tri_edge lng, sht;  /* long edge, current short edge */
    fx8 vx[3], vy[3];      /* sorted by y */
    uint64_t c[FX_TRI_MAX_ATTR], gx[FX_TRI_MAX_ATTR], gy[FX_TRI_MAX_ATTR];
} fx_tri;

typedef struct fx_tri_span {
    int32_t y, x0, x1; /* pixels [x0, x1) of row y, inside the clip, x0 < x1 */
} fx_tri_span;

/* Returns 1 when the triangle may cover pixels, 0 when it is empty
 * (degenerate or outside clip), -FX_ERANGE when a bound is exceeded.
 * attr: 3 * nattr values, vertex-major (attr[i * nattr + k]). */
int fx_tri_begin(fx_tri *t, fx_rect clip, const fx8 *xy, const int32_t *attr, int32_t nattr);
/* Next non-empty span; returns 0 when the triangle is done. */
int fx_tri_next_span(fx_tri *t, fx_tri_span *s);

/* Attribute k at pixel (x, y) of the triangle's plane, Q32.32 (above). */
static inline uint64_t fx_tri_attr_at(const fx_tri *t, int k, int32_t x, int32_t y)
{
    return t->c[k] + t->gx[k] * (uint64_t)(int64_t)x + t->gy[k] * (uint64_t)(int64_t)y;
}
/* Q32.32 (as stepped) -> nearest integer, ties up. */
static inline int32_t fx_tri_attr_round(uint64_t v)
{
    return (int32_t)((int64_t)(v + 0x80000000u) >> 32);
}

/* ---- intensity-dependent cross-hatching ----
 * A pen-and-ink rendering of a grey level: the darker the intensity
 * (0 black .. 255 white), the more hatch directions and the closer the
 * lines. Levels (FX_HATCH_LEVELS, level = (255 - intensity) * 8 / 256):
 *   0 no lines; 1 diagonal "/" every 8 px; 2 "/" every 4 px; 3 and
 *   "\" every 8 px; 4 both every 4 px; 5 and horizontal every 4 px;
 *   6 and vertical every 4 px; 7 all four every 2 px.
 * Each level's lines include the previous level's, so the ink covered
 * never falls as the intensity falls. fx_hatch_style writes the level's
 * 16 x 16 tile into bits (FX_HATCH_BYTES) and makes s a pattern style of
 * it with a transparent background (ink = the context's colour, anchored
 * at (0, 0)); it returns the number of hatch directions (0..4).
 * fx_hatch_ink: the set pixels of a level's tile (of 256). */
#define FX_HATCH_LEVELS 8
#define FX_HATCH_BYTES 32
int fx_hatch_level(uint8_t intensity);
int fx_hatch_style(fx_fill_style *s, uint8_t *bits, uint8_t intensity);
int32_t fx_hatch_ink(int level);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
