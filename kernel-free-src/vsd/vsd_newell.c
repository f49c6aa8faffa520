/* SPDX-License-Identifier: MIT */
/* fixel — depth sorting with Newell's overlap tests and polygon splitting.
 *
 * Pieces are sorted by their farthest depth, farthest first. The piece P
 * at the head is drawn once no later piece Q whose depth range overlaps
 * P's could be hidden by it, which one of the course's tests shows:
 *   1. the depth ranges do not overlap      2. the screen boxes do not
 *   3. P lies behind Q's plane              4. Q lies in front of P's plane
 *   5. the projections do not overlap (a separating edge)
 * When all fail and the reversed 3 or 4 hold, Q moves ahead of P and is
 * marked; meeting a marked piece again means a cycle, broken by cutting P
 * with Q's plane (or Q with P's), the pieces going back into the sorted
 * list. */
#include "vsd_int.h"

static int64_t abs64(int64_t v) { return v < 0 ? -v : v; }

/* all vertices of f on the given side of q's plane (1 behind, 2 front),
 * within the rounding of the vertices */
static int all_on(const fx_vsd_scene *s, const vsd_frag *f, int32_t q, int side)
{
    return (fx_vsd_frag_sides(s, f, q) & (3 & ~side)) == 0;
}

/* Some edge of a (as a line) has all of b strictly outside a. */
static int separated_by(const vsd_frag *a, const vsd_frag *b, int32_t sg)
{
    for (int32_t i = 0; i < a->nv; i++) {
        int32_t j = (i + 1) % a->nv;
        int64_t dx = a->x[j] - a->x[i], dy = a->y[j] - a->y[i];
        int64_t margin = 2 * (abs64(dx) + abs64(dy));
        int out = 1;
        for (int32_t k = 0; k < b->nv && out; k++) {
            int64_t e = (dx * (b->y[k] - a->y[i]) - dy * (b->x[k] - a->x[i])) * sg;
            if (e >= -margin)
                out = 0;
        }
        if (out)
            return 1;
    }
    return 0;
}

static int32_t area_sign(const fx_vsd_scene *s, const vsd_frag *f)
{
    /* The polygon's screen orientation, from its (unoriented) back flag. */
    return s->poly[f->poly].back ? 1 : -1;
}

/* Can P, drawn before Q, be left there? (one of tests 1..5 holds) */
static int p_before_q_ok(const fx_vsd_scene *s, const vsd_frag *P, const vsd_frag *Q, int *which)
{
    if (P->z0 >= Q->z1) {
        *which = 1;
        return 1;
    }
    if (P->x1 + 2 < Q->x0 || Q->x1 + 2 < P->x0 || P->y1 + 2 < Q->y0 || Q->y1 + 2 < P->y0) {
        *which = 2;
        return 1;
    }
    if (all_on(s, P, Q->poly, 1)) {
        *which = 3;
        return 1;
    }
    if (all_on(s, Q, P->poly, 2)) {
        *which = 4;
        return 1;
    }
    if (separated_by(P, Q, area_sign(s, P)) || separated_by(Q, P, area_sign(s, Q))) {
        *which = 5;
        return 1;
    }
    return 0;
}

/* Put piece index fi into the sorted run list[from..n) by farthest depth. */
static void insert_sorted(const vsd_frag *fr, int32_t *list, int32_t from, int32_t *n, int32_t fi)
{
    int32_t j = *n;
    while (j > from && fr[list[j - 1]].z1 < fr[fi].z1) {
        list[j] = list[j - 1];
        j--;
    }
    list[j] = fi;
    (*n)++;
}

int fx_vsd_newell(const fx_vsd_scene *s, int32_t *ids, void *work, size_t bytes, const fx_ctx *c,
               fx_vsd_stats *st)
{
    vsd_frag *fr;
    int32_t *list;
    int32_t cap = fx_vsd_frag_work(s, work, bytes, &fr, &list);
    if (cap < 0)
        return cap;
    int32_t nf = 0, n = 0;
    for (int32_t p = 0; p < s->npoly; p++) {
        fx_vsd_frag_from_poly(s, p, &fr[nf]);
        insert_sorted(fr, list, 0, &n, nf++);
    }
    /* marks are generations: a piece is marked when moved since the last
     * piece was drawn */
    int32_t pos = 0, gen = 1, gmoves = 0;
    while (pos < n) {
        vsd_frag *P = &fr[list[pos]];
        int redo = 0;
        for (int32_t k = pos + 1; k < n && !redo; k++) {
            vsd_frag *Q = &fr[list[k]];
            int which;
            if (p_before_q_ok(s, P, Q, &which))
                continue;
            int reversed = all_on(s, Q, P->poly, 1) || all_on(s, P, Q->poly, 2);
            int straddle = fx_vsd_frag_sides(s, P, Q->poly) == 3 || fx_vsd_frag_sides(s, Q, P->poly) == 3;
            /* A marked Q met again is the course's sign of a cycle; it is
             * broken by a split when one of the two straddles the other's
             * plane. When neither does, the cycle (if any) runs through
             * other pieces, and Q may move again, a bounded number of
             * times. */
            if (reversed && (Q->mark != gen || (!straddle && gmoves < n))) {
                Q->mark = gen;
                gmoves++;
                int32_t qi = list[k];
                for (int32_t j = k; j > pos; j--)
                    list[j] = list[j - 1];
                list[pos] = qi;
                st->moves++;
                if (c)
                    fx_trace(c, "newell: polygon %d may hide %d: %d moves ahead", P->poly,
                             Q->poly, Q->poly);
                redo = 1;
                break;
            }
            /* a cycle (or mutual overlap): split one by the other's plane */
            int32_t victim = -1, cutter = -1, li = -1;
            if (fx_vsd_frag_sides(s, P, Q->poly) == 3)
                victim = list[pos], cutter = Q->poly, li = pos;
            else if (fx_vsd_frag_sides(s, Q, P->poly) == 3)
                victim = list[k], cutter = P->poly, li = k;
            /* Q keeps coming back ahead of P with neither straddling the
             * other: a cycle through further pieces, the ones moved ahead
             * (marked). Cut one of P, Q and those by the plane of another
             * whose screen box it shares and whose plane it straddles. */
            for (int32_t r = pos; r < n && victim < 0; r++) {
                const vsd_frag *R = &fr[list[r]];
                if (r != pos && R->mark != gen)
                    continue;
                for (int32_t u = pos; u < n && victim < 0; u++) {
                    const vsd_frag *U = &fr[list[u]];
                    if (u == r || (u != pos && U->mark != gen) || R->poly == U->poly)
                        continue;
                    if (R->x1 < U->x0 || U->x1 < R->x0 || R->y1 < U->y0 || U->y1 < R->y0)
                        continue;
                    if (fx_vsd_frag_sides(s, R, U->poly) == 3)
                        victim = list[r], cutter = U->poly, li = r;
                }
            }
            if (victim < 0) {
                if (c)
                    fx_trace(c, "newell: polygon %d left before %d unresolved", P->poly, Q->poly);
                st->unresolved++;
                continue;
            }
            if (nf >= cap)
                return -FX_ENOSPC;
            vsd_frag a, b;
            int e = fx_vsd_frag_split(s, &fr[victim], cutter, &a, &b);
            if (e == -FX_EDOM) {
                if (c)
                    fx_trace(c, "newell: polygon %d left before %d unresolved", P->poly, Q->poly);
                st->unresolved++;
                continue;
            }
            if (e < 0)
                return e;
            if (c)
                fx_trace(c, "newell: %s, polygon %d cut by the plane of %d",
                         reversed ? "cycle" : "overlap", fr[victim].poly, cutter);
            st->splits++;
            fr[victim] = a;
            fr[nf] = b;
            for (int32_t j = li; j + 1 < n; j++)
                list[j] = list[j + 1];
            n--;
            insert_sorted(fr, list, pos, &n, victim);
            insert_sorted(fr, list, pos, &n, nf++);
            redo = 1;
        }
        if (!redo) {
            if (c)
                fx_trace(c, "newell: draw polygon %d (piece %d)", P->poly, list[pos]);
            pos++;
            gen++;
            gmoves = 0;
        }
    }
    for (int32_t i = 0; i < n; i++)
        fx_vsd_frag_paint(s, &fr[list[i]], ids);
    st->frags = nf;
    return 0;
}
