/* SPDX-License-Identifier: MIT */
/* fixel GLUT layer — state shared by gl.c (OpenGL 1.x), glut.c (windows,
 * input, the loop), shapes.c and text.c. Not installed. */
#ifndef FIXEL_GLUT_INT_H
#define FIXEL_GLUT_INT_H

#include <GL/freeglut.h>
#include <stdint.h>

#include "fixel/glcore.h"
#include "fixel/memfb.h"

#define FXG_STACK 32
#define FXG_PROJ_STACK 8
#define FXG_MAX_TEX 256
#define FXG_MAX_LISTS 4096

typedef struct fx_glut_vert {
    fx_gl_cvert cv;
} fx_glut_vert;

typedef struct fx_glut_tex {
    int used;
    fx_gl_texture t;
    uint8_t *mem;
    GLenum min_filter, mag_filter, wrap_s, wrap_t;
} fx_glut_tex;

typedef struct fx_glut_rec {
    uint32_t op, n; /* n: doubles, a blob's included */
    uint32_t off;   /* into the list's double pool */
} fx_glut_rec;

typedef struct fx_glut_list {
    int used;
    fx_glut_rec *rec;
    int nrec, caprec;
    double *pool;
    int npool, cappool;
} fx_glut_list;

typedef struct fx_glut_gl {
    /* the window's back buffer (what GL draws into and reads back) */
    fx_memfb fb;
    uint32_t *depth;
    int32_t w, h;
    fx_gl_target tgt;
    GLenum error;
    /* matrices */
    fx_glm mv[FXG_STACK], proj[FXG_PROJ_STACK], texm[4];
    int mv_top, proj_top, tex_top;
    GLenum matrix_mode;
    fx_glm mvp;
    fx32 nmat[9];
    int mvp_dirty, nmat_dirty;
    int vp[4], scissor[4];
    fx32 guard;
    /* enables */
    int depth_test, lighting, color_material, normalize, cull, blend, stipple, scissor_on,
        tex2d, rescale;
    GLenum cull_face, front_face, poly_front, poly_back, shade, depth_func;
    GLenum cm_face, cm_mode, bsrc, bdst;
    int depth_mask;
    fx16 clear_color[4];
    uint32_t clear_depth;
    float point_size, line_width;
    int stipple_factor;
    uint16_t stipple_pattern;
    uint8_t color_mask;
    /* current attributes */
    fx16 color[4];
    fx32 normal[3];
    fx16 texc[2];
    /* lighting */
    fx_gl_lighting L;
    fx_gl_material mat[2];
    int separate_specular; /* GL_LIGHT_MODEL_COLOR_CONTROL (see light_model) */
    /* immediate mode */
    GLenum prim;
    int in_begin;
    fx_glut_vert *vb;
    int nv, capv;
    int strip_started; /* points already drawn from this glBegin (for flushes) */
    /* raster position */
    int64_t rx, ry; /* window, 1/256 px */
    int raster_valid;
    fx16 raster_color[4];
    /* textures */
    fx_glut_tex tex[FXG_MAX_TEX];
    GLuint bound_tex;
    GLenum tex_env;
    /* pixel store */
    int unpack_align, pack_align;
    float zoom_x, zoom_y;
    /* display lists */
    fx_glut_list lists[FXG_MAX_LISTS];
    GLuint cur_list;
    int list_exec; /* COMPILE_AND_EXECUTE */
    int replaying;
    GLuint list_base;
    int64_t replay_left;   /* what one top-level glCallList may still replay */
    int64_t replay_budget; /* its start: 0 is FXG_REPLAY_BUDGET (the fuzz target sets less) */
    int replay_cut_logged;
    /* logged-once flags for unimplemented calls */
    char logged[512];
} fx_glut_gl;

extern fx_glut_gl fx_gl;

/* gl.c */
int fx_glut_gl_init(int32_t w, int32_t h);
void fx_glut_gl_resize(int32_t w, int32_t h);
void fx_glut_set_error(GLenum e);
/* The unimplemented-call path: record err and log the name once. */
void fx_glut_unimplemented(const char *name, GLenum err);
/* Mesh drawing for the GLUT solids (shapes.c): positions and normals in
 * Q16.16 as fx_mesh makes them, drawn as GL_TRIANGLES through the pipeline. */
void fx_glut_draw_tris_q16(const int32_t *pos, const int32_t *nrm, const uint32_t *tri, int32_t ntris,
                       int wire);
/* glutBitmapCharacter's raster drawing (text.c). */
void fx_glut_bitmap(int32_t w, int32_t h, int32_t xorig, int32_t yorig, int32_t xmove,
                const uint8_t *rows_top_first, int32_t row_bytes, int32_t scale);

/* glut.c: called at glFlush / glFinish / glutSwapBuffers */
void fx_glut_frame_done(int swap);
void fx_glut_log(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* The layer's environment (env.c), read once by glutInit. */
typedef struct fx_glut_env {
    long frames;        /* FIXEL_GLUT_FRAMES: exit 0 when frame N ends (0: never) */
    const char *out;    /* FIXEL_GLUT_OUT: write that frame here */
    const char *replay; /* FIXEL_GLUT_REPLAY: headless input */
    int fullscreen, headless, bench;
} fx_glut_env;
void fx_glut_env_read(fx_glut_env *v);

/* Float/double to fixed point at the API boundary (round to nearest even,
 * saturating): Q32.32 for geometry, Q16.16 for colours and parameters. */
fx32 fx_glut_d2x(double d);
int32_t fx_glut_d2i(double d);
int64_t fx_glut_d2win(double d);
fx_rect fx_glut_scissor_rect(void);
/* glViewport's clamps (gl.c): GL_MAX_VIEWPORT_DIMS and the bound on x, y */
#define FXG_MAX_VIEWPORT 16384
#define FXG_VIEWPORT_BOUND (1 << 20)
fx16 fx_glut_d2c(double d); /* clamped to [0, 1] */
fx16 fx_glut_d2q16(double d);
fx_angle fx_glut_deg2angle(double deg);
double fx_glut_x2d(fx32 v);

#endif
