/* SPDX-License-Identifier: MIT */
/* fixel — the ray tracer's lighting: the course's equation
 *     I = Iamb + Idiff + Ispec + Irefl + Itran
 * at the nearest hit, with shadow feelers toward each light (dimmed by
 * the transparency of the surfaces they cross, an approximation: no
 * refraction or caustics on the way to the light), Blinn-Phong
 * highlights, light attenuation 1 / (1 + k d^2), a reflected ray
 * r = d - 2 (d.m) m and a refracted one by Snell's law (total internal
 * reflection sends the transmitted share along r), up to a recursion limit
 * and while a ray's weight stays above the cut-off. Also the primary rays
 * of a pixel, the tile renderer and the --trace ray tree. */
#include "fixel/fixed.h"
#include "rt_int.h"
#include "../base/fx_internal.h"

#define ONE ((int64_t)FX16_ONE)

typedef struct tracer {
    const fx_rt_scene *s;
    fx_trace_fn trace;
    void *user;
} tracer;

static fx3d_rgb rgb(fx16 r, fx16 g, fx16 b)
{
    fx3d_rgb o = {r, g, b};
    return o;
}
static fx3d_rgb rgb_mul(fx3d_rgb a, fx3d_rgb b) { return rgb(fx16_mul(a.r, b.r), fx16_mul(a.g, b.g), fx16_mul(a.b, b.b)); }
static fx3d_rgb rgb_scale(fx3d_rgb a, fx16 k) { return rgb(fx16_mul(a.r, k), fx16_mul(a.g, k), fx16_mul(a.b, k)); }
static fx3d_rgb rgb_add(fx3d_rgb a, fx3d_rgb b)
{
    return rgb(rt_sat((int64_t)a.r + b.r), rt_sat((int64_t)a.g + b.g), rt_sat((int64_t)a.b + b.b));
}
static fx3d_rgb rgb_lerp(fx3d_rgb a, fx3d_rgb b, fx16 w)
{
    return rgb(rt_sat(a.r + rt_mul((int64_t)b.r - a.r, w)), rt_sat(a.g + rt_mul((int64_t)b.g - a.g, w)),
               rt_sat(a.b + rt_mul((int64_t)b.b - a.b, w)));
}

/* ---- solid textures ---- */

static int64_t smooth(int64_t f) { return rt_mul(rt_mul(f, f), 3 * ONE - 2 * f); } /* 3f^2 - 2f^3 */

fx16 fx_rt_noise3(fx_vec3 p)
{
    int32_t ix = p.x >> 16, iy = p.y >> 16, iz = p.z >> 16;
    int64_t fx = smooth(p.x & 0xFFFF), fy = smooth(p.y & 0xFFFF), fz = smooth(p.z & 0xFFFF);
    int64_t v[8];
    for (int k = 0; k < 8; k++)
        v[k] = rt_hash3(ix + (k & 1), iy + ((k >> 1) & 1), iz + ((k >> 2) & 1)) >> 16;
    int64_t x0 = v[0] + rt_mul(v[1] - v[0], fx), x1 = v[2] + rt_mul(v[3] - v[2], fx);
    int64_t x2 = v[4] + rt_mul(v[5] - v[4], fx), x3 = v[6] + rt_mul(v[7] - v[6], fx);
    int64_t y0 = x0 + rt_mul(x1 - x0, fy), y1 = x2 + rt_mul(x3 - x2, fy);
    int64_t r = y0 + rt_mul(y1 - y0, fz);
    return (fx16)(r < 0 ? 0 : r > ONE - 1 ? ONE - 1 : r);
}

fx16 fx_rt_turbulence3(fx_vec3 p, int octaves)
{
    int64_t sum = 0, norm = 0;
    if (octaves < 1)
        octaves = 1;
    if (octaves > 8)
        octaves = 8;
    for (int k = 0; k < octaves; k++) {
        sum += (int64_t)fx_rt_noise3(p) >> k;
        norm += ONE >> k;
        /* the lattice wraps (the hash takes integer cells mod 2^32), so
         * doubling a saturated coordinate stays defined */
        p = fx_vec3_make((fx16)((uint32_t)p.x * 2u), (fx16)((uint32_t)p.y * 2u), (fx16)((uint32_t)p.z * 2u));
    }
    return (fx16)(sum * ONE / norm);
}

fx16 fx_rt_solid(int kind, fx_vec3 q)
{
    fx16 w;
    if (kind == FX_RT_TEX_NONE) {
        w = 0;
    } else if (kind == FX_RT_TEX_CHECKER) {
        w = (((q.x >> 16) + (q.y >> 16) + (q.z >> 16)) & 1) ? FX16_ONE : 0;
    } else if (kind == FX_RT_TEX_MARBLE) {
        /* stripes across x, bent by turbulence: (1 + sin(2 pi (x + turb))) / 2 */
        int64_t u = (int64_t)q.x + (int64_t)fx_rt_turbulence3(q, 5);
        w = (fx16)((ONE + fx_sin((fx_angle)((uint64_t)u << 16))) / 2);
    } else {
        /* rings about the y axis, wobbled by noise */
        int64_t r = fx_hypot(q.x, q.z) + (fx_rt_noise3(q) >> 2);
        w = (fx16)((r * 4) & 0xFFFF);
        w = w < FX16_HALF ? 2 * w : 2 * (FX16_ONE - w);
    }
    return w;
}

static void bump_clamp(fx16 *height, fx16 *scale)
{
    if (*height > FX16_ONE)
        *height = FX16_ONE;
    if (*scale < FX16_ONE / 16)
        *scale = FX16_ONE / 16;
    if (*scale > 64 * FX16_ONE)
        *scale = 64 * FX16_ONE;
}

fx_vec3 fx_rt_bump_gradient(fx16 height, fx16 scale, fx_vec3 q)
{
    if (height <= 0)
        return fx_vec3_make(0, 0, 0);
    bump_clamp(&height, &scale);
    const fx16 dq = FX16_ONE >> 7;
    int64_t g[3];
    for (int i = 0; i < 3; i++) {
        fx_vec3 a = q, b = q;
        fx16 *pa = i == 0 ? &a.x : i == 1 ? &a.y : &a.z, *pb = i == 0 ? &b.x : i == 1 ? &b.y : &b.z;
        *pa = (fx16)((uint32_t)*pa + (uint32_t)dq);
        *pb = (fx16)((uint32_t)*pb - (uint32_t)dq);
        /* d noise / d q in Q16.16 (|.| <= 1.5: lattice values in [0, 1),
         * smoothstep slope at most 1.5), then times height / scale: the
         * gradient per unit of P, at most 24 units (Q32 / Q16 = Q16).
         * 2^-7 cells balances the stencil's truncation against the noise's
         * rounding (2^-8 and 2^-6 were measured worse) */
        int64_t d = ((int64_t)fx_rt_noise3(a) - fx_rt_noise3(b)) * 64;
        g[i] = d * height / scale;
    }
    return fx_vec3_make((fx16)g[0], (fx16)g[1], (fx16)g[2]);
}

fx_vec3 fx_rt_bump_normal(fx16 height, fx16 scale, fx_vec3 P, fx_vec3 n)
{
    if (height <= 0)
        return n;
    bump_clamp(&height, &scale);
    /* |P| <= 2^15 units saturated, / 1/16: q may saturate, which only
     * repeats the noise (the lattice wraps) */
    fx_vec3 q = fx_vec3_make(rt_sat((int64_t)P.x * 65536 / scale), rt_sat((int64_t)P.y * 65536 / scale),
                             rt_sat((int64_t)P.z * 65536 / scale));
    fx_vec3 gv = fx_rt_bump_gradient(height, scale, q);
    const int64_t g[3] = {gv.x, gv.y, gv.z};
    int64_t gn = rt_mul(g[0], n.x) + rt_mul(g[1], n.y) + rt_mul(g[2], n.z);
    fx_vec3 o = fx_vec3_make(rt_sat(n.x - (g[0] - rt_mul(gn, n.x))), rt_sat(n.y - (g[1] - rt_mul(gn, n.y))),
                             rt_sat(n.z - (g[2] - rt_mul(gn, n.z))));
    if (fx_vec3_normalize(&o) < 0)
        return n;
    return o;
}

static fx3d_rgb texture(const fx_rt_material *m, fx_vec3 P)
{
    if (m->texture == FX_RT_TEX_NONE)
        return m->diffuse;
    fx16 sc = m->tex_scale > 0 ? m->tex_scale : FX16_ONE;
    fx_vec3 q = fx_vec3_make(fx16_div(P.x, sc), fx16_div(P.y, sc), fx16_div(P.z, sc));
    return rgb_lerp(m->diffuse, m->tex_color, fx_rt_solid(m->texture, q));
}

/* ---- tracing ---- */

static int fmt16(char *b, size_t n, fx16 v)
{
    int64_t a = v < 0 ? -(int64_t)v : v;
    int64_t ip = a >> 16, fr = ((a & 0xFFFF) * 10000 + 0x8000) >> 16;
    if (fr >= 10000)
        ip++, fr -= 10000;
    return fx_fmt(b, n, "%s%lld.%04lld", v < 0 ? "-" : "", (long long)ip, (long long)fr);
}

static void say(const tracer *tr, int depth, const char *what, const char *name, int nv, const fx16 *v)
{
    char line[256];
    int n = 0;
    for (int i = 0; i < depth && i < 16; i++)
        line[n++] = ' ', line[n++] = ' ';
    n += fx_fmt(line + n, sizeof line - (size_t)n, "%s", what);
    if (name && n < (int)sizeof line)
        n += fx_fmt(line + n, sizeof line - (size_t)n, " %s", name);
    for (int i = 0; i < nv && n < (int)sizeof line - 16; i++) {
        if (i % 3 == 0)
            n += fx_fmt(line + n, sizeof line - (size_t)n, i ? ") (" : " (");
        else
            n += fx_fmt(line + n, sizeof line - (size_t)n, ", ");
        n += fmt16(line + n, sizeof line - (size_t)n, v[i]);
    }
    if (nv && n < (int)sizeof line - 1)
        fx_fmt(line + n, sizeof line - (size_t)n, ")");
    tr->trace(tr->user, line);
}

static const char *kind_name(int k)
{
    static const char *const names[] = {"sphere", "cube", "square", "plane", "cylinder", "mesh", "torus"};
    return k >= 0 && k <= FX_RT_TORUS ? names[k] : "?";
}

static fx16 dot(fx_vec3 a, fx_vec3 b) { return fx_vec3_dot(a, b); }
static fx_vec3 vadd_scaled(fx_vec3 a, fx_vec3 b, int64_t k)
{
    return fx_vec3_make(rt_sat(a.x + rt_mul(b.x, k)), rt_sat(a.y + rt_mul(b.y, k)), rt_sat(a.z + rt_mul(b.z, k)));
}

static fx3d_rgb shade(const tracer *tr, fx_vec3 S, fx_vec3 c, int depth, fx16 weight)
{
    const fx_rt_scene *s = tr->s;
    fx_rt_hit hit;
    fx_vec3 n;
    if (tr->trace) {
        fx16 v[6] = {S.x, S.y, S.z, c.x, c.y, c.z};
        say(tr, depth, depth ? "ray" : "primary ray", "from", 6, v);
    }
    if (!fx_rt_first_hit(s, S, c, depth ? FX_RT_EPS : 0, &hit, &n)) {
        if (tr->trace)
            say(tr, depth, "  miss: background", 0, 3, &s->background.r);
        return s->background;
    }
    const fx_rt_object *o = &s->obj[hit.obj];
    const fx_rt_material *mat = &o->mat;
    fx_vec3 P = vadd_scaled(S, c, hit.t);
    int inside = dot(c, n) > 0;
    fx_vec3 m = inside ? fx_vec3_make(-n.x, -n.y, -n.z) : n; /* faces the ray */
    if (tr->trace) {
        fx16 v[7] = {hit.t, P.x, P.y, P.z, n.x, n.y, n.z};
        char what[64];
        fx_fmt(what, sizeof what, "  hit object %d (%s, %s) t ", hit.obj, kind_name(o->kind),
               inside ? "leaving" : "entering");
        char tb[24];
        fmt16(tb, sizeof tb, v[0]);
        char line[96];
        fx_fmt(line, sizeof line, "%s%s at", what, tb);
        say(tr, depth, line, 0, 6, v + 1);
    }
    if (mat->bump > 0) {
        /* a bump tilted past the ray's grazing angle would face away from
         * it (reflection into the surface): keep the smooth normal there */
        fx_vec3 b = fx_rt_bump_normal(mat->bump, mat->bump_scale, P, m);
        if (dot(c, b) < 0)
            m = b;
        if (tr->trace) {
            fx16 v[3] = {m.x, m.y, m.z};
            say(tr, depth, "  bumped normal", 0, 3, v);
        }
    }
    /* frame mapping: the grain's tangent at the (bumped) normal */
    fx_vec3 ft = {0, 0, 0}, fb;
    int aniso = mat->frame != FX_RT_FRAME_NONE && mat->frame_k > 0 && mat->shininess > 0;
    if (aniso) {
        fx16 sc = FX_MIN(FX_MAX(mat->frame_scale, FX16_ONE / 16), 64 * FX16_ONE);
        fx_vec3 q = fx_vec3_make(rt_sat((int64_t)P.x * 65536 / sc), rt_sat((int64_t)P.y * 65536 / sc),
                                 rt_sat((int64_t)P.z * 65536 / sc));
        fx_rt_frame(fx_rt_frame_dir(mat->frame, q), m, &ft, &fb);
        if (tr->trace) {
            fx16 v[6] = {ft.x, ft.y, ft.z, fb.x, fb.y, fb.z};
            say(tr, depth, "  frame tangent, bitangent", 0, 6, v);
        }
    }
    fx3d_rgb diff = texture(mat, P);
    fx3d_rgb Iamb = rgb_add(mat->emissive, rgb_mul(s->ambient, mat->ambient)), Idiff = rgb(0, 0, 0), Ispec = rgb(0, 0, 0);
    for (int li = 0; li < s->nlights; li++) {
        const fx_rt_light *L = &s->light[li];
        fx_vec3 Ld = fx_vec3_make(rt_sat((int64_t)L->pos.x - P.x), rt_sat((int64_t)L->pos.y - P.y),
                                  rt_sat((int64_t)L->pos.z - P.z));
        fx16 dist = fx_vec3_length(Ld);
        fx_vec3 l = Ld;
        if (fx_vec3_normalize(&l) < 0)
            continue;
        fx16 lam = dot(m, l);
        if (lam <= 0)
            continue;
        /* the shadow feeler, dimmed by the transparency of what it passes
         * (issue #44: glass cast a black shadow); see fx_rt_feeler_transmit */
        int blocker;
        fx16 T = fx_rt_feeler_transmit(s, P, l, FX_RT_EPS, dist, &blocker);
        if (T <= 0) {
            if (tr->trace) {
                fx_rt_hit sh;
                char what[64];
                if (blocker >= 0 && fx_rt_first_hit(s, P, l, FX_RT_EPS, &sh, 0) && sh.obj == blocker) {
                    fx_fmt(what, sizeof what, "  light %d: shadow feeler blocked by object %d at t", li, sh.obj);
                    say(tr, depth, what, 0, 1, &sh.t);
                } else if (blocker >= 0) {
                    fx_fmt(what, sizeof what, "  light %d: shadow feeler blocked by object %d", li, blocker);
                    say(tr, depth, what, 0, 0, 0);
                } else {
                    fx_fmt(what, sizeof what, "  light %d: shadow feeler dimmed to 0 by transparent objects", li);
                    say(tr, depth, what, 0, 0, 0);
                }
            }
            continue;
        }
        /* Q16.16, may exceed int32 (< 2^34 within the world, < 2^46 for
         * any dist an fx16 holds). k is capped at 1 as fx_rt_add_light
         * does, for lights written into the struct directly: the product
         * k d^2 then stays below 2^62 */
        int64_t d2 = ((int64_t)dist * dist) >> 16;
        int64_t k = L->atten < 0 ? 0 : L->atten > FX16_ONE ? FX16_ONE : L->atten;
        int64_t den = ONE + rt_mul(k, d2);
        fx16 att = (fx16)((ONE << 16) / den);
        if (tr->trace) {
            char what[64];
            fx_fmt(what, sizeof what, "  light %d: visible; distance, m.l, attenuation", li);
            fx16 v[3] = {dist, lam, att};
            say(tr, depth, what, 0, 3, v);
            if (T < FX16_ONE) {
                fx_fmt(what, sizeof what, "  light %d: through transparent objects, transmitted", li);
                say(tr, depth, what, 0, 1, &T);
            }
        }
        att = fx16_mul(att, T);
        fx3d_rgb Il = rgb_scale(L->color, att);
        Idiff = rgb_add(Idiff, rgb_scale(rgb_mul(Il, diff), lam));
        if (mat->shininess > 0) {
            fx_vec3 h = fx_vec3_make(l.x - c.x, l.y - c.y, l.z - c.z);
            if (fx_vec3_normalize(&h) == 0) {
                fx16 mh = dot(m, h);
                fx16 sp = mh > 0 ? fx16_powi(mh, mat->shininess) : 0;
                if (aniso)
                    sp = fx_rt_aniso_spec(sp, mat->frame_k, ft, h, lam, mat->shininess);
                if (mh > 0 || aniso)
                    Ispec = rgb_add(Ispec, rgb_scale(rgb_mul(Il, mat->specular), sp));
            }
        }
    }
    fx3d_rgb I = rgb_add(rgb_add(Iamb, Idiff), Ispec), Irefl = rgb(0, 0, 0), Itran = rgb(0, 0, 0);
    fx16 dm = dot(c, m);
    fx_vec3 r = fx_vec3_make(rt_sat(c.x - 2 * rt_mul(dm, m.x)), rt_sat(c.y - 2 * rt_mul(dm, m.y)),
                             rt_sat(c.z - 2 * rt_mul(dm, m.z)));
    fx_vec3_normalize(&r);
    if (mat->reflectivity > 0 && depth < s->max_depth) {
        fx16 w = fx16_mul(weight, mat->reflectivity);
        if (w >= s->cutoff)
            Irefl = rgb_scale(shade(tr, P, r, depth + 1, w), mat->reflectivity);
    }
    if (mat->transparency > 0 && depth < s->max_depth) {
        fx16 w = fx16_mul(weight, mat->transparency);
        if (w >= s->cutoff) {
            fx16 ior = mat->ior > 0 ? mat->ior : FX16_ONE;
            fx16 eta = inside ? ior : fx16_div(FX16_ONE, ior); /* n1 / n2 */
            int64_t cos1 = -(int64_t)dm;
            int64_t k = ONE - rt_mul(rt_mul(eta, eta), ONE - rt_mul(cos1, cos1));
            fx_vec3 tdir = r; /* total internal reflection */
            if (k >= 0) {
                int64_t coef = rt_mul(eta, cos1) - fx16_sqrt((fx16)k);
                tdir = fx_vec3_make(rt_sat(rt_mul(eta, c.x) + rt_mul(coef, m.x)),
                                    rt_sat(rt_mul(eta, c.y) + rt_mul(coef, m.y)),
                                    rt_sat(rt_mul(eta, c.z) + rt_mul(coef, m.z)));
                fx_vec3_normalize(&tdir);
            } else if (tr->trace) {
                say(tr, depth, "  total internal reflection", 0, 0, 0);
            }
            Itran = rgb_scale(shade(tr, P, tdir, depth + 1, w), mat->transparency);
        }
    }
    I = rgb_add(rgb_add(I, Irefl), Itran);
    if (tr->trace) {
        fx16 v[18] = {Iamb.r, Iamb.g, Iamb.b, Idiff.r, Idiff.g, Idiff.b, Ispec.r, Ispec.g, Ispec.b,
                      Irefl.r, Irefl.g, Irefl.b, Itran.r, Itran.g, Itran.b, I.r, I.g, I.b};
        say(tr, depth, "  I = amb + diff + spec + refl + tran", 0, 18, v);
    }
    return I;
}

fx3d_rgb fx_rt_trace_ray(const fx_rt_scene *s, fx_vec3 S, fx_vec3 c, fx_trace_fn trace, void *user)
{
    tracer tr = {s, trace, user};
    return shade(&tr, S, c, 0, FX16_ONE);
}

void fx_rt_primary(const fx_rt_scene *s, int32_t w, int32_t h, int32_t x, int32_t y, fx_vec3 *S, fx_vec3 *c)
{
    const fx_camera *cam = &s->cam;
    if (h < 1)
        h = 1;
    /* the course's -N n + W (2 (x + 1/2) / w - 1) u + H (1 - 2 (y + 1/2) / h) v
     * with N = 1, H = tan(fovy / 2), W = H w / h */
    int64_t ux = ((2 * (int64_t)x + 1 - w) * s->tan_half) / h;
    int64_t vy = (((int64_t)h - 2 * (int64_t)y - 1) * s->tan_half) / h;
    fx_vec3 d = fx_vec3_make(rt_sat(-(int64_t)cam->n.x + rt_mul(ux, cam->u.x) + rt_mul(vy, cam->v.x)),
                             rt_sat(-(int64_t)cam->n.y + rt_mul(ux, cam->u.y) + rt_mul(vy, cam->v.y)),
                             rt_sat(-(int64_t)cam->n.z + rt_mul(ux, cam->u.z) + rt_mul(vy, cam->v.z)));
    fx_vec3_normalize(&d);
    *S = cam->eye;
    *c = d;
}

fx_color fx_rt_trace_pixel(const fx_rt_scene *s, int32_t w, int32_t h, int32_t x, int32_t y, fx_trace_fn trace,
                           void *user)
{
    fx_vec3 S, c;
    fx_rt_primary(s, w, h, x, y, &S, &c);
    return fx3d_rgb_to_color(fx_rt_trace_ray(s, S, c, trace, user));
}

void fx_rt_render(const fx_rt_scene *s, const fx_surface *surf, int32_t x0, int32_t y0, int32_t tw, int32_t th)
{
    int64_t xa = x0 < 0 ? 0 : x0, ya = y0 < 0 ? 0 : y0;
    int64_t xb = (int64_t)x0 + (tw > 0 ? tw : 0), yb = (int64_t)y0 + (th > 0 ? th : 0);
    if (xb > surf->w)
        xb = surf->w;
    if (yb > surf->h)
        yb = surf->h;
    for (int64_t y = ya; y < yb; y++)
        for (int64_t x = xa; x < xb; x++)
            fx_surface_put(surf, (int32_t)x, (int32_t)y,
                           fx_rt_trace_pixel(s, surf->w, surf->h, (int32_t)x, (int32_t)y, 0, 0));
}
