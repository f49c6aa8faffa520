/* SPDX-License-Identifier: MIT */
/* fixel — in-memory framebuffer and image files. */
#define _POSIX_C_SOURCE 200809L
#ifndef _GNU_SOURCE
#define _GNU_SOURCE /* realpath, also in builds (the rig) that do not pass -D_GNU_SOURCE */
#endif
#include "fixel/memfb.h"
#include "fixel/error.h"
#include "fixel/files.h"

#include <errno.h>
#include <setjmp.h>
#include <fcntl.h>
#include <sys/stat.h>
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
 * or interrupted write never leaves a partial file under the real name.
 * Only a regular file (or nothing) is ever replaced (issue #26): a symlink
 * is followed and its target replaced; a device, FIFO or socket at the path
 * is written in place (opened without blocking, never created or renamed
 * over: `-o /dev/full` fails with ENOSPC and the device stays). tmp[0] == 0
 * marks that direct mode; final gets the name to rename onto. */
static FILE *open_tmp(const char *path, char *tmp, size_t n, char *final, size_t nfinal)
{
    struct stat st;
    errno = 0;
    tmp[0] = 0;
    if (strlen(path) >= nfinal) {
        errno = ENAMETOOLONG;
        return NULL;
    }
    strcpy(final, path);
    if (lstat(path, &st) == 0 && S_ISLNK(st.st_mode)) {
        char *real = realpath(path, NULL);
        if (real && strlen(real) < nfinal) {
            strcpy(final, real);
        } else { /* a dangling link: its target, relative to the link's folder */
            char t[4096];
            ssize_t k = readlink(path, t, sizeof t - 1);
            const char *slash = strrchr(path, '/');
            size_t dir = slash ? (size_t)(slash - path) + 1 : 0;
            if (k > 0 && (size_t)k + dir < nfinal) {
                t[k] = 0;
                if (t[0] == '/')
                    dir = 0;
                memcpy(final, path, dir);
                strcpy(final + dir, t);
            }
        }
        free(real);
    }
    if (stat(final, &st) == 0 && !S_ISREG(st.st_mode)) {
        if (S_ISDIR(st.st_mode)) {
            errno = EISDIR;
            return NULL;
        }
        int fd = open(final, O_WRONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
        if (fd < 0)
            return NULL;
        fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) & ~O_NONBLOCK);
        FILE *f = fdopen(fd, "wb");
        if (!f)
            close(fd);
        return f;
    }
    /* An existing file this process may not write is refused with its own
     * error (EACCES, EROFS), as a shell's > would: the temporary file's
     * error (or rename's EPERM in a sticky directory) would name neither. */
    if (stat(final, &st) == 0 && access(final, W_OK) != 0)
        return NULL;
    if ((size_t)snprintf(tmp, n, "%s.tmp%ld", final, (long)getpid()) >= n) {
        tmp[0] = 0;
        errno = ENAMETOOLONG;
        return NULL;
    }
    return fopen(tmp, "wb");
}

static int finish_tmp(FILE *f, const char *tmp, const char *path, int ok)
{
    errno = 0;
    if (fflush(f) != 0)
        ok = 0;
    int e = errno;
    if (fclose(f) != 0) {
        ok = 0;
        if (!e)
            e = errno;
    }
    if (!tmp[0]) /* written in place */
        return ok ? 0 : -(e ? e : FX_EIO);
    /* open_tmp looked before writing; a FIFO or device node put there
     * since must still not be replaced (issue #40) */
    if (ok && fx_check_replaceable(path, NULL, 0) < 0) {
        e = errno;
        ok = 0;
    }
    if (ok && rename(tmp, path) == 0)
        return 0;
    if (!e)
        e = errno ? errno : FX_EIO;
    remove(tmp);
    return -e;
}

int fx_write_ppm(const char *path, const fx_surface *s)
{
    char tmp[4096], final[4096];
    FILE *f = open_tmp(path, tmp, sizeof tmp, final, sizeof final);
    if (!f)
        return errno ? -errno : -FX_EINVAL;
    uint8_t *row = malloc((size_t)s->w * 3);
    int ok = row != NULL && fprintf(f, "P6\n%d %d\n255\n", s->w, s->h) > 0;
    for (int32_t y = 0; ok && y < s->h; y++) {
        fx_surface_row_to_rgb(s, y, row);
        ok = fwrite(row, 3, (size_t)s->w, f) == (size_t)s->w;
    }
    free(row);
    return finish_tmp(f, tmp, final, ok);
}

/* Opens an input without blocking (a FIFO must not hang a reader), for
 * regular files only (fixel/files.h); *size gets its size. NULL with errno
 * set: EISDIR, EINVAL for another kind of file (these functions' documented
 * results), or open()'s. */
static FILE *open_regular(const char *path, off_t *size)
{
    int64_t sz = 0;
    FILE *f = fx_fopen_regular(path, &sz, NULL, 0);
    if (!f && errno == EOPNOTSUPP)
        errno = EINVAL;
    *size = (off_t)sz;
    return f;
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
    char tmp[4096], final[4096];
    FILE *f = open_tmp(path, tmp, sizeof tmp, final, sizeof final);
    if (!f)
        return errno ? -errno : -FX_EINVAL;
    return finish_tmp(f, tmp, final, write_png_stream(f, s->w, s->h, s, NULL));
}

int fx_write_png_rgb(const char *path, const uint8_t *rgb, int32_t w, int32_t h)
{
    char tmp[4096], final[4096];
    FILE *f = open_tmp(path, tmp, sizeof tmp, final, sizeof final);
    if (!f)
        return errno ? -errno : -FX_EINVAL;
    return finish_tmp(f, tmp, final, write_png_stream(f, w, h, NULL, rgb));
}

/* libpng's own limits (issue #26): a 141-byte PNG whose tEXt chunk declared
 * 2 GiB took 2 GB per load. Ancillary chunks are skipped unread, chunk
 * allocations are capped, and so are the dimensions before the pixel
 * buffer is allocated. Alpha is dropped (the colour kept, as docs/kiosk.md
 * says), not composited onto black. */
#define PNG_MAX_SIDE 16384u
#define PNG_MAX_PIXELS ((size_t)1 << 26)

static void png_quiet(png_structp png, png_const_charp msg)
{
    (void)png;
    (void)msg;
}

static void png_fail(png_structp png, png_const_charp msg)
{
    (void)msg; /* the caller reports the error code; no stderr noise */
    png_longjmp(png, 1);
}

int fx_read_png_rgb(const char *path, uint8_t **rgb, int32_t *w, int32_t *h)
{
    off_t fsize;
    FILE *f = open_regular(path, &fsize);
    if (!f)
        return errno == ENOENT ? -FX_ENOENT : errno == EISDIR ? -FX_EISDIR : errno == EACCES ? -FX_EACCES
                                                                                               : -FX_EBADMSG;
    int r = fx_read_png_rgb_stream(f, PNG_MAX_SIDE, PNG_MAX_PIXELS, rgb, w, h);
    fclose(f);
    return r;
}

int fx_read_png_rgb_stream(FILE *f, uint32_t max_side, size_t max_pixels, uint8_t **rgb, int32_t *w, int32_t *h)
{
    if (max_side > PNG_MAX_SIDE)
        max_side = PNG_MAX_SIDE;
    if (max_pixels > PNG_MAX_PIXELS)
        max_pixels = PNG_MAX_PIXELS;
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, png_fail, png_quiet);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    uint8_t *volatile buf = NULL;
    png_bytep *volatile rows = NULL;
    if (!info) {
        png_destroy_read_struct(&png, NULL, NULL);
        return -FX_ENOMEM;
    }
    volatile int huge = 0;
    if (setjmp(png_jmpbuf(png))) {
        free(buf);
        free(rows);
        png_destroy_read_struct(&png, &info, NULL);
        return huge ? -FX_EFBIG : -FX_EBADMSG;
    }
    png_set_user_limits(png, max_side, max_side);
    png_set_chunk_cache_max(png, 64);
    png_set_chunk_malloc_max(png, (png_alloc_size_t)8 << 20);
    /* every ancillary chunk, known or not, is skipped without being read */
    png_set_keep_unknown_chunks(png, PNG_HANDLE_CHUNK_NEVER, NULL, 0);
    static const png_byte skip[] = "bKGD\0cHRM\0eXIf\0gAMA\0hIST\0iCCP\0iTXt\0oFFs\0pCAL\0pHYs\0sBIT\0"
                                   "sCAL\0sPLT\0sRGB\0sTER\0tEXt\0tIME\0zTXt\0";
    png_set_keep_unknown_chunks(png, PNG_HANDLE_CHUNK_NEVER, skip, (int)(sizeof skip / 5));
    png_init_io(png, f);
    png_read_info(png, info);
    png_uint_32 W = png_get_image_width(png, info), H = png_get_image_height(png, info);
    if (!W || !H || W > max_side || H > max_side || (size_t)W * H > max_pixels) {
        huge = 1;
        png_error(png, "too large");
    }
    /* Every colour type and depth to 8-bit RGB by libpng's transforms:
     * png_set_expand turns palettes into RGB, grey below 8 bits into 8 and
     * a tRNS chunk into an alpha channel (of any type: a palette with tRNS
     * used to come out RGBA and fail the row size check below); the alpha,
     * from the file or from tRNS, is then stripped, the colour kept. */
    int ct = png_get_color_type(png, info);
    png_set_expand(png);
    png_set_strip_16(png);
    if (!(ct & PNG_COLOR_MASK_COLOR))
        png_set_gray_to_rgb(png);
    png_set_strip_alpha(png);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    if (png_get_rowbytes(png, info) != (size_t)W * 3)
        png_error(png, "unexpected row size");
    buf = malloc((size_t)W * H * 3);
    rows = malloc(sizeof(png_bytep) * H);
    if (!buf || !rows) {
        huge = 1;
        png_error(png, "out of memory");
    }
    for (png_uint_32 y = 0; y < H; y++)
        rows[y] = buf + (size_t)y * W * 3;
    png_read_image(png, rows);
    png_read_end(png, NULL);
    free(rows);
    png_destroy_read_struct(&png, &info, NULL);
    *rgb = buf;
    *w = (int32_t)W;
    *h = (int32_t)H;
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
int fx_read_png_rgb_stream(FILE *f, uint32_t max_side, size_t max_pixels, uint8_t **rgb, int32_t *w, int32_t *h)
{
    (void)f;
    (void)max_side;
    (void)max_pixels;
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
    off_t fsize = 0;
    errno = 0;
    FILE *f = open_regular(path, &fsize); /* no blocking on a FIFO */
    if (!f)
        return errno ? -errno : -FX_ENOENT;
    int W, H, maxval, r = -FX_EBADMSG;
    if (fscanf(f, "P6 %d %d %d", &W, &H, &maxval) == 3 && maxval == 255 && W > 0 && H > 0 &&
        W <= 65536 && H <= 65536 && fgetc(f) != EOF &&
        (uint64_t)W * (uint64_t)H * 3 <= (uint64_t)fsize) { /* the size capped by the file's before allocating */
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

/* The Makefile compiles every object with FX_NO_PNG when pkg-config found no
 * libpng, with FX_NO_BOARD_LIBS when it found no libdrm/libevdev/libgpiod
 * (boards/linux/absent then stands in for the DRM and input backends),
 * with FX_NO_TEXT without the text libraries (boards/text/absent) and
 * FX_NO_JPEG/GIF/WEBP per image decoder. The names are the ones the build's
 * own summary prints (the Makefile's BUILT_WITHOUT). */
static const char without[] = ""
#ifdef FX_NO_BOARD_LIBS
                              "/libdrm/libevdev/libgpiod"
#endif
#ifdef FX_NO_PNG
                              "/libpng"
#endif
#ifdef FX_NO_TEXT
                              "/FreeType/HarfBuzz/FriBiDi/fontconfig/libunibreak"
#endif
#ifdef FX_NO_JPEG
                              "/libjpeg"
#endif
#ifdef FX_NO_GIF
                              "/giflib"
#endif
#ifdef FX_NO_WEBP
                              "/libwebp"
#endif
    ;

const char *fx_built_without(void)
{
    return without[0] ? without + 1 : without;
}

const char *fx_built_without_hint(int err)
{
#ifdef FX_NO_PNG
    if (err == -FX_ENOTSUP)
        return " (this fixel was built without libpng: install libpng-dev and zlib1g-dev and run make"
               " again, or write .ppm)";
#endif
    (void)err;
    return "";
}
