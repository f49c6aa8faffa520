/* SPDX-License-Identifier: MIT */
/* libFuzzer target (issue #26): Wavefront OBJ files generated line by line
 * (v, vt, vn, f with v, v/t, v//n, v/t/n and negative indices, o, g, s,
 * usemtl, comments), every number at a corner (choice.h): coordinates near
 * +-2^15, 2^31, 2^63 and their fractions, indices 0, -1, past the end,
 * near 2^31. Then fuzz_obj.c's checks and 3D pipeline run on the text.
 * FUZZ_GRAMMAR_PRINT=1 prints the generated file. */
#include <stdlib.h>

#include "choice.h"

#define LLVMFuzzerTestOneInput obj_checks
#include "fuzz_obj.c"
#undef LLVMFuzzerTestOneInput

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static char text[16384];
    in s = {data, size};
    out o = {text, 0, sizeof text};
    text[0] = (char)take(&s, 1); /* fuzz_obj.c's mode byte */
    text[1] = 0;
    o.n = 1;
    int nv = 0;
    uint32_t lines = take(&s, 1) % 48;
    for (uint32_t l = 0; l < lines; l++) {
        uint32_t kind = take(&s, 1) % 12;
        if (kind < 4) { /* v x y z [w] */
            put(&o, kind == 3 ? "vn" : "v");
            for (int i = 0; i < 3 + (kind == 2); i++) {
                putc1(&o, ' ');
                put_dec(&o, corner(&s, -1024000, 1024000), (int)(take(&s, 1) % 4));
            }
            nv += kind < 3;
        } else if (kind == 4) {
            put(&o, "vt ");
            put_dec(&o, corner(&s, 0, 1000), 3);
            putc1(&o, ' ');
            put_dec(&o, corner(&s, 0, 1000), 3);
        } else if (kind < 9) { /* a face of 3.. vertices */
            put(&o, "f");
            uint32_t n = 3 + take(&s, 1) % 6;
            for (uint32_t i = 0; i < n; i++) {
                putc1(&o, ' ');
                uint32_t how = take(&s, 1);
                int64_t v = how & 1 ? corner(&s, -nv, nv) : 1 + (int64_t)(take(&s, 1) % (uint32_t)(nv + 1));
                put_dec(&o, v, 0);
                switch (how >> 1 & 3) {
                case 1: put(&o, "/"); put_dec(&o, corner(&s, -1, 4), 0); break;
                case 2: put(&o, "//"); put_dec(&o, corner(&s, -1, 4), 0); break;
                case 3: put(&o, "/1/"); put_dec(&o, corner(&s, -1, 4), 0); break;
                }
            }
        } else if (kind == 9) {
            static const char *const misc[] = {"o cube", "g a b", "s off", "s 1", "usemtl x", "mtllib x.mtl",
                                               "# comment", "", "l 1 2", "p 1", "vp 0.5", "\r"};
            put(&o, misc[take(&s, 1) % 12]);
        } else if (kind == 10) { /* the same face many times: one vertex in a huge fan */
            uint32_t n = take(&s, 1) % 64;
            for (uint32_t i = 0; i < n; i++)
                put(&o, "f 1 2 3\n");
            continue;
        } else {
            put(&o, "v 1e3 0x10 -0 +1 nan");
        }
        putc1(&o, '\n');
    }
    static int print = -1;
    if (print < 0)
        print = getenv("FUZZ_GRAMMAR_PRINT") != NULL;
    if (print)
        fprintf(stderr, "mode %02x\n%s\n", (uint8_t)text[0], text + 1);
    return obj_checks((const uint8_t *)text, o.n);
}
