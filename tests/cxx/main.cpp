// SPDX-License-Identifier: MIT
// A C++ program using fixel (issue #20): every public header is included
// (build/cxx/all-headers.h, generated from the include directories by
// tests/cxx/cxx.sh, so a new header is covered without editing this file),
// compiled with g++ -std=c++11 -Wall -Wextra -Werror and linked once against
// libfixel.a and once against libfixel.so. Prints "cxx-<kind>: N passed, N failed".
#include "all-headers.h"
#include <cstdio>
#include <cstring>

static int passed, failed;
static void check(bool ok, const char *what)
{
    if (ok) passed++;
    else { failed++; std::printf("FAIL %s\n", what); }
}

int main(int argc, char **argv)
{
    const char *kind = argc > 1 ? argv[1] : "cxx";
    fx_memfb fb;
    check(fx_memfb_create(&fb, 64, 48, FX_FMT_RGB565) == 0, "fx_memfb_create");
    fx_ctx c;
    fx_ctx_init(&c, &fb.surf);
    fx_ctx_set_color(&c, 0xFF2060A0);
    fx_fill_rect(&c, 2, 2, 20, 10);
    fx_line(&c, -1000, 40, 5000, -300);   // clipped, never moved
    fx_color in = fx_surface_get(&fb.surf, 5, 5);
    fx_color out = fx_surface_get(&fb.surf, 40, 45);
    check(fx_pack(FX_FMT_RGB565, in) == fx_pack(FX_FMT_RGB565, 0xFF2060A0), "fill_rect pixel");
    check(fx_pack(FX_FMT_RGB565, out) == 0, "untouched pixel");
    check(std::strcmp(fx_version(), FX_VERSION_STRING) == 0, "fx_version() == FX_VERSION_STRING");
    check(fx_version_number() == FX_VERSION_NUMBER, "fx_version_number() == FX_VERSION_NUMBER");
    check(fx16_mul(FX16_ONE * 3, FX16_ONE / 2) == FX16_ONE * 3 / 2, "fx16_mul");
    fx_memfb_destroy(&fb);
    std::printf("fixel %s from C++\n", fx_version());
    std::printf("%s: %d passed, %d failed\n", kind, passed, failed);
    return failed != 0;
}
