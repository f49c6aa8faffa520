/* SPDX-License-Identifier: MIT */
/* fixel — smooth text when fixel was built without FreeType, HarfBuzz,
 * FriBiDi, fontconfig or libunibreak (the Makefile's HAVE_TEXT): every call
 * says so, so programs link and fall back to the bitmap fonts. */
#include <stdio.h>
#include <string.h>

#include "fixel/error.h"
#include "fixel/face.h"

#define WHY "fixel was built without smooth text (needs libfreetype-dev libharfbuzz-dev libfribidi-dev " \
            "libfontconfig-dev libunibreak-dev)"

int fx_face_available(void) { return 0; }

int fx_face_open(const char *name, int32_t px, const fx_face_opts *opts, fx_face **out, char *err, size_t errsz)
{
    (void)px, (void)opts;
    if (out)
        *out = NULL;
    if (err && errsz)
        snprintf(err, errsz, "%s: %s", name ? name : "font", WHY);
    return -FX_ENOTSUP;
}

void fx_face_close(fx_face *f) { (void)f; }
void fx_face_shutdown(void) {}
int fx_face_set_size(fx_face *f, int32_t px) { (void)f, (void)px; return -FX_ENOTSUP; }
int32_t fx_face_size(const fx_face *f) { (void)f; return 0; }
int fx_face_set_features(fx_face *f, const char *list) { (void)f, (void)list; return -FX_ENOTSUP; }
const char *fx_face_error(const fx_face *f) { (void)f; return WHY; }
const char *fx_face_file(const fx_face *f, int i) { (void)f, (void)i; return NULL; }
void fx_face_cache_stats(const fx_face *f, fx_face_stats *st)
{
    (void)f;
    if (st)
        memset(st, 0, sizeof *st);
}
int fx_face_shape(fx_face *f, const char *s, size_t len, const fx_glyph **out)
{
    (void)f, (void)s, (void)len;
    if (out)
        *out = NULL;
    return -FX_ENOTSUP;
}
int fx_face_measure(fx_face *f, const char *s, size_t len, fx_text_metrics *m)
{
    (void)f, (void)s, (void)len, (void)m;
    return -FX_ENOTSUP;
}
int fx_face_draw(fx_face *f, const fx_ctx *c, int32_t x, int32_t y, const char *s, size_t len, unsigned rot)
{
    (void)f, (void)c, (void)x, (void)y, (void)s, (void)len, (void)rot;
    return -FX_ENOTSUP;
}
int fx_face_draw_box(fx_face *f, const fx_ctx *c, const fx_textbox *b, const char *s, size_t len, int32_t *lines,
                     int *overflow)
{
    (void)f, (void)c, (void)b, (void)s, (void)len;
    if (lines)
        *lines = 0;
    if (overflow)
        *overflow = 0;
    return -FX_ENOTSUP;
}
int32_t fx_face_fit(fx_face *f, const fx_textbox *b, const char *s, size_t len, int32_t min_px, int32_t max_px)
{
    (void)f, (void)b, (void)s, (void)len, (void)min_px, (void)max_px;
    return -FX_ENOTSUP;
}

/* Scripts still get a host: its 'font NAME SIZE' says what is missing. */
struct fx_face_scene {
    fx_scene_text_host host;
};
static int absent_open(void *user, const char *name, int32_t px, int32_t weight, const char *feats, void **face,
                       char *err, size_t errsz)
{
    (void)user, (void)px, (void)weight, (void)feats, (void)face;
    snprintf(err, errsz, "%s: %s", name, WHY);
    return -FX_ENOTSUP;
}
static int absent_draw(void *user, void *face, const fx_ctx *c, int32_t x, int32_t y, int32_t w, int32_t h, int align,
                       int ellipsis, const char *s, size_t len, char *err, size_t errsz)
{
    (void)user, (void)face, (void)c, (void)x, (void)y, (void)w, (void)h, (void)align, (void)ellipsis, (void)s;
    (void)len;
    snprintf(err, errsz, "%s", WHY);
    return -FX_ENOTSUP;
}
static fx_face_scene absent_scene = {{NULL, absent_open, absent_draw}};
fx_face_scene *fx_face_scene_new(void) { return &absent_scene; }
const fx_scene_text_host *fx_face_scene_host(const fx_face_scene *fs) { return fs ? &fs->host : NULL; }
void fx_face_scene_free(fx_face_scene *fs) { (void)fs; }
