/* SPDX-License-Identifier: MIT */
/* fixel — the ray tracer's scene: objects placed by affine transforms, CSG
 * trees over sorted hit lists, world bounding boxes that let a ray skip a
 * subtree, and the nearest hit over the scene.
 *
 * A hit list covers the whole line S + c t (every t, not only t > 0), with
 * whether the line starts inside the solid: combining two lists is then a
 * merge along t that keeps the running inside/outside state of each side
 * and emits a hit wherever the combined state changes (the notes' union,
 * intersection and difference). A traced ray's merges start at its tmin
 * (crossings behind it only set the starting state), so a ray that starts
 * inside a CSG solid (refraction) sees it exactly as one that starts
 * outside, and an overflowing list keeps the crossings ahead of the ray. */
#include "fixel/error.h"
#include "rt_int.h"
#include "../base/fx_internal.h"

#define ONE ((int64_t)FX16_ONE)
#define WORLD ((int64_t)FX_RT_WORLD * FX16_ONE)

void fx_rt_scene_init(fx_rt_scene *s, fx_rt_object *mem, int cap)
{
    __builtin_memset(s, 0, sizeof *s);
    s->obj = mem;
    s->cap = cap < 0 ? 0 : cap > 32767 ? 32767 : cap;
    s->max_depth = 4;
    s->cutoff = FX16_ONE / 256;
    fx_rt_set_camera(s, fx_vec3_make(0, 0, 5 * FX16_ONE), fx_vec3_make(0, 0, 0), fx_vec3_make(0, FX16_ONE, 0),
                     45 * FX16_ONE);
}

fx_rt_material fx_rt_material_make(fx_color ambient, fx_color diffuse, fx_color specular, int32_t shininess, fx16 kr,
                                   fx16 kt, fx16 ior)
{
    fx_rt_material m;
    __builtin_memset(&m, 0, sizeof m);
    m.ambient = fx3d_rgb_from_color(ambient);
    m.diffuse = fx3d_rgb_from_color(diffuse);
    m.specular = fx3d_rgb_from_color(specular);
    m.shininess = shininess;
    m.reflectivity = kr;
    m.transparency = kt;
    m.ior = ior;
    return m;
}

static int in_world(fx_vec3 p)
{
    return p.x >= -WORLD && p.x <= WORLD && p.y >= -WORLD && p.y <= WORLD && p.z >= -WORLD && p.z <= WORLD;
}

int fx_rt_set_camera(fx_rt_scene *s, fx_vec3 eye, fx_vec3 look, fx_vec3 up, fx16 fovy_deg)
{
    if (fovy_deg < FX16_ONE || fovy_deg > 179 * FX16_ONE || !in_world(eye))
        return -FX_EDOM;
    fx_camera c;
    int r = fx_camera_set(&c, eye, look, up);
    if (r < 0)
        return r;
    s->cam = c;
    fx_angle h = fx_angle_from_deg16(fovy_deg / 2);
    s->tan_half = fx16_div(fx_sin(h), fx_cos(h));
    return 0;
}

int fx_rt_add_light(fx_rt_scene *s, fx_vec3 pos, fx3d_rgb color, fx16 atten)
{
    if (s->nlights >= FX_RT_MAX_LIGHTS)
        return -FX_ENOSPC;
    if (!in_world(pos) || atten < 0 || atten > FX16_ONE)
        return -FX_EDOM;
    fx_rt_light *l = &s->light[s->nlights++];
    l->pos = pos;
    l->color = color;
    l->atten = atten;
    return s->nlights - 1;
}

/* The world box of the object box [lo, hi] placed by m (its eight corners),
 * checked against the scene-scale limit in 64 bits. */
static int world_box(const fx_mat4 *m, const int64_t lo[3], const int64_t hi[3], fx_rt_box *b)
{
    for (int i = 0; i < 3; i++)
        b->lo[i] = INT32_MAX, b->hi[i] = INT32_MIN;
    for (int k = 0; k < 8; k++) {
        const int64_t p[3] = {k & 1 ? hi[0] : lo[0], k & 2 ? hi[1] : lo[1], k & 4 ? hi[2] : lo[2]};
        for (int i = 0; i < 3; i++) {
            int64_t acc = (int64_t)m->m[i][0] * p[0] + (int64_t)m->m[i][1] * p[1] + (int64_t)m->m[i][2] * p[2] +
                          (int64_t)m->m[i][3] * ONE;
            acc >>= 16;
            if (acc < -WORLD || acc > WORLD)
                return -FX_ERANGE;
            if (acc - 4 < b->lo[i])
                b->lo[i] = (fx16)(acc - 4);
            if (acc + 4 > b->hi[i])
                b->hi[i] = (fx16)(acc + 4);
        }
    }
    return 0;
}

/* M^-1 of an object's placement, refused when singular or when it scales
 * an axis below 1/16 (the scene-scale limit). */
static int inverse(const fx_mat4 *m, fx_mat4 *inv)
{
    if (fx_mat4_invert(inv, m) < 0)
        return -FX_EDOM;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            if (inv->m[i][j] > 16 * FX16_ONE || inv->m[i][j] < -16 * FX16_ONE)
                return -FX_EDOM;
    return 0;
}

int fx_rt_add_mesh(fx_rt_scene *s, const fx_rt_mesh *mesh, const fx_mat4 *m, const fx_rt_material *mat)
{
    if (!mesh || !mesh->mesh || !mesh->node || mesh->nnodes < 1)
        return -FX_EINVAL;
    if (s->n >= s->cap)
        return -FX_ENOSPC;
    fx_mat4 inv;
    TRY(inverse(m, &inv));
    const fx_rt_bvh_node *root = &mesh->node[0];
    const int64_t lo[3] = {root->lo[0], root->lo[1], root->lo[2]}, hi[3] = {root->hi[0], root->hi[1], root->hi[2]};
    fx_rt_box b;
    TRY(world_box(m, lo, hi, &b));
    fx_rt_object *o = &s->obj[s->n];
    __builtin_memset(o, 0, sizeof *o);
    o->kind = FX_RT_MESH;
    o->top = 1;
    o->left = o->right = -1;
    o->taper = FX16_ONE;
    o->inv = inv;
    o->box = b;
    o->mesh = mesh;
    if (mat)
        o->mat = *mat;
    return s->n++;
}

int fx_rt_add_shape(fx_rt_scene *s, fx_rt_kind kind, fx16 taper, const fx_mat4 *m, const fx_rt_material *mat)
{
    if ((kind > FX_RT_CYLINDER && kind != FX_RT_TORUS) ||
        (kind == FX_RT_CYLINDER && (taper < 0 || taper > 2 * FX16_ONE)) ||
        (kind == FX_RT_TORUS && (taper < FX16_ONE / 16 || taper > FX16_ONE)))
        return -FX_EINVAL;
    if (s->n >= s->cap)
        return -FX_ENOSPC;
    fx_mat4 inv;
    TRY(inverse(m, &inv));
    fx_rt_box b;
    if (kind == FX_RT_PLANE) {
        for (int i = 0; i < 3; i++)
            b.lo[i] = (fx16)-WORLD, b.hi[i] = (fx16)WORLD;
    } else {
        int64_t r = kind == FX_RT_CYLINDER && taper > FX16_ONE ? taper : kind == FX_RT_TORUS ? ONE + taper : ONE;
        int64_t zlo = kind == FX_RT_CYLINDER || kind == FX_RT_SQUARE ? 0 : kind == FX_RT_TORUS ? -taper : -ONE;
        int64_t zhi = kind == FX_RT_SQUARE ? 0 : kind == FX_RT_TORUS ? taper : ONE;
        const int64_t lo[3] = {-r, -r, zlo}, hi[3] = {r, r, zhi};
        TRY(world_box(m, lo, hi, &b));
    }
    fx_rt_object *o = &s->obj[s->n];
    __builtin_memset(o, 0, sizeof *o);
    o->kind = (uint8_t)kind;
    o->top = 1;
    o->left = o->right = -1;
    o->taper = kind == FX_RT_CYLINDER || kind == FX_RT_TORUS ? taper : FX16_ONE;
    o->inv = inv;
    o->box = b;
    if (mat)
        o->mat = *mat;
    return s->n++;
}

static int depth_of(const fx_rt_scene *s, int i)
{
    const fx_rt_object *o = &s->obj[i];
    if (o->kind < FX_RT_UNION)
        return 1;
    int a = depth_of(s, o->left), b = depth_of(s, o->right);
    return 1 + (a > b ? a : b);
}

int fx_rt_add_csg(fx_rt_scene *s, fx_rt_kind op, int left, int right)
{
    if (op < FX_RT_UNION || op > FX_RT_DIFFERENCE || left < 0 || right < 0 || left >= s->n || right >= s->n ||
        left == right || !s->obj[left].top || !s->obj[right].top)
        return -FX_EINVAL;
    if (s->n >= s->cap)
        return -FX_ENOSPC;
    int da = depth_of(s, left), db = depth_of(s, right);
    if (1 + (da > db ? da : db) > FX_RT_MAX_DEPTH)
        return -FX_E2BIG;
    const fx_rt_box *a = &s->obj[left].box, *b = &s->obj[right].box;
    fx_rt_object *o = &s->obj[s->n];
    __builtin_memset(o, 0, sizeof *o);
    for (int i = 0; i < 3; i++) {
        if (op == FX_RT_UNION) {
            o->box.lo[i] = a->lo[i] < b->lo[i] ? a->lo[i] : b->lo[i];
            o->box.hi[i] = a->hi[i] > b->hi[i] ? a->hi[i] : b->hi[i];
        } else if (op == FX_RT_INTERSECTION) {
            o->box.lo[i] = a->lo[i] > b->lo[i] ? a->lo[i] : b->lo[i];
            o->box.hi[i] = a->hi[i] < b->hi[i] ? a->hi[i] : b->hi[i];
        } else {
            o->box.lo[i] = a->lo[i];
            o->box.hi[i] = a->hi[i];
        }
    }
    o->kind = (uint8_t)op;
    o->top = 1;
    o->left = (int16_t)left;
    o->right = (int16_t)right;
    s->obj[left].top = 0;
    s->obj[right].top = 0;
    return s->n++;
}

static int combine_state(int op, int a, int b)
{
    return op == FX_RT_UNION ? (a || b) : op == FX_RT_INTERSECTION ? (a && b) : (a && !b);
}

/* The notes' CSG merge: walk both sorted lists along t. Crossings at or
 * before tmin change the running state but are not emitted: the result
 * starts at tmin (inside0 is the state there), so when a long list
 * overflows, the crossings it keeps are the nearest ones *ahead* of the
 * ray, not those behind its origin. */
static void combine(int op, const fx_rt_hitlist *A, const fx_rt_hitlist *B, int64_t tmin, fx_rt_hitlist *out)
{
    int ina = A->inside0, inb = B->inside0, in = combine_state(op, ina, inb);
    out->n = 0;
    out->inside0 = (uint8_t)in;
    out->overflow = A->overflow | B->overflow;
    int i = 0, j = 0;
    while (i < A->n || j < B->n) {
        int fromA = j >= B->n || (i < A->n && A->h[i].t <= B->h[j].t);
        fx_rt_hit h = fromA ? A->h[i++] : B->h[j++];
        if (fromA)
            ina = h.entering;
        else
            inb = h.entering;
        int now = combine_state(op, ina, inb);
        if (now == in)
            continue;
        in = now;
        if (h.t <= tmin) {
            out->inside0 = (uint8_t)now;
            continue;
        }
        if (out->n >= FX_RT_MAX_HITS) {
            out->overflow = 1;
            break;
        }
        h.entering = (uint8_t)now;
        if (op == FX_RT_DIFFERENCE && !fromA)
            h.flip ^= 1;
        out->h[out->n++] = h;
    }
}

static void hits_rec(const fx_rt_scene *s, int i, fx_vec3 S, fx_vec3 c, int64_t tmin, fx_rt_hitlist *out)
{
    const fx_rt_object *o = &s->obj[i];
    out->n = 0;
    out->inside0 = 0;
    out->overflow = 0;
    /* a shape's own test costs no more than its box's: boxes are for
     * subtrees and meshes */
    if ((o->kind >= FX_RT_MESH) && !fx_rt_box_meets(&o->box, S, c))
        return;
    if (o->kind == FX_RT_MESH) {
        fx_rt_mesh_hits(o->mesh, i, fx_rt_xform(&o->inv, S, 1), fx_rt_xform_dir24(&o->inv, c), tmin, out);
        return;
    }
    if (o->kind < FX_RT_UNION) {
        fx_rt_leaf_hits(o, i, fx_rt_xform(&o->inv, S, 1), fx_rt_xform_dir24(&o->inv, c), out);
        return;
    }
    fx_rt_hitlist a, b;
    hits_rec(s, o->left, S, c, tmin, &a);
    /* an empty left side decides intersection and difference alone */
    if (!a.n && !a.inside0 && o->kind != FX_RT_UNION)
        return;
    hits_rec(s, o->right, S, c, tmin, &b);
    combine(o->kind, &a, &b, tmin, out);
}

void fx_rt_hits(const fx_rt_scene *s, int i, fx_vec3 S, fx_vec3 c, fx_rt_hitlist *out)
{
    if (i < 0 || i >= s->n) {
        out->n = 0;
        out->inside0 = out->overflow = 0;
        return;
    }
    hits_rec(s, i, S, c, INT64_MIN, out);
}

static fx_vec3 world_normal(const fx_rt_scene *s, const fx_rt_hit *h)
{
    fx_vec3 n = fx_rt_normal_to_world(&s->obj[h->obj].inv, h->normal);
    if (fx_vec3_normalize(&n) < 0)
        n = fx_vec3_make(0, 0, FX16_ONE);
    if (h->flip)
        n = fx_vec3_make(-n.x, -n.y, -n.z);
    return n;
}

int fx_rt_first_hit(const fx_rt_scene *s, fx_vec3 S, fx_vec3 c, fx16 tmin, fx_rt_hit *hit, fx_vec3 *n)
{
    int found = 0;
    for (int i = 0; i < s->n; i++) {
        if (!s->obj[i].top)
            continue;
        fx_rt_hitlist l;
        hits_rec(s, i, S, c, tmin, &l);
        for (int k = 0; k < l.n; k++) {
            const fx_rt_hit *h = &l.h[k];
            if (h->t <= tmin)
                continue;
            if (found && h->t >= hit->t)
                break;
            /* the world ends at the scene-scale limit: no ray starts beyond it */
            fx_vec3 p = fx_vec3_make(rt_sat(S.x + rt_mul(c.x, h->t)), rt_sat(S.y + rt_mul(c.y, h->t)),
                                     rt_sat(S.z + rt_mul(c.z, h->t)));
            if (!in_world(p))
                break;
            *hit = *h;
            found = 1;
            break;
        }
    }
    if (found && n)
        *n = world_normal(s, hit);
    return found;
}

fx16 fx_rt_feeler_transmit(const fx_rt_scene *s, fx_vec3 S, fx_vec3 c, fx16 tmin, fx16 tmax, int *blocker)
{
    fx16 T = FX16_ONE;
    int first = -1;
    fx16 tfirst = 0;
    for (int i = 0; i < s->n && T > 0; i++) {
        if (!s->obj[i].top)
            continue;
        fx_rt_hitlist l;
        hits_rec(s, i, S, c, tmin, &l);
        for (int k = 0; k < l.n; k++) {
            const fx_rt_hit *h = &l.h[k];
            if (h->t <= tmin)
                continue;
            if (h->t >= tmax)
                break;
            fx_vec3 p = fx_vec3_make(rt_sat(S.x + rt_mul(c.x, h->t)), rt_sat(S.y + rt_mul(c.y, h->t)),
                                     rt_sat(S.z + rt_mul(c.z, h->t)));
            if (!in_world(p))
                break;
            fx16 kt = s->obj[h->obj].mat.transparency;
            kt = kt < 0 ? 0 : kt > FX16_ONE ? FX16_ONE : kt;
            if (kt == 0 && (first < 0 || h->t < tfirst))
                first = h->obj, tfirst = h->t;
            T = fx16_mul(T, kt);
            if (T <= 0)
                break;
        }
    }
    *blocker = first;
    return T < 0 ? 0 : T;
}
