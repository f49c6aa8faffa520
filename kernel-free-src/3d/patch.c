/* SPDX-License-Identifier: MIT */
/* fixel — bicubic Bézier and uniform B-spline patches: evaluation and
 * tessellation (contracts in fixel/objects.h). */
#include "fixel/objects.h"
#include "fixel/error.h"
#include "objects_int.h"

#define LIM (1024 * FX16_ONE)

void fx_obj_bezier_basis(fx16 t, int64_t w[4], int64_t d[4])
{
    int64_t s = FX16_ONE - t;
    int64_t ss = (s * s) >> 16, tt = ((int64_t)t * t) >> 16, st = (s * t) >> 16;
    w[0] = (ss * s) >> 16;
    w[1] = 3 * ((ss * t) >> 16);
    w[2] = 3 * ((tt * s) >> 16);
    w[3] = (tt * t) >> 16;
    d[0] = -3 * ss;
    d[1] = 3 * ss - 6 * st;
    d[2] = 6 * st - 3 * tt;
    d[3] = 3 * tt;
}

/* Weights and derivatives in Q24, from Q32 polynomials (exact but for the
 * final rounding of each). */
static void basis24(fx_patch_basis b, fx16 t16, int64_t w[4], int64_t d[4])
{
    int64_t t = t16, s = FX16_ONE - t;
    int64_t t2 = t * t, s2 = s * s;              /* Q32 */
    int64_t t3 = (t2 * t) >> 16, s3 = (s2 * s) >> 16; /* Q32 */
    int64_t st = s * t, s2t = (s2 * t) >> 16, st2 = (t2 * s) >> 16;
    int64_t W[4], D[4];
    if (b == FX_PATCH_BEZIER) {
        W[0] = s3, W[1] = 3 * s2t, W[2] = 3 * st2, W[3] = t3;
        D[0] = -3 * s2, D[1] = 3 * s2 - 6 * st, D[2] = 6 * st - 3 * t2, D[3] = 3 * t2;
    } else {
        int64_t one = (int64_t)1 << 32;
        W[0] = s3 / 6;
        W[1] = (3 * t3 - 6 * t2 + 4 * one) / 6;
        W[2] = (-3 * t3 + 3 * t2 + 3 * (t << 16) + one) / 6;
        W[3] = t3 / 6;
        D[0] = -s2 / 2;
        D[1] = (3 * t2 - 4 * (t << 16)) / 2;
        D[2] = (-3 * t2 + 2 * (t << 16) + one) / 2;
        D[3] = t2 / 2;
    }
    for (int i = 0; i < 4; i++) {
        w[i] = (W[i] + 128) >> 8;
        d[i] = (D[i] + 128) >> 8;
    }
}

static fx16 round24(int64_t a) { return (fx16)((a + ((int64_t)1 << 23)) >> 24); }

static void eval3(const fx_vec3 P[16], fx_patch_basis basis, fx16 u, fx16 v, fx_vec3 *pt, fx_vec3 *du,
                  fx_vec3 *dv)
{
    int64_t wu[4], du_[4], wv[4], dv_[4];
    basis24(basis, u, wu, du_);
    basis24(basis, v, wv, dv_);
    int64_t acc[3][3] = {{0}};
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            const fx_vec3 *c = &P[i * 4 + j];
            int64_t k[3] = {(wu[i] * wv[j]) >> 24, (du_[i] * wv[j]) >> 24, (wu[i] * dv_[j]) >> 24};
            for (int q = 0; q < 3; q++) {
                acc[q][0] += k[q] * c->x;
                acc[q][1] += k[q] * c->y;
                acc[q][2] += k[q] * c->z;
            }
        }
    fx_vec3 *out[3] = {pt, du, dv};
    for (int q = 0; q < 3; q++)
        *out[q] = fx_vec3_make(round24(acc[q][0]), round24(acc[q][1]), round24(acc[q][2]));
}

static int normal_of(fx_vec3 a, fx_vec3 b, fx_vec3 *n)
{
    int64_t x = (int64_t)a.y * b.z - (int64_t)a.z * b.y, y = (int64_t)a.z * b.x - (int64_t)a.x * b.z,
            z = (int64_t)a.x * b.y - (int64_t)a.y * b.x;
    if (!x && !y && !z)
        return -FX_EDOM;
    *n = fx_obj_unit64(x, y, z);
    return 0;
}

static int points_ok(const fx_vec3 P[16])
{
    for (int i = 0; i < 16; i++)
        if (P[i].x < -LIM || P[i].x > LIM || P[i].y < -LIM || P[i].y > LIM || P[i].z < -LIM || P[i].z > LIM)
            return 0;
    return 1;
}

static fx16 inward(fx16 t)
{
    return t < FX16_ONE / 64 ? FX16_ONE / 64 : t > FX16_ONE - FX16_ONE / 64 ? FX16_ONE - FX16_ONE / 64 : t;
}

static int eval_checked(const fx_vec3 P[16], fx_patch_basis basis, fx16 u, fx16 v, fx_vec3 *pt, fx_vec3 *nrm)
{
    fx_vec3 p, du, dv;
    eval3(P, basis, u, v, &p, &du, &dv);
    if (pt)
        *pt = p;
    if (!nrm)
        return 0;
    if (normal_of(du, dv, nrm) == 0)
        return 0;
    /* A collapsed edge (the teapot's lid): the normal just inside. */
    eval3(P, basis, inward(u), inward(v), &p, &du, &dv);
    return normal_of(du, dv, nrm);
}

int fx_patch_eval(const fx_vec3 P[16], fx_patch_basis basis, fx16 u, fx16 v, fx_vec3 *pt, fx_vec3 *nrm)
{
    if (!P || (basis != FX_PATCH_BEZIER && basis != FX_PATCH_BSPLINE) || u < 0 || u > FX16_ONE || v < 0 ||
        v > FX16_ONE || !points_ok(P))
        return -FX_EINVAL;
    return eval_checked(P, basis, u, v, pt, nrm);
}

int fx_patch_tessellate(fx_mesh *m, const fx_vec3 P[16], fx_patch_basis basis, int32_t n)
{
    if (!m || !P || n < 1 || n > FX_MESH_MAX_SEG || (basis != FX_PATCH_BEZIER && basis != FX_PATCH_BSPLINE) ||
        !points_ok(P) || !m->pos || !m->nrm || !m->tri)
        return -FX_EINVAL;
    int64_t nv = (int64_t)(n + 1) * (n + 1), nt = 2 * (int64_t)n * n;
    if (m->nverts + nv > m->cap_verts || m->ntris + nt > m->cap_tris)
        return -FX_ENOSPC;
    int32_t base = m->nverts;
    for (int32_t i = 0; i <= n; i++)
        for (int32_t j = 0; j <= n; j++) {
            fx16 u = fx16_from_ratio(i, n), v = fx16_from_ratio(j, n);
            fx_vec3 p, nn;
            if (eval_checked(P, basis, u, v, &p, &nn) < 0) {
                m->nverts = base; /* as it was */
                return -FX_EDOM;
            }
            m->pos[m->nverts] = p;
            m->nrm[m->nverts] = nn;
            if (m->uv) {
                m->uv[2 * m->nverts] = u;
                m->uv[2 * m->nverts + 1] = v;
            }
            m->nverts++;
        }
    for (int32_t i = 0; i < n; i++)
        for (int32_t j = 0; j < n; j++) {
            uint32_t a = (uint32_t)(base + i * (n + 1) + j), b = a + (uint32_t)n + 1, c = b + 1, d = a + 1;
            uint32_t *t = &m->tri[3 * m->ntris];
            t[0] = a, t[1] = b, t[2] = c, t[3] = a, t[4] = c, t[5] = d;
            m->ntris += 2;
        }
    return 0;
}
