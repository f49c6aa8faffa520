/* SPDX-License-Identifier: MIT */
/* 2D transforms: the course's examples, exactness at multiples of 90
 * degrees, composition order, inversion error bound, window-to-viewport, and
 * rectangles drawn through a transform. */
#include <stdlib.h>
#include <string.h>

#include "fixel/clip.h"
#include "fixel/error.h"
#include "fixel/xform.h"
#include "canvas.h"
#include "fx_test.h"

#define F(v) ((fx16)((v) * 65536.0))
#define I(v) ((fx16)((v) * 65536))

static fx_pt16 P(fx16 x, fx16 y)
{
    fx_pt16 p = {x, y};
    return p;
}

static int same_matrix(const fx_xform2 *a, const fx_xform2 *b)
{
    return memcmp(a, b, sizeof *a) == 0;
}

FX_TEST(course_translate_polygon_by_minus_5_5_and_3_75)
{
    fx_pt16 poly[4] = {P(I(0), I(0)), P(I(10), I(2)), P(F(7.25), I(9)), P(I(-3), F(4.5))};
    fx_pt16 out[4];
    fx_xform2 t;
    fx_xform2_translation(&t, F(-5.5), F(3.75));
    fx_xform2_apply_pts(&t, poly, out, 4);
    for (int i = 0; i < 4; i++) {
        FX_CHECK_EQ(out[i].x, poly[i].x - F(5.5));
        FX_CHECK_EQ(out[i].y, poly[i].y + F(3.75));
    }
    /* in place, and back with the inverse */
    fx_xform2 inv;
    FX_CHECK_EQ(fx_xform2_invert(&inv, &t), 0);
    fx_xform2_apply_pts(&inv, out, out, 4);
    FX_CHECK(memcmp(out, poly, sizeof poly) == 0);
}

FX_TEST(course_square_into_rectangle_sx2_sy1)
{
    fx_pt16 sq[4] = {P(I(0), I(0)), P(I(10), I(0)), P(I(10), I(10)), P(I(0), I(10))};
    fx_pt16 want[4] = {P(I(0), I(0)), P(I(20), I(0)), P(I(20), I(10)), P(I(0), I(10))};
    fx_xform2 s;
    fx_xform2_scaling(&s, I(2), I(1), 0, 0);
    fx_pt16 out[4];
    fx_xform2_apply_pts(&s, sq, out, 4);
    FX_CHECK(memcmp(out, want, sizeof want) == 0);
    /* about a fixed point: the fixed point stays, the rest scales from it */
    fx_xform2_scaling(&s, I(2), F(0.5), I(5), I(5));
    fx_pt16 f = fx_xform2_apply(&s, P(I(5), I(5)));
    FX_CHECK(f.x == I(5) && f.y == I(5));
    fx_pt16 q = fx_xform2_apply(&s, P(I(10), I(10)));
    FX_CHECK(q.x == I(15) && q.y == F(7.5));
    /* uniform */
    fx_xform2_scaling(&s, F(0.25), F(0.25), 0, 0);
    q = fx_xform2_apply(&s, P(I(8), I(-12)));
    FX_CHECK(q.x == I(2) && q.y == I(-3));
}

FX_TEST(rotation_by_180_equals_reflection_through_the_pivot)
{
    fx16 px = F(3.5), py = F(-2.25);
    fx_xform2 r, t, refl, back, comp;
    fx_xform2_rotation(&r, FX_ANGLE_180, px, py);
    /* T(p) . reflect_origin . T(-p), the course's composite */
    fx_xform2_translation(&t, px, py);
    fx_xform2_reflection(&refl, FX_REFLECT_ORIGIN);
    fx_xform2_translation(&back, -px, -py);
    fx_xform2_mul(&comp, &t, &refl);
    fx_xform2_mul(&comp, &comp, &back);
    FX_CHECK(same_matrix(&r, &comp));
    fx_pt16 q = fx_xform2_apply(&r, P(I(10), I(1)));
    FX_CHECK(q.x == 2 * px - I(10) && q.y == 2 * py - I(1));
}

FX_TEST(rotations_by_multiples_of_90_are_exact)
{
    uint32_t s = 90;
    for (int i = 0; i < 2000; i++) {
        fx16 px = (fx16)(fx_test_rand(&s) % 0x2000000) - 0x1000000, py = (fx16)(fx_test_rand(&s) % 0x2000000) - 0x1000000;
        fx16 x = (fx16)(fx_test_rand(&s) % 0x4000000) - 0x2000000, y = (fx16)(fx_test_rand(&s) % 0x4000000) - 0x2000000;
        int q = (int)(fx_test_rand(&s) % 4);
        fx_xform2 r;
        fx_xform2_rotation(&r, (fx_angle)q * FX_ANGLE_90, px, py);
        fx_pt16 o = fx_xform2_apply(&r, P(x, y));
        int64_t dx = (int64_t)x - px, dy = (int64_t)y - py, ex, ey;
        switch (q) { /* (1,0) -> (cos, sin) */
        case 0: ex = dx, ey = dy; break;
        case 1: ex = -dy, ey = dx; break;
        case 2: ex = -dx, ey = -dy; break;
        default: ex = dy, ey = -dx; break;
        }
        FX_CHECK_EQ(o.x, px + ex);
        FX_CHECK_EQ(o.y, py + ey);
    }
    /* four quarter turns compose to the identity exactly */
    fx_xform2 r, acc;
    fx_xform2_rotation(&r, FX_ANGLE_90, F(1.25), F(7.5));
    fx_xform2_identity(&acc);
    for (int i = 0; i < 4; i++)
        fx_xform2_mul(&acc, &acc, &r);
    FX_CHECK(fx_xform2_is_identity(&acc));
}

FX_TEST(composition_order_matters_and_both_orders_are_offered)
{
    fx_xform2 t, r, a, b;
    fx_xform2_translation(&t, I(10), 0);
    fx_xform2_rotation(&r, FX_ANGLE_90, 0, 0);
    /* a = T . R: rotate first, then translate */
    a = t;
    fx_xform2_pre(&a, &r);
    fx_pt16 p = fx_xform2_apply(&a, P(I(1), 0));
    FX_CHECK(p.x == I(10) && p.y == I(1));
    /* b = R . T: translate first, then rotate */
    b = t;
    fx_xform2_then(&b, &r);
    p = fx_xform2_apply(&b, P(I(1), 0));
    FX_CHECK(p.x == 0 && p.y == I(11));
    fx_xform2 c;
    fx_xform2_mul(&c, &r, &t);
    FX_CHECK(same_matrix(&b, &c));
}

static void check_inverse_bound(const fx_xform2 *m)
{
    fx_xform2 inv, prod;
    int r = fx_xform2_invert(&inv, m);
    FX_CHECK_EQ(r, 0);
    if (r)
        return;
    fx_xform2_mul(&prod, m, &inv);
    for (int i = 0; i < 2; i++) {
        /* (|m[r][0]| + |m[r][1]| + 1) / 2 ulps, plus one for the product's rounding */
        int64_t bound = ((int64_t)llabs(m->m[i][0]) + llabs(m->m[i][1]) + 65536) / 2 / 65536 + 1 + 1;
        for (int j = 0; j < 3; j++) {
            int64_t want = i == j ? 65536 : 0;
            int64_t err = llabs((int64_t)prod.m[i][j] - want);
            FX_CHECK_MSG(err <= bound, "entry %d,%d off by %lld (bound %lld)", i, j, (long long)err, (long long)bound);
        }
    }
    FX_CHECK(prod.m[2][0] == 0 && prod.m[2][1] == 0 && prod.m[2][2] == 65536);
}

FX_TEST(inverse_round_trip_within_the_stated_error)
{
    uint32_t s = 7;
    int64_t worst = 0;
    for (int i = 0; i < 3000; i++) {
        fx_xform2 m, t;
        fx_xform2_rotation(&m, fx_test_rand(&s), (fx16)(fx_test_rand(&s) % 0x8000000) - 0x4000000,
                           (fx16)(fx_test_rand(&s) % 0x8000000) - 0x4000000);
        fx16 sx = (fx16)(fx_test_rand(&s) % (8 << 16)) + (1 << 14), sy = (fx16)(fx_test_rand(&s) % (8 << 16)) + (1 << 14);
        if (fx_test_rand(&s) & 1)
            sx = -sx;
        fx_xform2_scaling(&t, sx, sy, (fx16)(fx_test_rand(&s) % 0x1000000), 0);
        fx_xform2_pre(&m, &t);
        fx_xform2_shear_x(&t, (fx16)(fx_test_rand(&s) % 0x30000) - 0x18000, (fx16)(fx_test_rand(&s) % 0x1000000));
        fx_xform2_pre(&m, &t);
        check_inverse_bound(&m);
        fx_xform2 inv, prod;
        fx_xform2_invert(&inv, &m);
        fx_xform2_mul(&prod, &m, &inv);
        for (int j = 0; j < 3; j++) {
            int64_t e = llabs((int64_t)prod.m[0][j] - (j == 0 ? 65536 : 0));
            worst = e > worst ? e : worst;
        }
    }
    FX_CHECK(worst > 0); /* the bound is exercised, not vacuous */
    fx_xform2 z;
    fx_xform2_scaling(&z, 0, I(1), 0, 0);
    fx_xform2 o;
    FX_CHECK_EQ(fx_xform2_invert(&o, &z), -FX_EDOM);
    z.m[2][0] = 5;
    FX_CHECK_EQ(fx_xform2_invert(&o, &z), -FX_ENOTSUP);
}

FX_TEST(shears_relative_to_a_reference_line)
{
    fx_xform2 m;
    fx_xform2_shear_x(&m, F(0.5), I(-1));
    fx_pt16 p = fx_xform2_apply(&m, P(I(3), I(-1))); /* on y = yref: unchanged */
    FX_CHECK(p.x == I(3) && p.y == I(-1));
    p = fx_xform2_apply(&m, P(I(3), I(3)));
    FX_CHECK(p.x == I(5) && p.y == I(3));
    fx_xform2_shear_y(&m, F(-2), I(4));
    p = fx_xform2_apply(&m, P(I(4), I(9)));
    FX_CHECK(p.x == I(4) && p.y == I(9));
    p = fx_xform2_apply(&m, P(I(5), I(9)));
    FX_CHECK(p.x == I(5) && p.y == I(7));
}

FX_TEST(reflections_about_axes_diagonal_and_any_line)
{
    fx_xform2 m;
    fx_pt16 a = P(F(2.5), F(-7.25)), p;
    fx_xform2_reflection(&m, FX_REFLECT_X_AXIS);
    p = fx_xform2_apply(&m, a);
    FX_CHECK(p.x == a.x && p.y == -a.y);
    fx_xform2_reflection(&m, FX_REFLECT_Y_AXIS);
    p = fx_xform2_apply(&m, a);
    FX_CHECK(p.x == -a.x && p.y == a.y);
    fx_xform2_reflection(&m, FX_REFLECT_ORIGIN);
    p = fx_xform2_apply(&m, a);
    FX_CHECK(p.x == -a.x && p.y == -a.y);
    fx_xform2_reflection(&m, FX_REFLECT_DIAGONAL);
    p = fx_xform2_apply(&m, a);
    FX_CHECK(p.x == a.y && p.y == a.x);
    /* the line through (2, 3) at 45 degrees is y = x + 1: exact */
    fx_xform2_reflection_line(&m, I(2), I(3), FX_ANGLE_45);
    p = fx_xform2_apply(&m, a);
    FX_CHECK(p.x == a.y - I(1) && p.y == a.x + I(1));
    /* the x axis as a line at angle 0, and at 180 degrees: same reflection */
    fx_xform2 x0, x1, ax;
    fx_xform2_reflection_line(&x0, 0, 0, 0);
    fx_xform2_reflection_line(&x1, I(9), 0, FX_ANGLE_180);
    fx_xform2_reflection(&ax, FX_REFLECT_X_AXIS);
    FX_CHECK(same_matrix(&x0, &ax) && same_matrix(&x1, &ax));
    /* any angle: points on the line stay (within the trig error), twice is identity
     * within the round-trip bound, and it matches the course's composite
     * T . R(a) . Sx . R(-a) . T^-1 within a few ulps */
    uint32_t s = 3;
    for (int i = 0; i < 500; i++) {
        fx_angle ang = fx_test_rand(&s);
        fx16 px = (fx16)(fx_test_rand(&s) % 0x1000000) - 0x800000, py = (fx16)(fx_test_rand(&s) % 0x1000000) - 0x800000;
        fx_xform2_reflection_line(&m, px, py, ang);
        fx16 d = (fx16)(fx_test_rand(&s) % 0x400000);
        fx_pt16 on = P(px + (fx16)(((int64_t)fx_cos(ang) * d) >> 16), py + (fx16)(((int64_t)fx_sin(ang) * d) >> 16));
        fx_pt16 r = fx_xform2_apply(&m, on);
        /* fx_sin/fx_cos are within 1 ulp: the matrix entries and the sample
         * point are each off by at most d pixels' worth of ulps */
        int64_t tol = 3 * ((int64_t)d >> 16) + 3;
        FX_CHECK_MSG(llabs((int64_t)r.x - on.x) <= tol && llabs((int64_t)r.y - on.y) <= tol,
                     "on-line point moved by %lld,%lld (tol %lld)", (long long)r.x - on.x, (long long)r.y - on.y,
                     (long long)tol);
        fx_xform2 twice;
        fx_xform2_mul(&twice, &m, &m);
        for (int k = 0; k < 2; k++)
            FX_CHECK(llabs((int64_t)twice.m[k][k] - 65536) <= 3 && llabs((int64_t)twice.m[k][1 - k]) <= 3);
        fx_xform2 t1, rot, sx, rinv, t2, comp;
        fx_xform2_translation(&t1, px, py);
        fx_xform2_rotation(&rot, ang, 0, 0);
        fx_xform2_reflection(&sx, FX_REFLECT_X_AXIS);
        fx_xform2_rotation(&rinv, 0u - ang, 0, 0);
        fx_xform2_translation(&t2, -px, -py);
        fx_xform2_mul(&comp, &t1, &rot);
        fx_xform2_mul(&comp, &comp, &sx);
        fx_xform2_mul(&comp, &comp, &rinv);
        fx_xform2_mul(&comp, &comp, &t2);
        for (int k = 0; k < 2; k++)
            for (int j = 0; j < 2; j++)
                FX_CHECK(llabs((int64_t)comp.m[k][j] - m.m[k][j]) <= 4);
    }
}

FX_TEST(window_to_viewport)
{
    fx_xform2 m;
    FX_CHECK_EQ(fx_xform2_window_viewport(&m, 0, 0, I(10), I(5), I(100), I(50), I(200), I(100), 0), 0);
    fx_pt16 p = fx_xform2_apply(&m, P(0, 0));
    FX_CHECK(p.x == I(100) && p.y == I(50));
    p = fx_xform2_apply(&m, P(I(10), I(5)));
    FX_CHECK(p.x == I(200) && p.y == I(100));
    p = fx_xform2_apply(&m, P(I(5), F(2.5)));
    FX_CHECK(p.x == I(150) && p.y == I(75));
    /* a y-up world: wy0 > wy1 flips */
    fx_xform2_window_viewport(&m, I(-1), I(1), I(1), I(-1), 0, 0, I(64), I(64), 0);
    p = fx_xform2_apply(&m, P(F(0.5), F(0.5)));
    FX_CHECK(p.x == I(48) && p.y == I(16));
    /* aspect kept: a 2:1 window in a square viewport, centred */
    fx_xform2_window_viewport(&m, 0, 0, I(20), I(10), 0, 0, I(100), I(100), 1);
    p = fx_xform2_apply(&m, P(0, 0));
    FX_CHECK(p.x == 0 && p.y == I(25));
    p = fx_xform2_apply(&m, P(I(20), I(10)));
    FX_CHECK(p.x == I(100) && p.y == I(75));
    FX_CHECK_EQ(fx_xform2_window_viewport(&m, 0, 0, 0, I(1), 0, 0, I(1), I(1), 0), -FX_EINVAL);
}

FX_TEST(integer_points_saturate_and_round)
{
    fx_xform2 m;
    fx_xform2_scaling(&m, I(1000), I(1000), 0, 0);
    int32_t x, y;
    fx_xform2_apply_int(&m, INT32_MAX, INT32_MIN, &x, &y);
    FX_CHECK(x == INT32_MAX && y == INT32_MIN);
    fx_xform2_translation(&m, F(0.5), F(-0.5));
    fx_xform2_apply_int(&m, 3, 3, &x, &y);
    FX_CHECK(x == 4 && y == 3); /* ties toward +inf */
    fx_xform2_apply_int(&m, 2000000000, -2000000000, &x, &y);
    FX_CHECK(x == 2000000001 && y == -2000000000);
}

FX_TEST(rectangles_through_a_transform)
{
    enum { W = 64, H = 48 };
    canvas a = canvas_make(W, H), b = canvas_make(W, H);
    fx_ctx ca, cb;
    fx_ctx_init(&ca, &a.s);
    fx_ctx_init(&cb, &b.s);
    fx_xform2 m;
    /* a quarter turn about pixel centre (30, 20): the rotated rectangle's
     * pixels are exactly the rotated pixels */
    fx_xform2_rotation(&m, FX_ANGLE_90, I(30), I(20));
    ca.xform = &m;
    fx_xform_fill_rect(&ca, 32, 18, 12, 5); /* x 32..43, y 18..22 */
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            /* inverse: (x, y) = R(p) with p = (30 + (y - 20), 20 - (x - 30)) */
            int px = 30 + (y - 20), py = 20 - (x - 30);
            int want = px >= 32 && px < 44 && py >= 18 && py < 23;
            if ((a.mem[y * W + x] != 0) != want) {
                FX_CHECK_MSG(0, "pixel %d,%d", x, y);
                y = H;
                break;
            }
        }
    /* the identity and integer translations are fx_fill_rect exactly */
    memset(a.mem, 0, W * H * 4);
    fx_xform2_translation(&m, I(-7), I(5));
    fx_xform_fill_rect(&ca, 10, 3, 20, 9);
    fx_fill_rect(&cb, 3, 8, 20, 9);
    FX_CHECK(memcmp(a.mem, b.mem, W * H * 4) == 0);
    memset(a.mem, 0, W * H * 4);
    memset(b.mem, 0, W * H * 4);
    fx_xform_rect_outline(&ca, 10, 3, 20, 9);
    fx_rect_outline(&cb, 3, 8, 20, 9);
    FX_CHECK(memcmp(a.mem, b.mem, W * H * 4) == 0);
    int32_t x, y;
    fx_ctx_map(&ca, 1, 1, &x, &y);
    FX_CHECK(x == -6 && y == 6);
    FX_CHECK(fx_ctx_transformed(&ca));
    fx_xform2_identity(&m);
    FX_CHECK(!fx_ctx_transformed(&ca));
    free(a.mem);
    free(b.mem);
}
