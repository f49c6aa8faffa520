/* SPDX-License-Identifier: MIT */
/* GIF through giflib, frame by frame. DGifSlurp would hold every frame's
 * pixels (a 10,000-frame file of tiny LZW runs expands to gigabytes), so
 * the file is walked twice: at open, a pass skipping pixel data builds the
 * frame table (delays, disposal, rectangles; at most max_frames entries);
 * for a frame, the decoder continues from where it is (or restarts from
 * frame 0) and composites each frame on the canvas, one row at a time. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE /* clock_gettime under -std=c11, whoever compiles it */
#endif
#include <stdlib.h>
#include <string.h>

#include "fixel/error.h"
#include "image_int.h"

#ifndef FX_NO_GIF
#include <gif_lib.h>

typedef struct gframe {
    int left, top, w, h;
    int delay_cs, disposal, transparent; /* transparent: -1 for none */
} gframe;

struct fx_gif {
    const uint8_t *data;
    size_t len, pos;
    GifFileType *dec; /* the running decoder, positioned after frame done */
    int done;         /* last frame composited on the canvas, -1 none */
    int32_t w, h;
    int nframes;
    gframe *frames;
    uint8_t *prev;  /* the canvas before a frame with disposal 3 */
    uint8_t *line;  /* one row of colour indices */
    fx_image_limits lim;
};

static int gread(GifFileType *gf, GifByteType *out, int n)
{
    fx_gif *g = gf->UserData;
    size_t left = g->len - g->pos, k = n < 0 ? 0 : (size_t)n;
    if (k > left)
        k = left;
    memcpy(out, g->data + g->pos, k);
    g->pos += k;
    return (int)k;
}

static void gclose_dec(fx_gif *g)
{
    if (g->dec) {
        int err;
        DGifCloseFile(g->dec, &err);
        g->dec = NULL;
    }
}

static int gstart(fx_gif *g, char *why, size_t whylen)
{
    gclose_dec(g);
    g->pos = 0;
    g->done = -1;
    int err = 0;
    g->dec = DGifOpen(g, gread, &err);
    if (!g->dec) {
        const char *s = GifErrorString(err);
        fx_image_why(why, whylen, "GIF: %s", s ? s : "cannot open");
        return -FX_EBADMSG;
    }
    return 0;
}

static int gfail(fx_gif *g, char *why, size_t whylen)
{
    const char *s = g->dec ? GifErrorString(g->dec->Error) : NULL;
    fx_image_why(why, whylen, "GIF: %s", s ? s : "malformed data");
    gclose_dec(g);
    g->done = -1;
    return -FX_EBADMSG;
}

/* Skip the rest of an extension or a frame's LZW data. */
static int skip_ext(GifFileType *d, GifByteType *ext)
{
    while (ext)
        if (DGifGetExtensionNext(d, &ext) == GIF_ERROR)
            return -1;
    return 0;
}

int fx_gif_open(fx_gif **out, const uint8_t *data, size_t len, const fx_image_limits *l, int32_t *w, int32_t *h,
                int *frames, int *loops, char *why, size_t whylen)
{
    *out = NULL;
    fx_gif *g = calloc(1, sizeof *g);
    if (!g)
        return -FX_ENOMEM;
    g->data = data;
    g->len = len;
    g->lim = *l;
    int r = gstart(g, why, whylen);
    if (r < 0)
        goto fail;
    GifFileType *d = g->dec;
    r = fx_image_check_size("GIF", (uint64_t)(d->SWidth < 0 ? 0 : d->SWidth), (uint64_t)(d->SHeight < 0 ? 0 : d->SHeight),
                            l, why, whylen);
    if (r < 0)
        goto fail;
    g->w = d->SWidth;
    g->h = d->SHeight;
    int cap = 0, plays = 1;
    gframe pending = {0, 0, 0, 0, 0, 0, -1};
    for (;;) {
        GifRecordType t;
        if (DGifGetRecordType(d, &t) == GIF_ERROR) {
            r = gfail(g, why, whylen);
            goto fail;
        }
        if (t == TERMINATE_RECORD_TYPE)
            break;
        if (t == EXTENSION_RECORD_TYPE) {
            int code;
            GifByteType *ext;
            if (DGifGetExtension(d, &code, &ext) == GIF_ERROR) {
                r = gfail(g, why, whylen);
                goto fail;
            }
            if (code == GRAPHICS_EXT_FUNC_CODE && ext && ext[0] >= 4) {
                pending.disposal = (ext[1] >> 2) & 7;
                pending.delay_cs = ext[2] | ext[3] << 8;
                pending.transparent = (ext[1] & 1) ? ext[4] : -1;
            } else if (code == APPLICATION_EXT_FUNC_CODE && ext && ext[0] == 11 && !memcmp(ext + 1, "NETSCAPE2.0", 11)) {
                if (DGifGetExtensionNext(d, &ext) == GIF_ERROR) {
                    r = gfail(g, why, whylen);
                    goto fail;
                }
                if (ext && ext[0] >= 3 && ext[1] == 1) {
                    int n = ext[2] | ext[3] << 8;
                    plays = n == 0 ? 0 : n + 1; /* the extension counts repeats */
                }
            }
            if (skip_ext(d, ext) < 0) {
                r = gfail(g, why, whylen);
                goto fail;
            }
            continue;
        }
        if (t != IMAGE_DESC_RECORD_TYPE)
            continue;
        if (DGifGetImageDesc(d) == GIF_ERROR) {
            r = gfail(g, why, whylen);
            goto fail;
        }
        if ((uint32_t)g->nframes >= l->max_frames) {
            fx_image_why(why, whylen, "GIF: more than %u frames (fx_image_limits.max_frames)", l->max_frames);
            r = -FX_EFBIG;
            goto fail;
        }
        GifImageDesc *im = &d->Image;
        r = fx_image_check_size("GIF frame", (uint64_t)(im->Width < 0 ? 0 : im->Width),
                                (uint64_t)(im->Height < 0 ? 0 : im->Height), l, why, whylen);
        if (r < 0)
            goto fail;
        if (!im->ColorMap && !d->SColorMap) {
            fx_image_why(why, whylen, "GIF: frame %d has no colour table", g->nframes);
            r = -FX_EBADMSG;
            goto fail;
        }
        if (g->nframes == cap) {
            cap = cap ? cap * 2 : 16;
            gframe *nf = realloc(g->frames, sizeof *nf * (size_t)cap);
            if (!nf) {
                r = -FX_ENOMEM;
                goto fail;
            }
            g->frames = nf;
        }
        pending.left = im->Left, pending.top = im->Top, pending.w = im->Width, pending.h = im->Height;
        g->frames[g->nframes++] = pending;
        pending = (gframe){0, 0, 0, 0, 0, 0, -1};
        int cs;
        GifByteType *block;
        if (DGifGetCode(d, &cs, &block) == GIF_ERROR) {
            r = gfail(g, why, whylen);
            goto fail;
        }
        while (block)
            if (DGifGetCodeNext(d, &block) == GIF_ERROR) {
                r = gfail(g, why, whylen);
                goto fail;
            }
    }
    if (g->nframes == 0) {
        fx_image_why(why, whylen, "GIF: no frames");
        r = -FX_EBADMSG;
        goto fail;
    }
    size_t maxw = (size_t)g->w;
    for (int i = 0; i < g->nframes; i++)
        if ((size_t)g->frames[i].w > maxw)
            maxw = (size_t)g->frames[i].w;
    g->line = malloc(maxw);
    if (!g->line) {
        r = -FX_ENOMEM;
        goto fail;
    }
    gclose_dec(g);
    g->done = -1;
    *w = g->w;
    *h = g->h;
    *frames = g->nframes;
    *loops = plays;
    *out = g;
    return 0;
fail:
    fx_gif_close(g);
    return r;
}

int fx_gif_delay_ms(const fx_gif *g, int n)
{
    int cs = g->frames[n].delay_cs;
    return cs <= 1 ? 100 : cs * 10; /* 0 and 10 ms play at 100 ms, as browsers do */
}

static void rect_clip(const fx_gif *g, const gframe *f, int *x0, int *y0, int *x1, int *y1)
{
    *x0 = f->left, *y0 = f->top;
    *x1 = f->left + f->w, *y1 = f->top + f->h;
    if (*x1 > g->w)
        *x1 = g->w;
    if (*y1 > g->h)
        *y1 = g->h;
}

/* Decode the next frame (done + 1) of the running decoder onto canvas. */
static int gnext(fx_gif *g, uint8_t *canvas, char *why, size_t whylen)
{
    GifFileType *d = g->dec;
    int n = g->done + 1;
    const gframe *f = &g->frames[n];
    /* the previous frame's disposal, before this one draws */
    if (n > 0) {
        const gframe *p = &g->frames[n - 1];
        int x0, y0, x1, y1;
        rect_clip(g, p, &x0, &y0, &x1, &y1);
        if (p->disposal == 2 || (p->disposal == 3 && g->prev))
            for (int y = y0; y < y1; y++) {
                size_t o = ((size_t)y * (size_t)g->w + (size_t)x0) * 3, k = (size_t)(x1 - x0) * 3;
                if (x1 > x0) {
                    if (p->disposal == 2)
                        memset(canvas + o, 0, k);
                    else
                        memcpy(canvas + o, g->prev + o, k);
                }
            }
    }
    if (f->disposal == 3) {
        size_t bytes = (size_t)g->w * (size_t)g->h * 3;
        if (!g->prev && !(g->prev = malloc(bytes)))
            return -FX_ENOMEM;
        memcpy(g->prev, canvas, bytes);
    }
    struct timespec start;
    clock_gettime(CLOCK_MONOTONIC, &start);
    for (;;) {
        GifRecordType t;
        if (DGifGetRecordType(d, &t) == GIF_ERROR)
            return gfail(g, why, whylen);
        if (t == TERMINATE_RECORD_TYPE)
            return gfail(g, why, whylen); /* the table said there was one more */
        if (t == EXTENSION_RECORD_TYPE) {
            int code;
            GifByteType *ext;
            if (DGifGetExtension(d, &code, &ext) == GIF_ERROR || skip_ext(d, ext) < 0)
                return gfail(g, why, whylen);
            continue;
        }
        if (t == IMAGE_DESC_RECORD_TYPE)
            break;
    }
    if (DGifGetImageDesc(d) == GIF_ERROR)
        return gfail(g, why, whylen);
    const ColorMapObject *cm = d->Image.ColorMap ? d->Image.ColorMap : d->SColorMap;
    int interlaced = d->Image.Interlace;
    static const int start_row[] = {0, 4, 2, 1}, step[] = {8, 8, 4, 2};
    int pass = 0, row = 0;
    for (int i = 0; i < f->h; i++) {
        if (DGifGetLine(d, g->line, f->w) == GIF_ERROR)
            return gfail(g, why, whylen);
        if ((i & 63) == 0 && fx_image_elapsed_ms(&start) > g->lim.max_ms) {
            fx_image_why(why, whylen, "GIF: frame %d took more than %u ms (fx_image_limits.max_ms)", n,
                         g->lim.max_ms);
            gclose_dec(g);
            g->done = -1;
            return -FX_EFBIG;
        }
        int y;
        if (interlaced) {
            while (pass < 4 && row >= f->h) {
                pass++;
                row = pass < 4 ? start_row[pass] : 0;
            }
            y = row;
            row += step[pass < 4 ? pass : 3];
        } else {
            y = i;
        }
        y += f->top;
        if (y >= g->h)
            continue;
        for (int x = 0; x < f->w; x++) {
            int cx = f->left + x, ci = g->line[x];
            if (cx >= g->w)
                break;
            if (ci == f->transparent)
                continue;
            uint8_t *px = canvas + ((size_t)y * (size_t)g->w + (size_t)cx) * 3;
            if (ci < cm->ColorCount) {
                px[0] = cm->Colors[ci].Red, px[1] = cm->Colors[ci].Green, px[2] = cm->Colors[ci].Blue;
            } else {
                px[0] = px[1] = px[2] = 0; /* an index past the table: black, as browsers draw it */
            }
        }
    }
    g->done = n;
    return 0;
}

int fx_gif_frame(fx_gif *g, int n, uint8_t *canvas, char *why, size_t whylen)
{
    if (!g->dec || n <= g->done) {
        int r = gstart(g, why, whylen);
        if (r < 0)
            return r;
        memset(canvas, 0, (size_t)g->w * (size_t)g->h * 3);
    }
    while (g->done < n) {
        int r = gnext(g, canvas, why, whylen);
        if (r < 0)
            return r;
    }
    return 0;
}

void fx_gif_close(fx_gif *g)
{
    if (!g)
        return;
    gclose_dec(g);
    free(g->frames);
    free(g->prev);
    free(g->line);
    free(g);
}

#else /* FX_NO_GIF */
int fx_gif_open(fx_gif **out, const uint8_t *data, size_t len, const fx_image_limits *l, int32_t *w, int32_t *h,
                int *frames, int *loops, char *why, size_t whylen)
{
    (void)data, (void)len, (void)l, (void)w, (void)h, (void)frames, (void)loops;
    *out = NULL;
    fx_image_why(why, whylen, "GIF: built without giflib (FX_NO_GIF; install libgif-dev)");
    return -FX_ENOTSUP;
}
int fx_gif_delay_ms(const fx_gif *g, int n)
{
    (void)g, (void)n;
    return 0;
}
int fx_gif_frame(fx_gif *g, int n, uint8_t *canvas, char *why, size_t whylen)
{
    (void)g, (void)n, (void)canvas, (void)why, (void)whylen;
    return -FX_ENOTSUP;
}
void fx_gif_close(fx_gif *g)
{
    (void)g;
}
#endif
