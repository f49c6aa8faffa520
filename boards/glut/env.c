/* SPDX-License-Identifier: MIT */
/* The one place the GLUT layer reads the environment. A course program
 * cannot call fx_app_options_from_env itself, so glutInit reads these and
 * glutCreateWindow the FIXEL_* display and input variables (fixel/env.h). */
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "fixel/env.h"
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
 * number from 0 to 10^9 exits with status 2; their ranges are in the one
 * table of FIXEL_* variables (boards/env/env_table.c). */
/* The table's parse (fixel/env.h); a bad value of a switch is said and
 * ignored, as the library does with its own. */
static long sw(const char *name)
{
    long v = 0;
    char msg[256];
    if (fx_env_get(name, &v, msg, sizeof msg) < 0) {
        fx_glut_log("%s", msg);
        v = 0;
    }
    return v;
}

void fx_glut_env_read(fx_glut_env *v)
{
    char msg[256];
    long n = 0;
    /* a frame count that is not one must not run a scripted test forever */
    if (fx_env_get("FIXEL_GLUT_FRAMES", &n, msg, sizeof msg) < 0) {
        fx_glut_log("%s", msg);
        exit(2);
    }
    v->frames = n;
    const char *e = getenv("FIXEL_GLUT_OUT");
    v->out = e && *e ? e : NULL;
    e = getenv("FIXEL_GLUT_REPLAY");
    v->replay = e && *e ? e : NULL;
    v->fullscreen = sw("FIXEL_GLUT_FULLSCREEN") != 0;
    /* the library's own parse, so "headless" and "Memory" agree with it */
    long b = FX_BACKEND_AUTO;
    v->headless = fx_env_get("FIXEL_BACKEND", &b, NULL, 0) == 0 && b == FX_BACKEND_MEMORY;
    v->bench = sw("FIXEL_GLUT_BENCH") != 0;
}
