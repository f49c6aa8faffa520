/* SPDX-License-Identifier: MIT */
/* Animation (fixel/anim.h, scene_anim.c): in-betweens meet their keys
 * exactly and the spline is Catmull-Rom; the eases are monotone with exact
 * ends; morphing by adding vertices gives equal counts with the course's
 * section numbers and the added vertices on the old edges; the bouncing
 * ball meets the closed form and its energy never grows; the accumulation
 * buffer gives a static scene back unchanged; a blurred script equals its
 * unblurred self when nothing moves, and the host's clock overrides 'time'. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/anim.h"
#include "fixel/error.h"
#include "fixel/scene.h"
#include "fx_test.h"
#include "scenebuf.h"

static fx16 rnd16(uint32_t *s, int32_t range) /* uniform in [-range, range) units */
{
    return (fx16)((int64_t)(fx_test_rand(s) % (uint32_t)(2 * range * 65536u)) - (int64_t)range * 65536);
}

FX_TEST(anim_in_betweens_hit_the_keys_exactly)
{
    uint32_t s = 7;
    for (int it = 0; it < 300; it++) {
        fx_anim_key k[12];
        int n = 1 + (int)(fx_test_rand(&s) % 12), nch = 1 + (int)(fx_test_rand(&s) % FX_ANIM_MAX_CH);
        fx16 t = (fx16)(fx_test_rand(&s) % 65536);
        for (int i = 0; i < n; i++) {
            k[i].t = t;
            t += 1 + (fx16)(fx_test_rand(&s) % (1u << 20));
            for (int c = 0; c < FX_ANIM_MAX_CH; c++)
                k[i].v[c] = rnd16(&s, 30000);
        }
        for (int mode = 0; mode < 3; mode++)
            for (int e = 0; e < FX_EASE_COUNT; e++) {
                fx_anim_track tr = {k, n, nch, (uint8_t)mode, (uint8_t)e};
                for (int i = 0; i < n; i++) {
                    fx16 v[FX_ANIM_MAX_CH];
                    /* an ease moves the inner keys in time; the ends stay */
                    if (e && i && i < n - 1)
                        continue;
                    FX_CHECK_EQ(fx_anim_eval(&tr, k[i].t, v), i);
                    for (int c = 0; c < nch; c++)
                        FX_CHECK_EQ(v[c], k[i].v[c]);
                }
                fx16 v[FX_ANIM_MAX_CH];
                fx_anim_eval(&tr, k[0].t - 5, v); /* before the first key: it holds */
                FX_CHECK_EQ(v[0], k[0].v[0]);
                fx_anim_eval(&tr, k[n - 1].t + 5, v);
                FX_CHECK_EQ(v[0], k[n - 1].v[0]);
            }
    }
    fx_anim_key bad[2] = {{5, {0}}, {5, {1}}};
    fx_anim_track tr = {bad, 2, 1, FX_ANIM_LINEAR, 0};
    fx16 v[FX_ANIM_MAX_CH];
    FX_CHECK_EQ(fx_anim_eval(&tr, 5, v), -FX_EINVAL);
}

/* Uniform keys: the spline is Catmull-Rom, p(s) = 0.5 (2p1 + (p2 - p0) s +
 * (2p0 - 5p1 + 4p2 - p3) s^2 + (3p1 - p0 - 3p2 + p3) s^3), within 4 ulp;
 * linear in-betweens within 1 ulp; two keys make a straight spline. */
FX_TEST(anim_spline_is_catmull_rom_and_linear_is_straight)
{
    uint32_t s = 99;
    double worst = 0;
    for (int it = 0; it < 200; it++) {
        fx_anim_key k[6];
        fx16 dt = 65536 + (fx16)(fx_test_rand(&s) % 65536);
        for (int i = 0; i < 6; i++) {
            k[i].t = i * dt;
            k[i].v[0] = rnd16(&s, 1000);
        }
        fx_anim_track sp = {k, 6, 1, FX_ANIM_SPLINE, 0}, li = {k, 6, 1, FX_ANIM_LINEAR, 0};
        for (int j = 0; j < 50; j++) {
            fx16 t = dt + (fx16)(fx_test_rand(&s) % (uint32_t)(3 * dt)); /* inner segments 1..3 */
            int i = t / dt;
            double u = (double)(t - i * dt) / dt;
            double p0 = k[i - 1].v[0], p1 = k[i].v[0], p2 = k[i + 1].v[0], p3 = k[i + 2].v[0];
            double want = 0.5 * (2 * p1 + (p2 - p0) * u + (2 * p0 - 5 * p1 + 4 * p2 - p3) * u * u +
                                 (3 * p1 - p0 - 3 * p2 + p3) * u * u * u);
            fx16 v;
            FX_CHECK_EQ(fx_anim_eval(&sp, t, &v), i);
            double err = fabs(v - want);
            worst = err > worst ? err : worst;
            FX_CHECK_MSG(err <= 4, "spline %d vs %.2f at t=%d", v, want, t);
            fx_anim_eval(&li, t, &v);
            FX_CHECK_MSG(fabs(v - (p1 + (p2 - p1) * u)) <= 1, "linear %d", v);
        }
        fx_anim_track two = {k, 2, 1, FX_ANIM_SPLINE, 0};
        for (fx16 t = 0; t <= dt; t += dt / 17) {
            fx16 a, b;
            fx_anim_eval(&two, t, &a);
            li.n = 2;
            fx_anim_eval(&li, t, &b);
            FX_CHECK_MSG(abs(a - b) <= 2, "two-key spline %d, line %d", a, b);
        }
    }
    printf("    worst spline error %.2f ulp\n", worst);
}

FX_TEST(anim_ease_ends_exact_and_monotone)
{
    for (int e = 0; e < FX_EASE_COUNT; e++) {
        FX_CHECK_EQ(fx_anim_ease_apply((fx_anim_ease)e, 0), 0);
        FX_CHECK_EQ(fx_anim_ease_apply((fx_anim_ease)e, FX16_ONE), FX16_ONE);
        FX_CHECK_EQ(fx_anim_ease_apply((fx_anim_ease)e, -5), 0);
        FX_CHECK_EQ(fx_anim_ease_apply((fx_anim_ease)e, 3 * FX16_ONE), FX16_ONE);
        fx16 prev = 0;
        double worst = 0;
        for (fx16 x = 0; x <= FX16_ONE; x++) {
            fx16 y = fx_anim_ease_apply((fx_anim_ease)e, x);
            FX_CHECK_MSG(y >= prev, "ease %d falls at %d", e, x);
            prev = y;
            double u = x / 65536.0, w = u;
            if (e == FX_EASE_IN)
                w = 1 - cos(u * M_PI / 2);
            else if (e == FX_EASE_OUT)
                w = sin(u * M_PI / 2);
            else if (e == FX_EASE_INOUT)
                w = (1 - cos(u * M_PI)) / 2;
            else if (e == FX_EASE_SMOOTH)
                w = u * u * (3 - 2 * u);
            double err = fabs(y / 65536.0 - w);
            worst = err > worst ? err : worst;
        }
        FX_CHECK_MSG(worst < 1.0 / 32768, "ease %d off by %g", e, worst);
    }
    /* eased in: slower than linear at the start, so a quarter of the time covers less */
    FX_CHECK(fx_anim_ease_apply(FX_EASE_IN, FX16_ONE / 4) < FX16_ONE / 8);
    FX_CHECK(fx_anim_ease_apply(FX_EASE_OUT, FX16_ONE / 4) > FX16_ONE / 4);
}

FX_TEST(anim_color_lerp_ends_and_middle)
{
    FX_CHECK_EQ_HEX(fx_anim_color_lerp(0xFF102030, 0x80F0E0D0, 0), 0xFF102030);
    FX_CHECK_EQ_HEX(fx_anim_color_lerp(0xFF102030, 0x80F0E0D0, FX16_ONE), 0x80F0E0D0);
    FX_CHECK_EQ_HEX(fx_anim_color_lerp(0xFF000000, 0xFFFF00FF, FX16_ONE / 2), 0xFF800080);
}

/* The course's rule on the smaller outline: Ne = Lmax mod Lmin edges in
 * Ns + 1 sections, the others in Ns = Lmax / Lmin; every original vertex
 * kept in order; every added vertex on its edge. */
FX_TEST(anim_morph_adds_vertices_by_the_course_rule)
{
    uint32_t s = 3;
    static fx16 a[2 * 300], b[2 * 300], ao[2 * 300], bo[2 * 300];
    for (int it = 0; it < 400; it++) {
        int closed = it & 1, least = closed ? 3 : 2;
        int na = least + (int)(fx_test_rand(&s) % 60), nb = least + (int)(fx_test_rand(&s) % 60);
        for (int i = 0; i < 2 * na; i++)
            a[i] = rnd16(&s, 500);
        for (int i = 0; i < 2 * nb; i++)
            b[i] = rnd16(&s, 500);
        int n = fx_anim_morph_match(a, na, b, nb, 2, closed, ao, bo, 300);
        int big = na > nb ? na : nb;
        FX_CHECK_EQ(n, big);
        const fx16 *sm = na < nb ? a : b, *so = na < nb ? ao : bo, *lg = na < nb ? b : a, *lo = na < nb ? bo : ao;
        int ns_pts = na < nb ? na : nb;
        FX_CHECK(!memcmp(lg, lo, sizeof(fx16) * 2 * (size_t)big));
        if (na == nb)
            continue;
        int lmin = closed ? ns_pts : ns_pts - 1, lmax = closed ? big : big - 1;
        int Ns = lmax / lmin, Ne = lmax % lmin, o = 0, longer = 0;
        for (int i = 0; i < lmin; i++) {
            /* original vertex i sits at o; the next at o + sections */
            FX_CHECK(so[2 * o] == sm[2 * i] && so[2 * o + 1] == sm[2 * i + 1]);
            int j = (i + 1) % ns_pts, k = 1;
            while (o + k < n && !(so[2 * (o + k)] == sm[2 * j] && so[2 * (o + k) + 1] == sm[2 * j + 1] &&
                                  (k == Ns || k == Ns + 1)))
                k++;
            if (!closed || i < lmin - 1)
                FX_CHECK_MSG(k == Ns || k == Ns + 1, "edge %d has %d sections (Ns %d)", i, k, Ns);
            if (closed && i == lmin - 1)
                k = n - o;
            longer += k == Ns + 1;
            for (int q = 1; q < k; q++) { /* on the edge, evenly: within rounding */
                double ex = sm[2 * i] + (double)(sm[2 * j] - sm[2 * i]) * q / k;
                double ey = sm[2 * i + 1] + (double)(sm[2 * j + 1] - sm[2 * i + 1]) * q / k;
                FX_CHECK(fabs(so[2 * (o + q)] - ex) <= 0.5 && fabs(so[2 * (o + q) + 1] - ey) <= 0.5);
            }
            o += k;
        }
        FX_CHECK_EQ(longer, Ne);
        FX_CHECK_EQ(o + !closed, n);
    }
    /* the in-between at 0 and 1 is each outline, half-way the mean */
    fx16 m[2 * 300];
    fx_anim_morph_at(ao, bo, 20, 0, m);
    FX_CHECK(!memcmp(m, ao, 20 * sizeof *m));
    fx_anim_morph_at(ao, bo, 20, FX16_ONE, m);
    FX_CHECK(!memcmp(m, bo, 20 * sizeof *m));
    FX_CHECK_EQ(fx_anim_morph_match(a, 2, b, 5, 2, 1, ao, bo, 300), -FX_EINVAL);
    FX_CHECK_EQ(fx_anim_morph_match(a, 4, b, 5, 2, 1, ao, bo, 4), -FX_ENOSPC);
}

/* Dropped from rest at height h: the first impact at T1 = sqrt(2h/g), then
 * flights of 2 e^k sqrt(2gh) / g; between them the parabola. */
FX_TEST(anim_ball_meets_the_closed_form)
{
    const double h = 100, g = 980, e = 0.75;
    fx_anim_ball b = {0, 0, 0, 0, (fx16)(g * 65536), (fx16)(e * 65536), 0, 0, (fx16)(h * 65536)};
    double T = sqrt(2 * h / g), v = sqrt(2 * g * h), worst_t = 0, worst_y = 0;
    double impacts[20];
    for (int k = 1; k <= 20; k++) {
        fx16 t;
        FX_CHECK_EQ(fx_anim_ball_impact(&b, k, &t), 0);
        impacts[k - 1] = T;
        double err = fabs(t / 65536.0 - T);
        worst_t = err > worst_t ? err : worst_t;
        FX_CHECK_MSG(err < 1e-3, "impact %d at %.6f, closed form %.6f", k, t / 65536.0, T);
        v *= e;
        T += 2 * v / g;
    }
    /* positions between the impacts */
    for (int i = 0; i < 400; i++) {
        double t = i * 0.01, y;
        if (t < impacts[0]) {
            y = g * t * t / 2;
        } else {
            int k = 0;
            while (k < 19 && impacts[k + 1] <= t)
                k++;
            double u = sqrt(2 * g * h) * pow(e, k + 1), d = t - impacts[k];
            y = h - u * d + g * d * d / 2;
        }
        if (t > impacts[19])
            break;
        fx_anim_ball_state st;
        FX_CHECK_EQ(fx_anim_ball_at(&b, (fx16)lround(t * 65536), &st), 0);
        double err = fabs(st.y / 65536.0 - y);
        worst_y = err > worst_y ? err : worst_y;
        FX_CHECK_MSG(err < 0.05, "t=%.2f y %.4f, closed form %.4f", t, st.y / 65536.0, y);
        FX_CHECK(st.y <= b.floor);
    }
    printf("    worst impact time error %.2e s, worst height error %.2e px\n", worst_t, worst_y);
}

/* Sampled at increasing times the energy never grows by more than the
 * rounding of one sample (4 ulp of y times g, 4 ulp of v times |v|), and
 * each impact takes e of the speed; with e = 1 it is kept for ever. */
FX_TEST(anim_ball_energy_never_grows)
{
    uint32_t s = 41;
    for (int it = 0; it < 40; it++) {
        fx_anim_ball b;
        memset(&b, 0, sizeof b);
        b.g = 65536 * (10 + (int32_t)(fx_test_rand(&s) % 2000));
        b.e = (fx16)(fx_test_rand(&s) % 65537);
        if (it % 5 == 0)
            b.e = FX16_ONE;
        b.left = -200 * 65536;
        b.right = 200 * 65536;
        b.floor = 100 * 65536;
        b.x = rnd16(&s, 200);
        b.y = -(fx16)(fx_test_rand(&s) % (300u * 65536));
        b.vx = rnd16(&s, 500);
        b.vy = rnd16(&s, 500);
        fx_anim_ball_state st;
        FX_CHECK_EQ(fx_anim_ball_at(&b, 0, &st), 0);
        int64_t e0 = fx_anim_ball_energy(&b, &st), prev = e0;
        int32_t bounces = 0;
        for (fx16 t = 0; t < 30 * 65536; t += 65536 / 50) {
            FX_CHECK_EQ(fx_anim_ball_at(&b, t, &st), 0);
            int64_t en = fx_anim_ball_energy(&b, &st), tol = 4 * (int64_t)b.g + 4 * (int64_t)abs(st.vy) + 4 * 65536;
            FX_CHECK_MSG(en <= prev + tol, "it %d t=%d energy %lld after %lld (tol %lld)", it, t, (long long)en,
                         (long long)prev, (long long)tol);
            if (b.e == FX16_ONE)
                FX_CHECK_MSG(llabs(en - e0) <= tol, "e=1 energy %lld, at start %lld", (long long)en, (long long)e0);
            prev = en < prev ? en : prev;
            FX_CHECK(st.y <= b.floor && st.x >= b.left && st.x <= b.right);
            FX_CHECK(st.bounces >= bounces);
            bounces = st.bounces;
        }
    }
    /* the rest: e = 0 stops at the first impact */
    fx_anim_ball b = {0, 0, 0, 0, 100 * 65536, 0, 0, 0, 50 * 65536};
    fx_anim_ball_state st;
    fx_anim_ball_at(&b, 5 * 65536, &st);
    FX_CHECK(st.resting && st.y == b.floor && st.vy == 0 && st.bounces == 1);
    fx16 t;
    FX_CHECK_EQ(fx_anim_ball_impact(&b, 2, &t), -FX_ENOENT);
    b.y = b.floor + 1;
    FX_CHECK_EQ(fx_anim_ball_at(&b, 0, &st), -FX_ERANGE);
}

FX_TEST(anim_walls_reflect)
{
    fx_anim_ball b = {10 * 65536, 0, 30 * 65536, 0, 0, FX16_ONE, 0, 100 * 65536, 0};
    fx_anim_ball_state st;
    fx_anim_ball_at(&b, 3 * 65536, &st); /* 10 + 90 = 100: the right wall */
    FX_CHECK_EQ(st.x, 100 * 65536);
    fx_anim_ball_at(&b, 4 * 65536, &st); /* back 30 */
    FX_CHECK_EQ(st.x, 70 * 65536);
    FX_CHECK_EQ(st.vx, -30 * 65536);
    fx_anim_ball_at(&b, 9 * 65536, &st); /* 10 + 270 = 280 -> 200 - 80 ... folded: 280 - 200 = 80 */
    FX_CHECK_EQ(st.x, 80 * 65536);
    FX_CHECK_EQ(st.vx, 30 * 65536);
}

static void fill_random(fx_surface *s, uint32_t *seed)
{
    for (int32_t y = 0; y < s->h; y++)
        for (int32_t x = 0; x < s->w; x++)
            fx_surface_put(s, x, y, fx_test_rand(seed) | 0xFF000000u);
}

FX_TEST(anim_accum_static_scene_is_exact)
{
    static uint32_t pa[37 * 23], pb[37 * 23], pc[37 * 23], acc[37 * 23 * 4];
    const fx_format fmts[] = {FX_FMT_XRGB8888, FX_FMT_RGB565, FX_FMT_ARGB8888, FX_FMT_GRAY8};
    uint32_t seed = 5;
    for (int f = 0; f < 4; f++)
        for (int n = 1; n <= 9; n++) {
            fx_surface a, c;
            fx_surface_init(&a, pa, 37, 23, 37 * 4, fmts[f]);
            fx_surface_init(&c, pc, 37, 23, 37 * 4, fmts[f]);
            fill_random(&a, &seed);
            memset(pc, 0, sizeof pc);
            fx_accum ac;
            FX_CHECK_EQ(fx_accum_init(&ac, acc, sizeof acc, 37, 23), 0);
            for (int k = 0; k < n; k++)
                FX_CHECK_EQ(fx_accum_add(&ac, &a), 0);
            FX_CHECK_EQ(fx_accum_resolve(&ac, &c), 0);
            for (int32_t y = 0; y < 23; y++)
                for (int32_t x = 0; x < 37; x++)
                    FX_CHECK_EQ_HEX(fx_surface_get_native(&c, x, y), fx_surface_get_native(&a, x, y));
        }
    /* two frames: the rounded mean of each channel */
    fx_surface a, b, c;
    fx_surface_init(&a, pa, 37, 23, 37 * 4, FX_FMT_ARGB8888);
    fx_surface_init(&b, pb, 37, 23, 37 * 4, FX_FMT_ARGB8888);
    fx_surface_init(&c, pc, 37, 23, 37 * 4, FX_FMT_ARGB8888);
    fx_surface_clear(&a, 0xFF000000u);
    fx_surface_clear(&b, 0xFF0102FFu);
    fx_accum ac;
    fx_accum_init(&ac, acc, sizeof acc, 37, 23);
    fx_accum_add(&ac, &a);
    fx_accum_add(&ac, &b);
    fx_accum_resolve(&ac, &c);
    FX_CHECK_EQ_HEX(fx_surface_get(&c, 5, 5), 0xFF010180u); /* 0.5 -> 1 (ties up), 1 -> 1, 127.5 -> 128 */
    FX_CHECK_EQ(fx_accum_init(&ac, acc, 10, 37, 23), -FX_ENOSPC);
}

/* ---- the script commands ---- */

static uint32_t sa[96 * 64], sb[96 * 64];
static char last_err[256];

static int run(uint32_t *mem, const char *text, fx16 clock, int fix)
{
    static uint8_t arena[4 << 20];
    scene_buf buf = {mem, 96 * 64};
    fx_scene_host h = {&buf, scene_buf_make, NULL, NULL, NULL, NULL};
    fx_scene sc;
    fx_scene_init(&sc, &h, arena, sizeof arena);
    if (fix)
        fx_scene_set_clock(&sc, clock);
    int r = fx_scene_run(&sc, text, strlen(text));
    snprintf(last_err, sizeof last_err, "%d:%d: %s", sc.err_line, sc.err_col, sc.err);
    return r;
}

FX_TEST(anim_blur_of_a_static_scene_is_the_scene)
{
    const char *plain = "size 96 64\nclear #102030\ncolor #FF8000\nxpoly fill 10 10 80 20 40 60\n"
                        "color #4080FF\nline 0 63 95 0\n";
    const char *blurred = "size 96 64\nclear #102030\nblur 7 0.5\ncolor #FF8000\nxpoly fill 10 10 80 20 40 60\n"
                          "color #4080FF\nline 0 63 95 0\nendblur\n";
    FX_CHECK_EQ(run(sa, plain, 0, 0), 0);
    FX_CHECK_EQ(run(sb, blurred, 0, 0), 0);
    FX_CHECK(!memcmp(sa, sb, sizeof sa));
    /* a moving square blurred over the shutter: its two ends are partly covered */
    const char *moving = "size 96 64\nclear #000000\nkey m 0 0 0\nkey m 1 40 0\ninterp m linear\n"
                         "blur 8 1\ncolor #FFFFFF\ntween m translate\nfillrect 10 10 10 10\nendblur\n"
                         "fillrect 0 40 4 4\n";
    FX_CHECK_EQ(run(sa, moving, 0, 0), 0);
    FX_CHECK_EQ_HEX(sa[15 * 96 + 10] & 0xFFFFFF, 0x202020); /* one sub-frame of 8: 255/8 rounded */
    FX_CHECK_EQ_HEX(sa[15 * 96 + 19] & 0xFFFFFF, 0x404040); /* by two: offsets 0 and 5 */
    FX_CHECK_EQ_HEX(sa[15 * 96 + 50] & 0xFFFFFF, 0x202020); /* the last, offset 35, covers 45..54 */
    FX_CHECK_EQ_HEX(sa[15 * 96 + 55] & 0xFFFFFF, 0x000000);
    FX_CHECK_EQ_HEX(sa[41 * 96 + 1] & 0xFFFFFF, 0xFFFFFF); /* the colour after the block is as before it */
    FX_CHECK(run(sa, "size 9 9\nblur 2 1\nfillrect 0 0 1 1\n", 0, 0) < 0); /* left open */
    FX_CHECK_MSG(strstr(last_err, "without 'endblur'"), "%s", last_err);
    FX_CHECK(run(sa, "size 9 9\nendblur\n", 0, 0) < 0);
    FX_CHECK_MSG(!strcmp(last_err, "2:1: 'endblur' without 'blur'"), "%s", last_err);
    FX_CHECK(run(sa, "size 9 9\nblur 2 1\nblur 2 1\nendblur\n", 0, 0) < 0);
    FX_CHECK_MSG(!strcmp(last_err, "3:1: blur blocks do not nest"), "%s", last_err);
}

FX_TEST(anim_host_clock_overrides_time)
{
    const char *s = "size 96 64\nclear #000000\ntime 0\nkey m 0 0 0\nkey m 2 60 0\ninterp m linear\n"
                    "color #FFFFFF\ntween m translate\nfillrect 10 10 4 4\n";
    FX_CHECK_EQ(run(sa, s, 0, 0), 0);
    FX_CHECK_EQ_HEX(sa[11 * 96 + 11] & 0xFFFFFF, 0xFFFFFF);
    FX_CHECK_EQ(run(sb, s, FX16_ONE, 1), 0); /* t = 1: moved by 30 */
    FX_CHECK_EQ_HEX(sb[11 * 96 + 11] & 0xFFFFFF, 0);
    FX_CHECK_EQ_HEX(sb[11 * 96 + 41] & 0xFFFFFF, 0xFFFFFF);
    FX_CHECK(run(sa, "key m 1 0\nkey m 0.5 1\n", 0, 0) < 0); /* keys out of order */
    FX_CHECK_MSG(!strcmp(last_err, "2:1: keys of track 'm' must come in increasing time"), "%s", last_err);
    FX_CHECK(run(sa, "key m 1 0\nkey m 2 1 2\n", 0, 0) < 0); /* value counts differ */
    FX_CHECK_MSG(!strcmp(last_err, "2:1: track 'm' has 1 value per key, not 2"), "%s", last_err);
    FX_CHECK(run(sa, "size 9 9\ntween nope translate\n", 0, 0) < 0);
    FX_CHECK_MSG(strstr(last_err, "no track 'nope'"), "%s", last_err);
}

/* Issue #40: g (floor - y) + vy^2 / 2 overflowed for a ball past the
 * limits (the energy is a query; nothing validates b first). It saturates;
 * inside the limits it is exact. */
FX_TEST(anim_ball_energy_extremes)
{
    fx_anim_ball b = {0};
    fx_anim_ball_state s = {0};
    b.g = INT32_MAX;
    b.floor = INT32_MAX;
    s.y = INT32_MIN;
    s.vy = INT32_MIN;
    FX_CHECK_EQ(fx_anim_ball_energy(&b, &s), INT64_MAX);
    b.g = INT32_MIN; /* g (floor - y) = -2^31 (2^32 - 1), plus 2^61 */
    FX_CHECK_EQ(fx_anim_ball_energy(&b, &s), -(((int64_t)1 << 31) * (((int64_t)1 << 32) - 1)) + ((int64_t)1 << 61));
    /* at the limits: g 2^30, floor - y 2^31, vy^2 / 2 = 2^57 */
    b.g = FX_ANIM_BALL_G << 16;
    b.floor = FX_ANIM_BALL_POS << 16;
    s.y = -(FX_ANIM_BALL_POS << 16);
    s.vy = -(FX_ANIM_BALL_SPEED << 16);
    FX_CHECK_EQ(fx_anim_ball_energy(&b, &s), ((int64_t)1 << 61) + ((int64_t)1 << 57));
    FX_CHECK_EQ(fx_anim_ball_energy(NULL, &s), 0);
    FX_CHECK_EQ(fx_anim_ball_energy(&b, NULL), 0);
}
