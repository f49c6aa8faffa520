/* SPDX-License-Identifier: MIT */
/* fixel-demo — the gallery: one drawing function per page, shared by the
 * headless renderer and the interactive loop. */
#ifndef FIXEL_DEMO_H
#define FIXEL_DEMO_H
#include <stddef.h>
#include <stdint.h>
#include "fixel/draw.h"
#include "fixel/clip.h"
#include "fixel/mat3d.h"
#include "fixel/anim.h"
#include "fixel/julia.h"
#include "fixel/kinematics.h"

#define DEMO_FLIGHT_MAX 32
#define DEMO_ARM_LINKS 3
#define DEMO_ARM_TRAIL 48

#define DEMO_TAB_H 22

typedef struct demo_state {
    int page;
    int interactive;    /* 0: headless, deterministic pictures */
    int threads;        /* threads a page may start itself (demo_page.threads); 0: every core */
    int32_t w, h;
    int32_t mx, my;     /* last pointer position */
    /* clipping playground */
    fx_rect win;
    int32_t lx0, ly0, lx1, ly1;
    int clipper;        /* FX_CLIP_COHEN, _LIANG or _NLN */
    int drag;           /* 0 none, 1 start point, 2 end point, 3 window */
    int32_t dragx, dragy;
    /* fills: seed points clicked so far */
    int nseeds;
    int32_t seedx[16], seedy[16];
    /* fractals */
    int64_t mcre, mcim, mwidth; /* Mandelbrot view, fx56 */
    int32_t julia_x, julia_y;   /* pointer position choosing c */
    int koch_order;
    int orbit_off;              /* 1: the orbit-of-0 overlay hidden ('o') */
    /* colour page: chosen point on the wheel */
    int32_t pick_x, pick_y;
    /* 3D */
    fx_camera cam;
    int shading;        /* fx3d_shading */
    /* visible surfaces */
    int vsd_method;     /* fx_vsd_method */
    int32_t vsd_row;    /* the scan line traced */
    int32_t vsd_extra;  /* random triangles added to the course scene */
    int vsd_mesh;       /* 1: a torus of the 3D pipeline instead of the course scene */
    int32_t vsd_turn;   /* its rotation, degrees */
    /* animation */
    uint32_t frame;
    /* the Animation page's camera flight (page_anim.c) */
    fx_camera acam;
    fx_anim_key flight[DEMO_FLIGHT_MAX];
    int32_t nflight;
    int flying;
    uint32_t fly_from; /* the frame the flight started */
    /* the Animation page's arm (page_anim.c): its pose and aim point at
     * frame arm_frame, and the end's last DEMO_ARM_TRAIL positions */
    int arm_ready;
    uint32_t arm_frame;
    fx_angle arm_theta[DEMO_ARM_LINKS];
    fx16 arm_aim[2];
    fx16 arm_trail[2 * DEMO_ARM_TRAIL];
    int32_t arm_ntrail;
} demo_state;

typedef struct demo_page {
    const char *name;  /* file name and tab label */
    const char *title;
    void (*draw)(fx_ctx *c, demo_state *st);
    /* 1: draws only inside c's clip, reads no other pixel and writes no
     * shared memory, so bands of it may be drawn at once (fixel/par.h) */
    int bands;
    /* 1: not cut into bands but drawn on st->threads threads by the page
     * itself (the ray tracer's rows), with the same pixels on any number */
    int threads;
} demo_page;

extern const demo_page demo_pages[];
extern const int demo_npages;
extern const int demo_ntabs; /* the first demo_ntabs pages have a tab */
/* Tab i's columns [x0, x1) on a surface w pixels wide; the tab at column x
 * (-1: none). */
void demo_tab_span(int32_t w, int i, int32_t *x0, int32_t *x1);
int demo_tab_at(int32_t w, int32_t x);
/* The GLUT page (glutpage.c): a course program through boards/glut. */
void demo_page_glut(fx_ctx *c, demo_state *st);

void demo_state_init(demo_state *st, int32_t w, int32_t h);
/* Draw page st->page with its tab bar into c's surface. */
void demo_draw(fx_ctx *c, demo_state *st);
/* demo_draw on nthreads threads in bands (fixel/par.h) when the page allows
 * (demo_page.bands), else on this thread: the same pixels. Returns the
 * number of bands drawn (1: one thread). */
int demo_draw_threads(fx_ctx *c, demo_state *st, int nthreads);
/* Pointer input on the current page (down: 1 press, 0 move while pressed, -1 release). */
void demo_pointer(demo_state *st, int32_t x, int32_t y, int down);
/* A character key for the current page; returns 1 when it was used. */
int demo_key(demo_state *st, int key);

/* the visible-surface page (page_vsd.c) */
void demo_vsd_page(fx_ctx *c, demo_state *st, int32_t top);
int demo_vsd_key(demo_state *st, int key);

/* the ray-tracing page (page_rt.c); busy while a display's picture is
 * still being traced row by row */
#define DEMO_RT_X 8 /* the traced picture on the page */
#define DEMO_RT_Y (DEMO_TAB_H + 8)
#define DEMO_RT_W 784
#define DEMO_RT_H 408
void demo_rt_page(fx_ctx *c, demo_state *st, int32_t top);
/* page_objects.c: the objects of fixel/objects.h, each by scene-script lines */
void demo_objects_page(fx_ctx *c, demo_state *st, int32_t top);
int demo_rt_key(demo_state *st, int key);
int demo_rt_busy(const demo_state *st);

/* the Animation page (page_anim.c); --flight FILE keeps its recorded keys */
void demo_anim_init(demo_state *st);
void demo_anim_page(fx_ctx *c, demo_state *st, int32_t top);
int demo_anim_key(demo_state *st, int key);
int demo_camera_key(fx_camera *cam, int key, fx16 step);
void demo_anim_set_file(const char *path);

/* The Fractals page's orbit-of-0 overlay (orbit.c): fx_orbit0 of c for n
 * values into zre / zim (n entries each) and info, with two lines of text:
 * head "orbit of 0, c = RE IMi: KIND" (fixed point, spiral into a fixed
 * point, cycle of period P, explodes (|zK| > 2), bounded, no cycle found)
 * and vals, the first values z1..z4. Returns fx_orbit0's result. */
int demo_orbit_text(fx56 cre, fx56 cim, fx56 *zre, fx56 *zim, uint32_t n, fx_orbit0_info *info, char *head,
                    size_t nhead, char *vals, size_t nvals);

/* The Animation page's arm (page_anim.c): advance st's arm to frame f (the
 * page's clock in frames), a chain reaching by CCD for an aim point that
 * chases, at a bounded speed, a target running a figure of eight in the
 * panel at (x0, y0); the target at frame f goes to tx, ty (Q16.16 px). */
void demo_arm_advance(demo_state *st, uint32_t f, int32_t x0, int32_t y0, fx16 *tx, fx16 *ty);
void demo_arm_chain(int32_t x0, int32_t y0, fx_kin_chain *c);

/* helpers */
void demo_text(const fx_ctx *c, int32_t x, int32_t y, fx_color col, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
void demo_text_big(const fx_ctx *c, int32_t x, int32_t y, fx_color col, int scale, const char *s);

#endif
