/* SPDX-License-Identifier: MIT */
/* JPEG through libjpeg-turbo. Beyond the size limits: a progressive file
 * can hold thousands of scans each redoing the whole image (a decompression
 * bomb of a few kilobytes), so scans are capped and the clock is checked
 * from the progress monitor; libjpeg's own memory manager is capped too. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE /* clock_gettime under -std=c11, whoever compiles it */
#endif
#include <stdlib.h>
#include <string.h>

#include "fixel/error.h"
#include "image_int.h"

#ifndef FX_NO_JPEG
#include <setjmp.h>
#include <jpeglib.h>

#define JPEG_MAX_SCANS 256 /* libjpeg-turbo's advice for untrusted files; real files have < 20 */

struct jerr {
    struct jpeg_error_mgr mgr;
    struct jpeg_progress_mgr progress;
    jmp_buf jmp;
    char *why;
    size_t whylen;
    int code;
    struct timespec start;
    uint32_t max_ms;
};

static void jerr_exit(j_common_ptr c)
{
    struct jerr *e = (struct jerr *)c->err;
    if (e->code == 0) {
        char msg[JMSG_LENGTH_MAX];
        c->err->format_message(c, msg);
        fx_image_why(e->why, e->whylen, "JPEG: %s", msg);
        e->code = -FX_EBADMSG;
    }
    longjmp(e->jmp, 1);
}

static void jerr_quiet(j_common_ptr c, int level)
{
    /* warnings (a truncated file is "premature end") are errors here: a
     * half-grey picture on a kiosk is worse than a refusal naming the file */
    if (level < 0) {
        struct jerr *e = (struct jerr *)c->err;
        char msg[JMSG_LENGTH_MAX];
        c->err->format_message(c, msg);
        fx_image_why(e->why, e->whylen, "JPEG: %s", msg);
        e->code = -FX_EBADMSG;
        longjmp(e->jmp, 1);
    }
}

static void jprogress(j_common_ptr c)
{
    struct jerr *e = (struct jerr *)c->err;
    j_decompress_ptr d = (j_decompress_ptr)c;
    if (d->input_scan_number > JPEG_MAX_SCANS) {
        fx_image_why(e->why, e->whylen, "JPEG: more than %d progressive scans (a decompression bomb)", JPEG_MAX_SCANS);
        e->code = -FX_EFBIG;
        longjmp(e->jmp, 1);
    }
    if (fx_image_elapsed_ms(&e->start) > e->max_ms) {
        fx_image_why(e->why, e->whylen, "JPEG: decoding took more than %u ms (fx_image_limits.max_ms)", e->max_ms);
        e->code = -FX_EFBIG;
        longjmp(e->jmp, 1);
    }
}

int fx_jpeg_decode(const uint8_t *data, size_t len, const fx_image_limits *l, uint8_t **rgb, int32_t *w, int32_t *h,
                   char *why, size_t whylen)
{
    struct jpeg_decompress_struct d;
    struct jerr e;
    memset(&e, 0, sizeof e);
    uint8_t *volatile buf = NULL;
    d.err = jpeg_std_error(&e.mgr);
    e.mgr.error_exit = jerr_exit;
    e.mgr.emit_message = jerr_quiet;
    e.why = why;
    e.whylen = whylen;
    e.max_ms = l->max_ms;
    clock_gettime(CLOCK_MONOTONIC, &e.start);
    if (setjmp(e.jmp)) {
        jpeg_destroy_decompress(&d);
        free(buf);
        return e.code ? e.code : -FX_EBADMSG;
    }
    jpeg_create_decompress(&d);
    /* coefficients of a progressive image: 2 bytes per sample, 3 samples */
    d.mem->max_memory_to_use = (long)(l->max_pixels > ((size_t)1 << 28) ? (size_t)1 << 31 : l->max_pixels * 8);
    e.progress.progress_monitor = jprogress;
    d.progress = &e.progress;
    jpeg_mem_src(&d, data, (unsigned long)len);
    jpeg_read_header(&d, TRUE);
    int r = fx_image_check_size("JPEG", d.image_width, d.image_height, l, why, whylen);
    if (r < 0) {
        e.code = r;
        longjmp(e.jmp, 1);
    }
    d.out_color_space = JCS_RGB; /* grey and CMYK/YCCK too: libjpeg-turbo converts */
    if (d.jpeg_color_space == JCS_CMYK || d.jpeg_color_space == JCS_YCCK) {
        fx_image_why(why, whylen, "JPEG: CMYK images are not supported");
        e.code = -FX_ENOTSUP;
        longjmp(e.jmp, 1);
    }
    jpeg_start_decompress(&d);
    if (d.output_components != 3) {
        fx_image_why(why, whylen, "JPEG: %d output components", d.output_components);
        e.code = -FX_EBADMSG;
        longjmp(e.jmp, 1);
    }
    size_t stride = (size_t)d.output_width * 3;
    buf = malloc(stride * d.output_height);
    if (!buf) {
        fx_image_why(why, whylen, "JPEG: out of memory for %ux%u", d.output_width, d.output_height);
        e.code = -FX_ENOMEM;
        longjmp(e.jmp, 1);
    }
    while (d.output_scanline < d.output_height) {
        JSAMPROW row = buf + stride * d.output_scanline;
        if (jpeg_read_scanlines(&d, &row, 1) != 1) {
            fx_image_why(why, whylen, "JPEG: truncated at row %u", d.output_scanline);
            e.code = -FX_EBADMSG;
            longjmp(e.jmp, 1);
        }
    }
    jpeg_finish_decompress(&d);
    *w = (int32_t)d.output_width;
    *h = (int32_t)d.output_height;
    jpeg_destroy_decompress(&d);
    *rgb = buf;
    return 0;
}

#else /* FX_NO_JPEG */
int fx_jpeg_decode(const uint8_t *data, size_t len, const fx_image_limits *l, uint8_t **rgb, int32_t *w, int32_t *h,
                   char *why, size_t whylen)
{
    (void)data, (void)len, (void)l, (void)rgb, (void)w, (void)h;
    fx_image_why(why, whylen, "JPEG: built without libjpeg (FX_NO_JPEG; install libjpeg62-turbo-dev)");
    return -FX_ENOTSUP;
}
#endif
