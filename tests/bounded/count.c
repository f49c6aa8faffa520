/* SPDX-License-Identifier: MIT */
/* Runs one case of tests/core/bounded_cases.h (argv[1] = its number) on a
 * 16x16 surface, "none" for the process's own cost, "cases" to print how
 * many cases there are, or "control N" to draw
 * a visible 16-pixel line N times (work that grows with N, so the count is
 * seen to follow the work). tests/bounded/count.sh counts the instructions
 * under valgrind's lackey. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/bounded_cases.h"
#include "fixel/surface.h"

int main(int argc, char **argv)
{
    static uint32_t mem[W * H];
    fx_surface s;
    fx_surface_init(&s, mem, W, H, W * 4, FX_FMT_XRGB8888);
    fx_ctx c;
    fx_ctx_init(&c, &s);
    if (argc == 2 && !strcmp(argv[1], "none"))
        return 0;
    if (argc == 2 && !strcmp(argv[1], "cases")) {
        printf("%d\n", NCASES);
        return 0;
    }
    if (argc == 3 && !strcmp(argv[1], "control")) {
        for (long i = atol(argv[2]); i > 0; i--)
            fx_line(&c, 0, (int32_t)(i & 15), W - 1, 15 - (int32_t)(i & 15));
        return 0;
    }
    if (argc != 2)
        return 2;
    int k = atoi(argv[1]);
    if (k < 0 || k >= NCASES)
        return 2;
    run_case(k, &c);
    return 0;
}
