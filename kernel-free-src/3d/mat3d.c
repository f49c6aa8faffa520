/* SPDX-License-Identifier: MIT */
/* fixel — 3D vectors, matrices, the matrix stack, the camera and the
 * projections (contracts in fixel/mat3d.h). */
#include "fixel/mat3d.h"
#include "fixel/error.h"
#include "../base/fx_internal.h"

static uint64_t uabs64(int64_t v) { return v < 0 ? 0 - (uint64_t)v : (uint64_t)v; }

/* Q32 (a sum of Q16 products) -> Q16, rounded to nearest, saturating. */
static fx16 q32_to_fx16(int64_t v)
{
    if (v > INT64_MAX - 0x8000)
        return FX16_MAX;
    return fx_sat32((v + 0x8000) >> 16);
}

fx_vec3 fx_vec3_add(fx_vec3 a, fx_vec3 b)
{
    return fx_vec3_make(fx_sat32((int64_t)a.x + b.x), fx_sat32((int64_t)a.y + b.y),
                        fx_sat32((int64_t)a.z + b.z));
}

fx_vec3 fx_vec3_sub(fx_vec3 a, fx_vec3 b)
{
    return fx_vec3_make(fx_sat32((int64_t)a.x - b.x), fx_sat32((int64_t)a.y - b.y),
                        fx_sat32((int64_t)a.z - b.z));
}

fx_vec3 fx_vec3_scale(fx_vec3 a, fx16 s)
{
    return fx_vec3_make(fx16_mul(a.x, s), fx16_mul(a.y, s), fx16_mul(a.z, s));
}

fx16 fx_vec3_dot(fx_vec3 a, fx_vec3 b)
{
    /* Three products of at most 2^62 each would overflow together; halve
     * them first (the rounding below puts the lost bit back exactly). */
    int64_t s = (((int64_t)a.x * b.x) >> 1) + (((int64_t)a.y * b.y) >> 1) + (((int64_t)a.z * b.z) >> 1);
    return fx_sat32((s + 0x4000) >> 15);
}

fx_vec3 fx_vec3_cross(fx_vec3 a, fx_vec3 b)
{
    return fx_vec3_make(q32_to_fx16((int64_t)a.y * b.z - (int64_t)a.z * b.y),
                        q32_to_fx16((int64_t)a.z * b.x - (int64_t)a.x * b.z),
                        q32_to_fx16((int64_t)a.x * b.y - (int64_t)a.y * b.x));
}

fx16 fx_vec3_length(fx_vec3 a)
{
    uint64_t s = uabs64(a.x) * uabs64(a.x) + uabs64(a.y) * uabs64(a.y) + uabs64(a.z) * uabs64(a.z);
    uint32_t r = fx_isqrt64(s);
    return r > (uint32_t)FX16_MAX ? FX16_MAX : (fx16)r;
}

int fx_vec3_normalize(fx_vec3 *a)
{
    int64_t c[3] = {a->x, a->y, a->z};
    uint64_t m = FX_MAX(FX_MAX(uabs64(c[0]), uabs64(c[1])), uabs64(c[2]));
    if (m == 0)
        return -FX_EDOM;
    /* Bring the largest component into [2^29, 2^30): the length then has
     * 29+ significant bits whatever the vector's size, and the squares sum
     * below 2^62. */
    int sh = 0;
    if (m < ((uint64_t)1 << 29))
        while ((m << sh) < ((uint64_t)1 << 29))
            sh++;
    else
        while ((m >> -sh) >= ((uint64_t)1 << 30))
            sh--;
    uint64_t s = 0;
    for (int i = 0; i < 3; i++) {
        c[i] = sh >= 0 ? c[i] * ((int64_t)1 << sh) : c[i] >> -sh;
        s += (uint64_t)(c[i] * c[i]);
    }
    int64_t len = fx_isqrt64(s);
    fx16 *out[3] = {&a->x, &a->y, &a->z};
    for (int i = 0; i < 3; i++) {
        int64_t n = c[i] * FX16_ONE;
        *out[i] = (fx16)((n >= 0 ? n + len / 2 : n - len / 2) / len);
    }
    return 0;
}

void fx_mat4_identity(fx_mat4 *m)
{
    fx_memset(m, 0, sizeof *m);
    for (int i = 0; i < 4; i++)
        m->m[i][i] = FX16_ONE;
}

void fx_mat4_mul(fx_mat4 *r, const fx_mat4 *a, const fx_mat4 *b)
{
    fx_mat4 t;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            int64_t s = 0;
            for (int k = 0; k < 4; k++)
                s += ((int64_t)a->m[i][k] * b->m[k][j]) >> 2;
            t.m[i][j] = fx_sat32((s + 0x2000) >> 14);
        }
    *r = t;
}

fx_vec4 fx_mat4_apply(const fx_mat4 *m, fx_vec4 v)
{
    int32_t in[4] = {v.x, v.y, v.z, v.w}, out[4];
    for (int i = 0; i < 4; i++) {
        int64_t s = 0;
        for (int k = 0; k < 4; k++)
            s += ((int64_t)m->m[i][k] * in[k]) >> 2;
        out[i] = fx_sat32((s + 0x2000) >> 14);
    }
    fx_vec4 r = {out[0], out[1], out[2], out[3]};
    return r;
}

fx_vec4 fx_mat4_apply_point(const fx_mat4 *m, fx_vec3 p)
{
    fx_vec4 v = {p.x, p.y, p.z, FX16_ONE};
    return fx_mat4_apply(m, v);
}

fx_vec3 fx_mat4_apply_dir(const fx_mat4 *m, fx_vec3 d)
{
    fx_vec4 v = {d.x, d.y, d.z, 0};
    v = fx_mat4_apply(m, v);
    return fx_vec3_make(v.x, v.y, v.z);
}

void fx_mat4_transpose(fx_mat4 *r, const fx_mat4 *m)
{
    fx_mat4 t;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            t.m[i][j] = m->m[j][i];
    *r = t;
}

void fx_mat4_translate(fx_mat4 *m, fx16 x, fx16 y, fx16 z)
{
    fx_mat4_identity(m);
    m->m[0][3] = x;
    m->m[1][3] = y;
    m->m[2][3] = z;
}

void fx_mat4_scale(fx_mat4 *m, fx16 x, fx16 y, fx16 z)
{
    fx_mat4_identity(m);
    m->m[0][0] = x;
    m->m[1][1] = y;
    m->m[2][2] = z;
}

/* Rotation in the plane of axes i -> j (i turns toward j for positive a). */
static void rot_plane(fx_mat4 *m, int i, int j, fx_angle a)
{
    fx16 c = fx_cos(a), s = fx_sin(a);
    fx_mat4_identity(m);
    m->m[i][i] = c;
    m->m[j][j] = c;
    m->m[j][i] = s;
    m->m[i][j] = -s;
}

void fx_mat4_rotate_x(fx_mat4 *m, fx_angle a) { rot_plane(m, 1, 2, a); }
void fx_mat4_rotate_y(fx_mat4 *m, fx_angle a) { rot_plane(m, 2, 0, a); }
void fx_mat4_rotate_z(fx_mat4 *m, fx_angle a) { rot_plane(m, 0, 1, a); }

int fx_mat4_rotate(fx_mat4 *m, fx_angle a, fx_vec3 axis)
{
    fx_mat4_identity(m);
    if (fx_vec3_normalize(&axis) < 0)
        return -FX_EDOM;
    /* Q30 sine and cosine keep the t = 1 - c terms exact enough for small
     * angles, where 1 - c is tiny. */
    int64_t c = fx_cos30(a), s = fx_sin30(a), t = ((int64_t)1 << 30) - c;
    int64_t x = axis.x, y = axis.y, z = axis.z; /* Q16 */
    /* products: Q16*Q16*Q30 = Q62 would overflow; go through Q32 first. */
#define TQ(p, q) (((((p) * (q)) >> 2) * t) >> 28) /* Q32 */
#define SQ(p) (((p) * s) >> 14)                  /* Q32 */
    int64_t cq = c * 4;                            /* Q32 */
    int64_t e[3][3] = {
        {TQ(x, x) + cq, TQ(x, y) - SQ(z), TQ(x, z) + SQ(y)},
        {TQ(x, y) + SQ(z), TQ(y, y) + cq, TQ(y, z) - SQ(x)},
        {TQ(x, z) - SQ(y), TQ(y, z) + SQ(x), TQ(z, z) + cq},
    };
#undef TQ
#undef SQ
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            m->m[i][j] = q32_to_fx16(e[i][j]);
    return 0;
}

void fx_mat4_shear_z(fx_mat4 *m, fx16 a, fx16 b)
{
    fx_mat4_identity(m);
    m->m[0][2] = a;
    m->m[1][2] = b;
}

int fx_mat4_reflect(fx_mat4 *m, fx_vec3 n, fx16 d)
{
    fx_mat4_identity(m);
    if (fx_vec3_normalize(&n) < 0)
        return -FX_EDOM;
    fx16 v[3] = {n.x, n.y, n.z};
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++)
            m->m[i][j] = (i == j ? FX16_ONE : 0) - q32_to_fx16(2 * (int64_t)v[i] * v[j]);
        m->m[i][3] = q32_to_fx16(2 * (int64_t)d * v[i]);
    }
    return 0;
}

/* round(a * 2^32 / b) for the Q32.32 elimination: a 96-by-64-bit long
 * division, saturating. */
static int64_t div_q32(int64_t a, int64_t b)
{
    uint64_t ua = uabs64(a), ub = uabs64(b);
    int neg = (a < 0) != (b < 0);
    uint64_t hi = ua >> 32, lo = ua << 32;
    if (hi >= ub)
        return neg ? INT64_MIN : INT64_MAX;
    uint64_t q = 0, r = hi;
    for (int i = 63; i >= 0; i--) {
        uint64_t carry = r >> 63;
        r = (r << 1) | ((lo >> i) & 1);
        q <<= 1;
        if (carry || r >= ub) {
            r -= ub;
            q |= 1;
        }
    }
    if (r >= ub - r)
        q++;
    if (q > (uint64_t)INT64_MAX)
        return neg ? INT64_MIN : INT64_MAX;
    return neg ? -(int64_t)q : (int64_t)q;
}

int fx_mat4_invert(fx_mat4 *r, const fx_mat4 *m)
{
    int64_t a[4][8];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            a[i][j] = (int64_t)m->m[i][j] * 65536;
            a[i][j + 4] = i == j ? (int64_t)1 << 32 : 0;
        }
    for (int c = 0; c < 4; c++) {
        int p = c;
        for (int i = c + 1; i < 4; i++)
            if (uabs64(a[i][c]) > uabs64(a[p][c]))
                p = i;
        if (uabs64(a[p][c]) < ((uint64_t)1 << 8))
            return -FX_EDOM;
        if (p != c)
            for (int j = 0; j < 8; j++) {
                int64_t t = a[p][j];
                a[p][j] = a[c][j];
                a[c][j] = t;
            }
        int64_t piv = a[c][c];
        for (int j = 0; j < 8; j++)
            a[c][j] = div_q32(a[c][j], piv);
        for (int i = 0; i < 4; i++) {
            if (i == c || a[i][c] == 0)
                continue;
            int64_t f = a[i][c];
            for (int j = 0; j < 8; j++)
                a[i][j] -= fx_mul64_shift(f, a[c][j], 32);
        }
    }
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            int64_t v = a[i][j + 4];
            r->m[i][j] = v > INT64_MAX - 0x8000 ? FX16_MAX : fx_sat32((v + 0x8000) >> 16);
        }
    return 0;
}

/* ---- stack ---- */
int fx_mat_stack_init(fx_mat_stack *s, fx_mat4 *mem, int cap)
{
    if (!mem || cap < 1)
        return -FX_EINVAL;
    s->slot = mem;
    s->cap = cap;
    s->top = 0;
    fx_mat4_identity(&mem[0]);
    return 0;
}

int fx_mat_stack_push(fx_mat_stack *s)
{
    if (s->top + 1 >= s->cap)
        return -FX_ENOSPC;
    s->slot[s->top + 1] = s->slot[s->top];
    s->top++;
    return 0;
}

int fx_mat_stack_pop(fx_mat_stack *s)
{
    if (s->top == 0)
        return -FX_ERANGE;
    s->top--;
    return 0;
}

void fx_mat_stack_load(fx_mat_stack *s, const fx_mat4 *m) { s->slot[s->top] = *m; }

void fx_mat_stack_mult(fx_mat_stack *s, const fx_mat4 *m)
{
    fx_mat4_mul(&s->slot[s->top], &s->slot[s->top], m);
}

/* ---- camera ---- */
static void cam_orthonormalise(fx_camera *c)
{
    fx_vec3_normalize(&c->n);
    c->u = fx_vec3_cross(c->v, c->n);
    fx_vec3_normalize(&c->u);
    c->v = fx_vec3_cross(c->n, c->u);
    fx_vec3_normalize(&c->v);
}

int fx_camera_set(fx_camera *c, fx_vec3 eye, fx_vec3 look, fx_vec3 up)
{
    fx_vec3 n = fx_vec3_sub(eye, look);
    if (fx_vec3_normalize(&n) < 0)
        return -FX_EDOM;
    fx_vec3 u = fx_vec3_cross(up, n);
    if (fx_vec3_normalize(&u) < 0)
        return -FX_EDOM;
    c->eye = eye;
    c->n = n;
    c->u = u;
    c->v = fx_vec3_cross(n, u);
    fx_vec3_normalize(&c->v);
    return 0;
}

void fx_camera_slide(fx_camera *c, fx16 du, fx16 dv, fx16 dn)
{
    c->eye = fx_vec3_add(c->eye, fx_vec3_scale(c->u, du));
    c->eye = fx_vec3_add(c->eye, fx_vec3_scale(c->v, dv));
    c->eye = fx_vec3_add(c->eye, fx_vec3_scale(c->n, dn));
}

/* a' = cos a + sin b, b' = cos b - sin a: turns a toward b. */
static void turn(fx_vec3 *a, fx_vec3 *b, fx_angle ang)
{
    fx16 cs = fx_cos(ang), sn = fx_sin(ang);
    fx_vec3 na = fx_vec3_add(fx_vec3_scale(*a, cs), fx_vec3_scale(*b, sn));
    fx_vec3 nb = fx_vec3_sub(fx_vec3_scale(*b, cs), fx_vec3_scale(*a, sn));
    *a = na;
    *b = nb;
}

void fx_camera_roll(fx_camera *c, fx_angle a)
{
    turn(&c->u, &c->v, a);
    cam_orthonormalise(c);
}

void fx_camera_pitch(fx_camera *c, fx_angle a)
{
    /* The view direction -n turns toward v: v turns toward n. */
    turn(&c->v, &c->n, a);
    cam_orthonormalise(c);
}

void fx_camera_yaw(fx_camera *c, fx_angle a)
{
    /* The view direction -n turns toward -u: n turns toward u. */
    turn(&c->n, &c->u, a);
    cam_orthonormalise(c);
}

void fx_camera_view(const fx_camera *c, fx_mat4 *m)
{
    const fx_vec3 *ax[3] = {&c->u, &c->v, &c->n};
    fx_mat4_identity(m);
    for (int i = 0; i < 3; i++) {
        m->m[i][0] = ax[i]->x;
        m->m[i][1] = ax[i]->y;
        m->m[i][2] = ax[i]->z;
        int64_t d = (int64_t)ax[i]->x * c->eye.x + (int64_t)ax[i]->y * c->eye.y +
                    (int64_t)ax[i]->z * c->eye.z;
        m->m[i][3] = q32_to_fx16(-d);
    }
}

/* ---- projections ---- */
static fx16 ratio64(int64_t num, int64_t den)
{
    /* num/den rounded to nearest, saturating; den != 0. */
    uint64_t un = uabs64(num), ud = uabs64(den);
    uint64_t q = (un + ud / 2) / ud;
    int neg = (num < 0) != (den < 0);
    if (q > (uint64_t)INT32_MAX)
        return neg ? FX16_MIN : FX16_MAX;
    return neg ? -(fx16)q : (fx16)q;
}

int fx_mat4_perspective(fx_mat4 *m, fx_angle fovy, fx16 aspect, fx16 zn, fx16 zf)
{
    if (zn <= 0 || zf <= zn || aspect <= 0 || fovy == 0 || fovy >= FX_ANGLE_180)
        return -FX_EINVAL;
    int64_t c = fx_cos30(fovy / 2), s = fx_sin30(fovy / 2);
    fx16 f = ratio64(c << 16, s); /* cot(fovy / 2) */
    fx_memset(m, 0, sizeof *m);
    m->m[0][0] = ratio64((int64_t)f << 16, aspect);
    m->m[1][1] = f;
    m->m[2][2] = ratio64(((int64_t)zf + zn) << 16, (int64_t)zn - zf);
    m->m[2][3] = ratio64(2 * (int64_t)zf * zn, (int64_t)zn - zf);
    m->m[3][2] = -FX16_ONE;
    return 0;
}

int fx_mat4_ortho(fx_mat4 *m, fx16 l, fx16 r, fx16 b, fx16 t, fx16 zn, fx16 zf)
{
    if (l == r || b == t || zn == zf)
        return -FX_EINVAL;
    int64_t w = (int64_t)r - l, h = (int64_t)t - b, d = (int64_t)zf - zn;
    fx_mat4_identity(m);
    m->m[0][0] = ratio64((int64_t)2 << 32, w);
    m->m[1][1] = ratio64((int64_t)2 << 32, h);
    m->m[2][2] = ratio64(-((int64_t)2 << 32), d);
    m->m[0][3] = ratio64(-((int64_t)r + l) * 65536, w);
    m->m[1][3] = ratio64(-((int64_t)t + b) * 65536, h);
    m->m[2][3] = ratio64(-((int64_t)zf + zn) * 65536, d);
    return 0;
}

int fx_mat4_oblique(fx_mat4 *m, fx16 l, fx16 r, fx16 b, fx16 t, fx16 zn, fx16 zf,
                    fx_angle alpha, fx16 len, fx16 plane)
{
    fx_mat4 o, h;
    int e = fx_mat4_ortho(&o, l, r, b, t, zn, zf);
    if (e < 0)
        return e;
    /* Depth beyond the projection plane is d = -z - plane; the point
     * slides by len * d along (cos alpha, sin alpha). */
    fx16 lc = fx16_mul(len, fx_cos(alpha)), ls = fx16_mul(len, fx_sin(alpha));
    fx_mat4_identity(&h);
    h.m[0][2] = -lc;
    h.m[1][2] = -ls;
    h.m[0][3] = -fx16_mul(lc, plane);
    h.m[1][3] = -fx16_mul(ls, plane);
    fx_mat4_mul(m, &o, &h);
    return 0;
}

int fx_mat4_pixel_aspect(fx_mat4 *m, int32_t num, int32_t den)
{
    if (num < 1 || den < 1 || num > 65536 || den > 65536)
        return -FX_EINVAL;
    for (int c = 0; c < 4; c++) {
        int64_t p = (int64_t)m->m[0][c] * num; /* below 2^48 */
        int64_t q = (p < 0 ? p - den / 2 : p + den / 2) / den;
        m->m[0][c] = fx_sat32(q);
    }
    return 0;
}
