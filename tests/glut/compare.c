/* SPDX-License-Identifier: MIT */
/* Compares a fixel frame with the Mesa reference frame of the same program.
 *
 *   compare [--name NAME] [--diff PREFIX] FIXEL.png MESA.png 2d
 *   compare [--name NAME] [--diff PREFIX] FIXEL.png MESA.png 3d COVERAGE COLOUR
 *
 * 2d: the two frames must be identical, pixel for pixel.
 * 3d: a pixel is "covered" when it differs from the background, the most
 *     frequent colour of the Mesa frame. The fraction of pixels covered in one
 *     frame and not in the other must be <= COVERAGE, and over the pixels
 *     covered in both the largest difference of one channel (0-255) must be
 *     <= COLOUR, a pixel's difference being the smallest against the drawn
 *     Mesa pixels of its 3x3 neighbourhood (an edge between two faces that
 *     falls one pixel over counts as coverage, not as a shading error).
 * On a mismatch with --diff, writes PREFIX-fixel.png, PREFIX-mesa.png and
 * PREFIX-diff.png (grey: equal; red: only fixel drew; green: only Mesa drew;
 * yellow: both drew, colours differ; in 2d every differing pixel is magenta).
 * Prints one line and exits 0 (pass), 1 (fail) or 2 (error). */
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct { int w, h; unsigned char *px; } Image;   /* RGB, rows top-down */

static int load(const char *path, Image *im)
{
    png_image pi;
    memset(&pi, 0, sizeof pi);
    pi.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&pi, path)) {
        fprintf(stderr, "compare: %s: %s\n", path, pi.message);
        return -1;
    }
    pi.format = PNG_FORMAT_RGB;
    im->w = (int)pi.width;
    im->h = (int)pi.height;
    im->px = malloc(PNG_IMAGE_SIZE(pi));
    if (!im->px || !png_image_finish_read(&pi, NULL, im->px, 0, NULL)) {
        fprintf(stderr, "compare: %s: %s\n", path, pi.message);
        return -1;
    }
    return 0;
}

static void save(const char *path, const Image *im)
{
    png_image pi;
    memset(&pi, 0, sizeof pi);
    pi.version = PNG_IMAGE_VERSION;
    pi.width = (png_uint_32)im->w;
    pi.height = (png_uint_32)im->h;
    pi.format = PNG_FORMAT_RGB;
    if (!png_image_write_to_file(&pi, path, 0, im->px, 0, NULL))
        fprintf(stderr, "compare: cannot write %s: %s\n", path, pi.message);
}

static unsigned rgb(const unsigned char *p) { return (unsigned)p[0] << 16 | (unsigned)p[1] << 8 | p[2]; }

/* the most frequent colour; ties go to the first pixel's colour */
static unsigned background(const Image *im)
{
    size_t n = (size_t)im->w * (size_t)im->h, cap = 4096, used = 0;
    unsigned *key = calloc(cap, sizeof *key);
    size_t *cnt = calloc(cap, sizeof *cnt);
    unsigned char *set = calloc(cap, 1);
    unsigned best = n ? rgb(im->px) : 0;
    size_t bestn = 0;
    for (size_t i = 0; i < n; i++) {
        unsigned c = rgb(im->px + i * 3);
        size_t h = (c * 2654435761u) & (cap - 1);
        while (set[h] && key[h] != c) h = (h + 1) & (cap - 1);
        if (!set[h]) {
            if (used * 2 >= cap) {           /* grow: rehash everything */
                size_t ncap = cap * 2;
                unsigned *nk = calloc(ncap, sizeof *nk);
                size_t *nc = calloc(ncap, sizeof *nc);
                unsigned char *ns = calloc(ncap, 1);
                for (size_t j = 0; j < cap; j++)
                    if (set[j]) {
                        size_t g = (key[j] * 2654435761u) & (ncap - 1);
                        while (ns[g]) g = (g + 1) & (ncap - 1);
                        ns[g] = 1; nk[g] = key[j]; nc[g] = cnt[j];
                    }
                free(key); free(cnt); free(set);
                key = nk; cnt = nc; set = ns; cap = ncap;
                h = (c * 2654435761u) & (cap - 1);
                while (set[h] && key[h] != c) h = (h + 1) & (cap - 1);
            }
            set[h] = 1; key[h] = c; used++;
        }
        if (++cnt[h] > bestn) { bestn = cnt[h]; best = c; }
    }
    free(key); free(cnt); free(set);
    return best;
}

static int chandiff(const unsigned char *p, const unsigned char *q)
{
    int d = 0;
    for (int c = 0; c < 3; c++) {
        int x = abs((int)p[c] - (int)q[c]);
        if (x > d) d = x;
    }
    return d;
}

/* The colour difference of fixel's pixel P at (x, y) allowing a one-pixel
 * shift: the smallest difference to a drawn Mesa pixel of the 3x3
 * neighbourhood. An edge between two faces that lands one pixel over is a
 * coverage matter, not a shading error. */
static int shifted(const Image *m, unsigned bg, const unsigned char *p, int x, int y)
{
    int best = 256;
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
            int xx = x + dx, yy = y + dy;
            if (xx < 0 || yy < 0 || xx >= m->w || yy >= m->h) continue;
            const unsigned char *q = m->px + ((size_t)yy * (size_t)m->w + (size_t)xx) * 3;
            if (rgb(q) == bg) continue;
            int d = chandiff(p, q);
            if (d < best) best = d;
        }
    return best;
}

int main(int argc, char **argv)
{
    const char *name = NULL, *diff = NULL;
    int a = 1;
    while (a < argc && argv[a][0] == '-' && argv[a][1] == '-') {
        if (!strcmp(argv[a], "--name") && a + 1 < argc) name = argv[a + 1], a += 2;
        else if (!strcmp(argv[a], "--diff") && a + 1 < argc) diff = argv[a + 1], a += 2;
        else break;
    }
    int rest = argc - a;
    if (rest < 3 || (strcmp(argv[a + 2], "2d") && strcmp(argv[a + 2], "3d")) ||
        (!strcmp(argv[a + 2], "3d") && rest < 5)) {
        fprintf(stderr, "usage: compare [--name N] [--diff PREFIX] FIXEL.png MESA.png 2d\n"
                        "       compare [--name N] [--diff PREFIX] FIXEL.png MESA.png 3d COVERAGE COLOUR\n");
        return 2;
    }
    const char *fpath = argv[a], *mpath = argv[a + 1];
    int is3d = !strcmp(argv[a + 2], "3d");
    double cov_bound = is3d ? atof(argv[a + 3]) : 0;
    int col_bound = is3d ? atoi(argv[a + 4]) : 0;
    if (!name) name = mpath;

    Image f, m;
    if (load(fpath, &f) || load(mpath, &m)) { printf("%s: ERROR cannot read the frames\n", name); return 2; }
    if (f.w != m.w || f.h != m.h) {
        printf("%s: FAIL size %dx%d, Mesa's %dx%d\n", name, f.w, f.h, m.w, m.h);
        return 1;
    }
    size_t n = (size_t)f.w * (size_t)f.h, differ = 0, cov = 0, both = 0, over = 0;
    int maxd = 0, rawd = 0;
    unsigned bg = background(&m);
    Image d = { f.w, f.h, malloc(n * 3) };
    for (size_t i = 0; i < n; i++) {
        const unsigned char *p = f.px + i * 3, *q = m.px + i * 3;
        unsigned char *o = d.px + i * 3;
        int dd = chandiff(p, q);
        int fc = rgb(p) != bg, mc = rgb(q) != bg;
        if (fc != mc) cov++;
        else if (fc && mc) {
            both++;
            if (dd > rawd) rawd = dd;
            int sd = dd > col_bound ? shifted(&m, bg, p, (int)(i % (size_t)f.w), (int)(i / (size_t)f.w)) : dd;
            if (sd > maxd) maxd = sd;
            if (sd > col_bound) over++;
        }
        if (dd) differ++;
        if (!dd) {
            unsigned char g = (unsigned char)((q[0] + q[1] + q[2]) / 12 + 32);
            o[0] = o[1] = o[2] = g;
        } else if (!is3d) {
            o[0] = 255; o[1] = 0; o[2] = 255;
        } else if (fc && !mc) {
            o[0] = 255; o[1] = 0; o[2] = 0;
        } else if (mc && !fc) {
            o[0] = 0; o[1] = 255; o[2] = 0;
        } else {
            o[0] = 255; o[1] = 255; o[2] = 0;
        }
    }
    double covf = n ? (double)cov / (double)n : 0;
    int pass = is3d ? (covf <= cov_bound && maxd <= col_bound) : differ == 0;
    if (is3d)
        printf("%s: %s coverage differs at %zu of %zu pixels (%.5f, bound %.5f); largest colour "
               "difference %d (bound %d; %zu of the %zu pixels drawn in both exceed it; %d without "
               "the one-pixel shift)\n",
               name, pass ? "ok" : "FAIL", cov, n, covf, cov_bound, maxd, col_bound, over, both, rawd);
    else
        printf("%s: %s %zu of %zu pixels differ%s\n", name, pass ? "ok" : "FAIL", differ, n,
               differ ? "" : " (identical)");
    if (!pass && diff) {
        char path[4096];
        snprintf(path, sizeof path, "%s-fixel.png", diff); save(path, &f);
        snprintf(path, sizeof path, "%s-mesa.png", diff); save(path, &m);
        snprintf(path, sizeof path, "%s-diff.png", diff); save(path, &d);
        printf("%s: wrote %s-{fixel,mesa,diff}.png\n", name, diff);
    }
    free(f.px); free(m.px); free(d.px);
    return pass ? 0 : 1;
}
