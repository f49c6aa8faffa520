/* SPDX-License-Identifier: MIT */
/* fixel — the BSP-tree method.
 *
 * Build: polygons are inserted in table order; the first becomes the
 * root, every later one walks down, going to the back child when it lies
 * behind the node's plane, to the front child when in front (or in the
 * plane), and is cut in two by the plane when it straddles it, each piece
 * continuing on its side. Draw: from the root, the subtree on the far side
 * of the node's plane from the eye, then the node, then the near subtree.
 * The viewer looks along +z from infinitely far away (screen space), so
 * the eye is on the side a x + b y + c z + d < 0 of every plane. */
#include "vsd_int.h"

/* The eye at z = -infinity: its side of plane q, as fx_vsd_frag_sides bits. */
static int eye_side(const fx_vsd_poly *q) { return q->c > 0 ? 2 : 1; }

static void trace_tree(const fx_vsd_scene *s, const vsd_frag *fr, int32_t root, int32_t *stack,
                       int32_t *deps, const fx_ctx *c)
{
    int32_t sp = 0;
    stack[sp] = root;
    deps[sp++] = 0;
    while (sp) {
        sp--;
        int32_t n = stack[sp], d = deps[sp];
        const vsd_frag *f = &fr[n];
        const fx_vsd_poly *P = &s->poly[f->poly];
        fx_trace(c, "bsp depth %d node %d: polygon %d plane %lldx + %lldy + %lldz + %lld, front %d back %d",
                 d, n, f->poly, (long long)P->a, (long long)P->b, (long long)P->c,
                 (long long)P->d, f->front, f->back);
        if (f->back >= 0) {
            stack[sp] = f->back;
            deps[sp++] = d + 1;
        }
        if (f->front >= 0) {
            stack[sp] = f->front;
            deps[sp++] = d + 1;
        }
    }
}

int fx_vsd_bsp(const fx_vsd_scene *s, int32_t *ids, void *work, size_t bytes, const fx_ctx *c,
            fx_vsd_stats *st)
{
    vsd_frag *fr;
    int32_t *stack;
    int32_t cap = fx_vsd_frag_work(s, work, bytes, &fr, &stack);
    if (cap < 0)
        return cap;
    int32_t *from = stack + cap;
    int32_t nf = 0, root = -1;
    for (int32_t p = 0; p < s->npoly; p++) {
        int32_t sp = 0;
        fx_vsd_frag_from_poly(s, p, &fr[nf]);
        stack[sp] = nf++;
        from[sp++] = root;
        while (sp) {
            sp--;
            int32_t f = stack[sp], node = from[sp], depth = 1;
            if (root < 0) {
                root = f;
                continue;
            }
            if (node < 0)
                node = root;
            for (;;) {
                int side = fx_vsd_frag_sides(s, &fr[f], fr[node].poly);
                depth++;
                if (side == 3) {
                    if (nf >= cap)
                        return -FX_ENOSPC;
                    vsd_frag a, b;
                    int e = fx_vsd_frag_split(s, &fr[f], fr[node].poly, &a, &b);
                    if (e == 0) {
                        st->splits++;
                        if (c)
                            fx_trace(c, "bsp: polygon %d cut by the plane of %d", fr[f].poly,
                                     fr[node].poly);
                        fr[f] = a;
                        fr[nf] = b;
                        stack[sp] = nf++;
                        from[sp++] = node; /* the front piece starts again here */
                        side = 1;
                    } else if (e == -FX_EDOM) {
                        side = 2;
                    } else {
                        return e;
                    }
                }
                int32_t *child = side == 1 ? &fr[node].back : &fr[node].front;
                if (*child < 0) {
                    *child = f;
                    break;
                }
                node = *child;
            }
            if (depth > st->depth)
                st->depth = depth;
        }
    }
    st->nodes = st->frags = nf;
    if (root < 0)
        return 0;
    if (c)
        trace_tree(s, fr, root, stack, from, c);
    /* back to front without recursion: a node is pushed twice, first to
     * descend into its far side, then (tagged negative) to be drawn before
     * its near side */
    int32_t sp = 0;
    stack[sp++] = root;
    while (sp) {
        int32_t v = stack[--sp];
        if (v < 0) {
            int32_t n = -v - 1;
            fx_vsd_frag_paint(s, &fr[n], ids);
            int32_t nearc = eye_side(&s->poly[fr[n].poly]) == 2 ? fr[n].front : fr[n].back;
            if (nearc >= 0)
                stack[sp++] = nearc;
            continue;
        }
        int32_t farc = eye_side(&s->poly[fr[v].poly]) == 2 ? fr[v].back : fr[v].front;
        stack[sp++] = -v - 1;
        if (farc >= 0)
            stack[sp++] = farc;
    }
    return 0;
}
