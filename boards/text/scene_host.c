/* SPDX-License-Identifier: MIT */
/* fixel — smooth fonts for scene scripts: the fx_scene_text_host a host
 * (fixel-draw, the golden runner) lends its scenes (face.h). */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/error.h"
#include "fixel/face.h"

/* Faces are opened once per name, size, weight and features and kept until
 * fx_face_scene_free (every band of a banded script and every --frames
 * frame shares them); one lock, because banded scripts draw from several
 * threads and a face is not thread-safe. */
typedef struct face_entry {
    char *name, *feats;
    int32_t px, weight;
    fx_face *face;
    struct face_entry *next;
} face_entry;

struct fx_face_scene {
    fx_scene_text_host host;
    face_entry *faces;
    pthread_mutex_t lock;
};

static int text_open(void *user, const char *name, int32_t px, int32_t weight, const char *feats, void **face,
                     char *err, size_t errsz)
{
    fx_face_scene *fs = user;
    int r = 0;
    pthread_mutex_lock(&fs->lock);
    face_entry *e = fs->faces;
    while (e && !(e->px == px && e->weight == weight && !strcmp(e->name, name) && !strcmp(e->feats, feats)))
        e = e->next;
    if (!e) {
        fx_face_opts o = {0};
        o.weight = weight;
        o.features = feats;
        fx_face *f;
        r = fx_face_open(name, px, &o, &f, err, errsz);
        if (!r) {
            e = calloc(1, sizeof *e);
            if (e) {
                e->name = strdup(name);
                e->feats = strdup(feats);
            }
            if (!e || !e->name || !e->feats) {
                if (e) {
                    free(e->name);
                    free(e->feats);
                    free(e);
                }
                fx_face_close(f);
                snprintf(err, errsz, "%s: out of memory", name);
                r = -FX_ENOMEM;
            } else {
                e->px = px;
                e->weight = weight;
                e->face = f;
                e->next = fs->faces;
                fs->faces = e;
            }
        }
    }
    if (!r)
        *face = e;
    pthread_mutex_unlock(&fs->lock);
    return r;
}

static int text_draw(void *user, void *face, const fx_ctx *c, int32_t x, int32_t y, int32_t w, int32_t h, int align,
                     int ellipsis, const char *s, size_t len, char *err, size_t errsz)
{
    fx_face_scene *fs = user;
    face_entry *e = face;
    fx_textbox b = {{x, y, INT32_MAX, INT32_MAX}, (uint8_t)align, (uint8_t)ellipsis, 1, 0};
    if (w > 0) {
        b.box.x1 = (int32_t)((int64_t)x + w > INT32_MAX ? INT32_MAX : (int64_t)x + w);
        b.box.y1 = (int32_t)((int64_t)y + h > INT32_MAX ? INT32_MAX : (int64_t)y + h);
        b.no_wrap = 0;
    }
    pthread_mutex_lock(&fs->lock);
    int r = fx_face_draw_box(e->face, c, &b, s, len, NULL, NULL);
    if (r < 0)
        snprintf(err, errsz, "%s", fx_face_error(e->face));
    pthread_mutex_unlock(&fs->lock);
    return r;
}

fx_face_scene *fx_face_scene_new(void)
{
    fx_face_scene *fs = calloc(1, sizeof *fs);
    if (!fs)
        return NULL;
    pthread_mutex_init(&fs->lock, NULL);
    fs->host = (fx_scene_text_host){fs, text_open, text_draw};
    return fs;
}

const fx_scene_text_host *fx_face_scene_host(const fx_face_scene *fs) { return fs ? &fs->host : NULL; }

void fx_face_scene_free(fx_face_scene *fs)
{
    if (!fs)
        return;
    while (fs->faces) {
        face_entry *n = fs->faces->next;
        fx_face_close(fs->faces->face);
        free(fs->faces->name);
        free(fs->faces->feats);
        free(fs->faces);
        fs->faces = n;
    }
    pthread_mutex_destroy(&fs->lock);
    free(fs);
}
