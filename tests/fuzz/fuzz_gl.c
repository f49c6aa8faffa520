/* SPDX-License-Identifier: MIT */
/* GL op-sequence interpreter (issue #40): the input is a stream of choices
 * (choice.h) read as GL/GLU/GLUT calls -- any entry point of the table
 * generated from the layer's headers (tests/glut/gen-gl-table.sh) with
 * hostile floats (NaN, +-Inf, +-1e38, denormals, +-2^31 units and its
 * neighbours, any bit pattern), plus glBegin/glEnd, enables, matrix
 * stacks, viewport and scissor at int corners, pixel reads and writes,
 * display lists, text and the probe scene of tests/glut/gl-hostile.h.
 * Built by clang with -fsanitize=float-cast-overflow,undefined,address and
 * no recovery: any undefined behaviour, overrun or leak aborts; a call that
 * runs too long is a libFuzzer timeout. */
#include <stdlib.h>

#include "choice.h"
#include "gl-hostile.h"

static float any_float(in *s)
{
    uint32_t c = take(s, 1);
    if (c < 200)
        return fxgl_hostile_f[c % FXGL_NHF];
    if (c < 230) { /* any bit pattern: NaNs with payloads, denormals */
        uint32_t u = take(s, 4);
        float f;
        memcpy(&f, &u, 4);
        return f;
    }
    return (float)((int32_t)take(s, 2) - 32768) / 64.0f; /* ordinary values */
}
static double any_double(in *s)
{
    uint32_t c = take(s, 1);
    if (c < 200)
        return fxgl_hostile_d[c % FXGL_NHD];
    if (c < 230) {
        uint64_t u = (uint64_t)take(s, 4) << 32 | take(s, 4);
        double d;
        memcpy(&d, &u, 8);
        return d;
    }
    return (double)((int32_t)take(s, 2) - 32768) / 64.0;
}

/* The k-th parameter's name in e->names. */
static void param_name(const fxgl_entry *e, int k, char *out, size_t n)
{
    const char *p = e->names;
    for (int i = 0; i < k && p; i++) {
        p = strchr(p, ',');
        if (p)
            p++;
    }
    size_t l = p ? strcspn(p, ",") : 0;
    if (l >= n)
        l = n - 1;
    memcpy(out, p ? p : "", l);
    out[l] = 0;
}

/* Ints: sizes and strides that index the caller's buffers stay within
 * them (a program's own contract); counts of the solids take their
 * corners up to 40 (the cap of 256 and INT32_MAX are the unit test's:
 * test_glut_hostile.c, a 256x256 sphere is slow under ASan). */
static int any_int(in *s, const char *name)
{
    if (!strcmp(name, "w") || !strcmp(name, "h") || strstr(name, "stride") || strstr(name, "order") ||
        !strcmp(name, "un") || !strcmp(name, "vn") || !strcmp(name, "num_levels"))
        return (int)corner(s, -1, 8) % 9;
    static const int segs[] = {INT32_MIN, -1, 0, 1, 2, 3, 5, 40};
    return segs[take(s, 1) % 8];
}

static void call_entry(in *s, const fxgl_entry *e, fxgl_args *a)
{
    int nd = 0, ni = 0, ne = 0;
    char name[32];
    for (int k = 0; e->sig[k]; k++) {
        switch (e->sig[k]) {
        case 'f': a->d[nd++] = any_float(s); break;
        case 'd': a->d[nd++] = any_double(s); break;
        case 'F':
            for (int i = 0; i < 16; i++)
                a->fa[i] = any_float(s);
            nd++;
            break;
        case 'D':
            for (int i = 0; i < 16; i++)
                a->da[i] = any_double(s);
            nd++;
            break;
        case 'i':
            param_name(e, k, name, sizeof name);
            if (ni < 8)
                a->i[ni++] = any_int(s, name);
            break;
        case 'e': {
            const fxgl_enums *l = fxgl_enum_list(e, k);
            uint32_t c = take(s, 1);
            if (ne < 4)
                a->e[ne++] = c < 240 ? l->v[c % (uint32_t)l->n] : (GLenum)take(s, 2);
            break;
        }
        default: break;
        }
    }
    e->call(a);
}

static const GLenum modes[] = {GL_POINTS, GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP, GL_TRIANGLES,
                               GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON};
static const GLenum caps[] = {GL_LIGHTING, GL_LIGHT0, GL_LIGHT1, GL_DEPTH_TEST, GL_CULL_FACE,
                              GL_BLEND, GL_TEXTURE_2D, GL_SCISSOR_TEST, GL_LINE_STIPPLE,
                              GL_NORMALIZE, GL_COLOR_MATERIAL, GL_RESCALE_NORMAL, GL_POLYGON_STIPPLE};

static int32_t any_i32(in *s) { return (int32_t)corner(s, INT32_MIN, INT32_MAX); }

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static int inited;
    static GLUquadric *q;
    static fxgl_args a;
    if (!inited) {
        if (fx_glut_gl_init(40, 40) < 0)
            abort();
        q = gluNewQuadric();
        static GLuint tex;
        static GLubyte texels[4 * 4 * 4];
        glGenTextures(1, &tex);
        glBindTexture(GL_TEXTURE_2D, tex);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
        inited = 1;
    }
    fxgl_reset();
    /* lists calling lists: the layer's budget of 16M replayed calls per
     * top-level call bounds the work (unit test
     * glut_hostile_list_calling_itself_twice_ends); 48 such calls of it
     * take minutes here, so the fuzzer gives each 64K */
    fx_gl.replay_budget = 1 << 16;
    in s = {data, size};
    for (int op = 0; op < 48 && s.n; op++) {
        uint32_t c = take(&s, 1);
        if (c < 160) {
            const fxgl_entry *e = &fxgl_entries[take(&s, 1) % fxgl_nentries];
            void *font = strstr(e->name, "Stroke") ? GLUT_STROKE_ROMAN : GLUT_BITMAP_8_BY_13;
            fxgl_benign(&a, e, font, q);
            call_entry(&s, e, &a);
            continue;
        }
        switch (c % 16) {
        case 0: glBegin(modes[take(&s, 1) % 10]); break;
        case 1: glEnd(); break;
        case 2: glEnable(caps[take(&s, 1) % (sizeof caps / sizeof caps[0])]); break;
        case 3: glDisable(caps[take(&s, 1) % (sizeof caps / sizeof caps[0])]); break;
        case 4: glMatrixMode((GLenum[]){GL_MODELVIEW, GL_PROJECTION, GL_TEXTURE}[take(&s, 1) % 3]); break;
        case 5: take(&s, 1) & 1 ? glPushMatrix() : glPopMatrix(); break;
        case 6: {
            int32_t x = any_i32(&s), y = any_i32(&s), w = any_i32(&s), h = any_i32(&s);
            take(&s, 1) & 1 ? glViewport(x, y, w, h) : glScissor(x, y, w, h);
            break;
        }
        case 7: {
            /* a read of at most 8x8 pixels anywhere: the buffer is the caller's */
            static unsigned char px[8 * 8 * 4 * 4];
            int32_t x = any_i32(&s), y = any_i32(&s);
            GLenum f = (GLenum[]){GL_RGB, GL_RGBA, GL_LUMINANCE, GL_DEPTH_COMPONENT}[take(&s, 1) % 4];
            glReadPixels(x, y, (int)(take(&s, 1) % 9), (int)(take(&s, 1) % 9), f,
                         take(&s, 1) & 1 ? GL_FLOAT : GL_UNSIGNED_BYTE, px);
            break;
        }
        case 8: {
            static unsigned char px[8 * 8 * 4 * 4];
            for (size_t i = 0; i < 16; i++)
                px[i] = (unsigned char)take(&s, 1);
            glDrawPixels((int)(take(&s, 1) % 9), (int)(take(&s, 1) % 9), take(&s, 1) & 1 ? GL_RGB : GL_RGBA,
                         take(&s, 1) & 1 ? GL_FLOAT : GL_UNSIGNED_BYTE, px);
            break;
        }
        case 9: {
            uint32_t b = take(&s, 1);
            GLuint l = 1 + b % 4;
            /* what a list holds besides the calls of the entry table: bases
             * and glCallLists (resolved when the list runs), bitmaps (copied
             * when it is compiled) */
            if ((b >> 2) % 8 == 5) {
                glListBase((GLuint)any_i32(&s));
                break;
            }
            if ((b >> 2) % 8 == 6) {
                GLubyte ids[4] = {(GLubyte)take(&s, 1), (GLubyte)take(&s, 1), (GLubyte)take(&s, 1), (GLubyte)take(&s, 1)};
                glCallLists((GLsizei)(take(&s, 1) % 5), GL_UNSIGNED_BYTE, ids);
                break;
            }
            if ((b >> 2) % 8 == 7) {
                static GLubyte bits[8 * 16];
                for (size_t i = 0; i < 8; i++)
                    bits[i] = (GLubyte)take(&s, 1);
                glBitmap((GLsizei)(take(&s, 1) % 65), (GLsizei)(take(&s, 1) % 17), (GLfloat)any_i32(&s),
                         (GLfloat)any_i32(&s), (GLfloat)any_i32(&s), (GLfloat)any_i32(&s), bits);
                break;
            }
            uint32_t k = take(&s, 1) % 3;
            if (k == 0)
                glNewList(l, take(&s, 1) & 1 ? GL_COMPILE : GL_COMPILE_AND_EXECUTE);
            else if (k == 1)
                glEndList();
            else
                glCallList(l);
            break;
        }
        case 10: glutBitmapCharacter(GLUT_BITMAP_8_BY_13, (int)take(&s, 1)); break;
        case 11: glutStrokeCharacter(GLUT_STROKE_ROMAN, (int)take(&s, 1)); break;
        case 12: glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT); break;
        case 13: glLineStipple(any_i32(&s), (GLushort)take(&s, 2)); break;
        case 14: glRasterPos2i(any_i32(&s), any_i32(&s)); break;
        default: fxgl_probe(take(&s, 1) & 1); break;
        }
    }
    /* the state the sequence left, drawn once more; errors must be GL's */
    fxgl_probe(1);
    if (!fxgl_valid_error(glGetError()))
        abort();
    glEndList();
    return 0;
}
