/* SPDX-License-Identifier: MIT */
/* polyline — the GLUT course exercise on fixel: click to add a vertex, drag
 * to move the last one, the rubber band follows the pointer; c clears, q
 * (or Esc) quits. Display, mouse, motion, passive motion and keyboard
 * callbacks on fx_app, the way a GLUT program registers them.
 *
 * Runs on the screen (DRM/KMS or fbdev), or headless and scripted:
 *   FIXEL_BACKEND=memory FIXEL_REPLAY=examples/polyline.replay \
 *   FIXEL_OUT=polyline.png ./build/examples/polyline
 */
#include <string.h>

#include <fixel/app.h>
#include <fixel/draw.h>
#include <fixel/env.h>
#include <fixel/font.h>
#include <fixel/line.h>

#define MAXPTS 256

typedef struct {
    fx_app *app;
    int32_t xy[2 * MAXPTS];
    int n;
    int32_t mx, my; /* the pointer, for the rubber band */
    int hover;      /* the pointer position is known */
} polyline;

static void display(void *user)
{
    polyline *p = user;
    fx_surface s = fx_app_surface(p->app);
    fx_ctx c;
    fx_ctx_init(&c, &s);
    fx_ctx_set_color(&c, 0xFF101828);
    fx_clear(&c);
    fx_ctx_set_color(&c, 0xFFA0A8B8);
    fx_text(&c, 8, 8, "click: add a point   drag: move it   c: clear   q: quit");
    if (p->n > 0 && p->hover) { /* the rubber band from the last vertex */
        fx_ctx_set_color(&c, 0xFF506070);
        fx_line(&c, p->xy[2 * p->n - 2], p->xy[2 * p->n - 1], p->mx, p->my);
    }
    fx_ctx_set_color(&c, 0xFFF7B32B);
    fx_polyline(&c, p->xy, p->n);
    fx_ctx_set_color(&c, 0xFFF25C54);
    for (int i = 0; i < p->n; i++)
        fx_fill_rect(&c, p->xy[2 * i] - 2, p->xy[2 * i + 1] - 2, 5, 5);
    fx_app_present(p->app, NULL, 0);
}

static void mouse(void *user, int button, int state, int x, int y)
{
    polyline *p = user;
    if (button == FX_BUTTON_LEFT && state == FX_DOWN && p->n < MAXPTS) {
        p->xy[2 * p->n] = x;
        p->xy[2 * p->n + 1] = y;
        p->n++;
        fx_app_post_redisplay(p->app);
    }
}

static void motion(void *user, int x, int y) /* a button held: move the last point */
{
    polyline *p = user;
    if (p->n > 0) {
        p->xy[2 * p->n - 2] = x;
        p->xy[2 * p->n - 1] = y;
    }
    p->mx = x, p->my = y;
    fx_app_post_redisplay(p->app);
}

static void passive(void *user, int x, int y)
{
    polyline *p = user;
    p->mx = x, p->my = y;
    p->hover = 1;
    fx_app_post_redisplay(p->app);
}

static void keyboard(void *user, unsigned char key, int x, int y)
{
    polyline *p = user;
    (void)x, (void)y;
    if (key == 'c') {
        p->n = 0;
        fx_app_post_redisplay(p->app);
    } else if (key == 'q' || key == 27) {
        fx_app_quit(p->app);
    }
}

int main(void)
{
    fx_app_options o;
    fx_app_options_init(&o);
    if (fx_app_options_from_env(&o) < 0) /* FIXEL_BACKEND, FIXEL_REPLAY, ... */
        return 1;
    polyline p;
    memset(&p, 0, sizeof p);
    if (fx_app_open(&p.app, &o) < 0) /* the reason is logged */
        return 1;
    fx_callbacks cb = {.display = display, .mouse = mouse, .motion = motion,
                       .passive_motion = passive, .keyboard = keyboard};
    fx_app_set_callbacks(p.app, &cb, &p);
    int r = fx_app_main_loop(p.app);
    fx_app_close(p.app);
    return r < 0;
}
