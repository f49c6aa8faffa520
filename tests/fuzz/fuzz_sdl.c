/* SPDX-License-Identifier: MIT */
/* libFuzzer target: the textbook's SDL reader (fixel/sdl.h). The input is
 * the SDL text, optionally followed by a line "===" and the text every
 * 'mesh FILE' reads (a 3VN file), so both parsers get hostile text. A
 * rejection must come with a message naming the file; an accepted scene is
 * ray traced (default camera) into a small guarded surface, so whatever the
 * reader builds must be safe to render. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/error.h"
#include "fixel/rt.h"
#include "fixel/sdl.h"
#include "guard.h"

#define ARENA ((size_t)4 << 20)

typedef struct mem {
    uint8_t *base;
    size_t used;
    const char *mesh;
    size_t mesh_len;
} mem;

static void *bump(void *user, size_t n)
{
    mem *m = user;
    n = (n + 15) & ~(size_t)15;
    if (n > ARENA - m->used)
        return NULL;
    void *p = m->base + m->used;
    memset(p, 0, n);
    m->used += n;
    return p;
}

static int load(void *user, const char *path, const uint8_t **data, size_t *len)
{
    mem *m = user;
    (void)path;
    if (!m->mesh)
        return -FX_ENOENT;
    *data = (const uint8_t *)m->mesh;
    *len = m->mesh_len;
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    /* exact-size heap copies, so ASan catches a read one past the end */
    size_t cut = size;
    for (size_t i = 0; i + 4 <= size; i++)
        if (!memcmp(data + i, "===\n", 4) && (i == 0 || data[i - 1] == '\n')) {
            cut = i;
            break;
        }
    char *text = malloc(cut ? cut : 1);
    memcpy(text, data, cut);
    mem m = {malloc(ARENA), 0, NULL, 0};
    char *mesh = NULL;
    if (cut < size) {
        m.mesh_len = size - cut - 4;
        mesh = malloc(m.mesh_len ? m.mesh_len : 1);
        memcpy(mesh, data + cut + 4, m.mesh_len);
        m.mesh = mesh;
    }
    static fx_rt_object objs[32];
    fx_rt_scene s;
    fx_rt_scene_init(&s, objs, 32);
    fx_sdl_env env = {&m, bump, load};
    fx_sdl_error err;
    int n = fx_sdl_read(&s, text, cut, "f.sdl", &env, &err);
    if (n < 0) {
        if (!memchr(err.msg, 0, sizeof err.msg) || strncmp(err.msg, "f.sdl:", 6) || err.line < 1 || err.col < 1)
            abort(); /* a rejection must name its place */
    } else {
        int tops = 0;
        for (int i = 0; i < s.n; i++)
            tops += s.obj[i].top;
        if (n != tops || s.nlights > FX_RT_MAX_LIGHTS || s.max_depth > FX_RT_MAX_RECURSION)
            abort();
        if (fx_sdl_default_camera(&s, 45 * FX16_ONE) < 0)
            abort(); /* the default camera always exists */
        guarded g;
        if (guarded_make(&g, 8, 6, FX_FMT_XRGB8888, 0) == 0) {
            fx_rt_render(&s, &g.s, 0, 0, 8, 6);
            guarded_free(&g);
        }
    }
    free(mesh);
    free(m.base);
    free(text);
    return 0;
}
