/* SPDX-License-Identifier: MIT */
/* fixel — forward and inverse kinematics of a planar chain, and a
 * goal-directed motion (fixel/kinematics.h). The limits of the header keep
 * every joint within 2^14 units of the origin, so positions and their
 * differences stay inside Q16.16 and the 64-bit sums below cannot overflow:
 * a length (< 2^29 raw) times a Q2.30 sine is < 2^59, and the base shifted
 * by 30 plus the whole reach is < 2^60. */
#include "fixel/kinematics.h"
#include "fixel/error.h"

#define COORD ((int64_t)FX_KIN_COORD * FX16_ONE)
#define REACH ((int64_t)FX_KIN_REACH * FX16_ONE)

static int in_coord(fx16 v) { return v >= -COORD && v <= COORD; }

/* The chain's total length, or -1 when it breaks a limit. */
static int64_t chain_reach(const fx_kin_chain *c)
{
    if (!c || !c->len || c->n < 1 || c->n > FX_KIN_MAX_JOINTS || !in_coord(c->x) || !in_coord(c->y))
        return -1;
    int64_t sum = 0;
    for (int32_t i = 0; i < c->n; i++) {
        if (c->len[i] < 0)
            return -1;
        sum += c->len[i];
    }
    return sum > REACH ? -1 : sum;
}

/* Round a value with 46 fraction bits to Q16.16 (nearest, ties up). */
static fx16 round46(int64_t v) { return (fx16)((v + ((int64_t)1 << 29)) >> 30); }

/* The chain's points, assuming a valid chain. */
static void forward(const fx_kin_chain *c, const fx_angle *theta, fx16 *xy)
{
    int64_t x = (int64_t)c->x * (1 << 30), y = (int64_t)c->y * (1 << 30);
    fx_angle a = c->dir;
    xy[0] = c->x;
    xy[1] = c->y;
    for (int32_t i = 0; i < c->n; i++) {
        a += theta[i]; /* binary angles wrap: the sum is exact modulo a turn */
        x += (int64_t)c->len[i] * fx_cos30(a);
        y += (int64_t)c->len[i] * fx_sin30(a);
        xy[2 * i + 2] = round46(x);
        xy[2 * i + 3] = round46(y);
    }
}

int fx_kin_forward(const fx_kin_chain *c, const fx_angle *theta, fx16 *xy)
{
    if (chain_reach(c) < 0 || !theta || !xy)
        return -FX_EINVAL;
    forward(c, theta, xy);
    return c->n + 1;
}

static fx16 dist(fx16 x0, fx16 y0, fx16 x1, fx16 y1)
{
    return (fx16)fx_hypot(x1 - x0, y1 - y0); /* < 2^31: both within 2^15 units */
}

/* The bend at joint 1 that puts the end at distance d from the base: the
 * triangle of link 0 (a), the rest of the chain from joint 1 to the end as
 * one rigid piece (b) and d, by the law of cosines, the outer angle phi at
 * joint 1 being atan2(sqrt((2ab)^2 - X^2), X) with X = d^2 - a^2 - b^2.
 * The sides are scaled below 2^20 so the squares fit 64 bits. Returns 0
 * when no triangle exists (d outside [|a - b|, a + b]). */
static int bend_for(int64_t a, int64_t b, int64_t d, fx_angle *phi)
{
    unsigned sh = 0;
    while (((a | b | d) >> sh) >= ((int64_t)1 << 20))
        sh++;
    a >>= sh, b >>= sh, d >>= sh;
    if (!a || !b)
        return 0;
    int64_t x = d * d - a * a - b * b, ab2 = 2 * a * b;
    if (ab2 - x < 0 || ab2 + x < 0)
        return 0;
    int64_t y = (int64_t)fx_isqrt64((uint64_t)(ab2 - x)) * fx_isqrt64((uint64_t)(ab2 + x));
    while (y >= ((int64_t)1 << 30) || x >= ((int64_t)1 << 30) || x <= -((int64_t)1 << 30))
        y >>= 1, x >>= 1; /* arithmetic: x keeps its sign; the ratio, and so phi, is kept */
    *phi = fx_atan2((int32_t)y, (int32_t)x);
    return 1;
}

int fx_kin_ccd(const fx_kin_chain *c, fx_angle *theta, fx16 tx, fx16 ty, fx16 tol, int32_t max_iter,
               fx_kin_result *res)
{
    int64_t reach = chain_reach(c);
    if (reach < 0 || !theta || !in_coord(tx) || !in_coord(ty) || tol < 0 || tol > REACH || max_iter < 0 ||
        max_iter > FX_KIN_MAX_ITER)
        return -FX_EINVAL;
    fx16 p[2 * (FX_KIN_MAX_JOINTS + 1)];
    int32_t n = c->n, it = 0;
    if (dist(c->x, c->y, tx, ty) >= reach - tol) {
        /* Out of reach, or so near its edge that the straight arm is within
         * the tolerance: CCD would only creep toward the straight arm (its
         * convergence is slowest there), so give it directly. */
        theta[0] = fx_atan2(ty - c->y, tx - c->x) - c->dir;
        for (int32_t i = 1; i < n; i++)
            theta[i] = 0;
        forward(c, theta, p);
    } else {
        forward(c, theta, p);
        while (it < max_iter && dist(p[2 * n], p[2 * n + 1], tx, ty) > tol) {
            for (int32_t j = n - 1; j >= 0; j--) {
                fx16 jx = p[2 * j], jy = p[2 * j + 1];
                fx_angle phi;
                if (j == 1 && (p[2 * n] != jx || p[2 * n + 1] != jy) &&
                    bend_for(c->len[0], dist(jx, jy, p[2 * n], p[2 * n + 1]), dist(c->x, c->y, tx, ty), &phi)) {
                    /* CCD alone creeps when the arm is nearly straight (each sweep
                     * bends it a little); the closed-form bend of the triangle
                     * puts the end on the circle through the target, and joint 0
                     * then turns it onto the target. The bend keeps its side. */
                    fx_angle rel = fx_atan2(p[2 * n + 1] - jy, p[2 * n] - jx) - (c->dir + theta[0]);
                    theta[1] += ((int32_t)rel < 0 ? 0 - phi : phi) - rel;
                    forward(c, theta, p);
                    continue;
                }
                if (p[2 * n] == jx && p[2 * n + 1] == jy)
                    continue; /* the end sits on this joint: turning it moves nothing */
                fx_angle to_end = fx_atan2(p[2 * n + 1] - jy, p[2 * n] - jx);
                fx_angle to_target = fx_atan2(ty - jy, tx - jx);
                theta[j] += to_target - to_end;
                forward(c, theta, p);
            }
            it++;
        }
    }
    if (res) {
        res->iterations = it;
        res->distance = dist(p[2 * n], p[2 * n + 1], tx, ty);
        res->reached = res->distance <= tol;
    }
    return it;
}

int fx_kin_step(fx16 *px, fx16 *py, fx16 gx, fx16 gy, fx16 speed)
{
    if (!px || !py || !in_coord(*px) || !in_coord(*py) || !in_coord(gx) || !in_coord(gy) || speed < 0 ||
        speed > REACH)
        return -FX_EINVAL;
    int64_t dx = (int64_t)gx - *px, dy = (int64_t)gy - *py;
    int64_t d = fx_hypot((int32_t)dx, (int32_t)dy);
    if (d <= speed) {
        *px = gx;
        *py = gy;
        return 1;
    }
    /* speed / d < 1, so each moved component is smaller than its difference;
     * dx * speed < 2^31 * 2^30 fits int64. Round half away from zero. */
    int64_t mx = dx * speed, my = dy * speed;
    *px += (fx16)((mx + (mx < 0 ? -d / 2 : d / 2)) / d);
    *py += (fx16)((my + (my < 0 ? -d / 2 : d / 2)) / d);
    return 0;
}

int fx_kin_follow(const fx_kin_chain *c, fx_angle *theta, fx16 *px, fx16 *py, fx16 gx, fx16 gy, fx16 speed,
                  int32_t frames, fx16 tol, int32_t iter, fx16 *trail)
{
    if (chain_reach(c) < 0 || !theta || !px || !py || !in_coord(*px) || !in_coord(*py) || !in_coord(gx) ||
        !in_coord(gy) || speed < 0 || speed > REACH || frames < 0 || frames > 65536 || tol < 0 || tol > REACH ||
        iter < 0 || iter > FX_KIN_MAX_ITER)
        return -FX_EINVAL;
    int arrived = 0;
    fx16 p[2 * (FX_KIN_MAX_JOINTS + 1)];
    for (int32_t f = 0; f < frames; f++) {
        if (fx_kin_step(px, py, gx, gy, speed) == 1 && !arrived)
            arrived = f + 1;
        fx_kin_ccd(c, theta, *px, *py, tol, iter, 0);
        if (trail) {
            forward(c, theta, p);
            trail[2 * f] = p[2 * c->n];
            trail[2 * f + 1] = p[2 * c->n + 1];
        }
    }
    return arrived;
}
