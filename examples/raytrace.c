/* SPDX-License-Identifier: MIT */
/* The ray tracer on every core, rows reported as they finish: a glass
 * sphere and a mirror cube-minus-sphere over a marble floor, written to
 * raytrace.png. A display program would present each finished band from
 * the callback (fx_display_present with the band as damage). */
#include <stdio.h>
#include <string.h>

#include <fixel/memfb.h>
#include <fixel/rt_mt.h>

static fx_mat4 at(fx16 x, fx16 y, fx16 z, fx16 s)
{
    fx_mat4 t, k, m;
    fx_mat4_translate(&t, x, y, z);
    fx_mat4_scale(&k, s, s, s);
    fx_mat4_mul(&m, &t, &k);
    return m;
}

static void rows_done(void *user, int32_t y0, int32_t y1)
{
    int32_t *done = user;
    *done += y1 - y0;
    fprintf(stderr, "\rrows %d..%d done (%d in all)", y0, y1 - 1, *done);
}

int main(void)
{
    const fx16 one = FX16_ONE;
    fx_rt_object objects[8];
    fx_rt_scene s;
    fx_rt_scene_init(&s, objects, 8);
    fx_rt_set_camera(&s, fx_vec3_make(0, 2 * one, 6 * one), fx_vec3_make(0, 0, 0), fx_vec3_make(0, one, 0),
                     40 * one);
    s.ambient = fx3d_rgb_from_color(0x303030);
    s.background = fx3d_rgb_from_color(0x203050);
    fx_rt_add_light(&s, fx_vec3_make(-4 * one, 6 * one, 5 * one), fx3d_rgb_from_color(0xFFFFFF), 0);

    fx_rt_material floor;
    memset(&floor, 0, sizeof floor);
    floor.ambient = fx3d_rgb_from_color(0x404040);
    floor.diffuse = fx3d_rgb_from_color(0xF0F0F0);
    floor.texture = FX_RT_TEX_MARBLE;
    floor.tex_color = fx3d_rgb_from_color(0x303848);
    floor.tex_scale = one;
    floor.ior = one;
    fx_mat4 m = at(0, -one, 0, one), turn;
    fx_mat4_rotate_x(&turn, fx_angle_from_deg(-90)); /* the plane z <= 0 becomes y <= -1 */
    fx_mat4_mul(&m, &m, &turn);
    fx_rt_add_shape(&s, FX_RT_PLANE, 0, &m, &floor);

    fx_rt_material glass = floor;
    glass.texture = FX_RT_TEX_NONE;
    glass.ambient = fx3d_rgb_from_color(0);
    glass.diffuse = fx3d_rgb_from_color(0x101010);
    glass.specular = fx3d_rgb_from_color(0xFFFFFF);
    glass.shininess = 100;
    glass.reflectivity = one / 10;
    glass.transparency = one * 85 / 100;
    glass.ior = one * 3 / 2;
    m = at(-one, 0, 0, one);
    fx_rt_add_shape(&s, FX_RT_SPHERE, 0, &m, &glass);

    fx_rt_material mirror = glass;
    mirror.transparency = 0;
    mirror.reflectivity = one * 8 / 10;
    mirror.ior = one;
    m = at(one * 6 / 5, 0, 0, one * 3 / 4);
    int cube = fx_rt_add_shape(&s, FX_RT_CUBE, 0, &m, &mirror);
    m = at(one * 6 / 5, 0, 0, one);
    int ball = fx_rt_add_shape(&s, FX_RT_SPHERE, 0, &m, &mirror);
    fx_rt_add_csg(&s, FX_RT_INTERSECTION, cube, ball); /* a rounded cube */

    fx_memfb fb;
    if (fx_memfb_create(&fb, 640, 400, FX_FMT_XRGB8888) < 0)
        return 1;
    int32_t done = 0;
    int r = fx_rt_render_mt(&s, &fb.surf, fx_rt_cpu_count(), 8, rows_done, &done);
    fprintf(stderr, "\n");
    if (r == 0)
        r = fx_write_png("raytrace.png", &fb.surf);
    fx_memfb_destroy(&fb);
    return r < 0;
}
