/* SPDX-License-Identifier: MIT */
/* libFuzzer target: the PSF1/PSF2 font parser, and drawing text with
 * whatever it accepted (every glyph row read stays inside the buffer). */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/font.h"
#include "guard.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    /* an exact-size heap copy, so ASan catches a read one past the end */
    uint8_t *copy = malloc(size ? size : 1);
    memcpy(copy, data, size);
    fx_font f;
    if (fx_font_load(&f, copy, size) == 0) {
        guarded g;
        if (guarded_make(&g, 61, 23, FX_FMT_RGB565, 0) == 0) {
            fx_ctx c;
            fx_ctx_init(&c, &g.s);
            fx_text_style st = {&f, 1 + (int32_t)(size % 3), 0xFF000000u, (uint8_t)(size & 1),
                                (uint8_t)(size % 3)};
            c.text_style = &st;
            fx_text(&c, -3, 2, "Ag\xC3\xA9\xE2\x82\xAC?\x01");
            fx_text(&c, 40, -5, "wide text that runs off the edge");
            guarded_free(&g);
        }
        for (uint32_t cp = 0; cp < 600; cp += 7)
            (void)fx_font_glyph(&f, cp);
    }
    free(copy);
    return 0;
}
