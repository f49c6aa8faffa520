/* SPDX-License-Identifier: MIT */
/* fixel-bench: a double-precision ray tracer over the same fx_rt_scene (the
 * same object matrices, taken as exact), written from the course's
 * definitions, that the fixed-point tracer is measured against (the
 * benchmark's raytrace table, tests/core/test_rt.c), and the benchmark's
 * scenes. */
#ifndef FX_TEST_RTREF_H
#define FX_TEST_RTREF_H

#include "fixel/rt.h"

typedef struct rtref_hit {
    double t;
    int obj, entering, flip;
} rtref_hit;

typedef struct rtref_list {
    int n, inside0;
    rtref_hit h[64];
} rtref_list;

/* Every crossing of the whole line S + c t with object i, sorted. */
void rtref_hits(const fx_rt_scene *s, int i, const double S[3], const double c[3], rtref_list *out);
/* Whether world point p is inside object i (the solid's definition). */
int rtref_inside(const fx_rt_scene *s, int i, const double p[3]);
/* Nearest hit beyond tmin: t, or -1; the unit world normal facing out. */
double rtref_first_hit(const fx_rt_scene *s, const double S[3], const double c[3], double tmin, int *obj,
                       double n[3]);
/* The colour of one pixel, as the fixed-point tracer computes it; *rays
 * (may be NULL) is increased by the rays traced (primary, reflected,
 * refracted and shadow feelers). */
fx_color rtref_pixel(const fx_rt_scene *s, int32_t w, int32_t h, int32_t x, int32_t y, long *rays);

/* The course's examples built through the API: 0 lens, 1 bowl, 2 rocket
 * (the CSG trees alone; the root's index is returned), and with camera,
 * lights and a floor for rendering: rtref_scene(0..2) the CSG scenes of
 * the golden scripts, 3 the glass and mirror spheres over a marble floor.
 * Returns the root (0..2) or 0, negative on error. */
int rtref_csg(fx_rt_scene *s, int which);
int rtref_scene(fx_rt_scene *s, fx_rt_object *mem, int cap, int which);
extern const char *const rtref_scene_names[4];
/* translate(t) * scale(s), the placement the scenes use */
fx_mat4 rtref_place(double tx, double ty, double tz, double sx, double sy, double sz);

#endif
