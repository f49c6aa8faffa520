/* fixel-draw — render a scene script on the in-memory framebuffer. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#ifdef FX_DRAW_ZLIB /* set by tools/fixel-draw/zlib.mk when the target links zlib */
#include <zlib.h>
#endif

#include "fixel/error.h"
#include "fixel/memfb.h"
#include "fixel/scene.h"

static const char usage[] =
    "usage: fixel-draw [-o OUT.png|OUT.ppm] [-s WxH] [-f FORMAT] [--trace] [SCRIPT|-]\n"
    "Render a fixel scene script headless into a PNG or PPM file.\n"
    "  -o FILE      output image (default out.png; .ppm writes binary PPM)\n"
    "  -s WxH       surface size, overriding the script's 'size'\n"
    "  -f FORMAT    pixel format, overriding the script's 'format'\n"
    "  --trace      print each algorithm's steps (decision tables) on stdout\n"
    "  --commands   list every script command and exit\n"
    "  -h, --help   this text\n"
    "The script is read from SCRIPT, or from standard input with '-' or no argument.\n";

typedef struct host {
    fx_memfb fb;
    int have_fb;
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

static int read_all(FILE *f, uint8_t **data, size_t *len)
{
    size_t cap = 1 << 16, n = 0;
    uint8_t *buf = malloc(cap + 1);
    if (!buf)
        return -FX_ENOMEM;
    for (;;) {
        if (n == cap) {
            if (cap > ((size_t)1 << 30)) {
                free(buf);
                return -FX_E2BIG;
            }
            uint8_t *nb = realloc(buf, cap * 2 + 1);
            if (!nb) {
                free(buf);
                return -FX_ENOMEM;
            }
            buf = nb;
            cap *= 2;
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
    size_t cap = *len * 4 + 4096, n = 0;
    uint8_t *out = malloc(cap + 1);
    z_stream z;
    memset(&z, 0, sizeof z);
    if (!out || inflateInit2(&z, 16 + MAX_WBITS) != Z_OK) {
        free(out);
        return -FX_ENOMEM;
    }
    z.next_in = *buf;
    z.avail_in = (uInt)*len;
    int zr;
    do {
        if (n == cap) {
            uint8_t *nb = cap < ((size_t)64 << 20) ? realloc(out, cap * 2 + 1) : NULL;
            if (!nb) {
                inflateEnd(&z);
                free(out);
                return -FX_E2BIG;
            }
            out = nb;
            cap *= 2;
        }
        z.next_out = out + n;
        z.avail_out = (uInt)(cap - n);
        zr = inflate(&z, Z_NO_FLUSH);
        n = cap - z.avail_out;
    } while (zr == Z_OK);
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

static int load_file(void *u, const char *path, const uint8_t **data, size_t *len)
{
    host *H = u;
    FILE *f = fopen(path, "rb");
    if (!f)
        return -errno;
    uint8_t *buf;
    int r = read_all(f, &buf, len);
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

static void trace_line(void *u, const char *line)
{
    (void)u;
    puts(line);
}

static void list_commands(void)
{
    for (int t = 0; fx_scene_tables[t]; t++)
        for (const fx_scene_cmd *c = fx_scene_tables[t]; c->name; c++)
            printf("%s\n", c->usage);
}

int main(int argc, char **argv)
{
    const char *out = "out.png", *script = "-";
    int trace = 0, w = 0, h = 0;
    fx_format fmt = FX_FMT_COUNT;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            fputs(usage, stdout);
            return 0;
        } else if (!strcmp(a, "--commands")) {
            list_commands();
            return 0;
        } else if (!strcmp(a, "--trace")) {
            trace = 1;
        } else if (!strcmp(a, "-o") && i + 1 < argc) {
            out = argv[++i];
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
        } else if (a[0] == '-' && a[1]) {
            fprintf(stderr, "fixel-draw: unknown or incomplete option '%s'\n%s", a, usage);
            return 2;
        } else {
            script = a;
        }
    }

    FILE *in = strcmp(script, "-") ? fopen(script, "rb") : stdin;
    if (!in) {
        fprintf(stderr, "fixel-draw: cannot open %s: %s\n", script, strerror(errno));
        return 1;
    }
    uint8_t *text;
    size_t len;
    int r = read_all(in, &text, &len);
    if (in != stdin)
        fclose(in);
    if (r < 0) {
        fprintf(stderr, "fixel-draw: cannot read %s: %s\n", script, fx_strerror(r));
        return 1;
    }

    host H;
    memset(&H, 0, sizeof H);
    fx_scene_host hs = {&H, make_surface, load_file, NULL, trace ? trace_line : NULL};
    size_t arena_size = (size_t)128 << 20;
    void *arena = malloc(arena_size);
    if (!arena) {
        fprintf(stderr, "fixel-draw: out of memory\n");
        return 1;
    }
    static fx_scene sc;
    fx_scene_init(&sc, &hs, arena, arena_size);
    if (w)
        fx_scene_fix_size(&sc, w, h);
    if (fmt != FX_FMT_COUNT)
        fx_scene_fix_format(&sc, fmt);
    r = fx_scene_run(&sc, (const char *)text, len);
    int status = 0;
    if (r < 0) {
        fprintf(stderr, "%s:%d:%d: %s\n", strcmp(script, "-") ? script : "<stdin>", sc.err_line,
                sc.err_col, sc.err);
        status = 1;
    } else {
        fflush(stdout);
        r = fx_write_image(out, &H.fb.surf);
        if (r < 0) {
            fprintf(stderr, "fixel-draw: cannot write %s: %s\n", out, strerror(-r));
            status = 3;
        }
    }
    if (H.have_fb)
        fx_memfb_destroy(&H.fb);
    while (H.files) {
        struct loaded *n = H.files->next;
        free(H.files->data);
        free(H.files);
        H.files = n;
    }
    free(arena);
    free(text);
    return status;
}
