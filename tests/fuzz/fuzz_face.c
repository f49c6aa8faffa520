/* SPDX-License-Identifier: MIT */
/* libFuzzer target: smooth text (boards/text/face.c) — hostile font files
 * through FreeType, and any bytes as text through HarfBuzz, FriBiDi,
 * libunibreak and the layout (wrap, align, ellipsis, fit, rotation) into a
 * guarded surface.
 * Input: byte 0 picks the mode and options, byte 1 the size, bytes 2-3 how
 * many of the rest are the font (mode 1) or nothing (mode 0: DejaVu Sans,
 * the rest all text). */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#include "fixel/face.h"
#include "guard.h"

#define DEJAVU "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 4)
        return 0;
    unsigned mode = data[0];
    int32_t px = 1 + data[1] % 48;
    size_t fontlen = (size_t)(data[2] | data[3] << 8);
    data += 4;
    size -= 4;
    char path[64] = DEJAVU;
    int fd = -1;
    if (mode & 1) {
        if (fontlen > size)
            fontlen = size;
        /* The font as a file FreeType opens, without touching the disk. */
        fd = memfd_create("fuzz-font", 0);
        if (fd < 0 || write(fd, data, fontlen) != (ssize_t)fontlen) {
            if (fd >= 0)
                close(fd);
            return 0;
        }
        snprintf(path, sizeof path, "/proc/self/fd/%d", fd);
        data += fontlen;
        size -= fontlen;
    }
    fx_face_opts o = {0};
    o.no_fallback = 1; /* fontconfig's chain is not under test here */
    o.cache_bytes = (mode & 2) ? 2048 : 0;
    o.mask_flags = (mode & 4) ? FX_MASK_GAMMA : 0;
    o.features = (mode & 8) ? "tnum,-liga,kern=0" : NULL;
    fx_face *f = NULL;
    if (fx_face_open(path, px, &o, &f, NULL, 0) == 0) {
        /* the text as an exact-size heap copy: a read past it is caught */
        char *s = malloc(size ? size : 1);
        memcpy(s, data, size);
        const fx_glyph *g;
        (void)fx_face_shape(f, s, size, &g);
        fx_text_metrics m;
        (void)fx_face_measure(f, s, size, &m);
        guarded gs;
        if (guarded_make(&gs, 67, 41, (mode & 16) ? FX_FMT_RGB565 : FX_FMT_XRGB8888, 0) == 0) {
            fx_ctx c;
            fx_ctx_init(&c, &gs.s);
            fx_ctx_set_color(&c, 0x80FFC040u);
            c.blend = (mode >> 5) & 1;
            (void)fx_face_draw(f, &c, -5 + (int32_t)(size % 40), 20, s, size, (mode >> 6) & 3);
            fx_textbox b = {{2, -3, 60, 38}, (uint8_t)(mode % 3), (uint8_t)((mode >> 3) & 1), 0, 0};
            (void)fx_face_draw_box(f, &c, &b, s, size, NULL, NULL);
            b.no_wrap = 1;
            (void)fx_face_draw_box(f, &c, &b, s, size, NULL, NULL);
            if (size < 64)
                (void)fx_face_fit(f, &b, s, size, 1, 64);
            guarded_free(&gs);
        }
        free(s);
        fx_face_close(f);
    }
    if (fd >= 0)
        close(fd);
    return 0;
}
