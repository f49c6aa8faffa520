/* SPDX-License-Identifier: MIT */
/* fixel-draw — render a scene script on the in-memory framebuffer. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>
#ifdef FX_DRAW_ZLIB /* set by tools/fixel-draw/zlib.mk when the target links zlib */
#include <zlib.h>
#endif

#include "fixel/app.h"
#include "fixel/env.h"
#include "fixel/error.h"
#include "fixel/files.h"
#include "fixel/face.h"
#include "fixel/image.h"
#include "fixel/memfb.h"
#include "fixel/par.h"
#include "fixel/rt_mt.h"
#include "fixel/scene.h"

static const char usage[] =
    "usage: fixel-draw [-o OUT.png|OUT.ppm] [-s WxH] [-f FORMAT] [--trace] [SCRIPT|-]\n"
    "       fixel-draw --frames N [--fps F] -o OUT-%04d.png [SCRIPT|-]\n"
    "       fixel-draw --display [--hold] [SCRIPT|-]\n"
    "       fixel-draw [-o OUT.png] [-s WxH] [--camera EX,EY,EZ LX,LY,LZ UX,UY,UZ FOVY] [--preview] SCENE.sdl\n"
    "Render a fixel scene script headless into a PNG or PPM file, or onto the display.\n"
    "  -o FILE      output image (default out.png; .ppm writes binary PPM)\n"
    "  -s WxH       surface size, overriding the script's 'size'\n"
    "  -f FORMAT    pixel format, overriding the script's 'format'\n"
    "  --trace      print each algorithm's steps (decision tables) on stdout\n"
    "  -j N         draw on N threads (1..64; the same pixels as one): the script in N\n"
    "               bands of rows at once (fixel/par.h), or, when it cannot be (seed\n"
    "               fills, 'present', --trace, --display, --frames), only its 'raytrace';\n"
    "               without -j only 'raytrace' runs on every core; with --display the\n"
    "               traced rows appear as they finish\n"
    "  --frames N   render frames 0..N-1 (1..100000) of an animated script, frame k at\n"
    "               the clock k/FPS seconds, each to -o OUT, which must hold one %d\n"
    "               (e.g. %04d: out/frame-0000.png ...)\n"
    "  --fps F      frames a second for --frames (1..1000, default 25)\n"
    "  --commands   list every script command and exit\n"
    "  --camera E L U FOVY  with a .sdl scene (the textbook's Scene Description Language,\n"
    "               ray traced, 640x480 unless -s): eye, look-at point and up vector as\n"
    "               X,Y,Z and the vertical field of view in degrees, instead of the\n"
    "               default camera (docs/RAYTRACE.md)\n"
    "  --preview    with a .sdl scene: draw it with the z-buffer rasterizer (Phong; no CSG\n"
    "               but unions, no reflection, refraction or shadows) instead of tracing it\n"
    "  --display    show the result on the display (DRM, fbdev) instead of writing a file;\n"
    "               with the script on stdin ('-') lines run as they arrive and a line\n"
    "               'present' shows the frame so far (streaming)\n"
    "  --hold       with --display: keep showing the last frame until q, Esc or a signal\n"
    "  -h, --help   this text\n"
    "The script is read from SCRIPT, or from standard input with '-' or no argument.\n";

typedef struct host {
    fx_memfb fb;
    int have_fb;
    int threads; /* -j: bands of a script, or 'raytrace' rows */
    int display; /* --display: show ray-traced rows as they finish */
    struct loaded {
        uint8_t *data;
        struct loaded *next;
    } *files;
    char load_err[512];
} host;

static int make_surface(void *u, int32_t w, int32_t h, fx_format f, fx_surface *out)
{
    host *H = u;
    int r = fx_memfb_create(&H->fb, w, h, f);
    if (r < 0)
        return r;
    H->have_fb = 1;
    *out = H->fb.surf;
    return 0;
}

#define SCRIPT_MAX ((size_t)256 << 20)
#define FILE_MAX ((size_t)64 << 20) /* fonts and OBJ meshes, as gunzip's cap */

/* Reads f to its end, refusing more than max bytes (a script naming
 * /dev/zero as a font must fail quickly, not allocate gigabytes). */
static int read_all(FILE *f, size_t max, uint8_t **data, size_t *len)
{
    size_t cap = 1 << 16, n = 0;
    uint8_t *buf = malloc(cap + 1);
    if (!buf)
        return -FX_ENOMEM;
    for (;;) {
        if (n == cap) {
            if (cap >= max) {
                if (fgetc(f) == EOF)
                    break; /* exactly max bytes */
                free(buf);
                return -FX_EFBIG;
            }
            cap = cap * 2 > max ? max : cap * 2;
            uint8_t *nb = realloc(buf, cap + 1);
            if (!nb) {
                free(buf);
                return -FX_ENOMEM;
            }
            buf = nb;
        }
        size_t got = fread(buf + n, 1, cap - n, f);
        n += got;
        if (got == 0)
            break;
    }
    if (ferror(f)) {
        free(buf);
        return -FX_EIO;
    }
    buf[n] = 0;
    *data = buf;
    *len = n;
    return 0;
}

/* gzip data (fonts as .psf.gz) is inflated here, on the tool side: the core
 * only ever sees plain bytes. Output is capped at 64 MiB. Builds without
 * zlib (bare cross sysroots) refuse gzip files instead. */
#ifndef FX_DRAW_ZLIB
static int gunzip(uint8_t **buf, size_t *len)
{
    (void)buf, (void)len;
    return -FX_ENOTSUP;
}
#else
static int gunzip(uint8_t **buf, size_t *len)
{
    /* The output cap is exact: 64 MiB inflate, 64 MiB + 1 byte does not
     * (the first guess of 4x the input let ~256 MiB through). Concatenated
     * members (gzip a b > c) are all inflated, as gunzip does. */
    const size_t max = (size_t)64 << 20;
    size_t cap = *len < max / 4 ? *len * 4 + 4096 : max, n = 0;
    if (cap > max)
        cap = max;
    uint8_t *out = malloc(cap + 1);
    z_stream z;
    memset(&z, 0, sizeof z);
    if (!out || inflateInit2(&z, 16 + MAX_WBITS) != Z_OK) {
        free(out);
        return -FX_ENOMEM;
    }
    z.next_in = *buf;
    z.avail_in = (uInt)*len;
    int zr = Z_OK;
    for (;;) {
        if (n == cap) {
            if (cap == max) {
                /* full: any further byte of output is one too many */
                uint8_t probe;
                z.next_out = &probe;
                z.avail_out = 1;
                zr = inflate(&z, Z_NO_FLUSH);
                if (z.avail_out == 0) {
                    inflateEnd(&z);
                    free(out);
                    return -FX_E2BIG;
                }
                if (zr != Z_STREAM_END)
                    break;
            } else {
                size_t nc = cap * 2 > max ? max : cap * 2;
                uint8_t *nb = realloc(out, nc + 1);
                if (!nb) {
                    inflateEnd(&z);
                    free(out);
                    return -FX_ENOMEM;
                }
                out = nb;
                cap = nc;
            }
        }
        if (n < cap) {
            z.next_out = out + n;
            z.avail_out = (uInt)(cap - n);
            zr = inflate(&z, Z_NO_FLUSH);
            n = cap - z.avail_out;
        }
        if (zr == Z_STREAM_END) {
            /* another member follows? (trailing zero padding is ignored) */
            if (z.avail_in >= 2 && z.next_in[0] == 0x1f && z.next_in[1] == 0x8b) {
                if (inflateReset(&z) != Z_OK)
                    break;
                continue;
            }
            break;
        }
        if (zr != Z_OK)
            break;
    }
    inflateEnd(&z);
    if (zr != Z_STREAM_END) {
        free(out);
        return -FX_EBADMSG;
    }
    out[n] = 0;
    free(*buf);
    *buf = out;
    *len = n;
    return 0;
}
#endif

/* The scene reports failures with fx_strerror, which knows the fx codes
 * only: map the errno values that opening a user's path can give. */
static int fx_code(int e)
{
    switch (e) {
    case ENOENT: return -FX_ENOENT;
    case EACCES:
    case EPERM: return -FX_EACCES;
    case EISDIR: return -FX_EISDIR;
    case ENOTDIR: return -FX_ENOTDIR;
    case ENOMEM: return -FX_ENOMEM;
    case ENAMETOOLONG: return -FX_ERANGE;
    case EOPNOTSUPP: return -FX_ESPIPE; /* a FIFO, socket or device where a file is needed */
    default: return -FX_EIO;
    }
}

/* Opens an input without blocking (a FIFO with no writer blocked open()
 * forever, issue #26). Files the script names (fonts, OBJ, PNG, gzip) go
 * through fixel/files.h: regular files only, so a FIFO, socket or device
 * is refused (errno EOPNOTSUPP) and a directory too (EISDIR). The script
 * itself may come from a pipe (fifo_ok): then only a directory is
 * refused. Reads block again afterwards. NULL with errno set. */
static FILE *open_input(const char *path, int fifo_ok)
{
    if (!fifo_ok)
        return fx_fopen_regular(path, NULL, NULL, 0);
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0)
        return NULL;
    struct stat st;
    int e = 0;
    if (fstat(fd, &st) < 0)
        e = errno;
    else if (S_ISDIR(st.st_mode))
        e = EISDIR;
    FILE *f = e ? NULL : (fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) & ~O_NONBLOCK), fdopen(fd, "rb"));
    if (!f) {
        if (!e)
            e = errno;
        close(fd);
        errno = e;
    }
    return f;
}

static int load_file(void *u, const char *path, const uint8_t **data, size_t *len)
{
    host *H = u;
    FILE *f = open_input(path, 0);
    if (!f)
        return fx_code(errno);
    uint8_t *buf;
    int r = read_all(f, FILE_MAX, &buf, len);
    fclose(f);
    if (r < 0)
        return r;
    if (*len >= 2 && buf[0] == 0x1f && buf[1] == 0x8b && (r = gunzip(&buf, len)) < 0) {
        free(buf);
        return r;
    }
    struct loaded *l = malloc(sizeof *l);
    if (!l) {
        free(buf);
        return -FX_ENOMEM;
    }
    l->data = buf;
    l->next = H->files;
    H->files = l;
    *data = buf;
    return 0;
}

/* 'texture image PATH': PNG, JPEG, GIF, WebP or PPM (boards/image/, by
 * the first bytes) decoded into ARGB8888 (opaque), kept on the same list as
 * loaded files; at most 4096 pixels a side, 4 Mpixels. A GIF gives frame 0,
 * or frame N of "PATH#N" when PATH itself is not a file. The reason for a
 * refusal (the limit, the truncation) goes to stderr with the file name;
 * the script's error names the line. */
static int load_image(void *u, const char *path, fx_surface *out)
{
    host *H = u;
    char file[4096];
    long frame = 0;
    const char *hash = strrchr(path, '#');
    snprintf(file, sizeof file, "%s", path);
    if (hash && access(path, F_OK) != 0) {
        char *end;
        errno = 0;
        frame = strtol(hash + 1, &end, 10);
        if (hash[1] < '0' || hash[1] > '9' || *end || errno || frame > 100000) {
            fprintf(stderr, "fixel-draw: %s: '%s' is not a frame number\n", path, hash + 1);
            return -FX_EINVAL;
        }
        file[hash - path] = 0;
    }
    FILE *f = open_input(file, 0);
    if (!f)
        return fx_code(errno);
    uint8_t *rgb = NULL, *data = NULL;
    int32_t w = 0, h = 0;
    size_t len = 0;
    char why[256] = "";
    fx_image_limits lim;
    fx_image_limits_init(&lim);
    lim.max_side = 4096;
    lim.max_pixels = (size_t)4 << 20;
    int r = read_all(f, lim.max_bytes, &data, &len);
    fclose(f);
    if (r == 0) {
        fx_anim *a = NULL;
        const uint8_t *px = NULL;
        r = fx_anim_open(&a, data, len, &lim, why, sizeof why);
        if (r == 0 && (r = fx_anim_frame(a, (int)frame, &px, why, sizeof why)) == 0) {
            w = fx_anim_width(a), h = fx_anim_height(a);
            if (!(rgb = malloc((size_t)w * (size_t)h * 3)))
                r = -FX_ENOMEM;
            else
                memcpy(rgb, px, (size_t)w * (size_t)h * 3);
        }
        fx_anim_close(a);
        free(data);
    }
    if (r < 0) {
        if (why[0])
            fprintf(stderr, "fixel-draw: %s: %s\n", path, why);
        return r;
    }
    uint32_t *px = malloc((size_t)w * (size_t)h * 4);
    struct loaded *l = malloc(sizeof *l);
    if (!px || !l) {
        free(rgb), free(px), free(l);
        return -FX_ENOMEM;
    }
    for (size_t i = 0; i < (size_t)w * (size_t)h; i++)
        px[i] = 0xFF000000u | (uint32_t)rgb[3 * i] << 16 | (uint32_t)rgb[3 * i + 1] << 8 | rgb[3 * i + 2];
    free(rgb);
    l->data = (uint8_t *)px;
    l->next = H->files;
    H->files = l;
    return fx_surface_init(out, px, w, h, w * 4, FX_FMT_ARGB8888);
}

static void trace_line(void *u, const char *line)
{
    (void)u;
    puts(line);
}

/* ---- --display: the rendered surface goes to the display through the app API ---- */
static fx_app *g_app;
static const fx_surface *g_shown;

static void show(const fx_surface *s)
{
    if (!g_app) {
        fx_app_options o;
        fx_app_options_init(&o);
        o.display.memory_w = s->w;
        o.display.memory_h = s->h;
        if (fx_app_options_from_env(&o) < 0 || fx_app_open(&g_app, &o) < 0) {
            g_app = NULL;
            return;
        }
    }
    fx_surface d = fx_app_surface(g_app);
    /* a script smaller than the screen sits top-left on black */
    if (d.w > s->w || d.h > s->h) fx_surface_clear(&d, 0xFF000000u);
    fx_blit(&d, 0, 0, s);
    fx_app_present(g_app, NULL, 0);
    g_shown = s;
}

static void hold_display(void *u) { (void)u; if (g_shown) show(g_shown); }
static void hold_key(void *u, unsigned char k, int x, int y)
{
    (void)u; (void)x; (void)y;
    if (k == 'q' || k == 27) fx_app_quit(g_app);
}

/* 'raytrace' on the host's threads (boards/posix/rt_mt.c): the same pixels
 * as the core's one-thread fx_rt_render. On a display each finished band
 * is copied to the screen as it comes (the rows are final: no thread
 * writes them again), and the screen is presented at most every 40 ms, so
 * the picture builds up while the threads work. */
typedef struct rt_show {
    const fx_surface *src;
    fx_surface dst;
    long long last;
} rt_show;

static long long now_ms(void);

static void rt_rows(void *u, int32_t y0, int32_t y1)
{
    rt_show *v = u;
    fx_surface band;
    if (fx_surface_init(&band, v->src->pixels + (ptrdiff_t)y0 * v->src->stride, v->src->w, y1 - y0,
                        v->src->stride, v->src->format) < 0)
        return;
    fx_blit(&v->dst, 0, y0, &band);
    long long t = now_ms();
    if (t - v->last >= 40) {
        fx_app_present(g_app, NULL, 0);
        v->last = t;
    }
}

static int host_raytrace(void *u, const struct fx_rt_scene *s, const fx_surface *surf, int32_t x, int32_t y,
                         int32_t w, int32_t h)
{
    host *H = u;
    if (H->display && !g_app)
        show(surf); /* opens the display, showing what the script drew so far */
    if (!H->display || !g_app)
        return fx_rt_render_rect_mt(s, surf, x, y, w, h, H->threads, 0, NULL, NULL);
    rt_show v = {surf, fx_app_surface(g_app), now_ms()};
    int r = fx_rt_render_rect_mt(s, surf, x, y, w, h, H->threads, 0, rt_rows, &v);
    fx_app_present(g_app, NULL, 0);
    return r;
}

/* Per-line progress on stderr for long renders, only on a terminal and only
 * once a script has run for a while, so pipes and tests stay quiet. */
static long long now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (long long)t.tv_sec * 1000 + t.tv_nsec / 1000000;
}

/* -o for --frames: exactly one %d, %Nd or %0Nd (N < 10), and %% for a
 * percent sign; anything else would let the name run printf wild. */
static int frame_pattern_ok(const char *p)
{
    int convs = 0;
    for (; *p; p++) {
        if (*p != '%')
            continue;
        if (p[1] == '%') {
            p++;
            continue;
        }
        p++;
        if (*p == '0')
            p++;
        if (*p >= '1' && *p <= '9')
            p++;
        if (*p != 'd')
            return 0;
        convs++;
    }
    return convs == 1;
}

/* The fonts, meshes and images a scene loaded: a scene's data lives until
 * its picture is written (--frames frees them after each frame, or a long
 * sequence would hold every frame's copy). */
static void free_files(host *H)
{
    while (H->files) {
        struct loaded *n = H->files->next;
        free(H->files->data);
        free(H->files);
        H->files = n;
    }
}

/* Smooth fonts for the scripts (fixel/face.h), shared by every frame. */
static fx_face_scene *g_faces;

static int run_lines(fx_scene *sc, const char *text, size_t len, const host *H, int display)
{
    int tty = isatty(2), lines = 0, lineno = 1, shown = 0;
    long long t0 = now_ms(), last = t0;
    for (size_t i = 0; i < len; i++) lines += text[i] == '\n';
    for (size_t i = 0; i < len; lineno++) {
        size_t e = i;
        while (e < len && text[e] != '\n') e++;
        size_t n = e - i;
        while (n && (text[i + n - 1] == '\r' || text[i + n - 1] == ' ')) n--;
        if (display && n == 7 && !memcmp(text + i, "present", 7)) {
            if (fx_scene_surface(sc) < 0) return -1;
            show(&H->fb.surf);
        } else if (fx_scene_exec_line(sc, text + i, e - i, lineno) < 0)
            return -1;
        i = e + 1;
        long long t = now_ms();
        if (tty && t - t0 > 500 && t - last > 100) {
            fprintf(stderr, "\rfixel-draw: line %d/%d (%3d%%) %llds", lineno, lines,
                    lines ? lineno * 100 / lines : 100, (t - t0) / 1000);
            last = t;
            shown = 1;
        }
    }
    if (shown) fprintf(stderr, "\r\033[K");
    int r = fx_scene_end_script(sc);
    return r < 0 ? r : fx_scene_surface(sc);
}

/* Streaming: each stdin line runs as it arrives; "present" shows the frame. */
static int run_stream(fx_scene *sc, const host *H)
{
    /* Lines are capped (a 1 GB line took 1 GB, issue #26): longer is an error. */
    enum { LINE_MAX_BYTES = 1 << 20 };
    char *line = malloc(LINE_MAX_BYTES + 1);
    if (!line)
        return fx_scene_error(sc, "out of memory");
    ssize_t n;
    int lineno = 1, r = 0;
    for (;;) {
        int ch = 0;
        n = 0;
        while (n < LINE_MAX_BYTES && (ch = getchar()) != EOF && ch != '\n')
            line[n++] = (char)ch;
        if (n == LINE_MAX_BYTES && ch != '\n' && (ch = getchar()) != EOF && ch != '\n') {
            sc->lineno = lineno;
            sc->tok_col = 0;
            r = fx_scene_error(sc, "line longer than %d bytes", LINE_MAX_BYTES);
            break;
        }
        if (ch == EOF && n == 0)
            break;
        if (r < 0)
            break;
        while (n && (line[n - 1] == '\n' || line[n - 1] == '\r' || line[n - 1] == ' ')) n--;
        if (n == 7 && !memcmp(line, "present", 7)) {
            r = fx_scene_surface(sc);
            if (r >= 0) show(&H->fb.surf);
        } else
            r = fx_scene_exec_line(sc, line, (size_t)n, lineno);
        lineno++;
    }
    free(line);
    if (r >= 0)
        r = fx_scene_end_script(sc);
    return r < 0 ? r : fx_scene_surface(sc);
}

/* --commands: each command's usage line, then its arguments from the one
 * argument table (kernel-free-src/scene/scene_args.c), one per line:
 *     NAME  TYPE  RANGE  [optional] [bounds the work]
 * forms are introduced by "form KEYWORD" ("form *" for the default form),
 * repetitions by "repeat MIN..MAX times:". fixel-script(5) is generated from
 * this output. */
static void list_commands(void)
{
    static const char *const types[] = {"", "integer", "number", "number", "colour", "word", "string"};
    for (int t = 0; fx_scene_tables[t]; t++)
        for (const fx_scene_cmd *c = fx_scene_tables[t]; c->name; c++) {
            printf("%s\n", c->usage);
            const fx_scene_argspec *sp = fx_scene_args_find(c->name);
            if (!sp) {
                printf("    (no argument table entry)\n");
                continue;
            }
            if (sp->work)
                printf("    work: %s\n", sp->work);
            int opt = 0, indent = 4;
            for (const fx_scene_arg *a = sp->args; a->type != FX_ARG_END; a++) {
                char range[64];
                fx_scene_arg_range(a, range, sizeof range);
                switch (a->type) {
                case FX_ARG_OPT: opt = 1; break;
                case FX_ARG_FORM:
                    printf("    form %s\n", a->name ? a->name : "*");
                    indent = 6;
                    opt = 0;
                    break;
                case FX_ARG_REPEAT:
                    printf("%*srepeat %s times (%s):\n", indent, "", range, a->name);
                    indent += 2;
                    break;
                case FX_ARG_WORD:
                    printf("%*sword         one of %s%s\n", indent, "", a->name, opt ? " [optional]" : "");
                    break;
                default:
                    printf("%*s%-12s %-8s %s%s%s\n", indent, "", a->name, types[a->type], range,
                           opt ? " [optional]" : "", a->flags & FX_ARG_WORK ? " [bounds the work]" : "");
                }
            }
        }
}

int main(int argc, char **argv)
{
    const char *out = "out.png", *script = "-";
    const char *camera[4] = {0};
    int preview = 0;
    int trace = 0, w = 0, h = 0, display = 0, hold = 0, threads = 0, frames = 0, fps = 25;
    fx_format fmt = FX_FMT_COUNT;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            fputs(usage, stdout);
            return 0;
        } else if (!strcmp(a, "--commands")) {
            list_commands();
            return 0;
        } else if (!strcmp(a, "--display")) {
            display = 1;
        } else if (!strcmp(a, "--hold")) {
            hold = 1;
        } else if (!strcmp(a, "--trace")) {
            trace = 1;
        } else if (!strcmp(a, "-j") && i + 1 < argc) {
            char extra;
            if (sscanf(argv[++i], "%d%c", &threads, &extra) != 1 || threads < 1 || threads > 64) {
                fprintf(stderr, "fixel-draw: bad thread count '%s' (expected 1..64)\n", argv[i]);
                return 2;
            }
        } else if ((!strcmp(a, "--frames") || !strcmp(a, "--fps")) && i + 1 < argc) {
            int v, big = a[2] == 'f' && a[3] == 'r' ? 100000 : 1000;
            char extra;
            if (sscanf(argv[++i], "%d%c", &v, &extra) != 1 || v < 1 || v > big) {
                fprintf(stderr, "fixel-draw: bad %s '%s' (expected 1..%d)\n", a, argv[i], big);
                return 2;
            }
            *(big == 1000 ? &fps : &frames) = v;
        } else if (!strcmp(a, "-o") && i + 1 < argc) {
            out = argv[++i];
            /* fx_write_image writes PNG unless the name ends in .ppm: a name
             * with another extension (x.jpg) would get a PNG it does not
             * expect, so it is refused; a name without one (/dev/stdout) is PNG. */
            const char *base = strrchr(out, '/'), *dot;
            dot = strrchr(base ? base + 1 : out, '.');
            if (dot && dot[1] && strcasecmp(dot, ".png") && strcasecmp(dot, ".ppm")) {
                fprintf(stderr, "fixel-draw: -o %s: unknown image type '%s' (use .png or .ppm)\n", out, dot);
                return 2;
            }
        } else if (!strcmp(a, "-s") && i + 1 < argc) {
            char extra;
            if (sscanf(argv[++i], "%dx%d%c", &w, &h, &extra) != 2 || w < 1 || h < 1 ||
                w > 16384 || h > 16384) {
                fprintf(stderr, "fixel-draw: bad size '%s' (expected WxH, 1..16384)\n", argv[i]);
                return 2;
            }
        } else if (!strcmp(a, "-f") && i + 1 < argc) {
            fmt = fx_format_from_name(argv[++i]);
            if (fmt == FX_FMT_COUNT) {
                fprintf(stderr, "fixel-draw: unknown pixel format '%s'\n", argv[i]);
                return 2;
            }
        } else if (!strcmp(a, "--preview")) {
            preview = 1;
        } else if (!strcmp(a, "--camera") && i + 4 < argc) {
            for (int k = 0; k < 4; k++)
                camera[k] = argv[++i];
        } else if (a[0] == '-' && a[1]) {
            fprintf(stderr, "fixel-draw: unknown or incomplete option '%s'\n%s", a, usage);
            return 2;
        } else {
            script = a;
        }
    }

    if (frames && (display || !frame_pattern_ok(out))) {
        fprintf(stderr, "fixel-draw: --frames %s\n",
                display ? "writes files: it does not go with --display"
                        : "needs -o with one %d, %4d or %04d for the frame number (e.g. -o frame-%04d.png)");
        return 2;
    }
    size_t sl = strlen(script), sdl_len = 0;
    uint8_t *sdl_text = NULL;
    int sdl = sl > 4 && !strcasecmp(script + sl - 4, ".sdl");
    if ((camera[0] || preview) && !sdl) {
        fprintf(stderr, "fixel-draw: --camera and --preview go with a .sdl scene (a script uses rtcamera, rtpreview)\n");
        return 2;
    }
    if (sdl) {
        /* the scene file is read by the script command 'sdl' of a script
         * made here, so -j, -s, -f, --display and --trace work as for any script */
        if (strpbrk(script, "\"\n\\")) {
            fprintf(stderr, "fixel-draw: %s: a scene name may not hold '\"', '\\' or a newline\n", script);
            return 2;
        }
        char cam[512] = "";
        if (camera[0]) {
            int n = snprintf(cam, sizeof cam, "rtcamera %s %s %s %s\n", camera[0], camera[1], camera[2], camera[3]);
            for (int k = 0; k < n; k++)
                if (cam[k] == ',')
                    cam[k] = ' ';
            if (n >= (int)sizeof cam || strchr(cam, '#') || strcspn(cam, "\n") != (size_t)n - 1) {
                fprintf(stderr, "fixel-draw: --camera: expected EX,EY,EZ LX,LY,LZ UX,UY,UZ FOVY\n");
                return 2;
            }
        }
        size_t cap = sl + sizeof cam + 64;
        char *gen = malloc(cap);
        if (!gen) {
            fprintf(stderr, "fixel-draw: out of memory\n");
            return 1;
        }
        int n = snprintf(gen, cap, "size 640 480\nsdl \"%s\"\n%s%s\n", script, cam,
                         preview ? "rtpreview" : "raytrace");
        sdl_text = (uint8_t *)gen;
        sdl_len = (size_t)n;
    }
    int streaming = !sdl && display && !strcmp(script, "-");
    FILE *in = streaming || sdl ? NULL : strcmp(script, "-") ? open_input(script, 1) : stdin;
    if (!in && !streaming && !sdl) {
        if (errno == EISDIR)
            fprintf(stderr, "fixel-draw: cannot read %s: it is a directory\n", script);
        else
            fprintf(stderr, "fixel-draw: cannot open %s: %s\n", script, strerror(errno));
        return 1;
    }
    uint8_t *text = NULL;
    size_t len = 0;
    int r = streaming || sdl ? 0 : read_all(in, SCRIPT_MAX, &text, &len);
    if (sdl)
        text = sdl_text, len = sdl_len;
    if (in && in != stdin)
        fclose(in);
    if (r < 0) {
        fprintf(stderr, "fixel-draw: cannot read %s: %s\n", script, fx_strerror(r));
        return 1;
    }

    host H;
    memset(&H, 0, sizeof H);
    H.threads = threads ? threads : fx_rt_cpu_count();
    H.display = display;
    fx_scene_host hs = {&H, make_surface, load_file, NULL, trace ? trace_line : NULL, load_image};
    size_t arena_size = (size_t)128 << 20;
    void *arena = malloc(arena_size);
    if (!arena) {
        fprintf(stderr, "fixel-draw: out of memory\n");
        return 1;
    }
    static fx_scene sc;
    int status = 0;
    g_faces = fx_face_scene_new();
    /* --frames: the whole script once per frame, from a fresh scene, with
     * the clock at k / fps; each picture to its own file */
    for (int k = 0; k < frames && !status; k++) {
        fx_scene_init(&sc, &hs, arena, arena_size);
        sc.raytrace = host_raytrace;
        sc.text_host = fx_face_scene_host(g_faces);
        if (w)
            fx_scene_fix_size(&sc, w, h);
        if (fmt != FX_FMT_COUNT)
            fx_scene_fix_format(&sc, fmt);
        if (fx_scene_set_clock(&sc, fx16_from_ratio(k, fps)) < 0) {
            fprintf(stderr, "fixel-draw: frame %d: out of scene memory for the clock\n", k);
            status = 1;
        } else if (run_lines(&sc, (const char *)text, len, &H, 0) < 0) {
            fprintf(stderr, "%s:%d:%d: %s (frame %d)\n", strcmp(script, "-") ? script : "<stdin>", sc.err_line,
                    sc.err_col, sc.err, k);
            status = 1;
        } else {
            char name[4096];
            if (snprintf(name, sizeof name, out, k) >= (int)sizeof name) {
                fprintf(stderr, "fixel-draw: output name too long\n");
                status = 2;
            } else if ((r = fx_write_image(name, &H.fb.surf)) < 0) {
                fprintf(stderr, "fixel-draw: cannot write %s: %s%s\n", name, strerror(-r), fx_built_without_hint(r));
                status = 3;
            }
        }
        if (H.have_fb)
            fx_memfb_destroy(&H.fb);
        H.have_fb = 0;
        free_files(&H);
    }
    if (frames)
        goto done;
    fx_scene_init(&sc, &hs, arena, arena_size);
    sc.raytrace = host_raytrace;
    sc.text_host = fx_face_scene_host(g_faces);
    if (w)
        fx_scene_fix_size(&sc, w, h);
    if (fmt != FX_FMT_COUNT)
        fx_scene_fix_format(&sc, fmt);
    /* Whole scripts in bands when -j asks for it, where nothing is shown or
     * traced line by line (a display shows 'present' frames and ray-traced
     * rows as they come). Not by default: every band repeats the script's
     * set-up (a big font's glyph look-ups, tessellation), which a CPU limit
     * set for one thread would count N times. */
    if (threads > 1 && !streaming && !display && !trace)
        r = fx_scene_run_mt(&sc, (const char *)text, len, H.threads, NULL);
    else
        r = streaming ? run_stream(&sc, &H) : run_lines(&sc, (const char *)text, len, &H, display);
    if (r < 0 && sdl) {
        /* the SDL reader's message names its own FILE:LINE:COL; line 3 of
         * the generated script is --camera's rtcamera; anything else (the
         * surface, the tracer) is the scene's */
        if (!strncmp(sc.err, "sdl: ", 5))
            fprintf(stderr, "fixel-draw: %s\n", sc.err + 5);
        else if (camera[0] && sc.err_line == 3)
            fprintf(stderr, "fixel-draw: --camera: %s\n", sc.err);
        else
            fprintf(stderr, "fixel-draw: %s: %s\n", script, sc.err);
        status = 1;
    } else if (r < 0) {
        fprintf(stderr, "%s:%d:%d: %s\n", strcmp(script, "-") ? script : "<stdin>", sc.err_line,
                sc.err_col, sc.err);
        status = 1;
    } else if (display) {
        show(&H.fb.surf);
        if (!g_app) {
            status = 3;
        } else if (hold) {
            fx_callbacks cb = {.display = hold_display, .keyboard = hold_key};
            fx_app_set_callbacks(g_app, &cb, NULL);
            fx_app_main_loop(g_app);
        }
    } else {
        fflush(stdout);
        r = fx_write_image(out, &H.fb.surf);
        if (r < 0) {
            fprintf(stderr, "fixel-draw: cannot write %s: %s%s\n", out, strerror(-r), fx_built_without_hint(r));
            status = 3;
        }
    }
done:
    if (g_app)
        fx_app_close(g_app);
    if (H.have_fb)
        fx_memfb_destroy(&H.fb);
    free_files(&H);
    fx_face_scene_free(g_faces);
    fx_face_shutdown();
    free(arena);
    free(text);
    return status;
}
