/* SPDX-License-Identifier: MIT */
/* The fixed-point ray tracer (fixel/rt.h) against the double-precision
 * reference tracer of tests/lib/rtref.c: intersections on random rays
 * (worst-case error of t), CSG hit lists against the solids' definitions,
 * no overflow at the scene-scale limit (run under UBSan by SAN=1), the
 * lighting terms (shadows, reflection, refraction and total internal
 * reflection, recursion limit), tiles, the ray-tree trace and the
 * documented errors. The reference and the scenes are the benchmark's
 * (tools/fixel-bench/rtref.c). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/error.h"
#include "fixel/render3d.h"
#include "fixel/rt.h"
#include "fixel/scene.h"
#include "fixel/surface.h"
#include "fx_test.h"
#include "scenebuf.h"
#include "../../tools/fixel-bench/rtref.h"
#include "../../kernel-free-src/rt/rt_int.h" /* white box: the box test */

#define Q (1.0 / 65536.0)
#define FX(v) ((fx16)lround((v) * 65536.0))

static double urand(uint32_t *s, double lo, double hi) { return lo + (hi - lo) * (fx_test_rand(s) / 4294967296.0); }

/* A random placement: rotation about a random axis, scales in [lo, hi]
 * per axis, translation within +-tr. */
/* x, then y, then z: the order of a call's arguments is unspecified (gcc
 * takes them the other way round on ARM), and the random scenes must be the
 * same on every architecture. */
static fx_vec3 urand3(uint32_t *s, double xlo, double xhi, double ylo, double yhi, double zlo, double zhi)
{
    fx16 x = FX(urand(s, xlo, xhi));
    fx16 y = FX(urand(s, ylo, yhi));
    fx16 z = FX(urand(s, zlo, zhi));
    return fx_vec3_make(x, y, z);
}

static void random_matrix(uint32_t *s, double lo, double hi, double tr, fx_mat4 *m)
{
    fx_mat4 a, b, t;
    fx_vec3 tv = urand3(s, -tr, tr, -tr, tr, -tr, tr);
    fx_mat4_translate(&a, tv.x, tv.y, tv.z);
    fx_angle ang = fx_angle_from_deg(lround(urand(s, 0, 360)));
    fx_mat4_rotate(&b, ang, urand3(s, -1, 1, -1, 1, 0.1, 1));
    fx_mat4_mul(&t, &a, &b);
    fx_vec3 sv = urand3(s, lo, hi, lo, hi, lo, hi);
    fx_mat4_scale(&a, sv.x, sv.y, sv.z);
    fx_mat4_mul(m, &t, &a);
}

static void random_ray(uint32_t *s, double range, fx_vec3 *S, fx_vec3 *c)
{
    *S = urand3(s, -range, range, -range, range, -range, range);
    *c = urand3(s, -1, 1, -1, 1, -1, 1);
    if (fx_vec3_normalize(c) < 0)
        *c = fx_vec3_make(FX16_ONE, 0, 0);
}

static void to_d(fx_vec3 v, double o[3]) { o[0] = v.x * Q, o[1] = v.y * Q, o[2] = v.z * Q; }

FX_TEST(rt_isqrt_of_the_discriminant_is_exact)
{
    /* through a sphere's hits: a ray from (0,0,-d) along +z meets the unit
     * sphere at exactly d - 1 and d + 1 for every representable d */
    fx_rt_object mem[1];
    fx_rt_scene s;
    fx_rt_scene_init(&s, mem, 1);
    fx_mat4 m;
    fx_mat4_identity(&m);
    FX_CHECK_EQ(fx_rt_add_shape(&s, FX_RT_SPHERE, 0, &m, 0), 0);
    uint32_t seed = 5;
    for (int i = 0; i < 20000; i++) {
        fx16 d = (fx16)(fx_test_rand(&seed) % (100u << 16));
        fx_rt_hitlist l;
        fx_rt_hits(&s, 0, fx_vec3_make(0, 0, -d), fx_vec3_make(0, 0, FX16_ONE), &l);
        FX_CHECK_EQ(l.n, 2);
        FX_CHECK_EQ(l.h[0].t, d - FX16_ONE);
        FX_CHECK_EQ(l.h[1].t, d + FX16_ONE);
    }
}

/* The worst |t - t_ref| over random placements and rays for each shape,
 * skipping near-tangent rays (where t itself is ill-conditioned). */
static double errs[100000];
static int nerr;
static int cmp_d(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* How far world point P is from the surface of a (tapered) cylinder placed
 * by m, measured in object space (m inverted in double, independently of the
 * library's fixed-point inverse). */
static double cylinder_residual(const fx_mat4 *m, fx16 taper, const double P[3])
{
    double a[3][3], inv[3][3], q[3], o[3];
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++)
            a[i][j] = m->m[i][j] * Q;
        q[i] = P[i] - m->m[i][3] * Q;
    }
    double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                 a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
            inv[i][j] = (a[i1][j1] * a[i2][j2] - a[i1][j2] * a[i2][j1]) / det;
        }
    for (int i = 0; i < 3; i++)
        o[i] = inv[i][0] * q[0] + inv[i][1] * q[1] + inv[i][2] * q[2];
    double s = taper * Q, rho = hypot(o[0], o[1]), z = o[2];
    double zc = z < 0 ? 0 : z > 1 ? 1 : z, rad = 1 + (s - 1) * zc;
    double wall = fabs(rho - rad) + fabs(z - zc);                         /* on the side */
    double cap0 = fabs(z) + (rho > 1 ? rho - 1 : 0), cap1 = fabs(z - 1) + (rho > s ? rho - s : 0); /* on a cap */
    return fmin(wall, fmin(cap0, cap1));
}
static int n_illcond;

static double shape_error(fx_rt_kind kind, fx16 taper, int n, double *worst_rel)
{
    n_illcond = 0;
    nerr = 0;
    uint32_t seed = 1234 + (uint32_t)kind * 77 + (uint32_t)taper;
    double worst = 0;
    *worst_rel = 0;
    int compared = 0;
    for (int i = 0; i < n; i++) {
        fx_rt_object mem[1];
        fx_rt_scene s;
        fx_rt_scene_init(&s, mem, 1);
        fx_mat4 m;
        random_matrix(&seed, 0.25, 4, 20, &m);
        if (fx_rt_add_shape(&s, kind, taper, &m, 0) < 0)
            continue;
        fx_vec3 S, c;
        random_ray(&seed, 40, &S, &c);
        /* aim at the object half the time so most rays hit */
        if (i & 1) {
            fx_vec3 o = urand3(&seed, -1, 1, -1, 1, -1, 1);
            fx_vec3 target = fx_vec3_make(m.m[0][3] + o.x, m.m[1][3] + o.y, m.m[2][3] + o.z);
            c = fx_vec3_make(target.x - S.x, target.y - S.y, target.z - S.z);
            if (fx_vec3_normalize(&c) < 0)
                continue;
        }
        fx_rt_hitlist l;
        rtref_list r;
        double Sd[3], cd[3];
        to_d(S, Sd);
        to_d(c, cd);
        fx_rt_hits(&s, 0, S, c, &l);
        rtref_hits(&s, 0, Sd, cd, &r);
        if (kind != FX_RT_SQUARE && r.n == 2 && fabs(r.h[1].t - r.h[0].t) < 0.05)
            continue; /* grazing: tested separately */
        if (kind == FX_RT_TORUS) {
            /* a graze of either part of the ring: two crossings within
             * 0.05 (in either list: the reference's sampling can miss a
             * pair closer than its step) */
            int graze = 0;
            for (int k = 1; k < r.n; k++)
                graze |= r.h[k].t - r.h[k - 1].t < 0.05;
            for (int k = 1; k < l.n; k++)
                graze |= (l.h[k].t - l.h[k - 1].t) * Q < 0.05;
            if (graze)
                continue;
            FX_CHECK_MSG(l.n == r.n, "torus: %d hits, reference %d", l.n, r.n);
        }
        if (l.n != r.n) {
            /* a miss/hit disagreement is allowed only at a graze */
            FX_CHECK_MSG(r.n == 0 || kind == FX_RT_SQUARE || fabs(r.h[1].t - r.h[0].t) < 0.05, "kind %d: %d hits, reference %d (t %f %f)",
                         kind, l.n, r.n, r.n ? r.h[0].t : 0, r.n ? r.h[1].t : 0);
            continue;
        }
        for (int k = 0; k < l.n; k++) {
            if (fabs(r.h[k].t) > 2 * FX_RT_WORLD * 2)
                continue; /* beyond the world: such t saturate and are never used */
            double e = fabs(l.h[k].t * Q - r.h[k].t);
            if (kind == FX_RT_CYLINDER && e / fmax(1, fabs(r.h[k].t)) > 1.0 / 4096) {
                /* A ray leaving near a rim, almost along the wall: t is
                 * ill-conditioned there (a tiny step across the rim moves the
                 * exit far along the ray). Such a hit must still lie on the
                 * surface (backward error) and be rare; it is counted apart. */
                double P[3] = {Sd[0] + l.h[k].t * Q * cd[0], Sd[1] + l.h[k].t * Q * cd[1], Sd[2] + l.h[k].t * Q * cd[2]};
                double res = cylinder_residual(&m, taper, P);
                /* the patch tests' slack (RIM, 2^-10 in object space) plus as
                 * much again for the rounding of the point */
                FX_CHECK_MSG(res < 2.0 / 1024, "kind %d: hit at t %f is %g off the surface", kind, l.h[k].t * Q, res);
                n_illcond++;
                continue;
            }
            if (nerr < (int)(sizeof errs / sizeof errs[0]))
                errs[nerr++] = e / fmax(1, fabs(r.h[k].t));
            if (e > worst)
                worst = e;
            double rel = e / fmax(1, fabs(r.h[k].t));
            if (rel > *worst_rel)
                *worst_rel = rel;
            FX_CHECK_EQ(l.h[k].entering, r.h[k].entering);
        }
        compared++;
    }
    FX_CHECK_MSG(compared > n / 4, "only %d of %d rays compared", compared, n);
    return worst;
}

FX_TEST(rt_shapes_match_double_on_random_rays)
{
    static const struct { fx_rt_kind k; fx16 taper; const char *name; double bound; } shapes[] = {
        /* bounds on the error relative to max(1, |t|), docs/RAYTRACE.md */
        {FX_RT_SPHERE, 0, "sphere", 1.0 / 16384},   {FX_RT_CUBE, 0, "cube", 1.0 / 16384},
        {FX_RT_SQUARE, 0, "square", 1.0 / 16384},   {FX_RT_PLANE, 0, "plane", 1.0 / 256},
        {FX_RT_CYLINDER, FX16_ONE, "cylinder", 1.0 / 512}, {FX_RT_CYLINDER, 0, "cone", 1.0 / 512},
        {FX_RT_CYLINDER, FX16_ONE / 2, "tapered cylinder", 1.0 / 512},
        {FX_RT_TORUS, FX16_ONE / 4, "torus (r = 1/4)", 1.0 / 16384},
        {FX_RT_TORUS, FX16_ONE * 3 / 4, "torus (r = 3/4)", 1.0 / 16384},
    };
    for (size_t i = 0; i < sizeof shapes / sizeof shapes[0]; i++) {
        double rel, e = shape_error(shapes[i].k, shapes[i].taper, 20000, &rel);
        qsort(errs, (size_t)nerr, sizeof errs[0], cmp_d);
        printf("    %-17s worst |t - t_double| = %.3g; relative to max(1, |t|): worst %.3g, 99.9%% %.3g, median %.3g "
               "(%d hits; %d ill-conditioned rim exits on the surface)\n",
               shapes[i].name, e, rel, nerr ? errs[nerr * 999 / 1000] : 0, nerr ? errs[nerr / 2] : 0, nerr, n_illcond);
        FX_CHECK_MSG(n_illcond * 1000 <= nerr, "%s: %d ill-conditioned hits of %d", shapes[i].name, n_illcond, nerr);
        FX_CHECK_MSG(rel <= shapes[i].bound, "%s: relative t error %g above %g", shapes[i].name, rel,
                     shapes[i].bound);
    }
}

/* ---- CSG ---- */


FX_TEST(rt_csg_hit_lists_follow_the_solids_definition)
{
    uint32_t seed = 99;
    for (int which = 0; which < 3; which++) {
        fx_rt_object mem[16];
        fx_rt_scene s;
        fx_rt_scene_init(&s, mem, 16);
        int root = rtref_csg(&s, which);
        FX_CHECK(root >= 0);
        int checked = 0, nonempty = 0;
        for (int i = 0; i < 4000; i++) {
            fx_vec3 S, c;
            random_ray(&seed, 4, &S, &c);
            fx_vec3 target = urand3(&seed, -1, 1, -1, 1, -1, 1);
            c = fx_vec3_make(target.x - S.x, target.y - S.y, target.z - S.z);
            if (fx_vec3_normalize(&c) < 0)
                continue;
            fx_rt_hitlist l;
            fx_rt_hits(&s, root, S, c, &l);
            FX_CHECK(!l.overflow);
            nonempty += l.n > 0;
            double Sd[3], cd[3];
            to_d(S, Sd);
            to_d(c, cd);
            /* between consecutive hits (and before the first, after the
             * last) the list's state equals the definition at the middle */
            int in = l.inside0;
            for (int k = 0; k <= l.n; k++) {
                double t0 = k ? l.h[k - 1].t * Q : (l.n ? l.h[0].t * Q - 1 : 0);
                double t1 = k < l.n ? l.h[k].t * Q : (l.n ? l.h[l.n - 1].t * Q + 1 : 1);
                if (k)
                    in = l.h[k - 1].entering;
                if (k && k < l.n)
                    FX_CHECK(t1 >= t0);
                if (t1 - t0 < 1.0 / 1024)
                    continue; /* too thin to sample away from the surfaces */
                double tm = (t0 + t1) / 2, p[3] = {Sd[0] + cd[0] * tm, Sd[1] + cd[1] * tm, Sd[2] + cd[2] * tm};
                FX_CHECK_MSG(in == rtref_inside(&s, root, p), "csg %d ray %d interval %d: state %d", which, i, k, in);
                checked++;
            }
            /* the hits alternate entering and leaving */
            for (int k = 0; k < l.n; k++)
                FX_CHECK_EQ(l.h[k].entering, k == 0 ? !l.inside0 : !l.h[k - 1].entering);
        }
        FX_CHECK(checked > 4000);
        FX_CHECK(nonempty > 1000);
    }
}

FX_TEST(rt_csg_ray_starting_inside_sees_the_hits_ahead)
{
    /* a union of nine unit spheres in a row along x: the whole line
     * crosses it 18 times, more than a hit list holds. A ray starting at
     * the centre of the last sphere must still find its exit at t = 1,
     * whatever lies behind it (a refracted ray starts inside like this) */
    fx_rt_object mem[32];
    fx_rt_scene s;
    fx_rt_scene_init(&s, mem, 32);
    int root = -1;
    for (int k = 0; k < 9; k++) {
        fx_mat4 m;
        fx_mat4_translate(&m, (4 * k - 16) * FX16_ONE, 0, 0);
        int o = fx_rt_add_shape(&s, FX_RT_SPHERE, 0, &m, 0);
        FX_CHECK(o >= 0);
        root = k ? fx_rt_add_csg(&s, FX_RT_UNION, root, o) : o;
        FX_CHECK(root >= 0);
    }
    /* the whole line: the nearest 16 crossings kept, overflow reported */
    fx_rt_hitlist l;
    fx_rt_hits(&s, root, fx_vec3_make(16 * FX16_ONE, 0, 0), fx_vec3_make(FX16_ONE, 0, 0), &l);
    FX_CHECK(l.overflow);
    FX_CHECK_EQ(l.n, FX_RT_MAX_HITS);
    FX_CHECK(l.h[0].t < -30 * FX16_ONE);
    for (int k = 0; k < 2; k++) { /* a primary ray (tmin 0) and a secondary one */
        fx16 tmin = k ? FX_RT_EPS : 0;
        fx_rt_hit h;
        fx_vec3 n;
        FX_CHECK(fx_rt_first_hit(&s, fx_vec3_make(16 * FX16_ONE, 0, 0), fx_vec3_make(FX16_ONE, 0, 0), tmin, &h, &n));
        FX_CHECK_EQ(h.t, FX16_ONE);
        FX_CHECK(!h.entering);
        FX_CHECK_EQ(n.x, FX16_ONE);
        /* going back (-x) the list is long ahead of the ray: the exit
         * at t = 1 again */
        FX_CHECK(fx_rt_first_hit(&s, fx_vec3_make(16 * FX16_ONE, 0, 0), fx_vec3_make(-FX16_ONE, 0, 0), tmin, &h, 0));
        FX_CHECK_EQ(h.t, FX16_ONE);
    }
}

FX_TEST(rt_bounding_boxes_skip_only_missed_shapes)
{
    /* a ray the box test rejects has no hit on the shape itself */
    fx_rt_object mem[16];
    fx_rt_scene s;
    fx_rt_scene_init(&s, mem, 16);
    int root = rtref_csg(&s, 2);
    uint32_t seed = 4;
    int skipped = 0;
    for (int i = 0; i < 20000; i++) {
        fx_vec3 S, c;
        random_ray(&seed, 3, &S, &c);
        for (int o = 0; o <= root; o++) {
            if (s.obj[o].kind >= FX_RT_UNION || fx_rt_box_meets(&s.obj[o].box, S, c))
                continue;
            skipped++;
            fx_rt_hitlist l = {0, 0, 0, {{0}}};
            fx_rt_leaf_hits(&s.obj[o], o, fx_rt_xform(&s.obj[o].inv, S, 1), fx_rt_xform_dir24(&s.obj[o].inv, c), &l);
            FX_CHECK_MSG(l.n == 0, "ray %d: object %d skipped but hit at t %d", i, o, l.h[0].t);
        }
    }
    FX_CHECK(skipped > 10000);
}

FX_TEST(rt_no_overflow_at_the_scene_limit)
{
    /* extreme placements (scales 1/16 and 8, far translations) and rays
     * from anywhere in the world box: every list sorted, no sanitizer
     * report (SAN=1 runs this under UBSan) */
    uint32_t seed = 77;
    const double W = FX_RT_WORLD;
    int made = 0, hits = 0;
    for (int i = 0; i < 3000; i++) {
        fx_rt_object mem[4];
        fx_rt_scene s;
        fx_rt_scene_init(&s, mem, 4);
        fx_mat4 m;
        double lo = (i & 1) ? 1.0 / 16 : 1, hi = (i & 1) ? 0.2 : 8;
        random_matrix(&seed, lo, hi, W - 30, &m);
        int k = (int)(fx_test_rand(&seed) % 6);
        fx16 taper = (fx16)(fx_test_rand(&seed) % (2u * FX16_ONE + 1));
        if (k == 5) /* the torus: tube radius 1/16..1 */
            k = FX_RT_TORUS, taper = FX16_ONE / 16 + taper % (FX16_ONE * 15 / 16 + 1);
        int r = fx_rt_add_shape(&s, (fx_rt_kind)k, taper, &m, 0);
        if (r < 0) {
            FX_CHECK(r == -FX_ERANGE || r == -FX_EDOM);
            continue;
        }
        made++;
        for (int j = 0; j < 50; j++) {
            fx_vec3 S, c;
            random_ray(&seed, W, &S, &c);
            if (j & 1) { /* toward the object */
                c = fx_vec3_make(m.m[0][3] - S.x, m.m[1][3] - S.y, m.m[2][3] - S.z);
                if (fx_vec3_normalize(&c) < 0)
                    continue;
            } else if (j % 4 == 2) { /* almost parallel to the caps / faces: crossings far out */
                c = fx_vec3_make(m.m[0][0] + (fx16)(fx_test_rand(&seed) % 64) - 32, m.m[1][0], m.m[2][0]);
                if (fx_vec3_normalize(&c) < 0)
                    continue;
            }
            fx_rt_hitlist l;
            fx_rt_hits(&s, 0, S, c, &l);
            hits += l.n > 0;
            for (int q = 1; q < l.n; q++)
                FX_CHECK(l.h[q].t >= l.h[q - 1].t);
            fx_rt_hit h;
            fx_vec3 n;
            if (fx_rt_first_hit(&s, S, c, 0, &h, &n)) {
                /* the normal is unit */
                double len = sqrt((double)n.x * n.x + (double)n.y * n.y + (double)n.z * n.z) * Q;
                FX_CHECK_MSG(fabs(len - 1) < 1.0 / 1024, "normal length %f", len);
            }
        }
    }
    FX_CHECK(made > 1000);
    FX_CHECK(hits > 5000);
}

FX_TEST(rt_torus_grazes_and_self_intersection)
{
    /* tangent to the outer equator: z = r exactly along the ring's top,
     * a double root entering and leaving at the same t (or a miss), and
     * one raw unit above it a miss */
    fx_rt_object mem[2];
    fx_rt_scene s;
    fx_rt_scene_init(&s, mem, 2);
    fx_mat4 m;
    fx_mat4_identity(&m);
    FX_CHECK(fx_rt_add_shape(&s, FX_RT_TORUS, FX16_ONE / 4, &m, 0) == 0);
    fx_rt_hitlist l;
    fx_rt_hits(&s, 0, fx_vec3_make(-5 * FX16_ONE, FX16_ONE, FX16_ONE / 4 + 1), fx_vec3_make(FX16_ONE, 0, 0), &l);
    FX_CHECK_EQ(l.n, 0);
    fx_rt_hits(&s, 0, fx_vec3_make(-5 * FX16_ONE, FX16_ONE, FX16_ONE / 4), fx_vec3_make(FX16_ONE, 0, 0), &l);
    FX_CHECK(l.n == 0 || (l.n == 2 && abs(l.h[0].t - 5 * FX16_ONE) <= 2 && abs(l.h[1].t - 5 * FX16_ONE) <= 2));
    /* through the hole along z: a miss; along x: four crossings */
    fx_rt_hits(&s, 0, fx_vec3_make(0, 0, -5 * FX16_ONE), fx_vec3_make(0, 0, FX16_ONE), &l);
    FX_CHECK_EQ(l.n, 0);
    /* rays leaving 20 000 surface points outward never see the surface
     * they start on; the torus is not convex, so they may meet another
     * part of it, but not within 0.05 */
    uint32_t seed = 8;
    int other = 0;
    for (int i = 0; i < 20000; i++) {
        double u = urand(&seed, 0, 2 * M_PI), v = urand(&seed, 0, 2 * M_PI), r = 0.25;
        double n[3] = {cos(v) * cos(u), cos(v) * sin(u), sin(v)};
        fx_vec3 P = fx_vec3_make(FX((1 + r * cos(v)) * cos(u)), FX((1 + r * cos(v)) * sin(u)), FX(r * sin(v)));
        double w[3]; /* one by one: an initializer list's order is unspecified */
        for (int k = 0; k < 3; k++)
            w[k] = urand(&seed, -0.5, 0.5);
        fx_vec3 d = fx_vec3_make(FX(n[0] + w[0]), FX(n[1] + w[1]), FX(n[2] + w[2]));
        if (fx_vec3_normalize(&d) < 0 || (d.x * n[0] + d.y * n[1] + d.z * n[2]) * Q <= 0.125)
            continue;
        fx_rt_hit h;
        if (fx_rt_first_hit(&s, P, d, FX_RT_EPS, &h, 0)) {
            FX_CHECK_MSG(h.t > FX(0.05), "self-hit at t %d", h.t);
            other++;
        }
    }
    /* from the inner side across the hole (834 of them) */
    FX_CHECK_MSG(other > 400, "%d rays met the far side", other);
    printf("    torus: %d rays from its surface met another part of it, none itself\n", other);
}

FX_TEST(rt_grazing_rays_and_self_intersection)
{
    fx_rt_object mem[2];
    fx_rt_scene s;
    fx_rt_scene_init(&s, mem, 2);
    fx_mat4 m;
    fx_mat4_identity(&m);
    fx_rt_add_shape(&s, FX_RT_SPHERE, 0, &m, 0);
    fx_rt_hitlist l;
    /* tangent at x = 1 exactly: one double root, entering then leaving */
    fx_rt_hits(&s, 0, fx_vec3_make(FX16_ONE, 0, -5 * FX16_ONE), fx_vec3_make(0, 0, FX16_ONE), &l);
    FX_CHECK_EQ(l.n, 2);
    FX_CHECK_EQ(l.h[0].t, 5 * FX16_ONE);
    FX_CHECK_EQ(l.h[1].t, 5 * FX16_ONE);
    /* just outside: a miss */
    fx_rt_hits(&s, 0, fx_vec3_make(FX16_ONE + 1, 0, -5 * FX16_ONE), fx_vec3_make(0, 0, FX16_ONE), &l);
    FX_CHECK_EQ(l.n, 0);
    /* from every surface point, a ray leaving along the outward normal
     * must not see the surface it starts on (t > FX_RT_EPS) */
    uint32_t seed = 3;
    for (int i = 0; i < 20000; i++) {
        fx_vec3 d = urand3(&seed, -1, 1, -1, 1, -1, 1);
        if (fx_vec3_normalize(&d) < 0)
            continue;
        fx_rt_hit h;
        /* P on the sphere (to rounding), leaving outward and tangentially */
        fx_vec3 out = d;
        out.x = d.x + (fx16)(urand(&seed, -0.5, 0.5) * 65536);
        if (fx_vec3_normalize(&out) < 0 || fx_vec3_dot(out, d) <= FX16_ONE / 8)
            continue;
        FX_CHECK_MSG(!fx_rt_first_hit(&s, d, out, FX_RT_EPS, &h, 0), "self-hit at t %d", h.t);
    }
}

/* ---- lighting ---- */

static fx_rt_material matte(fx_color c)
{
    fx_rt_material m;
    memset(&m, 0, sizeof m);
    m.diffuse = fx3d_rgb_from_color(c);
    m.ior = FX16_ONE;
    return m;
}

static fx_mat4 floor_matrix(void)
{
    fx_mat4 a, b, m;
    fx_mat4_translate(&a, 0, -FX16_ONE, 0);
    fx_mat4_rotate_x(&b, fx_angle_from_deg(-90));
    fx_mat4_mul(&m, &a, &b);
    return m;
}

FX_TEST(rt_shadow_feelers_darken_what_the_light_cannot_see)
{
    fx_rt_object mem[4];
    fx_rt_scene s;
    fx_rt_scene_init(&s, mem, 4);
    fx_mat4 fl = floor_matrix(), sp;
    fx_rt_material white = matte(0xFFFFFF);
    fx_rt_add_shape(&s, FX_RT_PLANE, 0, &fl, &white);
    fx_mat4_scale(&sp, FX16_HALF, FX16_HALF, FX16_HALF);
    fx_rt_add_shape(&s, FX_RT_SPHERE, 0, &sp, &white);
    fx_rt_add_light(&s, fx_vec3_make(0, 10 * FX16_ONE, 0), fx3d_rgb_from_color(0xFFFFFF), 0);
    /* straight down onto the floor below the sphere, and beside it */
    fx_vec3 down = fx_vec3_make(0, -FX16_ONE, 0);
    fx3d_rgb under = fx_rt_trace_ray(&s, fx_vec3_make(FX16_ONE / 100, -FX16_ONE / 2 - 100, 0), down, 0, 0);
    fx3d_rgb beside = fx_rt_trace_ray(&s, fx_vec3_make(3 * FX16_ONE, 0, 0), down, 0, 0);
    FX_CHECK_EQ(under.r, 0); /* no ambient: the shadow is black */
    FX_CHECK(beside.r > FX16_ONE / 2);
    /* attenuation 1 / (1 + k d^2): k = 1 at d ~ 11 divides by ~122 */
    s.light[0].atten = FX16_ONE;
    fx3d_rgb att = fx_rt_trace_ray(&s, fx_vec3_make(3 * FX16_ONE, 0, 0), down, 0, 0);
    double d2 = 9 + 121, want = beside.r * Q / (1 + d2);
    FX_CHECK_MSG(fabs(att.r * Q - want) < 1.0 / 256, "attenuated %f, want %f", att.r * Q, want);
    /* the API caps k at 1; a larger k written into the struct counts as
     * 1, also with the light far outside the world (d^2 = 2^28 units^2:
     * k d^2 overflowed int64 before the cap, which SAN=1 reports) */
    FX_CHECK_EQ(fx_rt_add_light(&s, fx_vec3_make(0, 10 * FX16_ONE, 0), fx3d_rgb_from_color(0xFFFFFF), FX16_ONE + 1),
                -FX_EDOM);
    FX_CHECK_EQ(fx_rt_add_light(&s, fx_vec3_make(0, 10 * FX16_ONE, 0), fx3d_rgb_from_color(0xFFFFFF), -1), -FX_EDOM);
    s.light[0].atten = INT32_MAX;
    fx3d_rgb capped = fx_rt_trace_ray(&s, fx_vec3_make(3 * FX16_ONE, 0, 0), down, 0, 0);
    FX_CHECK_EQ(capped.r, att.r);
    s.light[0].pos = fx_vec3_make(0, INT32_MAX / 2, 0); /* 16 384 units up */
    fx3d_rgb far = fx_rt_trace_ray(&s, fx_vec3_make(3 * FX16_ONE, 0, 0), down, 0, 0);
    FX_CHECK(far.r >= 0 && far.r < 2);
}

/* Issue #44: glass casts no black shadow. A shadow feeler passes a surface
 * of transparency kt with kt of the light (the documented approximation:
 * straight, dimmed, no refraction), so an invisible lens (index 1, kt = 1)
 * leaves the floor as lit as without it, a ball of kt = 1/2 passes
 * 1/2 x 1/2 = 1/4 of it through its two surfaces, and an opaque ball
 * behind the glass still blocks everything. */
FX_TEST(rt_shadow_feelers_pass_through_glass)
{
    fx_rt_object mem[4];
    fx_rt_scene s;
    fx_vec3 down = fx_vec3_make(0, -FX16_ONE, 0), below = fx_vec3_make(FX16_ONE / 100, -FX16_ONE / 2 - 100, 0);
    fx3d_rgb lit = {0, 0, 0};
    for (int k = 0; k < 4; k++) {
        fx_rt_scene_init(&s, mem, 4);
        fx_mat4 fl = floor_matrix(), sp;
        fx_rt_material white = matte(0xFFFFFF), glass = matte(0xFFFFFF);
        glass.transparency = k == 1 ? FX16_ONE : FX16_HALF;
        glass.ior = FX16_ONE;
        fx_rt_add_shape(&s, FX_RT_PLANE, 0, &fl, &white);
        fx_mat4_scale(&sp, FX16_HALF, FX16_HALF, FX16_HALF);
        if (k > 0)
            fx_rt_add_shape(&s, FX_RT_SPHERE, 0, &sp, &glass);
        if (k == 3) { /* an opaque ball above the glass one */
            fx_mat4 t, sc2;
            fx_mat4_translate(&t, 0, 3 * FX16_ONE, 0);
            fx_mat4_scale(&sc2, FX16_HALF, FX16_HALF, FX16_HALF);
            fx_mat4_mul(&sp, &t, &sc2);
            fx_rt_add_shape(&s, FX_RT_SPHERE, 0, &sp, &white);
        }
        fx_rt_add_light(&s, fx_vec3_make(0, 10 * FX16_ONE, 0), fx3d_rgb_from_color(0xFFFFFF), 0);
        /* the floor point straight under the ball, seen from just above it */
        fx3d_rgb under = fx_rt_trace_ray(&s, below, down, 0, 0);
        if (k == 0)
            lit = under;
        else if (k == 1)
            FX_CHECK_MSG(under.r == lit.r, "invisible lens: %d, no lens %d", under.r, lit.r);
        else if (k == 2)
            FX_CHECK_MSG(abs(under.r - lit.r / 4) <= 2, "kt 1/2: %d, want %d", under.r, lit.r / 4);
        else
            FX_CHECK_EQ(under.r, 0);
    }
    FX_CHECK(lit.r > FX16_ONE / 2);
    /* the feeler's own numbers */
    int blocker;
    FX_CHECK_EQ(fx_rt_feeler_transmit(&s, below, fx_vec3_make(0, FX16_ONE, 0), FX_RT_EPS, 10 * FX16_ONE, &blocker), 0);
    FX_CHECK_EQ(blocker, 2);
    FX_CHECK_EQ(fx_rt_feeler_transmit(&s, below, fx_vec3_make(0, FX16_ONE, 0), FX_RT_EPS, 2 * FX16_ONE, &blocker),
                FX16_ONE / 4);
    FX_CHECK_EQ(blocker, -1);
}

typedef struct lines {
    char text[1 << 16];
    size_t len;
    int rays, tir, hits;
} lines;

static void collect(void *u, const char *line)
{
    lines *l = u;
    size_t n = strlen(line);
    if (l->len + n + 2 < sizeof l->text) {
        memcpy(l->text + l->len, line, n);
        l->len += n;
        l->text[l->len++] = '\n';
        l->text[l->len] = 0;
    }
    l->rays += strstr(line, "ray from") != 0;
    l->tir += strstr(line, "total internal reflection") != 0;
    l->hits += strstr(line, "hit object") != 0;
}

FX_TEST(rt_reflection_and_refraction_follow_the_laws)
{
    fx_rt_object mem[4];
    fx_rt_scene s;
    fx_rt_scene_init(&s, mem, 4);
    s.background = fx3d_rgb_from_color(0x0000FF);
    fx_rt_material glass = matte(0);
    glass.transparency = FX16_ONE;
    glass.ior = FX16_ONE * 3 / 2;
    fx_mat4 m;
    fx_mat4_identity(&m);
    fx_rt_add_shape(&s, FX_RT_SPHERE, 0, &m, &glass);
    /* through the centre: no bending, the background comes through whole */
    fx3d_rgb c = fx_rt_trace_ray(&s, fx_vec3_make(0, 0, 5 * FX16_ONE), fx_vec3_make(0, 0, -FX16_ONE), 0, 0);
    FX_CHECK(abs(c.b - FX16_ONE) < 16 && c.r == 0);
    /* from inside at a steep angle to the surface: total internal
     * reflection (critical angle asin(1/1.5) = 41.8 degrees) */
    lines *L = calloc(1, sizeof *L);
    s.max_depth = 3;
    fx_vec3 d = fx_vec3_make(FX16_ONE, FX16_ONE / 10, 0);
    fx_vec3_normalize(&d);
    fx_rt_trace_ray(&s, fx_vec3_make(0, FX16_ONE * 9 / 10, 0), d, collect, L);
    FX_CHECK_MSG(L->tir >= 1, "no total internal reflection in:\n%s", L->text);
    /* the recursion limit bounds the ray tree: depth 3 -> at most 4 rays on a chain */
    FX_CHECK(L->rays <= 4);
    FX_CHECK(L->rays >= 2);
    free(L);

    /* a mirror: r = d - 2 (d.m) m, seen as the colour of what it reflects */
    fx_rt_object mem2[4];
    fx_rt_scene t;
    fx_rt_scene_init(&t, mem2, 4);
    fx_rt_material mirror = matte(0);
    mirror.reflectivity = FX16_ONE;
    fx_mat4 fl = floor_matrix();
    fx_rt_add_shape(&t, FX_RT_PLANE, 0, &fl, &mirror);
    fx_rt_material red = matte(0xFF0000);
    red.ambient = fx3d_rgb_from_color(0xFF0000);
    t.ambient = fx3d_rgb_from_color(0xFFFFFF);
    fx_mat4 sq = rtref_place(4, 1, 0, 0.5, 0.5, 0.5);
    fx_rt_add_shape(&t, FX_RT_SPHERE, 0, &sq, &red);
    /* from (0,1,0) down at 45 degrees toward +x: bounces at (2,-1,0) and
     * rises into the sphere about (4,1,0) */
    fx_vec3 dd = fx_vec3_make(FX16_ONE, -FX16_ONE, 0);
    fx_vec3_normalize(&dd);
    fx3d_rgb seen = fx_rt_trace_ray(&t, fx_vec3_make(0, FX16_ONE, 0), dd, 0, 0);
    FX_CHECK(seen.r > FX16_ONE / 2 && seen.g == 0);
    t.max_depth = 0; /* no recursion: the mirror shows only its own (black) terms */
    seen = fx_rt_trace_ray(&t, fx_vec3_make(0, FX16_ONE, 0), dd, 0, 0);
    FX_CHECK_EQ(seen.r, 0);
}

FX_TEST(rt_image_agrees_with_the_double_reference)
{
    fx_rt_object mem[8];
    fx_rt_scene s;
    FX_CHECK_EQ(rtref_scene(&s, mem, 8, 3), 0);
    const int W = 120, H = 80;
    int differ = 0, worst = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            fx_color a = fx_rt_trace_pixel(&s, W, H, x, y, 0, 0), b = rtref_pixel(&s, W, H, x, y, 0);
            int d = 0;
            for (int k = 0; k < 24; k += 8) {
                int e = abs((int)((a >> k) & 255) - (int)((b >> k) & 255));
                d = e > d ? e : d;
            }
            differ += d > 2;
            worst = d > worst ? d : worst;
        }
    printf("    spheres %dx%d: %d of %d pixels differ by more than 2 levels from double (worst %d)\n", W, H, differ,
           W * H, worst);
    FX_CHECK_MSG(differ * 100 <= W * H, "%d pixels differ", differ); /* at most 1% */
}

FX_TEST(rt_torus_image_agrees_with_the_double_reference)
{
    /* a reflective ring standing on a floor, a glass ring lying in front:
     * the reference finds the quartic's roots by sampling and bisection */
    fx_rt_object mem[4];
    fx_rt_scene s;
    /* the lens scene's camera, light and floor y = -1 (object 0), without
     * the lens */
    FX_CHECK(rtref_scene(&s, mem, 4, 0) >= 0);
    s.n = 1;
    fx_rt_material gold = matte(0xD0A030), glass = matte(0x101010);
    gold.specular = glass.specular = fx3d_rgb_from_color(0xFFFFFF);
    gold.shininess = 80;
    gold.reflectivity = FX(0.3);
    glass.shininess = 120;
    glass.transparency = FX(0.85);
    glass.ior = FX(1.5);
    fx_mat4 a, b, m;
    fx_mat4_translate(&a, 0, FX(0.2), FX(-0.5));
    fx_mat4_rotate_y(&b, fx_angle_from_deg(25));
    fx_mat4_mul(&m, &a, &b);
    fx_mat4_scale(&b, FX(0.9), FX(0.9), FX(0.9));
    fx_mat4_mul(&m, &m, &b);
    FX_CHECK(fx_rt_add_shape(&s, FX_RT_TORUS, FX(0.3), &m, &gold) >= 0);
    fx_mat4_translate(&a, FX(0.8), FX(-0.75), FX(1));
    fx_mat4_rotate_x(&b, fx_angle_from_deg(90));
    fx_mat4_mul(&m, &a, &b);
    fx_mat4_scale(&b, FX(0.6), FX(0.6), FX(0.6));
    fx_mat4_mul(&m, &m, &b);
    FX_CHECK(fx_rt_add_shape(&s, FX_RT_TORUS, FX(0.4), &m, &glass) >= 0);
    const int W = 120, H = 80;
    int differ = 0, worst = 0, ring = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            fx_color p = fx_rt_trace_pixel(&s, W, H, x, y, 0, 0), q = rtref_pixel(&s, W, H, x, y, 0);
            fx_vec3 S, c;
            fx_rt_primary(&s, W, H, x, y, &S, &c);
            fx_rt_hit h;
            ring += fx_rt_first_hit(&s, S, c, 0, &h, 0) && h.obj > 0;
            int d = 0;
            for (int k = 0; k < 24; k += 8) {
                int e = abs((int)((p >> k) & 255) - (int)((q >> k) & 255));
                d = e > d ? e : d;
            }
            differ += d > 2;
            worst = d > worst ? d : worst;
        }
    printf("    tori %dx%d: %d of %d pixels differ by more than 2 levels from double (worst %d); %d pixels on a ring\n",
           W, H, differ, W * H, worst, ring);
    FX_CHECK(ring > W * H / 10);
    FX_CHECK_MSG(differ * 100 <= W * H, "%d pixels differ", differ); /* at most 1% */
}

FX_TEST(rt_tiles_make_the_same_image)
{
    fx_rt_object mem[8];
    fx_rt_scene s;
    FX_CHECK_EQ(rtref_scene(&s, mem, 8, 3), 0);
    const int W = 64, H = 40;
    static uint32_t a[64 * 40], b[64 * 40];
    fx_surface sa, sb;
    fx_surface_init(&sa, a, W, H, W * 4, FX_FMT_XRGB8888);
    fx_surface_init(&sb, b, W, H, W * 4, FX_FMT_XRGB8888);
    fx_rt_render(&s, &sa, 0, 0, W, H);
    for (int ty = -5; ty < H; ty += 13)
        for (int tx = -7; tx < W; tx += 17)
            fx_rt_render(&s, &sb, tx, ty, 17, 13);
    FX_CHECK(memcmp(a, b, sizeof a) == 0);
    /* and each pixel is the one-pixel trace */
    FX_CHECK_EQ_HEX(a[17 * W + 33] | 0xFF000000u, fx_rt_trace_pixel(&s, W, H, 33, 17, 0, 0));
}

FX_TEST(rt_trace_prints_the_ray_tree)
{
    fx_rt_object mem[8];
    fx_rt_scene s;
    FX_CHECK_EQ(rtref_scene(&s, mem, 8, 3), 0);
    lines *L = calloc(1, sizeof *L);
    /* a pixel on the glass sphere: primary, reflected and refracted rays */
    fx_rt_trace_pixel(&s, 240, 160, 80, 80, collect, L);
    FX_CHECK(strstr(L->text, "primary ray from (0.0000, 1.6000, 6.0000)") != 0);
    FX_CHECK_MSG(L->hits >= 3, "%s", L->text);
    FX_CHECK(strstr(L->text, "I = amb + diff + spec + refl + tran") != 0);
    FX_CHECK(strstr(L->text, "(sphere, entering) t ") != 0);
    FX_CHECK(strstr(L->text, "(sphere, leaving) t ") != 0);
    free(L);
}

FX_TEST(rt_documented_errors)
{
    fx_rt_object mem[20];
    fx_rt_scene s;
    fx_rt_scene_init(&s, mem, 20);
    fx_mat4 m;
    fx_mat4_scale(&m, 0, FX16_ONE, FX16_ONE);
    FX_CHECK_EQ(fx_rt_add_shape(&s, FX_RT_SPHERE, 0, &m, 0), -FX_EDOM); /* singular */
    fx_mat4_scale(&m, FX16_ONE / 32, FX16_ONE, FX16_ONE);
    FX_CHECK_EQ(fx_rt_add_shape(&s, FX_RT_SPHERE, 0, &m, 0), -FX_EDOM); /* below 1/16 */
    m = rtref_place(FX_RT_WORLD - 0.5, 0, 0, 1, 1, 1);
    FX_CHECK_EQ(fx_rt_add_shape(&s, FX_RT_CUBE, 0, &m, 0), -FX_ERANGE);
    fx_mat4_identity(&m);
    FX_CHECK_EQ(fx_rt_add_shape(&s, FX_RT_CYLINDER, 3 * FX16_ONE, &m, 0), -FX_EINVAL);
    FX_CHECK_EQ(fx_rt_add_shape(&s, FX_RT_UNION, 0, &m, 0), -FX_EINVAL);
    int a = fx_rt_add_shape(&s, FX_RT_SPHERE, 0, &m, 0);
    FX_CHECK_EQ(fx_rt_add_csg(&s, FX_RT_UNION, a, a), -FX_EINVAL);
    for (int i = 0; i < 16; i++) {
        int b = fx_rt_add_shape(&s, FX_RT_CUBE, 0, &m, 0);
        int r = fx_rt_add_csg(&s, FX_RT_UNION, a, b);
        if (r == -FX_E2BIG || r == -FX_ENOSPC) {
            FX_CHECK(i >= 8);
            break;
        }
        FX_CHECK(r >= 0);
        a = r;
    }
    FX_CHECK_EQ(fx_rt_add_csg(&s, FX_RT_UNION, a, 0), -FX_EINVAL); /* 0 is inside the tree */
    fx_rt_scene_init(&s, mem, 1);
    FX_CHECK_EQ(fx_rt_add_shape(&s, FX_RT_SPHERE, 0, &m, 0), 0);
    FX_CHECK_EQ(fx_rt_add_shape(&s, FX_RT_SPHERE, 0, &m, 0), -FX_ENOSPC);
    FX_CHECK_EQ(fx_rt_set_camera(&s, fx_vec3_make(0, 0, 0), fx_vec3_make(0, 0, 0), fx_vec3_make(0, FX16_ONE, 0),
                                 45 * FX16_ONE),
                -FX_EDOM);
    FX_CHECK_EQ(fx_rt_set_camera(&s, fx_vec3_make(0, 0, 200 * FX16_ONE), fx_vec3_make(0, 0, 0),
                                 fx_vec3_make(0, FX16_ONE, 0), 45 * FX16_ONE),
                -FX_EDOM);
}

/* ---- meshes through the BVH ---- */

typedef struct tmesh {
    fx_mesh m;
    fx_rt_mesh rm;
    fx_vec3 *mem;
    fx_rt_bvh_node *nodes;
    uint32_t *order;
} tmesh;

static int make_mesh(tmesh *t, fx_mesh_kind kind, fx16 a, fx16 b, int n, int k)
{
    fx_mesh_params p = {kind, a, b, 0, n, k};
    int32_t nv, nt;
    if (fx_mesh_size(&p, &nv, &nt) < 0)
        return -1;
    t->mem = calloc((size_t)nv * 2 + (size_t)nt, sizeof(fx_vec3));
    t->m = (fx_mesh){t->mem, t->mem + nv, (uint32_t *)(t->mem + 2 * nv), 0, 0, nv, nt, NULL, NULL};
    if (fx_mesh_make(&t->m, &p) < 0)
        return -1;
    t->nodes = calloc((size_t)nt * 2, sizeof *t->nodes);
    t->order = calloc((size_t)nt, sizeof *t->order);
    return fx_rt_mesh_build(&t->rm, &t->m, t->nodes, nt * 2, t->order);
}

static void free_mesh(tmesh *t)
{
    free(t->mem);
    free(t->nodes);
    free(t->order);
}

/* The nearest crossing over every triangle, in double (t > 0), and how
 * close it is to a triangle's edge (min barycentric). */
static double brute_nearest(const fx_mesh *m, const double S[3], const double c[3], double *edge)
{
    double best = -1;
    *edge = 1;
    for (int32_t i = 0; i < m->ntris; i++) {
        double v[3][3];
        for (int k = 0; k < 3; k++) {
            fx_vec3 p = m->pos[m->tri[3 * i + k]];
            v[k][0] = p.x * Q, v[k][1] = p.y * Q, v[k][2] = p.z * Q;
        }
        double e1[3], e2[3], tv[3], p[3], q[3];
        for (int k = 0; k < 3; k++)
            e1[k] = v[1][k] - v[0][k], e2[k] = v[2][k] - v[0][k], tv[k] = S[k] - v[0][k];
        p[0] = c[1] * e2[2] - c[2] * e2[1], p[1] = c[2] * e2[0] - c[0] * e2[2], p[2] = c[0] * e2[1] - c[1] * e2[0];
        double det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
        if (det == 0)
            continue;
        double u = (tv[0] * p[0] + tv[1] * p[1] + tv[2] * p[2]) / det;
        q[0] = tv[1] * e1[2] - tv[2] * e1[1], q[1] = tv[2] * e1[0] - tv[0] * e1[2], q[2] = tv[0] * e1[1] - tv[1] * e1[0];
        double w = (c[0] * q[0] + c[1] * q[1] + c[2] * q[2]) / det;
        double t = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
        if (u < 0 || w < 0 || u + w > 1 || t <= 0)
            continue;
        if (best < 0 || t < best) {
            best = t;
            *edge = fmin(fmin(u, w), 1 - u - w);
        }
    }
    return best;
}

/* A scene of the one mesh, untransformed. */
static void mesh_scene(fx_rt_scene *s, fx_rt_object *mem, const tmesh *t)
{
    fx_rt_scene_init(s, mem, 1);
    fx_mat4 id;
    fx_mat4_identity(&id);
    FX_CHECK_EQ(fx_rt_add_mesh(s, &t->rm, &id, 0), 0);
}

FX_TEST(rt_mesh_bvh_finds_the_nearest_triangle)
{
    tmesh t;
    FX_CHECK_EQ(make_mesh(&t, FX_MESH_TEAPOT, FX16_ONE, 0, 4, 0), 0);
    FX_CHECK(t.rm.nnodes <= 2 * t.m.ntris);
    fx_rt_object mem[1];
    fx_rt_scene s;
    mesh_scene(&s, mem, &t);
    uint32_t seed = 21;
    int hits = 0, compared = 0;
    double worst = 0;
    for (int i = 0; i < 3000; i++) {
        fx_vec3 S, c;
        random_ray(&seed, 8, &S, &c);
        fx_vec3 target = urand3(&seed, -2, 2, 0, 3, -2, 2);
        c = fx_vec3_make(target.x - S.x, target.y - S.y, target.z - S.z);
        if (fx_vec3_normalize(&c) < 0)
            continue;
        double Sd[3], cd[3], edge;
        to_d(S, Sd);
        to_d(c, cd);
        double want = brute_nearest(&t.m, Sd, cd, &edge);
        fx_rt_hit h;
        fx_vec3 n;
        int got = fx_rt_first_hit(&s, S, c, 0, &h, &n);
        if (edge < 1e-3) /* through an edge or a vertex: either neighbour will do */
            continue;
        compared++;
        FX_CHECK_MSG(got == (want > 0), "ray %d: fixed %s, double %s (t %f)", i, got ? "hits" : "misses",
                     want > 0 ? "hits" : "misses", want);
        if (got && want > 0) {
            hits++;
            double e = fabs(h.t * Q - want) / fmax(1, want);
            worst = e > worst ? e : worst;
        }
    }
    printf("    teapot (%d triangles, %d BVH nodes): %d hits of %d rays, worst relative t error %.3g\n", t.m.ntris,
           t.rm.nnodes, hits, compared, worst);
    FX_CHECK(hits > 800);
    FX_CHECK_MSG(worst < 1.0 / 16384, "worst %g", worst);
    free_mesh(&t);
}

FX_TEST(rt_mesh_is_watertight)
{
    /* rays from inside a closed mesh (a tessellated sphere) always leave
     * through a triangle: the exact inside test leaves no crack along a
     * shared edge or at a shared vertex */
    tmesh t;
    FX_CHECK_EQ(make_mesh(&t, FX_MESH_SPHERE, 2 * FX16_ONE, 0, 12, 6), 0);
    fx_rt_object mem[1];
    fx_rt_scene s;
    mesh_scene(&s, mem, &t);
    uint32_t seed = 8;
    int missed = 0;
    for (int i = 0; i < 20000; i++) {
        fx_vec3 S = urand3(&seed, -0.5, 0.5, -0.5, 0.5, -0.5, 0.5);
        fx_vec3 c;
        if (i < 2000) { /* straight at the vertices, where many triangles meet */
            fx_vec3 v = t.m.pos[fx_test_rand(&seed) % (uint32_t)t.m.nverts];
            S = fx_vec3_make(0, 0, 0);
            c = v;
        } else {
            c = urand3(&seed, -1, 1, -1, 1, -1, 1);
        }
        if (fx_vec3_normalize(&c) < 0)
            continue;
        fx_rt_hit h;
        missed += !fx_rt_first_hit(&s, S, c, 0, &h, 0);
    }
    FX_CHECK_EQ(missed, 0);
    free_mesh(&t);
}

FX_TEST(rt_mesh_build_errors)
{
    fx_vec3 pos[3] = {{0, 0, 0}, {FX16_ONE, 0, 0}, {0, 40 * FX16_ONE, 0}};
    fx_vec3 nrm[3] = {{0, 0, FX16_ONE}, {0, 0, FX16_ONE}, {0, 0, FX16_ONE}};
    uint32_t tri[3] = {0, 1, 2}, order[1];
    fx_rt_bvh_node nodes[2];
    fx_mesh m = {pos, nrm, tri, 3, 1, 3, 1, NULL, NULL};
    fx_rt_mesh rm;
    FX_CHECK_EQ(fx_rt_mesh_build(&rm, &m, nodes, 2, order), -FX_ERANGE); /* y = 40 > 32 */
    pos[2].y = FX16_ONE;
    FX_CHECK_EQ(fx_rt_mesh_build(&rm, &m, nodes, 1, order), -FX_ENOSPC);
    tri[2] = 3;
    FX_CHECK_EQ(fx_rt_mesh_build(&rm, &m, nodes, 2, order), -FX_EINVAL);
    tri[2] = 2;
    FX_CHECK_EQ(fx_rt_mesh_build(&rm, &m, nodes, 2, order), 0);
    /* one triangle: the ray through its middle, from both sides */
    fx_rt_object mem[1];
    fx_rt_scene s;
    fx_rt_scene_init(&s, mem, 1);
    fx_mat4 id;
    fx_mat4_identity(&id);
    FX_CHECK_EQ(fx_rt_add_mesh(&s, &rm, &id, 0), 0);
    fx_rt_hit h;
    fx_vec3 n;
    FX_CHECK(fx_rt_first_hit(&s, fx_vec3_make(FX16_ONE / 4, FX16_ONE / 4, 3 * FX16_ONE), fx_vec3_make(0, 0, -FX16_ONE),
                             0, &h, &n));
    FX_CHECK_EQ(h.t, 3 * FX16_ONE);
    FX_CHECK_EQ(n.z, FX16_ONE);
    FX_CHECK(fx_rt_first_hit(&s, fx_vec3_make(FX16_ONE / 4, FX16_ONE / 4, -2 * FX16_ONE), fx_vec3_make(0, 0, FX16_ONE),
                             0, &h, &n));
    FX_CHECK_EQ(h.t, 2 * FX16_ONE);
}

/* ---- the script commands ---- */

typedef struct script_host {
    scene_buf buf;
    lines *out;
} script_host;

static int host_surface(void *u, int32_t w, int32_t h, fx_format f, fx_surface *o)
{
    return scene_buf_make(&((script_host *)u)->buf, w, h, f, o);
}

static void host_trace(void *u, const char *line) { collect(((script_host *)u)->out, line); }

FX_TEST(rt_script_renders_and_traces_a_pixel)
{
    static uint32_t px[64 * 48];
    script_host h = {{px, 64 * 48}, calloc(1, sizeof(lines))};
    fx_scene_host hs = {&h, host_surface, 0, 0, host_trace, NULL};
    size_t arena_size = 1 << 20;
    void *arena = malloc(arena_size);
    fx_scene sc;
    fx_scene_init(&sc, &hs, arena, arena_size);
    static const char script[] = "size 64 48\n"
                                 "rtcamera 0 0 5 0 0 0 0 1 0 40\n"
                                 "rtlight 3 4 5 #FFFFFF\n"
                                 "rtmaterial #000000 #FF0000 #000000 0\n"
                                 "rtshape sphere\n"
                                 "rtscale 2 0.5 2\n"
                                 "rtshape cube\n"
                                 "rtcsg difference\n"
                                 "raytrace\n"
                                 "rttrace 32 14\n";
    FX_CHECK_EQ(fx_scene_run(&sc, script, sizeof script - 1), 0);
    /* the centre row is cut away (the slab), above it the red sphere */
    FX_CHECK_EQ_HEX(px[24 * 64 + 32] & 0xFFFFFF, 0);
    FX_CHECK((px[14 * 64 + 32] >> 16 & 255) > 100 && (px[14 * 64 + 32] & 0xFFFF) == 0);
    char want[64];
    snprintf(want, sizeof want, "rttrace pixel (32, 14) = #%06X", px[14 * 64 + 32] & 0xFFFFFF);
    FX_CHECK_MSG(strstr(h.out->text, want) != 0, "%s not in:\n%s", want, h.out->text);
    FX_CHECK(strstr(h.out->text, "hit object 2 (sphere, entering)") != 0 ||
             strstr(h.out->text, "hit object 0 (sphere, entering)") != 0);
    FX_CHECK(strstr(h.out->text, "light 0: visible") != 0);
    /* a range error names the argument and its range */
    fx_scene_init(&sc, &hs, arena, arena_size);
    static const char bad[] = "rtshape taper 3\n";
    FX_CHECK(fx_scene_run(&sc, bad, sizeof bad - 1) < 0);
    FX_CHECK_MSG(strstr(sc.err, "0..2") != 0, "%s", sc.err);
    free(arena);
    free(h.out);
}

/* fx_rt_noise3 in double with its exact gradient: the lattice values are
 * the core's (rt_hash3, top 16 bits), the smoothstep weights and the
 * trilinear blend exact. */
static void ref_noise_grad(const fx16 q[3], double g[3])
{
    int32_t ix[3];
    double sm[3], ds[3];
    for (int k = 0; k < 3; k++) {
        ix[k] = q[k] >> 16;
        double f = (q[k] & 0xFFFF) * Q;
        sm[k] = f * f * (3 - 2 * f);
        ds[k] = 6 * f * (1 - f);
    }
    double v[8];
    for (int k = 0; k < 8; k++)
        v[k] = (rt_hash3(ix[0] + (k & 1), ix[1] + ((k >> 1) & 1), ix[2] + ((k >> 2) & 1)) >> 16) * Q;
    double sx = sm[0], sy = sm[1], sz = sm[2];
    double x0 = v[0] + (v[1] - v[0]) * sx, x1 = v[2] + (v[3] - v[2]) * sx;
    double x2 = v[4] + (v[5] - v[4]) * sx, x3 = v[6] + (v[7] - v[6]) * sx;
    double y0 = x0 + (x1 - x0) * sy, y1 = x2 + (x3 - x2) * sy;
    g[2] = (y1 - y0) * ds[2];
    g[1] = ((1 - sz) * (x1 - x0) + sz * (x3 - x2)) * ds[1];
    g[0] = ((1 - sz) * ((1 - sy) * (v[1] - v[0]) + sy * (v[3] - v[2])) +
            sz * ((1 - sy) * (v[5] - v[4]) + sy * (v[7] - v[6]))) *
           ds[0];
}

#define BUMP_WORST_DEG 0.75 /* measured 0.40 (docs/RAYTRACE.md) */

FX_TEST(rt_bump_normals_follow_the_height_gradient)
{
    /* the surface displaced along n by H(P) = height * noise(P / scale):
     * its normal is n minus the tangential part of grad H. The reference
     * takes the exact gradient of the same noise in double, then tilts and
     * normalises in double */
    uint32_t seed = 2024;
    double worst = 0, mean_tilt = 0, berr[4000];
    int n_cmp = 0;
    for (int i = 0; i < 4000; i++) {
        fx_vec3 n = urand3(&seed, -1, 1, -1, 1, -1, 1);
        if (fx_vec3_normalize(&n) < 0)
            continue;
        fx_vec3 P = urand3(&seed, -100, 100, -100, 100, -100, 100);
        double height = urand(&seed, 0.01, 1), scale = urand(&seed, 0.0625, 8);
        fx16 hq = FX(height), sq = FX(scale);
        fx_vec3 b = fx_rt_bump_normal(hq, sq, P, n);
        double nd[3], bd[3];
        to_d(n, nd);
        to_d(b, bd);
        /* at the same quantised texture point q the core uses */
        fx16 qv[3];
        for (int k = 0; k < 3; k++)
            qv[k] = (fx16)((int64_t)(k == 0 ? P.x : k == 1 ? P.y : P.z) * 65536 / sq);
        double g[3];
        ref_noise_grad(qv, g);
        for (int k = 0; k < 3; k++)
            g[k] *= (hq * Q) / (sq * Q);
        double gn = g[0] * nd[0] + g[1] * nd[1] + g[2] * nd[2], r[3], len = 0;
        for (int k = 0; k < 3; k++) {
            r[k] = nd[k] - (g[k] - gn * nd[k]);
            len += r[k] * r[k];
        }
        len = sqrt(len);
        double blen = sqrt(bd[0] * bd[0] + bd[1] * bd[1] + bd[2] * bd[2]);
        FX_CHECK_MSG(fabs(blen - 1) < 1.0 / 1024, "bumped normal length %f", blen);
        double cosang = (r[0] * bd[0] + r[1] * bd[1] + r[2] * bd[2]) / len / blen;
        double err = acos(cosang > 1 ? 1 : cosang) * 180 / M_PI;
        if (err > worst)
            worst = err;
        berr[n_cmp] = err;
        mean_tilt += acos(fmin(1, (nd[0] * bd[0] + nd[1] * bd[1] + nd[2] * bd[2]) / blen)) * 180 / M_PI;
        n_cmp++;
    }
    mean_tilt /= n_cmp;
    qsort(berr, (size_t)n_cmp, sizeof berr[0], cmp_d);
    FX_CHECK(n_cmp > 3000);
    FX_CHECK_MSG(worst < BUMP_WORST_DEG, "worst angle to the reference %.3f degrees", worst);
    FX_CHECK_MSG(mean_tilt > 5, "mean tilt %.2f degrees: bumps do nothing", mean_tilt);
    printf("  bump normals against the exact gradient: worst %.3f, 99.9%% %.3f, median %.4f degrees; mean tilt %.2f "
           "degrees\n",
           worst, berr[n_cmp * 999 / 1000], berr[n_cmp / 2], mean_tilt);
    /* no bumps, no change */
    fx_vec3 n = fx_vec3_make(0, FX16_ONE, 0);
    fx_vec3 b = fx_rt_bump_normal(0, FX16_ONE, fx_vec3_make(FX16_ONE / 3, 0, 0), n);
    FX_CHECK(b.x == n.x && b.y == n.y && b.z == n.z);
}

FX_TEST(rt_bumps_on_the_rasterizer_tilt_phong_normals)
{
    /* a quad facing the camera at z = -2 (60 pixels a unit), Phong, one
     * directional light along the view axis, diffuse white only: a pixel
     * is 255 (N'.L) = 255 / sqrt(1 + gx^2 + gy^2), g the exact gradient of
     * the height field at its object point */
    enum { RW = 160, RH = 120 };
    static uint32_t px[RW * RH];
    fx_surface surf;
    fx_surface_init(&surf, px, RW, RH, RW * 4, FX_FMT_XRGB8888);
    fx_mat4 ms[4], ps[2];
    fx3d r;
    FX_CHECK_EQ(fx3d_init(&r, &surf, ms, 4, ps, 2), 0);
    FX_CHECK_EQ(fx3d_perspective(&r, fx_angle_from_deg(53), fx16_from_ratio(RW, RH), FX16_ONE / 2, 50 * FX16_ONE), 0);
    r.cull = FX3D_CULL_NONE;
    r.shading = FX3D_PHONG;
    r.ambient = fx3d_rgb_from_color(0);
    r.mat.ambient = r.mat.specular = fx3d_rgb_from_color(0);
    r.mat.diffuse = fx3d_rgb_from_color(0xFFFFFF);
    const double height = 0.3, scale = 0.25;
    fx3d_bump(&r, FX(height), FX(scale));
    fx16 hx = FX16_ONE * 2 / 3, hy = FX16_ONE / 2;
    fx_vec3 pos[4] = {fx_vec3_make(-hx, -hy, -2 * FX16_ONE), fx_vec3_make(hx, -hy, -2 * FX16_ONE),
                      fx_vec3_make(hx, hy, -2 * FX16_ONE), fx_vec3_make(-hx, hy, -2 * FX16_ONE)};
    uint32_t tri[6] = {0, 1, 2, 0, 2, 3};
    fx_mesh m = {pos, NULL, tri, 4, 2, 4, 2, NULL, NULL};
    FX_CHECK_EQ(fx3d_draw(&r, &m), 0);
    int worst = 0, lo = 255, n = 0;
    for (int y = 35; y < 85; y++)
        for (int x = 45; x < 115; x++) {
            double P[2] = {(x + 0.5 - 80) / 60, -(y + 0.5 - 60) / 60};
            fx16 q[3] = {FX(P[0] / scale), FX(P[1] / scale), FX(-2 / scale)};
            double g[3];
            ref_noise_grad(q, g);
            double gx = g[0] * height / scale, gy = g[1] * height / scale;
            int want = (int)lround(255 / sqrt(1 + gx * gx + gy * gy));
            int got = (int)(px[y * RW + x] >> 16 & 255);
            int e = abs(got - want);
            if (e > worst)
                worst = e;
            if (got < lo)
                lo = got;
            n++;
        }
    FX_CHECK(n == 3500);
    /* interpolation puts the object point within a fraction of a pixel
     * (1/60 unit, 1/15 of a noise cell): where the noise bends most that
     * moves the gradient by a few per cent (measured: 3 levels) */
    FX_CHECK_MSG(worst <= 6, "worst %d levels from the exact bumped normal", worst);
    FX_CHECK_MSG(lo < 200, "darkest pixel %d: the bumps tilt nothing", lo);
    printf("  rasterizer bumps: worst %d levels of 255 from the exact normal, darkest %d\n", worst, lo);
    /* bumps off: a flat lit quad again, and Gouraud ignores them */
    fx3d_bump(&r, 0, FX(scale));
    FX_CHECK_EQ(fx3d_draw(&r, &m), 0);
    FX_CHECK_EQ(px[60 * RW + 80] & 0xFFFFFF, 0xFFFFFFu);
    fx3d_bump(&r, FX(height), FX(scale));
    r.shading = FX3D_GOURAUD;
    FX_CHECK_EQ(fx3d_draw(&r, &m), 0);
    FX_CHECK_EQ(px[60 * RW + 80] & 0xFFFFFF, 0xFFFFFFu);
}
