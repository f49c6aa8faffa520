/* SPDX-License-Identifier: MIT */
/* Textures: the course's lookup example, bilinear sampling against a double
 * reference, exact affine mapping, procedural textures and gradients. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/texture.h"
#include "fx_test.h"

static fx16 fxd(const char *s)
{
    fx16 v = 0;
    fx16_parse(s, (int)strlen(s), &v);
    return v;
}

FX_TEST(texture_course_lookup_example)
{
    enum { C = 600, R = 400 };
    uint32_t *px = malloc(sizeof(uint32_t) * C * R);
    for (int j = 0; j < R; j++)
        for (int i = 0; i < C; i++)
            px[j * C + i] = (uint32_t)i << 12 | (uint32_t)j;
    fx_texture tx = {.wrap = FX_TEX_REPEAT, .filter = FX_TEX_NEAREST};
    fx_surface_init(&tx.img, px, C, R, C * 4, FX_FMT_XRGB8888);
    fx_color c = fx_tex_lookup(&tx, fxd("0.261"), fxd("0.783"));
    FX_CHECK_EQ((c >> 12) & 0xFFF, 156);
    FX_CHECK_EQ(c & 0xFFF, 313);
    /* repeat and clamp outside the unit square */
    c = fx_tex_lookup(&tx, fxd("1.261"), fxd("-0.217"));
    FX_CHECK_EQ((c >> 12) & 0xFFF, 156);
    FX_CHECK_EQ(c & 0xFFF, 313);
    tx.wrap = FX_TEX_CLAMP;
    c = fx_tex_lookup(&tx, fxd("1.5"), fxd("-3"));
    FX_CHECK_EQ((c >> 12) & 0xFFF, C - 1);
    FX_CHECK_EQ(c & 0xFFF, 0);
    free(px);
}

FX_TEST(texture_bilinear_matches_reference)
{
    enum { TW = 7, TH = 5 };
    uint32_t px[TW * TH];
    uint32_t seed = 3;
    for (int i = 0; i < TW * TH; i++)
        px[i] = fx_test_rand(&seed);
    fx_texture tx = {.wrap = FX_TEX_REPEAT, .filter = FX_TEX_BILINEAR};
    fx_surface_init(&tx.img, px, TW, TH, TW * 4, FX_FMT_ARGB8888);
    /* at a texel centre: that texel */
    FX_CHECK_EQ_HEX(fx_tex_sample(&tx, (fx16)((2 * 2 + 1) * 65536 / (2 * TW)) + 1, (fx16)(3 * 65536 + 32768) / TH + 1),
                    px[3 * TW + 2]);
    int bad = 0;
    for (int k = 0; k < 5000; k++) {
        fx16 s = (fx16)(fx_test_rand(&seed) % (3 * 65536)) - 65536, t = (fx16)(fx_test_rand(&seed) % 65536);
        double u = s / 65536.0 * TW - 0.5, v = t / 65536.0 * TH - 0.5;
        double fu = floor(u * 256) / 256 - floor(u), fv = floor(v * 256) / 256 - floor(v);
        int i0 = (int)floor(u), j0 = (int)floor(v);
        int ia = ((i0 % TW) + TW) % TW, ib = (((i0 + 1) % TW) + TW) % TW;
        int ja = ((j0 % TH) + TH) % TH, jb = (((j0 + 1) % TH) + TH) % TH;
        fx_color got = fx_tex_sample(&tx, s, t);
        for (int sh = 0; sh < 32; sh += 8) {
            double e = ((px[ja * TW + ia] >> sh) & 0xFF) * (1 - fu) * (1 - fv) + ((px[ja * TW + ib] >> sh) & 0xFF) * fu * (1 - fv) +
                       ((px[jb * TW + ia] >> sh) & 0xFF) * (1 - fu) * fv + ((px[jb * TW + ib] >> sh) & 0xFF) * fu * fv;
            bad += fabs(((got >> sh) & 0xFF) - e) > 0.5 + 1e-9;
        }
    }
    FX_CHECK_EQ(bad, 0);
}

FX_TEST(texture_affine_mapping_is_exact_for_identity)
{
    enum { S = 64 };
    static uint32_t tex[S * S], img[S * S];
    for (int i = 0; i < S * S; i++)
        tex[i] = 0xFF000000u | (uint32_t)i * 2654435761u >> 8;
    fx_texture tx = {.wrap = FX_TEX_CLAMP, .filter = FX_TEX_NEAREST};
    fx_surface_init(&tx.img, tex, S, S, S * 4, FX_FMT_ARGB8888);
    fx_surface sf;
    fx_surface_init(&sf, img, S, S, S * 4, FX_FMT_ARGB8888);
    fx_ctx c;
    fx_ctx_init(&c, &sf);
    memset(img, 0, sizeof img);
    /* s = x / 64 at every pixel centre: the image is copied pixel for pixel */
    int32_t quad[8] = {0, 0, 63, 0, 63, 63, 0, 63};
    fx16 st[8] = {0, 0, 63 * 1024, 0, 63 * 1024, 63 * 1024, 0, 63 * 1024};
    fx_fill_poly_tex(&c, quad, st, 4, &tx);
    int bad = 0, drawn = 0;
    for (int y = 0; y < 63; y++)
        for (int x = 0; x < 63; x++) {
            drawn += img[y * S + x] != 0;
            bad += img[y * S + x] != tex[y * S + x];
        }
    FX_CHECK_EQ(drawn, 63 * 63);
    FX_CHECK_EQ(bad, 0);
}

FX_TEST(texture_procedural_values)
{
    FX_CHECK_EQ(fx_proc_fakesphere(FX16_HALF, FX16_HALF), FX16_ONE);
    for (int d = 0; d < 19661; d += 97) { /* linear fall-off 1 - r/0.3 */
        double e = 65536.0 * (1 - (d / 65536.0) / 0.3);
        FX_CHECK(fabs(fx_proc_fakesphere(FX16_HALF, FX16_HALF + d) - e) <= 1.0);
    }
    FX_CHECK_EQ(fx_proc_fakesphere(0, 0), 13107);
    FX_CHECK_EQ(fx_proc_fakesphere(FX16_HALF + fxd("0.3"), FX16_HALF), 13107);
    FX_CHECK(fx_proc_fakesphere(FX16_HALF + fxd("0.2999"), FX16_HALF) < 100);
    uint32_t seed = 1;
    int bad = 0;
    for (int k = 0; k < 20000; k++) {
        fx16 s = (fx16)(fx_test_rand(&seed) % (8 << 16)), t = (fx16)(fx_test_rand(&seed) % (8 << 16));
        for (int kind = 0; kind < FX_PROC_COUNT; kind++) {
            fx16 v = fx_proc_eval(kind, s, t, 7);
            bad += v < 0 || v > FX16_ONE;
            bad += v != fx_proc_eval(kind, s, t, 7);
        }
        /* noise is continuous: a 2^-16 step moves it by little */
        fx16 a = fx_proc_noise(s, t, 3), b = fx_proc_noise(s + 1, t, 3);
        bad += abs(a - b) > 8;
    }
    FX_CHECK_EQ(bad, 0);
    /* at lattice points noise is the hashed value itself, and seeds differ */
    int same = 0;
    for (int i = 0; i < 50; i++)
        same += fx_proc_noise(i << 16, 0, 1) == fx_proc_noise(i << 16, 0, 2);
    FX_CHECK(same < 3);
}

FX_TEST(texture_gradients)
{
    fx_gradient g = {.x0 = 10, .y0 = 0, .x1 = 110, .y1 = 0, .nstops = 2, .stops = {0xFF000000u, 0xFFFFFFFFu}};
    fx_color out[121];
    fx_gradient_shade(&g, 5, 0, 121, out);
    FX_CHECK_EQ_HEX(out[0], 0xFF000000u);
    FX_CHECK_EQ_HEX(out[10], 0xFF000000u);
    FX_CHECK_EQ_HEX(out[110], 0xFFFFFFFFu);
    FX_CHECK_EQ_HEX(out[120], 0xFFFFFFFFu);
    FX_CHECK_EQ_HEX(out[60], 0xFF808080u); /* 127.5 rounds up */
    int mono = 1;
    for (int i = 1; i < 121; i++)
        mono &= (out[i] & 0xFF) >= (out[i - 1] & 0xFF);
    FX_CHECK(mono);
    fx_gradient r = {.radial = 1, .x0 = 50, .y0 = 50, .r = 40, .nstops = 3,
                     .stops = {0xFFFF0000u, 0xFF00FF00u, 0xFF0000FFu}};
    fx_gradient_shade(&r, 50, 50, 1, out);
    FX_CHECK_EQ_HEX(out[0], 0xFFFF0000u);
    fx_gradient_shade(&r, 50, 70, 1, out); /* half way: the middle stop */
    FX_CHECK_EQ_HEX(out[0], 0xFF00FF00u);
    fx_gradient_shade(&r, 90, 50, 1, out);
    FX_CHECK_EQ_HEX(out[0], 0xFF0000FFu);
    FX_CHECK_EQ_HEX(fx_color_lerp(0x00000000u, 0xFF204060u, FX16_HALF), 0x80102030u);
}
