/* SPDX-License-Identifier: MIT */
/* fixel — in-memory framebuffer and image files. */
#define _POSIX_C_SOURCE 200809L
#include "fixel/memfb.h"
#include "fixel/error.h"

#include <errno.h>
#ifndef FX_NO_PNG
#include <png.h>
#endif
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

int fx_memfb_create(fx_memfb *fb, int32_t w, int32_t h, fx_format f)
{
    memset(fb, 0, sizeof *fb);
    if ((unsigned)f >= FX_FMT_COUNT || w <= 0 || h <= 0 || w > 65536 || h > 65536)
        return -FX_EINVAL;
    int32_t stride = (fx_format_min_stride(f, w) + 63) & ~63;
    size_t bytes = (size_t)stride * (size_t)h;
    void *mem = NULL;
    if (posix_memalign(&mem, 64, bytes))
        return -FX_ENOMEM;
    memset(mem, 0, bytes);
    int r = fx_surface_init(&fb->surf, mem, w, h, stride, f);
    if (r < 0) {
        free(mem);
        return r;
    }
    fb->mem = mem;
    return 0;
}

void fx_memfb_destroy(fx_memfb *fb)
{
    free(fb->mem);
    memset(fb, 0, sizeof *fb);
}

/* Images are written to a temporary name and renamed into place, so a failed
 * or interrupted write never leaves a partial file under the real name. */
static FILE *open_tmp(const char *path, char *tmp, size_t n)
{
    if ((size_t)snprintf(tmp, n, "%s.tmp%ld", path, (long)getpid()) >= n)
        return NULL;
    return fopen(tmp, "wb");
}

static int finish_tmp(FILE *f, const char *tmp, const char *path, int ok)
{
    if (fclose(f) != 0)
        ok = 0;
    if (ok && rename(tmp, path) == 0)
        return 0;
    int e = errno ? errno : FX_EIO;
    remove(tmp);
    return -e;
}

int fx_write_ppm(const char *path, const fx_surface *s)
{
    char tmp[4096];
    FILE *f = open_tmp(path, tmp, sizeof tmp);
    if (!f)
        return errno ? -errno : -FX_EINVAL;
    uint8_t *row = malloc((size_t)s->w * 3);
    int ok = row != NULL && fprintf(f, "P6\n%d %d\n255\n", s->w, s->h) > 0;
    for (int32_t y = 0; ok && y < s->h; y++) {
        fx_surface_row_to_rgb(s, y, row);
        ok = fwrite(row, 3, (size_t)s->w, f) == (size_t)s->w;
    }
    free(row);
    return finish_tmp(f, tmp, path, ok);
}

#ifndef FX_NO_PNG
static int write_png_stream(FILE *f, int32_t w, int32_t h, const fx_surface *s, const uint8_t *rgb)
{
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    uint8_t *volatile row = NULL;
    if (!info) {
        png_destroy_write_struct(&png, NULL);
        return 0;
    }
    if (setjmp(png_jmpbuf(png))) {
        free(row);
        png_destroy_write_struct(&png, &info);
        return 0;
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    if (s) {
        row = malloc((size_t)w * 3);
        if (!row)
            png_error(png, "out of memory");
    }
    for (int32_t y = 0; y < h; y++) {
        if (s) {
            fx_surface_row_to_rgb(s, y, row);
            png_write_row(png, row);
        } else {
            png_write_row(png, (png_const_bytep)(rgb + (size_t)y * (size_t)w * 3));
        }
    }
    png_write_end(png, NULL);
    free(row);
    png_destroy_write_struct(&png, &info);
    return 1;
}

int fx_write_png(const char *path, const fx_surface *s)
{
    char tmp[4096];
    FILE *f = open_tmp(path, tmp, sizeof tmp);
    if (!f)
        return errno ? -errno : -FX_EINVAL;
    return finish_tmp(f, tmp, path, write_png_stream(f, s->w, s->h, s, NULL));
}

int fx_write_png_rgb(const char *path, const uint8_t *rgb, int32_t w, int32_t h)
{
    char tmp[4096];
    FILE *f = open_tmp(path, tmp, sizeof tmp);
    if (!f)
        return errno ? -errno : -FX_EINVAL;
    return finish_tmp(f, tmp, path, write_png_stream(f, w, h, NULL, rgb));
}

int fx_read_png_rgb(const char *path, uint8_t **rgb, int32_t *w, int32_t *h)
{
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&img, path))
        return access(path, R_OK) ? -FX_ENOENT : -FX_EBADMSG;
    img.format = PNG_FORMAT_RGB;
    size_t bytes = PNG_IMAGE_SIZE(img);
    uint8_t *buf = malloc(bytes);
    if (!buf) {
        png_image_free(&img);
        return -FX_ENOMEM;
    }
    if (!png_image_finish_read(&img, NULL, buf, 0, NULL)) {
        free(buf);
        png_image_free(&img);
        return -FX_EBADMSG;
    }
    *rgb = buf;
    *w = (int32_t)img.width;
    *h = (int32_t)img.height;
    return 0;
}

#else /* FX_NO_PNG: built without libpng; PPM still works */
int fx_write_png(const char *path, const fx_surface *s)
{
    (void)path;
    (void)s;
    return -FX_ENOTSUP;
}
int fx_write_png_rgb(const char *path, const uint8_t *rgb, int32_t w, int32_t h)
{
    (void)path;
    (void)rgb;
    (void)w;
    (void)h;
    return -FX_ENOTSUP;
}
int fx_read_png_rgb(const char *path, uint8_t **rgb, int32_t *w, int32_t *h)
{
    (void)path;
    (void)rgb;
    (void)w;
    (void)h;
    return -FX_ENOTSUP;
}
#endif

int fx_read_ppm_rgb(const char *path, uint8_t **rgb, int32_t *w, int32_t *h)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return errno ? -errno : -FX_ENOENT;
    int W, H, maxval, r = -FX_EBADMSG;
    if (fscanf(f, "P6 %d %d %d", &W, &H, &maxval) == 3 && maxval == 255 && W > 0 && H > 0 &&
        W <= 65536 && H <= 65536 && fgetc(f) != EOF) {
        size_t bytes = (size_t)W * (size_t)H * 3;
        uint8_t *buf = malloc(bytes);
        if (!buf) {
            r = -FX_ENOMEM;
        } else if (fread(buf, 1, bytes, f) != bytes) {
            free(buf);
        } else {
            *rgb = buf;
            *w = W;
            *h = H;
            r = 0;
        }
    }
    fclose(f);
    return r;
}

int fx_write_image(const char *path, const fx_surface *s)
{
    size_t n = strlen(path);
    if (n >= 4 && strcasecmp(path + n - 4, ".ppm") == 0)
        return fx_write_ppm(path, s);
    return fx_write_png(path, s);
}

