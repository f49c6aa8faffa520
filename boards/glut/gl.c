/* SPDX-License-Identifier: MIT */
/* fixel GLUT layer — OpenGL 1.x state, immediate mode and the boundary
 * conversions. Floats and doubles are converted to fixed point here
 * (fx_glut_d2x & co: round to nearest, ties to even, saturating) and
 * everything after that runs in kernel-free-src/gl (fixel/glcore.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "glut_int.h"

fx_glut_gl fx_gl;

/* ---- boundary conversions ---- */
fx32 fx_glut_d2x(double d)
{
    if (d != d)
        return 0;
    if (d >= 2147483647.0)
        return INT64_MAX;
    if (d <= -2147483648.0)
        return INT64_MIN;
    return (fx32)llrint(d * 4294967296.0);
}
fx16 fx_glut_d2q16(double d)
{
    if (d != d)
        return 0;
    if (d >= 32767.0)
        return INT32_MAX;
    if (d <= -32768.0)
        return INT32_MIN;
    return (fx16)lrint(d * 65536.0);
}
/* The 8-bit level llvmpipe stores for a colour f (GL keeps colours as
 * floats): f * 255/256 rounded to float, then to an integer number of
 * 1/256 ties to even (Mesa's float_to_ubyte and its shader's
 * float-to-unorm8 both add 32768.0f and keep the low 8 bits). */
static int mesa_level(float f)
{
    if (!(f > 0.0f))
        return 0;
    if (f >= 1.0f)
        return 255;
    float t = (float)((double)f * (255.0 / 256.0)); /* exact product, one rounding */
    return (int)lrint((double)t * 256.0);
}
/* A colour as Q16.16 in [0, 1]: the nearest value to (float)d, moved by
 * 1/65536 where needed so that the core's round(c * 255) gives the level
 * llvmpipe gives (they differ only at ties, e.g. 0.3f: 76.5 -> 76). */
fx16 fx_glut_d2c(double d)
{
    float f = (float)d;
    fx16 v = fx_glut_d2q16(f);
    if (v <= 0)
        return 0;
    if (v >= FX16_ONE)
        return FX16_ONE;
    int want = mesa_level(f);
    while (v > 0 && (int)(((int64_t)v * 255 + 0x8000) >> 16) > want)
        v--;
    while (v < FX16_ONE && (int)(((int64_t)v * 255 + 0x8000) >> 16) < want)
        v++;
    return v;
}
/* A double to int32 for the integer parameters GL takes as floats
 * (glTexParameterf, glPixelStoref, glBitmap's origin): rounded to nearest,
 * saturating, NaN as 0 -- a float-to-int conversion out of range is
 * undefined behaviour in C, llrint's result unspecified. */
int32_t fx_glut_d2i(double d)
{
    if (d != d)
        return 0;
    if (d >= 2147483647.0)
        return INT32_MAX;
    if (d <= -2147483648.0)
        return INT32_MIN;
    return (int32_t)lrint(d);
}
/* A window coordinate in 1/256 pixel (glWindowPos, glBitmap's moves):
 * clamped to +-FX_GL_WIN_MAX, the range the rasterizers are proved for. */
int64_t fx_glut_d2win(double d)
{
    double w = (double)FX_GL_WIN_MAX;
    if (d != d)
        return 0;
    d *= 256.0;
    return d >= w ? FX_GL_WIN_MAX : d <= -w ? -FX_GL_WIN_MAX : (int64_t)llrint(d);
}
static int64_t clamp_win(int64_t v)
{
    return v < -FX_GL_WIN_MAX ? -FX_GL_WIN_MAX : v > FX_GL_WIN_MAX ? FX_GL_WIN_MAX : v;
}
fx_angle fx_glut_deg2angle(double deg)
{
    if (!isfinite(deg)) /* fmod(inf, 360) is NaN: no angle; GL leaves it undefined */
        return 0;
    double t = fmod(deg, 360.0) / 360.0; /* (-1, 1) */
    return (fx_angle)(uint32_t)(int64_t)llrint(t * 4294967296.0);
}
double fx_glut_x2d(fx32 v) { return (double)v / 4294967296.0; }

void fx_glut_set_error(GLenum e)
{
    if (fx_gl.error == GL_NO_ERROR)
        fx_gl.error = e;
}

void fx_glut_unimplemented(const char *name, GLenum err)
{
    fx_glut_set_error(err);
    unsigned h = 5381;
    for (const char *p = name; *p; p++)
        h = h * 33 + (unsigned char)*p;
    h %= sizeof fx_gl.logged * 8;
    if (!(fx_gl.logged[h / 8] & (1 << (h % 8)))) {
        fx_gl.logged[h / 8] |= (char)(1 << (h % 8));
        fx_glut_log("%s is not implemented by fixel's GL layer (ignored)", name);
    }
}

GLenum glGetError(void)
{
    GLenum e = fx_gl.error;
    fx_gl.error = GL_NO_ERROR;
    return e;
}

/* ---- display lists: recording ---- */
/* Every GL call a display list holds, declared once: X(NAME, replay)
 * makes both the OP_ enum and the replay switch, so a call recorded under
 * a name always has its replay. `a` is the recorded doubles, `d` the
 * nesting depth; a blob (bitmap or pixel rows, unpacked at compile time as
 * GL says) follows the call's doubles in the pool, at a + its count. The
 * calls GL runs at once even while compiling (glGen*, glGet*, glIsList,
 * glDeleteLists, glPixelStore, glReadPixels, glFlush, glFinish, client
 * state) are not listed. */
#define FX_GLUT_LIST_OPS(X)                                                                          \
    X(BEGIN, glBegin((GLenum)a[0]))                                                                  \
    X(END, glEnd())                                                                                  \
    X(VERTEX, vertex(a[0], a[1], a[2], a[3]))                                                        \
    X(COLOR, set_color(a[0], a[1], a[2], a[3]))                                                      \
    X(NORMAL, set_normal(a[0], a[1], a[2]))                                                          \
    X(TEXCOORD, set_tc(a[0], a[1]))                                                                  \
    X(MATRIXMODE, glMatrixMode((GLenum)a[0]))                                                        \
    X(LOADIDENTITY, glLoadIdentity())                                                                \
    X(PUSH, glPushMatrix())                                                                          \
    X(POP, glPopMatrix())                                                                            \
    X(MULT, glMultMatrixd(a))                                                                        \
    X(LOAD, glLoadMatrixd(a))                                                                        \
    X(TRANSLATE, glTranslated(a[0], a[1], a[2]))                                                     \
    X(ROTATE, glRotated(a[0], a[1], a[2], a[3]))                                                     \
    X(SCALE, glScaled(a[0], a[1], a[2]))                                                             \
    X(ENABLE, glEnable((GLenum)a[0]))                                                                \
    X(DISABLE, glDisable((GLenum)a[0]))                                                              \
    X(SHADE, glShadeModel((GLenum)a[0]))                                                             \
    X(POINTSIZE, glPointSize((GLfloat)a[0]))                                                         \
    X(LINEWIDTH, glLineWidth((GLfloat)a[0]))                                                         \
    X(MATERIAL, material_v((GLenum)a[0], (GLenum)a[1], a + 2))                                       \
    X(LIGHT, light_v((GLenum)a[0], (GLenum)a[1], a + 2))                                             \
    X(CALLLIST, replay((GLuint)a[0], d + 1))                                                         \
    X(CALLLIST_BASE, replay(fx_gl.list_base + (GLuint)a[0], d + 1))                                  \
    X(LISTBASE, glListBase((GLuint)a[0]))                                                            \
    X(BINDTEX, glBindTexture((GLenum)a[0], (GLuint)a[1]))                                            \
    X(TEXPARAM, glTexParameteri((GLenum)a[0], (GLenum)a[1], (GLint)a[2]))                            \
    X(TEXENV, glTexEnvi((GLenum)a[0], (GLenum)a[1], (GLint)a[2]))                                    \
    X(TEXENVCOLOR, tex_env_color(a))                                                                 \
    X(RECT, glRectd(a[0], a[1], a[2], a[3]))                                                         \
    X(ORTHO, glOrtho(a[0], a[1], a[2], a[3], a[4], a[5]))                                            \
    X(FRUSTUM, glFrustum(a[0], a[1], a[2], a[3], a[4], a[5]))                                        \
    X(POLYMODE, glPolygonMode((GLenum)a[0], (GLenum)a[1]))                                           \
    X(STIPPLE, glLineStipple((GLint)a[0], (GLushort)a[1]))                                           \
    X(LIGHTMODEL, light_model((GLenum)a[0], a + 1))                                                  \
    X(COLORMATERIAL, glColorMaterial((GLenum)a[0], (GLenum)a[1]))                                    \
    X(RASTERPOS, raster_pos(a[0], a[1], a[2], a[3]))                                                 \
    X(WINDOWPOS, window_pos(a[0], a[1]))                                                             \
    X(BITMAP, bitmap_rec(a))                                                                         \
    X(BITMAPCHAR, bitmapchar_rec(a))                                                                 \
    X(DRAWPIXELS, draw_pixels_rec(a))                                                                \
    X(PIXELZOOM, glPixelZoom((GLfloat)a[0], (GLfloat)a[1]))                                          \
    X(BLENDFUNC, glBlendFunc((GLenum)a[0], (GLenum)a[1]))                                            \
    X(DEPTHFUNC, glDepthFunc((GLenum)a[0]))                                                          \
    X(DEPTHMASK, glDepthMask((GLboolean)a[0]))                                                       \
    X(COLORMASK, glColorMask((GLboolean)a[0], (GLboolean)a[1], (GLboolean)a[2], (GLboolean)a[3]))    \
    X(CULLFACE, glCullFace((GLenum)a[0]))                                                            \
    X(FRONTFACE, glFrontFace((GLenum)a[0]))                                                          \
    X(VIEWPORT, glViewport((GLint)a[0], (GLint)a[1], (GLsizei)a[2], (GLsizei)a[3]))                  \
    X(SCISSOR, glScissor((GLint)a[0], (GLint)a[1], (GLsizei)a[2], (GLsizei)a[3]))                    \
    X(CLEAR, glClear((GLbitfield)a[0]))                                                              \
    X(CLEARCOLOR, glClearColor((GLclampf)a[0], (GLclampf)a[1], (GLclampf)a[2], (GLclampf)a[3]))      \
    X(CLEARDEPTH, glClearDepth(a[0]))
enum {
#define FX_GLUT_OP_ENUM(name, run) OP_##name,
    OP_NONE_ = 0,
    FX_GLUT_LIST_OPS(FX_GLUT_OP_ENUM)
#undef FX_GLUT_OP_ENUM
};

static int recording(void) { return fx_gl.cur_list != 0 && !fx_gl.replaying; }

/* A list's pool holds at most FXG_LIST_POOL doubles (1 GiB): a bigger
 * list is GL_OUT_OF_MEMORY, before any int sum of sizes can wrap. */
#define FXG_LIST_POOL (1 << 27)
/* n doubles from a, then a blob of nb bytes (bitmap or pixel rows) padded
 * to whole doubles; the replay finds the blob at a + n. */
static void record_blob(int op, int n, const double *a, const void *blob, size_t nb)
{
    fx_glut_list *l = &fx_gl.lists[fx_gl.cur_list];
    size_t nblob = (nb + sizeof(double) - 1) / sizeof(double);
    if (nblob > FXG_LIST_POOL || (size_t)l->npool + (size_t)n + nblob > FXG_LIST_POOL) {
        fx_glut_set_error(GL_OUT_OF_MEMORY);
        return;
    }
    int all = n + (int)nblob;
    if (l->nrec == l->caprec) {
        int nc = l->caprec ? l->caprec * 2 : 64;
        fx_glut_rec *r = realloc(l->rec, (size_t)nc * sizeof *r);
        if (!r) {
            fx_glut_set_error(GL_OUT_OF_MEMORY);
            return;
        }
        l->rec = r, l->caprec = nc;
    }
    if (l->npool + all > l->cappool) {
        int nc = l->cappool ? l->cappool * 2 : 256;
        while (nc < l->npool + all)
            nc *= 2;
        double *p = realloc(l->pool, (size_t)nc * sizeof *p);
        if (!p) {
            fx_glut_set_error(GL_OUT_OF_MEMORY);
            return;
        }
        l->pool = p, l->cappool = nc;
    }
    l->rec[l->nrec++] = (fx_glut_rec){(uint32_t)op, (uint32_t)all, (uint32_t)l->npool};
    if (n) /* a call of no arguments before the pool exists: memcpy(NULL, ...) is undefined */
        memcpy(l->pool + l->npool, a, (size_t)n * sizeof *a);
    if (nb) {
        l->pool[l->npool + all - 1] = 0; /* the padding of the last double */
        memcpy(l->pool + l->npool + n, blob, nb);
    }
    l->npool += all;
}
static void record(int op, int n, const double *a) { record_blob(op, n, a, NULL, 0); }

/* Record and tell whether to execute now. */
#define REC(op, ...)                                             \
    do {                                                         \
        if (recording()) {                                       \
            double a_[] = {__VA_ARGS__};                         \
            record(op, (int)(sizeof a_ / sizeof a_[0]), a_);     \
            if (!fx_gl.list_exec)                                  \
                return;                                          \
        }                                                        \
    } while (0)
#define REC0(op)                           \
    do {                                   \
        if (recording()) {                 \
            record(op, 0, NULL);           \
            if (!fx_gl.list_exec)            \
                return;                    \
        }                                  \
    } while (0)

/* ---- initialisation ---- */
/* The scissor box as a rectangle: x + w of GL's int32 box can pass
 * INT32_MAX, so the corners are summed in 64 bits and clamped. */
fx_rect fx_glut_scissor_rect(void)
{
    int64_t x1 = (int64_t)fx_gl.scissor[0] + fx_gl.scissor[2], y1 = (int64_t)fx_gl.scissor[1] + fx_gl.scissor[3];
    return (fx_rect){fx_gl.scissor[0], fx_gl.scissor[1], x1 > INT32_MAX ? INT32_MAX : (int32_t)x1,
                     y1 > INT32_MAX ? INT32_MAX : (int32_t)y1};
}
static void update_clip(void)
{
    /* the viewport is clamped where it is set (glViewport), so its sums
     * fit; the scissor box is GL's any x, y and size: fx_glut_scissor_rect */
    fx_rect r = {fx_gl.vp[0], fx_gl.vp[1], fx_gl.vp[0] + fx_gl.vp[2], fx_gl.vp[1] + fx_gl.vp[3]};
    fx_rect win = {0, 0, fx_gl.w, fx_gl.h};
    r = fx_rect_intersect(r, win);
    if (fx_gl.scissor_on)
        r = fx_rect_intersect(r, fx_glut_scissor_rect());
    if (fx_rect_empty(r))
        r = (fx_rect){0, 0, 0, 0};
    fx_gl.tgt.clip = r;
    int32_t m = fx_gl.vp[2] > fx_gl.vp[3] ? fx_gl.vp[2] : fx_gl.vp[3];
    if (m < 1)
        m = 1;
    fx_gl.guard = fx_muldiv64((int64_t)1 << 21, FX32_ONE, m);
    if (fx_gl.guard < FX32_ONE)
        fx_gl.guard = FX32_ONE;
}

static void default_light(fx_gl_light *l, int i)
{
    memset(l, 0, sizeof *l);
    l->ambient[3] = FX16_ONE;
    if (i == 0) {
        for (int k = 0; k < 4; k++)
            l->diffuse[k] = l->specular[k] = FX16_ONE;
    } else {
        l->diffuse[3] = l->specular[3] = FX16_ONE;
    }
    l->pos[2] = FX32_ONE; /* (0, 0, 1, 0) */
    l->spot_dir[2] = -FX32_ONE;
    l->att[0] = FX32_ONE;
}

static void default_material(fx_gl_material *m)
{
    memset(m, 0, sizeof *m);
    for (int k = 0; k < 3; k++) {
        m->ambient[k] = fx_glut_d2c(0.2);
        m->diffuse[k] = fx_glut_d2c(0.8);
    }
    m->ambient[3] = m->diffuse[3] = m->specular[3] = m->emission[3] = FX16_ONE;
}

int fx_glut_gl_init(int32_t w, int32_t h)
{
    if (fx_memfb_create(&fx_gl.fb, w, h, FX_FMT_XRGB8888) < 0)
        return -1;
    fx_gl.depth = calloc((size_t)w * (size_t)h, sizeof *fx_gl.depth);
    if (!fx_gl.depth)
        return -1;
    fx_gl.w = w, fx_gl.h = h;
    memset(&fx_gl.tgt, 0, sizeof fx_gl.tgt);
    fx_gl.tgt.surf = fx_gl.fb.surf;
    fx_gl.tgt.depth = fx_gl.depth;
    fx_gl.tgt.depth_write = 1;
    fx_gl.tgt.depth_func = FX_GL_DEPTH_LESS;
    fx_glm_identity(&fx_gl.mv[0]);
    fx_glm_identity(&fx_gl.proj[0]);
    fx_glm_identity(&fx_gl.texm[0]);
    fx_gl.matrix_mode = GL_MODELVIEW;
    fx_gl.mvp_dirty = fx_gl.nmat_dirty = 1;
    fx_gl.vp[0] = fx_gl.vp[1] = 0, fx_gl.vp[2] = w, fx_gl.vp[3] = h;
    fx_gl.scissor[0] = fx_gl.scissor[1] = 0, fx_gl.scissor[2] = w, fx_gl.scissor[3] = h;
    fx_gl.cull_face = GL_BACK, fx_gl.front_face = GL_CCW;
    fx_gl.poly_front = fx_gl.poly_back = GL_FILL;
    fx_gl.shade = GL_SMOOTH, fx_gl.depth_func = GL_LESS, fx_gl.depth_mask = 1;
    fx_gl.cm_face = GL_FRONT_AND_BACK, fx_gl.cm_mode = GL_AMBIENT_AND_DIFFUSE;
    fx_gl.bsrc = GL_ONE, fx_gl.bdst = GL_ZERO;
    fx_gl.clear_depth = 0xFFFFFF;
    fx_gl.point_size = fx_gl.line_width = 1.0f;
    fx_gl.stipple_factor = 1, fx_gl.stipple_pattern = 0xFFFF;
    fx_gl.color_mask = 0xF;
    for (int k = 0; k < 4; k++)
        fx_gl.color[k] = FX16_ONE;
    fx_gl.normal[2] = FX32_ONE;
    for (int i = 0; i < FX_GL_MAX_LIGHTS; i++)
        default_light(&fx_gl.L.light[i], i);
    for (int k = 0; k < 3; k++)
        fx_gl.L.model_ambient[k] = fx_glut_d2c(0.2);
    fx_gl.L.model_ambient[3] = FX16_ONE;
    default_material(&fx_gl.mat[0]);
    default_material(&fx_gl.mat[1]);
    fx_gl.tex_env = GL_MODULATE;
    fx_gl.unpack_align = fx_gl.pack_align = 4;
    fx_gl.zoom_x = fx_gl.zoom_y = 1.0f;
    update_clip();
    fx_gl_clear(&fx_gl.tgt, (fx_rect){0, 0, w, h}, 0xFF000000u, 1, 0xFFFFFF, 1);
    return 0;
}

void fx_glut_gl_resize(int32_t w, int32_t h)
{
    if (w == fx_gl.w && h == fx_gl.h)
        return;
    fx_memfb nfb;
    uint32_t *nd = calloc((size_t)w * (size_t)h, sizeof *nd);
    if (!nd || fx_memfb_create(&nfb, w, h, FX_FMT_XRGB8888) < 0) {
        free(nd);
        return;
    }
    fx_memfb_destroy(&fx_gl.fb);
    free(fx_gl.depth);
    fx_gl.fb = nfb, fx_gl.depth = nd;
    fx_gl.w = w, fx_gl.h = h;
    fx_gl.tgt.surf = fx_gl.fb.surf;
    fx_gl.tgt.depth = nd;
    update_clip();
}

/* ---- matrices ---- */
static fx_glm *cur_matrix(void)
{
    switch (fx_gl.matrix_mode) {
    case GL_PROJECTION: return &fx_gl.proj[fx_gl.proj_top];
    case GL_TEXTURE: return &fx_gl.texm[fx_gl.tex_top];
    default: return &fx_gl.mv[fx_gl.mv_top];
    }
}
static void matrix_changed(void)
{
    fx_gl.mvp_dirty = 1;
    if (fx_gl.matrix_mode == GL_MODELVIEW)
        fx_gl.nmat_dirty = 1;
}
static void mult_cur(const fx_glm *m)
{
    fx_glm *c = cur_matrix();
    fx_glm_mul(c, c, m);
    matrix_changed();
}

void glMatrixMode(GLenum mode)
{
    REC(OP_MATRIXMODE, (double)mode);
    if (mode != GL_MODELVIEW && mode != GL_PROJECTION && mode != GL_TEXTURE) {
        fx_glut_set_error(GL_INVALID_ENUM);
        return;
    }
    fx_gl.matrix_mode = mode;
}
void glLoadIdentity(void)
{
    REC0(OP_LOADIDENTITY);
    fx_glm_identity(cur_matrix());
    matrix_changed();
}
void glPushMatrix(void)
{
    REC0(OP_PUSH);
    int *top = fx_gl.matrix_mode == GL_PROJECTION ? &fx_gl.proj_top
               : fx_gl.matrix_mode == GL_TEXTURE  ? &fx_gl.tex_top
                                                : &fx_gl.mv_top;
    int cap = fx_gl.matrix_mode == GL_PROJECTION ? FXG_PROJ_STACK
              : fx_gl.matrix_mode == GL_TEXTURE  ? 4
                                               : FXG_STACK;
    if (*top + 1 >= cap) {
        fx_glut_set_error(GL_STACK_OVERFLOW);
        return;
    }
    fx_glm *c = cur_matrix();
    (*top)++;
    *cur_matrix() = *c;
}
void glPopMatrix(void)
{
    REC0(OP_POP);
    int *top = fx_gl.matrix_mode == GL_PROJECTION ? &fx_gl.proj_top
               : fx_gl.matrix_mode == GL_TEXTURE  ? &fx_gl.tex_top
                                                : &fx_gl.mv_top;
    if (*top == 0) {
        fx_glut_set_error(GL_STACK_UNDERFLOW);
        return;
    }
    (*top)--;
    matrix_changed();
}
static void load_d(const double *m, int mult)
{
    fx_glm t;
    for (int i = 0; i < 16; i++)
        t.m[i] = fx_glut_d2x(m[i]);
    if (mult)
        mult_cur(&t);
    else {
        *cur_matrix() = t;
        matrix_changed();
    }
}
void glLoadMatrixd(const GLdouble *m)
{
    if (recording()) {
        record(OP_LOAD, 16, m);
        if (!fx_gl.list_exec)
            return;
    }
    load_d(m, 0);
}
void glLoadMatrixf(const GLfloat *m)
{
    double d[16];
    for (int i = 0; i < 16; i++)
        d[i] = m[i];
    glLoadMatrixd(d);
}
void glMultMatrixd(const GLdouble *m)
{
    if (recording()) {
        record(OP_MULT, 16, m);
        if (!fx_gl.list_exec)
            return;
    }
    load_d(m, 1);
}
void glMultMatrixf(const GLfloat *m)
{
    double d[16];
    for (int i = 0; i < 16; i++)
        d[i] = m[i];
    glMultMatrixd(d);
}
void glTranslated(GLdouble x, GLdouble y, GLdouble z)
{
    REC(OP_TRANSLATE, x, y, z);
    fx_glm t;
    fx_glm_translate(&t, fx_glut_d2x(x), fx_glut_d2x(y), fx_glut_d2x(z));
    mult_cur(&t);
}
void glTranslatef(GLfloat x, GLfloat y, GLfloat z) { glTranslated(x, y, z); }
void glScaled(GLdouble x, GLdouble y, GLdouble z)
{
    REC(OP_SCALE, x, y, z);
    fx_glm t;
    fx_glm_scale(&t, fx_glut_d2x(x), fx_glut_d2x(y), fx_glut_d2x(z));
    mult_cur(&t);
}
void glScalef(GLfloat x, GLfloat y, GLfloat z) { glScaled(x, y, z); }
void glRotated(GLdouble a, GLdouble x, GLdouble y, GLdouble z)
{
    REC(OP_ROTATE, a, x, y, z);
    fx_glm t;
    fx_glm_rotate(&t, fx_glut_deg2angle(a), fx_glut_d2x(x), fx_glut_d2x(y), fx_glut_d2x(z));
    mult_cur(&t);
}
void glRotatef(GLfloat a, GLfloat x, GLfloat y, GLfloat z) { glRotated(a, x, y, z); }
void glOrtho(GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f)
{
    REC(OP_ORTHO, l, r, b, t, n, f);
    fx_glm m;
    if (fx_glm_ortho(&m, fx_glut_d2x(l), fx_glut_d2x(r), fx_glut_d2x(b), fx_glut_d2x(t), fx_glut_d2x(n),
                     fx_glut_d2x(f)) < 0) {
        fx_glut_set_error(GL_INVALID_VALUE);
        return;
    }
    mult_cur(&m);
}
void glFrustum(GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f)
{
    REC(OP_FRUSTUM, l, r, b, t, n, f);
    fx_glm m;
    if (fx_glm_frustum(&m, fx_glut_d2x(l), fx_glut_d2x(r), fx_glut_d2x(b), fx_glut_d2x(t), fx_glut_d2x(n),
                       fx_glut_d2x(f)) < 0) {
        fx_glut_set_error(GL_INVALID_VALUE);
        return;
    }
    mult_cur(&m);
}
void gluOrtho2D(GLdouble l, GLdouble r, GLdouble b, GLdouble t) { glOrtho(l, r, b, t, -1, 1); }
void gluPerspective(GLdouble fovy, GLdouble aspect, GLdouble n, GLdouble f)
{
    fx_glm m;
    if (fx_glm_perspective(&m, fx_glut_deg2angle(fovy), fx_glut_d2x(aspect), fx_glut_d2x(n), fx_glut_d2x(f)) < 0)
        return;
    double d[16];
    for (int i = 0; i < 16; i++)
        d[i] = fx_glut_x2d(m.m[i]);
    glMultMatrixd(d);
}
void gluLookAt(GLdouble ex, GLdouble ey, GLdouble ez, GLdouble cx, GLdouble cy, GLdouble cz,
               GLdouble ux, GLdouble uy, GLdouble uz)
{
    fx32 e[3] = {fx_glut_d2x(ex), fx_glut_d2x(ey), fx_glut_d2x(ez)};
    fx32 c[3] = {fx_glut_d2x(cx), fx_glut_d2x(cy), fx_glut_d2x(cz)};
    fx32 u[3] = {fx_glut_d2x(ux), fx_glut_d2x(uy), fx_glut_d2x(uz)};
    fx_glm m;
    if (fx_glm_lookat(&m, e, c, u) < 0)
        return;
    double d[16];
    for (int i = 0; i < 16; i++)
        d[i] = fx_glut_x2d(m.m[i]);
    glMultMatrixd(d);
}
/* GL clamps the size to GL_MAX_VIEWPORT_DIMS (16384 here); x and y are
 * clamped to +-FXG_VIEWPORT_BOUND (2^20, GL 4.1's VIEWPORT_BOUNDS_RANGE
 * idea) so that x + w and the window coordinates x * 256 + w * 128 * ndc
 * stay inside the rasterizers' range (fixel/glcore.h, FX_GL_WIN_MAX). */
void glViewport(GLint x, GLint y, GLsizei w, GLsizei h)
{
    REC(OP_VIEWPORT, x, y, w, h);
    if (w < 0 || h < 0) {
        fx_glut_set_error(GL_INVALID_VALUE);
        return;
    }
    if (w > FXG_MAX_VIEWPORT) w = FXG_MAX_VIEWPORT;
    if (h > FXG_MAX_VIEWPORT) h = FXG_MAX_VIEWPORT;
    x = x < -FXG_VIEWPORT_BOUND ? -FXG_VIEWPORT_BOUND : x > FXG_VIEWPORT_BOUND ? FXG_VIEWPORT_BOUND : x;
    y = y < -FXG_VIEWPORT_BOUND ? -FXG_VIEWPORT_BOUND : y > FXG_VIEWPORT_BOUND ? FXG_VIEWPORT_BOUND : y;
    fx_gl.vp[0] = x, fx_gl.vp[1] = y, fx_gl.vp[2] = w, fx_gl.vp[3] = h;
    update_clip();
}
void glScissor(GLint x, GLint y, GLsizei w, GLsizei h)
{
    REC(OP_SCISSOR, x, y, w, h);
    if (w < 0 || h < 0) {
        fx_glut_set_error(GL_INVALID_VALUE);
        return;
    }
    fx_gl.scissor[0] = x, fx_gl.scissor[1] = y, fx_gl.scissor[2] = w, fx_gl.scissor[3] = h;
    update_clip();
}

static void ensure_mvp(void)
{
    if (fx_gl.mvp_dirty) {
        fx_glm_mul(&fx_gl.mvp, &fx_gl.proj[fx_gl.proj_top], &fx_gl.mv[fx_gl.mv_top]);
        fx_gl.mvp_dirty = 0;
    }
    if (fx_gl.nmat_dirty && fx_gl.lighting) {
        fx_glm_normal_matrix(&fx_gl.mv[fx_gl.mv_top], fx_gl.nmat);
        fx_gl.nmat_dirty = 0;
    }
}

/* ---- enables ---- */
static int *cap_flag(GLenum cap)
{
    switch (cap) {
    case GL_DEPTH_TEST: return &fx_gl.depth_test;
    case GL_LIGHTING: return &fx_gl.lighting;
    case GL_COLOR_MATERIAL: return &fx_gl.color_material;
    case GL_NORMALIZE: return &fx_gl.normalize;
    case GL_RESCALE_NORMAL: return &fx_gl.rescale;
    case GL_CULL_FACE: return &fx_gl.cull;
    case GL_BLEND: return &fx_gl.blend;
    case GL_LINE_STIPPLE: return &fx_gl.stipple;
    case GL_SCISSOR_TEST: return &fx_gl.scissor_on;
    case GL_TEXTURE_2D: return &fx_gl.tex2d;
    default: return NULL;
    }
}
static void apply_color_material(void);
static void set_cap(GLenum cap, int on)
{
    if (cap >= GL_LIGHT0 && cap <= GL_LIGHT7) {
        fx_gl.L.light[cap - GL_LIGHT0].enabled = on;
        return;
    }
    int *f = cap_flag(cap);
    if (f) {
        *f = on;
        if (cap == GL_SCISSOR_TEST)
            update_clip();
        if (cap == GL_LIGHTING)
            fx_gl.nmat_dirty = 1;
        if (cap == GL_COLOR_MATERIAL && on)
            apply_color_material(); /* the current colour is taken at once, as in Mesa */
        return;
    }
    switch (cap) {
    case GL_DITHER: case GL_POINT_SMOOTH: case GL_LINE_SMOOTH: case GL_POLYGON_SMOOTH:
    case GL_MULTISAMPLE: case GL_AUTO_NORMAL:
        return; /* accepted; no visible effect here (llvmpipe dithers nothing either) */
    case GL_ALPHA_TEST: case GL_FOG: case GL_STENCIL_TEST: case GL_POLYGON_OFFSET_FILL:
    case GL_POLYGON_OFFSET_LINE: case GL_POLYGON_OFFSET_POINT: case GL_COLOR_LOGIC_OP:
    case GL_INDEX_LOGIC_OP: case GL_POLYGON_STIPPLE: case GL_TEXTURE_1D: case GL_CLIP_PLANE0:
    case GL_CLIP_PLANE1: case GL_CLIP_PLANE2: case GL_CLIP_PLANE3: case GL_TEXTURE_GEN_S:
    case GL_TEXTURE_GEN_T: case GL_MAP2_VERTEX_3: case GL_MAP1_VERTEX_3:
        if (on)
            fx_glut_unimplemented(cap == GL_FOG ? "glEnable(GL_FOG)"
                              : cap == GL_ALPHA_TEST ? "glEnable(GL_ALPHA_TEST)"
                              : cap == GL_COLOR_LOGIC_OP ? "glEnable(GL_COLOR_LOGIC_OP)"
                              : cap == GL_POLYGON_OFFSET_FILL ? "glEnable(GL_POLYGON_OFFSET_FILL)"
                              : "glEnable(an unsupported capability)",
                              GL_INVALID_ENUM);
        return;
    default:
        fx_glut_set_error(GL_INVALID_ENUM);
    }
}
void glEnable(GLenum cap)
{
    REC(OP_ENABLE, (double)cap);
    set_cap(cap, 1);
}
void glDisable(GLenum cap)
{
    REC(OP_DISABLE, (double)cap);
    set_cap(cap, 0);
}
GLboolean glIsEnabled(GLenum cap)
{
    if (cap >= GL_LIGHT0 && cap <= GL_LIGHT7)
        return (GLboolean)fx_gl.L.light[cap - GL_LIGHT0].enabled;
    int *f = cap_flag(cap);
    return f ? (GLboolean)(*f != 0) : GL_FALSE;
}

void glShadeModel(GLenum m)
{
    REC(OP_SHADE, (double)m);
    if (m != GL_FLAT && m != GL_SMOOTH) {
        fx_glut_set_error(GL_INVALID_ENUM);
        return;
    }
    fx_gl.shade = m;
}
void glPointSize(GLfloat s)
{
    REC(OP_POINTSIZE, s);
    if (!(s > 0)) { /* NaN too */
        fx_glut_set_error(GL_INVALID_VALUE);
        return;
    }
    fx_gl.point_size = s;
}
void glLineWidth(GLfloat w)
{
    REC(OP_LINEWIDTH, w);
    if (!(w > 0)) { /* NaN too */
        fx_glut_set_error(GL_INVALID_VALUE);
        return;
    }
    fx_gl.line_width = w;
}
void glLineStipple(GLint factor, GLushort pattern)
{
    REC(OP_STIPPLE, factor, pattern);
    fx_gl.stipple_factor = factor < 1 ? 1 : factor > 256 ? 256 : factor;
    fx_gl.stipple_pattern = pattern;
}
void glPolygonMode(GLenum face, GLenum mode)
{
    REC(OP_POLYMODE, (double)face, (double)mode);
    if (mode != GL_POINT && mode != GL_LINE && mode != GL_FILL) {
        fx_glut_set_error(GL_INVALID_ENUM);
        return;
    }
    if (face == GL_FRONT || face == GL_FRONT_AND_BACK)
        fx_gl.poly_front = mode;
    if (face == GL_BACK || face == GL_FRONT_AND_BACK)
        fx_gl.poly_back = mode;
}
void glDepthFunc(GLenum f)
{
    REC(OP_DEPTHFUNC, (double)f);
    if (f < GL_NEVER || f > GL_ALWAYS) {
        fx_glut_set_error(GL_INVALID_ENUM);
        return;
    }
    fx_gl.depth_func = f;
}
void glDepthMask(GLboolean flag)
{
    REC(OP_DEPTHMASK, flag);
    fx_gl.depth_mask = flag != 0;
}
void glDepthRange(GLclampd n, GLclampd f)
{
    if (n != 0.0 || f != 1.0)
        fx_glut_unimplemented("glDepthRange (other than 0, 1)", GL_INVALID_OPERATION);
}
void glCullFace(GLenum m)
{
    REC(OP_CULLFACE, (double)m);
    if (m != GL_FRONT && m != GL_BACK && m != GL_FRONT_AND_BACK) {
        fx_glut_set_error(GL_INVALID_ENUM);
        return;
    }
    fx_gl.cull_face = m;
}
void glFrontFace(GLenum m)
{
    REC(OP_FRONTFACE, (double)m);
    if (m != GL_CW && m != GL_CCW) {
        fx_glut_set_error(GL_INVALID_ENUM);
        return;
    }
    fx_gl.front_face = m;
}
static int blend_factor(GLenum f)
{
    switch (f) {
    case GL_ZERO: return FX_GL_BF_ZERO;
    case GL_ONE: return FX_GL_BF_ONE;
    case GL_SRC_COLOR: return FX_GL_BF_SRC_COLOR;
    case GL_ONE_MINUS_SRC_COLOR: return FX_GL_BF_ONE_MINUS_SRC_COLOR;
    case GL_SRC_ALPHA: return FX_GL_BF_SRC_ALPHA;
    case GL_ONE_MINUS_SRC_ALPHA: return FX_GL_BF_ONE_MINUS_SRC_ALPHA;
    case GL_DST_ALPHA: return FX_GL_BF_DST_ALPHA;
    case GL_ONE_MINUS_DST_ALPHA: return FX_GL_BF_ONE_MINUS_DST_ALPHA;
    case GL_DST_COLOR: return FX_GL_BF_DST_COLOR;
    case GL_ONE_MINUS_DST_COLOR: return FX_GL_BF_ONE_MINUS_DST_COLOR;
    case GL_SRC_ALPHA_SATURATE: return FX_GL_BF_SRC_ALPHA_SATURATE;
    default: return -1;
    }
}
void glBlendFunc(GLenum s, GLenum d)
{
    REC(OP_BLENDFUNC, (double)s, (double)d);
    if (blend_factor(s) < 0 || blend_factor(d) < 0) {
        fx_glut_set_error(GL_INVALID_ENUM);
        return;
    }
    fx_gl.bsrc = s, fx_gl.bdst = d;
}
void glColorMask(GLboolean r, GLboolean g, GLboolean b, GLboolean a)
{
    REC(OP_COLORMASK, r, g, b, a);
    fx_gl.color_mask = (uint8_t)((r ? 1 : 0) | (g ? 2 : 0) | (b ? 4 : 0) | (a ? 8 : 0));
    if (!fx_gl.color_mask)
        fx_gl.color_mask = 0x10; /* nothing written */
}
void glHint(GLenum target, GLenum mode) { (void)target, (void)mode; }

/* ---- clearing ---- */
void glClearColor(GLclampf r, GLclampf g, GLclampf b, GLclampf a)
{
    REC(OP_CLEARCOLOR, r, g, b, a);
    fx_gl.clear_color[0] = fx_glut_d2c(r), fx_gl.clear_color[1] = fx_glut_d2c(g);
    fx_gl.clear_color[2] = fx_glut_d2c(b), fx_gl.clear_color[3] = fx_glut_d2c(a);
}
void glClearDepth(GLclampd d)
{
    REC(OP_CLEARDEPTH, d);
    d = !(d > 0) ? 0 : d > 1 ? 1 : d; /* NaN as 0 */
    int64_t z = llrint(d * 16777216.0);
    fx_gl.clear_depth = z > 0xFFFFFF ? 0xFFFFFF : (uint32_t)z;
}
static int lvl(fx16 c) { return (int)(((int64_t)c * 255 + 0x8000) >> 16); }
void glClear(GLbitfield mask)
{
    REC(OP_CLEAR, (double)mask);
    if (fx_gl.in_begin) {
        fx_glut_set_error(GL_INVALID_OPERATION);
        return;
    }
    fx_rect r = {0, 0, fx_gl.w, fx_gl.h};
    if (fx_gl.scissor_on)
        r = fx_glut_scissor_rect(); /* x + w may pass INT32_MAX */
    fx_color c = ((fx_color)lvl(fx_gl.clear_color[3]) << 24) | ((fx_color)lvl(fx_gl.clear_color[0]) << 16) |
                 ((fx_color)lvl(fx_gl.clear_color[1]) << 8) | (fx_color)lvl(fx_gl.clear_color[2]);
    fx_gl_clear(&fx_gl.tgt, r, c, (mask & GL_COLOR_BUFFER_BIT) != 0, fx_gl.clear_depth,
                (mask & GL_DEPTH_BUFFER_BIT) != 0);
}

void glFlush(void) { fx_glut_frame_done(0); }
void glFinish(void) { fx_glut_frame_done(0); }

/* ---- current attributes ---- */
static void apply_color_material(void)
{
    if (!fx_gl.color_material)
        return;
    for (int f = 0; f < 2; f++) {
        if ((f == 0 && fx_gl.cm_face == GL_BACK) || (f == 1 && fx_gl.cm_face == GL_FRONT))
            continue;
        fx_gl_material *m = &fx_gl.mat[f];
        for (int k = 0; k < 4; k++) {
            switch (fx_gl.cm_mode) {
            case GL_AMBIENT: m->ambient[k] = fx_gl.color[k]; break;
            case GL_DIFFUSE: m->diffuse[k] = fx_gl.color[k]; break;
            case GL_SPECULAR: m->specular[k] = fx_gl.color[k]; break;
            case GL_EMISSION: m->emission[k] = fx_gl.color[k]; break;
            default: m->ambient[k] = m->diffuse[k] = fx_gl.color[k]; break;
            }
        }
    }
}
static void set_color(double r, double g, double b, double a)
{
    REC(OP_COLOR, r, g, b, a);
    fx_gl.color[0] = fx_glut_d2c(r), fx_gl.color[1] = fx_glut_d2c(g), fx_gl.color[2] = fx_glut_d2c(b),
    fx_gl.color[3] = fx_glut_d2c(a);
    apply_color_material();
}
#define B(v) ((2.0 * (v) + 1.0) / 255.0)
#define S(v) ((2.0 * (v) + 1.0) / 65535.0)
#define I(v) ((2.0 * (double)(v) + 1.0) / 4294967295.0)
void glColor3b(GLbyte r, GLbyte g, GLbyte b) { set_color(B(r), B(g), B(b), 1); }
void glColor3d(GLdouble r, GLdouble g, GLdouble b) { set_color(r, g, b, 1); }
void glColor3f(GLfloat r, GLfloat g, GLfloat b) { set_color(r, g, b, 1); }
void glColor3i(GLint r, GLint g, GLint b) { set_color(I(r), I(g), I(b), 1); }
void glColor3s(GLshort r, GLshort g, GLshort b) { set_color(S(r), S(g), S(b), 1); }
void glColor3ub(GLubyte r, GLubyte g, GLubyte b) { set_color(r / 255.0, g / 255.0, b / 255.0, 1); }
void glColor3ui(GLuint r, GLuint g, GLuint b) { set_color(r / 4294967295.0, g / 4294967295.0, b / 4294967295.0, 1); }
void glColor3us(GLushort r, GLushort g, GLushort b) { set_color(r / 65535.0, g / 65535.0, b / 65535.0, 1); }
void glColor4b(GLbyte r, GLbyte g, GLbyte b, GLbyte a) { set_color(B(r), B(g), B(b), B(a)); }
void glColor4d(GLdouble r, GLdouble g, GLdouble b, GLdouble a) { set_color(r, g, b, a); }
void glColor4f(GLfloat r, GLfloat g, GLfloat b, GLfloat a) { set_color(r, g, b, a); }
void glColor4i(GLint r, GLint g, GLint b, GLint a) { set_color(I(r), I(g), I(b), I(a)); }
void glColor4s(GLshort r, GLshort g, GLshort b, GLshort a) { set_color(S(r), S(g), S(b), S(a)); }
void glColor4ub(GLubyte r, GLubyte g, GLubyte b, GLubyte a) { set_color(r / 255.0, g / 255.0, b / 255.0, a / 255.0); }
void glColor4ui(GLuint r, GLuint g, GLuint b, GLuint a) { set_color(r / 4294967295.0, g / 4294967295.0, b / 4294967295.0, a / 4294967295.0); }
void glColor4us(GLushort r, GLushort g, GLushort b, GLushort a) { set_color(r / 65535.0, g / 65535.0, b / 65535.0, a / 65535.0); }
void glColor3bv(const GLbyte *v) { glColor3b(v[0], v[1], v[2]); }
void glColor3dv(const GLdouble *v) { glColor3d(v[0], v[1], v[2]); }
void glColor3fv(const GLfloat *v) { glColor3f(v[0], v[1], v[2]); }
void glColor3iv(const GLint *v) { glColor3i(v[0], v[1], v[2]); }
void glColor3sv(const GLshort *v) { glColor3s(v[0], v[1], v[2]); }
void glColor3ubv(const GLubyte *v) { glColor3ub(v[0], v[1], v[2]); }
void glColor3uiv(const GLuint *v) { glColor3ui(v[0], v[1], v[2]); }
void glColor3usv(const GLushort *v) { glColor3us(v[0], v[1], v[2]); }
void glColor4bv(const GLbyte *v) { glColor4b(v[0], v[1], v[2], v[3]); }
void glColor4dv(const GLdouble *v) { glColor4d(v[0], v[1], v[2], v[3]); }
void glColor4fv(const GLfloat *v) { glColor4f(v[0], v[1], v[2], v[3]); }
void glColor4iv(const GLint *v) { glColor4i(v[0], v[1], v[2], v[3]); }
void glColor4sv(const GLshort *v) { glColor4s(v[0], v[1], v[2], v[3]); }
void glColor4ubv(const GLubyte *v) { glColor4ub(v[0], v[1], v[2], v[3]); }
void glColor4uiv(const GLuint *v) { glColor4ui(v[0], v[1], v[2], v[3]); }
void glColor4usv(const GLushort *v) { glColor4us(v[0], v[1], v[2], v[3]); }

static void set_normal(double x, double y, double z)
{
    REC(OP_NORMAL, x, y, z);
    fx_gl.normal[0] = fx_glut_d2x(x), fx_gl.normal[1] = fx_glut_d2x(y), fx_gl.normal[2] = fx_glut_d2x(z);
}
void glNormal3b(GLbyte x, GLbyte y, GLbyte z) { set_normal(B(x), B(y), B(z)); }
void glNormal3d(GLdouble x, GLdouble y, GLdouble z) { set_normal(x, y, z); }
void glNormal3f(GLfloat x, GLfloat y, GLfloat z) { set_normal(x, y, z); }
void glNormal3i(GLint x, GLint y, GLint z) { set_normal(I(x), I(y), I(z)); }
void glNormal3s(GLshort x, GLshort y, GLshort z) { set_normal(S(x), S(y), S(z)); }
void glNormal3bv(const GLbyte *v) { glNormal3b(v[0], v[1], v[2]); }
void glNormal3dv(const GLdouble *v) { set_normal(v[0], v[1], v[2]); }
void glNormal3fv(const GLfloat *v) { set_normal(v[0], v[1], v[2]); }
void glNormal3iv(const GLint *v) { glNormal3i(v[0], v[1], v[2]); }
void glNormal3sv(const GLshort *v) { glNormal3s(v[0], v[1], v[2]); }
#undef B
#undef S
#undef I

static void set_tc(double s, double t)
{
    REC(OP_TEXCOORD, s, t);
    fx_gl.texc[0] = fx_glut_d2q16(s), fx_gl.texc[1] = fx_glut_d2q16(t);
}
void glTexCoord1f(GLfloat s) { set_tc(s, 0); }
void glTexCoord1d(GLdouble s) { set_tc(s, 0); }
void glTexCoord2d(GLdouble s, GLdouble t) { set_tc(s, t); }
void glTexCoord2f(GLfloat s, GLfloat t) { set_tc(s, t); }
void glTexCoord2i(GLint s, GLint t) { set_tc(s, t); }
void glTexCoord2s(GLshort s, GLshort t) { set_tc(s, t); }
void glTexCoord2dv(const GLdouble *v) { set_tc(v[0], v[1]); }
void glTexCoord2fv(const GLfloat *v) { set_tc(v[0], v[1]); }
void glTexCoord2iv(const GLint *v) { set_tc(v[0], v[1]); }
void glTexCoord2sv(const GLshort *v) { set_tc(v[0], v[1]); }
void glTexCoord3f(GLfloat s, GLfloat t, GLfloat r) { (void)r, set_tc(s, t); }
void glTexCoord4f(GLfloat s, GLfloat t, GLfloat r, GLfloat q) { (void)r, (void)q, set_tc(s, t); }

/* ---- lights and materials ---- */
static fx_gl_light *light_of(GLenum l)
{
    if (l < GL_LIGHT0 || l > GL_LIGHT7) {
        fx_glut_set_error(GL_INVALID_ENUM);
        return NULL;
    }
    return &fx_gl.L.light[l - GL_LIGHT0];
}
static void light_v(GLenum light, GLenum pname, const double *p)
{
    if (recording()) {
        double a[6] = {(double)light, (double)pname, p[0], 0, 0, 0};
        int n = pname == GL_POSITION || pname == GL_AMBIENT || pname == GL_DIFFUSE ||
                        pname == GL_SPECULAR ? 4 : pname == GL_SPOT_DIRECTION ? 3 : 1;
        for (int i = 1; i < n; i++)
            a[2 + i] = p[i];
        record(OP_LIGHT, 6, a);
        if (!fx_gl.list_exec)
            return;
    }
    fx_gl_light *l = light_of(light);
    if (!l)
        return;
    /* GL 1.x's ranges (Mesa: GL_INVALID_VALUE and nothing changes) */
    if ((pname == GL_SPOT_EXPONENT && !(p[0] >= 0 && p[0] <= 128)) ||
        (pname == GL_SPOT_CUTOFF && !(p[0] >= 0 && p[0] <= 90) && p[0] != 180.0) ||
        ((pname == GL_CONSTANT_ATTENUATION || pname == GL_LINEAR_ATTENUATION ||
          pname == GL_QUADRATIC_ATTENUATION) && !(p[0] >= 0))) {
        fx_glut_set_error(GL_INVALID_VALUE);
        return;
    }
    switch (pname) {
    case GL_AMBIENT: for (int k = 0; k < 4; k++) l->ambient[k] = fx_glut_d2q16(p[k]); break;
    case GL_DIFFUSE: for (int k = 0; k < 4; k++) l->diffuse[k] = fx_glut_d2q16(p[k]); break;
    case GL_SPECULAR: for (int k = 0; k < 4; k++) l->specular[k] = fx_glut_d2q16(p[k]); break;
    case GL_POSITION: {
        fx_glv4 v = {fx_glut_d2x(p[0]), fx_glut_d2x(p[1]), fx_glut_d2x(p[2]), fx_glut_d2x(p[3])};
        v = fx_glm_apply(&fx_gl.mv[fx_gl.mv_top], v);
        l->pos[0] = v.x, l->pos[1] = v.y, l->pos[2] = v.z, l->pos[3] = v.w;
        break;
    }
    case GL_SPOT_DIRECTION: {
        const fx_glm *m = &fx_gl.mv[fx_gl.mv_top];
        fx32 d[3] = {fx_glut_d2x(p[0]), fx_glut_d2x(p[1]), fx_glut_d2x(p[2])};
        for (int r = 0; r < 3; r++)
            l->spot_dir[r] = fx32_add(fx32_add(fx32_mul(m->m[r], d[0]), fx32_mul(m->m[4 + r], d[1])),
                                      fx32_mul(m->m[8 + r], d[2])); /* each product may saturate */
        break;
    }
    case GL_SPOT_EXPONENT: l->spot_exp = fx_glut_d2q16(p[0]); break;
    case GL_SPOT_CUTOFF:
        l->spot_cut = p[0] != 180.0;
        l->spot_cos = fx32_cos(fx_glut_deg2angle(p[0]));
        break;
    case GL_CONSTANT_ATTENUATION: l->att[0] = fx_glut_d2x(p[0]); break;
    case GL_LINEAR_ATTENUATION: l->att[1] = fx_glut_d2x(p[0]); break;
    case GL_QUADRATIC_ATTENUATION: l->att[2] = fx_glut_d2x(p[0]); break;
    default: fx_glut_set_error(GL_INVALID_ENUM);
    }
}
void glLightfv(GLenum l, GLenum pname, const GLfloat *p)
{
    double d[4] = {p[0], 0, 0, 0};
    int n = pname == GL_SPOT_DIRECTION ? 3 : (pname == GL_AMBIENT || pname == GL_DIFFUSE ||
                                               pname == GL_SPECULAR || pname == GL_POSITION) ? 4 : 1;
    for (int i = 1; i < n; i++)
        d[i] = p[i];
    light_v(l, pname, d);
}
void glLightiv(GLenum l, GLenum pname, const GLint *p)
{
    double d[4] = {p[0], 0, 0, 0};
    int n = pname == GL_SPOT_DIRECTION ? 3 : (pname == GL_AMBIENT || pname == GL_DIFFUSE ||
                                               pname == GL_SPECULAR || pname == GL_POSITION) ? 4 : 1;
    for (int i = 1; i < n; i++)
        d[i] = p[i];
    if (pname == GL_AMBIENT || pname == GL_DIFFUSE || pname == GL_SPECULAR)
        for (int i = 0; i < 4; i++)
            d[i] = (2.0 * p[i] + 1) / 4294967295.0;
    light_v(l, pname, d);
}
void glLightf(GLenum l, GLenum pname, GLfloat p)
{
    double d[4] = {p, 0, 0, 0};
    light_v(l, pname, d);
}
void glLighti(GLenum l, GLenum pname, GLint p) { glLightf(l, pname, (GLfloat)p); }
void glGetLightfv(GLenum light, GLenum pname, GLfloat *p)
{
    fx_gl_light *l = light_of(light);
    if (!l)
        return;
    const fx16 *c = pname == GL_AMBIENT ? l->ambient : pname == GL_DIFFUSE ? l->diffuse
                    : pname == GL_SPECULAR ? l->specular : NULL;
    if (c)
        for (int k = 0; k < 4; k++)
            p[k] = (GLfloat)(c[k] / 65536.0);
    else if (pname == GL_POSITION)
        for (int k = 0; k < 4; k++)
            p[k] = (GLfloat)fx_glut_x2d(l->pos[k]);
    else
        fx_glut_set_error(GL_INVALID_ENUM);
}
static void light_model(GLenum pname, const double *p)
{
    if (recording()) {
        double a[5] = {(double)pname, p[0], pname == GL_LIGHT_MODEL_AMBIENT ? p[1] : 0,
                       pname == GL_LIGHT_MODEL_AMBIENT ? p[2] : 0,
                       pname == GL_LIGHT_MODEL_AMBIENT ? p[3] : 0};
        record(OP_LIGHTMODEL, 5, a);
        if (!fx_gl.list_exec)
            return;
    }
    switch (pname) {
    case GL_LIGHT_MODEL_AMBIENT:
        for (int k = 0; k < 4; k++)
            fx_gl.L.model_ambient[k] = fx_glut_d2q16(p[k]);
        break;
    case GL_LIGHT_MODEL_TWO_SIDE: fx_gl.L.two_side = p[0] != 0; break;
    case GL_LIGHT_MODEL_LOCAL_VIEWER: fx_gl.L.local_viewer = p[0] != 0; break;
    case GL_LIGHT_MODEL_COLOR_CONTROL:
        /* GL 1.2's separate specular colour only differs from the single
         * colour where a texture is applied between the two sums (or a
         * negative light colour meets a clamp); without texturing the
         * layer's single sum is the same picture */
        if (p[0] == GL_SEPARATE_SPECULAR_COLOR) {
            fx_gl.separate_specular = 1;
        } else if (p[0] == GL_SINGLE_COLOR) {
            fx_gl.separate_specular = 0;
        } else {
            fx_glut_set_error(GL_INVALID_ENUM);
        }
        break;
    default: fx_glut_set_error(GL_INVALID_ENUM);
    }
}
void glLightModelfv(GLenum pname, const GLfloat *p)
{
    double d[4] = {p[0], 0, 0, 0};
    if (pname == GL_LIGHT_MODEL_AMBIENT)
        for (int i = 1; i < 4; i++)
            d[i] = p[i];
    light_model(pname, d);
}
void glLightModeliv(GLenum pname, const GLint *p)
{
    double d[4] = {p[0], 0, 0, 0};
    if (pname == GL_LIGHT_MODEL_AMBIENT)
        for (int i = 0; i < 4; i++)
            d[i] = (2.0 * p[i] + 1) / 4294967295.0;
    light_model(pname, d);
}
void glLightModelf(GLenum pname, GLfloat p)
{
    double d[4] = {p, 0, 0, 0};
    light_model(pname, d);
}
void glLightModeli(GLenum pname, GLint p) { glLightModelf(pname, (GLfloat)p); }

static void material_v(GLenum face, GLenum pname, const double *p)
{
    if (recording()) {
        double a[6] = {(double)face, (double)pname, p[0], 0, 0, 0};
        if (pname != GL_SHININESS)
            a[3] = p[1], a[4] = p[2], a[5] = p[3];
        record(OP_MATERIAL, 6, a);
        if (!fx_gl.list_exec)
            return;
    }
    if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) {
        fx_glut_set_error(GL_INVALID_ENUM);
        return;
    }
    if (pname == GL_SHININESS && !(p[0] >= 0 && p[0] <= 128)) {
        fx_glut_set_error(GL_INVALID_VALUE); /* GL 1.x: [0, 128]; Mesa changes nothing */
        return;
    }
    for (int f = 0; f < 2; f++) {
        if ((f == 0 && face == GL_BACK) || (f == 1 && face == GL_FRONT))
            continue;
        /* while GL_COLOR_MATERIAL tracks the current colour into this face's
         * pname, glMaterial leaves it alone (Mesa's rule: the colour wins) */
        if (fx_gl.color_material && fx_gl.cm_face != (f == 0 ? GL_BACK : GL_FRONT) &&
            (pname == fx_gl.cm_mode ||
             (fx_gl.cm_mode == GL_AMBIENT_AND_DIFFUSE && (pname == GL_AMBIENT || pname == GL_DIFFUSE))))
            continue;
        fx_gl_material *m = &fx_gl.mat[f];
        switch (pname) {
        case GL_AMBIENT: for (int k = 0; k < 4; k++) m->ambient[k] = fx_glut_d2q16(p[k]); break;
        case GL_DIFFUSE: for (int k = 0; k < 4; k++) m->diffuse[k] = fx_glut_d2q16(p[k]); break;
        case GL_SPECULAR: for (int k = 0; k < 4; k++) m->specular[k] = fx_glut_d2q16(p[k]); break;
        case GL_EMISSION: for (int k = 0; k < 4; k++) m->emission[k] = fx_glut_d2q16(p[k]); break;
        case GL_AMBIENT_AND_DIFFUSE:
            for (int k = 0; k < 4; k++) {
                int tracked = fx_gl.color_material && fx_gl.cm_face != (f == 0 ? GL_BACK : GL_FRONT);
                if (!tracked || fx_gl.cm_mode == GL_DIFFUSE)
                    m->ambient[k] = fx_glut_d2q16(p[k]);
                if (!tracked || fx_gl.cm_mode == GL_AMBIENT)
                    m->diffuse[k] = fx_glut_d2q16(p[k]);
            }
            break;
        case GL_SHININESS: m->shininess = fx_glut_d2q16(p[0]); break;
        default: fx_glut_set_error(GL_INVALID_ENUM); return;
        }
    }
}
void glMaterialfv(GLenum face, GLenum pname, const GLfloat *p)
{
    double d[4] = {p[0], 0, 0, 0};
    if (pname != GL_SHININESS)
        for (int i = 1; i < 4; i++)
            d[i] = p[i];
    material_v(face, pname, d);
}
void glMaterialiv(GLenum face, GLenum pname, const GLint *p)
{
    double d[4] = {p[0], 0, 0, 0};
    if (pname != GL_SHININESS)
        for (int i = 0; i < 4; i++)
            d[i] = (2.0 * p[i] + 1) / 4294967295.0;
    material_v(face, pname, d);
}
void glMaterialf(GLenum face, GLenum pname, GLfloat p)
{
    double d[4] = {p, 0, 0, 0};
    material_v(face, pname, d);
}
void glMateriali(GLenum face, GLenum pname, GLint p) { glMaterialf(face, pname, (GLfloat)p); }
void glGetMaterialfv(GLenum face, GLenum pname, GLfloat *p)
{
    if (face != GL_FRONT && face != GL_BACK) {
        fx_glut_set_error(GL_INVALID_ENUM);
        return;
    }
    fx_gl_material *m = &fx_gl.mat[face == GL_BACK];
    const fx16 *c = pname == GL_AMBIENT ? m->ambient : pname == GL_DIFFUSE ? m->diffuse
                    : pname == GL_SPECULAR ? m->specular : pname == GL_EMISSION ? m->emission
                                                                               : NULL;
    if (c)
        for (int k = 0; k < 4; k++)
            p[k] = (GLfloat)(c[k] / 65536.0);
    else if (pname == GL_SHININESS)
        p[0] = (GLfloat)(m->shininess / 65536.0);
    else
        fx_glut_set_error(GL_INVALID_ENUM);
}
void glColorMaterial(GLenum face, GLenum mode)
{
    REC(OP_COLORMATERIAL, (double)face, (double)mode);
    if ((face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) ||
        (mode != GL_EMISSION && mode != GL_AMBIENT && mode != GL_DIFFUSE && mode != GL_SPECULAR &&
         mode != GL_AMBIENT_AND_DIFFUSE)) {
        fx_glut_set_error(GL_INVALID_ENUM);
        return;
    }
    fx_gl.cm_face = face, fx_gl.cm_mode = mode;
    apply_color_material();
}

/* ---- the pipeline ---- */
static void sync_target(void)
{
    fx_gl_target *t = &fx_gl.tgt;
    t->depth_test = (uint8_t)fx_gl.depth_test;
    t->depth_write = (uint8_t)fx_gl.depth_mask;
    t->depth_func = (uint8_t)(fx_gl.depth_func - GL_NEVER);
    t->blend = (uint8_t)(fx_gl.blend && !(fx_gl.bsrc == GL_ONE && fx_gl.bdst == GL_ZERO));
    t->bf_src = (uint8_t)blend_factor(fx_gl.bsrc);
    t->bf_dst = (uint8_t)blend_factor(fx_gl.bdst);
    t->stipple_on = (uint8_t)fx_gl.stipple;
    t->stipple_pattern = fx_gl.stipple_pattern;
    t->stipple_factor = fx_gl.stipple_factor;
    t->color_mask = fx_gl.color_mask == 0x10 ? 0 : fx_gl.color_mask;
    t->tex = NULL;
    if (fx_gl.tex2d && fx_gl.bound_tex < FXG_MAX_TEX && fx_gl.tex[fx_gl.bound_tex].used &&
        fx_gl.tex[fx_gl.bound_tex].mem) {
        static int told;
        if (fx_gl.lighting && fx_gl.separate_specular && !told) {
            told = 1; /* the one case where GL's separate specular colour shows */
            fx_glut_log("GL_SEPARATE_SPECULAR_COLOR: fixel's layer adds the specular term before "
                    "texturing, not after (ignored)");
        }
        t->tex = &fx_gl.tex[fx_gl.bound_tex].t;
        t->tex_env = fx_gl.tex_env == GL_REPLACE ? FX_GL_TEX_REPLACE
                     : fx_gl.tex_env == GL_DECAL ? FX_GL_TEX_DECAL
                     : fx_gl.tex_env == GL_BLEND ? FX_GL_TEX_BLEND
                     : fx_gl.tex_env == GL_ADD   ? FX_GL_TEX_ADD
                                               : FX_GL_TEX_MODULATE;
    }
}

static int32_t isize(float s)
{
    if (!(s >= 1.0f)) /* NaN too (glPointSize refuses it; a display list may not) */
        return 1;
    return s >= 256.0f ? 256 : (int32_t)lrintf(s);
}

/* A vertex through modelview, lighting and projection. */
/* Q32.32 -> Q16.16, rounded to nearest, saturating. */
static fx16 q32_to_q16(fx32 v)
{
    int64_t r = (v >= INT64_MAX - 0x8000 ? INT64_MAX : v + 0x8000) >> 16; /* v may be saturated */
    return r > INT32_MAX ? INT32_MAX : r < INT32_MIN ? INT32_MIN : (fx16)r;
}

/* The GL_TEXTURE matrix (glMatrixMode(GL_TEXTURE)): the vertex's (s, t, 0, 1)
 * through the top of the texture stack with the same fx_glm_apply as the
 * vertices, divided by q only for a projective matrix (q is exactly 1 for
 * translate, rotate and scale, so those keep one rounding). */
static void tex_matrix(fx_gl_cvert *o)
{
    fx_glv4 v = {(fx32)o->s * 65536, (fx32)o->t * 65536, 0, FX32_ONE};
    v = fx_glm_apply(&fx_gl.texm[fx_gl.tex_top], v);
    if (v.w > 0 && v.w != FX32_ONE)
        v.x = fx32_div(v.x, v.w), v.y = fx32_div(v.y, v.w);
    o->s = q32_to_q16(v.x), o->t = q32_to_q16(v.y);
}

static void process_vertex(fx32 x, fx32 y, fx32 z, fx32 w, fx_gl_cvert *o)
{
    ensure_mvp();
    fx_glv4 v = {x, y, z, w};
    o->p = fx_glm_apply(&fx_gl.mvp, v);
    if (fx_gl.lighting) {
        fx_glv4 e = fx_glm_apply(&fx_gl.mv[fx_gl.mv_top], v);
        fx32 n[3];
        for (int r = 0; r < 3; r++)
            n[r] = fx32_add(fx32_add(fx32_mul(fx_gl.nmat[r], fx_gl.normal[0]),
                                     fx32_mul(fx_gl.nmat[3 + r], fx_gl.normal[1])),
                            fx32_mul(fx_gl.nmat[6 + r], fx_gl.normal[2]));
        if (fx_gl.normalize || fx_gl.rescale)
            fx_glv3_normalize(n);
        fx32 p[4] = {e.x, e.y, e.z, e.w};
        /* directional lights' vectors once, not per vertex (same bits) */
        static fx_gl_shade_cache shade_cache;
        fx_gl_shade_cached(&fx_gl.L, &shade_cache, &fx_gl.mat[0], p, n, o->c);
        if (fx_gl.L.two_side) {
            /* GL 1.x: a back face is lit with the back material and the
             * normal reversed; which colour a polygon takes is decided by
             * its facing in window coordinates (raster_poly) */
            fx32 bn[3] = {fx32_neg(n[0]), fx32_neg(n[1]), fx32_neg(n[2])};
            fx_gl_shade_cached(&fx_gl.L, &shade_cache, &fx_gl.mat[1], p, bn, o->bc);
        } else {
            memcpy(o->bc, o->c, sizeof o->bc);
        }
    } else {
        for (int k = 0; k < 4; k++)
            o->c[k] = o->bc[k] = fx_gl.color[k];
    }
    o->s = fx_gl.texc[0], o->t = fx_gl.texc[1];
    if (fx_gl.tex2d)
        tex_matrix(o);
}

static int to_win(const fx_gl_cvert *c, fx_gl_wvert *w)
{
    if (fx_gl_to_window(&c->p, fx_gl.vp[0], fx_gl.vp[1], fx_gl.vp[2], fx_gl.vp[3], w) < 0)
        return -1;
    for (int k = 0; k < 4; k++)
        w->c[k] = c->c[k];
    w->s = c->s, w->t = c->t;
    return 0;
}

static void draw_point(const fx_gl_cvert *c)
{
    if (!fx_gl_point_visible(&c->p))
        return;
    /* beyond the guard band nothing can be seen and the arithmetic would overflow */
    fx32 gw = fx32_mul(fx_gl.guard, c->p.w);
    if (c->p.x > gw || c->p.x < -gw || c->p.y > gw || c->p.y < -gw)
        return;
    fx_gl_wvert w;
    if (to_win(c, &w) == 0)
        fx_gl_point(&fx_gl.tgt, &w, isize(fx_gl.point_size));
}

static void draw_line(const fx_gl_cvert *a, const fx_gl_cvert *b, const fx16 *provoking)
{
    fx_gl_cvert ca = *a, cb = *b;
    if (!fx_gl_clip_line(&ca, &cb, fx_gl.guard))
        return;
    fx_gl_wvert wa, wb;
    if (to_win(&ca, &wa) < 0 || to_win(&cb, &wb) < 0)
        return;
    fx_gl_line(&fx_gl.tgt, &wa, &wb, isize(fx_gl.line_width),
               fx_gl.shade == GL_FLAT ? provoking : NULL);
}

/* One polygon of n (3 or 4) clip-space vertices, convex, with GL edge
 * flags: edge i (v[i] -> v[i+1]) is drawn in line mode when bit i is set. */
static void raster_poly(fx_gl_wvert *w, int m, int n, const fx_gl_cvert *provoking, unsigned edges,
                        const fx_gl_cvert *const *src);
static void draw_poly(const fx_gl_cvert *const *v, int n, const fx_gl_cvert *provoking,
                      unsigned edges)
{
    fx_gl_cvert in[4], out[16], tmp[16];
    for (int i = 0; i < n; i++)
        in[i] = *v[i];
    int m = fx_gl_clip_poly(in, n, out, tmp, fx_gl.guard);
    if (m < 3)
        return;
    fx_gl_wvert w[16];
    for (int i = 0; i < m; i++)
        if (to_win(&out[i], &w[i]) < 0)
            return;
    const fx_gl_cvert *src[16];
    if (fx_gl.lighting && fx_gl.L.two_side)
        for (int i = 0; i < m; i++)
            src[i] = &out[i];
    raster_poly(w, m, n, provoking, edges, src);
}
/* Culling, polygon mode and rasterization of a polygon already in window
 * coordinates (m vertices; n: how many it had before clipping); src[i] is
 * the clip-space vertex of w[i], read for its back colour when two-sided
 * lighting is on. */
static void raster_poly(fx_gl_wvert *w, int m, int n, const fx_gl_cvert *provoking, unsigned edges,
                        const fx_gl_cvert *const *src)
{
    int64_t area = 0;
    for (int i = 1; i + 1 < m && area == 0; i++)
        area = fx_gl_area2(&w[0], &w[i], &w[i + 1]);
    if (area == 0)
        return;
    int front = (area > 0) == (fx_gl.front_face == GL_CCW);
    if (fx_gl.cull && (fx_gl.cull_face == GL_FRONT_AND_BACK || (front && fx_gl.cull_face == GL_FRONT) ||
                     (!front && fx_gl.cull_face == GL_BACK)))
        return;
    const fx16 *flat = fx_gl.shade == GL_FLAT ? provoking->c : NULL;
    if (fx_gl.lighting && fx_gl.L.two_side && !front) {
        /* the whole polygon, in every polygon mode, takes the back colours */
        for (int i = 0; i < m; i++)
            memcpy(w[i].c, src[i]->bc, sizeof w[i].c);
        if (flat)
            flat = provoking->bc;
    }
    GLenum mode = front ? fx_gl.poly_front : fx_gl.poly_back;
    if (mode == GL_FILL) {
        for (int i = 1; i + 1 < m; i++)
            fx_gl_triangle(&fx_gl.tgt, &w[0], &w[i], &w[i + 1], flat);
    } else if (mode == GL_LINE) {
        int clipped = m != n;
        for (int i = 0; i < m; i++)
            if (clipped || (edges >> i) & 1) {
                fx_gl.tgt.stipple_count = 0;
                fx_gl_line(&fx_gl.tgt, &w[i], &w[(i + 1) % m], isize(fx_gl.line_width), flat);
            }
    } else {
        for (int i = 0; i < m; i++)
            if (m != n || (edges >> i) & 1)
                fx_gl_point(&fx_gl.tgt, &w[i], isize(fx_gl.point_size));
    }
}

static void draw_tri(const fx_gl_cvert *a, const fx_gl_cvert *b, const fx_gl_cvert *c,
                     const fx_gl_cvert *prov, unsigned edges)
{
    const fx_gl_cvert *v[3] = {a, b, c};
    draw_poly(v, 3, prov, edges);
}

/* Assemble the buffered vertices; final = glEnd (else keep what a strip needs). */
static void assemble(int final)
{
    sync_target();
    fx_glut_vert *vb = fx_gl.vb;
    int n = fx_gl.nv, used = n;
    switch (fx_gl.prim) {
    case GL_POINTS:
        for (int i = 0; i < n; i++)
            draw_point(&vb[i].cv);
        break;
    case GL_LINES:
        for (int i = 0; i + 1 < n; i += 2) {
            fx_gl.tgt.stipple_count = 0;
            draw_line(&vb[i].cv, &vb[i + 1].cv, vb[i + 1].cv.c);
        }
        used = n & ~1;
        break;
    case GL_LINE_STRIP:
    case GL_LINE_LOOP:
        if (!final)
            return;
        fx_gl.tgt.stipple_count = 0;
        for (int i = 0; i + 1 < n; i++)
            draw_line(&vb[i].cv, &vb[i + 1].cv, vb[i + 1].cv.c);
        if (fx_gl.prim == GL_LINE_LOOP && n >= 2)
            draw_line(&vb[n - 1].cv, &vb[0].cv, vb[0].cv.c);
        break;
    case GL_TRIANGLES:
        for (int i = 0; i + 2 < n; i += 3)
            draw_tri(&vb[i].cv, &vb[i + 1].cv, &vb[i + 2].cv, &vb[i + 2].cv, 7);
        used = n - n % 3;
        break;
    case GL_QUADS:
        for (int i = 0; i + 3 < n; i += 4) {
            const fx_gl_cvert *v[4] = {&vb[i].cv, &vb[i + 1].cv, &vb[i + 2].cv, &vb[i + 3].cv};
            draw_poly(v, 4, &vb[i + 3].cv, 15);
        }
        used = n & ~3;
        break;
    case GL_TRIANGLE_STRIP:
    case GL_TRIANGLE_FAN:
    case GL_QUAD_STRIP:
    case GL_POLYGON:
        if (!final)
            return;
        if (fx_gl.prim == GL_TRIANGLE_STRIP) {
            for (int i = 0; i + 2 < n; i++) {
                if (i & 1)
                    draw_tri(&vb[i + 1].cv, &vb[i].cv, &vb[i + 2].cv, &vb[i + 2].cv, 7);
                else
                    draw_tri(&vb[i].cv, &vb[i + 1].cv, &vb[i + 2].cv, &vb[i + 2].cv, 7);
            }
        } else if (fx_gl.prim == GL_TRIANGLE_FAN) {
            for (int i = 1; i + 1 < n; i++)
                draw_tri(&vb[0].cv, &vb[i].cv, &vb[i + 1].cv, &vb[i + 1].cv, 7);
        } else if (fx_gl.prim == GL_QUAD_STRIP) {
            for (int i = 0; i + 3 < n; i += 2) {
                const fx_gl_cvert *v[4] = {&vb[i].cv, &vb[i + 1].cv, &vb[i + 3].cv, &vb[i + 2].cv};
                draw_poly(v, 4, &vb[i + 3].cv, 15);
            }
        } else if (n >= 3) {
            /* a polygon: a fan from vertex 0, flat colour from vertex 0; in line
             * mode only its own edges */
            const fx_gl_cvert *v0 = &vb[0].cv;
            GLenum pm = fx_gl.poly_front == fx_gl.poly_back ? fx_gl.poly_front : GL_FILL;
            if (pm == GL_FILL) {
                for (int i = 1; i + 1 < n; i++)
                    draw_tri(v0, &vb[i].cv, &vb[i + 1].cv, v0, 7);
            } else {
                for (int i = 1; i + 1 < n; i++) {
                    unsigned e = 2; /* middle edge v[i] -> v[i+1] */
                    if (i == 1)
                        e |= 1;
                    if (i + 2 == n)
                        e |= 4;
                    draw_tri(v0, &vb[i].cv, &vb[i + 1].cv, v0, e);
                }
            }
        }
        break;
    default:
        break;
    }
    if (used < n)
        memmove(vb, vb + used, (size_t)(n - used) * sizeof *vb);
    fx_gl.nv = n - used;
}

void glBegin(GLenum mode)
{
    REC(OP_BEGIN, (double)mode);
    if (fx_gl.in_begin) {
        fx_glut_set_error(GL_INVALID_OPERATION);
        return;
    }
    if (mode > GL_POLYGON) {
        fx_glut_set_error(GL_INVALID_ENUM);
        return;
    }
    fx_gl.in_begin = 1;
    fx_gl.prim = mode;
    fx_gl.nv = 0;
}

void glEnd(void)
{
    REC0(OP_END);
    if (!fx_gl.in_begin) {
        fx_glut_set_error(GL_INVALID_OPERATION);
        return;
    }
    assemble(1);
    fx_gl.in_begin = 0;
    fx_gl.nv = 0;
}

static void vertex(double x, double y, double z, double w)
{
    REC(OP_VERTEX, x, y, z, w);
    if (!fx_gl.in_begin) /* GL: undefined; Mesa ignores it */
        return;
    if (fx_gl.nv == fx_gl.capv) {
        int open = fx_gl.prim == GL_LINE_STRIP || fx_gl.prim == GL_LINE_LOOP || fx_gl.prim >= GL_TRIANGLE_STRIP;
        if (!open || fx_gl.prim == GL_QUADS) {
            assemble(0);
        }
        if (fx_gl.nv == fx_gl.capv) {
            int nc = fx_gl.capv ? fx_gl.capv * 2 : 4096;
            fx_glut_vert *nb = realloc(fx_gl.vb, (size_t)nc * sizeof *nb);
            if (!nb) {
                fx_glut_set_error(GL_OUT_OF_MEMORY);
                return;
            }
            fx_gl.vb = nb, fx_gl.capv = nc;
        }
    }
    process_vertex(fx_glut_d2x(x), fx_glut_d2x(y), fx_glut_d2x(z), fx_glut_d2x(w), &fx_gl.vb[fx_gl.nv].cv);
    fx_gl.nv++;
}

void glVertex2d(GLdouble x, GLdouble y) { vertex(x, y, 0, 1); }
void glVertex2f(GLfloat x, GLfloat y) { vertex(x, y, 0, 1); }
void glVertex2i(GLint x, GLint y) { vertex(x, y, 0, 1); }
void glVertex2s(GLshort x, GLshort y) { vertex(x, y, 0, 1); }
void glVertex3d(GLdouble x, GLdouble y, GLdouble z) { vertex(x, y, z, 1); }
void glVertex3f(GLfloat x, GLfloat y, GLfloat z) { vertex(x, y, z, 1); }
void glVertex3i(GLint x, GLint y, GLint z) { vertex(x, y, z, 1); }
void glVertex3s(GLshort x, GLshort y, GLshort z) { vertex(x, y, z, 1); }
void glVertex4d(GLdouble x, GLdouble y, GLdouble z, GLdouble w) { vertex(x, y, z, w); }
void glVertex4f(GLfloat x, GLfloat y, GLfloat z, GLfloat w) { vertex(x, y, z, w); }
void glVertex4i(GLint x, GLint y, GLint z, GLint w) { vertex(x, y, z, w); }
void glVertex4s(GLshort x, GLshort y, GLshort z, GLshort w) { vertex(x, y, z, w); }
void glVertex2dv(const GLdouble *v) { vertex(v[0], v[1], 0, 1); }
void glVertex2fv(const GLfloat *v) { vertex(v[0], v[1], 0, 1); }
void glVertex2iv(const GLint *v) { vertex(v[0], v[1], 0, 1); }
void glVertex2sv(const GLshort *v) { vertex(v[0], v[1], 0, 1); }
void glVertex3dv(const GLdouble *v) { vertex(v[0], v[1], v[2], 1); }
void glVertex3fv(const GLfloat *v) { vertex(v[0], v[1], v[2], 1); }
void glVertex3iv(const GLint *v) { vertex(v[0], v[1], v[2], 1); }
void glVertex3sv(const GLshort *v) { vertex(v[0], v[1], v[2], 1); }
void glVertex4dv(const GLdouble *v) { vertex(v[0], v[1], v[2], v[3]); }
void glVertex4fv(const GLfloat *v) { vertex(v[0], v[1], v[2], v[3]); }
void glVertex4iv(const GLint *v) { vertex(v[0], v[1], v[2], v[3]); }
void glVertex4sv(const GLshort *v) { vertex(v[0], v[1], v[2], v[3]); }

void glRectd(GLdouble x1, GLdouble y1, GLdouble x2, GLdouble y2)
{
    REC(OP_RECT, x1, y1, x2, y2);
    /* GL: the polygon (x1,y1) (x2,y1) (x2,y2) (x1,y2) */
    int rec = fx_gl.cur_list;
    fx_gl.cur_list = 0;
    glBegin(GL_POLYGON);
    glVertex2d(x1, y1);
    glVertex2d(x2, y1);
    glVertex2d(x2, y2);
    glVertex2d(x1, y2);
    glEnd();
    fx_gl.cur_list = (GLuint)rec;
}
void glRectf(GLfloat x1, GLfloat y1, GLfloat x2, GLfloat y2) { glRectd(x1, y1, x2, y2); }
void glRecti(GLint x1, GLint y1, GLint x2, GLint y2) { glRectd(x1, y1, x2, y2); }
void glRects(GLshort x1, GLshort y1, GLshort x2, GLshort y2) { glRectd(x1, y1, x2, y2); }
void glRectdv(const GLdouble *a, const GLdouble *b) { glRectd(a[0], a[1], b[0], b[1]); }
void glRectfv(const GLfloat *a, const GLfloat *b) { glRectd(a[0], a[1], b[0], b[1]); }
void glRectiv(const GLint *a, const GLint *b) { glRectd(a[0], a[1], b[0], b[1]); }
void glRectsv(const GLshort *a, const GLshort *b) { glRectd(a[0], a[1], b[0], b[1]); }

/* An indexed mesh as glDrawElements(GL_TRIANGLES) draws it: each vertex
 * transformed and lit once, then the triangles assembled from the results
 * (the same bits as the immediate-mode path below, which display lists and
 * glBegin nesting still take). */
static int draw_indexed(const int32_t *pos, const int32_t *nrm, int32_t nverts, const uint32_t *tri,
                        int32_t ntris)
{
    static fx_gl_cvert *cv;
    static int32_t cap;
    if (recording() || fx_gl.in_begin || fx_gl.poly_front != GL_FILL || fx_gl.poly_back != GL_FILL)
        return -1;
    if (nverts > cap) {
        fx_gl_cvert *n = realloc(cv, (size_t)nverts * sizeof *n);
        if (!n)
            return -1;
        cv = n, cap = nverts;
    }
    sync_target();
    for (int32_t k = 0; k < nverts; k++) {
        if (nrm)
            for (int i = 0; i < 3; i++)
                fx_gl.normal[i] = (fx32)nrm[3 * k + i] * 65536;
        process_vertex((fx32)pos[3 * k] * 65536, (fx32)pos[3 * k + 1] * 65536,
                       (fx32)pos[3 * k + 2] * 65536, FX32_ONE, &cv[k]);
    }
    /* window coordinates once per vertex that needs no clipping (inside the
     * guard band and the depth range): its triangles skip the clipper */
    static fx_gl_wvert *wv;
    static unsigned char *inside;
    static int32_t capw;
    if (nverts > capw) {
        fx_gl_wvert *nw = realloc(wv, (size_t)nverts * sizeof *nw);
        unsigned char *ni = nw ? realloc(inside, (size_t)nverts) : NULL;
        if (!nw || !ni) {
            if (nw)
                wv = nw;
            return -1;
        }
        wv = nw, inside = ni, capw = nverts;
    }
    for (int32_t k = 0; k < nverts; k++) {
        const fx_glv4 *p = &cv[k].p;
        fx32 gw = fx32_mul(fx_gl.guard, p->w);
        inside[k] = p->w > 0 && p->x <= gw && p->x >= -gw && p->y <= gw && p->y >= -gw &&
                    p->z <= p->w && p->z >= -p->w && to_win(&cv[k], &wv[k]) == 0;
    }
    for (int32_t i = 0; i < ntris; i++) {
        uint32_t a = tri[3 * i], b = tri[3 * i + 1], c = tri[3 * i + 2];
        if (inside[a] && inside[b] && inside[c]) {
            fx_gl_wvert w[3] = {wv[a], wv[b], wv[c]};
            const fx_gl_cvert *src[3] = {&cv[a], &cv[b], &cv[c]};
            raster_poly(w, 3, 3, &cv[c], 7, src);
        } else {
            draw_tri(&cv[a], &cv[b], &cv[c], &cv[c], 7);
        }
    }
    return 0;
}

void fx_glut_draw_tris_q16(const int32_t *pos, const int32_t *nrm, const uint32_t *tri, int32_t ntris,
                       int wire)
{
    if (!wire) {
        uint32_t maxv = 0;
        for (int32_t i = 0; i < ntris * 3; i++)
            if (tri[i] > maxv)
                maxv = tri[i];
        if (ntris > 0 && draw_indexed(pos, nrm, (int32_t)maxv + 1, tri, ntris) == 0)
            return;
    }
    GLenum save_f = fx_gl.poly_front, save_b = fx_gl.poly_back;
    if (wire)
        fx_gl.poly_front = fx_gl.poly_back = GL_LINE;
    glBegin(GL_TRIANGLES);
    for (int32_t i = 0; i < ntris * 3; i++) {
        uint32_t k = tri[i];
        if (nrm)
            glNormal3d(nrm[3 * k] / 65536.0, nrm[3 * k + 1] / 65536.0, nrm[3 * k + 2] / 65536.0);
        glVertex3d(pos[3 * k] / 65536.0, pos[3 * k + 1] / 65536.0, pos[3 * k + 2] / 65536.0);
    }
    glEnd();
    fx_gl.poly_front = save_f, fx_gl.poly_back = save_b;
}

/* ---- raster position, bitmaps, pixels ---- */
static void raster_pos(double x, double y, double z, double w)
{
    REC(OP_RASTERPOS, x, y, z, w);
    fx_gl_cvert c;
    process_vertex(fx_glut_d2x(x), fx_glut_d2x(y), fx_glut_d2x(z), fx_glut_d2x(w), &c);
    fx_gl.raster_valid = fx_gl_point_visible(&c.p) && c.p.x <= c.p.w && c.p.x >= -c.p.w &&
                       c.p.y <= c.p.w && c.p.y >= -c.p.w;
    fx_gl_wvert wv;
    if (fx_gl.raster_valid && to_win(&c, &wv) == 0) {
        fx_gl.rx = wv.x, fx_gl.ry = wv.y;
        for (int k = 0; k < 4; k++)
            fx_gl.raster_color[k] = c.c[k];
    } else {
        fx_gl.raster_valid = 0;
    }
}
void glRasterPos2d(GLdouble x, GLdouble y) { raster_pos(x, y, 0, 1); }
void glRasterPos2f(GLfloat x, GLfloat y) { raster_pos(x, y, 0, 1); }
void glRasterPos2i(GLint x, GLint y) { raster_pos(x, y, 0, 1); }
void glRasterPos2s(GLshort x, GLshort y) { raster_pos(x, y, 0, 1); }
void glRasterPos3d(GLdouble x, GLdouble y, GLdouble z) { raster_pos(x, y, z, 1); }
void glRasterPos3f(GLfloat x, GLfloat y, GLfloat z) { raster_pos(x, y, z, 1); }
void glRasterPos3i(GLint x, GLint y, GLint z) { raster_pos(x, y, z, 1); }
void glRasterPos4f(GLfloat x, GLfloat y, GLfloat z, GLfloat w) { raster_pos(x, y, z, w); }
void glRasterPos2fv(const GLfloat *v) { raster_pos(v[0], v[1], 0, 1); }
void glRasterPos2iv(const GLint *v) { raster_pos(v[0], v[1], 0, 1); }
void glRasterPos2dv(const GLdouble *v) { raster_pos(v[0], v[1], 0, 1); }
void glRasterPos3fv(const GLfloat *v) { raster_pos(v[0], v[1], v[2], 1); }
/* the rest of the 24 glRasterPos forms GL 1.1 has (Mesa's gl.h declares all) */
void glRasterPos2sv(const GLshort *v) { raster_pos(v[0], v[1], 0, 1); }
void glRasterPos3s(GLshort x, GLshort y, GLshort z) { raster_pos(x, y, z, 1); }
void glRasterPos3sv(const GLshort *v) { raster_pos(v[0], v[1], v[2], 1); }
void glRasterPos3iv(const GLint *v) { raster_pos(v[0], v[1], v[2], 1); }
void glRasterPos3dv(const GLdouble *v) { raster_pos(v[0], v[1], v[2], 1); }
void glRasterPos4s(GLshort x, GLshort y, GLshort z, GLshort w) { raster_pos(x, y, z, w); }
void glRasterPos4sv(const GLshort *v) { raster_pos(v[0], v[1], v[2], v[3]); }
void glRasterPos4i(GLint x, GLint y, GLint z, GLint w) { raster_pos(x, y, z, w); }
void glRasterPos4iv(const GLint *v) { raster_pos(v[0], v[1], v[2], v[3]); }
void glRasterPos4fv(const GLfloat *v) { raster_pos(v[0], v[1], v[2], v[3]); }
void glRasterPos4d(GLdouble x, GLdouble y, GLdouble z, GLdouble w) { raster_pos(x, y, z, w); }
void glRasterPos4dv(const GLdouble *v) { raster_pos(v[0], v[1], v[2], v[3]); }
static void window_pos(double x, double y)
{
    REC(OP_WINDOWPOS, x, y);
    fx_gl.rx = fx_glut_d2win(x), fx_gl.ry = fx_glut_d2win(y);
    fx_gl.raster_valid = 1;
    for (int k = 0; k < 4; k++)
        fx_gl.raster_color[k] = fx_gl.color[k];
}
void glWindowPos2i(GLint x, GLint y) { window_pos(x, y); }
void glWindowPos2f(GLfloat x, GLfloat y) { window_pos(x, y); }

/* Bitmap at the raster position: rows given top first; window rows go up. */
static void bitmap_draw(int32_t w, int32_t h, int32_t xorig, int32_t yorig, int32_t xmove,
                        const uint8_t *rows, int32_t row_bytes, int32_t scale)
{
    if (!fx_gl.raster_valid)
        return;
    /* GL: the bitmap's lower-left corner is at floor(raster - orig) */
    int64_t x0 = ((fx_gl.rx - 128) >> 8) - xorig, y0 = ((fx_gl.ry - 128) >> 8) - yorig;
    /* llvmpipe puts the raster position's pixel at floor(x) for integer-centred text */
    x0 = (fx_gl.rx >> 8) - xorig;
    y0 = (fx_gl.ry >> 8) - yorig;
    fx_color c = 0xFF000000u | ((fx_color)lvl(fx_gl.raster_color[0]) << 16) |
                 ((fx_color)lvl(fx_gl.raster_color[1]) << 8) | (fx_color)lvl(fx_gl.raster_color[2]);
    fx_rect clip = {0, 0, fx_gl.w, fx_gl.h};
    if (fx_gl.scissor_on)
        clip = fx_rect_intersect(clip, fx_glut_scissor_rect());
    uint32_t native = fx_pack(fx_gl.fb.surf.format, c);
    for (int32_t r = 0; r < h; r++)
        for (int32_t col = 0; col < w; col++) {
            if (!((rows[r * row_bytes + col / 8] >> (7 - col % 8)) & 1))
                continue;
            for (int32_t sy = 0; sy < scale; sy++)
                for (int32_t sx = 0; sx < scale; sx++) {
                    int64_t X = x0 + (int64_t)col * scale + sx;
                    int64_t Y = y0 + (int64_t)(h - 1 - r) * scale + sy;
                    if (X < clip.x0 || X >= clip.x1 || Y < clip.y0 || Y >= clip.y1)
                        continue;
                    fx_surface_put_native(&fx_gl.fb.surf, (int32_t)X, fx_gl.h - 1 - (int32_t)Y, native);
                }
        }
    fx_gl.rx = clamp_win(fx_gl.rx + (int64_t)xmove * 256);
}

/* GLUT's bitmap characters: inside glNewList they are compiled, as
 * freeglut's glBitmap calls are. */
void fx_glut_bitmap(int32_t w, int32_t h, int32_t xorig, int32_t yorig, int32_t xmove,
                    const uint8_t *rows, int32_t row_bytes, int32_t scale)
{
    if (recording()) {
        double a[7] = {w, h, xorig, yorig, xmove, row_bytes, scale};
        size_t nb = w > 0 && h > 0 && row_bytes > 0 ? (size_t)h * (size_t)row_bytes : 0;
        record_blob(OP_BITMAPCHAR, 7, a, rows, nb);
        if (!fx_gl.list_exec)
            return;
    }
    bitmap_draw(w, h, xorig, yorig, xmove, rows, row_bytes, scale);
}
static void bitmapchar_rec(const double *a)
{
    int32_t w = (int32_t)a[0], h = (int32_t)a[1], rb = (int32_t)a[5];
    bitmap_draw(w, h, (int32_t)a[2], (int32_t)a[3], (int32_t)a[4], w > 0 && h > 0 && rb > 0 ? (const uint8_t *)(a + 7) : NULL,
                rb, (int32_t)a[6]);
}

/* rows: top row first, rb bytes each (NULL: nothing drawn, the raster
 * position still moves) */
static void bitmap_exec(int32_t w, int32_t h, int32_t xo, int32_t yo, double xmove, double ymove,
                        const uint8_t *rows, int32_t rb)
{
    if (rows)
        bitmap_draw(w, h, xo, yo, 0, rows, rb, 1);
    /* the raster position moves by any float: the sum saturates at the
     * rasterizers' range (+-2^21 pixels) instead of overflowing */
    if (fx_gl.raster_valid) {
        fx_gl.rx = clamp_win(fx_gl.rx + fx_glut_d2win(xmove));
        fx_gl.ry = clamp_win(fx_gl.ry + fx_glut_d2win(ymove));
    }
}
static void bitmap_rec(const double *a)
{
    int32_t w = (int32_t)a[0], h = (int32_t)a[1], rb = (int32_t)a[6];
    bitmap_exec(w, h, (int32_t)a[2], (int32_t)a[3], a[4], a[5], rb > 0 ? (const uint8_t *)(a + 7) : NULL, rb);
}

void glBitmap(GLsizei w, GLsizei h, GLfloat xorig, GLfloat yorig, GLfloat xmove, GLfloat ymove,
              const GLubyte *bitmap)
{
    if (w < 0 || h < 0) {
        fx_glut_set_error(GL_INVALID_VALUE);
        return;
    }
    /* GL bitmaps are stored bottom row first, rows aligned to the unpack
     * alignment; (w + 7) / 8 in 64 bits: w + 7 passes INT32_MAX */
    int64_t al = fx_gl.unpack_align, rb = ((int64_t)w + 7) / 8;
    rb = (rb + al - 1) / al * al;
    /* the origin clamped to the raster range: beyond it the bitmap is off
     * the surface either way */
    int32_t xo = fx_glut_d2i(xorig), yo = fx_glut_d2i(yorig);
    xo = xo > FXG_VIEWPORT_BOUND * 4 ? FXG_VIEWPORT_BOUND * 4 : xo < -FXG_VIEWPORT_BOUND * 4 ? -FXG_VIEWPORT_BOUND * 4 : xo;
    yo = yo > FXG_VIEWPORT_BOUND * 4 ? FXG_VIEWPORT_BOUND * 4 : yo < -FXG_VIEWPORT_BOUND * 4 ? -FXG_VIEWPORT_BOUND * 4 : yo;
    uint8_t *flip = NULL;
    if (bitmap && w > 0 && h > 0 && rb <= INT32_MAX && (uint64_t)rb * (uint64_t)h <= SIZE_MAX / 2) {
        flip = malloc((size_t)rb * (size_t)h);
        if (!flip) {
            fx_glut_set_error(GL_OUT_OF_MEMORY);
            return;
        }
        for (int32_t r = 0; r < h; r++)
            memcpy(flip + (size_t)r * (size_t)rb, bitmap + (size_t)(h - 1 - r) * (size_t)rb, (size_t)rb);
    }
    /* compiled with its rows unpacked now, as GL says: the caller's array
     * may change before the list runs */
    if (recording()) {
        double a[7] = {w, h, xo, yo, xmove, ymove, flip ? (double)rb : 0};
        record_blob(OP_BITMAP, 7, a, flip, flip ? (size_t)rb * (size_t)h : 0);
        if (!fx_gl.list_exec) {
            free(flip);
            return;
        }
    }
    bitmap_exec(w, h, xo, yo, xmove, ymove, flip, (int32_t)rb);
    free(flip);
}

void glPixelStorei(GLenum pname, GLint param)
{
    if (pname == GL_UNPACK_ALIGNMENT && (param == 1 || param == 2 || param == 4 || param == 8))
        fx_gl.unpack_align = param;
    else if (pname == GL_PACK_ALIGNMENT && (param == 1 || param == 2 || param == 4 || param == 8))
        fx_gl.pack_align = param;
    else if (pname == GL_UNPACK_ALIGNMENT || pname == GL_PACK_ALIGNMENT)
        fx_glut_set_error(GL_INVALID_VALUE);
}
void glPixelStoref(GLenum pname, GLfloat param) { glPixelStorei(pname, fx_glut_d2i(param)); }
void glPixelZoom(GLfloat xf, GLfloat yf)
{
    REC(OP_PIXELZOOM, xf, yf);
    fx_gl.zoom_x = xf, fx_gl.zoom_y = yf;
}

static int comps(GLenum format)
{
    switch (format) {
    case GL_RGB: case GL_BGR: return 3;
    case GL_RGBA: case GL_BGRA: return 4;
    case GL_RED: case GL_GREEN: case GL_BLUE: case GL_ALPHA: case GL_LUMINANCE: return 1;
    case GL_LUMINANCE_ALPHA: return 2;
    default: return 0;
    }
}

void glReadPixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum format, GLenum type,
                  GLvoid *pixels)
{
    int nc = comps(format);
    if (w < 0 || h < 0) {
        fx_glut_set_error(GL_INVALID_VALUE);
        return;
    }
    /* x + c and y + r are taken in 64 bits below: x near INT32_MAX plus
     * the width overflows an int */
    if (format == GL_DEPTH_COMPONENT && (type == GL_FLOAT || type == GL_UNSIGNED_INT)) {
        size_t stride = (size_t)w * 4;
        for (GLsizei r = 0; r < h; r++)
            for (GLsizei c = 0; c < w; c++) {
                int64_t X = (int64_t)x + c, Y = (int64_t)y + r;
                uint32_t d = 0xFFFFFF;
                if (X >= 0 && Y >= 0 && X < fx_gl.w && Y < fx_gl.h)
                    d = fx_gl.depth[(size_t)(fx_gl.h - 1 - Y) * (size_t)fx_gl.w + (size_t)X];
                uint8_t *p = (uint8_t *)pixels + (size_t)r * stride + (size_t)c * 4;
                if (type == GL_FLOAT) {
                    float f = (float)(d / 16777215.0);
                    memcpy(p, &f, 4);
                } else {
                    uint32_t u = (d << 8) | (d >> 16);
                    memcpy(p, &u, 4);
                }
            }
        return;
    }
    if (!nc || (type != GL_UNSIGNED_BYTE && type != GL_FLOAT)) {
        fx_glut_unimplemented("glReadPixels (this format/type)", GL_INVALID_ENUM);
        return;
    }
    int bpc = type == GL_FLOAT ? 4 : 1;
    size_t rowb = (size_t)w * nc * bpc;
    size_t al = (size_t)fx_gl.pack_align;
    rowb = (rowb + al - 1) / al * al;
    for (GLsizei r = 0; r < h; r++)
        for (GLsizei c = 0; c < w; c++) {
            int64_t X = (int64_t)x + c, Y = (int64_t)y + r;
            fx_color px = 0;
            if (X >= 0 && Y >= 0 && X < fx_gl.w && Y < fx_gl.h)
                px = fx_surface_get(&fx_gl.fb.surf, (int32_t)X, fx_gl.h - 1 - (int32_t)Y);
            int ch[4] = {(int)(px >> 16) & 255, (int)(px >> 8) & 255, (int)px & 255, 255};
            int out[4], k = 0;
            switch (format) {
            case GL_RGB: out[0] = ch[0], out[1] = ch[1], out[2] = ch[2]; break;
            case GL_BGR: out[0] = ch[2], out[1] = ch[1], out[2] = ch[0]; break;
            case GL_RGBA: out[0] = ch[0], out[1] = ch[1], out[2] = ch[2], out[3] = 255; break;
            case GL_BGRA: out[0] = ch[2], out[1] = ch[1], out[2] = ch[0], out[3] = 255; break;
            case GL_RED: out[0] = ch[0]; break;
            case GL_GREEN: out[0] = ch[1]; break;
            case GL_BLUE: out[0] = ch[2]; break;
            case GL_ALPHA: out[0] = 255; break;
            case GL_LUMINANCE: out[0] = ch[0] + ch[1] + ch[2] > 765 ? 255 : (ch[0] + ch[1] + ch[2]) / 3; break;
            default: out[0] = ch[0], out[1] = 255; break;
            }
            uint8_t *p = (uint8_t *)pixels + (size_t)r * rowb + (size_t)c * nc * bpc;
            for (k = 0; k < nc; k++) {
                if (bpc == 1)
                    p[k] = (uint8_t)out[k];
                else {
                    float f = out[k] / 255.0f;
                    memcpy(p + 4 * k, &f, 4);
                }
            }
        }
}

void glDrawPixels(GLsizei w, GLsizei h, GLenum format, GLenum type, const GLvoid *pixels)
{
    int nc = comps(format);
    if (!nc || (type != GL_UNSIGNED_BYTE && type != GL_FLOAT)) {
        fx_glut_unimplemented("glDrawPixels (this format/type)", GL_INVALID_ENUM);
        return;
    }
    if (w < 0 || h < 0) {
        fx_glut_set_error(GL_INVALID_VALUE);
        return;
    }
    int bpc = type == GL_FLOAT ? 4 : 1;
    size_t rowb = (size_t)w * nc * bpc, al = (size_t)fx_gl.unpack_align;
    rowb = (rowb + al - 1) / al * al;
    /* compiled with its pixels copied now (GL unpacks at compile time);
     * the rows keep the alignment they were given under, recorded with
     * them. record_blob refuses a size past its pool bound. */
    if (recording()) {
        size_t nb = pixels && w > 0 && h > 0 && rowb <= (SIZE_MAX >> 4) / (size_t)h ? rowb * (size_t)h : 0;
        if (pixels && w > 0 && h > 0 && !nb) {
            fx_glut_set_error(GL_OUT_OF_MEMORY);
            return;
        }
        double a[6] = {w, h, format, type, (double)al, nb != 0};
        record_blob(OP_DRAWPIXELS, 6, a, pixels, nb);
        if (!fx_gl.list_exec)
            return;
    }
    if (!fx_gl.raster_valid || !pixels)
        return;
    int64_t x0 = fx_gl.rx >> 8, y0 = fx_gl.ry >> 8;
    /* Zoom factors are any float (glPixelZoom stores them as given): here
     * they are whole pixels in [1, 2^24] (NaN as 1), and each source pixel
     * fills only the part of its zx-by-zy block inside the clip rectangle,
     * so the work is the source size plus at most the surface, whatever
     * the zoom (glPixelZoom(1e5, 1e5) was a 10^10-iteration loop). */
    int64_t zx = fx_glut_d2i(fx_gl.zoom_x), zy = fx_glut_d2i(fx_gl.zoom_y);
    zx = zx < 1 ? 1 : zx > (1 << 24) ? (1 << 24) : zx;
    zy = zy < 1 ? 1 : zy > (1 << 24) ? (1 << 24) : zy;
    sync_target();
    fx_rect cl = fx_gl.tgt.clip;
    for (GLsizei r = 0; r < h; r++) {
        int64_t by0 = y0 + (int64_t)r * zy, by1 = by0 + zy;
        if (by1 <= cl.y0 || by0 >= cl.y1)
            continue; /* the row's blocks are all outside */
        for (GLsizei c = 0; c < w; c++) {
            int64_t bx0 = x0 + (int64_t)c * zx, bx1 = bx0 + zx;
            if (bx1 <= cl.x0 || bx0 >= cl.x1)
                continue;
            const uint8_t *p = (const uint8_t *)pixels + (size_t)r * rowb + (size_t)c * nc * bpc;
            int v[4];
            for (int k = 0; k < nc; k++) {
                if (bpc == 1)
                    v[k] = p[k];
                else {
                    float f;
                    memcpy(&f, p + 4 * k, 4);
                    v[k] = f <= 0 ? 0 : f >= 1 ? 255 : (int)lrintf(f * 255.0f);
                }
            }
            int rgba[4] = {0, 0, 0, 255};
            switch (format) {
            case GL_RGB: rgba[0] = v[0], rgba[1] = v[1], rgba[2] = v[2]; break;
            case GL_BGR: rgba[0] = v[2], rgba[1] = v[1], rgba[2] = v[0]; break;
            case GL_RGBA: rgba[0] = v[0], rgba[1] = v[1], rgba[2] = v[2], rgba[3] = v[3]; break;
            case GL_BGRA: rgba[0] = v[2], rgba[1] = v[1], rgba[2] = v[0], rgba[3] = v[3]; break;
            case GL_LUMINANCE: rgba[0] = rgba[1] = rgba[2] = v[0]; break;
            case GL_LUMINANCE_ALPHA: rgba[0] = rgba[1] = rgba[2] = v[0], rgba[3] = v[1]; break;
            case GL_RED: rgba[0] = v[0]; break;
            case GL_GREEN: rgba[1] = v[0]; break;
            case GL_BLUE: rgba[2] = v[0]; break;
            default: rgba[3] = v[0]; break;
            }
            fx_color col = ((fx_color)rgba[3] << 24) | ((fx_color)rgba[0] << 16) |
                           ((fx_color)rgba[1] << 8) | (fx_color)rgba[2];
            int64_t X0 = bx0 < cl.x0 ? cl.x0 : bx0, X1 = bx1 > cl.x1 ? cl.x1 : bx1;
            int64_t Y0 = by0 < cl.y0 ? cl.y0 : by0, Y1 = by1 > cl.y1 ? cl.y1 : by1;
            uint32_t native = fx_pack(fx_gl.fb.surf.format, col);
            for (int64_t Y = Y0; Y < Y1; Y++)
                for (int64_t X = X0; X < X1; X++)
                    fx_surface_put_native(&fx_gl.fb.surf, (int32_t)X, fx_gl.h - 1 - (int32_t)Y, native);
        }
    }
}
static void draw_pixels_rec(const double *a)
{
    int al = fx_gl.unpack_align;
    fx_gl.unpack_align = (int)a[4];
    glDrawPixels((GLsizei)a[0], (GLsizei)a[1], (GLenum)a[2], (GLenum)a[3], a[5] != 0 ? a + 6 : NULL);
    fx_gl.unpack_align = al;
}

/* ---- textures ---- */
void glGenTextures(GLsizei n, GLuint *t)
{
    for (GLsizei i = 0; i < n; i++) {
        t[i] = 0;
        for (GLuint k = 1; k < FXG_MAX_TEX; k++)
            if (!fx_gl.tex[k].used) {
                fx_gl.tex[k].used = 1;
                fx_gl.tex[k].min_filter = GL_NEAREST_MIPMAP_LINEAR;
                fx_gl.tex[k].mag_filter = GL_LINEAR;
                fx_gl.tex[k].wrap_s = fx_gl.tex[k].wrap_t = GL_REPEAT;
                t[i] = k;
                break;
            }
        if (!t[i])
            fx_glut_set_error(GL_OUT_OF_MEMORY);
    }
}
void glDeleteTextures(GLsizei n, const GLuint *t)
{
    for (GLsizei i = 0; i < n; i++)
        if (t[i] && t[i] < FXG_MAX_TEX) {
            free(fx_gl.tex[t[i]].mem);
            memset(&fx_gl.tex[t[i]], 0, sizeof fx_gl.tex[t[i]]);
            if (fx_gl.bound_tex == t[i])
                fx_gl.bound_tex = 0;
        }
}
void glBindTexture(GLenum target, GLuint t)
{
    REC(OP_BINDTEX, (double)target, (double)t);
    if (target != GL_TEXTURE_2D) {
        fx_glut_unimplemented("glBindTexture (other than GL_TEXTURE_2D)", GL_INVALID_ENUM);
        return;
    }
    if (t >= FXG_MAX_TEX) {
        fx_glut_set_error(GL_INVALID_VALUE);
        return;
    }
    if (t && !fx_gl.tex[t].used) {
        fx_gl.tex[t].used = 1;
        fx_gl.tex[t].min_filter = GL_NEAREST_MIPMAP_LINEAR;
        fx_gl.tex[t].mag_filter = GL_LINEAR;
        fx_gl.tex[t].wrap_s = fx_gl.tex[t].wrap_t = GL_REPEAT;
    }
    fx_gl.bound_tex = t;
}
GLboolean glIsTexture(GLuint t) { return t && t < FXG_MAX_TEX && fx_gl.tex[t].used; }
static void tex_params(fx_glut_tex *tx)
{
    tx->t.linear = tx->mag_filter == GL_LINEAR;
    tx->t.clamp_s = tx->wrap_s != GL_REPEAT;
    tx->t.clamp_t = tx->wrap_t != GL_REPEAT;
}
void glTexImage2D(GLenum target, GLint level, GLint internalformat, GLsizei w, GLsizei h,
                  GLint border, GLenum format, GLenum type, const GLvoid *pixels)
{
    (void)internalformat, (void)border;
    if (target != GL_TEXTURE_2D || level > 0) {
        if (level > 0)
            return; /* mipmap levels: only level 0 is used */
        fx_glut_unimplemented("glTexImage2D (this target)", GL_INVALID_ENUM);
        return;
    }
    int nc = comps(format);
    if (!nc || type != GL_UNSIGNED_BYTE) {
        fx_glut_unimplemented("glTexImage2D (format/type other than bytes)", GL_INVALID_ENUM);
        return;
    }
    if (w <= 0 || h <= 0 || w > 4096 || h > 4096) {
        fx_glut_set_error(GL_INVALID_VALUE);
        return;
    }
    fx_glut_tex *tx = &fx_gl.tex[fx_gl.bound_tex];
    if (!fx_gl.tex[fx_gl.bound_tex].used) {
        tx->used = 1;
        tx->min_filter = GL_NEAREST_MIPMAP_LINEAR, tx->mag_filter = GL_LINEAR;
        tx->wrap_s = tx->wrap_t = GL_REPEAT;
    }
    uint8_t *mem = malloc((size_t)w * h * 4);
    if (!mem) {
        fx_glut_set_error(GL_OUT_OF_MEMORY);
        return;
    }
    size_t rowb = (size_t)w * nc, al = (size_t)fx_gl.unpack_align;
    rowb = (rowb + al - 1) / al * al;
    for (GLsizei r = 0; r < h; r++)
        for (GLsizei c = 0; c < w; c++) {
            uint8_t *d = mem + ((size_t)r * w + c) * 4;
            if (!pixels) {
                d[0] = d[1] = d[2] = d[3] = 255;
                continue;
            }
            const uint8_t *p = (const uint8_t *)pixels + r * rowb + (size_t)c * nc;
            switch (format) {
            case GL_RGB: d[0] = p[0], d[1] = p[1], d[2] = p[2], d[3] = 255; break;
            case GL_BGR: d[0] = p[2], d[1] = p[1], d[2] = p[0], d[3] = 255; break;
            case GL_RGBA: memcpy(d, p, 4); break;
            case GL_BGRA: d[0] = p[2], d[1] = p[1], d[2] = p[0], d[3] = p[3]; break;
            case GL_LUMINANCE: d[0] = d[1] = d[2] = p[0], d[3] = 255; break;
            case GL_LUMINANCE_ALPHA: d[0] = d[1] = d[2] = p[0], d[3] = p[1]; break;
            case GL_ALPHA: d[0] = d[1] = d[2] = 255, d[3] = p[0]; break;
            default: d[0] = d[1] = d[2] = p[0], d[3] = 255; break;
            }
        }
    free(tx->mem);
    tx->mem = mem;
    tx->t.rgba = mem;
    tx->t.w = w, tx->t.h = h;
    tex_params(tx);
}
void glTexParameteri(GLenum target, GLenum pname, GLint param)
{
    REC(OP_TEXPARAM, (double)target, (double)pname, param);
    if (target != GL_TEXTURE_2D) {
        fx_glut_set_error(GL_INVALID_ENUM);
        return;
    }
    fx_glut_tex *tx = &fx_gl.tex[fx_gl.bound_tex];
    switch (pname) {
    case GL_TEXTURE_MIN_FILTER: tx->min_filter = (GLenum)param; break;
    case GL_TEXTURE_MAG_FILTER: tx->mag_filter = (GLenum)param; break;
    case GL_TEXTURE_WRAP_S: tx->wrap_s = (GLenum)param; break;
    case GL_TEXTURE_WRAP_T: tx->wrap_t = (GLenum)param; break;
    default: break;
    }
    tex_params(tx);
}
void glTexParameterf(GLenum target, GLenum pname, GLfloat param) { glTexParameteri(target, pname, fx_glut_d2i(param)); }
void glTexParameteriv(GLenum target, GLenum pname, const GLint *p) { glTexParameteri(target, pname, p[0]); }
void glTexParameterfv(GLenum target, GLenum pname, const GLfloat *p)
{
    if (pname != GL_TEXTURE_BORDER_COLOR)
        glTexParameteri(target, pname, fx_glut_d2i(p[0]));
}
void glTexEnvi(GLenum target, GLenum pname, GLint param)
{
    REC(OP_TEXENV, (double)target, (double)pname, param);
    if (target == GL_TEXTURE_ENV && pname == GL_TEXTURE_ENV_MODE)
        fx_gl.tex_env = (GLenum)param;
}
void glTexEnvf(GLenum target, GLenum pname, GLfloat param) { glTexEnvi(target, pname, fx_glut_d2i(param)); }
void glTexEnviv(GLenum target, GLenum pname, const GLint *p) { glTexEnvi(target, pname, p[0]); }
static void tex_env_color(const double *p)
{
    if (recording()) {
        record(OP_TEXENVCOLOR, 4, p);
        if (!fx_gl.list_exec)
            return;
    }
    for (int k = 0; k < 4; k++)
        fx_gl.tgt.tex_env_color[k] = fx_glut_d2c(p[k]);
}
void glTexEnvfv(GLenum target, GLenum pname, const GLfloat *p)
{
    if (pname == GL_TEXTURE_ENV_COLOR) {
        double d[4] = {p[0], p[1], p[2], p[3]};
        tex_env_color(d);
    } else
        glTexEnvi(target, pname, fx_glut_d2i(p[0]));
}

/* ---- display lists ---- */
GLuint glGenLists(GLsizei range)
{
    if (range <= 0) {
        fx_glut_set_error(GL_INVALID_VALUE);
        return 0;
    }
    for (GLuint s = 1; s + (GLuint)range <= FXG_MAX_LISTS; s++) {
        GLsizei k = 0;
        while (k < range && !fx_gl.lists[s + k].used)
            k++;
        if (k == range) {
            for (k = 0; k < range; k++)
                fx_gl.lists[s + k].used = 1;
            return s;
        }
        s += (GLuint)k;
    }
    fx_glut_set_error(GL_OUT_OF_MEMORY);
    return 0;
}
void glNewList(GLuint list, GLenum mode)
{
    if (list == 0 || list >= FXG_MAX_LISTS) {
        fx_glut_set_error(GL_INVALID_VALUE);
        return;
    }
    if (fx_gl.cur_list) {
        fx_glut_set_error(GL_INVALID_OPERATION);
        return;
    }
    fx_glut_list *l = &fx_gl.lists[list];
    l->used = 1;
    l->nrec = l->npool = 0;
    fx_gl.cur_list = list;
    fx_gl.list_exec = mode == GL_COMPILE_AND_EXECUTE;
}
void glEndList(void)
{
    if (!fx_gl.cur_list) {
        fx_glut_set_error(GL_INVALID_OPERATION);
        return;
    }
    fx_gl.cur_list = 0;
}
GLboolean glIsList(GLuint list) { return list && list < FXG_MAX_LISTS && fx_gl.lists[list].used; }
void glDeleteLists(GLuint list, GLsizei range)
{
    for (GLsizei i = 0; i < range; i++) {
        GLuint k = list + (GLuint)i;
        if (k && k < FXG_MAX_LISTS) {
            free(fx_gl.lists[k].rec);
            free(fx_gl.lists[k].pool);
            memset(&fx_gl.lists[k], 0, sizeof fx_gl.lists[k]);
        }
    }
}
void glListBase(GLuint base)
{
    REC(OP_LISTBASE, (double)base);
    fx_gl.list_base = base;
}

/* Nesting multiplies: a list that calls itself twice runs 2^64 times at
 * GL's nesting depth of 64 (Mesa hangs on it). One top-level glCallList
 * (or each list of a top-level glCallLists) replays at most
 * FXG_REPLAY_BUDGET recorded calls, 16M,
 * more than a frame of any real program; the rest is skipped and logged
 * once. */
#define FXG_REPLAY_BUDGET ((int64_t)1 << 24)
static void replay(GLuint id, int d)
{
    if (!id || id >= FXG_MAX_LISTS || d > 64)
        return;
    fx_glut_list *l = &fx_gl.lists[id];
    for (int i = 0; i < l->nrec; i++) {
        if (fx_gl.replay_left <= 0) {
            if (!fx_gl.replay_cut_logged)
                fx_glut_log("glCallList: stopped after %lld calls replayed by one top-level call "
                            "(lists calling lists multiply; the rest is skipped)",
                            (long long)(fx_gl.replay_budget > 0 ? fx_gl.replay_budget : FXG_REPLAY_BUDGET));
            fx_gl.replay_cut_logged = 1;
            return;
        }
        fx_gl.replay_left--;
        const double *a = l->pool + l->rec[i].off;
        switch (l->rec[i].op) {
#define FX_GLUT_OP_CASE(name, run) \
    case OP_##name: run; break;
            FX_GLUT_LIST_OPS(FX_GLUT_OP_CASE)
#undef FX_GLUT_OP_CASE
        default: break;
        }
    }
}
static void call_list(GLuint list)
{
    int was = fx_gl.replaying;
    if (!was)
        fx_gl.replay_left = fx_gl.replay_budget > 0 ? fx_gl.replay_budget : FXG_REPLAY_BUDGET;
    fx_gl.replaying = 1;
    replay(list, 0);
    fx_gl.replaying = was;
}
void glCallList(GLuint list)
{
    REC(OP_CALLLIST, (double)list);
    call_list(list);
}
void glCallLists(GLsizei n, GLenum type, const GLvoid *lists)
{
    for (GLsizei i = 0; i < n; i++) {
        GLuint id;
        switch (type) {
        case GL_UNSIGNED_BYTE: id = ((const GLubyte *)lists)[i]; break;
        case GL_BYTE: id = (GLuint)((const GLbyte *)lists)[i]; break;
        case GL_UNSIGNED_SHORT: id = ((const GLushort *)lists)[i]; break;
        case GL_SHORT: id = (GLuint)((const GLshort *)lists)[i]; break;
        case GL_INT: id = (GLuint)((const GLint *)lists)[i]; break;
        case GL_UNSIGNED_INT: id = ((const GLuint *)lists)[i]; break;
        case GL_FLOAT: id = (GLuint)((const GLfloat *)lists)[i]; break;
        default: fx_glut_set_error(GL_INVALID_ENUM); return;
        }
        if (recording()) { /* GL adds the base in effect when the list runs */
            double a = id;
            record(OP_CALLLIST_BASE, 1, &a);
            if (fx_gl.list_exec)
                call_list(fx_gl.list_base + id);
            continue;
        }
        glCallList(fx_gl.list_base + id);
    }
}

/* ---- queries ---- */
static int get_values(GLenum pname, double *v)
{
    const fx_glm *m = NULL;
    switch (pname) {
    case GL_MODELVIEW_MATRIX: m = &fx_gl.mv[fx_gl.mv_top]; break;
    case GL_PROJECTION_MATRIX: m = &fx_gl.proj[fx_gl.proj_top]; break;
    case GL_TEXTURE_MATRIX: m = &fx_gl.texm[fx_gl.tex_top]; break;
    default: break;
    }
    if (m) {
        for (int i = 0; i < 16; i++)
            v[i] = fx_glut_x2d(m->m[i]);
        return 16;
    }
    switch (pname) {
    case GL_VIEWPORT: for (int i = 0; i < 4; i++) v[i] = fx_gl.vp[i]; return 4;
    case GL_SCISSOR_BOX: for (int i = 0; i < 4; i++) v[i] = fx_gl.scissor[i]; return 4;
    case GL_CURRENT_COLOR: for (int i = 0; i < 4; i++) v[i] = fx_gl.color[i] / 65536.0; return 4;
    case GL_COLOR_CLEAR_VALUE: for (int i = 0; i < 4; i++) v[i] = fx_gl.clear_color[i] / 65536.0; return 4;
    case GL_CURRENT_NORMAL: for (int i = 0; i < 3; i++) v[i] = fx_glut_x2d(fx_gl.normal[i]); return 3;
    case GL_CURRENT_RASTER_POSITION: v[0] = fx_gl.rx / 256.0, v[1] = fx_gl.ry / 256.0, v[2] = 0, v[3] = 1; return 4;
    case GL_CURRENT_RASTER_POSITION_VALID: v[0] = fx_gl.raster_valid; return 1;
    case GL_MATRIX_MODE: v[0] = fx_gl.matrix_mode; return 1;
    case GL_MODELVIEW_STACK_DEPTH: v[0] = fx_gl.mv_top + 1; return 1;
    case GL_PROJECTION_STACK_DEPTH: v[0] = fx_gl.proj_top + 1; return 1;
    case GL_MAX_MODELVIEW_STACK_DEPTH: v[0] = FXG_STACK; return 1;
    case GL_MAX_PROJECTION_STACK_DEPTH: v[0] = FXG_PROJ_STACK; return 1;
    case GL_MAX_LIGHTS: v[0] = FX_GL_MAX_LIGHTS; return 1;
    case GL_MAX_TEXTURE_SIZE: v[0] = 4096; return 1;
    case GL_MAX_VIEWPORT_DIMS: v[0] = v[1] = FXG_MAX_VIEWPORT; return 2;
    case GL_POINT_SIZE: v[0] = fx_gl.point_size; return 1;
    case GL_LINE_WIDTH: v[0] = fx_gl.line_width; return 1;
    case GL_POINT_SIZE_RANGE: case GL_LINE_WIDTH_RANGE: v[0] = 1, v[1] = 256; return 2;
    case GL_SHADE_MODEL: v[0] = fx_gl.shade; return 1;
    case GL_DEPTH_FUNC: v[0] = fx_gl.depth_func; return 1;
    case GL_DEPTH_WRITEMASK: v[0] = fx_gl.depth_mask; return 1;
    case GL_DEPTH_CLEAR_VALUE: v[0] = fx_gl.clear_depth / 16777215.0; return 1;
    case GL_CULL_FACE_MODE: v[0] = fx_gl.cull_face; return 1;
    case GL_FRONT_FACE: v[0] = fx_gl.front_face; return 1;
    case GL_BLEND_SRC: v[0] = fx_gl.bsrc; return 1;
    case GL_BLEND_DST: v[0] = fx_gl.bdst; return 1;
    case GL_LINE_STIPPLE_PATTERN: v[0] = fx_gl.stipple_pattern; return 1;
    case GL_LINE_STIPPLE_REPEAT: v[0] = fx_gl.stipple_factor; return 1;
    case GL_RED_BITS: case GL_GREEN_BITS: case GL_BLUE_BITS: v[0] = 8; return 1;
    case GL_ALPHA_BITS: case GL_STENCIL_BITS: v[0] = 0; return 1;
    case GL_DEPTH_BITS: v[0] = 24; return 1;
    case GL_SUBPIXEL_BITS: v[0] = 8; return 1;
    case GL_DOUBLEBUFFER: v[0] = glutGet(GLUT_WINDOW_DOUBLEBUFFER); return 1;
    case GL_RGBA_MODE: v[0] = 1; return 1;
    case GL_TEXTURE_BINDING_2D: v[0] = fx_gl.bound_tex; return 1;
    case GL_LIST_BASE: v[0] = fx_gl.list_base; return 1;
    case GL_ZOOM_X: v[0] = fx_gl.zoom_x; return 1;
    case GL_ZOOM_Y: v[0] = fx_gl.zoom_y; return 1;
    case GL_LIST_INDEX: v[0] = fx_gl.cur_list; return 1;
    case GL_UNPACK_ALIGNMENT: v[0] = fx_gl.unpack_align; return 1;
    case GL_PACK_ALIGNMENT: v[0] = fx_gl.pack_align; return 1;
    case GL_LIGHT_MODEL_AMBIENT: for (int i = 0; i < 4; i++) v[i] = fx_gl.L.model_ambient[i] / 65536.0; return 4;
    case GL_LIGHT_MODEL_TWO_SIDE: v[0] = fx_gl.L.two_side; return 1;
    case GL_LIGHT_MODEL_LOCAL_VIEWER: v[0] = fx_gl.L.local_viewer; return 1;
    case GL_LIGHT_MODEL_COLOR_CONTROL: v[0] = fx_gl.separate_specular ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR; return 1;
    case GL_COLOR_MATERIAL_FACE: v[0] = fx_gl.cm_face; return 1;
    case GL_COLOR_MATERIAL_PARAMETER: v[0] = fx_gl.cm_mode; return 1;
    case GL_COLOR_WRITEMASK: for (int i = 0; i < 4; i++) v[i] = (fx_gl.color_mask >> i) & 1; return 4;
    case GL_DEPTH_RANGE: v[0] = 0, v[1] = 1; return 2;
    default: break;
    }
    if (cap_flag(pname) || (pname >= GL_LIGHT0 && pname <= GL_LIGHT7)) {
        v[0] = glIsEnabled(pname);
        return 1;
    }
    fx_glut_set_error(GL_INVALID_ENUM);
    return 0;
}
void glGetDoublev(GLenum pname, GLdouble *p)
{
    double v[16];
    int n = get_values(pname, v);
    for (int i = 0; i < n; i++)
        p[i] = v[i];
}
void glGetFloatv(GLenum pname, GLfloat *p)
{
    double v[16];
    int n = get_values(pname, v);
    for (int i = 0; i < n; i++)
        p[i] = (GLfloat)v[i];
}
void glGetIntegerv(GLenum pname, GLint *p)
{
    double v[16];
    int n = get_values(pname, v);
    int colorish = pname == GL_CURRENT_COLOR || pname == GL_COLOR_CLEAR_VALUE ||
                   pname == GL_LIGHT_MODEL_AMBIENT;
    for (int i = 0; i < n; i++)
        p[i] = colorish ? fx_glut_d2i(v[i] * 2147483647.0) : fx_glut_d2i(v[i]);
}
void glGetBooleanv(GLenum pname, GLboolean *p)
{
    double v[16];
    int n = get_values(pname, v);
    for (int i = 0; i < n; i++)
        p[i] = v[i] != 0;
}
const GLubyte *glGetString(GLenum name)
{
    switch (name) {
    case GL_VENDOR: return (const GLubyte *)"fixel";
    case GL_RENDERER: return (const GLubyte *)"fixel integer rasterizer (llvmpipe rules)";
    case GL_VERSION: return (const GLubyte *)"1.1 fixel";
    case GL_EXTENSIONS: return (const GLubyte *)"";
    default: fx_glut_set_error(GL_INVALID_ENUM); return NULL;
    }
}

/* accepted without effect: one colour buffer, read and drawn alike */
void glDrawBuffer(GLenum mode) { (void)mode; }
void glReadBuffer(GLenum mode) { (void)mode; }
void glPolygonOffset(GLfloat factor, GLfloat units)
{
    (void)factor, (void)units;
    fx_glut_unimplemented("glPolygonOffset", GL_INVALID_OPERATION);
}
