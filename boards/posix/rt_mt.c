/* SPDX-License-Identifier: MIT */
/* fixel — the ray tracer on several threads (see rt_mt.h). */
#include "fixel/rt_mt.h"

#include <pthread.h>
#include <stdatomic.h>
#include <unistd.h>

#include "fixel/error.h"
#include "posix_int.h"

typedef struct rt_job {
    const fx_rt_scene *s;
    const fx_surface *surf;
    int32_t x0, x1, y0, y1; /* the clipped rectangle */
    int32_t band;
    atomic_int next;
    fx_rt_rows_fn done;
    void *user;
    pthread_mutex_t lock;
} rt_job;

static void *worker(void *arg)
{
    rt_job *j = arg;
    for (;;) {
        int b = atomic_fetch_add(&j->next, 1);
        int64_t y0 = j->y0 + (int64_t)b * j->band;
        if (y0 >= j->y1)
            return 0;
        int32_t y1 = (int32_t)(y0 + j->band < j->y1 ? y0 + j->band : j->y1);
        fx_rt_render(j->s, j->surf, j->x0, (int32_t)y0, j->x1 - j->x0, y1 - (int32_t)y0);
        if (j->done) {
            pthread_mutex_lock(&j->lock);
            j->done(j->user, (int32_t)y0, y1);
            pthread_mutex_unlock(&j->lock);
        }
    }
}

static int32_t clamp32(int64_t v, int32_t lo, int32_t hi) { return v < lo ? lo : v > hi ? hi : (int32_t)v; }

int fx_rt_render_rect_mt(const fx_rt_scene *s, const fx_surface *surf, int32_t x, int32_t y, int32_t w, int32_t h,
                         int nthreads, int32_t band_rows, fx_rt_rows_fn done, void *user)
{
    if (!s || !surf || nthreads < 1 || nthreads > 64 || band_rows < 0)
        return -FX_EINVAL;
    if (surf->w <= 0 || surf->h <= 0 || w <= 0 || h <= 0)
        return 0;
    rt_job j = {.s = s, .surf = surf, .done = done, .user = user};
    j.x0 = clamp32(x, 0, surf->w);
    j.x1 = clamp32((int64_t)x + w, 0, surf->w);
    j.y0 = clamp32(y, 0, surf->h);
    j.y1 = clamp32((int64_t)y + h, 0, surf->h);
    if (j.x0 >= j.x1 || j.y0 >= j.y1)
        return 0;
    j.band = band_rows ? (band_rows < j.y1 - j.y0 ? band_rows : j.y1 - j.y0) : 4;
    atomic_init(&j.next, 0);
    pthread_mutex_init(&j.lock, 0);
    int spawn_err = fx_posix_workers(worker, &j, nthreads);
    pthread_mutex_destroy(&j.lock);
    return spawn_err;
}

int fx_rt_render_mt(const fx_rt_scene *s, const fx_surface *surf, int nthreads, int32_t band_rows,
                    fx_rt_rows_fn done, void *user)
{
    if (!s || !surf || nthreads < 1 || nthreads > 64 || band_rows < 0 || band_rows > (surf->h > 0 ? surf->h : 1))
        return -FX_EINVAL;
    return fx_rt_render_rect_mt(s, surf, 0, 0, surf->w, surf->h, nthreads, band_rows, done, user);
}

int fx_rt_cpu_count(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n < 1 ? 1 : n > 64 ? 64 : (int)n;
}
