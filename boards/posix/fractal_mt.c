/* SPDX-License-Identifier: MIT */
/* fixel — the tiled multithreaded escape-time renderer (see fractal_mt.h). */
#include "fixel/fractal_mt.h"

#include <errno.h>
#include <pthread.h>
#include <stdatomic.h>

#include "fixel/error.h"
#include "posix_int.h"

/* Bands this tall keep the per-band overhead (one walk set-up per row) tiny
 * while leaving dozens of bands per thread to even out the work: rows
 * through the set cost 256x more than rows outside it. */
#define BAND 8

typedef struct mt_job {
    const fx_surface *s;
    const fx_fractal_view *v;
    const fx_dwell_pal *pal;
    fx_rect r;
    atomic_int next;
    atomic_int err;
} mt_job;

static void *worker(void *arg)
{
    mt_job *j = arg;
    for (;;) {
        int b = atomic_fetch_add(&j->next, 1);
        int64_t y0 = (int64_t)j->r.y0 + (int64_t)b * BAND;
        if (y0 >= j->r.y1)
            return 0;
        fx_rect band = {j->r.x0, (int32_t)y0, j->r.x1,
                        (int32_t)(y0 + BAND < j->r.y1 ? y0 + BAND : j->r.y1)};
        int e = fx_fractal_render(j->s, band, j->v, j->pal);
        if (e < 0)
            atomic_store(&j->err, e);
    }
}

int fx_fractal_render_mt(const fx_surface *s, fx_rect r, const fx_fractal_view *v,
                         const fx_dwell_pal *pal, int nthreads)
{
    if (!s || !v || !pal || nthreads < 1 || nthreads > 64 || fx_fractal_check(v) < 0)
        return -FX_EINVAL;
    mt_job j = {.s = s, .v = v, .pal = pal};
    fx_rect fr = {0, 0, v->fw, v->fh};
    j.r = fx_rect_intersect(fx_rect_intersect(r, fr), fx_surface_rect(s));
    if (fx_rect_empty(j.r))
        return 0;
    atomic_init(&j.next, 0);
    atomic_init(&j.err, 0);
    int spawn_err = fx_posix_workers(worker, &j, nthreads);
    int e = atomic_load(&j.err);
    return e < 0 ? e : spawn_err;
}
