/* SPDX-License-Identifier: MIT */
/* fixel's W9 on every core: the frame cut into bands of rows handed out
 * through an atomic counter (bands near the set cost far more than bands
 * outside it, so static halves would leave one core idle), each band drawn
 * by the public fx_fractal_render. fractal.h promises that tiles assemble
 * the identical picture, and the harness checks it like any peer.
 * Threads are created per frame, as a caller without a pool would do; that
 * cost is inside the timing. */
#include "bench.h"

#include <pthread.h>
#include <stdatomic.h>
#include <unistd.h>

#if __has_include(<fixel/fractal.h>)
#include <fixel/fractal.h>

#define BAND 8
#define MAX_THREADS 64

struct mt {
    fx_surface s;
    fx_fractal_view v;
    fx_dwell_pal pal;
    uint32_t lut[65];
    atomic_int next;
};
static struct mt M;

static void *mt_open(const struct target *t)
{
    if (t->fmt != FMT_XRGB8888 ||
        fx_surface_init(&M.s, t->pixels, BW, BH, t->stride, FX_FMT_XRGB8888) != 0)
        return NULL;
    return &M;
}
static void mt_close(void *ctx) { (void)ctx; }

static void *worker(void *arg)
{
    struct mt *m = arg;
    for (;;) {
        int b = atomic_fetch_add(&m->next, 1);
        if (b * BAND >= BH)
            return NULL;
        fx_rect r = {0, b * BAND, BW, b * BAND + BAND};
        fx_fractal_render(&m->s, r, &m->v, &m->pal);
    }
}

static void mt_w9(void *ctx, int n)
{
    struct mt *m = ctx;
    (void)n;
    long nt = sysconf(_SC_NPROCESSORS_ONLN);
    nt = nt < 1 ? 1 : nt > MAX_THREADS ? MAX_THREADS : nt;
    /* the same view and palette bench_mandel_w9 uses */
    fx_dwell_pal_w9(&m->pal, m->lut, FX_FMT_XRGB8888);
    m->v = fx_mandel_view(-(FX56_ONE / 2), 0, 3 * FX56_ONE, BW, BH, 256);
    atomic_store(&m->next, 0);
    pthread_t th[MAX_THREADS];
    long started = 0;
    for (long i = 1; i < nt; i++)
        if (pthread_create(&th[started], NULL, worker, m) == 0)
            started++;
    worker(m);
    for (long i = 0; i < started; i++)
        pthread_join(th[i], NULL);
}

const struct peer peer_fixel_mt = {
    .name = "fixel-mt",
    .fmt_mask = 1,
    .open = mt_open,
    .close = mt_close,
    .fn = {[W9_MANDEL] = mt_w9},
};
#else
const struct peer peer_fixel_mt = {.name = "fixel-mt"};
#endif
