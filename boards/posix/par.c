/* SPDX-License-Identifier: MIT */
/* fixel — whole frames on several threads, in bands (see par.h). */
/* clock_gettime and CLOCK_THREAD_CPUTIME_ID are POSIX, hidden by a plain
 * -std=c11 (the kernel rig builds this file with one). */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include "fixel/par.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "fixel/error.h"
#include "fixel/rt.h"
#include "posix_int.h"

/* ---- drawing functions ---- */

typedef struct bands_job {
    const fx_ctx *c;
    int nbands;
    fx_par_draw_fn draw;
    void *user;
    atomic_int next;
} bands_job;

static fx_rect band_rect(fx_rect r, int k, int n)
{
    int64_t h = (int64_t)r.y1 - r.y0;
    fx_rect b = r;
    b.y0 = (int32_t)(r.y0 + h * k / n);
    b.y1 = (int32_t)(r.y0 + h * (k + 1) / n);
    return b;
}

static void *bands_worker(void *arg)
{
    bands_job *j = arg;
    for (;;) {
        int k = atomic_fetch_add(&j->next, 1);
        if (k >= j->nbands)
            return 0;
        fx_ctx c = *j->c;
        c.clip = band_rect(j->c->clip, k, j->nbands);
        if (!fx_rect_empty(c.clip))
            j->draw(j->user, &c, k);
    }
}

int fx_par_bands(const fx_ctx *c, int nbands, int nthreads, fx_par_draw_fn draw, void *user)
{
    if (!c || !draw || nthreads < 1 || nthreads > 64 || nbands < 0 || nbands > 1024)
        return -FX_EINVAL;
    bands_job j = {.c = c, .nbands = nbands ? nbands : nthreads, .draw = draw, .user = user};
    atomic_init(&j.next, 0);
    return fx_posix_workers(bands_worker, &j, nthreads < j.nbands ? nthreads : j.nbands);
}

static void *no_job(void *arg)
{
    (void)arg;
    return 0;
}

int fx_par_start(int nthreads)
{
    if (nthreads < 1 || nthreads > 64)
        return -FX_EINVAL;
    fx_posix_batch b;
    (void)fx_posix_pool_start(&b, no_job, 0, nthreads - 1); /* the count says it */
    int n = b.n + 1;
    fx_posix_pool_wait(&b);
    return n;
}

/* ---- scene scripts ---- */

typedef struct scene_job scene_job;

typedef struct band {
    scene_job *job;
    fx_scene *sc;
    int index;
    int rc;
    int64_t cpu_ns; /* the band's script run, CPU time of its thread */
} band;

struct scene_job {
    const char *text;
    size_t len;
    int n;
    band b[64];
    fx_scene_host host; /* the caller's */
    fx_scene_raytrace_fn raytrace;
    pthread_mutex_t host_lock; /* the host's functions, one call at a time */
    int have_surface;
    fx_surface surf;
    uint64_t key;      /* the script, size, format and band count (plan_key) */
    int32_t cut[65];   /* band k is rows [cut[k], cut[k + 1]) */
    /* files and images loaded for one band serve the others (a 48 MiB font
     * is read and unpacked once, not once per band) */
    struct loaded {
        char path[256];
        const uint8_t *data;
        size_t len;
        fx_surface img;
        int rc, image;
    } cache[32];
    int ncache;
    atomic_int next;
    /* the collective steps (the ray tracer): a barrier of the bands still
     * running the script */
    pthread_mutex_t lock;
    pthread_cond_t cond;
    int active, arrived, go;
    unsigned gen;
    /* the rectangle traced together */
    const fx_rt_scene *rt;
    int32_t rx0, rx1, ry0, ry1;
    atomic_int rt_next;
};

/* Wait until every band still running has arrived (bands that finished
 * their script, or failed, no longer count). */
static void barrier(scene_job *j)
{
    pthread_mutex_lock(&j->lock);
    unsigned gen = j->gen;
    if (++j->arrived >= j->active) {
        j->arrived = 0;
        j->gen++;
        pthread_cond_broadcast(&j->cond);
    } else {
        while (gen == j->gen)
            pthread_cond_wait(&j->cond, &j->lock);
    }
    pthread_mutex_unlock(&j->lock);
}

static void band_done(scene_job *j)
{
    pthread_mutex_lock(&j->lock);
    j->active--;
    if (j->arrived && j->arrived >= j->active) {
        j->arrived = 0;
        j->gen++;
        pthread_cond_broadcast(&j->cond);
    }
    pthread_mutex_unlock(&j->lock);
}

/* ---- where the bands are cut ----
 * Equal bands of rows are only as even as the picture (a teapot's lid and
 * spout are in its top half), so a script drawn again at the same size is
 * cut where the last frame's cost says: each band's thread CPU time is
 * spread evenly over its rows, and the new cuts split that cost into equal
 * parts. Only the time a frame takes depends on the cuts, never its pixels
 * (every band draws the whole frame clipped to its rows). One plan is
 * kept, for the last script run banded. */
static pthread_mutex_t plan_lock = PTHREAD_MUTEX_INITIALIZER;
static uint64_t plan_key;
static int32_t plan_cut[65];

static uint64_t plan_key_of(const char *text, size_t len, int32_t w, int32_t h, fx_format f, int n)
{
    uint64_t k = 0xcbf29ce484222325ull; /* FNV-1a */
    for (size_t i = 0; i < len; i++)
        k = (k ^ (uint8_t)text[i]) * 0x100000001b3ull;
    uint64_t v[4] = {(uint64_t)len, (uint64_t)(uint32_t)w << 32 | (uint32_t)h, (uint64_t)f, (uint64_t)n};
    for (int i = 0; i < 4; i++)
        k = (k ^ v[i]) * 0x100000001b3ull;
    return k | 1; /* never 0, the empty plan */
}

void fx_par_balance(int n, const int32_t *cut, const int64_t *cost, int32_t *out)
{
    int32_t h = cut[n];
    for (int k = 0; k <= n; k++)
        out[k] = (int32_t)((int64_t)h * k / n);
    int64_t total = 0;
    for (int k = 0; k < n; k++) {
        if (cost[k] < 0 || cut[k + 1] <= cut[k] || cost[k] > INT64_MAX / 2 / 64 - total)
            return; /* not a plan to follow: equal bands */
        total += cost[k];
    }
    if (total <= 0 || h < n)
        return;
    int k = 0;
    int64_t before = 0; /* the cost of bands before k */
    for (int m = 1; m < n; m++) {
        int64_t want = total * m; /* the cost up to cut m, times n */
        while (k < n - 1 && (before + cost[k]) * n <= want)
            before += cost[k++];
        /* inside band k, cost[k] spread over its rows */
        int64_t rows = cut[k + 1] - cut[k], c = cost[k] * n;
        /* want - before*n < c here, so scaling both below 2^31 keeps
         * (part * rows) inside 64 bits without __int128, which 32-bit ARM lacks */
        int64_t part = want - before * n;
        while (c >= ((int64_t)1 << 31)) {
            c >>= 1;
            part >>= 1;
        }
        int64_t at = cut[k] + (c > 0 ? part * rows / c : 0);
        if (at > cut[k + 1])
            at = cut[k + 1];
        /* at least one row per band */
        if (at < out[m - 1] + 1)
            at = out[m - 1] + 1;
        if (at > h - (n - m))
            at = h - (n - m);
        out[m] = (int32_t)at;
    }
}

static void plan_cuts(scene_job *j, int32_t w, int32_t h, fx_format f)
{
    j->key = plan_key_of(j->text, j->len, w, h, f, j->n);
    for (int k = 0; k <= j->n; k++)
        j->cut[k] = (int32_t)((int64_t)h * k / j->n);
    pthread_mutex_lock(&plan_lock);
    if (plan_key == j->key)
        memcpy(j->cut, plan_cut, sizeof j->cut[0] * (size_t)(j->n + 1));
    pthread_mutex_unlock(&plan_lock);
}

static void plan_learn(scene_job *j)
{
    int64_t cost[64];
    for (int k = 0; k < j->n; k++)
        cost[k] = j->b[k].cpu_ns;
    int32_t next[65];
    fx_par_balance(j->n, j->cut, cost, next);
    pthread_mutex_lock(&plan_lock);
    plan_key = j->key;
    memcpy(plan_cut, next, sizeof next[0] * (size_t)(j->n + 1));
    pthread_mutex_unlock(&plan_lock);
}

void fx_par_last_cuts(int32_t *cut, int n)
{
    pthread_mutex_lock(&plan_lock);
    memcpy(cut, plan_cut, sizeof cut[0] * (size_t)(n + 1));
    pthread_mutex_unlock(&plan_lock);
}

static int64_t thread_cpu_ns(void)
{
    struct timespec t;
    if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t))
        return 0;
    return (int64_t)t.tv_sec * 1000000000 + t.tv_nsec;
}

static int host_make_surface(void *u, int32_t w, int32_t h, fx_format f, fx_surface *out)
{
    band *b = u;
    scene_job *j = b->job;
    int r = 0;
    pthread_mutex_lock(&j->host_lock);
    if (!j->have_surface) {
        r = j->host.make_surface(j->host.user, w, h, f, &j->surf);
        j->have_surface = r >= 0;
        if (r >= 0)
            plan_cuts(j, w, h, f);
    }
    pthread_mutex_unlock(&j->host_lock);
    if (r < 0)
        return r;
    /* every band asks for the same size and format: it runs the same script */
    if (j->surf.w != w || j->surf.h != h || j->surf.format != f)
        return -FX_EINVAL;
    *out = j->surf;
    fx_rect whole = {0, 0, w, h};
    whole.y0 = j->cut[b->index];
    whole.y1 = j->cut[b->index + 1];
    fx_scene_set_band(b->sc, whole);
    return 0;
}

/* The cache entry of path (image or file), or NULL; under host_lock. */
static struct loaded *cached(scene_job *j, const char *path, int image)
{
    for (int i = 0; i < j->ncache; i++)
        if (j->cache[i].image == image && !strcmp(j->cache[i].path, path))
            return &j->cache[i];
    return 0;
}

static struct loaded *remember(scene_job *j, const char *path, int image)
{
    if (j->ncache == 32 || strlen(path) >= sizeof j->cache[0].path)
        return 0;
    struct loaded *l = &j->cache[j->ncache++];
    memset(l, 0, sizeof *l);
    strcpy(l->path, path);
    l->image = image;
    return l;
}

static int host_load_file(void *u, const char *path, const uint8_t **data, size_t *len)
{
    scene_job *j = ((band *)u)->job;
    pthread_mutex_lock(&j->host_lock);
    struct loaded *l = cached(j, path, 0);
    int r;
    if (l) {
        r = l->rc;
        *data = l->data;
        *len = l->len;
    } else {
        r = j->host.load_file(j->host.user, path, data, len);
        if ((l = remember(j, path, 0)))
            l->rc = r, l->data = r < 0 ? 0 : *data, l->len = r < 0 ? 0 : *len;
    }
    pthread_mutex_unlock(&j->host_lock);
    return r;
}

static int host_load_image(void *u, const char *path, fx_surface *out)
{
    scene_job *j = ((band *)u)->job;
    pthread_mutex_lock(&j->host_lock);
    struct loaded *l = cached(j, path, 1);
    int r;
    if (l) {
        r = l->rc;
        if (r >= 0)
            *out = l->img;
    } else {
        r = j->host.load_image(j->host.user, path, out);
        if ((l = remember(j, path, 1)))
            l->rc = r, l->img = r < 0 ? (fx_surface){0} : *out;
    }
    pthread_mutex_unlock(&j->host_lock);
    return r;
}

/* 'raytrace': every band arrives with the same rectangle; the first sets it
 * up, all trace rows of it from a shared counter, and none goes on until
 * the whole rectangle is done (the bands' later commands draw over it). */
static int band_raytrace(void *u, const struct fx_rt_scene *s, const fx_surface *surf, int32_t x, int32_t y,
                         int32_t w, int32_t h)
{
    scene_job *j = ((band *)u)->job;
    barrier(j); /* every band's earlier drawing is done */
    pthread_mutex_lock(&j->lock);
    if (!j->rt) {
        int64_t x1 = (int64_t)x + w, y1 = (int64_t)y + h;
        j->rt = s;
        j->rx0 = x < 0 ? 0 : x;
        j->ry0 = y < 0 ? 0 : y;
        j->rx1 = (int32_t)(x1 > surf->w ? surf->w : x1);
        j->ry1 = (int32_t)(y1 > surf->h ? surf->h : y1);
        atomic_store(&j->rt_next, 0);
    }
    pthread_mutex_unlock(&j->lock);
    enum { ROWS = 4 };
    for (;;) {
        int64_t y0 = j->ry0 + (int64_t)atomic_fetch_add(&j->rt_next, 1) * ROWS;
        if (y0 >= j->ry1 || j->rx0 >= j->rx1)
            break;
        int32_t y1 = (int32_t)(y0 + ROWS < j->ry1 ? y0 + ROWS : j->ry1);
        fx_rt_render(j->rt, surf, j->rx0, (int32_t)y0, j->rx1 - j->rx0, y1 - (int32_t)y0);
    }
    barrier(j); /* the whole rectangle is done */
    pthread_mutex_lock(&j->lock);
    j->rt = 0; /* the next 'raytrace' sets up anew (all are past its use) */
    pthread_mutex_unlock(&j->lock);
    return 0;
}

/* The extra bands' arenas, kept from one frame to the next: fresh memory
 * from malloc is mapped anew each time, and a band's first touch of every
 * page of its depth buffer then faults and has the kernel zero the page
 * (at 1920x1080 that was an eighth of the band's CPU time). One block is
 * kept, with its real size (a smaller script may use a bigger block, which
 * stays as big); a second caller at the same time takes its own. It stays
 * until exit, like any cache, or until fx_par_trim. */
static pthread_mutex_t arena_lock = PTHREAD_MUTEX_INITIALIZER;
static uint8_t *arena_keep;
static size_t arena_keep_size;

/* At least size bytes; *got is what the block really holds. */
static uint8_t *arenas_take(size_t size, size_t *got)
{
    uint8_t *a = 0;
    pthread_mutex_lock(&arena_lock);
    if (arena_keep && arena_keep_size >= size) {
        a = arena_keep;
        *got = arena_keep_size;
        arena_keep = 0;
        arena_keep_size = 0;
    }
    pthread_mutex_unlock(&arena_lock);
    if (!a) {
        a = malloc(size);
        *got = a ? size : 0;
    }
    return a;
}

/* Keep the bigger of a and the block kept so far; free the other. */
static void arenas_give(uint8_t *a, size_t size)
{
    if (!a)
        return;
    pthread_mutex_lock(&arena_lock);
    if (!arena_keep || arena_keep_size < size) {
        uint8_t *old = arena_keep;
        arena_keep = a;
        arena_keep_size = size;
        a = old;
    }
    pthread_mutex_unlock(&arena_lock);
    free(a);
}

size_t fx_par_trim(void)
{
    pthread_mutex_lock(&arena_lock);
    uint8_t *a = arena_keep;
    size_t n = arena_keep_size;
    arena_keep = 0;
    arena_keep_size = 0;
    pthread_mutex_unlock(&arena_lock);
    free(a);
    return a ? n : 0;
}

/* A band runs the script; the bands run all at once, one per thread (the
 * collective steps wait for every band), so the number of bands is the
 * number of threads that could be started. */
static void *scene_worker(void *arg)
{
    scene_job *j = arg;
    pthread_mutex_lock(&j->lock);
    while (!j->go)
        pthread_cond_wait(&j->cond, &j->lock);
    pthread_mutex_unlock(&j->lock);
    int k = atomic_fetch_add(&j->next, 1);
    if (k < j->n) {
        band *b = &j->b[k];
        int64_t t0 = thread_cpu_ns();
        b->rc = fx_scene_run(b->sc, j->text, j->len);
        b->cpu_ns = thread_cpu_ns() - t0;
        band_done(j);
    }
    return 0;
}

int fx_scene_run_mt(fx_scene *sc, const char *text, size_t len, int nthreads, int *bands)
{
    if (bands)
        *bands = 1;
    if (!sc || nthreads < 1 || nthreads > 64)
        return -FX_EINVAL;
    if (nthreads == 1 || sc->host.trace || sc->have_surface || sc->arena_used || !sc->host.make_surface ||
        fx_scene_script_serial(text, len))
        return fx_scene_run(sc, text, len);
    /* one arena per extra band: fixel-draw's is 128 MiB, and 32-bit boards
     * would wrap the product at -j 33 */
    if (sc->arena_size > SIZE_MAX / (size_t)(nthreads - 1))
        return fx_scene_run(sc, text, len);
    scene_job *j = calloc(1, sizeof *j);
    fx_scene *extra = calloc((size_t)nthreads - 1, sizeof *extra);
    size_t arenas_size = 0;
    uint8_t *arenas = sc->arena_size ? arenas_take(sc->arena_size * (size_t)(nthreads - 1), &arenas_size) : 0;
    if (!j || !extra || (sc->arena_size && !arenas)) {
        free(j);
        free(extra);
        arenas_give(arenas, arenas_size);
        return fx_scene_run(sc, text, len);
    }
    j->text = text;
    j->len = len;
    j->host = sc->host;
    j->raytrace = sc->raytrace;
    atomic_init(&j->next, 0);
    atomic_init(&j->rt_next, 0);
    pthread_mutex_init(&j->host_lock, 0);
    pthread_mutex_init(&j->lock, 0);
    pthread_cond_init(&j->cond, 0);
    fx_posix_batch pool;
    (void)fx_posix_pool_start(&pool, scene_worker, j, nthreads - 1); /* fewer: fewer bands */
    j->n = pool.n + 1;

    fx_scene_host wrapped = sc->host;
    wrapped.make_surface = host_make_surface;
    wrapped.load_file = sc->host.load_file ? host_load_file : 0;
    wrapped.load_image = sc->host.load_image ? host_load_image : 0;
    wrapped.present = 0; /* 'present' is serial: never called */
    for (int k = 0; k < j->n; k++) {
        fx_scene *s = k ? &extra[k - 1] : sc;
        if (k) {
            *s = *sc; /* size, format and what the host fixed */
            s->arena = arenas + sc->arena_size * (size_t)(k - 1);
        }
        j->b[k] = (band){.job = j, .sc = s, .index = k};
        s->host = wrapped;
        s->host.user = &j->b[k];
        s->raytrace = band_raytrace;
    }
    pthread_mutex_lock(&j->lock);
    j->active = j->n;
    j->go = 1;
    pthread_cond_broadcast(&j->cond);
    pthread_mutex_unlock(&j->lock);
    scene_worker(j);
    fx_posix_pool_wait(&pool);

    int rc = 0;
    if (j->have_surface && j->n > 1)
        plan_learn(j);
    for (int k = 0; k < j->n; k++)
        if (j->b[k].rc < 0) {
            rc = j->b[k].rc;
            if (k) {
                memcpy(sc->err, extra[k - 1].err, sizeof sc->err);
                sc->err_line = extra[k - 1].err_line;
                sc->err_col = extra[k - 1].err_col;
            }
            break;
        }
    /* sc goes on as an ordinary scene on the whole surface */
    sc->host = j->host;
    sc->raytrace = j->raytrace;
    sc->banded = 0;
    if (sc->have_surface) {
        sc->ctx.trace_user = sc->host.user;
        fx_ctx_reset_clip(&sc->ctx);
    }
    if (bands)
        *bands = j->n;
    pthread_cond_destroy(&j->cond);
    pthread_mutex_destroy(&j->lock);
    pthread_mutex_destroy(&j->host_lock);
    arenas_give(arenas, arenas_size);
    free(extra);
    free(j);
    return rc;
}

int fx_par_cpu_count(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n < 1 ? 1 : n > 64 ? 64 : (int)n;
}
