/* SPDX-License-Identifier: MIT */
/* The one place the GLUT layer reads the environment. A course program
 * cannot call fx_app_options_from_env itself, so glutInit reads these and
 * glutCreateWindow the FIXEL_* display and input variables (fixel/env.h). */
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "glut_int.h"

/* Every environment variable the GLUT layer reads, read here once:
 *   FIXEL_BACKEND=memory   headless: a memory framebuffer of the window's size
 *                          (also when no display opens)
 *   FIXEL_GLUT_FRAMES=N    exit 0 when the N-th frame ends
 *   FIXEL_GLUT_OUT=F       write that frame, the window's pixels: 8-bit RGB PNG
 *                          (or binary PPM when F ends in .ppm), top row first
 *   FIXEL_GLUT_REPLAY=F    headless input from replay file F (replay.c)
 *   FIXEL_GLUT_FULLSCREEN=1  the window is the whole screen
 *   FIXEL_GLUT_BENCH=1     at exit, print "fixel-glut: frames 2..N in T s = F fps"
 *                          (wall clock from the end of frame 1, as the Mesa shim)
 * An empty value is the same as unset; a FIXEL_GLUT_FRAMES that is not a
 * number >= 0 exits with status 2. */
void fxg_env_read(fxg_env *v)
{
    const char *e = getenv("FIXEL_GLUT_FRAMES");
    v->frames = 0;
    if (e && *e) {
        char *end;
        v->frames = strtol(e, &end, 10);
        if (*end || v->frames < 0) {
            fxg_log("FIXEL_GLUT_FRAMES=%s is not a frame count", e);
            exit(2);
        }
    }
    e = getenv("FIXEL_GLUT_OUT");
    v->out = e && *e ? e : NULL;
    e = getenv("FIXEL_GLUT_REPLAY");
    v->replay = e && *e ? e : NULL;
    e = getenv("FIXEL_GLUT_FULLSCREEN");
    v->fullscreen = e && !strcmp(e, "1");
    e = getenv("FIXEL_BACKEND");
    v->headless = e && !strcasecmp(e, "memory");
    e = getenv("FIXEL_GLUT_BENCH");
    v->bench = e && atoi(e) > 0;
}

