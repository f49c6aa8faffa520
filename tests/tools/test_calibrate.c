/* SPDX-License-Identifier: MIT */
/* fixel-calibrate's fit (tools/fixel-calibrate/fit.c): known transforms are
 * recovered from the five targets, written as pointercal integers that the
 * library's own parser and mapping (fx_calib_parse, fx_input) turn back into
 * the target pixels; rotated displays; degenerate touches refused. */
#include "fx_test.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../tools/fixel-calibrate/fit.c"
#include "fixel/input.h"

/* raw = inverse of screen = A*raw + b: build raw points for given targets */
static void make_points(cal_point *p, const int32_t (*t)[2], int n, double m00, double m01, double m10,
                        double m11, double ox, double oy)
{
    /* raw = M * screen + o */
    for (int i = 0; i < n; i++) {
        p[i].sx = t[i][0];
        p[i].sy = t[i][1];
        p[i].rx = m00 * t[i][0] + m01 * t[i][1] + ox;
        p[i].ry = m10 * t[i][0] + m11 * t[i][1] + oy;
    }
}

static const int32_t T[6][2] = {{30, 30}, {769, 30}, {769, 449}, {30, 449}, {400, 240}, {200, 360}};

static int32_t got_x, got_y, got_n;
static void on_event(void *user, const fx_event *e)
{
    (void)user;
    if (e->type == FX_EVENT_MOUSE || e->type == FX_EVENT_TOUCH || e->type == FX_EVENT_MOTION) {
        got_x = e->x;
        got_y = e->y;
        got_n++;
    }
}

/* Through the library: the pointercal text parsed by fx_calib_parse, a
 * touch fed to fx_input on an 800x480 panel at rotation rot; the logical
 * pixel it reports. */
static void library_maps_rot(const int32_t c[7], int rot, int32_t rx, int32_t ry, int32_t *x, int32_t *y)
{
    char text[128];
    snprintf(text, sizeof text, "%d %d %d %d %d %d %d 800 480", c[0], c[1], c[2], c[3], c[4], c[5], c[6]);
    fx_input in;
    fx_input_dev d;
    fx_input_init(&in, 800, 480, rot);
    fx_input_dev_init(&d, FX_DEV_TOUCH);
    d.abs_min[0] = d.abs_min[1] = -100000;
    d.abs_max[0] = d.abs_max[1] = 100000;
    FX_CHECK_EQ(fx_calib_parse(&d.calib, text, (unsigned)strlen(text)), 0);
    FX_CHECK(d.calib.valid);
    const fx_raw_event ev[] = {{0, 3, 0, rx}, {0, 3, 1, ry}, {0, 1, 0x14a, 1}, {0, 0, 0, 0}}; /* ABS_X/Y, BTN_TOUCH, SYN */
    got_n = 0;
    for (int i = 0; i < 4; i++)
        fx_input_feed(&in, &d, &ev[i], on_event, NULL);
    FX_CHECK(got_n > 0);
    *x = got_x;
    *y = got_y;
}

static void library_maps(const int32_t c[7], int32_t rx, int32_t ry, int32_t *x, int32_t *y)
{
    library_maps_rot(c, 0, rx, ry, x, y);
}

FX_TEST(calibrate_fit_scale_and_offset)
{
    cal_point p[6];
    /* a resistive panel: 0..4095 over 800x480 with an offset, y inverted */
    make_points(p, T, 6, 4.9, 0, 0, -8.1, 120, 4000);
    double a[6];
    FX_CHECK_EQ(cal_fit(p, 5, a), 0);
    FX_CHECK(fabs(a[0] - 1 / 4.9) < 1e-9);
    FX_CHECK(fabs(a[1]) < 1e-9);
    FX_CHECK(fabs(a[3]) < 1e-9);
    FX_CHECK(fabs(a[4] + 1 / 8.1) < 1e-9);
    FX_CHECK(fabs(a[2] + 120 / 4.9) < 1e-6);
    int32_t c[7];
    FX_CHECK_EQ(cal_pointercal(a, c), 0);
    FX_CHECK_EQ(c[6], 65536);
    FX_CHECK_EQ(c[0], (int32_t)lround(65536 / 4.9));
    /* every target, the unfitted check point too, within a pixel */
    for (int i = 0; i < 6; i++) {
        int32_t x, y;
        library_maps(c, (int32_t)lround(p[i].rx), (int32_t)lround(p[i].ry), &x, &y);
        FX_CHECK_MSG(abs(x - T[i][0]) <= 1 && abs(y - T[i][1]) <= 1, "target %d: %d,%d want %d,%d", i, x, y,
                     T[i][0], T[i][1]);
    }
}

/* Panel axes swapped and a little shear (a touch film glued askew). */
FX_TEST(calibrate_fit_swapped_axes_and_shear)
{
    cal_point p[6];
    make_points(p, T, 6, 0.3, 7.5, 5.0, -0.2, 300, 100);
    double a[6];
    FX_CHECK_EQ(cal_fit(p, 5, a), 0);
    /* the fitted map is the inverse of [[0.3 7.5][5 -0.2]] */
    double det = 0.3 * -0.2 - 7.5 * 5.0;
    FX_CHECK(fabs(a[0] - (-0.2 / det)) < 1e-9);
    FX_CHECK(fabs(a[1] - (-7.5 / det)) < 1e-9);
    FX_CHECK(fabs(a[3] - (-5.0 / det)) < 1e-9);
    FX_CHECK(fabs(a[4] - (0.3 / det)) < 1e-9);
    int32_t c[7];
    FX_CHECK_EQ(cal_pointercal(a, c), 0);
    int32_t x, y;
    library_maps(c, (int32_t)lround(p[5].rx), (int32_t)lround(p[5].ry), &x, &y);
    FX_CHECK_MSG(abs(x - T[5][0]) <= 1 && abs(y - T[5][1]) <= 1, "check point %d,%d", x, y);
}

/* Touches a few units off: least squares spreads the error. */
FX_TEST(calibrate_fit_noisy_touches)
{
    cal_point p[6];
    make_points(p, T, 6, 5, 0, 0, 8, 0, 0);
    static const double noise[5][2] = {{6, -4}, {-5, 3}, {4, 7}, {-7, -2}, {2, -4}};
    for (int i = 0; i < 5; i++)
        p[i].rx += noise[i][0], p[i].ry += noise[i][1];
    double a[6];
    FX_CHECK_EQ(cal_fit(p, 5, a), 0);
    int32_t c[7];
    FX_CHECK_EQ(cal_pointercal(a, c), 0);
    int32_t x, y;
    cal_apply(c, (int32_t)lround(p[5].rx), (int32_t)lround(p[5].ry), &x, &y);
    FX_CHECK_MSG(abs(x - T[5][0]) <= 2 && abs(y - T[5][1]) <= 2, "check point %d,%d", x, y);
}

FX_TEST(calibrate_fit_refuses_degenerate_touches)
{
    cal_point p[5];
    for (int i = 0; i < 5; i++) { /* all on one line */
        p[i].rx = 100 + 50 * i;
        p[i].ry = 200 + 25 * i;
        p[i].sx = T[i][0];
        p[i].sy = T[i][1];
    }
    double a[6];
    FX_CHECK_EQ(cal_fit(p, 5, a), -1);
    for (int i = 0; i < 5; i++) /* the same point every time */
        p[i].rx = p[i].ry = 1000;
    FX_CHECK_EQ(cal_fit(p, 5, a), -1);
    FX_CHECK_EQ(cal_fit(p, 2, a), -1);
    /* a map too steep for 32-bit pointercal */
    double big[6] = {40000, 0, 0, 0, 1, 0};
    int32_t c[7];
    FX_CHECK_EQ(cal_pointercal(big, c), -1);
}

/* The targets' physical pixels under rotation are where the display shows
 * them: mapping back with the library's fx_input_to_logical gives the
 * logical target again. */
FX_TEST(calibrate_targets_follow_rotation)
{
    static const int rots[4] = {0, 90, 180, 270};
    for (int r = 0; r < 4; r++) {
        fx_input in;
        fx_input_init(&in, 800, 480, rots[r]);
        int32_t lw, lh;
        fx_input_logical_size(&in, &lw, &lh);
        const int32_t pts[3][2] = {{30, 30}, {lw - 31, 30}, {lw / 4, (3 * lh) / 4}};
        for (int i = 0; i < 3; i++) {
            int32_t px, py, lx, ly;
            cal_logical_to_physical(rots[r], 800, 480, pts[i][0], pts[i][1], &px, &py);
            FX_CHECK(px >= 0 && px < 800 && py >= 0 && py < 480);
            fx_input_to_logical(&in, px, py, &lx, &ly);
            FX_CHECK_MSG(lx == pts[i][0] && ly == pts[i][1], "rotation %d: %d,%d -> %d,%d -> %d,%d", rots[r],
                         pts[i][0], pts[i][1], px, py, lx, ly);
        }
    }
}

/* The whole chain on a display turned 90: targets placed logically, fitted
 * to physical pixels, and a touch on each comes back as the logical target. */
FX_TEST(calibrate_fit_rotated_display_end_to_end)
{
    static const int rots[3] = {90, 180, 270};
    for (int r = 0; r < 3; r++) {
        int32_t lw = rots[r] == 180 ? 800 : 480, lh = rots[r] == 180 ? 480 : 800;
        const int32_t lt[6][2] = {{30, 30}, {lw - 31, 30}, {lw - 31, lh - 31}, {30, lh - 31}, {lw / 2, lh / 2},
                                  {lw / 4, (3 * lh) / 4}};
        int32_t pt[6][2];
        for (int i = 0; i < 6; i++)
            cal_logical_to_physical(rots[r], 800, 480, lt[i][0], lt[i][1], &pt[i][0], &pt[i][1]);
        cal_point p[6];
        make_points(p, (const int32_t(*)[2])pt, 6, 5.1, 0, 0, 8.3, 200, 150);
        double a[6];
        int32_t c[7];
        FX_CHECK_EQ(cal_fit(p, 5, a), 0);
        FX_CHECK_EQ(cal_pointercal(a, c), 0);
        for (int i = 0; i < 6; i++) {
            int32_t x, y;
            library_maps_rot(c, rots[r], (int32_t)lround(p[i].rx), (int32_t)lround(p[i].ry), &x, &y);
            FX_CHECK_MSG(abs(x - lt[i][0]) <= 1 && abs(y - lt[i][1]) <= 1, "rotation %d target %d: %d,%d want %d,%d",
                         rots[r], i, x, y, lt[i][0], lt[i][1]);
        }
    }
}
