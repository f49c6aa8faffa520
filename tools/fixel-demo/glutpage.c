/* SPDX-License-Identifier: MIT */
/* fixel-demo's GLUT page: a course program -- GLUT callbacks, GL 1.x
 * immediate mode, fixed-function lighting -- run through fixel's GLUT layer
 * (boards/glut) into an offscreen window, its pixels read back with
 * glReadPixels and put on the page. The program's two callbacks are written
 * as a student writes them; the page calls reshape and display itself
 * instead of glutMainLoop (fx_glut_offscreen_window). */
#include <GL/freeglut.h>
#include <stdint.h>
#include <stdlib.h>

#include "demo.h"
#include "fixel/draw.h"
#include "fixel/surface.h"

/* ---- the course program: a lit teapot beside a wire cone and a torus ---- */
static float spin;

static void reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40.0, (double)w / h, 1.0, 50.0);
    glMatrixMode(GL_MODELVIEW);
}

static void display(void)
{
    GLfloat pos[] = {4.0f, 6.0f, 8.0f, 1.0f};
    GLfloat white[] = {1.0f, 1.0f, 1.0f, 1.0f};
    glClearColor(0.09f, 0.15f, 0.23f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_COLOR_MATERIAL);
    glEnable(GL_NORMALIZE);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glMaterialfv(GL_FRONT, GL_SPECULAR, white);
    glMaterialf(GL_FRONT, GL_SHININESS, 40.0f);
    glLoadIdentity();
    gluLookAt(0.0, 2.5, 9.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);

    glPushMatrix();
    glRotatef(spin, 0.0f, 1.0f, 0.0f);
    glColor3f(0.85f, 0.35f, 0.15f);
    glutSolidTeapot(1.6);
    glPopMatrix();

    glPushMatrix();
    glTranslatef(-3.4f, -1.0f, -1.0f);
    glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
    glColor3f(0.3f, 0.6f, 0.9f);
    glutSolidCone(0.9, 2.2, 24, 8);
    glPopMatrix();

    glPushMatrix();
    glTranslatef(3.4f, 0.0f, -1.0f);
    glRotatef(60.0f + spin, 1.0f, 0.0f, 0.0f);
    glColor3f(0.45f, 0.8f, 0.4f);
    glutSolidTorus(0.35, 0.95, 20, 32);
    glPopMatrix();

    glDisable(GL_LIGHTING);
    glColor3f(0.95f, 0.76f, 0.31f);
    glLoadIdentity();
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    gluOrtho2D(0, 1, 0, 1);
    glRasterPos2f(0.02f, 0.03f);
    glutBitmapString(GLUT_BITMAP_HELVETICA_12, (const unsigned char *)"glutSolidTeapot / Cone / Torus, GL_LIGHT0");
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    glutSwapBuffers();
}

/* ---- the page ---- */
#define GW 560
#define GH 400

void demo_page_glut(fx_ctx *c, demo_state *st)
{
    static int window;
    static uint32_t px[GW * GH];
    static uint8_t rgba[GW * GH * 4];
    int32_t top = DEMO_TAB_H + 8;
    if (!window)
        window = fx_glut_offscreen_window(GW, GH);
    demo_text(c, 14, top + 5, 0xFFF2C14Eu, "GLUT: a course program through fixel's GLUT layer");
    if (window) {
        spin = (float)(st->frame * 2 % 360);
        reshape(GW, GH);
        display();
        glReadPixels(0, 0, GW, GH, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
        for (int y = 0; y < GH; y++) /* GL's rows go up */
            for (int x = 0; x < GW; x++) {
                const uint8_t *p = &rgba[((GH - 1 - y) * GW + x) * 4];
                px[y * GW + x] = 0xFF000000u | (uint32_t)p[0] << 16 | (uint32_t)p[1] << 8 | p[2];
            }
        fx_surface win;
        fx_surface_init(&win, px, GW, GH, GW * 4, FX_FMT_XRGB8888);
        fx_blit(&c->surf, 8, top + 24, &win);
    }
    demo_text(c, 584, top + 30, 0xFFE8E8E8u, "#include <GL/glut.h>");
    demo_text(c, 584, top + 50, 0xFFE8E8E8u, "reshape: gluPerspective");
    demo_text(c, 584, top + 64, 0xFFE8E8E8u, "display: gluLookAt,");
    demo_text(c, 584, top + 78, 0xFFE8E8E8u, "  glLightfv, glMaterialf,");
    demo_text(c, 584, top + 92, 0xFFE8E8E8u, "  GL_COLOR_MATERIAL,");
    demo_text(c, 584, top + 106, 0xFFE8E8E8u, "  glutSolidTeapot/Cone/");
    demo_text(c, 584, top + 120, 0xFFE8E8E8u, "  Torus, glutBitmapString");
    demo_text(c, 584, top + 148, 0xFF7A8AA0u, "Build your own:");
    demo_text(c, 584, top + 162, 0xFF7A8AA0u, "cc lab.c $(pkg-config");
    demo_text(c, 584, top + 176, 0xFF7A8AA0u, " --cflags --libs fixel-glut)");
    demo_text(c, 584, top + 204, 0xFF7A8AA0u, "Frame = the pixels the");
    demo_text(c, 584, top + 218, 0xFF7A8AA0u, "program would show; Mesa's");
    demo_text(c, 584, top + 232, 0xFF7A8AA0u, "llvmpipe is the reference");
    demo_text(c, 584, top + 246, 0xFF7A8AA0u, "(make test-glut-mesa).");
}
