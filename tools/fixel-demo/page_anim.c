/* SPDX-License-Identifier: MIT */
/* fixel-demo — the Animation page (docs/ANIMATION.md): a morph by added
 * vertices, the bouncing ball, an eased square following a spline path, a
 * jointed arm reaching by inverse kinematics for a goal-directed target, and
 * a 3D camera flight recorded from key presses and played back through
 * fx_anim_eval. The clock is the demo's frame counter (30 a second); the
 * headless picture is drawn at 1.2 s with the default flight half flown. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "demo.h"
#include "fixel/anim.h"
#include "fixel/circle.h"
#include "fixel/files.h"
#include "fixel/fill.h"
#include "fixel/kinematics.h"
#include "fixel/line.h"
#include "fixel/mesh.h"
#include "fixel/render3d.h"
#include "fixel/xform.h"

#define PANELC 0xFF18263Au
#define EDGE 0xFF2E4A6Bu
#define INK 0xFFE8E8E8u
#define DIM 0xFF7A8AA0u
#define ACCENT 0xFFF2C14Eu
#define KEY_GAP (3 * FX16_ONE / 2) /* a recorded key every 1.5 s of flight */

static const char *flight_file; /* --flight FILE: keys appended as recorded */

static fx16 clock_of(const demo_state *st, uint32_t from)
{
    return fx16_from_ratio((int32_t)(st->frame - from) + (st->interactive ? 0 : 36), 30);
}

static void box(fx_ctx *c, int32_t x, int32_t y, int32_t w, int32_t h)
{
    fx_ctx_set_color(c, PANELC);
    fx_fill_rect(c, x, y, w, h);
    fx_ctx_set_color(c, EDGE);
    fx_rect_outline(c, x, y, w, h);
}

/* the view as a key: eye, and a look-at point 4 units ahead */
static void cam_key(const fx_camera *cam, fx16 t, fx_anim_key *k)
{
    memset(k, 0, sizeof *k);
    k->t = t;
    k->v[0] = cam->eye.x, k->v[1] = cam->eye.y, k->v[2] = cam->eye.z;
    k->v[3] = cam->eye.x - 4 * cam->n.x, k->v[4] = cam->eye.y - 4 * cam->n.y, k->v[5] = cam->eye.z - 4 * cam->n.z;
}

static void set_cam(fx_camera *cam, const fx16 *v)
{
    fx_camera_set(cam, fx_vec3_make(v[0], v[1], v[2]), fx_vec3_make(v[3], v[4], v[5]),
                  fx_vec3_make(0, FX16_ONE, 0));
}

void demo_anim_init(demo_state *st)
{
    static const int32_t eyes[4][3] = {{0, 3, 8}, {6, 2, 4}, {5, 4, -5}, {-6, 1, 2}};
    fx_camera_set(&st->acam, fx_vec3_make(0, 3 * FX16_ONE, 8 * FX16_ONE), fx_vec3_make(0, 0, 0),
                  fx_vec3_make(0, FX16_ONE, 0));
    st->nflight = 0;
    st->flying = 0;
    if (flight_file) { /* a recorded flight: T EX EY EZ LX LY LZ, raw Q16.16 */
        char why[160];
        FILE *f = fx_fopen_regular(flight_file, NULL, why, sizeof why);
        if (!f && errno != ENOENT) /* missing: no flight recorded yet */
            fprintf(stderr, "fixel-demo: --flight %s: %s\n", flight_file, why);
        fx_anim_key k;
        memset(&k, 0, sizeof k);
        while (f && st->nflight < DEMO_FLIGHT_MAX &&
               fscanf(f, "%d %d %d %d %d %d %d", &k.t, &k.v[0], &k.v[1], &k.v[2], &k.v[3], &k.v[4], &k.v[5]) == 7) {
            if (st->nflight && k.t <= st->flight[st->nflight - 1].t)
                break; /* times must increase: the rest is not this flight */
            st->flight[st->nflight++] = k;
        }
        if (f)
            fclose(f);
        return;
    }
    for (int i = 0; i < 4; i++) { /* round the objects, always looking at the middle */
        fx_anim_key *k = &st->flight[st->nflight++];
        memset(k, 0, sizeof *k);
        k->t = i * KEY_GAP;
        for (int j = 0; j < 3; j++)
            k->v[j] = eyes[i][j] * FX16_ONE;
    }
    if (!st->interactive) { /* the headless picture: half-way through the flight */
        st->flying = 1;
        st->fly_from = 36 - 68;
    }
}

void demo_anim_set_file(const char *path) { flight_file = path; }

static fx_anim_track flight_track(const demo_state *st)
{
    fx_anim_track tr = {st->flight, st->nflight, 6, FX_ANIM_SPLINE, FX_EASE_INOUT};
    return tr;
}

/* ---- 2D: morph, ball, path ---- */

static const fx16 tri[] = {0, -50 * 65536, 46 * 65536, 34 * 65536, -46 * 65536, 34 * 65536};
static const fx16 star[] = {0,         -56 * 65536, 14 * 65536,  -14 * 65536, 56 * 65536,  0,         14 * 65536, 14 * 65536,
                            0,         56 * 65536,  -14 * 65536, 14 * 65536,  -56 * 65536, 0,         -14 * 65536, -14 * 65536};

static void draw_morph(fx_ctx *c, fx16 t, int32_t cx, int32_t cy)
{
    fx16 a[16], b[16], m[16];
    int32_t n = fx_anim_morph_match(tri, 3, star, 8, 2, 1, a, b, 8);
    int64_t p = t % (4 * FX16_ONE); /* there and back in 4 s */
    fx16 s = (fx16)(p < 2 * FX16_ONE ? p / 2 : (4 * FX16_ONE - p) / 2);
    fx_anim_morph_at(a, b, 2 * n, fx_anim_ease_apply(FX_EASE_INOUT, s), m);
    fx_pt16 pt[8];
    for (int i = 0; i < n; i++)
        pt[i] = (fx_pt16){m[2 * i] + (cx * 65536), m[2 * i + 1] + (cy * 65536)};
    int starts[2] = {0, n};
    fx_ctx_set_color(c, 0xFF3C8CD0u);
    fx_poly_fill16(c, pt, starts, 1);
    fx_ctx_set_color(c, INK);
    for (int i = 0; i < n; i++)
        fx_fill_rect(c, fx16_round(pt[i].x) - 1, fx16_round(pt[i].y) - 1, 3, 3);
    demo_text(c, cx - 60, cy + 64, DIM, "morph 3 -> 8 vertices");
}

static void draw_ball(fx_ctx *c, fx16 t, int32_t x0, int32_t y0, int32_t w, int32_t h)
{
    fx_anim_ball b = {(x0 + 20) * 65536, (y0 + 20) * 65536, 70 * 65536, -30 * 65536, 300 * 65536, 52429 /* 0.8 */,
                      (x0 + 7) * 65536, (x0 + w - 8) * 65536, (y0 + h - 8) * 65536};
    t %= 6 * FX16_ONE;
    fx_anim_ball_state s;
    int32_t px = 0, py = 0;
    fx_ctx_set_color(c, 0xFF4060A0u);
    for (int i = 0; i <= 120; i++) {
        fx_anim_ball_at(&b, (fx16)((int64_t)t * i / 120), &s);
        if (i)
            fx_line(c, px, py, fx16_round(s.x), fx16_round(s.y));
        px = fx16_round(s.x), py = fx16_round(s.y);
    }
    fx_anim_ball_at(&b, t, &s);
    fx_ctx_set_color(c, ACCENT);
    fx_disc(c, fx16_round(s.x), fx16_round(s.y), 6);
    demo_text(c, x0 + 4, y0 + h + 4, DIM, "g 300, e 0.8: %d bounce%s", s.bounces, s.bounces == 1 ? "" : "s");
}

static void draw_path(fx_ctx *c, fx16 t, int32_t x0, int32_t y0)
{
    static const int32_t pts[5][2] = {{10, 100}, {45, 20}, {90, 110}, {140, 30}, {175, 90}};
    fx_anim_key k[5];
    for (int i = 0; i < 5; i++) {
        memset(&k[i], 0, sizeof k[i]);
        k[i].t = i * FX16_ONE;
        k[i].v[0] = (x0 + pts[i][0]) * 65536;
        k[i].v[1] = (y0 + pts[i][1]) * 65536;
    }
    fx_anim_track tr = {k, 5, 2, FX_ANIM_SPLINE, FX_EASE_NONE};
    fx16 v[FX_ANIM_MAX_CH], d[FX_ANIM_MAX_CH];
    fx_ctx_set_color(c, 0xFF505A6Au);
    int32_t px = 0, py = 0;
    for (int i = 0; i <= 100; i++) {
        fx_anim_eval(&tr, 4 * FX16_ONE * i / 100, v);
        if (i)
            fx_line(c, px, py, fx16_round(v[0]), fx16_round(v[1]));
        px = fx16_round(v[0]), py = fx16_round(v[1]);
    }
    fx_ctx_set_color(c, 0xFFFF4040u);
    for (int i = 0; i < 5; i++)
        fx_fill_rect(c, x0 + pts[i][0] - 1, y0 + pts[i][1] - 1, 3, 3);
    tr.ease = FX_EASE_INOUT;
    fx16 u = (fx16)(t % (5 * FX16_ONE)); /* 4 s along, 1 s resting at the end */
    fx_anim_eval(&tr, u, v);
    fx_anim_tangent(&tr, u, d);
    fx_xform2 m, r;
    fx_xform2_translation(&m, v[0], v[1]);
    fx_xform2_rotation(&r, fx_atan2(d[1], d[0]), 0, 0);
    fx_xform2_pre(&m, &r);
    fx_pt16 sq[4] = {{-9 * 65536, -6 * 65536}, {9 * 65536, -6 * 65536}, {9 * 65536, 6 * 65536}, {-9 * 65536, 6 * 65536}};
    fx_xform2_apply_pts(&m, sq, sq, 4);
    int starts[2] = {0, 4};
    fx_ctx_set_color(c, 0xFF60D080u);
    fx_poly_fill16(c, sq, starts, 1);
    demo_text(c, x0 + 4, y0 + 120, DIM, "spline path, ease in/out,");
    demo_text(c, x0 + 4, y0 + 134, DIM, "facing its way");
}

/* ---- kinematics: an arm after a goal-directed target ---- */

/* The arm stands on the bottom middle of its ARM_W x ARM_H panel at (x0, y0)
 * pointing up; its target runs a figure of eight round (ARM_CX, ARM_CY) in
 * ARM_PERIOD frames, inside the reach; the aim point chases it at ARM_SPEED
 * px a frame (the target's fastest is about 2.3), so the end lags after a
 * restart and then stays on the target. */
#define ARM_W 184
#define ARM_H 196
#define ARM_CX (ARM_W / 2)
#define ARM_CY 110
#define ARM_RX 55
#define ARM_RY 30
#define ARM_PERIOD 240
#define ARM_SPEED (3 * FX16_ONE)

static const fx16 arm_len[DEMO_ARM_LINKS] = {60 * FX16_ONE, 45 * FX16_ONE, 30 * FX16_ONE};

void demo_arm_chain(int32_t x0, int32_t y0, fx_kin_chain *c)
{
    c->x = (x0 + ARM_W / 2) * FX16_ONE;
    c->y = (y0 + ARM_H - 14) * FX16_ONE;
    c->dir = FX_ANGLE_270; /* up the y-down screen */
    c->n = DEMO_ARM_LINKS;
    c->len = arm_len;
}

static void arm_target(uint32_t f, int32_t x0, int32_t y0, fx16 *tx, fx16 *ty)
{
    fx_angle a = (fx_angle)((uint64_t)(f % ARM_PERIOD) * 0x100000000ull / ARM_PERIOD);
    *tx = (x0 + ARM_CX) * FX16_ONE + ARM_RX * fx_sin(a);
    *ty = (y0 + ARM_CY) * FX16_ONE - ARM_RY * fx_sin((fx_angle)(2 * a));
}

void demo_arm_advance(demo_state *st, uint32_t f, int32_t x0, int32_t y0, fx16 *tx, fx16 *ty)
{
    fx_kin_chain ch;
    demo_arm_chain(x0, y0, &ch);
    /* a fresh page, a reset clock or a long gap: the straight arm again,
     * from frame 0 when headless so its picture shows the chase (never
     * more than 4 periods of steps at once) */
    if (!st->arm_ready || f < st->arm_frame || f - st->arm_frame > 4 * ARM_PERIOD) {
        fx16 p[2 * (DEMO_ARM_LINKS + 1)];
        memset(st->arm_theta, 0, sizeof st->arm_theta);
        fx_kin_forward(&ch, st->arm_theta, p);
        st->arm_aim[0] = p[2 * DEMO_ARM_LINKS];
        st->arm_aim[1] = p[2 * DEMO_ARM_LINKS + 1];
        st->arm_frame = st->interactive || f > 4 * ARM_PERIOD ? f : 0;
        st->arm_ntrail = 0;
        st->arm_ready = 1;
    }
    while (st->arm_frame < f) {
        fx16 gx, gy, end[2];
        st->arm_frame++;
        arm_target(st->arm_frame, x0, y0, &gx, &gy);
        fx_kin_follow(&ch, st->arm_theta, &st->arm_aim[0], &st->arm_aim[1], gx, gy, ARM_SPEED, 1, FX16_ONE / 64,
                      64, end);
        if (st->arm_ntrail == DEMO_ARM_TRAIL) {
            memmove(st->arm_trail, st->arm_trail + 2, (2 * DEMO_ARM_TRAIL - 2) * sizeof st->arm_trail[0]);
            st->arm_ntrail--;
        }
        st->arm_trail[2 * st->arm_ntrail] = end[0];
        st->arm_trail[2 * st->arm_ntrail + 1] = end[1];
        st->arm_ntrail++;
    }
    arm_target(st->arm_frame, x0, y0, tx, ty);
}

static void draw_arm(fx_ctx *c, demo_state *st, uint32_t f, int32_t x0, int32_t y0)
{
    box(c, x0, y0, ARM_W, ARM_H);
    fx16 tx, ty, p[2 * (DEMO_ARM_LINKS + 1)];
    demo_arm_advance(st, f, x0, y0, &tx, &ty);
    fx_ctx_set_color(c, 0xFF505A6Au); /* the target's path */
    int32_t ox = 0, oy = 0;
    for (uint32_t i = 0; i <= 96; i++) {
        fx16 x, y;
        arm_target(i * ARM_PERIOD / 96, x0, y0, &x, &y);
        if (i)
            fx_line(c, ox, oy, fx16_round(x), fx16_round(y));
        ox = fx16_round(x), oy = fx16_round(y);
    }
    fx_ctx_set_color(c, 0xFF60D080u); /* where the end has been */
    for (int32_t i = 1; i < st->arm_ntrail; i++)
        fx_line(c, fx16_round(st->arm_trail[2 * i - 2]), fx16_round(st->arm_trail[2 * i - 1]),
                fx16_round(st->arm_trail[2 * i]), fx16_round(st->arm_trail[2 * i + 1]));
    int32_t gx = fx16_round(tx), gy = fx16_round(ty);
    fx_ctx_set_color(c, 0xFFFF4040u);
    fx_line(c, gx - 7, gy, gx + 7, gy);
    fx_line(c, gx, gy - 7, gx, gy + 7);
    fx_circle(c, gx, gy, 6);
    fx_kin_chain ch;
    demo_arm_chain(x0, y0, &ch);
    fx_kin_forward(&ch, st->arm_theta, p);
    fx_ctx_set_color(c, DIM);
    fx_fill_rect(c, fx16_round(ch.x) - 12, fx16_round(ch.y), 25, 6);
    fx_ctx_set_color(c, 0xFF3C8CD0u);
    for (int32_t i = 0; i < DEMO_ARM_LINKS; i++)
        for (int32_t d = -1; d <= 1; d++) /* three pixels thick */
            fx_line(c, fx16_round(p[2 * i]) + d, fx16_round(p[2 * i + 1]), fx16_round(p[2 * i + 2]) + d,
                    fx16_round(p[2 * i + 3]));
    fx_ctx_set_color(c, INK);
    for (int32_t i = 0; i < DEMO_ARM_LINKS; i++)
        fx_circle(c, fx16_round(p[2 * i]), fx16_round(p[2 * i + 1]), 3);
    fx_ctx_set_color(c, ACCENT);
    fx_disc(c, fx16_round(p[2 * DEMO_ARM_LINKS]), fx16_round(p[2 * DEMO_ARM_LINKS + 1]), 3);
    demo_text(c, x0 + 6, y0 + 5, ACCENT, "Arm: CCD inverse kinematics");
    demo_text(c, x0 + 6, y0 + 18, DIM, "goal-directed, 3 px a frame");
}

/* ---- 3D: the flight ---- */

static void draw_mesh(fx3d *rd, const fx_mesh_params *mp, fx_color col, fx16 x, fx16 y, fx16 z)
{
    int32_t nv, nt;
    if (fx_mesh_size(mp, &nv, &nt) < 0)
        return;
    fx_mesh m;
    memset(&m, 0, sizeof m);
    m.pos = malloc((size_t)nv * 2 * sizeof(fx_vec3));
    m.tri = malloc((size_t)nt * 3 * sizeof(uint32_t));
    if (m.pos && m.tri) {
        m.nrm = m.pos + nv;
        m.cap_verts = nv;
        m.cap_tris = nt;
        if (fx_mesh_make(&m, mp) == 0) {
            rd->mat.ambient = rd->mat.diffuse = fx3d_rgb_from_color(col);
            fx_mat_stack_push(&rd->model);
            fx_mat4 t;
            fx_mat4_translate(&t, x, y, z);
            fx_mat_stack_mult(&rd->model, &t);
            fx3d_draw(rd, &m);
            fx_mat_stack_pop(&rd->model);
        }
    }
    free(m.tri);
    free(m.pos);
}

static void draw_world(fx_ctx *c, const demo_state *st, fx_rect r)
{
    fx_surface s = fx_surface_sub(c->surf, r);
    void *z = malloc(fx3d_depth_bytes(&s, 32));
    fx3d *rd = malloc(sizeof *rd);
    fx_mat4 ms[4], ps[2];
    if (z && rd && fx3d_init(rd, &s, ms, 4, ps, 2) == 0) {
        fx3d_set_depth(rd, z, 32);
        fx_camera_view(&st->acam, &rd->view);
        fx3d_perspective(rd, fx_angle_from_deg(50), fx16_from_ratio(s.w, s.h), FX16_ONE / 4, 60 * FX16_ONE);
        rd->light[0].type = FX3D_LIGHT_DIRECTIONAL;
        rd->light[0].pos = fx_vec3_make(FX16_ONE, 2 * FX16_ONE, FX16_ONE);
        rd->mat.specular = fx3d_rgb_from_color(0x808080);
        rd->mat.shininess = 30;
        rd->shading = FX3D_GOURAUD;
        fx_mesh_params floor = {FX_MESH_PLANE, 12 * FX16_ONE, 0, 0, 12, 0};
        fx_mesh_params cube = {FX_MESH_CUBE, 2 * FX16_ONE, 0, 0, 0, 0};
        fx_mesh_params cone = {FX_MESH_CONE, FX16_ONE, 3 * FX16_ONE, 0, 24, 0};
        fx_mesh_params ball = {FX_MESH_SPHERE, FX16_ONE, 0, 0, 20, 12};
        draw_mesh(rd, &floor, 0xFF304050u, 0, 0, 0);
        draw_mesh(rd, &cube, 0xFFC04020u, -2 * FX16_ONE, FX16_ONE, 0);
        draw_mesh(rd, &cone, 0xFF40A060u, 2 * FX16_ONE, 0, -FX16_ONE);
        draw_mesh(rd, &ball, 0xFF4070D0u, FX16_ONE / 2, FX16_ONE, 2 * FX16_ONE);
    }
    free(rd);
    free(z);
}

/* the flight seen from above: the spline through the keys, the camera now */
static void draw_map(fx_ctx *c, const demo_state *st, int32_t x0, int32_t y0, int32_t size)
{
    box(c, x0, y0, size, size);
    int32_t mid = size / 2, scale = size / 20; /* 20 units across */
#define MX(v) (x0 + mid + fx16_round((fx16)((int64_t)(v) * scale)))
#define MY(v) (y0 + mid + fx16_round((fx16)((int64_t)(v) * scale)))
    if (st->nflight > 1) {
        fx_anim_track tr = flight_track(st);
        tr.ease = FX_EASE_NONE;
        fx16 v[FX_ANIM_MAX_CH], t1 = st->flight[st->nflight - 1].t;
        int32_t px = 0, py = 0;
        fx_ctx_set_color(c, DIM);
        for (int i = 0; i <= 80; i++) {
            fx_anim_eval(&tr, (fx16)((int64_t)t1 * i / 80), v);
            if (i)
                fx_line(c, px, py, MX(v[0]), MY(v[2]));
            px = MX(v[0]), py = MY(v[2]);
        }
    }
    fx_ctx_set_color(c, 0xFFFF4040u);
    for (int i = 0; i < st->nflight; i++)
        fx_fill_rect(c, MX(st->flight[i].v[0]) - 1, MY(st->flight[i].v[2]) - 1, 3, 3);
    fx_ctx_set_color(c, ACCENT);
    fx_disc(c, MX(st->acam.eye.x), MY(st->acam.eye.z), 3);
    fx_line(c, MX(st->acam.eye.x), MY(st->acam.eye.z), MX(st->acam.eye.x - 2 * st->acam.n.x),
            MY(st->acam.eye.z - 2 * st->acam.n.z));
#undef MX
#undef MY
}

void demo_anim_page(fx_ctx *c, demo_state *st, int32_t top)
{
    fx16 t = clock_of(st, 0);
    box(c, 8, top, 388, 400);
    draw_morph(c, t, 80, top + 90);
    draw_ball(c, t, 170, top + 20, 216, 140);
    draw_path(c, t, 16, top + 220);
    draw_arm(c, st, st->frame + (st->interactive ? 0 : 36), 204, top + 198);
    if (st->flying && st->nflight) {
        fx_anim_track tr = flight_track(st);
        fx16 v[FX_ANIM_MAX_CH], ft = clock_of(st, st->fly_from);
        fx_anim_eval(&tr, ft, v);
        set_cam(&st->acam, v);
        if (ft >= st->flight[st->nflight - 1].t && st->interactive)
            st->flying = 0; /* arrived: the camera rests on the last key */
    }
    box(c, 404, top, 388, 400);
    draw_world(c, st, (fx_rect){405, top + 1, 791, top + 399});
    draw_map(c, st, 404 + 388 - 101, top, 101);
    demo_text(c, 410, top + 5, ACCENT, "Camera flight: %d key%s%s", st->nflight, st->nflight == 1 ? "" : "s",
              st->flying ? ", flying" : "");
    box(c, 8, top + 408, 784, 36);
    demo_text(c, 16, top + 414, INK, "camera: u/d f/b h/j slide, y/Y yaw, t/T pitch;  k record a key, g fly the keys");
    demo_text(c, 16, top + 428, INK, "(spline, ease in/out), x clear%s", flight_file ? ";  keys saved to --flight FILE" : "");
}

/* The camera keys of the 3D and Animation pages (here, where the flight
 * test compiles this file alone): slides of STEP, turns of 5 degrees; 1
 * when the key was one of them. */
int demo_camera_key(fx_camera *cam, int key, fx16 step)
{
    fx_angle a = FX_ANGLE_45 / 9;
    switch (key) {
    case 'u': fx_camera_slide(cam, 0, step, 0); break;
    case 'd': fx_camera_slide(cam, 0, -step, 0); break;
    case 'f': fx_camera_slide(cam, 0, 0, -step); break;
    case 'b': fx_camera_slide(cam, 0, 0, step); break;
    case 'h': fx_camera_slide(cam, -step, 0, 0); break;
    case 'j': fx_camera_slide(cam, step, 0, 0); break;
    case 'y': fx_camera_yaw(cam, a); break;
    case 'Y': fx_camera_yaw(cam, (fx_angle)-a); break;
    case 't': fx_camera_pitch(cam, a); break;
    case 'T': fx_camera_pitch(cam, (fx_angle)-a); break;
    case 'o': fx_camera_roll(cam, a); break;
    case 'O': fx_camera_roll(cam, (fx_angle)-a); break;
    default: return 0;
    }
    return 1;
}

int demo_anim_key(demo_state *st, int key)
{
    /* no roll (o/O): a flight key holds the eye and the point looked at,
     * not the up vector, so a roll could not be flown back */
    if (key != 'o' && key != 'O' && demo_camera_key(&st->acam, key, FX16_ONE / 2))
        return 1;
    switch (key) {
    case 'x':
        st->nflight = 0;
        st->flying = 0;
        /* the file too: keys appended after a clear start again at t = 0,
         * and a reload stops where times stop increasing */
        if (flight_file) {
            char why[160];
            FILE *f = fx_fopen_regular_write(flight_file, 0, why, sizeof why);
            if (f)
                fclose(f);
            else
                fprintf(stderr, "fixel-demo: cannot clear the flight file %s: %s\n", flight_file, why);
        }
        break;
    case 'g':
        if (st->nflight < 2)
            return 1;
        st->flying = 1;
        st->fly_from = st->frame;
        break;
    case 'k': {
        if (st->nflight == DEMO_FLIGHT_MAX)
            return 1;
        fx_anim_key *k = &st->flight[st->nflight];
        cam_key(&st->acam, st->nflight ? st->flight[st->nflight - 1].t + KEY_GAP : 0, k);
        st->nflight++;
        if (flight_file) {
            char why[160] = "";
            FILE *f = fx_fopen_regular_write(flight_file, 1, why, sizeof why);
            int ok = f != NULL;
            if (f) {
                ok = fprintf(f, "%d %d %d %d %d %d %d\n", k->t, k->v[0], k->v[1], k->v[2], k->v[3], k->v[4], k->v[5]) > 0;
                ok = fclose(f) == 0 && ok;
            }
            if (!ok)
                fprintf(stderr, "fixel-demo: cannot save the flight key to %s: %s\n", flight_file,
                        why[0] ? why : strerror(errno));
        }
        break;
    }
    default: return 0;
    }
    return 1;
}
