/* SPDX-License-Identifier: MIT */
/* Host side of the rig: renders a guest scene in memory and writes it as a
 * binary PPM, the expectation the guest's screen is compared with.
 * usage: host_render SCENE W H OUT.ppm */
#include <stdio.h>
#include <stdlib.h>

#include "fixel/surface.h"
#include "guest/scenes.h"

int main(int argc, char **argv)
{
    if (argc != 5) {
        fprintf(stderr, "usage: host_render SCENE W H OUT.ppm\n");
        return 2;
    }
    int32_t w = atoi(argv[2]), h = atoi(argv[3]);
    fx_surface s;
    uint8_t *px = calloc((size_t)w * (size_t)h, 4);
    uint8_t *rgb = malloc((size_t)w * 3);
    if (!px || !rgb || fx_surface_init(&s, px, w, h, w * 4, FX_FMT_XRGB8888) < 0)
        return 1;
    if (scene_draw(argv[1], &s) < 0) {
        fprintf(stderr, "host_render: unknown scene %s\n", argv[1]);
        return 2;
    }
    FILE *f = fopen(argv[4], "wb");
    if (!f)
        return 1;
    fprintf(f, "P6\n%d %d\n255\n", w, h);
    for (int32_t y = 0; y < h; y++) {
        fx_surface_row_to_rgb(&s, y, rgb);
        fwrite(rgb, 3, (size_t)w, f);
    }
    free(px);
    free(rgb);
    return fclose(f) ? 1 : 0;
}
