/* SPDX-License-Identifier: MIT */
/* fixel — grass, fire and the terrain mesh (contracts in randfract.h). */
#include "fixel/randfract.h"
#include "fixel/error.h"
#include "fixel/turtle.h"
#include "../base/fx_internal.h"

static uint32_t below(uint32_t *st, uint32_t n) { return (uint32_t)(((uint64_t)fx_rand32(st) * n) >> 32); }

/* ---- grass ---- */

typedef struct blade_job {
    fx_turtle t;
    uint32_t *st;
    fx16 up; /* +1 in the course frame, -1 on the y-down screen: see fx_grass */
} blade_job;

/* A blade of `len` px from the turtle's position along its heading, in
 * eight steps bent by `curl` degrees each (Q16.16) plus jitter. */
static void blade(blade_job *j, fx16 len, fx16 curl, int depth)
{
    fx16 step = len / 8;
    for (int i = 0; i < 8; i++) {
        fx_turtle_turn(&j->t, j->up * (curl + fx16_mul(fx_gauss16(j->st), 3 << 16)));
        fx_turtle_forward(&j->t, step, 1);
        if (depth < 2 && i >= 2 && i < 7 && below(j->st, 8) == 0) {
            /* a side shoot: F -> F[+F]F, the bracket saving the turtle */
            fx_turtle save = j->t;
            fx16 ang = (fx16)((20 + below(j->st, 21)) << 16);
            fx_turtle_turn(&j->t, j->up * (below(j->st, 2) ? ang : -ang));
            blade(j, fx16_mul(step, (8 - i) * 39322 /* 0.6 */), curl, depth + 1);
            save.segs = j->t.segs;
            j->t = save;
        }
    }
}

int32_t fx_grass(const fx_ctx *c, fx_rect r, uint32_t nblades, uint32_t seed)
{
    if (!c || fx_rect_empty(r) || nblades > FX_GRASS_MAX_BLADES || r.x0 < -32767 || r.y0 < -32767 ||
        r.x1 > 32767 || r.y1 > 32767)
        return -FX_EINVAL;
    uint32_t st = seed ? seed : 1;
    int32_t w = r.x1 - r.x0, h = r.y1 - r.y0;
    fx_ctx cc = *c;
    uint64_t segs = 0;
    for (uint32_t b = 0; b < nblades; b++) {
        /* brightness 60 .. 124 % of the context's colour, per blade */
        uint32_t k = 154 + below(&st, 164), col = c->color;
        uint32_t rr = FX_MIN(255u, (col >> 16 & 255) * k / 256), gg = FX_MIN(255u, (col >> 8 & 255) * k / 256),
                 bb = FX_MIN(255u, (col & 255) * k / 256);
        fx_ctx_set_color(&cc, (col & 0xFF000000u) | rr << 16 | gg << 8 | bb);
        blade_job j;
        int32_t root = c->coords == FX_COORDS_COURSE ? r.y0 : r.y1 - 1; /* the picture's bottom row */
        fx16 x = (fx16)((r.x0 + (int32_t)below(&st, (uint32_t)w)) * 65536), y = (fx16)(root * 65536);
        /* Blades grow up the picture in both frames: the turtle turns from
         * +x towards +y of the frame (issue #44), so on the y-down screen
         * every angle is mirrored, which draws the blades of before. */
        j.up = c->coords == FX_COORDS_COURSE ? 1 : -1;
        fx_turtle_init(&j.t, &cc, x, y, j.up * ((90 << 16) + fx16_mul(fx_gauss16(&st), 10 << 16)));
        j.st = &st;
        fx16 len = (fx16)(((int64_t)h << 16) * (128 + below(&st, 129)) / 256);
        fx16 curl = fx16_mul(fx_gauss16(&st), 3 << 16);
        blade(&j, len, curl, 0);
        segs += j.t.segs;
    }
    return (int32_t)FX_MIN(segs, (uint64_t)INT32_MAX);
}

/* ---- fire ---- */

fx_color fx_fire_color(int32_t heat)
{
    int32_t i = heat < 0 ? 0 : heat > 255 ? 255 : heat;
    uint32_t r = (uint32_t)FX_MIN(255, 3 * i), g = (uint32_t)FX_MAX(0, FX_MIN(255, 3 * i - 255)),
             b = (uint32_t)FX_MAX(0, FX_MIN(255, 3 * i - 510));
    return 0xFF000000u | r << 16 | g << 8 | b;
}

static uint32_t hash3(uint32_t seed, int32_t x, int32_t y)
{
    uint32_t h = seed * 0x9E3779B1u ^ (uint32_t)x * 0x85EBCA77u ^ (uint32_t)y * 0xC2B2AE3Du;
    h ^= h >> 15;
    h *= 0x2C1B3C6Du;
    h ^= h >> 12;
    h *= 0x297A2D39u;
    h ^= h >> 15;
    return h & 255;
}

/* Value noise 0..255 on a lattice of lx x ly px, bilinear. */
static int32_t vnoise(uint32_t seed, int32_t x, int32_t y, int32_t lx, int32_t ly)
{
    int32_t ix = x / lx, iy = y / ly;
    int32_t fx = (x % lx) * 256 / lx, fy = (y % ly) * 256 / ly;
    int32_t a = (int32_t)hash3(seed, ix, iy), b = (int32_t)hash3(seed, ix + 1, iy);
    int32_t c = (int32_t)hash3(seed, ix, iy + 1), d = (int32_t)hash3(seed, ix + 1, iy + 1);
    int32_t top = a * 256 + (b - a) * fx, bot = c * 256 + (d - c) * fx;
    return (top * 256 + (bot - top) * fy) >> 16;
}

#define FIRE_K 8
#define FIRE_N (1 << FIRE_K)

int fx_fire(const fx_ctx *c, fx_rect r, fx16 rough, uint32_t seed)
{
    if (!c || fx_rect_empty(r) || rough < 0 || rough > FX16_ONE || r.x0 < 0 || r.y0 < 0 || r.x1 > (1 << 20) ||
        r.y1 > (1 << 20))
        return -FX_EINVAL;
    uint32_t st = seed ? seed : 1;
    /* the outline: tongue heights in Q16.16 fractions of the rectangle,
     * raised or lowered at each midpoint by up to amp, amp * 2^-rough per level */
    int32_t t[FIRE_N + 1];
    fx16 scale = fx16_exp2(-rough);
    int32_t amp = 1 << 15;
    t[0] = (1 << 15) + (int32_t)below(&st, 1 << 14);
    t[FIRE_N] = (1 << 15) + (int32_t)below(&st, 1 << 14);
    for (int s = FIRE_N; s > 1; s /= 2) {
        amp = (int32_t)(((int64_t)amp * scale) >> 16);
        for (int i = s / 2; i < FIRE_N; i += s) {
            int32_t m = (t[i - s / 2] + t[i + s / 2]) / 2 + (int32_t)below(&st, 2 * (uint32_t)amp + 1) - amp;
            t[i] = FX_MAX(1 << 13, FX_MIN(1 << 16, m));
        }
    }
    int32_t w = r.x1 - r.x0, h = r.y1 - r.y0;
    fx_rect cl = fx_rect_intersect(c->clip, r);
    int32_t lx = FX_MAX(4, w / 12), ly = FX_MAX(4, h / 6);
    for (int32_t x = cl.x0; x < cl.x1; x++) {
        /* the profile at x, interpolated between samples (Q16.16 fraction) */
        int64_t pos = (int64_t)(x - r.x0) * FIRE_N * 256 / w;
        int32_t i = (int32_t)(pos >> 8), f = (int32_t)(pos & 255);
        int32_t tx = i >= FIRE_N ? t[FIRE_N] : (int32_t)(t[i] + (((int64_t)(t[i + 1] - t[i]) * f) >> 8));
        /* a parabolic envelope (0.3 at the sides, 1 in the middle): the
         * fire is a blaze, not a wall cut off by the rectangle */
        int64_t uu = (int64_t)(2 * (x - r.x0) + 1) * 256 / (2 * w); /* 0..256 */
        int64_t env = 77 + (179 * 4 * uu * (256 - uu) >> 16);    /* /256 */
        int64_t top = ((int64_t)tx * h * env >> 8) + 65536; /* tongue height in Q16.16 px */
        for (int32_t y = cl.y0; y < cl.y1; y++) {
            int64_t u = (int64_t)(r.y1 - 1 - y) << 16;
            int32_t base = (int32_t)((top - u) * 270 / top); /* 270 at the foot, 0 at the tip */
            if (base < -96)
                continue;
            int32_t xx = x - r.x0, yy = r.y1 - 1 - y;
            int32_t n = (4 * vnoise(seed, xx, yy, lx, ly) + 2 * vnoise(seed + 1, xx, yy, FX_MAX(2, lx / 2), FX_MAX(2, ly / 2)) +
                         vnoise(seed + 2, xx, yy, FX_MAX(1, lx / 4), FX_MAX(1, ly / 4))) / 7;
            int32_t heat = base + (n - 128) * 3 / 4;
            if (heat < 24)
                continue;
            fx_surface_put_native(&c->surf, x, y, fx_pack(c->surf.format, fx_fire_color(heat)));
        }
    }
    return 0;
}

/* ---- terrain mesh ---- */

int fx_terrain_mesh_size(int k, int32_t *nverts, int32_t *ntris)
{
    if (k < 1 || k > FX_TERRAIN_MESH_MAX_K || !nverts || !ntris)
        return -FX_EINVAL;
    int32_t n = 1 << k;
    *nverts = (n + 1) * (n + 1);
    *ntris = 2 * n * n;
    return 0;
}

fx_color fx_terrain_color(fx16 t)
{
    static const struct {
        fx16 at;
        fx_color c;
    } stops[] = {
        {0, 0xFFD2C08Au},     {5243, 0xFF5E9A3Cu},  {26214, 0xFF2F6B2Au}, {40632, 0xFF7A6450u},
        {52429, 0xFF8E8A86u}, {58982, 0xFFF2F2F6u}, {65536, 0xFFFFFFFFu},
    };
    if (t <= 0)
        return stops[0].c;
    for (unsigned i = 1; i < FX_ARRAY_LEN(stops); i++)
        if (t <= stops[i].at) {
            int64_t f = ((int64_t)(t - stops[i - 1].at) << 8) / (stops[i].at - stops[i - 1].at);
            fx_color a = stops[i - 1].c, b = stops[i].c, o = 0xFF000000u;
            for (int sh = 0; sh < 24; sh += 8) {
                int64_t ca = a >> sh & 255, cb = b >> sh & 255;
                o |= (uint32_t)(ca + (((cb - ca) * f) >> 8)) << sh;
            }
            return o;
        }
    return 0xFFFFFFFFu;
}

int fx_terrain_peak(int32_t *h, int32_t stride, int k, int32_t amp)
{
    if (!h || k < 1 || k > 12 || amp < -(1 << 28) || amp > (1 << 28) || stride < (1 << k) + 1)
        return -FX_EINVAL;
    int64_t n = (int64_t)1 << k, r2 = n * n / 4;
    for (int64_t j = 0; j <= n; j++)
        for (int64_t i = 0; i <= n; i++) {
            int64_t d2 = (2 * i - n) * (2 * i - n) / 4 + (2 * j - n) * (2 * j - n) / 4;
            if (d2 < r2)
                h[j * stride + i] = fx_sat32(h[j * stride + i] + amp * (r2 - d2) / r2);
        }
    return 0;
}

int fx_terrain_mesh(fx_mesh *m, const int32_t *h, int32_t stride, int k, fx16 size, fx16 height, fx16 sea)
{
    int32_t nv, nt;
    if (!m || !h || !m->pos || !m->nrm || !m->tri || !m->col || fx_terrain_mesh_size(k, &nv, &nt) < 0 ||
        m->cap_verts < nv || m->cap_tris < nt || size <= 0 || height < 0 || sea < 0 || sea > FX16_ONE)
        return -FX_EINVAL;
    int32_t n = 1 << k;
    if (stride < n + 1)
        return -FX_EINVAL;
    int32_t lo = INT32_MAX, hi = INT32_MIN;
    for (int32_t j = 0; j <= n; j++)
        for (int32_t i = 0; i <= n; i++) {
            int32_t v = h[(ptrdiff_t)j * stride + i];
            lo = FX_MIN(lo, v);
            hi = FX_MAX(hi, v);
        }
    int64_t range = (int64_t)hi - lo;
    if (range == 0)
        range = 1;
    for (int32_t j = 0; j <= n; j++)
        for (int32_t i = 0; i <= n; i++) {
            int32_t v = h[(ptrdiff_t)j * stride + i];
            fx16 t = (fx16)((((int64_t)v - lo) << 16) / range); /* 0..1 over the grid */
            fx_color col;
            if (t < sea) {
                t = sea;
                col = 0xFF1E4A8Cu;
            } else {
                col = fx_terrain_color(sea < FX16_ONE ? (fx16)((((int64_t)t - sea) << 16) / (FX16_ONE - sea)) : 0);
            }
            int32_t vi = j * (n + 1) + i;
            m->pos[vi] = fx_vec3_make((fx16)(-size / 2 + (int64_t)size * i / n), fx16_mul(t, height),
                                      (fx16)(-size / 2 + (int64_t)size * j / n));
            m->col[vi] = col;
        }
    int32_t q = 0;
    for (int32_t j = 0; j < n; j++)
        for (int32_t i = 0; i < n; i++) {
            uint32_t a = (uint32_t)(j * (n + 1) + i), b = a + 1, c = a + (uint32_t)(n + 1), d = c + 1;
            /* (a, c, b) and (b, c, d): counter-clockwise seen from +y */
            uint32_t tri[6] = {a, c, b, b, c, d};
            for (int e = 0; e < 6; e++)
                m->tri[q++] = tri[e];
        }
    m->nverts = nv;
    m->ntris = nt;
    fx_mesh_compute_normals(m);
    return 0;
}
