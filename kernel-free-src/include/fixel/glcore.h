/* SPDX-License-Identifier: MIT */
/* fixel — the integer core behind the GLUT / OpenGL 1.x layer
 * (boards/glut): Q32.32 matrices and vertex transformation, clip-space
 * clipping, the fixed-function lighting equation, and a rasterizer that
 * follows OpenGL's rules as Mesa's llvmpipe applies them.
 *
 * Numbers. Positions, matrices and clip coordinates are Q32.32 in int64_t
 * (fx32: 1.0 = 2^32, range +-2^31): a gluOrtho2D(0, 800, 0, 600) entry such
 * as 2/800 is then exact to 2^-32, so integer and half-integer vertices land
 * exactly where float arithmetic puts them (after snapping). Every product
 * is formed at 128 bits and rounded to nearest once per output entry (ties
 * up); quotients round to nearest. Window coordinates are snapped to 1/256
 * pixel (llvmpipe's FIXED_ORDER 8), rounded to nearest. Colours are Q16.16
 * fractions of full intensity (fx16, 1.0 = 65536) and become 8-bit by
 * round(c * 255) after clamping to [0, 1]. Depth is 24 bits:
 * round((z/w + 1) * 2^23), clamped to [0, 2^24 - 1].
 *
 * Window coordinates are GL's: y up, pixel (X, Y) is the square
 * [X, X+1) x [Y, Y+1) with its centre at (X + 1/2, Y + 1/2); the surface row
 * of window row Y is h - 1 - Y.
 *
 * Coverage, measured against llvmpipe (Mesa 22.3) and tested in
 * tests/glut/test_glut_raster.c (and against Mesa by tests/glut/compare.c):
 *   triangles  the pixels whose centres are inside; a centre exactly on an
 *              edge is in when that edge is a left edge (the interior lies
 *              to its right) or a bottom horizontal edge, out on right and
 *              top edges ("bottom-left" in GL's y-up frame), so triangles
 *              sharing an edge light each pixel once.
 *   points     size s (>= 1, rounded to an integer): pixel X is lit when
 *              x - s/2 < X + 1/2 <= x + s/2, the same in y: a size-1 point
 *              lights the pixel containing it, floor(x), floor(y).
 *   lines      diamond-exit: an x-major line (|dx| >= |dy|) lights one run
 *              of w rows per column whose centre x_c it crosses, the columns
 *              x0 <= x_c < x1 (x0 > x_c >= x1 leftwards), the first column
 *              also when the line starts inside its pixel's diamond
 *              |x - x_c| + |y - y_c| < 1/2 and the last one not when it ends
 *              inside it. In a column the rows are those whose centre y_c
 *              lies within w/2 of the line's y at x_c, a centre exactly on
 *              the run's edge taking the triangle rule of the parallelogram
 *              llvmpipe draws (lower edge in, upper out for horizontal and
 *              falling lines; upper in, lower out for rising ones). y-major
 *              lines are the same with x and y swapped, the left edge in.
 *              So a horizontal line at integer y lights row y - 1 and a
 *              vertical one at integer x column x - 1.
 * Flat shading takes the colour the caller passes as the provoking one.
 * Triangle colours and texture coordinates are interpolated perspective-
 * correctly, as llvmpipe does: when the three clip w differ, the
 * barycentric weights are those of a/w and 1/w interpolated in window space
 * (1/w normalised to 2^22 at the nearest vertex), divided per pixel, to
 * 2^-16 and clamped to the triangle; with equal w (any orthographic projection) it is the plain affine
 * interpolation. Depth is always affine in window space, as GL specifies.
 *
 * Nothing here allocates or keeps globals: the caller owns the surface, the
 * depth buffer and the texture memory.
 */
#ifndef FIXEL_GLCORE_H
#define FIXEL_GLCORE_H

#include <stdint.h>
#include "fixel/fixed.h"
#include "fixel/surface.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef int64_t fx32; /* Q32.32 */
#define FX32_ONE ((fx32)1 << 32)
#define FX32_HALF ((fx32)1 << 31)

/* ---- arithmetic ---- */
/* round(a * b / 2^32) (ties up), saturating: inline with a 128-bit
 * product where the compiler has one (the vertex path's hot spot), else
 * fx_mul64_shift's portable wide product; both give the same bits. */
static inline fx32 fx32_mul(fx32 a, fx32 b)
{
#ifdef __SIZEOF_INT128__
    __int128 r = ((__int128)a * b + ((__int128)1 << 31)) >> 32;
    int64_t r64 = (int64_t)r; /* the result unless it saturates (rare) */
    if (__builtin_expect(r != r64, 0))
        return r < 0 ? INT64_MIN : INT64_MAX;
    return r64;
#else
    return fx_mul64_shift(a, b, 32);
#endif
}
/* Saturating sums: every fx32 the GL layer stores can be anywhere in
 * int64_t (the boundary saturates doubles at +-2^31 units, products
 * saturate), so a sum that is stored goes through these and pins at
 * INT64_MIN / INT64_MAX instead of overflowing. */
static inline fx32 fx32_add(fx32 a, fx32 b)
{
    fx32 r;
    if (__builtin_add_overflow(a, b, &r))
        return a < 0 ? INT64_MIN : INT64_MAX;
    return r;
}
static inline fx32 fx32_sub(fx32 a, fx32 b)
{
    fx32 r;
    if (__builtin_sub_overflow(a, b, &r))
        return a < 0 ? INT64_MIN : INT64_MAX;
    return r;
}
static inline fx32 fx32_neg(fx32 a) { return a == INT64_MIN ? INT64_MAX : -a; }
/* round(a * b / c) with a 128-bit intermediate, saturating; c == 0 gives
 * INT64_MAX or INT64_MIN by the sign of a*b (0 for a*b == 0). */
int64_t fx_muldiv64(int64_t a, int64_t b, int64_t c);
/* a / b in Q32.32 (round(a * 2^32 / b)). */
static inline fx32 fx32_div(fx32 a, fx32 b) { return fx_muldiv64(a, FX32_ONE, b); }
/* floor(sqrt(a)) in Q32.32 for a >= 0 (0 for negative a). */
fx32 fx32_sqrt(fx32 a);
/* sin and cos of a binary angle in Q32.32 (|error| <= 2^-30). */
fx32 fx32_sin(fx_angle a);
fx32 fx32_cos(fx_angle a);

/* ---- matrices: column-major as GL (m[col * 4 + row]) ---- */
typedef struct fx_glm {
    fx32 m[16];
} fx_glm;

typedef struct fx_glv4 {
    fx32 x, y, z, w;
} fx_glv4;

/* m = the identity matrix. */
void fx_glm_identity(fx_glm *m);
/* r = a * b (r may alias a or b). */
void fx_glm_mul(fx_glm *r, const fx_glm *a, const fx_glm *b);
fx_glv4 fx_glm_apply(const fx_glm *m, fx_glv4 v);
/* Builders (each writes a whole matrix), the matrices of glTranslate,
 * glScale, glRotate (axis normalised here; a zero axis gives the identity
 * and -1), glOrtho, glFrustum (-1 for empty volumes, as GL_INVALID_VALUE),
 * gluPerspective (fovy in binary angle units) and gluLookAt. */
void fx_glm_translate(fx_glm *m, fx32 x, fx32 y, fx32 z);
void fx_glm_scale(fx_glm *m, fx32 x, fx32 y, fx32 z);
int fx_glm_rotate(fx_glm *m, fx_angle a, fx32 x, fx32 y, fx32 z);
int fx_glm_ortho(fx_glm *m, fx32 l, fx32 r, fx32 b, fx32 t, fx32 n, fx32 f);
int fx_glm_frustum(fx_glm *m, fx32 l, fx32 r, fx32 b, fx32 t, fx32 n, fx32 f);
int fx_glm_perspective(fx_glm *m, fx_angle fovy, fx32 aspect, fx32 n, fx32 f);
int fx_glm_lookat(fx_glm *m, const fx32 eye[3], const fx32 at[3], const fx32 up[3]);
/* The normal matrix: the inverse transpose of m's upper 3x3, in n[0..8]
 * (column-major). Returns -1 (and the identity) when it is singular. */
int fx_glm_normal_matrix(const fx_glm *m, fx32 n[9]);
/* Unit vector in place (Q32.32); returns -1 for the zero vector. */
int fx_glv3_normalize(fx32 v[3]);

/* ---- lighting (GL 1.x fixed function) ---- */
#define FX_GL_MAX_LIGHTS 8

typedef struct fx_gl_light {
    int enabled;
    fx16 ambient[4], diffuse[4], specular[4];
    fx32 pos[4];      /* eye coordinates; w = 0: directional */
    fx32 spot_dir[3]; /* eye coordinates */
    fx32 spot_cos;    /* cos(cut-off); cut-off 180 means no spot: spot_cut = 0 */
    int spot_cut;     /* 1 when the cut-off is below 180 degrees */
    fx16 spot_exp;    /* 0..128 */
    fx32 att[3];      /* constant, linear, quadratic */
} fx_gl_light;

typedef struct fx_gl_material {
    fx16 ambient[4], diffuse[4], specular[4], emission[4];
    fx16 shininess; /* 0..128 */
} fx_gl_material;

typedef struct fx_gl_lighting {
    fx_gl_light light[FX_GL_MAX_LIGHTS];
    fx16 model_ambient[4];
    int two_side;     /* the caller lights back faces (fx_gl_cvert.bc) */
    int local_viewer; /* 0: the eye at (0, 0, +inf); 1: at the eye-space origin */
} fx_gl_lighting;

/* The colour of a vertex at eye position p (w = 1 or any w) with eye
 * normal n (used as given: GL lights unnormalised normals as they are),
 * clamped to [0, 1]: the sum of GL's equation
 *   e + a * A_global + sum_i att_i spot_i (a A_i + max(N.L, 0) d D_i
 *                                          + [N.L > 0] max(N.H, 0)^s s S_i)
 * with H = normalize(L + (0, 0, 1)), or normalize(L + normalize(-p)) with
 * local_viewer; alpha is the material's diffuse alpha. Two-sided lighting
 * is the caller's: the back colour is this with the back material and -n.
 * Shininess and spot exponents are rounded to 1/16 and the powers taken by
 * repeated squaring of the integer part times a 16-step interpolated root. */
void fx_gl_shade(const fx_gl_lighting *L, const fx_gl_material *m, const fx32 p[4],
                 const fx32 n[3], fx16 out[4]);
/* fx_gl_shade for many vertices: what depends only on a light (the unit
 * vector and half vector of a directional light, the unit spot direction)
 * is kept in the caller's cache between calls, with the light position and
 * spot direction it was computed from, and computed again when they change.
 * Gives fx_gl_shade's bits. A cache starts zeroed (or with valid = 0). */
typedef struct fx_gl_shade_light {
    int valid;
    fx32 pos[4], spot_dir[3]; /* what vp, h, sd were computed from */
    fx32 vp[3], h[3], sd[3];
} fx_gl_shade_light;
typedef struct fx_gl_shade_cache {
    fx_gl_shade_light light[FX_GL_MAX_LIGHTS];
} fx_gl_shade_cache;
void fx_gl_shade_cached(const fx_gl_lighting *L, fx_gl_shade_cache *cache,
                        const fx_gl_material *m, const fx32 p[4], const fx32 n[3], fx16 out[4]);
/* x^e for x in [0, 1] (Q16.16) and e >= 0 (Q16.16). */
fx16 fx_gl_pow(fx16 x, fx16 e);

/* ---- rasterization ---- */
enum {
    FX_GL_DEPTH_NEVER, FX_GL_DEPTH_LESS, FX_GL_DEPTH_EQUAL, FX_GL_DEPTH_LEQUAL,
    FX_GL_DEPTH_GREATER, FX_GL_DEPTH_NOTEQUAL, FX_GL_DEPTH_GEQUAL, FX_GL_DEPTH_ALWAYS
};
/* Blend factors. */
enum {
    FX_GL_BF_ZERO, FX_GL_BF_ONE, FX_GL_BF_SRC_COLOR, FX_GL_BF_ONE_MINUS_SRC_COLOR,
    FX_GL_BF_SRC_ALPHA, FX_GL_BF_ONE_MINUS_SRC_ALPHA, FX_GL_BF_DST_ALPHA,
    FX_GL_BF_ONE_MINUS_DST_ALPHA, FX_GL_BF_DST_COLOR, FX_GL_BF_ONE_MINUS_DST_COLOR,
    FX_GL_BF_SRC_ALPHA_SATURATE
};
/* Texture environment and filters. */
enum { FX_GL_TEX_MODULATE, FX_GL_TEX_REPLACE, FX_GL_TEX_DECAL, FX_GL_TEX_BLEND, FX_GL_TEX_ADD };

typedef struct fx_gl_texture {
    const uint8_t *rgba; /* w * h * 4 bytes, row 0 = t near 0 */
    int32_t w, h;
    uint8_t linear;      /* magnification/minification: 0 nearest, 1 linear */
    uint8_t clamp_s, clamp_t; /* 1: clamp to edge, 0: repeat */
} fx_gl_texture;

typedef struct fx_gl_target {
    fx_surface surf;
    fx_rect clip;        /* window coordinates, y up: viewport (and scissor) inside the surface */
    uint32_t *depth;     /* surf.w * surf.h values (row r = surface row r) or NULL */
    uint8_t depth_test, depth_write, depth_func;
    uint8_t blend, bf_src, bf_dst;
    uint8_t stipple_on;
    uint16_t stipple_pattern;
    int32_t stipple_factor;
    uint32_t stipple_count; /* pixels of the current strip so far (reset by the caller) */
    const fx_gl_texture *tex; /* NULL: no texturing */
    uint8_t tex_env;
    uint8_t color_mask;  /* bit 0 r, 1 g, 2 b, 3 a; 0 is taken as 0xF */
    fx16 tex_env_color[4];
} fx_gl_target;

/* A vertex in window coordinates, ready to draw. */
typedef struct fx_gl_wvert {
    int64_t x, y;   /* 1/256 pixel, y up (snapped) */
    int32_t z;      /* 0 .. 2^24 - 1 */
    fx16 c[4];      /* rgba in [0, 1] */
    fx16 s, t;      /* texture coordinates (1.0 = 65536) */
    fx32 w;         /* clip w (> 0), for perspective-correct interpolation; 0: affine */
} fx_gl_wvert;

/* Ranges the rasterizers are proved for (the Bound comments in
 * glraster.c): window x and y within +-FX_GL_WIN_MAX (1/256 pixel, i.e.
 * +-2^21 pixels; fx_gl_to_window clamps to it), point sizes and line
 * widths up to FX_GL_MAX_SIZE pixels (clamped). */
#define FX_GL_WIN_MAX ((int64_t)1 << 29)
#define FX_GL_MAX_SIZE 32768
/* Clip coordinates -> window vertex for viewport (vx, vy, vw, vh).
 * Returns -1 when w <= 0 (the caller clips first). */
int fx_gl_to_window(const fx_glv4 *clip, int32_t vx, int32_t vy, int32_t vw, int32_t vh,
                    fx_gl_wvert *out);

/* Size: pixels (>= 1; the caller rounds GL's float size). */
void fx_gl_point(fx_gl_target *t, const fx_gl_wvert *v, int32_t size);
/* Line of width w pixels (>= 1). With flat != NULL every pixel takes that
 * colour (the provoking vertex's), else colours are interpolated. */
void fx_gl_line(fx_gl_target *t, const fx_gl_wvert *a, const fx_gl_wvert *b, int32_t width,
                const fx16 *flat);
/* Triangle (any winding; the caller culls). flat as for lines. */
void fx_gl_triangle(fx_gl_target *t, const fx_gl_wvert *a, const fx_gl_wvert *b,
                    const fx_gl_wvert *c, const fx16 *flat);
/* Twice the signed area in 1/256-pixel units squared (> 0 counter-clockwise). */
int64_t fx_gl_area2(const fx_gl_wvert *a, const fx_gl_wvert *b, const fx_gl_wvert *c);

/* ---- clipping in clip space ---- */
/* A clip-space vertex with the attributes that are interpolated: bc is the
 * back-face colour of two-sided lighting (the caller keeps it equal to c
 * otherwise; the clipper interpolates it like c). */
typedef struct fx_gl_cvert {
    fx_glv4 p;
    fx16 c[4];
    fx16 s, t;
    fx16 bc[4];
} fx_gl_cvert;

/* The guard band: x and y are clipped at |x|, |y| <= g w (g chosen by the
 * caller so window coordinates stay within +-2^20 pixels), z at |z| <= w.
 * Lines: returns 0 when nothing is left, else 1 with a and b replaced by
 * the visible part. Polygons: in[0..n-1] -> out (room for n + 6 vertices),
 * returns the number of vertices left (0, or >= 3). */
int fx_gl_clip_line(fx_gl_cvert *a, fx_gl_cvert *b, fx32 g);
int fx_gl_clip_poly(const fx_gl_cvert *in, int n, fx_gl_cvert *out, fx_gl_cvert *tmp, fx32 g);
/* 1 when p is inside the view volume in z (and w > 0). */
int fx_gl_point_visible(const fx_glv4 *p);

/* Pixel helpers for glReadPixels / glDrawPixels / glClear (window coords,
 * y up; all clipped to the surface). */
void fx_gl_clear(fx_gl_target *t, fx_rect r, fx_color c, int color, uint32_t depth, int depth_on);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
