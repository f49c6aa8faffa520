/* SPDX-License-Identifier: MIT */
/* Kinematics of a jointed chain (fixel/kinematics.h): forward kinematics
 * against a double-precision reference within the header's bound; CCD
 * reaching every reachable target within the tolerance and iteration bound
 * (checked by an independent double FK of the returned pose); an out-of-reach
 * target giving the straight arm pointing at it; the same bits on a second
 * run; every argument range-checked; the extremes of the limits free of
 * overflow (run under UBSan); the goal-directed step with bounded speed and
 * exact arrival, and the arm following it. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "fixel/error.h"
#include "fixel/kinematics.h"
#include "fx_test.h"

#define U 65536.0
#define TURN 4294967296.0

static void ref_fk(const fx_kin_chain *c, const fx_angle *th, double *xy)
{
    double x = c->x / U, y = c->y / U;
    uint32_t a = c->dir;
    xy[0] = x, xy[1] = y;
    for (int i = 0; i < c->n; i++) {
        a += th[i];
        double r = a / TURN * 2 * M_PI;
        x += c->len[i] / U * cos(r);
        y += c->len[i] / U * sin(r);
        xy[2 * i + 2] = x, xy[2 * i + 3] = y;
    }
}

/* A random chain: n links, total length up to `reach` units, base within `coord`. */
static void rnd_chain(uint32_t *s, fx_kin_chain *c, fx16 *len, int n, int32_t reach, int32_t coord)
{
    int64_t sum = 0;
    for (int i = 0; i < n; i++) {
        len[i] = (fx16)(fx_test_rand(s) % ((uint32_t)reach * 65536u / (uint32_t)n + 1));
        sum += len[i];
    }
    c->x = (fx16)((int64_t)(fx_test_rand(s) % (2u * (uint32_t)coord * 65536u + 1)) - (int64_t)coord * 65536);
    c->y = (fx16)((int64_t)(fx_test_rand(s) % (2u * (uint32_t)coord * 65536u + 1)) - (int64_t)coord * 65536);
    c->dir = fx_test_rand(s);
    c->n = n;
    c->len = len;
    (void)sum;
}

FX_TEST(kinem_forward_matches_double)
{
    uint32_t s = 11;
    double worst = 0;
    for (int it = 0; it < 3000; it++) {
        fx_kin_chain c;
        fx16 len[FX_KIN_MAX_JOINTS], xy[2 * FX_KIN_MAX_JOINTS + 2];
        fx_angle th[FX_KIN_MAX_JOINTS];
        double ref[2 * FX_KIN_MAX_JOINTS + 2];
        int n = 1 + (int)(fx_test_rand(&s) % FX_KIN_MAX_JOINTS);
        rnd_chain(&s, &c, len, n, it % 2 ? FX_KIN_REACH : 100, it % 3 ? FX_KIN_COORD : 10);
        for (int i = 0; i < n; i++)
            th[i] = fx_test_rand(&s);
        FX_CHECK_EQ(fx_kin_forward(&c, th, xy), n + 1);
        ref_fk(&c, th, ref);
        double reach = 0;
        for (int i = 0; i < n; i++)
            reach += len[i] / U;
        double bound = 1.0 / 131072 + reach / 1048576 + 1e-9;
        for (int i = 0; i < 2 * n + 2; i++) {
            double e = fabs(xy[i] / U - ref[i]);
            worst = e > worst ? e : worst;
            FX_CHECK_MSG(e <= bound, "chain %d value %d: %.9f vs %.9f (bound %.3g)", it, i, xy[i] / U, ref[i], bound);
        }
    }
    printf("  fk: worst error %.3g units over 3000 chains\n", worst);
}

/* A reachable target: the end of the chain at a random pose. */
FX_TEST(kinem_ccd_reaches_reachable_targets)
{
    uint32_t s = 23;
    const fx16 tol = 65536 / 64;
    const int32_t max_iter = 100;
    int worst = 0;
    long total = 0;
    for (int it = 0; it < 2000; it++) {
        fx_kin_chain c;
        fx16 len[FX_KIN_MAX_JOINTS], xy[2 * FX_KIN_MAX_JOINTS + 2];
        fx_angle th[FX_KIN_MAX_JOINTS], pose[FX_KIN_MAX_JOINTS];
        int n = 2 + (int)(fx_test_rand(&s) % (FX_KIN_MAX_JOINTS - 1));
        int32_t reach = 1 + (int32_t)(fx_test_rand(&s) % (FX_KIN_REACH / 2));
        rnd_chain(&s, &c, len, n, reach, FX_KIN_COORD - reach); /* the target stays within the limits */
        /* equal-ish lengths leave no hole round the base: every point within reach is reachable */
        for (int i = 0; i < n; i++) {
            len[i] = len[0];
            pose[i] = fx_test_rand(&s);
            th[i] = 0;
        }
        fx_kin_forward(&c, pose, xy);
        fx16 tx = xy[2 * n], ty = xy[2 * n + 1];
        fx_kin_result r;
        int k = fx_kin_ccd(&c, th, tx, ty, tol, max_iter, &r);
        FX_CHECK_MSG(k >= 0 && k <= max_iter && r.reached == 1 && r.iterations == k && r.distance <= tol,
                     "chain %d (n %d, link %.3f, target at %.5f of the reach): %d sweeps, reached %d, distance %.5f", it, n, len[0] / U, hypot(tx / U - c.x / U, ty / U - c.y / U) / (n * len[0] / U), k,
                     r.reached, r.distance / U);
        double ref[2 * FX_KIN_MAX_JOINTS + 2];
        ref_fk(&c, th, ref);
        double d = hypot(ref[2 * n] - tx / U, ref[2 * n + 1] - ty / U);
        FX_CHECK_MSG(d <= tol / U + 1e-3, "chain %d: the pose's true end is %.5f from the target", it, d);
        worst = k > worst ? k : worst;
        total += k;
    }
    printf("  ccd: 2000 reachable targets, mean %.1f sweeps, worst %d (bound %d)\n", total / 2000.0, worst,
           max_iter);
}

FX_TEST(kinem_unreachable_target_gives_the_straight_arm)
{
    uint32_t s = 5;
    for (int it = 0; it < 1000; it++) {
        fx_kin_chain c;
        fx16 len[FX_KIN_MAX_JOINTS], xy[2 * FX_KIN_MAX_JOINTS + 2];
        fx_angle th[FX_KIN_MAX_JOINTS];
        int n = 1 + (int)(fx_test_rand(&s) % FX_KIN_MAX_JOINTS);
        rnd_chain(&s, &c, len, n, 1 + (int32_t)(fx_test_rand(&s) % 2000), 1000);
        double reach = 0;
        for (int i = 0; i < n; i++) {
            reach += len[i] / U;
            th[i] = fx_test_rand(&s);
        }
        /* a target past the reach, in a random direction */
        double a = (fx_test_rand(&s) % 3600) / 1800.0 * M_PI, D = reach + 0.5 + (fx_test_rand(&s) % 4000);
        double tx = c.x / U + D * cos(a), ty = c.y / U + D * sin(a);
        if (fabs(tx) > FX_KIN_COORD || fabs(ty) > FX_KIN_COORD)
            continue;
        fx16 ftx = (fx16)lround(tx * U), fty = (fx16)lround(ty * U);
        fx_kin_result r;
        FX_CHECK_EQ(fx_kin_ccd(&c, th, ftx, fty, 65536 / 16, 100, &r), 0);
        FX_CHECK_EQ(r.reached, 0);
        for (int i = 1; i < n; i++)
            FX_CHECK_EQ(th[i], 0u);
        FX_CHECK_EQ(fx_kin_forward(&c, th, xy), n + 1);
        /* every joint on the ray from the base toward the target, at its running length */
        double ux = (ftx / U - c.x / U) / hypot(ftx / U - c.x / U, fty / U - c.y / U);
        double uy = (fty / U - c.y / U) / hypot(ftx / U - c.x / U, fty / U - c.y / U);
        double run = 0;
        for (int i = 0; i < n; i++) {
            run += len[i] / U;
            double ex = c.x / U + run * ux, ey = c.y / U + run * uy;
            double e = hypot(xy[2 * i + 2] / U - ex, xy[2 * i + 3] / U - ey);
            FX_CHECK_MSG(e <= 1e-3 + run * 1e-5, "chain %d joint %d off the ray by %.6f", it, i + 1, e);
        }
        double want = hypot(ftx / U - c.x / U, fty / U - c.y / U) - reach;
        FX_CHECK_MSG(fabs(r.distance / U - want) <= 2e-3, "distance %.5f, expected %.5f", r.distance / U, want);
    }
}

FX_TEST(kinem_is_deterministic)
{
    uint32_t s = 99;
    for (int it = 0; it < 200; it++) {
        fx_kin_chain c;
        fx16 len[FX_KIN_MAX_JOINTS];
        fx_angle a[FX_KIN_MAX_JOINTS], b[FX_KIN_MAX_JOINTS];
        int n = 1 + (int)(fx_test_rand(&s) % FX_KIN_MAX_JOINTS);
        rnd_chain(&s, &c, len, n, 500, 500);
        for (int i = 0; i < n; i++)
            a[i] = b[i] = fx_test_rand(&s);
        fx16 tx = (fx16)(fx_test_rand(&s) % (1000u << 16)) - (500 << 16);
        fx16 ty = (fx16)(fx_test_rand(&s) % (1000u << 16)) - (500 << 16);
        fx_kin_result ra, rb;
        int ka = fx_kin_ccd(&c, a, tx, ty, 100, 50, &ra), kb = fx_kin_ccd(&c, b, tx, ty, 100, 50, &rb);
        FX_CHECK_EQ(ka, kb);
        FX_CHECK(memcmp(a, b, sizeof(fx_angle) * (size_t)n) == 0);
        FX_CHECK(memcmp(&ra, &rb, sizeof ra) == 0);
        /* a pose that reached its target needs no sweep the second time */
        if (ra.reached)
            FX_CHECK_EQ(fx_kin_ccd(&c, a, tx, ty, 100, 50, &ra), 0);
    }
}

FX_TEST(kinem_rejects_bad_arguments)
{
    fx16 len[FX_KIN_MAX_JOINTS + 1] = {65536, 65536}, xy[2 * FX_KIN_MAX_JOINTS + 4];
    fx_angle th[FX_KIN_MAX_JOINTS + 1] = {0};
    fx_kin_chain c = {0, 0, 0, 2, len};
    fx16 C = FX_KIN_COORD * 65536, px = 0, py = 0;
    FX_CHECK_EQ(fx_kin_forward(&c, th, xy), 3);
    FX_CHECK_EQ(fx_kin_forward(0, th, xy), -FX_EINVAL);
    FX_CHECK_EQ(fx_kin_forward(&c, 0, xy), -FX_EINVAL);
    FX_CHECK_EQ(fx_kin_forward(&c, th, 0), -FX_EINVAL);
    fx_kin_chain bad = c;
    bad.n = 0;
    FX_CHECK_EQ(fx_kin_forward(&bad, th, xy), -FX_EINVAL);
    bad.n = FX_KIN_MAX_JOINTS + 1;
    FX_CHECK_EQ(fx_kin_forward(&bad, th, xy), -FX_EINVAL);
    bad = c;
    bad.len = 0;
    FX_CHECK_EQ(fx_kin_forward(&bad, th, xy), -FX_EINVAL);
    bad = c;
    bad.x = C + 1;
    FX_CHECK_EQ(fx_kin_forward(&bad, th, xy), -FX_EINVAL);
    bad = c;
    bad.y = -C - 1;
    FX_CHECK_EQ(fx_kin_forward(&bad, th, xy), -FX_EINVAL);
    fx16 neg[2] = {65536, -1}, over[2] = {FX_KIN_REACH * 65536, 1}, full[2] = {FX_KIN_REACH * 65536, 0};
    bad = c;
    bad.len = neg;
    FX_CHECK_EQ(fx_kin_forward(&bad, th, xy), -FX_EINVAL);
    bad.len = over;
    FX_CHECK_EQ(fx_kin_forward(&bad, th, xy), -FX_EINVAL);
    bad.len = full;
    FX_CHECK_EQ(fx_kin_forward(&bad, th, xy), 3);
    fx_kin_result r;
    FX_CHECK_EQ(fx_kin_ccd(&c, th, C, -C, 0, FX_KIN_MAX_ITER, &r), 0);
    FX_CHECK_EQ(fx_kin_ccd(&c, th, C + 1, 0, 0, 10, &r), -FX_EINVAL);
    FX_CHECK_EQ(fx_kin_ccd(&c, th, 0, -C - 1, 0, 10, &r), -FX_EINVAL);
    FX_CHECK_EQ(fx_kin_ccd(&c, th, 0, 0, -1, 10, &r), -FX_EINVAL);
    FX_CHECK_EQ(fx_kin_ccd(&c, th, 0, 0, FX_KIN_REACH * 65536 + 1, 10, &r), -FX_EINVAL);
    FX_CHECK_EQ(fx_kin_ccd(&c, th, 0, 0, 0, -1, &r), -FX_EINVAL);
    FX_CHECK_EQ(fx_kin_ccd(&c, th, 0, 0, 0, FX_KIN_MAX_ITER + 1, &r), -FX_EINVAL);
    FX_CHECK_EQ(fx_kin_ccd(&c, 0, 0, 0, 0, 10, &r), -FX_EINVAL);
    FX_CHECK_EQ(fx_kin_ccd(&bad, th, 0, 0, 0, 10, 0) >= 0, 1); /* res may be NULL */
    bad.len = over;
    FX_CHECK_EQ(fx_kin_ccd(&bad, th, 0, 0, 0, 10, &r), -FX_EINVAL);
    FX_CHECK_EQ(fx_kin_step(0, &py, 0, 0, 1), -FX_EINVAL);
    FX_CHECK_EQ(fx_kin_step(&px, 0, 0, 0, 1), -FX_EINVAL);
    FX_CHECK_EQ(fx_kin_step(&px, &py, C + 1, 0, 1), -FX_EINVAL);
    FX_CHECK_EQ(fx_kin_step(&px, &py, 0, -C - 1, 1), -FX_EINVAL);
    FX_CHECK_EQ(fx_kin_step(&px, &py, 0, 0, -1), -FX_EINVAL);
    FX_CHECK_EQ(fx_kin_step(&px, &py, 0, 0, FX_KIN_REACH * 65536 + 1), -FX_EINVAL);
    px = C + 1;
    FX_CHECK_EQ(fx_kin_step(&px, &py, 0, 0, 1), -FX_EINVAL);
    FX_CHECK_EQ(px, C + 1); /* nothing written on an error */
    px = 0;
    FX_CHECK_EQ(fx_kin_follow(&c, th, &px, &py, 0, 0, 1, -1, 0, 10, 0), -FX_EINVAL);
    FX_CHECK_EQ(fx_kin_follow(&c, th, &px, &py, 0, 0, 1, 65537, 0, 10, 0), -FX_EINVAL);
    FX_CHECK_EQ(fx_kin_follow(&c, th, &px, &py, 0, 0, -1, 1, 0, 10, 0), -FX_EINVAL);
    FX_CHECK_EQ(fx_kin_follow(&c, th, &px, &py, 0, 0, 1, 1, -1, 10, 0), -FX_EINVAL);
    FX_CHECK_EQ(fx_kin_follow(&c, th, &px, &py, 0, 0, 1, 1, 0, FX_KIN_MAX_ITER + 1, 0), -FX_EINVAL);
    FX_CHECK_EQ(fx_kin_follow(&c, 0, &px, &py, 0, 0, 1, 1, 0, 10, 0), -FX_EINVAL);
    FX_CHECK_EQ(fx_kin_follow(&bad, th, &px, &py, 0, 0, 1, 1, 0, 10, 0), -FX_EINVAL);
    FX_CHECK_EQ(fx_kin_follow(&c, th, &px, &py, C + 1, 0, 1, 1, 0, 10, 0), -FX_EINVAL);
}

/* The corners of the limits: the largest base, target and reach, the most
 * links, zero lengths, angles next to the wrap. UBSan catches an overflow. */
FX_TEST(kinem_extremes_do_not_overflow)
{
    const fx16 C = FX_KIN_COORD * 65536, corner[3] = {-C, 0, C};
    fx16 len[FX_KIN_MAX_JOINTS], xy[2 * FX_KIN_MAX_JOINTS + 2];
    fx_angle th[FX_KIN_MAX_JOINTS];
    for (int shape = 0; shape < 3; shape++) {
        for (int i = 0; i < FX_KIN_MAX_JOINTS; i++)
            len[i] = shape == 0 ? FX_KIN_REACH * 65536 / FX_KIN_MAX_JOINTS : shape == 1 ? 0 : (i ? 0 : FX_KIN_REACH * 65536);
        for (int bx = 0; bx < 3; bx++)
            for (int by = 0; by < 3; by++)
                for (int t = 0; t < 9; t++) {
                    fx_kin_chain c = {corner[bx], corner[by], 0xFFFFFFFFu, FX_KIN_MAX_JOINTS, len};
                    for (int i = 0; i < FX_KIN_MAX_JOINTS; i++)
                        th[i] = i % 2 ? 0x80000001u : 0xFFFFFFFFu;
                    FX_CHECK_EQ(fx_kin_forward(&c, th, xy), FX_KIN_MAX_JOINTS + 1);
                    fx_kin_result r;
                    int k = fx_kin_ccd(&c, th, corner[t % 3], corner[t / 3], 0, 20, &r);
                    FX_CHECK(k >= 0 && k <= 20);
                    FX_CHECK(r.distance >= 0);
                    fx16 px = corner[bx], py = corner[by];
                    FX_CHECK(fx_kin_follow(&c, th, &px, &py, corner[t % 3], corner[t / 3], FX_KIN_REACH * 65536, 3,
                                           0, 5, xy) >= 0);
                    FX_CHECK_EQ(px, corner[t % 3]); /* the full speed crosses the box in two frames */
                    FX_CHECK_EQ(py, corner[t / 3]);
                }
    }
}

FX_TEST(kinem_step_has_bounded_speed_and_exact_arrival)
{
    uint32_t s = 3;
    for (int it = 0; it < 2000; it++) {
        fx16 x = (fx16)(fx_test_rand(&s) % (8000u << 16)) - (4000 << 16);
        fx16 y = (fx16)(fx_test_rand(&s) % (8000u << 16)) - (4000 << 16);
        fx16 gx = (fx16)(fx_test_rand(&s) % (8000u << 16)) - (4000 << 16);
        fx16 gy = (fx16)(fx_test_rand(&s) % (8000u << 16)) - (4000 << 16);
        fx16 v = 1 + (fx16)(fx_test_rand(&s) % (500u << 16));
        double d0 = hypot((gx - (double)x) / U, (gy - (double)y) / U);
        int frames = 0, r = 0;
        while (!r && frames < 100000) {
            fx16 ox = x, oy = y;
            r = fx_kin_step(&x, &y, gx, gy, v);
            FX_CHECK(r == 0 || r == 1);
            /* at most the speed, plus the rounding of each component */
            FX_CHECK(hypot((x - (double)ox) / U, (y - (double)oy) / U) <= v / U + 1.5 / U);
            frames++;
        }
        FX_CHECK(x == gx && y == gy);
        /* straight at the goal: no more frames than the distance needs, give or take rounding */
        FX_CHECK_MSG(frames <= (int)ceil(d0 / (v / U) + 1e-9) + 1, "%d frames for %.3f at %.3f", frames, d0, v / U);
        FX_CHECK(frames >= (int)ceil(d0 / (v / U) - 1e-6));
    }
}

FX_TEST(kinem_arm_follows_the_goal)
{
    fx16 len[3] = {60 << 16, 50 << 16, 40 << 16}, trail[2 * 200];
    fx_angle th[3] = {0, 0, 0};
    fx_kin_chain c = {0, 0, 0, 3, len};
    fx16 px = 150 << 16, py = 0; /* the end of the straight arm */
    const fx16 speed = 2 << 16, tol = 65536 / 32;
    int arrived = fx_kin_follow(&c, th, &px, &py, -40 * 65536, 90 << 16, speed, 200, tol, 50, trail);
    double d = hypot(190, 90);
    FX_CHECK_MSG(arrived == (int)ceil(d / 2) || arrived == (int)ceil(d / 2) + 1, "arrived at frame %d", arrived);
    FX_CHECK(px == -40 * 65536 && py == 90 << 16);
    /* the end tracks the aim point: within the tolerance of it every frame, and it moves continuously */
    fx16 ax = 150 << 16, ay = 0;
    for (int f = 0; f < 200; f++) {
        double ox = f ? trail[2 * f - 2] / U : 150, oy = f ? trail[2 * f - 1] / U : 0;
        fx_kin_step(&ax, &ay, -40 * 65536, 90 << 16, speed);
        FX_CHECK_MSG(hypot(trail[2 * f] / U - ax / U, trail[2 * f + 1] / U - ay / U) <= tol / U + 1e-4,
                     "frame %d off the aim", f);
        FX_CHECK(hypot(trail[2 * f] / U - ox, trail[2 * f + 1] / U - oy) <= 2 + 2 * tol / U + 1e-4);
    }
}

/* A long first link leaves a hole round the base that no pose reaches: the
 * solve spends its sweeps, says so, and its distance is never below the
 * hole's true gap (L0 - the rest - |target - base|). */
FX_TEST(kinem_hole_round_the_base_is_not_reached)
{
    fx16 len[3] = {100 << 16, 30 << 16, 20 << 16};
    fx_kin_chain c = {0, 0, 0, 3, len};
    for (int k = 0; k < 40; k++) {
        fx_angle th[3] = {(fx_angle)k * 0x06000000u, 0x40000000u, 0};
        double a = k * 0.3, r = 5 + k;
        fx16 tx = (fx16)lround(r * cos(a) * U), ty = (fx16)lround(r * sin(a) * U);
        fx_kin_result res;
        FX_CHECK_EQ(fx_kin_ccd(&c, th, tx, ty, 65536 / 64, 60, &res), 60);
        FX_CHECK_EQ(res.reached, 0);
        double gap = 100 - 50 - hypot(tx / U, ty / U);
        FX_CHECK_MSG(res.distance / U >= gap - 1e-3, "target %d: distance %.4f below the gap %.4f", k,
                     res.distance / U, gap);
    }
}
