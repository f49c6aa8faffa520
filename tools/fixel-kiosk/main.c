/* SPDX-License-Identifier: MIT */
/* fixel-kiosk — a dashboard for wall and panel displays.
 *
 * A config file (see examples/kiosk-*.conf and docs/kiosk.md) lays widgets
 * out on a grid; "name=value" or CSV lines on stdin, a named pipe or a
 * growing file update them. Everything lives in fixed arrays (kiosk.h) except
 * decoded images, one bounded buffer per image widget, freed before the next
 * load: a kiosk that runs for months holds the same memory as one that just
 * started (make kiosk-soak measures it). Only widgets whose picture changed
 * are redrawn and presented (damage rectangles).
 */
#include "kiosk.h"
#include "kiosk_mqtt.h"
#include "kiosk_screen.h"

#include <errno.h>
#include <fcntl.h>
#include <malloc.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "fixel/app.h"
#include "fixel/env.h"
#include "fixel/files.h"
#include "fixel/circle.h"
#include "fixel/colormap.h"
#include "fixel/draw.h"
#include "fixel/error.h"
#include "fixel/fill.h"
#include "fixel/fixed.h"
#include "fixel/font.h"
#include "fixel/line.h"
#include "fixel/image.h"
#include "fixel/memfb.h"
#include "fixel/par.h"
#include "fixel/texture.h"
#include "fixel/version.h"
#include "fixel/viz.h"

#ifndef FX_NO_QR
#include <qrencode.h>
#endif

#ifndef FX_NO_PNG
#include <png.h>
#endif
#ifdef KIOSK_HAVE_SYSTEMD
#include <systemd/sd-daemon.h>
#else
/* without libsystemd: no service manager to tell */
static int sd_notify(int unset, const char *state) { (void)unset; (void)state; return 0; }
#endif

#define TITLE_H 22
#define STATUS_H 14
#define GAP 4
#define DIM 0xFF8A94A3u
#define STALE_FG 0xFF6B7280u
#define AMBER 0xFFFFB300u
#define BAD_RED 0xFFEF5350u
#define EMPTY_CELL 0xFF2A3441u

/* Images larger than this are refused before any pixel memory is taken:
 * 2048x2048 RGB is 12 MiB, plenty for a panel a few hundred pixels wide. */
#define IMG_MAX_DIM 4096
#define IMG_MAX_PIXELS (2048 * 2048)

enum { IMG_NONE, IMG_OK, IMG_MISSING, IMG_BAD, IMG_HUGE };

typedef struct kimg {
    uint8_t *rgb;    /* decoded R, G, B bytes, w*h*3 */
    int32_t w, h;
    int64_t file_size; /* of the file being loaded: PPM data must fit in it */
    int state, tried;
    char path[KIOSK_PATH_MAX]; /* what the last attempt read */
    uint32_t gen;
    int have_id;     /* the file existed at the last attempt */
    dev_t dev;
    ino_t ino;
    off_t size;
    struct timespec mtim;
    /* an animated GIF: rgb holds the current frame */
    fx_anim *anim;
    int frame, plays;     /* plays: loops completed */
    int64_t next_ms;      /* when the next frame is due */
} kimg;

typedef struct kline {
    char buf[KIOSK_LINE_MAX + 1];
    size_t len;
    int overlong;
} kline;

/* One screen: the app's own display, or one added for an output section
 * ("output NAME" in the config). Widgets know theirs (kiosk_widget.screen). */
typedef struct kscreen {
    fx_display *d;   /* NULL: the app's own display */
    int32_t W, H;
    int full, status; /* at its next frame: redraw everything / the status line */
} kscreen;

/* qr widgets: the modules of the text last encoded (encoded between
 * frames, never while bands of a frame are drawn on threads) */
typedef struct kqr {
    char text[KIOSK_TEXT_MAX];
    int tried;
    int size;       /* modules a side; 0: nothing to show */
    uint8_t *mods;  /* size * size, 1 dark */
    const char *why; /* when size is 0 */
} kqr;

typedef struct kiosk {
    kiosk_config cfg;
    fx_app *app;
    int headless;
    int64_t now_ms;
    uint32_t lines, bad, ignored;
    uint8_t dirty[KIOSK_MAX_WIDGETS];
    uint8_t stale[KIOSK_MAX_WIDGETS];
    int status_dirty, full;
    int64_t clock_sec;
    int64_t wall_sec; /* the clock widgets' time of day, read once per frame (every band shows the same) */
    int fd;
    /* one line buffer per source: a partial stdin line must not swallow an
     * MQTT payload arriving meanwhile (issue #24 review) */
    kline in, mqline;
    int frame_end; /* headless: an "@frame" line ended the frame */
    int64_t frame_step;
    kscreen scr[KIOSK_MAX_OUTPUTS];
    int nscr;        /* 1, or the config's output sections */
    int always_full; /* --full: redraw everything each frame (tests check damage against it) */
    int threads;     /* --threads: a frame's drawing in bands of rows on this many threads */
    kimg img[KIOSK_MAX_WIDGETS];
    kqr qr[KIOSK_MAX_WIDGETS];
    uint32_t img_errors;  /* image loads that failed (missing, corrupt, too large) */
    /* live mode: MQTT, control and status (docs/kiosk.md, "MQTT") */
    const char *cfgpath;
    const char *live_out; /* --out in live mode: DIR/live.ppm after every frame drawn */
    kmq *mq;
    kmq_state mst;        /* as last seen by the main loop */
    uint32_t frames, frames_at_status;
    int64_t start_ms, status_ms;
    int status_due;
    int screen_on, brightness;
    kiosk_screen_ops screen;
    kiosk_screen_hw screen_hw;
    kiosk_power pw;             /* schedule, idle blanking, waking touches */
    int swallow_up;             /* the waking press was swallowed: so is its release */
    int64_t identify_until;
    int identify_phase;
    uint32_t reloads;
    char cfg_error[300];  /* why the last reload was refused ("" : it was not) */
    int ready_sent;       /* systemd: READY=1 after the first frame */
    int64_t wd_ms, wd_last; /* systemd watchdog: ping interval (0: none), last ping */
    /* pages and touch (kiosk_pages.h, docs/kiosk.md "Pages and touch") */
    int page;             /* the page shown */
    int64_t page_since;   /* when it came up (the carousel's dwell counts from here) */
    int press_down;       /* a press is held */
    int press_x, press_y; /* where it started */
    int pressed;          /* the button widget drawn pressed, -1: none */
    int64_t pressed_until; /* after the release it stays drawn pressed until then */
    int press_failed;     /* the last tap's message could not be sent: drawn red while pressed */
    uint32_t presses, press_errors;
} kiosk;

static int64_t mono_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (int64_t)ts.tv_sec * 1000 + ts.tv_nsec / 1000000;
}

/* ---- data ---- */

static void mark_sources(kiosk *k, uint32_t mask)
{
    for (int i = 0; i < k->cfg.nwidgets; i++)
        if (k->cfg.widgets[i].source >= 0 && (mask >> k->cfg.widgets[i].source & 1)) k->dirty[i] = 1;
}

static void end_line(kiosk *k, kline *lb)
{
    const char *l = lb->buf;
    size_t n = lb->len;
    lb->len = 0;
    if (lb->overlong) {
        lb->overlong = 0;
        k->lines++;
        k->bad++;
        k->status_dirty = 1;
        return;
    }
    /* "@frame [MS]": frame boundary of a scripted (headless) stream; live
     * streams may carry it too and it is harmless there. */
    if (n >= 6 && memcmp(l, "@frame", 6) == 0) {
        int64_t ms = 1000;
        if (n > 7) {
            size_t a = 7;
            while (a < n && l[a] == ' ') a++;
            if (kiosk_parse_milli(l + a, n - a, &ms) == 0) ms /= 1000;
            else ms = 1000;
        }
        k->frame_step = ms < 0 ? 0 : ms;
        k->frame_end = 1;
        return;
    }
    int s = -1;
    int r = kiosk_data_line(&k->cfg, l, n, k->now_ms, &s);
    if (r == KIOSK_LINE_IGNORED && (n == 0 || l[0] == '#')) return;
    k->lines++;
    k->status_dirty = 1;
    if (r == KIOSK_LINE_BAD) k->bad++;
    else if (r == KIOSK_LINE_IGNORED) k->ignored++;
    else if (r == KIOSK_LINE_OK) mark_sources(k, k->cfg.changed);
}

static void feed(kiosk *k, kline *lb, const char *buf, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        if (buf[i] == '\n') { end_line(k, lb); continue; }
        if (lb->len < KIOSK_LINE_MAX) lb->buf[lb->len++] = buf[i];
        else lb->overlong = 1;
    }
}

/* Headless: read until an "@frame" line or the end of the stream. */
static void feed_frame(kiosk *k)
{
    char c;
    k->frame_end = 0;
    k->frame_step = 1000;
    while (!k->frame_end && k->fd >= 0) {
        ssize_t r = read(k->fd, &c, 1);
        if (r <= 0) {
            if (k->in.len || k->in.overlong) end_line(k, &k->in);
            if (k->fd > 0) close(k->fd);
            k->fd = -1;
            break;
        }
        feed(k, &k->in, &c, 1);
    }
}

/* Live: whatever is there now; a regular file is followed as it grows. */
static void feed_available(kiosk *k)
{
    char buf[4096];
    for (int rounds = 0; rounds < 64 && k->fd >= 0; rounds++) {
        ssize_t r = read(k->fd, buf, sizeof buf);
        if (r > 0) { feed(k, &k->in, buf, (size_t)r); continue; }
        if (r < 0 && errno == EINTR) continue;
        break;
    }
}

/* ---- images ---- */

/* The next PPM header number; '#' comments run to the end of the line. */
static int ppm_num(FILE *f, int32_t *out)
{
    int c = fgetc(f);
    for (;;) {
        while (c == ' ' || c == '\t' || c == '\n' || c == '\r') c = fgetc(f);
        if (c != '#') break;
        while (c != EOF && c != '\n') c = fgetc(f);
    }
    int32_t v = 0, n = 0;
    for (; c >= '0' && c <= '9'; c = fgetc(f), n++) {
        if (n == 7) return -1;
        v = v * 10 + (c - '0');
    }
    /* exactly one whitespace byte ends the number (the last one before the pixels) */
    if (n == 0 || !(c == ' ' || c == '\t' || c == '\n' || c == '\r')) return -1;
    *out = v;
    return 0;
}

static int dims_ok(int64_t w, int64_t h)
{
    return w >= 1 && h >= 1 && w <= IMG_MAX_DIM && h <= IMG_MAX_DIM && w * h <= IMG_MAX_PIXELS;
}

static int load_ppm(FILE *f, kimg *m)
{
    int32_t w, h, maxval;
    if (fgetc(f) != 'P' || fgetc(f) != '6' || ppm_num(f, &w) || ppm_num(f, &h) || ppm_num(f, &maxval) ||
        maxval != 255)
        return IMG_BAD;
    if (!dims_ok(w, h)) return IMG_HUGE;
    size_t bytes = (size_t)w * (size_t)h * 3;
    if ((int64_t)bytes > m->file_size) return IMG_BAD; /* truncated: refused before allocating */
    if (!(m->rgb = malloc(bytes))) return IMG_HUGE;
    if (fread(m->rgb, 1, bytes, f) != bytes) return IMG_BAD;
    m->w = w;
    m->h = h;
    return IMG_OK;
}

static int load_png(FILE *f, kimg *m)
{
#ifndef FX_NO_PNG
    /* libpng's own limits (memfb.c): ancillary chunks skipped unread (a tEXt
     * chunk declaring 2 GiB took 2 GB per load), sizes refused before any
     * pixel memory, alpha dropped as docs/kiosk.md says (it was composited
     * onto black), issue #26 */
    int r = fx_read_png_rgb_stream(f, IMG_MAX_DIM, IMG_MAX_PIXELS, &m->rgb, &m->w, &m->h);
    return r == 0 ? IMG_OK : r == -FX_EFBIG ? IMG_HUGE : IMG_BAD;
#else
    (void)f;
    (void)m;
    return IMG_BAD; /* built without libpng: PPM only */
#endif
}

/* JPEG, GIF (its first frame) and WebP: boards/image/, same limits */
static int load_decoded(FILE *f, kimg *m, const char *path)
{
    fx_image_limits l;
    fx_image_limits_init(&l);
    l.max_side = IMG_MAX_DIM;
    l.max_pixels = IMG_MAX_PIXELS;
    l.max_bytes = (size_t)16 << 20;
    char why[200];
    unsigned char magic[6];
    int gif = fread(magic, 1, 6, f) == 6 && fx_image_sniff(magic, 6) == FX_IMAGE_GIF;
    rewind(f);
    why[0] = 0;
    if (!gif) {
        int r = fx_image_read_rgb(f, &l, &m->rgb, &m->w, &m->h, why, sizeof why);
        /* the cell says "bad image" or "too large"; the log says which limit */
        if (r < 0) fprintf(stderr, "fixel-kiosk: %s: %s\n", path, why[0] ? why : fx_strerror(r));
        return r == 0 ? IMG_OK : r == -FX_EFBIG ? IMG_HUGE : IMG_BAD;
    }
    /* GIF: kept open to animate (bounded: the file, two canvases) */
    if (m->file_size > (int64_t)l.max_bytes) return IMG_HUGE;
    size_t len = (size_t)m->file_size;
    uint8_t *data = malloc(len ? len : 1);
    if (!data) return IMG_HUGE;
    if (fread(data, 1, len, f) != len) { free(data); return IMG_BAD; }
    int r = fx_anim_open(&m->anim, data, len, &l, why, sizeof why);
    free(data);
    const uint8_t *px;
    if (r == 0 && (r = fx_anim_frame(m->anim, 0, &px, why, sizeof why)) == 0) {
        m->w = fx_anim_width(m->anim), m->h = fx_anim_height(m->anim);
        if (!(m->rgb = malloc((size_t)m->w * (size_t)m->h * 3))) r = -FX_ENOMEM;
        else memcpy(m->rgb, px, (size_t)m->w * (size_t)m->h * 3);
    }
    if (r == 0 && fx_anim_frames(m->anim) < 2) { fx_anim_close(m->anim); m->anim = NULL; }
    if (r < 0) { fx_anim_close(m->anim); m->anim = NULL; }
    m->frame = 0;
    m->plays = 0;
    m->next_ms = -1; /* the clock starts when it is first shown */
    if (r < 0) fprintf(stderr, "fixel-kiosk: %s: %s\n", path, why[0] ? why : fx_strerror(r));
    return r == 0 ? IMG_OK : r == -FX_EFBIG ? IMG_HUGE : IMG_BAD;
}

static int load_image(const char *path, kimg *m)
{
    /* never blocks on open (a FIFO named as the image), regular files only */
    int64_t size = 0;
    FILE *f = fx_fopen_regular(path, &size, NULL, 0);
    if (!f) return errno == EISDIR || errno == EOPNOTSUPP ? IMG_BAD : IMG_MISSING;
    m->file_size = (off_t)size;
    unsigned char magic[12]; /* WebP's RIFF....WEBP */
    size_t n = fread(magic, 1, sizeof magic, f);
    int r = IMG_BAD;
    rewind(f);
    if (n >= 8 && !memcmp(magic, "\x89PNG\r\n\x1a\n", 8)) r = load_png(f, m);
    else if (n >= 2 && magic[0] == 'P' && magic[1] == '6') r = load_ppm(f, m);
    else if (fx_image_sniff(magic, n) != FX_IMAGE_UNKNOWN) r = load_decoded(f, m, path);
    fclose(f);
    if (r != IMG_OK) {
        free(m->rgb);
        m->rgb = NULL;
        fx_anim_close(m->anim);
        m->anim = NULL;
    }
    return r;
}

/* Reload every image whose path was named again or whose file changed
 * (device, inode, size or mtime): a writer that replaces the file by
 * rename and one that rewrites it in place are both seen. */
static void animate_images(kiosk *k);

static void check_images(kiosk *k)
{
    animate_images(k);
    for (int i = 0; i < k->cfg.nwidgets; i++) {
        const kiosk_widget *w = &k->cfg.widgets[i];
        if (w->type != KIOSK_IMAGE) continue;
        const kiosk_source *so = &k->cfg.sources[w->source];
        kimg *m = &k->img[i];
        struct stat st;
        int have = so->path[0] && stat(so->path, &st) == 0;
        if (m->tried && m->gen == so->path_gen && !strcmp(m->path, so->path) && have == m->have_id &&
            (!have || (st.st_dev == m->dev && st.st_ino == m->ino && st.st_size == m->size &&
                       st.st_mtim.tv_sec == m->mtim.tv_sec && st.st_mtim.tv_nsec == m->mtim.tv_nsec)))
            continue;
        m->tried = 1;
        m->gen = so->path_gen;
        snprintf(m->path, sizeof m->path, "%s", so->path);
        m->have_id = have;
        if (have) {
            m->dev = st.st_dev;
            m->ino = st.st_ino;
            m->size = st.st_size;
            m->mtim = st.st_mtim;
        }
        free(m->rgb);
        m->rgb = NULL;
        fx_anim_close(m->anim);
        m->anim = NULL;
        /* only regular files: opening a FIFO or a device could block the kiosk */
        m->state = !so->path[0] ? IMG_NONE : !have ? IMG_MISSING : !S_ISREG(st.st_mode) ? IMG_BAD
                 : load_image(so->path, m);
        if (m->anim) m->next_ms = k->now_ms + fx_anim_delay_ms(m->anim, 0); /* frame 0 shows from now */
        if (m->state != IMG_OK && m->state != IMG_NONE) k->img_errors++;
        k->dirty[i] = 1;
        k->status_dirty = 1;
    }
}

/* Animated GIFs: each frame shown for its own delay (the GIF's, 0 and 10
 * ms as 100 ms), looping as the file says; frames late by more than one
 * delay are skipped, not played fast. */
static void animate_images(kiosk *k)
{
    for (int i = 0; i < k->cfg.nwidgets; i++) {
        kimg *m = &k->img[i];
        if (!m->anim || m->state != IMG_OK || !m->rgb) continue;
        int n = fx_anim_frames(m->anim), loops = fx_anim_loops(m->anim);
        if (m->next_ms < 0) m->next_ms = k->now_ms + fx_anim_delay_ms(m->anim, m->frame);
        int step = 0;
        while (k->now_ms >= m->next_ms && step < n) {
            if (m->frame + 1 == n) {
                if (loops && m->plays + 1 >= loops) { m->next_ms = INT64_MAX; break; }
                m->plays++;
            }
            m->frame = (m->frame + 1) % n;
            m->next_ms += fx_anim_delay_ms(m->anim, m->frame);
            step++;
        }
        if (k->now_ms >= m->next_ms && m->next_ms != INT64_MAX) m->next_ms = k->now_ms + fx_anim_delay_ms(m->anim, m->frame);
        if (!step) continue;
        const uint8_t *px;
        char why[200];
        if (fx_anim_frame(m->anim, m->frame, &px, why, sizeof why) == 0)
            memcpy(m->rgb, px, (size_t)m->w * (size_t)m->h * 3);
        else { fx_anim_close(m->anim); m->anim = NULL; }
        k->dirty[i] = 1;
    }
}

/* Encode each qr widget's text again when it changed: the source's last
 * value, else the configured text=. */
static void check_qr(kiosk *k)
{
    for (int i = 0; i < k->cfg.nwidgets; i++) {
        const kiosk_widget *w = &k->cfg.widgets[i];
        if (w->type != KIOSK_QR) continue;
        const kiosk_source *so = w->source >= 0 ? &k->cfg.sources[w->source] : NULL;
        const char *text = so && so->updates && so->text[0] ? so->text : w->qrtext;
        kqr *q = &k->qr[i];
        if (q->tried && !strcmp(q->text, text)) continue;
        q->tried = 1;
        snprintf(q->text, sizeof q->text, "%s", text);
        free(q->mods);
        q->mods = NULL;
        q->size = 0;
        q->why = "no data";
        k->dirty[i] = 1;
        if (!text[0]) continue;
#ifndef FX_NO_QR
        static const QRecLevel levels[] = {QR_ECLEVEL_L, QR_ECLEVEL_M, QR_ECLEVEL_Q, QR_ECLEVEL_H};
        QRcode *c = QRcode_encodeString8bit(text, 0, levels[w->qr_ecc & 3]);
        if (!c || c->width < 21 || !(q->mods = malloc((size_t)c->width * (size_t)c->width))) {
            q->why = "cannot encode";
            if (c) QRcode_free(c);
            continue;
        }
        for (int j = 0; j < c->width * c->width; j++) q->mods[j] = c->data[j] & 1;
        q->size = c->width;
        QRcode_free(c);
#else
        q->why = "no libqrencode";
#endif
    }
}

static void free_images(kiosk *k)
{
    for (int i = 0; i < KIOSK_MAX_WIDGETS; i++) {
        free(k->img[i].rgb);
        fx_anim_close(k->img[i].anim);
        k->img[i].anim = NULL;
        k->img[i].rgb = NULL;
        free(k->qr[i].mods);
        k->qr[i].mods = NULL;
    }
}

static void update_stale(kiosk *k)
{
    int64_t sec = k->now_ms / 1000;
    for (int i = 0; i < k->cfg.nwidgets; i++) {
        const kiosk_widget *w = &k->cfg.widgets[i];
        uint8_t st = 0;
        if (w->source >= 0) {
            const kiosk_source *s = &k->cfg.sources[w->source];
            /* never heard from counts as stale too, once the grace time passed */
            st = s->updates ? k->now_ms - s->last_ms > k->cfg.stale_ms : k->now_ms > k->cfg.stale_ms;
        } else if (sec != k->clock_sec)
            k->dirty[i] = 1;
        if (st != k->stale[i]) { k->stale[i] = st; k->dirty[i] = 1; k->status_dirty = 1; }
    }
    k->clock_sec = sec;
}

/* ---- drawing ---- */

static fx_rect widget_rect(const kiosk *k, const kiosk_widget *w)
{
    /* each page has a grid of its own; each output section too (the two do not mix) */
    const kiosk_output *o = k->cfg.noutputs ? &k->cfg.outputs[w->screen] : NULL;
    const kiosk_page *pg = &k->cfg.pg.pages[w->page];
    int cols = o ? o->cols : pg->cols, rows = o ? o->rows : pg->rows;
    int32_t top = (o ? o->title : k->cfg.title)[0] ? TITLE_H : 0;
    int32_t gw = k->scr[w->screen].W, gh = k->scr[w->screen].H - top - STATUS_H;
    fx_rect r;
    r.x0 = w->col * gw / cols + GAP;
    r.x1 = (w->col + w->w) * gw / cols - GAP / 2;
    r.y0 = top + w->row * gh / rows + GAP;
    r.y1 = top + (w->row + w->h) * gh / rows - GAP / 2;
    return r;
}

static void text_at(fx_ctx *c, int32_t x, int32_t y, int32_t scale, fx_color col, const char *s)
{
    fx_text_style st = {0};
    st.scale = scale;
    fx_ctx t = *c;
    t.text_style = &st;
    fx_ctx_set_color(&t, col);
    fx_text(&t, x, y, s);
}

static int32_t text_w(const char *s, int32_t scale)
{
    fx_text_style st = {0};
    int64_t w, h;
    st.scale = scale;
    fx_text_extent(&st, s, &w, &h);
    return (int32_t)w;
}

/* The largest scale (1..maxs) at which s fits w x h pixels. */
static int32_t fit_scale(const char *s, int32_t w, int32_t h, int32_t maxs)
{
    int32_t sc = maxs;
    while (sc > 1 && (text_w(s, sc) > w || 10 * sc > h)) sc--;
    return sc;
}

static void fill(fx_ctx *c, fx_color col, int32_t x, int32_t y, int32_t w, int32_t h)
{
    fx_ctx t = *c;
    fx_ctx_set_color(&t, col);
    fx_fill_rect(&t, x, y, w, h);
}

/* a * b / c for 0 <= a <= c, 0 <= b < 2^32, c > 0, without overflow: the
 * product in 96 bits, then long division (values are bounded by
 * KIOSK_VALUE_MAX, their differences not by much less than 2^61). */
static int64_t muldiv(uint64_t a, uint64_t b, uint64_t c)
{
    uint64_t lo = (a & 0xFFFFFFFFu) * b, mid = (a >> 32) * b;
    uint64_t p_lo = lo + (mid << 32), p_hi = (mid >> 32) + (p_lo < lo);
    uint64_t q = 0, rem = 0;
    for (int i = 127; i >= 0; i--) {
        uint64_t bit = i >= 64 ? (p_hi >> (i - 64)) & 1 : (p_lo >> i) & 1;
        rem = rem << 1 | bit;
        if (rem >= c) {
            rem -= c;
            if (i < 64) q |= (uint64_t)1 << i;
        }
    }
    return (int64_t)q;
}

static int64_t frac_permille(const kiosk_widget *w, int64_t v)
{
    if (w->max <= w->min) return 0;
    if (v <= w->min) return 0;
    if (v >= w->max) return 1000;
    return muldiv((uint64_t)(v - w->min), 1000, (uint64_t)(w->max - w->min));
}

static void value_text(const kiosk *k, const kiosk_widget *w, char *buf, size_t size)
{
    const kiosk_source *s = &k->cfg.sources[w->source];
    if (w->type == KIOSK_TEXT) snprintf(buf, size, "%s", s->updates ? s->text : "--");
    else if (!s->has_value) snprintf(buf, size, "--");
    else kiosk_format_milli(buf, size, s->value, w->decimals);
}

static void draw_gauge(kiosk *k, fx_ctx *c, const kiosk_widget *w, fx_rect r, fx_color acc, int stale)
{
    const kiosk_source *s = &k->cfg.sources[w->source];
    int32_t rw = r.x1 - r.x0, rh = r.y1 - r.y0;
    int32_t rad = (rw - 16) / 2, avail = rh - 18 - 22;
    if (rad > avail * 10 / 17) rad = avail * 10 / 17; /* the 270 degree dial is ~1.7 r tall */
    if (rad < 8) return;
    int32_t cx = r.x0 + rw / 2, cy = r.y0 + 18 + rad;
    int32_t thick = rad / 5 < 4 ? 4 : rad / 5;
    fx_ctx t = *c;
    fx_ctx_set_color(&t, 0xFF374151u);
    /* The dial's angles are y-up (the needle below uses cy - sin); fx_pie
     * turns with y down, so each slice is given mirrored: y-up a0 -> a1 is
     * -a1 -> -a0. */
    fx_pie(&t, cx, cy, rad, 0u - fx_angle_from_deg(225), 0u - fx_angle_from_deg(315));
    int64_t f = s->has_value ? frac_permille(w, s->value) : 0;
    fx_angle a225 = fx_angle_from_deg(225);
    fx_angle av = a225 - (fx_angle)((uint64_t)0xC0000000u * (uint64_t)f / 1000);
    if (f > 0) {
        fx_ctx_set_color(&t, acc);
        fx_pie(&t, cx, cy, rad, 0u - a225, 0u - av);
    }
    fx_ctx_set_color(&t, k->cfg.panel);
    fx_disc(&t, cx, cy, rad - thick);
    if (s->has_value) {
        int32_t nx = cx + (int32_t)(((int64_t)(rad - 2) * fx_cos(av)) >> 16);
        int32_t ny = cy - (int32_t)(((int64_t)(rad - 2) * fx_sin(av)) >> 16);
        fx_ctx_set_color(&t, stale ? STALE_FG : k->cfg.fg);
        for (int d = -1; d <= 1; d++) {
            fx_line(&t, cx + d, cy, nx + d, ny);
            fx_line(&t, cx, cy + d, nx, ny + d);
        }
        fx_disc(&t, cx, cy, 3);
    }
    char v[48], line[96];
    value_text(k, w, v, sizeof v);
    snprintf(line, sizeof line, "%s%s%s", v, w->unit[0] ? " " : "", w->unit);
    int32_t sc = fit_scale(line, rw - 12, r.y1 - (cy + rad / 2) - 4, 3);
    text_at(c, cx - text_w(line, sc) / 2, r.y1 - 10 * sc - 6, sc, stale ? STALE_FG : k->cfg.fg, line);
}

static void draw_spark(kiosk *k, fx_ctx *c, const kiosk_widget *w, fx_rect r, fx_color acc, int stale)
{
    const kiosk_source *s = &k->cfg.sources[w->source];
    uint32_t hist = (uint32_t)k->cfg.history, n = s->count < hist ? s->count : hist;
    int32_t x0 = r.x0 + 6, x1 = r.x1 - 7, y0 = r.y0 + 20, y1 = r.y1 - 7;
    char v[48], line[96];
    value_text(k, w, v, sizeof v);
    snprintf(line, sizeof line, "%s%s", v, w->unit);
    text_at(c, r.x1 - 6 - text_w(line, 1), r.y0 + 5, 1, stale ? STALE_FG : k->cfg.fg, line);
    if (x1 - x0 < 4 || y1 - y0 < 4) return;
    fx_ctx t = *c;
    fx_ctx_set_color(&t, 0xFF2A3441u);
    fx_line(&t, x0, y1, x1, y1);
    fx_line(&t, x0, (y0 + y1) / 2, x1, (y0 + y1) / 2);
    fx_line(&t, x0, y0, x1, y0);
    if (n == 0) return;
    int64_t lo = w->min, hi = w->max;
    if (lo >= hi) {
        lo = hi = kiosk_hist_at(s, n, 0);
        for (uint32_t i = 1; i < n; i++) {
            int64_t h = kiosk_hist_at(s, n, i);
            if (h < lo) lo = h;
            if (h > hi) hi = h;
        }
        if (lo == hi) { lo -= 1000; hi += 1000; }
    }
    int32_t px = 0, py = 0;
    fx_ctx_set_color(&t, stale ? STALE_FG : acc);
    for (uint32_t i = 0; i < n; i++) {
        int64_t h = kiosk_hist_at(s, n, i);
        if (h < lo) h = lo;
        if (h > hi) h = hi;
        int32_t x = x0 + (int32_t)((int64_t)(i + hist - n) * (x1 - x0) / (hist - 1));
        int32_t y = y1 - (int32_t)muldiv((uint64_t)(h - lo), (uint64_t)(y1 - y0), (uint64_t)(hi - lo));
        if (i) { fx_line(&t, px, py, x, y); fx_line(&t, px, py - 1, x, y - 1); }
        px = x; py = y;
    }
    fx_disc(&t, px, py, 2);
}

static void draw_heat(kiosk *k, fx_ctx *c, const kiosk_widget *w, fx_rect r, int stale)
{
    const kiosk_source *s = &k->cfg.sources[w->source];
    fx_cmap m = stale ? FX_CMAP_GREY : (fx_cmap)w->cmap;
    fx_rect a = {r.x0 + 8, r.y0 + 18, r.x1 - 20, r.y1 - 6};
    fx_rect bar = {r.x1 - 14, r.y0 + 18, r.x1 - 6, r.y1 - 6};
    if (a.x1 - a.x0 < s->gw || a.y1 - a.y0 < s->gh) return;
    fx_ctx t = *c;
    fx_ctx_set_color(&t, DIM);
    fx_colorbar(&t, bar, m, 0);
    int full = s->has_value;
    for (int i = 0; i < s->gw * s->gh; i++) full &= s->cells[i] != KIOSK_CELL_NONE;
    int32_t lo = (int32_t)w->min, hi = (int32_t)w->max; /* the parser keeps them in int32 */
    if (w->smooth && full && s->gw >= 2 && s->gh >= 2) {
        fx_grid g = {s->cells, s->gw, s->gh, s->gw};
        fx_heatmap(c, a, &g, lo, hi, m);
        return;
    }
    /* blocks, quantised to fx_heatmap's 256 steps so both modes agree on a cell's colour */
    fx_color tab[256];
    fx_cmap_table(m, tab, 256);
    int64_t range = (int64_t)hi - lo;
    for (int y = 0; y < s->gh; y++)
        for (int x = 0; x < s->gw; x++) {
            int32_t x0 = a.x0 + (a.x1 - a.x0) * x / s->gw, x1 = a.x0 + (a.x1 - a.x0) * (x + 1) / s->gw;
            int32_t y0 = a.y0 + (a.y1 - a.y0) * y / s->gh, y1 = a.y0 + (a.y1 - a.y0) * (y + 1) / s->gh;
            int32_t v = s->cells[y * s->gw + x];
            fx_color col = EMPTY_CELL;
            if (v != KIOSK_CELL_NONE) {
                int64_t idx = ((int64_t)v - lo) * 255;
                idx = idx < 0 ? 0 : (idx + range / 2) / range;
                col = tab[idx > 255 ? 255 : idx];
            }
            fill(c, col, x0, y0, x1 - x0, y1 - y0);
        }
}

/* Texture coordinates for the image's box: pixel (x, y) samples at its centre. */
typedef struct img_map {
    fx_texture tx;
    int32_t ox, oy, dw, dh;
} img_map;

static void img_shade(const void *user, int32_t y, int32_t x, int32_t n, fx_color *out)
{
    const img_map *m = user;
    fx16 t = (fx16)((((int64_t)(y - m->oy) * 2 + 1) << 16) / (2 * m->dh));
    for (int32_t i = 0; i < n; i++) {
        fx16 s = (fx16)((((int64_t)(x + i - m->ox) * 2 + 1) << 16) / (2 * m->dw));
        out[i] = fx_tex_sample(&m->tx, s, t);
    }
}

/* Whole pixels per module (a scanner needs square, equal modules), the
 * quiet zone white like the code's light modules, centred in the cell. */
static void draw_qr(kiosk *k, fx_ctx *c, int i, fx_rect r)
{
    const kqr *q = &k->qr[i];
    const kiosk_widget *w = &k->cfg.widgets[i];
    fx_rect a = {r.x0 + 8, r.y0 + 18, r.x1 - 6, r.y1 - 6};
    int32_t aw = a.x1 - a.x0, ah = a.y1 - a.y0, side = aw < ah ? aw : ah;
    int32_t n = q->size + 2 * w->qr_quiet, px = n > 0 ? side / n : 0;
    if (!q->mods || px < 1) {
        const char *why = q->mods ? "too small" : q->why ? q->why : "no data";
        fill(c, EMPTY_CELL, a.x0, a.y0, aw, ah);
        int32_t sc = fit_scale(why, aw - 8, ah, 2);
        text_at(c, a.x0 + (aw - text_w(why, sc)) / 2, a.y0 + (ah - 10 * sc) / 2, sc, q->mods ? BAD_RED : DIM, why);
        return;
    }
    int32_t x0 = a.x0 + (aw - n * px) / 2, y0 = a.y0 + (ah - n * px) / 2, m0 = w->qr_quiet * px;
    fill(c, 0xFFFFFFFFu, x0, y0, n * px, n * px);
    for (int32_t y = 0; y < q->size; y++)
        for (int32_t x = 0; x < q->size; x++)
            if (q->mods[y * q->size + x]) fill(c, 0xFF000000u, x0 + m0 + x * px, y0 + m0 + y * px, px, px);
}

static void draw_image(kiosk *k, fx_ctx *c, int i, fx_rect r)
{
    const kimg *m = &k->img[i];
    fx_rect a = {r.x0 + 8, r.y0 + 18, r.x1 - 6, r.y1 - 6};
    int32_t aw = a.x1 - a.x0, ah = a.y1 - a.y0;
    if (aw < 2 || ah < 2) return;
    if (m->state == IMG_OK && m->rgb) {
        /* fit inside the box, keeping the aspect ratio */
        img_map im;
        memset(&im, 0, sizeof im);
        im.dw = aw;
        im.dh = (int32_t)((int64_t)m->h * aw / m->w);
        if (im.dh > ah) { im.dh = ah; im.dw = (int32_t)((int64_t)m->w * ah / m->h); }
        if (im.dw < 1) im.dw = 1;
        if (im.dh < 1) im.dh = 1;
        im.ox = a.x0 + (aw - im.dw) / 2;
        im.oy = a.y0 + (ah - im.dh) / 2;
        if (fx_surface_init(&im.tx.img, m->rgb, m->w, m->h, m->w * 3, FX_FMT_BGR888) < 0) return;
        im.tx.wrap = FX_TEX_CLAMP;
        im.tx.filter = k->cfg.widgets[i].smooth ? FX_TEX_BILINEAR : FX_TEX_NEAREST;
        fx_fill_style st;
        memset(&st, 0, sizeof st);
        st.kind = FX_FILL_SHADER;
        st.shade = img_shade;
        st.user = &im;
        fx_ctx t = *c;
        t.fill_style = &st;
        for (int32_t y = im.oy; y < im.oy + im.dh; y++) fx_fill_span(&t, y, im.ox, im.ox + im.dw);
        return;
    }
    /* the placeholder: a crossed box saying why */
    const char *why = m->state == IMG_MISSING ? "missing" : m->state == IMG_BAD ? "bad image"
                    : m->state == IMG_HUGE ? "too large" : "no image";
    fx_color col = m->state == IMG_NONE ? DIM : BAD_RED;
    fx_ctx t = *c;
    fill(c, EMPTY_CELL, a.x0, a.y0, aw, ah);
    fx_ctx_set_color(&t, 0xFF374151u);
    fx_line(&t, a.x0, a.y0, a.x1 - 1, a.y1 - 1);
    fx_line(&t, a.x0, a.y1 - 1, a.x1 - 1, a.y0);
    int32_t sc = fit_scale(why, aw - 8, ah, 2);
    int32_t tw = text_w(why, sc);
    fill(c, k->cfg.panel, a.x0 + (aw - tw) / 2 - 3, a.y0 + (ah - 10 * sc) / 2 - 3, tw + 6, 10 * sc + 4);
    text_at(c, a.x0 + (aw - tw) / 2, a.y0 + (ah - 10 * sc) / 2, sc, col, why);
}

static void draw_button(kiosk *k, fx_ctx *c, int i, fx_rect r);

static void draw_widget(kiosk *k, fx_ctx *base, int i)
{
    const kiosk_widget *w = &k->cfg.widgets[i];
    fx_rect r = widget_rect(k, w);
    fx_ctx c = *base;
    /* narrowed, never replaced: base's clip is a band when threads draw (fixel/par.h) */
    c.clip = fx_rect_intersect(r, base->clip);
    if (w->type == KIOSK_BUTTON) { draw_button(k, &c, i, r); return; }
    int stale = k->stale[i];
    fx_color acc = stale ? STALE_FG : w->color, fgc = stale ? STALE_FG : k->cfg.fg;
    int32_t rw = r.x1 - r.x0, rh = r.y1 - r.y0;
    fill(&c, k->cfg.panel, r.x0, r.y0, rw, rh);
    fill(&c, acc, r.x0, r.y0, 3, rh);
    text_at(&c, r.x0 + 8, r.y0 + 5, 1, DIM, w->label);
    if (stale) {
        const char *m = "STALE";
        int32_t tw = text_w(m, 1);
        fill(&c, AMBER, r.x1 - tw - 10, r.y0 + 3, tw + 6, 13);
        text_at(&c, r.x1 - tw - 7, r.y0 + 5, 1, 0xFF111111u, m);
    }
    char v[48], buf[96];
    switch (w->type) {
    case KIOSK_NUMBER:
    case KIOSK_TEXT: {
        value_text(k, w, v, sizeof v);
        int32_t us = 1, sc = fit_scale(v, rw - 16, rh - 24, w->type == KIOSK_TEXT ? 4 : 12);
        int32_t uw = 0;
        if (w->unit[0]) {
            us = sc / 2 < 1 ? 1 : sc / 2;
            /* shrink together until value and unit share the width */
            while (sc > 1 && text_w(v, sc) + text_w(w->unit, us) + 4 > rw - 16) {
                sc--;
                us = sc / 2 < 1 ? 1 : sc / 2;
            }
            uw = text_w(w->unit, us) + 4;
        }
        int32_t tw = text_w(v, sc) + uw;
        int32_t x = r.x0 + (rw - tw) / 2, y = r.y0 + 14 + (rh - 14 - 10 * sc) / 2;
        text_at(&c, x, y, sc, fgc, v);
        if (w->unit[0]) text_at(&c, x + tw - uw + 4, y + 10 * sc - 10 * us - sc, us, stale ? STALE_FG : DIM, w->unit);
        break;
    }
    case KIOSK_GAUGE: draw_gauge(k, &c, w, r, acc, stale); break;
    case KIOSK_BAR: {
        const kiosk_source *s = &k->cfg.sources[w->source];
        int32_t bh = rh / 4 < 8 ? 8 : rh / 4 > 28 ? 28 : rh / 4;
        int32_t bx = r.x0 + 10, bw = rw - 20, by = r.y0 + 18 + (rh - 18 - bh - 14) / 2;
        int64_t f = s->has_value ? frac_permille(w, s->value) : 0;
        fill(&c, 0xFF374151u, bx, by, bw, bh);
        fill(&c, acc, bx, by, (int32_t)(bw * f / 1000), bh);
        value_text(k, w, v, sizeof v);
        snprintf(buf, sizeof buf, "%s%s%s", v, w->unit[0] ? " " : "", w->unit);
        int32_t sc = fit_scale(buf, bw, r.y1 - (by + bh) - 4, 2);
        text_at(&c, bx, by + bh + 4, sc, fgc, buf);
        kiosk_format_milli(v, sizeof v, w->max, w->decimals);
        text_at(&c, bx + bw - text_w(v, 1), by + bh + 4, 1, DIM, v);
        break;
    }
    case KIOSK_SPARK: draw_spark(k, &c, w, r, acc, stale); break;
    case KIOSK_HEAT: draw_heat(k, &c, w, r, stale); break;
    case KIOSK_IMAGE: draw_image(k, &c, i, r); break;
    case KIOSK_QR: draw_qr(k, &c, i, r); break;
    case KIOSK_BUTTON:
    case KIOSK_NTYPES: break;
    case KIOSK_CLOCK: {
        int64_t sec = k->wall_sec;
        snprintf(buf, sizeof buf, "%02d:%02d:%02d", (int)(sec / 3600 % 24), (int)(sec / 60 % 60), (int)(sec % 60));
        int32_t sc = fit_scale(buf, rw - 16, rh - 24, 8);
        text_at(&c, r.x0 + (rw - text_w(buf, sc)) / 2, r.y0 + 14 + (rh - 14 - 10 * sc) / 2, sc, w->color, buf);
        break;
    }
    }
}

static void draw_page_dots(kiosk *k, fx_ctx *c, int32_t x, fx_rect r);

static fx_rect status_rect(const kiosk *k, int si)
{
    return (fx_rect){0, k->scr[si].H - STATUS_H, k->scr[si].W, k->scr[si].H};
}

static void draw_status(kiosk *k, fx_ctx *base, int si)
{
    fx_rect r = status_rect(k, si);
    fx_ctx c = *base;
    c.clip = fx_rect_intersect(r, base->clip);
    fill(&c, k->cfg.bg, r.x0, r.y0, r.x1 - r.x0, r.y1 - r.y0);
    int nstale = 0;
    for (int i = 0; i < k->cfg.nwidgets; i++) nstale += k->stale[i];
    char buf[128];
    snprintf(buf, sizeof buf, "lines %u", k->lines);
    text_at(&c, 6, r.y0 + 2, 1, DIM, buf);
    int32_t x = 6 + text_w(buf, 1) + 12;
    snprintf(buf, sizeof buf, "bad %u", k->bad);
    text_at(&c, x, r.y0 + 2, 1, k->bad ? BAD_RED : DIM, buf);
    x += text_w(buf, 1) + 12;
    snprintf(buf, sizeof buf, "stale %d", nstale);
    text_at(&c, x, r.y0 + 2, 1, nstale ? AMBER : DIM, buf);
    if (k->img_errors) {
        x += text_w(buf, 1) + 12;
        snprintf(buf, sizeof buf, "image errors %u", k->img_errors);
        text_at(&c, x, r.y0 + 2, 1, BAD_RED, buf);
    }
    x += text_w(buf, 1) + 12;
    draw_page_dots(k, &c, x, r);
    if (k->mq && !k->mst.connected) {
        /* the values above age into STALE on their own; this says why */
        time_t t = (time_t)k->mst.offline_since;
        struct tm tmv;
        if (localtime_r(&t, &tmv))
            snprintf(buf, sizeof buf, "broker offline since %02d:%02d:%02d", tmv.tm_hour, tmv.tm_min, tmv.tm_sec);
        else
            snprintf(buf, sizeof buf, "broker offline");
        text_at(&c, r.x1 - 6 - text_w(buf, 1), r.y0 + 2, 1, BAD_RED, buf);
    }
}

/* FIXEL_KIOSK_TRACE=FILE (docs/kiosk.md, "Latency trace"): after every
 * presented frame one line, "MONO_NS<TAB>FRAME<TAB>LINES" and a
 * "<TAB>SOURCE=VALUE" per widget drawn in it, VALUE as the widget shows it.
 * make bench-kiosk matches these against its publish times; a single write()
 * per line, so a reader polling the file never sees half of one. */
static int trace_fd = -1;

static void trace_frame(kiosk *k, const uint8_t *drawn, int64_t t_ns)
{
    char buf[4096], v[KIOSK_TEXT_MAX + 48];
    int o = snprintf(buf, sizeof buf, "%lld\t%u\t%u", (long long)t_ns, k->frames, k->lines);
    for (int i = 0; i < k->cfg.nwidgets && o < (int)sizeof buf; i++) {
        const kiosk_widget *w = &k->cfg.widgets[i];
        if (!drawn[i] || w->source < 0) continue;
        const kiosk_source *s = &k->cfg.sources[w->source];
        if (s->kind == KIOSK_KIND_NUMBER || w->type == KIOSK_TEXT) value_text(k, w, v, sizeof v);
        else snprintf(v, sizeof v, "%s", s->text);
        o += snprintf(buf + o, sizeof buf - (size_t)o, "\t%s=%s", s->name, v);
    }
    if (o >= (int)sizeof buf - 1) o = (int)sizeof buf - 2;
    buf[o++] = '\n';
    if (write(trace_fd, buf, (size_t)o) < 0) trace_fd = -1; /* a full disk ends the trace, not the kiosk */
}

/* k->full and k->status_dirty ask every screen; each clears its own. */
static void spread_flags(kiosk *k)
{
    for (int s = 0; s < k->nscr; s++) {
        k->scr[s].full |= k->full;
        k->scr[s].status |= k->status_dirty;
    }
    k->full = k->status_dirty = 0;
}

/* One frame's drawing, decided before any is done: --threads draws it in
 * bands of rows, each thread all of it with its clip narrowed to its band
 * (fixel/par.h), so the drawing only reads the kiosk (the widgets' values,
 * decoded images, page and press state) and writes pixels inside c's clip;
 * the flags and counters are settled by render() on its own thread. */
typedef struct kframe {
    kiosk *k;
    int si, whole, status;
    const char *title;
    const uint8_t *draw; /* the widgets to draw */
} kframe;

static void draw_frame(void *user, fx_ctx *c, int band)
{
    const kframe *f = user;
    kiosk *k = f->k;
    kscreen *sc = &k->scr[f->si];
    (void)band;
    if (f->whole) {
        fx_surface_fill(&c->surf, c->clip, k->cfg.bg);
        if (f->title[0]) text_at(c, 8, 4, 2, k->cfg.fg, f->title);
    }
    for (int i = 0; i < k->cfg.nwidgets; i++)
        /* a widget draws only inside its own rectangle: outside the band it is skipped whole */
        if (f->draw[i] && !fx_rect_empty(fx_rect_intersect(widget_rect(k, &k->cfg.widgets[i]), c->clip)))
            draw_widget(k, c, i);
    if (f->status && !fx_rect_empty(fx_rect_intersect(status_rect(k, f->si), c->clip))) draw_status(k, c, f->si);
    if (k->identify_phase) {
        /* identify: a frame around the whole screen, alternating colours;
         * each phase change is a full redraw (the frame crosses every widget gap) */
        fx_color col = k->identify_phase == 1 ? AMBER : 0xFFFFFFFFu;
        fill(c, col, 0, 0, sc->W, 6);
        fill(c, col, 0, sc->H - 6, sc->W, 6);
        fill(c, col, 0, 0, 6, sc->H);
        fill(c, col, sc->W - 6, 0, 6, sc->H);
    }
}

/* Draw what changed on screen si and present exactly those rectangles. */
static void render(kiosk *k, int si)
{
    if (k->headless) k->wall_sec = k->now_ms / 1000; /* virtual time: reproducible frames */
    else {
        time_t now = time(NULL);
        struct tm tmv;
        localtime_r(&now, &tmv);
        k->wall_sec = tmv.tm_hour * 3600 + tmv.tm_min * 60 + tmv.tm_sec;
    }
    kscreen *sc = &k->scr[si];
    uint8_t drawn[KIOSK_MAX_WIDGETS] = {0};
    fx_surface s = sc->d ? fx_display_surface(sc->d) : fx_app_surface(k->app);
    fx_ctx c;
    fx_rect dmg[KIOSK_MAX_WIDGETS + 2];
    int n = 0;
    const char *title = k->cfg.noutputs ? k->cfg.outputs[si].title : k->cfg.title;
    spread_flags(k);
    if (sc->d && (s.w != sc->W || s.h != sc->H)) { /* an added display's size after a hotplug */
        sc->W = s.w;
        sc->H = s.h;
        sc->full = 1;
    }
    fx_ctx_init(&c, &s);
    int whole = sc->full || k->always_full;
    if (whole) {
        for (int i = 0; i < k->cfg.nwidgets; i++)
            if (k->cfg.widgets[i].screen == si) k->dirty[i] = 1;
        sc->status = 1;
    }
    for (int i = 0; i < k->cfg.nwidgets; i++)
        if (k->dirty[i] && k->cfg.widgets[i].screen == si) {
            k->dirty[i] = 0;
            /* widgets of other pages keep their values; a page turn redraws everything */
            if (k->cfg.widgets[i].page != k->page) continue;
            drawn[i] = 1;
            dmg[n++] = widget_rect(k, &k->cfg.widgets[i]);
        }
    kframe fr = {k, si, whole, sc->status, title, drawn};
    if (sc->status) {
        sc->status = 0;
        dmg[n++] = status_rect(k, si);
    }
    if (k->threads > 1 && (whole || n || k->identify_phase)) {
        if (!whole && !k->identify_phase) {
            /* only the damage's rows are cut into bands: one changed
             * widget keeps every thread on it, not one */
            fx_rect b = dmg[0];
            for (int i = 1; i < n; i++) {
                b.x0 = dmg[i].x0 < b.x0 ? dmg[i].x0 : b.x0;
                b.y0 = dmg[i].y0 < b.y0 ? dmg[i].y0 : b.y0;
                b.x1 = dmg[i].x1 > b.x1 ? dmg[i].x1 : b.x1;
                b.y1 = dmg[i].y1 > b.y1 ? dmg[i].y1 : b.y1;
            }
            c.clip = fx_rect_intersect(b, c.clip);
        }
        /* 4 bands a thread: widgets cost unevenly (a heat map, an image)
         * and each thread takes the next band as it finishes. The threads
         * are the library's kept pool (started by fx_par_start); the call
         * returns once they are all back from their bands, so none draws
         * after the frame, and a thread that cannot be had leaves its bands
         * to the others (every band is drawn: the result is not needed) */
        (void)fx_par_bands(&c, 4 * k->threads, k->threads, draw_frame, &fr);
    } else
        draw_frame(&fr, &c, 0);
    if (sc->d) {
        if (whole) fx_display_present(sc->d, NULL, 0);
        else if (n) fx_display_present(sc->d, dmg, n);
    } else if (whole) fx_app_present(k->app, NULL, 0);
    else if (n) fx_app_present(k->app, dmg, n);
    if (whole || n) {
        k->frames++;
        if (trace_fd >= 0) {
            struct timespec ts;
            clock_gettime(CLOCK_MONOTONIC, &ts);
            trace_frame(k, drawn, (int64_t)ts.tv_sec * 1000000000 + ts.tv_nsec);
        }
        if (!k->headless && !k->ready_sent) {
            /* Type=notify: the unit is up once something is on the screen */
            sd_notify(0, "READY=1\nSTATUS=drawing");
            k->ready_sent = 1;
        }
        if (k->live_out) {
            char path[4096], tmp[4100], sfx[KIOSK_OUTPUT_MAX + 1] = "";
            if (k->cfg.noutputs) snprintf(sfx, sizeof sfx, "-%s", k->cfg.outputs[si].name);
            snprintf(path, sizeof path, "%s/live%s.ppm", k->live_out, sfx);
            snprintf(tmp, sizeof tmp, "%s/live%s.tmp.ppm", k->live_out, sfx);
            fx_surface sf = sc->d ? fx_display_surface(sc->d) : fx_app_surface(k->app);
            /* the rename must not replace a FIFO or device node someone put
             * there, nor the write go into one (issue #40): refused, said
             * once, and live output stops */
            char why[160];
            const char *bad = fx_check_replaceable(path, why, sizeof why) < 0 ? path
                              : fx_check_replaceable(tmp, why, sizeof why) < 0 ? tmp : NULL;
            if (bad) {
                fprintf(stderr, "fixel-kiosk: --out %s: %s; live output stopped\n", bad, why);
                k->live_out = NULL;
            } else if (fx_write_image(tmp, &sf) == 0)
                rename(tmp, path); /* readers never see half a frame */
        }
    }
    sc->full = 0;
}

/* ---- live mode ---- */

static void on_display(void *user) { render(user, 0); }

/* An output section's display (fx_app_add_display): its own frames. */
static void on_display_extra(fx_app *a, fx_display *d, void *user)
{
    kiosk *k = user;
    (void)a;
    for (int s = 1; s < k->nscr; s++)
        if (k->scr[s].d == d) render(k, s);
}

/* The main display through the screen hooks (with its backlight), then
 * every output section's display: "screen off" is the whole kiosk. The
 * main display's answer is the result. */
static int set_power_all(kiosk *k, int on)
{
    if (k->screen.set_power && k->screen.set_power(k->screen.ctx, on) < 0) return -1;
    for (int s = 1; s < k->nscr; s++) fx_display_set_power(k->scr[s].d, on);
    return 0;
}

/* Switch the screen to what kiosk_power decided; a refusal is logged by
 * the display and leaves the state as it was. */
static void apply_power(kiosk *k, int on)
{
    if (on == k->screen_on) return;
    if (set_power_all(k, on) < 0) return;
    k->screen_on = on;
    k->status_due = 1;
    if (on) k->full = 1, fx_app_post_redisplay(k->app);
}

/* Input on a dark screen wakes it and goes no further: nobody presses a
 * button they cannot see. */
static int woke(kiosk *k)
{
    k->now_ms = mono_ms();
    if (!kiosk_power_input(&k->pw, k->now_ms)) return 0;
    apply_power(k, 1);
    return 1;
}

static void on_key(void *user, unsigned char key, int x, int y)
{
    kiosk *k = user;
    (void)x; (void)y;
    if (woke(k)) return;
    if (key == 'q' || key == 27) fx_app_quit(k->app);
}

static void touch_press(kiosk *k, int state, int x, int y);

static void on_mouse(void *user, int button, int state, int x, int y)
{
    kiosk *k = user;
    if (state == FX_UP && k->swallow_up) { k->swallow_up = 0; return; }
    if (state == FX_DOWN && woke(k)) { k->swallow_up = 1; return; }
    /* a touchscreen's finger arrives as the left button */
    if (button == FX_BUTTON_LEFT) touch_press(k, state, x, y);
}

static void go_page(kiosk *k, int p);

/* Left/right arrows and Page Up/Down turn pages as swipes do. */
static void on_special(void *user, int key, int x, int y)
{
    kiosk *k = user;
    (void)x; (void)y;
    if (woke(k)) return;
    int n = k->cfg.pg.npages;
    if (key == FX_KEY_RIGHT || key == FX_KEY_PAGE_DOWN) go_page(k, (k->page + 1) % n);
    else if (key == FX_KEY_LEFT || key == FX_KEY_PAGE_UP) go_page(k, (k->page + n - 1) % n);
}

static void on_reshape(void *user, int w, int h)
{
    kiosk *k = user;
    k->scr[0].W = w;
    k->scr[0].H = h;
    k->scr[0].full = 1;
}

static int any_dirty(const kiosk *k)
{
    if (k->full || k->status_dirty) return 1;
    for (int s = 0; s < k->nscr; s++)
        if (k->scr[s].full || k->scr[s].status) return 1;
    for (int i = 0; i < k->cfg.nwidgets; i++)
        if (k->dirty[i] && k->cfg.widgets[i].page == k->page) return 1;
    return 0;
}

/* ---- pages and touch (kiosk_pages.h) ---- */

/* Show page p; choosing the page shown again restarts its dwell. */
static void go_page(kiosk *k, int p)
{
    if (p < 0 || p >= k->cfg.pg.npages) return;
    k->page_since = k->now_ms;
    if (p == k->page) return;
    k->page = p;
    k->pressed = -1;
    k->press_down = 0; /* the rest of a swipe or press belongs to the old page */
    k->full = 1;
    k->status_due = 1;
    if (k->app) fx_app_post_redisplay(k->app);
}

/* The carousel and the end of a button's pressed look, at k->now_ms. */
static void pages_tick(kiosk *k)
{
    int64_t since = k->page_since;
    int p = kiosk_carousel(&k->cfg.pg, k->page, &since, k->now_ms);
    if (p != k->page && !k->press_down) { /* never under a finger */
        go_page(k, p);
        k->page_since = since;
    }
    if (k->pressed >= 0 && !k->press_down && k->now_ms >= k->pressed_until) {
        k->dirty[k->pressed] = 1;
        k->pressed = -1;
    }
}

static int button_at(kiosk *k, int x, int y)
{
    for (int i = 0; i < k->cfg.nwidgets; i++) {
        const kiosk_widget *w = &k->cfg.widgets[i];
        if (w->type != KIOSK_BUTTON || w->page != k->page) continue;
        fx_rect r = widget_rect(k, w);
        if (x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1) return i;
    }
    return -1;
}

/* A tap on button widget i: its message, then its page. */
static void button_action(kiosk *k, int i)
{
    const kiosk_button *b = &k->cfg.pg.buttons[k->cfg.widgets[i].button];
    k->presses++;
    k->status_due = 1;
    k->press_failed = 0;
    if (b->topic[0] && kmq_publish_to(k->mq, b->topic, b->payload, b->qos, b->retain) < 0) {
        /* offline: not queued (a light switched minutes later surprises
         * more than one that did not switch); the button flashes red */
        k->press_errors++;
        k->press_failed = 1;
        fprintf(stderr, "fixel-kiosk: button %s: not sent, the broker is offline\n", k->cfg.widgets[i].label);
    }
    int n = k->cfg.pg.npages;
    if (b->page == KIOSK_PAGE_NEXT) go_page(k, (k->page + 1) % n);
    else if (b->page == KIOSK_PAGE_PREV) go_page(k, (k->page + n - 1) % n);
    else if (b->page >= 0) go_page(k, b->page);
}

/* Presses that reach the widgets (a waking press never does): a button
 * is drawn pressed while held and acts on its release inside it, unless
 * the finger swiped; any other press is a swipe or an edge tap
 * (kiosk_gesture). */
static void touch_press(kiosk *k, int state, int x, int y)
{
    k->now_ms = k->headless ? k->now_ms : mono_ms();
    if (state == FX_DOWN) {
        k->press_down = 1;
        k->press_x = x;
        k->press_y = y;
        if (k->pressed >= 0) k->dirty[k->pressed] = 1; /* a flash still showing ends */
        k->pressed = button_at(k, x, y);
        k->press_failed = 0;
        if (k->pressed >= 0) k->dirty[k->pressed] = 1;
    } else {
        if (!k->press_down) return;
        k->press_down = 0;
        /* a swipe that started on a button is a swipe: the button lets go */
        kiosk_pages_cfg swipes = k->cfg.pg;
        swipes.edge_pct = 0;
        int sw = kiosk_gesture(&swipes, k->scr[0].W, k->press_x, k->press_y, x, y), n = k->cfg.pg.npages;
        if (k->pressed >= 0) {
            int i = k->pressed;
            fx_rect r = widget_rect(k, &k->cfg.widgets[i]);
            k->dirty[i] = 1;
            if (sw) {
                k->pressed = -1;
                go_page(k, (k->page + n + sw) % n);
            } else if (x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1) {
                k->pressed_until = k->now_ms + KIOSK_PRESS_MS;
                button_action(k, i); /* may turn the page (pressed is then -1) */
            } else
                k->pressed = -1; /* slid off: no tap */
        } else {
            int g = kiosk_gesture(&k->cfg.pg, k->scr[0].W, k->press_x, k->press_y, x, y);
            if (g) go_page(k, (k->page + n + g) % n);
        }
    }
    if (k->app && any_dirty(k)) fx_app_post_redisplay(k->app);
}

static void draw_button(kiosk *k, fx_ctx *c, int i, fx_rect r)
{
    const kiosk_widget *w = &k->cfg.widgets[i];
    int32_t rw = r.x1 - r.x0, rh = r.y1 - r.y0;
    int down = k->pressed == i;
    fx_color face = down ? (k->press_failed ? BAD_RED : w->color) : k->cfg.panel;
    fill(c, w->color, r.x0, r.y0, rw, rh); /* the rim */
    fill(c, face, r.x0 + 3, r.y0 + 3, rw - 6, rh - 6);
    int32_t sc = fit_scale(w->label, rw - 16, rh - 8, 4);
    text_at(c, r.x0 + (rw - text_w(w->label, sc)) / 2 + down, r.y0 + (rh - 10 * sc) / 2 + down, sc,
            down ? k->cfg.bg : k->cfg.fg, w->label);
}

/* "NAME 2/3" in the status line, pages only. */
static void draw_page_dots(kiosk *k, fx_ctx *c, int32_t x, fx_rect r)
{
    const kiosk_pages_cfg *pg = &k->cfg.pg;
    if (pg->npages < 2) return;
    char buf[64];
    snprintf(buf, sizeof buf, "%s %d/%d", pg->pages[k->page].name, k->page + 1, pg->npages);
    text_at(c, x, r.y0 + 2, 1, k->cfg.fg, buf);
    x += text_w(buf, 1) + 6;
    for (int i = 0; i < pg->npages; i++, x += 8)
        fill(c, i == k->page ? k->cfg.fg : DIM, x, r.y0 + (i == k->page ? 4 : 5), i == k->page ? 5 : 3,
             i == k->page ? 5 : 3);
}

static kiosk *g_kiosk; /* the timer callback's only way back to the state */

/* Read and parse the config at path into *cfg. On error -1 and
 * "PATH:LINE:COL: reason" (or "PATH: reason") in err. Startup and the
 * MQTT reload command share it: a reload that fails keeps the old config. */
static int load_config(const char *path, kiosk_config *cfg, char *err, size_t errsize)
{
    static char cbuf[65536];
    /* never blocks in open (a FIFO without writer), refuses what is not a
     * file (fixel/files.h), and a config of exactly 65536 bytes is fine
     * (issue #26) */
    char why[160];
    FILE *cf = fx_fopen_regular(path, NULL, why, sizeof why);
    if (!cf) { snprintf(err, errsize, "%s: %s", path, why); return -1; }
    size_t clen = fread(cbuf, 1, sizeof cbuf, cf);
    int toolong = clen == sizeof cbuf && fgetc(cf) != EOF, rerr = ferror(cf);
    fclose(cf);
    if (rerr) { snprintf(err, errsize, "%s: read error", path); return -1; }
    if (toolong) { snprintf(err, errsize, "%s: larger than %zu bytes", path, sizeof cbuf); return -1; }
    char e[240]; /* the unknown-widget-key message lists every key */
    if (kiosk_config_parse(cfg, cbuf, clen, e, sizeof e) < 0) {
        const char *msg = e;
        /* the parser says "line N: reason"; the place goes in front as FILE:LINE:COL */
        if (!strncmp(msg, "line ", 5)) {
            const char *c = strchr(msg, ':');
            if (c) msg = c + 2;
        }
        if (cfg->errline) snprintf(err, errsize, "%s:%d:%d: %s", path, cfg->errline, cfg->errcol, msg);
        else snprintf(err, errsize, "%s: %s", path, msg);
        return -1;
    }
    return 0;
}

/* ---- MQTT: data, control, status ---- */

static void count_line(kiosk *k, int r)
{
    k->lines++;
    k->status_dirty = 1;
    if (r == KIOSK_LINE_BAD) k->bad++;
    else if (r == KIOSK_LINE_IGNORED) k->ignored++;
    else if (r == KIOSK_LINE_OK) mark_sources(k, k->cfg.changed);
}

static void publish_status(kiosk *k)
{
    char js[1024], err[260];
    long rss_kb = -1, pages, res;
    FILE *f = fopen("/proc/self/statm", "r");
    if (f) {
        if (fscanf(f, "%ld %ld", &pages, &res) == 2) rss_kb = res * (sysconf(_SC_PAGESIZE) / 1024);
        fclose(f);
    }
    unsigned long long heap = 0;
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33))
    struct mallinfo2 mi = mallinfo2();
    heap = (unsigned long long)mi.uordblks + mi.hblkhd;
#endif
    int nstale = 0;
    for (int i = 0; i < k->cfg.nwidgets; i++) nstale += k->stale[i];
    int64_t dt = k->now_ms - k->status_ms;
    uint32_t df = k->frames - k->frames_at_status;
    int64_t fps10 = dt > 0 ? (int64_t)df * 10000 / dt : 0;
    /* the reason holds a file name and parser text: escaped for JSON */
    size_t o = 0;
    for (const char *c = k->cfg_error; *c && o + 3 < sizeof err; c++) {
        if (*c == '"' || *c == '\\') err[o++] = '\\';
        err[o++] = (unsigned char)*c < 0x20 ? '?' : *c;
    }
    err[o] = 0;
    snprintf(js, sizeof js,
             "{\"version\":\"%s\",\"state\":\"online\",\"page\":%d,\"pages\":%d,\"page_name\":\"%s\","
             "\"presses\":%u,\"press_errors\":%u,\"frames\":%u,"
             "\"fps\":%lld.%lld,\"lines\":%u,\"bad\":%u,\"ignored\":%u,\"stale\":%d,\"uptime\":%lld,"
             "\"screen\":\"%s\",\"brightness\":%d,\"screen_hw\":\"%s\",\"identify\":%d,"
             "\"connects\":%u,\"dropped\":%u,\"reloads\":%u,\"config_error\":\"%s\","
             "\"heap\":%llu,\"rss_kb\":%ld}",
             FX_VERSION_STRING, k->page, k->cfg.pg.npages, k->cfg.pg.pages[k->page].name, k->presses,
             k->press_errors, k->frames, (long long)(fps10 / 10), (long long)(fps10 % 10), k->lines, k->bad,
             k->ignored, nstale, (long long)((k->now_ms - k->start_ms) / 1000), k->screen_on ? "on" : "off",
             k->brightness, k->screen.name, k->identify_phase != 0, k->mst.connects, k->mst.dropped, k->reloads,
             err, heap, rss_kb);
    kmq_publish(k->mq, "status", js, 1);
    k->status_ms = k->now_ms;
    k->frames_at_status = k->frames;
    k->status_due = 0;
}

static void reload(kiosk *k)
{
    static kiosk_config fresh; /* as large as the model: not on the stack */
    char err[300];
    if (load_config(k->cfgpath, &fresh, err, sizeof err) < 0) {
        /* the old config keeps running; the status says why */
        snprintf(k->cfg_error, sizeof k->cfg_error, "%s", err);
        fprintf(stderr, "fixel-kiosk: reload refused: %s\n", err);
        return;
    }
    /* the displays were opened for the outputs at start */
    int same = fresh.noutputs == k->cfg.noutputs;
    for (int i = 0; same && i < fresh.noutputs; i++) same = !strcmp(fresh.outputs[i].name, k->cfg.outputs[i].name);
    if (!same) {
        snprintf(k->cfg_error, sizeof k->cfg_error, "%s: the output sections differ from the running ones (restart to change them)",
                 k->cfgpath);
        fprintf(stderr, "fixel-kiosk: reload refused: %s\n", k->cfg_error);
        return;
    }
    k->cfg_error[0] = 0;
    char shown[KIOSK_NAME_MAX];
    snprintf(shown, sizeof shown, "%s", k->cfg.pg.pages[k->page].name);
    k->cfg = fresh;
    /* the same page by name if it still exists, else the first */
    int p = 0;
    for (int i = 0; i < fresh.pg.npages; i++)
        if (!strcmp(fresh.pg.pages[i].name, shown)) p = i;
    k->page = p;
    k->page_since = k->now_ms;
    k->pressed = -1;
    k->press_down = 0;
    for (int i = 0; i < k->cfg.nsources; i++) k->cfg.sources[i].last_ms = k->now_ms;
    free_images(k);
    memset(k->img, 0, sizeof k->img);
    memset(k->stale, 0, sizeof k->stale);
    k->full = 1;
    k->reloads++;
    kmq_set_subs(k->mq, &k->cfg.mqtt);
    fprintf(stderr, "fixel-kiosk: reloaded %s\n", k->cfgpath);
}

/* PREFIX/set/WHAT: screen on|off, brightness 0..100, identify [seconds],
 * reload, page N. Anything else, or a value out of range, is a bad line. */
static int control(kiosk *k, const char *what, const char *v, size_t n)
{
    char val[32];
    /* val is compared as a C string below: a NUL inside would cut it short */
    if (n >= sizeof val || memchr(v, 0, n)) return KIOSK_LINE_BAD;
    memcpy(val, v, n);
    val[n] = 0;
    while (n && (val[n - 1] == ' ' || val[n - 1] == '\n' || val[n - 1] == '\r')) val[--n] = 0;
    int64_t x = 0;
    int isnum = n && kiosk_parse_milli(val, n, &x) == 0 && x % 1000 == 0;
    k->status_due = 1;
    if (!strcmp(what, "screen")) {
        int on = kiosk_parse_onoff(val, n);
        if (on < 0) return KIOSK_LINE_BAD;
        if (set_power_all(k, on) < 0) return KIOSK_LINE_BAD;
        k->screen_on = on;
        kiosk_power_manual(&k->pw, on, k->now_ms);
    } else if (!strcmp(what, "brightness")) {
        if (!isnum || x < 0 || x > 100000) return KIOSK_LINE_BAD;
        if (k->screen.set_brightness && k->screen.set_brightness(k->screen.ctx, (int)(x / 1000)) < 0)
            return KIOSK_LINE_BAD;
        k->brightness = (int)(x / 1000);
    } else if (!strcmp(what, "identify")) {
        int64_t sec = n ? x / 1000 : 5;
        if ((n && !isnum) || sec < 1 || sec > 60) return KIOSK_LINE_BAD;
        k->identify_until = k->now_ms + sec * 1000;
        if (!k->identify_phase) { k->identify_phase = 1; k->full = 1; }
    } else if (!strcmp(what, "reload")) {
        reload(k);
        if (k->cfg_error[0]) return KIOSK_LINE_BAD;
    } else if (!strcmp(what, "page")) {
        int p = kiosk_page_lookup(&k->cfg.pg, k->page, val, (unsigned)n);
        if (p < 0) return KIOSK_LINE_BAD;
        go_page(k, p);
    } else
        return KIOSK_LINE_BAD;
    return KIOSK_LINE_OK;
}

static void mqtt_message(kiosk *k, const kmq_msg *m)
{
    const kiosk_mqtt_cfg *c = &k->cfg.mqtt;
    size_t tl = strlen(m->topic), pl = strlen(c->prefix);
    if (m->oversize) { count_line(k, KIOSK_LINE_BAD); return; }
    if (pl && tl > pl + 5 && !memcmp(m->topic, c->prefix, pl) && !memcmp(m->topic + pl, "/set/", 5)) {
        count_line(k, control(k, m->topic + pl + 5, m->payload, m->plen));
        return;
    }
    int matched = 0;
    for (int i = 0; i < c->nsubs; i++) {
        const kiosk_sub *sb = &c->subs[i];
        if (!kiosk_topic_match(sb->topic, m->topic, tl)) continue;
        matched = 1;
        if (sb->source < 0) {
            /* data lines, exactly as on stdin; a last line needs no newline */
            feed(k, &k->mqline, m->payload, m->plen);
            if (k->mqline.len || k->mqline.overlong) end_line(k, &k->mqline);
            continue;
        }
        char v[KIOSK_LINE_MAX + 1];
        const char *val = m->payload;
        size_t vn = m->plen;
        if (sb->json[0]) {
            if (kmq_json_field(m->payload, m->plen, sb->json, v, sizeof v) < 0) {
                count_line(k, KIOSK_LINE_BAD);
                continue;
            }
            val = v;
            vn = strlen(v);
        }
        count_line(k, kiosk_set_value(&k->cfg, sb->source, val, vn, k->now_ms));
    }
    if (!matched) count_line(k, KIOSK_LINE_IGNORED);
}

static void mqtt_pump(kiosk *k)
{
    static kmq_msg msg; /* 8 KiB: not on the stack */
    if (!k->mq) return;
    /* bounded: the ring holds 128 and the thread refills it while we work */
    for (int i = 0; i < 1024 && kmq_take(k->mq, &msg); i++) mqtt_message(k, &msg);
    kmq_state st;
    kmq_get_state(k->mq, &st);
    if (st.connected != k->mst.connected || st.offline_since != k->mst.offline_since) k->status_dirty = 1;
    if (st.connects != k->mst.connects) k->status_due = 1; /* a new session: say who we are at once */
    if (st.dropped != k->mst.dropped) {
        k->bad += st.dropped - k->mst.dropped; /* lost to a full ring or an absurd topic: bad lines */
        k->status_dirty = 1;
    }
    k->mst = st;
    if (k->identify_phase) {
        int ph = k->now_ms >= k->identify_until ? 0 : 1 + (int)((k->identify_until - k->now_ms) / 500 % 2);
        if (ph != k->identify_phase) { k->identify_phase = ph; k->full = 1; k->status_due = 1; }
    }
    if (st.connected && (k->status_due || k->now_ms - k->status_ms >= (int64_t)k->cfg.mqtt.status_s * 1000))
        publish_status(k);
}

static void post_dirty(kiosk *k);

/* The MQTT thread queued something: take it now, not at the next tick (a
 * value used to wait up to the tick's 100 ms). Frames stay paced by the
 * display, so a burst of messages still costs one frame per refresh. */
static void on_mqtt_wake(void *user, int fd)
{
    kiosk *k = user;
    uint64_t n;
    if (read(fd, &n, sizeof n) < 0) {
        /* EAGAIN: already cleared */
    }
    k->now_ms = mono_ms();
    mqtt_pump(k);
    post_dirty(k);
}

static void on_tick(void *user, int value)
{
    kiosk *k = g_kiosk;
    (void)user; (void)value;
    k->now_ms = mono_ms();
    feed_available(k);
    mqtt_pump(k);
    check_images(k);
    check_qr(k);
    /* WatchdogSec=: pinged from the main loop's own timer, so a hung loop
     * (not just a dead process) gets the kiosk restarted */
    if (k->wd_ms && k->now_ms - k->wd_last >= k->wd_ms) {
        sd_notify(0, "WATCHDOG=1");
        k->wd_last = k->now_ms;
    } /* a stat() per image widget: cheap at 10 Hz */
    update_stale(k);
    pages_tick(k);
    {
        time_t t = time(NULL);
        struct tm lt;
        int sched = 1;
        k->pw.idle_ms = (int64_t)k->cfg.screen.idle_min * 60000; /* a reload may change it */
        if (k->cfg.screen.nsched && localtime_r(&t, &lt))
            sched = kiosk_sched_on(k->cfg.screen.sched, k->cfg.screen.nsched, (lt.tm_wday + 6) % 7,
                                   lt.tm_hour * 60 + lt.tm_min);
        apply_power(k, kiosk_power_want(&k->pw, k->now_ms, sched));
    }
    post_dirty(k);
    fx_app_timer(k->app, 100, on_tick, 0);
}

static void post_dirty(kiosk *k)
{
    if (any_dirty(k)) {
        fx_app_post_redisplay(k->app);
        for (int s = 1; s < k->nscr; s++) fx_app_post_redisplay_on(k->app, k->scr[s].d);
    }
}

/* ---- main ---- */

/* Resident set and heap in use, for the soak test (make kiosk-soak). */
static void mem_report(const char *when, int frame)
{
    long rss_kb = -1, pages, res;
    FILE *f = fopen("/proc/self/statm", "r");
    if (f) {
        if (fscanf(f, "%ld %ld", &pages, &res) == 2) rss_kb = res * (sysconf(_SC_PAGESIZE) / 1024);
        fclose(f);
    }
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33))
    struct mallinfo2 mi = mallinfo2();
    unsigned long long heap = (unsigned long long)mi.uordblks + mi.hblkhd;
#else
    unsigned long long heap = 0; /* no mallinfo2 here: RSS only */
#endif
    printf("fixel-kiosk: mem %s frame %d rss_kb %ld heap_bytes %llu\n", when, frame, rss_kb, heap);
    fflush(stdout);
}

static void usage(FILE *f)
{
    fprintf(f,
            "usage: fixel-kiosk [options] CONFIG\n"
            "A dashboard: widgets laid out by CONFIG, fed by \"name=value\", \"name,value\" or CSV lines\n"
            "(a header line \"a,b,c\" names the columns of the rows after it).\n"
            "  --data FILE|-     data source: a file (followed as it grows), a named pipe, or - for\n"
            "                    stdin (default -)\n"
            "  --headless        draw into memory instead of a display (tests, previews)\n"
            "  --keys            list every directive, widget key and data value with its range\n"
            "  --frames N        headless: frames to draw (default 1); each frame reads the data up\n"
            "                    to the next \"@frame [MS]\" line, then the clock advances MS (1000)\n"
            "  --out DIR         headless: write DIR/frame-NNNN.png for every frame; live (on\n"
            "                    FIXEL_BACKEND=memory, say): DIR/live.ppm after every frame drawn\n"
            "  --last            headless: write only the last frame (DIR/last.png)\n"
            "  --full            redraw every widget each frame (default: only changed ones)\n"
            "  --threads N       draw each frame on N threads (1..64, 0: every online core; default\n"
            "                    1), in bands of rows: the same pixels as one thread\n"
            "  --mem-report N    headless: print RSS and heap in use after frame N and at the end\n"
            "  --size WxH        headless surface size (default: the config's size, else 480x320)\n"
            "  --format F        headless pixel format: XRGB8888 (default) or RGB565, as on a panel\n"
            "Screens: \"output NAME\" lines split the config into one section per display (up to 4,\n"
            "one process; docs/kiosk-screens.md).\n"
            "  --help            this text\n"
            "Bad data lines are counted on screen, never fatal. Keys: q or Esc quits.\n"
            "Widgets: number gauge bar spark text clock heat image button.\n"
            "Pages: swipe, tap a screen edge, arrow keys, or PREFIX/set/page over MQTT.\n"
            "Config and data reference: docs/kiosk.md; examples: examples/kiosk-*.conf\n");
}

int main(int argc, char **argv)
{
    static kiosk K; /* static: the model is large and constant-size */
    kiosk *k = &K;
    const char *cfgpath = NULL, *data = "-", *out = NULL;
    int frames = 1, last_only = 0, sw = 0, sh = 0, mem_frame = -1;
    fx_format headless_fmt = FX_FMT_COUNT; /* --format: the memory display's, as a panel's would be */
    k->fd = -1;
    k->pressed = -1;
    k->threads = 1;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) { usage(stdout); return 0; }
        else if (!strcmp(a, "--headless")) k->headless = 1;
        else if (!strcmp(a, "--keys")) {
            /* the one table (kiosk_keys in kiosk_parse.c); fixel-kiosk(1) is generated from it */
            static const char *const types[] = {"i", "integer", "p", "AxB", "m", "number", "c", "colour",
                                                "t", "text", "f", "path", "w", "word"};
            for (const kiosk_key *q = kiosk_keys; q->name; q++) {
                const char *ty = "?";
                for (int j = 0; j < 14; j += 2)
                    if (types[j][0] == q->type) ty = types[j + 1];
                printf("%-9s %-9s %-7s ", q->scope, q->name, ty);
                if (q->type == 'i' || q->type == 'p')
                    printf("%lld..%lld", (long long)q->min, (long long)q->max);
                else if (q->type == 'm') {
                    char lo[40], hi[40];
                    kiosk_format_milli(lo, sizeof lo, q->min, 3);
                    kiosk_format_milli(hi, sizeof hi, q->max, 3);
                    printf("%s..%s", lo, hi);
                } else if (q->type == 't' || q->type == 'f')
                    printf(q->max ? "at most %lld bytes" : "-", (long long)q->max);
                else
                    printf("-");
                printf("  %s", q->help);
                unsigned all = (1u << KIOSK_NTYPES) - 1, shows = all & ~(1u << KIOSK_BUTTON);
                if (q->widgets == shows) printf(" (not button)");
                else if (q->widgets && q->widgets != all) { /* the widget types it applies to */
                    static const char *const wt[KIOSK_NTYPES] = {"number", "gauge", "bar",   "spark", "text",
                                                                 "clock",  "heat",  "image", "qr", "button"};
                    const char *sep = " (";
                    for (int j = 0; j < KIOSK_NTYPES; j++)
                        if (q->widgets >> j & 1) { printf("%s%s", sep, wt[j]); sep = ", "; }
                    printf(" only)");
                }
                printf("\n");
            }
            return 0;
        }
        else if (!strcmp(a, "--last")) last_only = 1;
        else if (!strcmp(a, "--full")) k->always_full = 1;
        else if (!strcmp(a, "--threads") && i + 1 < argc) {
            char *end;
            long n = strtol(argv[++i], &end, 10);
            if (end == argv[i] || *end || n < 0 || n > 64) {
                fprintf(stderr, "fixel-kiosk: --threads wants a number of threads from 0 (every core) to 64, not '%s'\n",
                        argv[i]);
                return 2;
            }
            k->threads = n ? (int)n : fx_par_cpu_count();
        }
        else if (!strcmp(a, "--data") && i + 1 < argc) data = argv[++i];
        else if (!strcmp(a, "--out") && i + 1 < argc) out = argv[++i];
        else if (!strcmp(a, "--frames") && i + 1 < argc) {
            char *end;
            long n = strtol(argv[++i], &end, 10);
            if (end == argv[i] || *end || n < 1 || n > 100000000L) {
                fprintf(stderr, "fixel-kiosk: --frames wants a number of frames from 1 to 100000000, not '%s'\n", argv[i]);
                return 2;
            }
            frames = (int)n;
        }
        else if (!strcmp(a, "--mem-report") && i + 1 < argc) {
            char *end;
            long n = strtol(argv[++i], &end, 10);
            if (end == argv[i] || *end || n < 0 || n > 100000000L) {
                fprintf(stderr, "fixel-kiosk: --mem-report wants a frame number from 0 to 100000000, not '%s'\n",
                        argv[i]);
                return 2;
            }
            mem_frame = (int)n;
        }
        else if (!strcmp(a, "--size") && i + 1 < argc) {
            char extra;
            if (sscanf(argv[++i], "%dx%d%c", &sw, &sh, &extra) != 2 || sw < 16 || sh < 16 || sw > 8192 || sh > 8192) {
                fprintf(stderr, "fixel-kiosk: --size wants WxH, each from 16 to 8192, not '%s'\n", argv[i]);
                return 2;
            }
        } else if (!strcmp(a, "--format") && i + 1 < argc) {
            headless_fmt = fx_format_from_name(argv[++i]);
            if (headless_fmt != FX_FMT_XRGB8888 && headless_fmt != FX_FMT_RGB565) {
                fprintf(stderr, "fixel-kiosk: --format wants XRGB8888 or RGB565\n");
                return 2;
            }
        } else if (a[0] == '-' && a[1]) { fprintf(stderr, "fixel-kiosk: unknown option %s\n", a); usage(stderr); return 2; }
        else cfgpath = a;
    }
    if (!cfgpath) { usage(stderr); return 2; }
    if (frames < 1) frames = 1;
    /* the report's own output buffer must not show up as heap growth */
    static char outbuf[BUFSIZ];
    if (mem_frame >= 0) setvbuf(stdout, outbuf, _IOFBF, sizeof outbuf);

    char err[300];
    if (load_config(cfgpath, &k->cfg, err, sizeof err) < 0) {
        fprintf(stderr, "fixel-kiosk: %s\n", err);
        return 1;
    }
    k->cfgpath = cfgpath;

    if (!strcmp(data, "-")) k->fd = 0;
    else if ((k->fd = open(data, O_RDONLY | O_NONBLOCK | O_CLOEXEC)) < 0) {
        fprintf(stderr, "fixel-kiosk: %s: %s\n", data, strerror(errno));
        return 1;
    }
    struct stat dst;
    if (k->fd > 0 && fstat(k->fd, &dst) == 0 && S_ISDIR(dst.st_mode)) { /* exited 0 before */
        fprintf(stderr, "fixel-kiosk: %s: is a directory\n", data);
        close(k->fd);
        return 1;
    }

    fx_app_options o;
    fx_app_options_init(&o);
    if (k->headless) {
        /* a scripted run: said once, as a new user took the silence for a
         * kiosk that could not connect (issue #41's trial of the guide) */
        if (k->cfg.mqtt.enabled)
            fprintf(stderr, "fixel-kiosk: %s: --headless draws the data lines of stdin (or --data) only; "
                            "the mqtt lines are not used. A live MQTT kiosk without a display: "
                            "FIXEL_BACKEND=memory fixel-kiosk --out DIR %s (DIR/live.ppm, each frame)\n",
                    cfgpath, cfgpath);
        o.display.backend = FX_BACKEND_MEMORY;
        o.display.memory_w = sw ? sw : k->cfg.width ? k->cfg.width : 480;
        o.display.memory_h = sh ? sh : k->cfg.height ? k->cfg.height : 320;
        o.display.format = headless_fmt;
        o.input = 0;
        /* blocking reads: a scripted stream is consumed frame by frame */
        fcntl(k->fd, F_SETFL, fcntl(k->fd, F_GETFL) & ~O_NONBLOCK);
    } else {
        fcntl(k->fd, F_SETFL, fcntl(k->fd, F_GETFL) | O_NONBLOCK);
        /* FIXEL_BACKEND=memory runs the live kiosk with nobody watching
         * (the MQTT tests): the size as headless would pick it */
        o.display.memory_w = sw ? sw : k->cfg.width ? k->cfg.width : 480;
        o.display.memory_h = sh ? sh : k->cfg.height ? k->cfg.height : 320;
    }
    if (fx_app_options_from_env(&o) < 0) return 1;
    if (k->cfg.noutputs) {
        /* the first section is the app's own display (input, pointer, console) */
        const kiosk_output *o0 = &k->cfg.outputs[0];
        o.display.connector = o0->name;
        if (o0->rotation >= 0) o.display.rotation = o0->rotation;
        if (!sw && o0->width) {
            o.display.memory_w = o0->width;
            o.display.memory_h = o0->height;
        }
    }
    /* the latency trace (trace_frame); O_NONBLOCK only for the open: a
     * FIFO nobody reads is refused now (ENXIO) instead of hanging here */
    const char *tr = getenv("FIXEL_KIOSK_TRACE");
    if (tr && *tr) {
        trace_fd = open(tr, O_WRONLY | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC | O_NONBLOCK | O_NOCTTY, 0644);
        if (trace_fd < 0) {
            char shown[120]; /* no terminal escapes from the environment into the log */
            int e = errno;
            snprintf(shown, sizeof shown, "%s", tr);
            for (char *c = shown; *c; c++)
                if ((unsigned char)*c < 0x20 || *c == 0x7f) *c = '?';
            fprintf(stderr, "fixel-kiosk: FIXEL_KIOSK_TRACE=%s: %s\n", shown, strerror(e));
            return 1;
        }
        fcntl(trace_fd, F_SETFL, fcntl(trace_fd, F_GETFL) & ~O_NONBLOCK);
    }
    /* A kiosk booted before its screen is plugged in (or switched on) waits
     * for it instead of drawing into memory; FIXEL_WAIT_DISPLAY=0 does not. */
    long wait = 1;
    char wmsg[256];
    if (fx_env_get("FIXEL_WAIT_DISPLAY", &wait, wmsg, sizeof wmsg) < 0)
        fprintf(stderr, "fixel-kiosk: %s\n", wmsg);
    if (!k->headless && wait) {
        int w = fx_display_wait_connected(&o.display, -1);
        if (w < 0 && w != -FX_ENODEV) return 1;
    }
    if (fx_app_open(&k->app, &o) < 0) return 1;
    /* the extra threads started now, not in the first frame; fewer when
     * some cannot be (k->threads then says how many draw). They block the
     * asynchronous signals themselves (boards/posix/workers.c), so those
     * stay with the main loop's signalfd, and headless with this thread */
    if (k->threads > 1) k->threads = fx_par_start(k->threads);
    if (k->headless) {
        /* fx_app_open blocks SIGINT/SIGTERM/SIGHUP for its signalfd, which
         * only the main loop reads: the headless loop never does, so Ctrl-C
         * and timeout(1) could not stop it (issue #26). Default action. */
        sigset_t ss;
        sigemptyset(&ss);
        sigaddset(&ss, SIGINT);
        sigaddset(&ss, SIGTERM);
        sigaddset(&ss, SIGHUP);
        sigprocmask(SIG_UNBLOCK, &ss, NULL);
    }
    fx_app_size(k->app, &k->scr[0].W, &k->scr[0].H);
    k->full = 1;
    k->nscr = 1;
    for (int s = 1; s < k->cfg.noutputs; s++) {
        /* one display per further section, on whichever card has it */
        const kiosk_output *os = &k->cfg.outputs[s];
        fx_display_options d2 = o.display;
        d2.connector = os->name;
        if (os->rotation >= 0) d2.rotation = os->rotation;
        d2.memory_w = sw ? sw : os->width ? os->width : 480;
        d2.memory_h = sh ? sh : os->height ? os->height : 320;
        if (fx_app_add_display(k->app, &d2, on_display_extra, k, &k->scr[s].d) < 0) {
            fprintf(stderr, "fixel-kiosk: %s:%d: output %s: cannot open it (the reason is above)\n", cfgpath,
                    os->line, os->name);
            fx_app_close(k->app);
            if (k->fd > 0) close(k->fd);
            return 1;
        }
        fx_surface s2 = fx_display_surface(k->scr[s].d);
        k->scr[s].W = s2.w;
        k->scr[s].H = s2.h;
        k->nscr = s + 1;
    }

    int rc = 0;
    fx_display_info di;
    fx_display_get_info(fx_app_display(k->app), &di);
    if (!k->headless && di.backend == FX_BACKEND_MEMORY && o.display.backend == FX_BACKEND_AUTO) {
        /* The automatic choice found no display: a kiosk nobody sees must
         * fail (systemd's Restart= can act); --headless asks for memory. */
        fprintf(stderr, "fixel-kiosk: no display here (the reason is above); --headless [--out DIR] "
                        "draws into memory\n");
        fx_app_close(k->app);
        if (k->fd > 0) close(k->fd);
        return 1;
    }
    if (k->headless && out && fx_mkdir_parents(out) < 0) {
        fprintf(stderr, "fixel-kiosk: cannot create %s: %s\n", out, strerror(errno));
        rc = 1;
    } else if (k->headless) {
        k->now_ms = 0;
        for (int f = 0; f < frames; f++) {
            feed_frame(k);
            check_images(k);
            check_qr(k);
            update_stale(k);
            pages_tick(k);
            for (int s = 0; s < k->nscr; s++) render(k, s);
            if (f == mem_frame) mem_report("warm", f);
            for (int s = 0; out && (!last_only || f == frames - 1) && s < k->nscr && !rc; s++) {
                /* with output sections each screen's file carries its name */
                char path[4096], sfx[KIOSK_OUTPUT_MAX + 1] = "";
                if (k->cfg.noutputs) snprintf(sfx, sizeof sfx, "-%s", k->cfg.outputs[s].name);
                if (last_only) snprintf(path, sizeof path, "%s/last%s.png", out, sfx);
                else snprintf(path, sizeof path, "%s/frame-%04d%s.png", out, f, sfx);
                fx_surface sf = k->scr[s].d ? fx_display_surface(k->scr[s].d) : fx_app_surface(k->app);
                int we = fx_write_image(path, &sf);
                if (we < 0) {
                    fprintf(stderr, "fixel-kiosk: cannot write %s: %s%s\n", path, strerror(-we), fx_built_without_hint(we));
                    rc = 1;
                }
            }
            if (rc) break;
            k->now_ms += k->frame_step;
        }
        if (mem_frame >= 0) mem_report("end", frames - 1);
        printf("fixel-kiosk: %d frames, %u lines, %u bad, %u ignored, %u image errors\n", frames, k->lines, k->bad,
               k->ignored, k->img_errors);
    } else {
        fx_callbacks cb = {.display = on_display, .keyboard = on_key, .mouse = on_mouse, .special = on_special,
                           .reshape = on_reshape};
        g_kiosk = k;
        k->now_ms = mono_ms();
        k->start_ms = k->status_ms = k->page_since = k->now_ms;
        k->screen_on = 1;
        k->brightness = 100;
        {
            char serr[400];
            if (kiosk_screen_open(&k->screen_hw, &k->screen, fx_app_display(k->app), &k->cfg.screen, serr,
                                  sizeof serr) < 0) {
                fprintf(stderr, "fixel-kiosk: %s: %s\n", cfgpath, serr);
                fx_app_close(k->app);
                return 1;
            }
            if (k->screen_hw.have_bl) {
                int b = fx_backlight_brightness(&k->screen_hw.bl);
                if (b >= 0) k->brightness = b;
            }
            kiosk_power_init(&k->pw, (int64_t)k->cfg.screen.idle_min * 60000, k->now_ms);
            fprintf(stderr, "fixel-kiosk: screen power: %s%s\n", k->screen.name,
                    k->screen_hw.have_bl ? "" : " (no backlight: on/off only)");
        }
        if (out && fx_mkdir_parents(out) < 0) {
            fprintf(stderr, "fixel-kiosk: cannot create %s: %s\n", out, strerror(errno));
            kiosk_screen_close(&k->screen_hw);
            fx_app_close(k->app);
            return 1;
        }
        k->live_out = out;
#ifdef KIOSK_HAVE_SYSTEMD
        uint64_t wd_us;
        if (sd_watchdog_enabled(0, &wd_us) > 0) k->wd_ms = wd_us / 2000 < 100 ? 100 : (int64_t)(wd_us / 2000);
#endif
        if (k->cfg.mqtt.enabled) {
            char merr[300] = "";
            if (!(k->mq = kmq_start(&k->cfg.mqtt, FX_VERSION_STRING, merr, sizeof merr))) {
                fprintf(stderr, "fixel-kiosk: %s: %s\n", cfgpath, merr);
                kiosk_screen_close(&k->screen_hw);
                fx_app_close(k->app);
                return 1;
            }
            kmq_get_state(k->mq, &k->mst);
            if (kmq_wake_fd(k->mq) >= 0) fx_app_watch_fd(k->app, kmq_wake_fd(k->mq), on_mqtt_wake, k);
        }
        /* stale timing starts now, not at the monotonic clock's origin */
        for (int i = 0; i < k->cfg.nsources; i++) k->cfg.sources[i].last_ms = k->now_ms;
        k->clock_sec = -1;
        fx_app_set_callbacks(k->app, &cb, k);
        fx_app_post_redisplay(k->app);
        fx_app_timer(k->app, 100, on_tick, 0);
        rc = fx_app_main_loop(k->app) < 0;
        /* screen and console first: stopping the MQTT client can take a
         * moment (a connect in progress), and a kill meanwhile must not
         * leave the screen dark or the console in graphics mode */
        kiosk_screen_close(&k->screen_hw);
        fx_app_close(k->app);
        k->app = NULL;
        kmq_stop(k->mq);
    }
    fx_app_close(k->app);
    free_images(k);
    if (k->fd > 0) close(k->fd);
    return rc;
}
