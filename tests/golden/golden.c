/* SPDX-License-Identifier: MIT */
/* fixel — golden-image suite: every tests/golden/scripts/NAME.fxs rendered in
 * every pixel format (or those listed on a "# formats:" line) and compared
 * exactly, as 8-bit RGB, with tests/golden/FORMAT/NAME.png. A mismatch writes
 * OUT/FORMAT/NAME.actual.png and NAME.diff.png (differing pixels red on a
 * dimmed copy of the expected picture). --update rewrites the goldens. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "fixel/error.h"
#include "fixel/face.h"
#include "fixel/image.h"
#include "fixel/memfb.h"
#include "fixel/scene.h"
#include "fixel/par.h"

/* Smooth fonts ('font FAMILY SIZE'), shared by every script and band. */
static fx_face_scene *g_faces;

typedef struct host {
    fx_memfb fb;
    int have;
    int prefill; /* --band-check: the surface starts as 0x5A bytes, not black */
    void *files[64];
    int nfiles;
} host;

static int make_surface(void *u, int32_t w, int32_t h, fx_format f, fx_surface *out)
{
    host *H = u;
    int r = fx_memfb_create(&H->fb, w, h, f);
    if (r == 0) {
        H->have = 1;
        if (H->prefill)
            memset(H->fb.surf.pixels, 0x5A, (size_t)H->fb.surf.stride * (size_t)h);
        *out = H->fb.surf;
    }
    return r;
}

static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *buf = n >= 0 ? malloc((size_t)n + 1) : NULL;
    if (buf && fread(buf, 1, (size_t)n, f) != (size_t)n) {
        free(buf);
        buf = NULL;
    }
    fclose(f);
    if (buf) {
        buf[n] = 0;
        *len = (size_t)n;
    }
    return buf;
}

static int load_file(void *u, const char *path, const uint8_t **data, size_t *len)
{
    host *H = u;
    if (H->nfiles == 64)
        return -FX_ENOMEM;
    char *b = slurp(path, len);
    if (!b)
        return -errno;
    H->files[H->nfiles++] = b;
    *data = (const uint8_t *)b;
    return 0;
}

/* A target built without libpng (a cross run) reads the texture images as
 * PPM copies the host wrote with --export-textures into this directory. */
static const char *textures_ppm;

/* 'texture image PATH': a PNG as an opaque ARGB8888 surface. */
static int load_image(void *u, const char *path, fx_surface *out)
{
    host *H = u;
    if (H->nfiles == 64)
        return -FX_ENOMEM;
    uint8_t *rgb;
    int32_t w, h;
    /* PNG, JPEG, GIF (frame 0), WebP: boards/image/ by the first bytes */
    int r;
    FILE *f = fopen(path, "rb");
    if (!f) {
        r = -FX_ENOENT;
    } else {
        r = fx_image_read_rgb(f, NULL, &rgb, &w, &h, NULL, 0);
        fclose(f);
    }
    if (r < 0 && textures_ppm) {
        const char *base = strrchr(path, '/');
        char alt[1024];
        snprintf(alt, sizeof alt, "%s/%.*s.ppm", textures_ppm, (int)strcspn(base ? base + 1 : path, "."),
                 base ? base + 1 : path);
        r = fx_read_ppm_rgb(alt, &rgb, &w, &h);
    }
    if (r < 0)
        return r;
    uint32_t *px = malloc((size_t)w * (size_t)h * 4);
    if (!px) {
        free(rgb);
        return -FX_ENOMEM;
    }
    for (size_t i = 0; i < (size_t)w * (size_t)h; i++)
        px[i] = 0xFF000000u | (uint32_t)rgb[3 * i] << 16 | (uint32_t)rgb[3 * i + 1] << 8 | rgb[3 * i + 2];
    free(rgb);
    H->files[H->nfiles++] = (char *)px;
    return fx_surface_init(out, px, w, h, w * 4, FX_FMT_ARGB8888);
}

static void mkdirs(const char *dir);

static char band_msg[256];

/* --band-check: each of n bands of the script drawn alone (fx_scene_set_band)
 * on a surface of 0x5A bytes equals want inside the band and leaves the rest
 * alone (n < 0: a band per row, every place a cut can fall, since
 * fx_scene_run_mt cuts where the last frame's cost says). 0, or 1 with
 * band_msg set. */
static int check_bands(const char *text, size_t len, fx_format f, const fx_surface *want, int n)
{
    if (n < 0)
        n = want->h;
    static void *arena;
    size_t arena_size = (size_t)64 << 20;
    if (!arena && !(arena = malloc(arena_size))) {
        snprintf(band_msg, sizeof band_msg, "out of memory");
        return 1;
    }
    size_t row = (size_t)want->w * fx_format_get(f)->bits_per_pixel / 8; /* MONO1: the padding bits of a last byte are not pixels */
    for (int k = 0; k < n; k++) {
        host B;
        memset(&B, 0, sizeof B);
        B.prefill = 1;
        fx_scene_host hs = {&B, make_surface, load_file, NULL, NULL, load_image};
        static fx_scene sc;
        fx_scene_init(&sc, &hs, arena, arena_size);
        sc.text_host = fx_face_scene_host(g_faces);
        fx_scene_fix_format(&sc, f);
        fx_rect band = {0, (int32_t)((int64_t)want->h * k / n), want->w, (int32_t)((int64_t)want->h * (k + 1) / n)};
        fx_scene_set_band(&sc, band);
        int r = fx_scene_run(&sc, text, len), bad = 0;
        if (r < 0)
            snprintf(band_msg, sizeof band_msg, "band %d/%d: %d:%d: %s", k, n, sc.err_line, sc.err_col, sc.err);
        for (int32_t y = 0; r >= 0 && !bad && y < want->h; y++) {
            const uint8_t *g = (const uint8_t *)B.fb.surf.pixels + (size_t)y * (size_t)B.fb.surf.stride;
            const uint8_t *w = (const uint8_t *)want->pixels + (size_t)y * (size_t)want->stride;
            if (y >= band.y0 && y < band.y1) {
                if (memcmp(g, w, row))
                    bad = snprintf(band_msg, sizeof band_msg, "band %d/%d (rows %d..%d): row %d differs from the whole picture",
                                   k, n, band.y0, band.y1 - 1, y);
            } else {
                for (size_t x = 0; x < row && !bad; x++)
                    if (g[x] != 0x5A)
                        bad = snprintf(band_msg, sizeof band_msg, "band %d/%d (rows %d..%d) wrote row %d (byte %zu)",
                                       k, n, band.y0, band.y1 - 1, y, x);
            }
        }
        if (B.have)
            fx_memfb_destroy(&B.fb);
        for (int i = 0; i < B.nfiles; i++)
            free(B.files[i]);
        if (r < 0 || bad)
            return 1;
    }
    return 0;
}

/* The host's side of textures_ppm: every DIR/textures/NAME.png as OUT/NAME.ppm. */
static int export_textures(const char *dir, const char *out)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/textures", dir);
    DIR *d = opendir(path);
    if (!d) {
        fprintf(stderr, "golden: cannot open %s: %s\n", path, strerror(errno));
        return 1;
    }
    mkdirs(out);
    int bad = 0;
    struct dirent *e;
    while ((e = readdir(d))) {
        size_t l = strlen(e->d_name);
        if (l < 5 || strcmp(e->d_name + l - 4, ".png"))
            continue;
        char src[2048], dst[2048];
        snprintf(src, sizeof src, "%s/%s", path, e->d_name);
        snprintf(dst, sizeof dst, "%s/%.*s.ppm", out, (int)(l - 4), e->d_name);
        uint8_t *rgb;
        int32_t w, h;
        fx_memfb fb;
        int r = fx_read_png_rgb(src, &rgb, &w, &h);
        if (r == 0) {
            if ((r = fx_memfb_create(&fb, w, h, FX_FMT_RGB888)) == 0) {
                for (int32_t y = 0; y < h; y++)
                    for (int32_t x = 0; x < w; x++) {
                        const uint8_t *q = rgb + ((size_t)y * (size_t)w + (size_t)x) * 3;
                        fx_surface_put(&fb.surf, x, y, (fx_color)q[0] << 16 | (fx_color)q[1] << 8 | q[2]);
                    }
                r = fx_write_ppm(dst, &fb.surf);
                fx_memfb_destroy(&fb);
            }
            free(rgb);
        }
        if (r < 0) {
            fprintf(stderr, "golden: %s -> %s: %s\n", src, dst, fx_strerror(r));
            bad = 1;
        }
    }
    closedir(d);
    return bad;
}

static void mkdirs(const char *dir)
{
    char tmp[1024];
    snprintf(tmp, sizeof tmp, "%s", dir);
    for (char *p = tmp + 1; *p; p++)
        if (*p == '/') {
            *p = 0;
            mkdir(tmp, 0777);
            *p = '/';
        }
    mkdir(tmp, 0777);
}

static int cmpstr(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

/* Formats named on a "# formats: A B" line, or all. */
static int wants_format(const char *script, fx_format f)
{
    const char *p = strstr(script, "# formats:");
    if (!p)
        return 1;
    const char *e = strchr(p, '\n');
    size_t n = e ? (size_t)(e - p) : strlen(p);
    const char *name = fx_format_get(f)->name;
    size_t k = strlen(name);
    for (const char *q = p + 10; q + k <= p + n; q++)
        if (!strncmp(q, name, k) && (q[k] == ' ' || q[k] == '\n' || q + k == p + n) && q[-1] == ' ')
            return 1;
    return 0;
}

/* "# needs: smooth-text" marks a script drawn with FreeType/HarfBuzz fonts:
 * a build without those libraries (a cross target whose sysroot lacks
 * them) cannot draw it, and says so instead of failing on a missing font.
 * In --compare-ppm mode the target rendered the PPMs: a missing one of such
 * a script means the target skipped it. */
static int needs_text(const char *script) { return strstr(script, "# needs: smooth-text") != NULL; }
/* "# needs: image-decoders": JPEG, GIF and WebP textures (boards/image),
 * which a build without libjpeg, giflib or libwebp refuses. */
static int lacks_needed(const char *script)
{
    if (needs_text(script) && !fx_face_available())
        return 1;
#if defined(FX_NO_JPEG) || defined(FX_NO_GIF) || defined(FX_NO_WEBP)
    if (strstr(script, "# needs: image-decoders"))
        return 1;
#endif
    return 0;
}

int main(int argc, char **argv)
{
    const char *dir = "tests/golden", *out = "build/golden", *render_ppm = NULL, *compare_ppm = NULL;
    const char *scripts = NULL; /* default DIR/scripts */
    int update = 0, threads = 0, band_check = 0, banded = 0, renders = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--dir") && i + 1 < argc)
            dir = argv[++i];
        /* scripts kept elsewhere (examples/course), goldens still in DIR */
        else if (!strcmp(argv[i], "--scripts") && i + 1 < argc)
            scripts = argv[++i];
        else if (!strcmp(argv[i], "--out") && i + 1 < argc)
            out = argv[++i];
        else if (!strcmp(argv[i], "--update"))
            update = 1;
        /* Banded rendering (boards/posix/par.c, docs/ARCHITECTURE.md): run
         * every script with fx_scene_run_mt on N threads, against the same
         * goldens; --band-check N also draws each band of N alone on a
         * surface of 0x5A bytes: inside the band it must be the one-thread
         * picture, outside it untouched. */
        else if (!strcmp(argv[i], "--threads") && i + 1 < argc)
            threads = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--band-check") && i + 1 < argc) {
            /* "rows": a band per row, in XRGB8888 only (its cost is a run
             * per row; the formats differ only in how pixels are stored) */
            band_check = !strcmp(argv[++i], "rows") ? -1 : atoi(argv[i]);
        }
        /* Cross-architecture runs without libpng on the target: the target
         * renders PPMs (--render-ppm DIR), the host compares them with the
         * same golden PNGs (--compare-ppm DIR). */
        else if (!strcmp(argv[i], "--render-ppm") && i + 1 < argc)
            render_ppm = argv[++i];
        else if (!strcmp(argv[i], "--compare-ppm") && i + 1 < argc)
            compare_ppm = argv[++i];
        else if (!strcmp(argv[i], "--textures-ppm") && i + 1 < argc)
            textures_ppm = argv[++i];
        else if (!strcmp(argv[i], "--export-textures") && i + 1 < argc)
            return export_textures(dir, argv[++i]);
    }
    char path[2200], sdir[1024];
    snprintf(sdir, sizeof sdir, "%s/scripts", dir);
    if (scripts)
        snprintf(sdir, sizeof sdir, "%s", scripts);
    snprintf(path, sizeof path, "%s", sdir);
    DIR *d = opendir(path);
    if (!d) {
        fprintf(stderr, "golden: cannot open %s: %s\n", path, strerror(errno));
        printf("golden: 0 passed, 1 failed\n");
        return 1;
    }
    g_faces = fx_face_scene_new();
    char *names[4096];
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)) && n < 4096) {
        size_t l = strlen(e->d_name);
        if (l > 4 && !strcmp(e->d_name + l - 4, ".fxs"))
            names[n++] = strndup(e->d_name, l - 4);
    }
    closedir(d);
    qsort(names, (size_t)n, sizeof *names, cmpstr);

    int passed = 0, failed = 0, skipped = 0;
    size_t arena_size = (size_t)64 << 20;
    void *arena = malloc(arena_size);
    for (int i = 0; i < n; i++) {
        size_t len;
        snprintf(path, sizeof path, "%s/%s.fxs", sdir, names[i]);
        char *text = slurp(path, &len);
        for (int f = 0; text && f < FX_FMT_COUNT; f++) {
            if (!wants_format(text, (fx_format)f))
                continue;
            const char *fname = fx_format_get((fx_format)f)->name;
            if (needs_text(text) || strstr(text, "# needs: image-decoders")) {
                int skip = lacks_needed(text);
                if (!skip && compare_ppm) {
                    char pp[2200];
                    struct stat pst;
                    snprintf(pp, sizeof pp, "%s/%s/%s.ppm", compare_ppm, fname, names[i]);
                    skip = stat(pp, &pst) != 0;
                }
                if (skip) {
                    printf("skip %s [%s]: it needs %s, which this build has not\n", names[i], fname,
                           needs_text(text) ? "FreeType/HarfBuzz/FriBiDi/fontconfig/libunibreak"
                                            : "libjpeg, giflib and libwebp");
                    skipped++;
                    continue;
                }
            }
            host H;
            memset(&H, 0, sizeof H);
            fx_scene_host hs = {&H, make_surface, load_file, NULL, NULL, load_image};
            static fx_scene sc;
            fx_scene_init(&sc, &hs, arena, arena_size);
            sc.text_host = fx_face_scene_host(g_faces);
            fx_scene_fix_format(&sc, (fx_format)f);
            uint8_t *ppm = NULL;
            int32_t pw = 0, ph = 0;
            char ppath[2200];
            snprintf(ppath, sizeof ppath, "%s/%s/%s.ppm", compare_ppm ? compare_ppm : render_ppm ? render_ppm : "",
                     fname, names[i]);
            int r;
            if (compare_ppm) {
                r = fx_read_ppm_rgb(ppath, &ppm, &pw, &ph);
                if (r < 0)
                    snprintf(sc.err, sizeof sc.err, "cannot read the rendered PPM: %s", fx_strerror(r));
                /* stand in for the rendered surface */
                else if (fx_memfb_create(&H.fb, pw, ph, FX_FMT_RGB888) == 0) {
                    H.have = 1;
                    for (int32_t y = 0; y < ph; y++)
                        for (int32_t x = 0; x < pw; x++) {
                            const uint8_t *q = ppm + ((size_t)y * (size_t)pw + (size_t)x) * 3;
                            fx_surface_put(&H.fb.surf, x, y, (fx_color)q[0] << 16 | (fx_color)q[1] << 8 | q[2]);
                        }
                }
                free(ppm);
            } else if (threads) {
                int bands = 1;
                r = fx_scene_run_mt(&sc, text, len, threads, &bands);
                renders++;
                banded += bands > 1;
            } else {
                r = fx_scene_run(&sc, text, len);
            }
            if (r >= 0 && band_check && H.have && !fx_scene_script_serial(text, len) &&
                (band_check > 0 || f == FX_FMT_XRGB8888)) {
                int bad = check_bands(text, len, (fx_format)f, &H.fb.surf, band_check);
                renders++;
                banded++;
                if (bad) {
                    printf("FAIL %s [%s]: %s\n", names[i], fname, band_msg);
                    failed++;
                } else {
                    passed++;
                }
            }
            if (r >= 0 && render_ppm) {
                char rdir[1024];
                snprintf(rdir, sizeof rdir, "%s/%s", render_ppm, fname);
                mkdirs(rdir);
                r = fx_write_ppm(ppath, &H.fb.surf);
                printf("%s %s\n", r ? "FAILED to write" : "rendered", ppath);
                r ? failed++ : passed++;
                if (H.have)
                    fx_memfb_destroy(&H.fb);
                continue;
            }
            char gold[2200], act[2200], dif[2200], odir[1024];
            snprintf(gold, sizeof gold, "%s/%s/%s.png", dir, fname, names[i]);
            snprintf(odir, sizeof odir, "%s/%s", out, fname);
            snprintf(act, sizeof act, "%s/%s.actual.png", odir, names[i]);
            snprintf(dif, sizeof dif, "%s/%s.diff.png", odir, names[i]);
            if (r < 0) {
                printf("FAIL %s [%s]: script error %d:%d: %s\n", names[i], fname, sc.err_line,
                       sc.err_col, sc.err);
                failed++;
            } else if (update) {
                snprintf(odir, sizeof odir, "%s/%s", dir, fname);
                mkdirs(odir);
                r = fx_write_png(gold, &H.fb.surf);
                printf("%s %s\n", r ? "FAILED to write" : "wrote", gold);
                r ? failed++ : passed++;
            } else {
                uint8_t *exp = NULL;
                int32_t w, h;
                fx_surface *s = &H.fb.surf;
                r = fx_read_png_rgb(gold, &exp, &w, &h);
                size_t px = (size_t)s->w * (size_t)s->h;
                uint8_t *got = malloc(px * 3);
                for (int32_t y = 0; y < s->h; y++)
                    fx_surface_row_to_rgb(s, y, got + (size_t)y * (size_t)s->w * 3);
                long diff = -1;
                if (r == 0 && w == s->w && h == s->h) {
                    diff = 0;
                    for (size_t k = 0; k < px; k++)
                        diff += memcmp(got + 3 * k, exp + 3 * k, 3) != 0;
                }
                if (diff == 0) {
                    passed++;
                } else {
                    failed++;
                    mkdirs(odir);
                    fx_write_png(act, s);
                    if (r == 0 && diff > 0) {
                        for (size_t k = 0; k < px; k++) {
                            int same = !memcmp(got + 3 * k, exp + 3 * k, 3);
                            uint8_t g = (uint8_t)((exp[3 * k] + exp[3 * k + 1] + exp[3 * k + 2]) / 12);
                            got[3 * k] = same ? g : 255;
                            got[3 * k + 1] = same ? g : 0;
                            got[3 * k + 2] = same ? g : 0;
                        }
                        fx_write_png_rgb(dif, got, s->w, s->h);
                        printf("FAIL %s [%s]: %ld pixels differ; see %s and %s\n", names[i], fname,
                               diff, act, dif);
                    } else if (r == 0) {
                        printf("FAIL %s [%s]: size %dx%d, golden is %dx%d; see %s\n", names[i],
                               fname, s->w, s->h, w, h, act);
                    } else {
                        printf("FAIL %s [%s]: no golden %s (%s); rendered %s — look at it, then "
                               "make golden-update\n",
                               names[i], fname, gold, fx_strerror(r), act);
                    }
                }
                free(got);
                free(exp);
            }
            if (H.have)
                fx_memfb_destroy(&H.fb);
            for (int k = 0; k < H.nfiles; k++)
                free(H.files[k]);
        }
        if (!text) {
            printf("FAIL cannot read %s\n", path);
            failed++;
        }
        free(text);
        free(names[i]);
    }
    free(arena);
    fx_face_scene_free(g_faces);
    fx_face_shutdown();
    if (threads || band_check)
        printf("golden: %d of %d renders drawn in bands (%s %d)\n", banded, renders,
               threads ? "threads" : "band-check", threads ? threads : band_check);
    if (skipped)
        printf("golden: %d passed, %d failed, %d skipped\n", passed, failed, skipped);
    else
        printf("golden: %d passed, %d failed\n", passed, failed);
    return failed != 0;
}
