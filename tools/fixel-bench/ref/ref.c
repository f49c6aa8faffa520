/* The double-precision reference of W9 (and a plain store loop for W1),
 * compiled twice by bench.mk: as-is at -O2 -fno-tree-vectorize (peer "ref",
 * the baseline WORKLOADS.md names) and with -DREF_NATIVE at -O3
 * -march=native (peer "ref-native"). Kept in its own file so that the
 * project's flags never change what the baseline measures. */
#include "../bench.h"

#ifdef REF_NATIVE
#define REF(name) ref_native_##name
#else
#define REF(name) ref_##name
#endif

void REF(mandel)(uint32_t *dst)
{
    uint32_t pal[257];
    for (int n = 0; n < 256; n++)
        pal[n] = (uint32_t)(4 * n < 255 ? 4 * n : 255) * 0x010101u;
    pal[256] = 0;

    const double s = 3.0 / 1920;
    for (int y = 0; y < BH; y++) {
        double ci = (540.0 - (y + 0.5)) * s;
        uint32_t *row = dst + (size_t)y * BW;
        for (int x = 0; x < BW; x++) {
            double cr = -0.5 + ((x + 0.5) - 960.0) * s;
            double zr = 0, zi = 0;
            int n = 0;
            while (n < 256) {
                double zr2 = zr * zr, zi2 = zi * zi;
                if (zr2 + zi2 > 4.0)
                    break;
                zi = 2 * zr * zi + ci;
                zr = zr2 - zi2 + cr;
                n++;
            }
            row[x] = pal[n];
        }
    }
}

void REF(clear)(const struct target *t, uint32_t native)
{
    if (t->fmt == FMT_XRGB8888) {
        uint32_t *p = (uint32_t *)t->pixels;
        for (size_t i = 0; i < (size_t)BW * BH; i++)
            p[i] = native;
    } else {
        uint16_t *p = (uint16_t *)t->pixels;
        for (size_t i = 0; i < (size_t)BW * BH; i++)
            p[i] = (uint16_t)native;
    }
}
