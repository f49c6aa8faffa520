/* SPDX-License-Identifier: MIT */
/* imgcmp A B: compare two pictures (PNG, or binary PPM for a .ppm name) as
 * 8-bit RGB. Exit 0 when equal; 1 with the size or the number of differing
 * pixels on stdout; 2 when one cannot be read. For the shell tests of
 * tests/boards/ and tests/tools/. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/error.h"
#include "fixel/memfb.h"

static int load(const char *path, uint8_t **rgb, int32_t *w, int32_t *h)
{
    size_t l = strlen(path);
    int r = l > 4 && !strcmp(path + l - 4, ".ppm") ? fx_read_ppm_rgb(path, rgb, w, h)
                                                    : fx_read_png_rgb(path, rgb, w, h);
    if (r < 0)
        printf("imgcmp: cannot read %s: %s\n", path, fx_strerror(r));
    return r;
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: imgcmp A B\n");
        return 2;
    }
    uint8_t *a = NULL, *b = NULL;
    int32_t aw, ah, bw, bh;
    if (load(argv[1], &a, &aw, &ah) < 0 || load(argv[2], &b, &bw, &bh) < 0) {
        free(a);
        return 2;
    }
    int rc = 0;
    if (aw != bw || ah != bh) {
        printf("imgcmp: %s is %dx%d, %s is %dx%d\n", argv[1], aw, ah, argv[2], bw, bh);
        rc = 1;
    } else {
        long bad = 0;
        for (size_t i = 0; i < (size_t)aw * (size_t)ah; i++)
            bad += memcmp(a + 3 * i, b + 3 * i, 3) != 0;
        if (bad) {
            printf("imgcmp: %ld of %ld pixels differ\n", bad, (long)aw * ah);
            rc = 1;
        }
    }
    free(a);
    free(b);
    return rc;
}
