/* SPDX-License-Identifier: MIT */
/* GL corner test (issue #40): every GL/GLU/GLUT entry point that takes a
 * float or double (the table generated from boards/glut/include/GL/ headers by
 * tests/glut/gen-gl-table.sh, so a new entry point is in it by itself) is
 * called with each hostile value (NaN, +-Inf, +-1e38, denormals, +-2^31
 * units and its neighbours, ...: tests/glut/gl-hostile.h) in each of its
 * float positions in turn -- for a pointer parameter, every element --
 * with each enum its GLenum parameters take, the others benign; then the
 * probe scene draws with the state that left. A case passes when it
 * returns, glGetError gives one of GL's errors and, in the sanitized
 * builds (SAN=1 with gcc, and clang's float-cast-overflow build: make
 * test-gl-corners), nothing undefined happened: those abort.
 * Prints "gl-corners: N passed, N failed". */
#include <stdio.h>
#include <stdlib.h>

#include "gl-hostile.h"

static long P, F;

static void run_case(const fxgl_entry *e, fxgl_args *a)
{
    e->call(a);
    GLenum err = glGetError();
    fxgl_probe(1);
    GLenum err2 = glGetError();
    if (fxgl_valid_error(err) && fxgl_valid_error(err2)) {
        P++;
    } else {
        F++;
        fprintf(stderr, "FAIL %s: glGetError gave 0x%x / 0x%x\n", e->name, err, err2);
    }
    while (glGetError() != GL_NO_ERROR) {
    }
}

/* Every combination of the entry's enum parameters (k: the next one). */
static void enums_then(const fxgl_entry *e, fxgl_args *a, int k, int ne, int slot, int elem, double v)
{
    for (; e->sig[k] && e->sig[k] != 'e'; k++) {
    }
    if (!e->sig[k]) {
        char kind = 0;
        int s = 0;
        for (int j = 0; e->sig[j]; j++)
            if (strchr("fdFD", e->sig[j]) && s++ == slot)
                kind = e->sig[j];
        /* v comes from the float list for f and F (so the conversion is
         * exact), from the double list for d and D */
        for (int i = 0; i < FXGL_ARR; i++)
            if ((kind == 'F' || kind == 'D') && (elem < 0 || i == elem)) {
                if (kind == 'F')
                    a->fa[i] = (float)v;
                else
                    a->da[i] = v;
            }
        if (kind == 'f' || kind == 'd')
            a->d[slot] = v;
        run_case(e, a);
        return;
    }
    const fxgl_enums *l = fxgl_enum_list(e, k);
    for (int i = 0; i < l->n; i++) {
        a->e[ne] = l->v[i];
        enums_then(e, a, k + 1, ne + 1, slot, elem, v);
    }
}

int main(void)
{
    if (fx_glut_gl_init(40, 40) < 0) {
        fprintf(stderr, "gl-corners: no memory for a 40x40 window\n");
        return 1;
    }
    GLUquadric *q = gluNewQuadric();
    static fxgl_args a;
    for (int n = 0; n < fxgl_nentries; n++) {
        const fxgl_entry *e = &fxgl_entries[n];
        void *font = strstr(e->name, "Stroke") ? GLUT_STROKE_ROMAN : GLUT_BITMAP_8_BY_13;
        int slots = 0;
        for (int j = 0; e->sig[j]; j++)
            slots += strchr("fdFD", e->sig[j]) != NULL;
        for (int slot = 0; slot < slots; slot++) {
            char kind = 0;
            int s = 0;
            for (int j = 0; e->sig[j]; j++)
                if (strchr("fdFD", e->sig[j]) && s++ == slot)
                    kind = e->sig[j];
            int isf = kind == 'f' || kind == 'F';
            int nv = isf ? FXGL_NHF : FXGL_NHD;
            /* a pointer: all elements at once, then the first four one by one
             * (a w, an alpha, a cut-off among benign ones) */
            int nelem = (kind == 'F' || kind == 'D') ? 5 : 1;
            for (int el = 0; el < nelem; el++)
                for (int v = 0; v < nv; v++) {
                    fxgl_reset();
                    fxgl_benign(&a, e, font, q);
                    double val = isf ? (double)fxgl_hostile_f[v] : fxgl_hostile_d[v];
                    enums_then(e, &a, 0, 0, slot, el - 1, val);
                }
        }
    }
    gluDeleteQuadric(q);
    printf("gl-corners: %ld passed, %ld failed (%d entry points from the headers)\n", P, F, fxgl_nentries);
    return F != 0;
}
