/* SPDX-License-Identifier: MIT */
/* fixel-bench: the double-precision reference ray tracer and the
 * benchmark's ray-tracing scenes (rtref.h). */
#include "rtref.h"

#include <math.h>
#include <string.h>

#define Q (1.0 / 65536.0)

static void xf(const fx_mat4 *m, const double p[3], int w, double o[3])
{
    for (int i = 0; i < 3; i++)
        o[i] = (m->m[i][0] * p[0] + m->m[i][1] * p[1] + m->m[i][2] * p[2]) * Q + (w ? m->m[i][3] * Q : 0);
}

static void put(rtref_list *l, int obj, double t, int entering)
{
    if (l->n < 64) {
        rtref_hit h = {t, obj, entering, 0};
        l->h[l->n++] = h;
    }
}

static int quad(double A, double B, double C, double *t0, double *t1)
{
    if (A == 0) {
        if (B == 0)
            return 0;
        *t0 = *t1 = -C / (2 * B);
        return 1;
    }
    double d = B * B - A * C;
    if (d < 0)
        return 0;
    double sq = sqrt(d), r0 = (-B - sq) / A, r1 = (-B + sq) / A;
    *t0 = fmin(r0, r1);
    *t1 = fmax(r0, r1);
    return 2;
}

/* The torus's quartic (x^2 + y^2 + z^2 + 1 - r^2)^2 - 4 (x^2 + y^2) at
 * S + c t: negative inside. */
static double torus_f(double r, const double S[3], const double c[3], double t)
{
    double p[3] = {S[0] + c[0] * t, S[1] + c[1] * t, S[2] + c[2] * t};
    double g = p[0] * p[0] + p[1] * p[1] + p[2] * p[2] + 1 - r * r;
    return g * g - 4 * (p[0] * p[0] + p[1] * p[1]);
}

/* Its roots on the ray's stretch inside the box, found otherwise than the
 * fixed-point tracer does: the sign sampled at 4096 points, each change
 * bisected to the last bit of a double. Two roots closer than a sample
 * step (a grazing ray) can be missed: the test leaves such rays out. */
static void torus_hits(double r, int idx, const double S[3], const double c[3], rtref_list *l)
{
    const double half[3] = {1 + r, 1 + r, r};
    double tin = -INFINITY, tout = INFINITY;
    for (int i = 0; i < 3; i++) {
        if (c[i] == 0) {
            if (fabs(S[i]) > half[i])
                return;
            continue;
        }
        double a = (-half[i] - S[i]) / c[i], b = (half[i] - S[i]) / c[i];
        tin = fmax(tin, fmin(a, b));
        tout = fmin(tout, fmax(a, b));
    }
    if (!(tin < tout))
        return;
    enum { N = 4096 };
    double step = (tout - tin) / N, t0 = tin, f0 = torus_f(r, S, c, tin);
    for (int k = 1; k <= N; k++) {
        double t1 = k == N ? tout : tin + step * k, f1 = torus_f(r, S, c, t1);
        if ((f0 < 0) != (f1 < 0)) {
            double lo = t0, hi = t1;
            for (int it = 0; it < 200 && hi - lo > 0; it++) {
                double mid = lo + (hi - lo) / 2;
                if (mid <= lo || mid >= hi)
                    break;
                if ((torus_f(r, S, c, mid) < 0) == (f0 < 0))
                    lo = mid;
                else
                    hi = mid;
            }
            put(l, idx, (lo + hi) / 2, f0 >= 0);
        }
        t0 = t1, f0 = f1;
    }
}

static void leaf(const fx_rt_object *o, int idx, const double S[3], const double c[3], rtref_list *l)
{
    double t0, t1;
    switch (o->kind) {
    case FX_RT_SPHERE:
        if (quad(c[0] * c[0] + c[1] * c[1] + c[2] * c[2], S[0] * c[0] + S[1] * c[1] + S[2] * c[2],
                 S[0] * S[0] + S[1] * S[1] + S[2] * S[2] - 1, &t0, &t1) == 2) {
            put(l, idx, t0, 1);
            put(l, idx, t1, 0);
        }
        break;
    case FX_RT_CUBE: {
        double tin = -INFINITY, tout = INFINITY;
        for (int i = 0; i < 3; i++) {
            if (c[i] == 0) {
                if (fabs(S[i]) > 1)
                    return;
                continue;
            }
            double a = (-1 - S[i]) / c[i], b = (1 - S[i]) / c[i];
            tin = fmax(tin, fmin(a, b));
            tout = fmin(tout, fmax(a, b));
        }
        if (tin <= tout) {
            put(l, idx, tin, 1);
            put(l, idx, tout, 0);
        }
        break;
    }
    case FX_RT_SQUARE:
        if (c[2] != 0) {
            double t = -S[2] / c[2], x = S[0] + c[0] * t, y = S[1] + c[1] * t;
            if (fabs(x) <= 1 && fabs(y) <= 1) {
                put(l, idx, t, 1);
                put(l, idx, t, 0);
            }
        }
        break;
    case FX_RT_PLANE:
        if (c[2] == 0) {
            l->inside0 = S[2] <= 0;
        } else {
            l->inside0 = c[2] > 0;
            put(l, idx, -S[2] / c[2], c[2] < 0);
        }
        break;
    case FX_RT_CYLINDER: {
        double k = o->taper * Q - 1, F = 1 + k * S[2], kc = k * c[2];
        double ts[4];
        int n = 0, nr = quad(c[0] * c[0] + c[1] * c[1] - kc * kc, S[0] * c[0] + S[1] * c[1] - F * kc,
                             S[0] * S[0] + S[1] * S[1] - F * F, &t0, &t1);
        double r[2] = {t0, t1};
        for (int i = 0; i < nr; i++) {
            double z = S[2] + c[2] * r[i];
            if (z >= 0 && z <= 1)
                ts[n++] = r[i];
        }
        if (c[2] != 0)
            for (int cap = 0; cap < 2; cap++) {
                double t = (cap - S[2]) / c[2], x = S[0] + c[0] * t, y = S[1] + c[1] * t;
                double rr = cap ? (o->taper * Q) * (o->taper * Q) : 1;
                if (x * x + y * y <= rr)
                    ts[n++] = t;
            }
        if (!n)
            break;
        double lo = ts[0], hi = ts[0];
        for (int i = 1; i < n; i++)
            lo = fmin(lo, ts[i]), hi = fmax(hi, ts[i]);
        put(l, idx, lo, 1);
        put(l, idx, hi, 0);
        break;
    }
    case FX_RT_TORUS: torus_hits(o->taper * Q, idx, S, c, l); break;
    }
}

static int state(int op, int a, int b)
{
    return op == FX_RT_UNION ? (a || b) : op == FX_RT_INTERSECTION ? (a && b) : (a && !b);
}

void rtref_hits(const fx_rt_scene *s, int i, const double S[3], const double c[3], rtref_list *out)
{
    const fx_rt_object *o = &s->obj[i];
    out->n = 0;
    out->inside0 = 0;
    if (o->kind < FX_RT_UNION) {
        double So[3], co[3];
        xf(&o->inv, S, 1, So);
        xf(&o->inv, c, 0, co);
        leaf(o, i, So, co, out);
        return;
    }
    rtref_list a, b;
    rtref_hits(s, o->left, S, c, &a);
    rtref_hits(s, o->right, S, c, &b);
    int ina = a.inside0, inb = b.inside0, in = state(o->kind, ina, inb);
    out->inside0 = in;
    int p = 0, q = 0;
    while (p < a.n || q < b.n) {
        int fromA = q >= b.n || (p < a.n && a.h[p].t <= b.h[q].t);
        rtref_hit h = fromA ? a.h[p++] : b.h[q++];
        if (fromA)
            ina = h.entering;
        else
            inb = h.entering;
        int now = state(o->kind, ina, inb);
        if (now == in)
            continue;
        in = now;
        h.entering = now;
        if (o->kind == FX_RT_DIFFERENCE && !fromA)
            h.flip ^= 1;
        if (out->n < 64)
            out->h[out->n++] = h;
    }
}

int rtref_inside(const fx_rt_scene *s, int i, const double p[3])
{
    const fx_rt_object *o = &s->obj[i];
    if (o->kind >= FX_RT_UNION)
        return state(o->kind, rtref_inside(s, o->left, p), rtref_inside(s, o->right, p));
    double q[3];
    xf(&o->inv, p, 1, q);
    switch (o->kind) {
    case FX_RT_SPHERE: return q[0] * q[0] + q[1] * q[1] + q[2] * q[2] <= 1;
    case FX_RT_CUBE: return fabs(q[0]) <= 1 && fabs(q[1]) <= 1 && fabs(q[2]) <= 1;
    case FX_RT_PLANE: return q[2] <= 0;
    case FX_RT_CYLINDER: {
        double r = 1 + (o->taper * Q - 1) * q[2];
        return q[2] >= 0 && q[2] <= 1 && q[0] * q[0] + q[1] * q[1] <= r * r;
    }
    case FX_RT_TORUS: {
        double z[3] = {0, 0, 0};
        return torus_f(o->taper * Q, q, z, 0) <= 0;
    }
    default: return 0;
    }
}

static void unit(double v[3])
{
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (l > 0)
        v[0] /= l, v[1] /= l, v[2] /= l;
}

/* The leaf's outward normal at world point p (object-space gradient taken
 * to world by M^-T). */
static void normal_at(const fx_rt_scene *s, int obj, int flip, const double p[3], double n[3])
{
    const fx_rt_object *o = &s->obj[obj];
    double q[3], m[3] = {0, 0, 0};
    xf(&o->inv, p, 1, q);
    switch (o->kind) {
    case FX_RT_SPHERE: memcpy(m, q, sizeof m); break;
    case FX_RT_CUBE: {
        int a = 0;
        for (int i = 1; i < 3; i++)
            if (fabs(q[i]) > fabs(q[a]))
                a = i;
        m[a] = q[a] < 0 ? -1 : 1;
        break;
    }
    case FX_RT_SQUARE:
    case FX_RT_PLANE: m[2] = 1; break;
    case FX_RT_CYLINDER: {
        double k = o->taper * Q - 1, r = 1 + k * q[2];
        if (q[2] < 1e-4)
            m[2] = -1;
        else if (q[2] > 1 - 1e-4 && q[0] * q[0] + q[1] * q[1] < r * r * (1 - 1e-3))
            m[2] = 1;
        else
            m[0] = q[0], m[1] = q[1], m[2] = -k * r;
        break;
    }
    case FX_RT_TORUS: {
        double r = o->taper * Q, g = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + 1 - r * r;
        m[0] = (g - 2) * q[0], m[1] = (g - 2) * q[1], m[2] = g * q[2];
        break;
    }
    }
    for (int i = 0; i < 3; i++)
        n[i] = (o->inv.m[0][i] * m[0] + o->inv.m[1][i] * m[1] + o->inv.m[2][i] * m[2]) * Q;
    unit(n);
    if (flip)
        n[0] = -n[0], n[1] = -n[1], n[2] = -n[2];
}

double rtref_first_hit(const fx_rt_scene *s, const double S[3], const double c[3], double tmin, int *obj,
                       double n[3])
{
    double best = -1;
    int bo = -1, bf = 0;
    for (int i = 0; i < s->n; i++) {
        if (!s->obj[i].top)
            continue;
        rtref_list l;
        rtref_hits(s, i, S, c, &l);
        for (int k = 0; k < l.n; k++) {
            if (l.h[k].t <= tmin)
                continue;
            double t = l.h[k].t, W = FX_RT_WORLD;
            int out = 0;
            for (int j = 0; j < 3; j++)
                out |= fabs(S[j] + c[j] * t) > W;
            if (!out && (best < 0 || t < best))
                best = t, bo = l.h[k].obj, bf = l.h[k].flip;
            break;
        }
    }
    if (best >= 0) {
        double p[3] = {S[0] + c[0] * best, S[1] + c[1] * best, S[2] + c[2] * best};
        normal_at(s, bo, bf, p, n);
        if (s->obj[bo].kind == FX_RT_SQUARE && n[0] * c[0] + n[1] * c[1] + n[2] * c[2] > 0)
            n[0] = -n[0], n[1] = -n[1], n[2] = -n[2];
    }
    *obj = bo;
    return best;
}

typedef struct { double r, g, b; } rgb;
static rgb mk(fx3d_rgb c) { rgb o = {c.r * Q, c.g * Q, c.b * Q}; return o; }
static double dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static double noise3(const double p[3])
{
    fx_vec3 v = fx_vec3_make((fx16)floor(p[0] * 65536), (fx16)floor(p[1] * 65536), (fx16)floor(p[2] * 65536));
    return fx_rt_noise3(v) * Q; /* the lattice values are the definition */
}

static double turb(const double p[3], int oct)
{
    double sum = 0, norm = 0, q[3] = {p[0], p[1], p[2]};
    for (int k = 0; k < oct; k++) {
        sum += noise3(q) / (1 << k);
        norm += 1.0 / (1 << k);
        q[0] *= 2, q[1] *= 2, q[2] *= 2;
    }
    return sum / norm;
}

static rgb texture(const fx_rt_material *m, const double P[3])
{
    rgb d = mk(m->diffuse), e = mk(m->tex_color);
    if (m->texture == FX_RT_TEX_NONE)
        return d;
    double sc = m->tex_scale > 0 ? m->tex_scale * Q : 1, q[3] = {P[0] / sc, P[1] / sc, P[2] / sc}, w;
    if (m->texture == FX_RT_TEX_CHECKER) {
        w = ((long long)floor(q[0]) + (long long)floor(q[1]) + (long long)floor(q[2])) & 1;
    } else if (m->texture == FX_RT_TEX_MARBLE) {
        w = (1 + sin(2 * M_PI * (q[0] + turb(q, 5)))) / 2;
    } else {
        double r = hypot(q[0], q[2]) + noise3(q) / 4, f = r * 4 - floor(r * 4);
        w = f < 0.5 ? 2 * f : 2 * (1 - f);
    }
    rgb o = {d.r + (e.r - d.r) * w, d.g + (e.g - d.g) * w, d.b + (e.b - d.b) * w};
    return o;
}

/* The product of kt over the surfaces the line S + c t crosses with
 * tmin < t < tmax inside the world. */
static double transmit(const fx_rt_scene *s, const double S[3], const double c[3], double tmin, double tmax)
{
    double T = 1;
    for (int i = 0; i < s->n; i++) {
        if (!s->obj[i].top)
            continue;
        rtref_list l;
        rtref_hits(s, i, S, c, &l);
        for (int k = 0; k < l.n; k++) {
            double t = l.h[k].t, W = FX_RT_WORLD;
            if (t <= tmin)
                continue;
            if (t >= tmax)
                break;
            int out = 0;
            for (int j = 0; j < 3; j++)
                out |= fabs(S[j] + c[j] * t) > W;
            if (out)
                break;
            double kt = s->obj[l.h[k].obj].mat.transparency * Q;
            T *= kt < 0 ? 0 : kt > 1 ? 1 : kt;
        }
    }
    return T;
}

static rgb shade(const fx_rt_scene *s, const double S[3], const double c[3], int depth, double weight, long *rays)
{
    ++*rays;
    double n[3];
    int obj;
    double t = rtref_first_hit(s, S, c, depth ? FX_RT_EPS * Q : 0, &obj, n);
    if (t < 0)
        return mk(s->background);
    const fx_rt_material *mat = &s->obj[obj].mat;
    double P[3] = {S[0] + c[0] * t, S[1] + c[1] * t, S[2] + c[2] * t};
    int inside = dot(c, n) > 0;
    double m[3] = {inside ? -n[0] : n[0], inside ? -n[1] : n[1], inside ? -n[2] : n[2]};
    rgb diff = texture(mat, P), amb = mk(s->ambient), ma = mk(mat->ambient), sp = mk(mat->specular);
    rgb I = {amb.r * ma.r, amb.g * ma.g, amb.b * ma.b};
    for (int li = 0; li < s->nlights; li++) {
        const fx_rt_light *L = &s->light[li];
        double l[3] = {L->pos.x * Q - P[0], L->pos.y * Q - P[1], L->pos.z * Q - P[2]};
        double dist = sqrt(dot(l, l));
        unit(l);
        double lam = dot(m, l);
        if (lam <= 0)
            continue;
        double sn[3];
        int so;
        ++*rays; /* the shadow feeler */
        double st = rtref_first_hit(s, P, l, FX_RT_EPS * Q, &so, sn);
        double T = 1; /* dimmed by the transparency of each surface it crosses (issue #44) */
        if (st >= 0 && st < dist)
            T = transmit(s, P, l, FX_RT_EPS * Q, dist);
        if (T <= 0)
            continue;
        double att = T / (1 + L->atten * Q * dist * dist);
        rgb Il = mk(L->color);
        I.r += Il.r * att * diff.r * lam, I.g += Il.g * att * diff.g * lam, I.b += Il.b * att * diff.b * lam;
        if (mat->shininess > 0) {
            double h[3] = {l[0] - c[0], l[1] - c[1], l[2] - c[2]};
            unit(h);
            double mh = dot(m, h);
            if (mh > 0) {
                double f = pow(mh, mat->shininess) * att;
                I.r += Il.r * sp.r * f, I.g += Il.g * sp.g * f, I.b += Il.b * sp.b * f;
            }
        }
    }
    double dm = dot(c, m), r[3] = {c[0] - 2 * dm * m[0], c[1] - 2 * dm * m[1], c[2] - 2 * dm * m[2]};
    unit(r);
    double kr = mat->reflectivity * Q, kt = mat->transparency * Q;
    if (kr > 0 && depth < s->max_depth && weight * kr >= s->cutoff * Q) {
        rgb o = shade(s, P, r, depth + 1, weight * kr, rays);
        I.r += kr * o.r, I.g += kr * o.g, I.b += kr * o.b;
    }
    if (kt > 0 && depth < s->max_depth && weight * kt >= s->cutoff * Q) {
        double ior = mat->ior > 0 ? mat->ior * Q : 1, eta = inside ? ior : 1 / ior, cos1 = -dm;
        double k = 1 - eta * eta * (1 - cos1 * cos1), td[3] = {r[0], r[1], r[2]};
        if (k >= 0) {
            double coef = eta * cos1 - sqrt(k);
            for (int i = 0; i < 3; i++)
                td[i] = eta * c[i] + coef * m[i];
            unit(td);
        }
        rgb o = shade(s, P, td, depth + 1, weight * kt, rays);
        I.r += kt * o.r, I.g += kt * o.g, I.b += kt * o.b;
    }
    return I;
}

static uint32_t ch(double v)
{
    v = v < 0 ? 0 : v > 1 ? 1 : v;
    return (uint32_t)floor(v * 255 + 0.5);
}

fx_color rtref_pixel(const fx_rt_scene *s, int32_t w, int32_t h, int32_t x, int32_t y, long *rays)
{
    long dummy = 0;
    const fx_camera *cam = &s->cam;
    double th = s->tan_half * Q, ux = (2.0 * x + 1 - w) * th / h, vy = (h - 2.0 * y - 1) * th / h;
    double d[3] = {-cam->n.x * Q + ux * cam->u.x * Q + vy * cam->v.x * Q,
                   -cam->n.y * Q + ux * cam->u.y * Q + vy * cam->v.y * Q,
                   -cam->n.z * Q + ux * cam->u.z * Q + vy * cam->v.z * Q};
    unit(d);
    double S[3] = {cam->eye.x * Q, cam->eye.y * Q, cam->eye.z * Q};
    rgb c = shade(s, S, d, 0, 1, rays ? rays : &dummy);
    return 0xFF000000u | ch(c.r) << 16 | ch(c.g) << 8 | ch(c.b);
}

/* ---- the scenes ---- */

#define FX(v) ((fx16)lround((v) * 65536.0))

const char *const rtref_scene_names[4] = {"lens", "bowl", "rocket", "spheres"};

fx_mat4 rtref_place(double tx, double ty, double tz, double sx, double sy, double sz)
{
    fx_mat4 a, b, m;
    fx_mat4_translate(&a, FX(tx), FX(ty), FX(tz));
    fx_mat4_scale(&b, FX(sx), FX(sy), FX(sz));
    fx_mat4_mul(&m, &a, &b);
    return m;
}

/* y up: the shapes' z axis turned to +y (the scripts' rtrotate -90 1 0 0) */
static fx_mat4 upright(fx_mat4 m)
{
    fx_mat4 r, o;
    fx_mat4_rotate_x(&r, fx_angle_from_deg(-90));
    fx_mat4_mul(&o, &r, &m);
    return o;
}

static fx_rt_material mat(fx_color amb, fx_color diff, fx_color spec, int f, double kr, double kt, double ior)
{
    return fx_rt_material_make(amb, diff, spec, f, FX(kr), FX(kt), FX(ior));
}

static int shape(fx_rt_scene *s, fx_rt_kind k, double taper, fx_mat4 m, const fx_rt_material *mt)
{
    return fx_rt_add_shape(s, k, FX(taper), &m, mt);
}

static int csg_tree(fx_rt_scene *s, int which, int up, const fx_rt_material *m1, const fx_rt_material *m2)
{
#define P(...) (up ? upright(rtref_place(__VA_ARGS__)) : rtref_place(__VA_ARGS__))
    if (which == 0) {
        int a = shape(s, FX_RT_SPHERE, 0, rtref_place(-0.6, 0, 0, 1, 1, 1), m1);
        int b = shape(s, FX_RT_SPHERE, 0, rtref_place(0.6, 0, 0, 1, 1, 1), m1);
        return fx_rt_add_csg(s, FX_RT_INTERSECTION, a, b);
    }
    if (which == 1) {
        int a = shape(s, FX_RT_SPHERE, 0, rtref_place(0, 0, 0, 1, 1, 1), m1);
        int b = shape(s, FX_RT_SPHERE, 0, rtref_place(0, 0, 0, 0.9, 0.9, 0.9), m1);
        int d = fx_rt_add_csg(s, FX_RT_DIFFERENCE, a, b);
        int c = shape(s, FX_RT_CUBE, 0, rtref_place(0, 1.2, 0, 1.2, 1.2, 1.2), m1);
        return fx_rt_add_csg(s, FX_RT_DIFFERENCE, d, c);
    }
    int a = shape(s, FX_RT_CYLINDER, 1, P(0, 0, -0.3, 0.4, 0.4, 1.6), m1);
    int b = shape(s, FX_RT_CYLINDER, 0, P(0, 0, 1.3, 0.4, 0.4, 0.8), m2);
    int u = fx_rt_add_csg(s, FX_RT_UNION, a, b);
    int c = shape(s, FX_RT_CYLINDER, 4.0 / 3, P(0, 0, -0.8, 0.3, 0.3, 0.5), m1);
    u = fx_rt_add_csg(s, FX_RT_UNION, u, c);
    int d = shape(s, FX_RT_CUBE, 0, P(0, 0, -0.5, 0.8, 0.08, 0.3), m2);
    return fx_rt_add_csg(s, FX_RT_UNION, u, d);
#undef P
}

int rtref_csg(fx_rt_scene *s, int which) { return csg_tree(s, which, 0, 0, 0); }

int rtref_scene(fx_rt_scene *s, fx_rt_object *mem, int cap, int which)
{
    fx_rt_scene_init(s, mem, cap);
    fx_vec3 up = fx_vec3_make(0, FX16_ONE, 0);
    s->ambient = fx3d_rgb_from_color(which == 3 ? 0x303030 : 0x404040);
    fx_rt_material fl = mat(0x303030, 0xA0A0A0, 0, 0, 0, 0, 1);
    fx_mat4 fm = rtref_place(0, -1, 0, 1, 1, 1), turn; /* the floor y = -1: the plane's z turned to +y */
    fx_mat4_rotate_x(&turn, fx_angle_from_deg(-90));
    fx_mat4_mul(&fm, &fm, &turn);
    if (which < 3) {
        static const double cam[3][7] = {
            {3, 2.5, 5, 0, 0, 0, 40}, {0, 3, 4, 0, -0.2, 0, 40}, {3, 1.5, 5, 0, 0.6, 0, 45}};
        const double *c = cam[which];
        fx_rt_set_camera(s, fx_vec3_make(FX(c[0]), FX(c[1]), FX(c[2])), fx_vec3_make(FX(c[3]), FX(c[4]), FX(c[5])),
                         up, FX(c[6]));
        s->background = fx3d_rgb_from_color(0x203040);
        fx_rt_add_light(s, fx_vec3_make(FX(3), FX(6), FX(4)), fx3d_rgb_from_color(0xFFFFFF), 0);
        fx_rt_add_shape(s, FX_RT_PLANE, 0, &fm, &fl);
        fx_rt_material m1 = mat(0x402010, 0xD08030, 0xFFFFFF, 40, 0, 0, 1);
        fx_rt_material m2 = mat(0x401010, 0xE03020, 0xFFFFFF, 60, 0, 0, 1);
        return csg_tree(s, which, 1, &m1, &m2) < 0 ? -1 : 0;
    }
    fx_rt_set_camera(s, fx_vec3_make(0, FX(1.6), FX(6)), fx_vec3_make(0, 0, 0), up, FX(40));
    s->background = fx3d_rgb_from_color(0x304060);
    s->max_depth = 5;
    s->cutoff = FX(0.004);
    fx_rt_add_light(s, fx_vec3_make(FX(-4), FX(6), FX(6)), fx3d_rgb_from_color(0xE0E0E0), FX(0.005));
    fx_rt_add_light(s, fx_vec3_make(FX(5), FX(4), FX(3)), fx3d_rgb_from_color(0x606060), 0);
    fx_rt_material marble = mat(0x404040, 0xF0F0F0, 0x404040, 10, 0.15, 0, 1);
    marble.texture = FX_RT_TEX_MARBLE;
    marble.tex_color = fx3d_rgb_from_color(0x283040);
    marble.tex_scale = FX(0.8);
    fx_rt_add_shape(s, FX_RT_PLANE, 0, &fm, &marble);
    fx_rt_material glass = mat(0, 0x101010, 0xFFFFFF, 120, 0.1, 0.85, 1.5);
    fx_rt_material mirror = mat(0x101010, 0x202020, 0xFFFFFF, 100, 0.85, 0, 1);
    if (shape(s, FX_RT_SPHERE, 0, rtref_place(-1.1, 0, 0, 1, 1, 1), &glass) < 0 ||
        shape(s, FX_RT_SPHERE, 0, rtref_place(1.2, 0, 0.3, 1, 1, 1), &mirror) < 0)
        return -1;
    return 0;
}
