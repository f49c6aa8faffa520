/* LD_PRELOAD shim for the Mesa reference runs: counts frames as the fixel
 * GLUT layer does (glFlush/glFinish when single-buffered, glutSwapBuffers
 * when double-buffered) and, at frame MESACAP_FRAMES (default 1), reads the
 * window back with glReadPixels and writes it as a binary PPM to MESACAP_OUT,
 * then exits. Build: cc -shared -fPIC capture.c -o capture.so -ldl -lGL
 * Run: LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=llvmpipe MESACAP_OUT=x.ppm \
 *      LD_PRELOAD=./capture.so xvfb-run -a ./prog */
#define _GNU_SOURCE
#include <GL/gl.h>
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

static int frames;
static int in_swap;

static void grab(GLenum buf)
{
    int target = getenv("MESACAP_FRAMES") ? atoi(getenv("MESACAP_FRAMES")) : 1;
    if (++frames < target)
        return;
    GLint vp[4];
    GLint dims[2] = {0, 0};
    glGetIntegerv(GL_VIEWPORT, vp);
    /* the window size: the drawable's, read through the viewport of the first reshape
     * is not reliable, so ask GLUT-free GL for the scissor box default instead */
    GLint sb[4];
    glGetIntegerv(GL_SCISSOR_BOX, sb);
    dims[0] = sb[2];
    dims[1] = sb[3];
    if (getenv("MESACAP_W")) {
        dims[0] = atoi(getenv("MESACAP_W"));
        dims[1] = atoi(getenv("MESACAP_H"));
    }
    int w = dims[0], h = dims[1];
    unsigned char *px = malloc((size_t)w * h * 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(buf);
    glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, px);
    const char *out = getenv("MESACAP_OUT") ? getenv("MESACAP_OUT") : "mesa.ppm";
    FILE *f = fopen(out, "wb");
    fprintf(f, "P6\n%d %d\n255\n", w, h);
    for (int y = h - 1; y >= 0; y--)
        fwrite(px + (size_t)y * w * 3, 1, (size_t)w * 3, f);
    fclose(f);
    _exit(0);
}

void glFlush(void)
{
    static void (*real)(void);
    if (!real)
        real = (void (*)(void))dlsym(RTLD_NEXT, "glFlush");
    real();
    if (!in_swap) {
        GLboolean db;
        glGetBooleanv(GL_DOUBLEBUFFER, &db);
        if (!db)
            grab(GL_FRONT);
    }
}

void glFinish(void)
{
    static void (*real)(void);
    if (!real)
        real = (void (*)(void))dlsym(RTLD_NEXT, "glFinish");
    real();
    GLboolean db;
    glGetBooleanv(GL_DOUBLEBUFFER, &db);
    if (!db)
        grab(GL_FRONT);
}

void glutSwapBuffers(void)
{
    static void (*real)(void);
    if (!real)
        real = (void (*)(void))dlsym(RTLD_NEXT, "glutSwapBuffers");
    grab(GL_BACK);
    in_swap = 1;
    real();
    in_swap = 0;
}
