/* SPDX-License-Identifier: MIT */
/* fixel — the Bresenham leaf: the seekable iterator, the exact step-range
 * clip both line iterators share (the axis ranges), and the walks that
 * write a clipped run of steps. It calls nothing above it: line.c (the
 * dispatcher), clip.c, stroke.c and dda.c build on it (see line_internal.h). */
#include "fixel/line.h"
#include "../base/fx_internal.h"
#include "line_internal.h"

void fx_bres_init(fx_bres *b, int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
    FX_LINE_AXES_INIT(b, x0, y0, x1, y1);
    fx_bres_seek(b, 0);
}

uint32_t fx_bres_minor_at(const fx_bres *b, uint32_t k)
{
    if (!b->major)
        return 0;
    uint64_t t = (uint64_t)k * b->minor; /* < 2^64: k, minor <= major < 2^32 */
    uint64_t q = t / b->major, r = t % b->major;
    return (uint32_t)(q + (2 * r >= b->major));
}

void fx_bres_seek(fx_bres *b, uint32_t k)
{
    int64_t m = 0, p = 2 * (int64_t)b->minor - b->major;
    if (b->major && k) { /* step 0 (every line's start) needs no division */
        uint64_t t = (uint64_t)k * b->minor;
        uint64_t q = t / b->major, r = t % b->major;
        int64_t rr = (int64_t)r;
        m = (int64_t)q;
        if (2 * r >= b->major) {
            m++;
            rr -= b->major;
        }
        /* p_k = 2*minor*(k+1) - major - 2*major*m_k, rewritten through the
         * remainder so no intermediate exceeds 2^35. */
        p = 2 * (int64_t)b->minor + 2 * rr - b->major;
    }
    int64_t a = (int64_t)k, mm = m;
    if (b->ymajor) {
        b->x = (int32_t)(b->x0 + b->sx * mm);
        b->y = (int32_t)(b->y0 + b->sy * a);
    } else {
        b->x = (int32_t)(b->x0 + b->sx * a);
        b->y = (int32_t)(b->y0 + b->sy * mm);
    }
    b->k = k;
    b->p = p;
}

/* Smallest k in [0, major] with minor_at(k) >= m (minor_at is non-decreasing). */
static uint32_t first_k_with_minor(const fx_line_axes *g, uint32_t m)
{
    uint32_t lo = 0, hi = g->major;
    while (lo < hi) {
        uint32_t mid = lo + (hi - lo) / 2;
        if (g->minor_at(g->it, mid) >= m)
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}

/* The steps k whose coordinate start + s*k lies in [lo, hi], as [*a, *b]. */
static int axis_range(int32_t start, int32_t s, int64_t lo, int64_t hi, int64_t *a, int64_t *b)
{
    if (s > 0) {
        *a = lo - start;
        *b = hi - start;
    } else if (s < 0) {
        *a = start - hi;
        *b = start - lo;
    } else {
        if (start < lo || start > hi)
            return 0;
        *a = INT64_MIN;
        *b = INT64_MAX;
    }
    return *a <= *b;
}

int fx_line_axes_clip(const fx_line_axes *g, fx_rect clip, uint32_t *k0, uint32_t *k1)
{
    if (fx_rect_empty(clip))
        return 0;
    int64_t lo = 0, hi = g->major, a0, a1, m0, m1;
    int32_t ma_start = g->ymajor ? g->y0 : g->x0, ma_s = g->ymajor ? g->sy : g->sx;
    int32_t mi_start = g->ymajor ? g->x0 : g->y0, mi_s = g->ymajor ? g->sx : g->sy;
    int64_t ma_lo = g->ymajor ? clip.y0 : clip.x0, ma_hi = (g->ymajor ? clip.y1 : clip.x1) - 1;
    int64_t mi_lo = g->ymajor ? clip.x0 : clip.y0, mi_hi = (g->ymajor ? clip.x1 : clip.y1) - 1;
    if (!axis_range(ma_start, ma_s, ma_lo, ma_hi, &a0, &a1))
        return 0;
    lo = FX_MAX(lo, a0);
    hi = FX_MIN(hi, a1);
    if (lo > hi)
        return 0;
    /* The minor axis gives a range of offsets m; turn it into steps. */
    if (!axis_range(mi_start, mi_s, mi_lo, mi_hi, &m0, &m1))
        return 0;
    if (mi_s != 0) {
        if (m1 < 0 || m0 > g->minor)
            return 0;
        if (m0 > 0)
            lo = FX_MAX(lo, (int64_t)first_k_with_minor(g, (uint32_t)m0));
        if (m1 < g->minor)
            hi = FX_MIN(hi, (int64_t)first_k_with_minor(g, (uint32_t)m1 + 1) - 1);
    }
    if (lo > hi)
        return 0;
    *k0 = (uint32_t)lo;
    *k1 = (uint32_t)hi;
    return 1;
}

static uint32_t bres_minor_at(const void *b, uint32_t k) { return fx_bres_minor_at(b, k); }

int fx_bres_clip(const fx_bres *b, fx_rect clip, uint32_t *k0, uint32_t *k1)
{
    fx_line_axes g = {b->x0, b->y0, b->sx, b->sy, b->major, b->minor, b->ymajor, bres_minor_at, b};
    return fx_line_axes_clip(&g, clip, k0, k1);
}

/* ---- the fast walk: a DDA whose minor coordinate is exactly Bresenham's ----
 * Bresenham's error branch is taken in a slope-dependent pattern that the
 * branch predictor cannot learn for arbitrary slopes, and its error term is
 * a loop-carried dependency. Here the minor offset of step k is computed on
 * its own as m_k = floor(acc_k / 2^32) with acc_k = k*S + 2^31 and
 * S = ceil(minor * 2^32 / major): no branch, and the steps of an unrolled
 * loop are independent.
 *
 * Why it equals fx_bres_minor_at(k) = floor(X_k), X_k = k*minor/major + 1/2:
 * write S = minor*2^32/major + eps with 0 <= eps < 1; then
 * acc_k / 2^32 = X_k + k*eps/2^32. X_k is a multiple of 1/(2*major), so its
 * fractional part is at most 1 - 1/(2*major) (ties, fraction 0, stay put:
 * the error is never negative). The floor is unchanged as long as
 * k*eps/2^32 < 1/(2*major), which holds for every k <= major when
 * 2*major^2 < 2^32, i.e. major <= 46340 (2*46340^2 = 4294635200).
 * Longer lines (only huge clipped ones: a visible piece is at most a few
 * thousand steps) take the Bresenham walk.
 *
 * A walk starting at step k0 keeps only the fraction of acc_k0: adding a
 * multiple of 2^32 shifts every floor by the same integer, so
 * floor((frac + j*S) / 2^32) = m_{k0+j} - m_{k0}, the offset from the pixel
 * fx_bres_seek found. */
#define FX_DDA_WALK_MAX 46340u

#define FX_POS(i) ((ptrdiff_t)(i))
#define FX_NEG(i) (-(ptrdiff_t)(i))

/* y-major: row j of the walk is base + j*st; its column moves by
 * SX(m_j) pixels. Byte offsets (not pointers) run ahead of the last pixel
 * so no pointer is ever formed outside the surface. */
#define FX_DDA_YMAJOR(T, SX)                                                                \
    do {                                                                                    \
        ptrdiff_t o = 0, st2 = 2 * st, st3 = 3 * st, st4 = 4 * st;                          \
        for (; n >= 4; n -= 4, o += st4, a += S4) {                                         \
            ((T *)(void *)(base + o))[SX(a >> 32)] = (T)v;                                  \
            ((T *)(void *)(base + o + st))[SX((a + S) >> 32)] = (T)v;                       \
            ((T *)(void *)(base + o + st2))[SX((a + S2) >> 32)] = (T)v;                     \
            ((T *)(void *)(base + o + st3))[SX((a + S3) >> 32)] = (T)v;                     \
        }                                                                                   \
        for (; n > 0; n--, o += st, a += S)                                                 \
            ((T *)(void *)(base + o))[SX(a >> 32)] = (T)v;                                  \
    } while (0)

/* x-major: pixel j is SX(j) pixels along the row of step k0, m_j rows down
 * (st is signed). */
#define FX_DDA_XMAJOR(T, SX)                                                                \
    do {                                                                                    \
        ptrdiff_t o = 0;                                                                    \
        for (; n >= 4; n -= 4, o += SX(4 * sizeof(T)), a += S4) {                          \
            *(T *)(void *)(base + o + (ptrdiff_t)(a >> 32) * st) = (T)v;                    \
            *(T *)(void *)(base + o + SX(sizeof(T)) + (ptrdiff_t)((a + S) >> 32) * st) =    \
                (T)v;                                                                       \
            *(T *)(void *)(base + o + SX(2 * sizeof(T)) + (ptrdiff_t)((a + S2) >> 32) * st) = \
                (T)v;                                                                       \
            *(T *)(void *)(base + o + SX(3 * sizeof(T)) + (ptrdiff_t)((a + S3) >> 32) * st) = \
                (T)v;                                                                       \
        }                                                                                   \
        for (; n > 0; n--, o += SX(sizeof(T)), a += S)                                      \
            *(T *)(void *)(base + o + (ptrdiff_t)(a >> 32) * st) = (T)v;                    \
    } while (0)

#define FX_DDA_WALK(T)                                 \
    do {                                               \
        if (b->ymajor) {                               \
            if (b->sx >= 0)                            \
                FX_DDA_YMAJOR(T, FX_POS);              \
            else                                       \
                FX_DDA_YMAJOR(T, FX_NEG);              \
        } else {                                       \
            if (b->sx >= 0)                            \
                FX_DDA_XMAJOR(T, FX_POS);              \
            else                                       \
                FX_DDA_XMAJOR(T, FX_NEG);              \
        }                                              \
    } while (0)

/* ---- x-major lines as horizontal runs ----
 * An x-major line whose major/minor ratio is at least 2 lights runs of at
 * least 2 pixels per row; a run is one or two wide stores instead of a
 * store per pixel. (From 2, not 4: W3's lines with 2-3 pixels a row ran
 * 10-15 % faster as runs once the row loops below were specialised, and
 * ratio 3 alone gained nothing; lines of 1-2 pixels a row stay with the
 * DDA, where two stores a row would outnumber the pixels.)
 *
 * Row m (1 <= m <= minor) starts at the first step whose minor offset
 * reaches m: m_k >= m <=> 2k*minor + major >= 2m*major, so
 * k_m = ceil(T_m), T_m = (2m - 1)*major / (2*minor). T_m is a multiple of
 * 1/(2*minor), hence k_m = floor(U_m) with U_m = T_m + 1 - 1/(2*minor),
 * again a multiple of 1/(2*minor) (fraction at most 1 - 1/(2*minor)).
 * With R = ceil(major*2^32/minor) and C = ceil((2*minor - 1 - major)*2^32 /
 * (2*minor)), m*R + C = U_m*2^32 + e, 0 <= e < m + 1 <= minor + 1, so
 * floor((m*R + C) / 2^32) = k_m while (minor + 1)*2*minor <= 2^32, true for
 * every minor < major <= FX_DDA_WALK_MAX. At m = minor + 1 (past the last
 * row) the value only overestimates, so it is > k_minor, which is all the
 * loop below asks of it. Interior rows (0 < m < minor) hold q =
 * floor(major/minor) or q + 1 pixels of B bytes; with W the largest power
 * of two <= q*B, q*B < 2W, so (q + 1)*B <= 2W (both are multiples of B)
 * and one W-byte store at each end of a row covers it exactly. Rows of 32
 * bytes or more take 16-byte stores across them instead. The first and
 * last rows (and rows cut by the clip) are filled as plain runs. */
#define FX_RUNS_MIN_RATIO 2u

static void fill_run(uint8_t *lo, uint32_t len, uint32_t v, unsigned bytes)
{
    if (bytes == 4)
        fx_run32((uint32_t *)(void *)lo, (int32_t)len, v);
    else if (bytes == 2)
        fx_run16((uint16_t *)(void *)lo, (int32_t)len, (uint16_t)v);
    else
        fx_memset(lo, (int)(v & 0xFF), len);
}

/* The lowest address of steps [ka, kb) on the row whose step-k0 column is
 * at address rowa. The row moves as an integer, not a pointer, so that no
 * pointer is formed past the last row drawn (undefined behaviour in C). */
#define FX_RUN_LO(ka, kb)                                                                   \
    ((uint8_t *)rowa +                                                                      \
     (b->sx > 0 ? (ptrdiff_t)((ka) - k0) : (ptrdiff_t)k0 + 1 - (ptrdiff_t)(kb)) * (ptrdiff_t)bytes)

/* Whole interior rows of B-byte pixels, the line running left when NEGX:
 * row [k, kn) is one W-byte store at each end, or for W = 32 (rows of 32
 * bytes or more) 16-byte stores across it. B, W and NEGX are constants, so
 * each loop is a handful of instructions a row with everything in
 * registers (a generic loop that read b->sx and multiplied by the pixel
 * size on every row cost more than the stores it saved). */
#define FX_RUN_ROWS(B, W, NEGX)                                                                      \
    for (; (kn = (uint32_t)(acc >> 32)) <= kend; acc += R, k = kn, rowa += (uintptr_t)st) {          \
        ptrdiff_t a_ = (ptrdiff_t)(k - k0) * (B), e_ = (ptrdiff_t)(kn - k0) * (B);                   \
        uint8_t *rp_ = (uint8_t *)rowa;                                                              \
        uint8_t *lo = (NEGX) ? rp_ + (B)-e_ : rp_ + a_, *end = (NEGX) ? rp_ + (B)-a_ : rp_ + e_;     \
        if ((W) == 32) {                                                                             \
            for (; lo < end - 16; lo += 16)                                                          \
                fx_memcpy(lo, &q, 16);                                                               \
            fx_memcpy(end - 16, &q, 16);                                                             \
        } else {                                                                                     \
            fx_memcpy(lo, &q, (W) > 16 ? 16 : (W));                                                  \
            fx_memcpy(end - (W), &q, (W) > 16 ? 16 : (W));                                           \
        }                                                                                            \
    }

#define FX_RUN_ROWS_DIR(B, W)             \
    do {                                  \
        if (b->sx > 0)                    \
            FX_RUN_ROWS(B, W, 0)          \
        else                              \
            FX_RUN_ROWS(B, W, 1)          \
    } while (0)

/* Rows long enough for rep stos on x86-64 (fx_run32) go to fill_run. */
#ifdef FX_STOS_MIN_BYTES
#define FX_RUN_STOS_BYTES FX_STOS_MIN_BYTES
#else
#define FX_RUN_STOS_BYTES UINT32_MAX
#endif

/* W: the widest store that fits the shortest interior row (w bytes); a
 * width below the pixel size never occurs (w >= 2 pixels), the (B) tests
 * only keep such loops from being compiled. */
#define FX_RUN_ROWS_B(B)                                                                          \
    do {                                                                                          \
        if (w >= FX_RUN_STOS_BYTES)                                                               \
            for (; (kn = (uint32_t)(acc >> 32)) <= kend; acc += R, k = kn, rowa += (uintptr_t)st) \
                fill_run(FX_RUN_LO(k, kn), kn - k, v, bytes);                                     \
        else if (w >= 32)                                                                         \
            FX_RUN_ROWS_DIR(B, 32);                                                               \
        else if (w >= 16)                                                                         \
            FX_RUN_ROWS_DIR(B, 16);                                                               \
        else if (w >= 8 || (B) == 4)                                                              \
            FX_RUN_ROWS_DIR(B, 8);                                                                \
        else if (w >= 4 || (B) == 2)                                                              \
            FX_RUN_ROWS_DIR(B, 4);                                                                \
        else                                                                                      \
            FX_RUN_ROWS_DIR(B, 2);                                                                \
    } while (0)

/* Steps [k0, k0 + n) of an x-major line with minor >= 1 and
 * major >= FX_RUNS_MIN_RATIO * minor; S is the slope of walk_dda. */
static void walk_runs(const fx_ctx *c, const fx_bres *b, uint32_t k0, uint32_t n, unsigned bytes,
                      uint64_t S)
{
    uint32_t major = b->major, minor = b->minor, k1 = k0 + (n - 1);
    uint32_t M = (uint32_t)(((uint64_t)k0 * S + (1u << 31)) >> 32); /* the row of step k0 */
    ptrdiff_t st = b->sy * (ptrdiff_t)c->surf.stride;
    uintptr_t rowa = (uintptr_t)(fx_row(&c->surf, b->y) + (ptrdiff_t)b->x * (ptrdiff_t)bytes);
    uint32_t v = c->native, k = k0;
    if (M == minor) {
        fill_run(FX_RUN_LO(k0, k1 + 1), n, v, bytes);
        return;
    }
    uint64_t R = (((uint64_t)major << 32) + minor - 1) / minor;
    int64_t num = ((int64_t)2 * minor - 1 - (int64_t)major) * ((int64_t)1 << 32), d = 2 * (int64_t)minor;
    uint64_t C = (uint64_t)(num >= 0 ? (num + d - 1) / d : -(-num / d)); /* mod 2^64 */
    uint64_t acc = (uint64_t)(M + 1) * R + C; /* k_{M+1} in the high half */
    uint32_t klast = (uint32_t)(((uint64_t)minor * R + C) >> 32);
    uint32_t kend = k1 < klast ? k1 + 1 : klast; /* rows ending by kend are whole interior rows */
    uint32_t kn = (uint32_t)(acc >> 32);
    if (kn > k1) {
        fill_run(FX_RUN_LO(k0, k1 + 1), n, v, bytes);
        return;
    }
    fill_run(FX_RUN_LO(k0, kn), kn - k0, v, bytes);
    k = kn;
    rowa += (uintptr_t)st;
    acc += R;
    uint32_t w = major / minor * bytes; /* bytes of the shortest interior row */
    uint32_t v32 = bytes == 4 ? v : bytes == 2 ? (v & 0xFFFFu) * 0x10001u : (v & 0xFFu) * 0x01010101u;
    fx_v4u32 q = {v32, v32, v32, v32};
    if (bytes == 4)
        FX_RUN_ROWS_B(4);
    else if (bytes == 2)
        FX_RUN_ROWS_B(2);
    else
        FX_RUN_ROWS_B(1);
    if (k <= k1)
        fill_run(FX_RUN_LO(k, k1 + 1), k1 + 1 - k, v, bytes);
}

/* Steps [k0, k0 + n) of b (seeked to k0, major <= FX_DDA_WALK_MAX), all
 * inside the clip, in native pixels of bytes 4, 2 or 1. */
static void walk_dda(const fx_ctx *c, const fx_bres *b, uint32_t n, unsigned bytes)
{
    uint64_t S = b->major ? (((uint64_t)b->minor << 32) + b->major - 1) / b->major : 0;
    uint64_t a = (uint32_t)((uint64_t)b->k * S + (1u << 31)); /* the fraction of acc_k0 */
    uint64_t S2 = 2 * S, S3 = 3 * S, S4 = 4 * S;
    ptrdiff_t st = b->sy * (ptrdiff_t)c->surf.stride; /* one step along y, in bytes */
    uint8_t *base = fx_row(&c->surf, b->y) + (ptrdiff_t)b->x * (ptrdiff_t)bytes;
    uint32_t v = c->native;
    if (!b->ymajor && b->minor && b->major / b->minor >= FX_RUNS_MIN_RATIO) {
        walk_runs(c, b, b->k, n, bytes, S);
        return;
    }
    if (bytes == 4)
        FX_DDA_WALK(uint32_t);
    else if (bytes == 2)
        FX_DDA_WALK(uint16_t);
    else
        FX_DDA_WALK(uint8_t);
}

/* fx_plot per step: traces, blending, exterior clipping, sub-byte formats. */
__attribute__((noinline)) static void walk_plot(const fx_ctx *c, fx_bres *b, uint32_t n)
{
    for (;;) {
        fx_plot(c, b->x, b->y);
        if (--n == 0)
            break;
        if (c->trace) {
            int64_t p = b->p;
            uint32_t k = b->k;
            fx_bres_step(b);
            fx_trace(c, "%-4u %-12lld (%d, %d)", k, (long long)p, b->x, b->y);
        } else {
            fx_bres_step(b);
        }
    }
}

/* The Bresenham walk for lines too long for the DDA: the pointer moves by
 * precomputed byte offsets, no per-pixel multiplies or checks. */
__attribute__((noinline)) static void walk_bres(const fx_ctx *c, const fx_bres *b, uint32_t n, unsigned bpp)
{
    ptrdiff_t bytes = (ptrdiff_t)(bpp / 8);
    ptrdiff_t step_x = b->sx * bytes, step_y = b->sy * (ptrdiff_t)c->surf.stride;
    ptrdiff_t step_major = b->ymajor ? step_y : step_x, step_minor = b->ymajor ? step_x : step_y;
    uint8_t *p = fx_row(&c->surf, b->y) + (ptrdiff_t)b->x * bytes;
    int64_t e = b->p, inc1 = 2 * (int64_t)b->minor, inc2 = inc1 - 2 * (int64_t)b->major;
    uint32_t v = c->native;
    FX_LINE_WALK_BPP(bpp, 1, fx_bres_err_step(&e, inc1, inc2), (void)0);
}

/* A dispatcher only, so that a plain line reaches walk_dda without the
 * register saves of the other walks (why that matters: fx_rect_fill_native). */
void fx_bres_walk(const fx_ctx *c, fx_bres *b, uint32_t k0, uint32_t k1)
{
    fx_bres_seek(b, k0);
    uint32_t n = k1 - k0 + 1;
    unsigned bpp = fx_format_table[c->surf.format].bits_per_pixel;
    if (c->trace || c->exterior || (c->blend == FX_BLEND_OVER && (c->color >> 24) != 255) ||
        bpp < 8 || bpp == 24)
        walk_plot(c, b, n);
    else if (b->major <= FX_DDA_WALK_MAX)
        walk_dda(c, b, n, bpp / 8);
    else
        walk_bres(c, b, n, bpp);
}

void fx_line_steps(const fx_ctx *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1, uint32_t k0,
                   uint32_t k1)
{
    fx_bres b;
    uint32_t c0, c1;
    fx_bres_init(&b, x0, y0, x1, y1);
    if (k1 > b.major)
        k1 = b.major;
    if (k0 > k1 || !fx_bres_clip(&b, c->clip, &c0, &c1))
        return;
    c0 = FX_MAX(c0, k0);
    c1 = FX_MIN(c1, k1);
    if (c0 <= c1)
        fx_bres_walk(c, &b, c0, c1);
}

void fx_line_steps_inside(const fx_ctx *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1,
                          uint32_t k0, uint32_t k1)
{
    fx_bres b;
    fx_bres_init(&b, x0, y0, x1, y1);
    if (k1 > b.major)
        k1 = b.major;
    if (k0 <= k1)
        fx_bres_walk(c, &b, k0, k1);
}

