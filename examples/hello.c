/* SPDX-License-Identifier: MIT */
#include <fixel/draw.h>
#include <fixel/line.h>
#include <fixel/memfb.h>

int main(void)
{
    fx_memfb fb;
    if (fx_memfb_create(&fb, 320, 240, FX_FMT_RGB565) < 0)
        return 1;
    fx_ctx c;
    fx_ctx_init(&c, &fb.surf);          /* clip = whole surface, colour white */
    fx_ctx_set_color(&c, 0xFF2060A0);   /* colours are 0xAARRGGBB */
    fx_fill_rect(&c, 10, 10, 100, 50);
    fx_line(&c, -1000, 200, 5000, -300); /* clipped exactly, never moved */
    int r = fx_write_png("hello.png", &fb.surf);
    fx_memfb_destroy(&fb);
    return r < 0;
}
