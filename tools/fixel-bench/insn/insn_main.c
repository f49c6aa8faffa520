/* SPDX-License-Identifier: MIT */
/* fixel-insn — draws one workload of docs/BENCHMARK.md once through
 * fixel-bench's fixel peer, between two marker calls, so that an
 * instruction counter can count exactly that drawing: callgrind
 * (--toggle-collect=insn_region) on x86-64, or qemu-user's exec trace
 * (tools/fixel-bench/insn/qemu-count.c counts between insn_begin and insn_end) for
 * the Pi targets. Instruction counts do not depend on a loaded machine, so
 * `make bench-insn` shows per-primitive costs that timing on a shared box
 * cannot. It is a plain program (no peer libraries), so it cross-builds.
 *
 *   fixel-insn -w W3 -f xrgb8888 [-n N]     draw the first N primitives (all)
 *   fixel-insn --list                       the workloads, one "name N" a line
 */
#include "../bench.h"

#include <stdlib.h>
#include <string.h>

const struct workloads *WL;

static const struct {
    const char *name;
    int n;
    unsigned fmts;
} W[W_COUNT] = {
    [W1_CLEAR] = {"W1_clear", 1, 3},
    [W2_RECTS] = {"W2_rects", N_RECTS, 3},
    [W3_LINES] = {"W3_lines", N_LINES, 3},
    [W4_AALINES] = {"W4_aalines", N_AALINES, 3},
    [W5_CIRCLES] = {"W5_circles", N_CIRCLES, 3},
    [W6_DISCS] = {"W6_discs", N_DISCS, 3},
    [W7_POLYS] = {"W7_polys", N_POLYS, 3},
    [W8_TRIS] = {"W8_tris", N_TRIS, 3},
    [W8G_TRIS_GOURAUD] = {"W8g_tris_gouraud", N_TRIS, 3},
    [W9_MANDEL] = {"W9_mandel", 1, 1},
    [W10_BLIT] = {"W10_blit", 1, 3},
};

/* The markers: never inlined, never merged (each has its own side effect),
 * so each is a block of its own that a trace can name. */
volatile int insn_marks;
__attribute__((noinline)) void insn_begin(void);
__attribute__((noinline)) void insn_end(void);
__attribute__((noinline)) void insn_region(const struct peer *p, void *ctx, int w, int n);
__attribute__((noinline)) void insn_begin(void) { insn_marks = 1; }
__attribute__((noinline)) void insn_end(void) { insn_marks = 2; }
__attribute__((noinline)) void insn_region(const struct peer *p, void *ctx, int w, int n)
{
    insn_begin();
    p->fn[w](ctx, n);
    insn_end();
}

static int find(const char *name)
{
    size_t len = strlen(name);
    for (int w = 0; w < W_COUNT; w++)
        if (!strcmp(W[w].name, name) || (!strncmp(W[w].name, name, len) && W[w].name[len] == '_'))
            return w;
    return -1;
}

static void usage(void)
{
    fprintf(stderr, "usage: fixel-insn -w WORKLOAD -f xrgb8888|rgb565 [-n N] | --list\n");
    exit(2);
}

int main(int argc, char **argv)
{
    int w = -1, f = FMT_XRGB8888, n = -1;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--list")) {
            for (int k = 0; k < W_COUNT; k++)
                printf("%s %d %s\n", W[k].name, W[k].n, W[k].fmts & 2 ? "xrgb8888,rgb565" : "xrgb8888");
            return 0;
        } else if (v && !strcmp(a, "-w")) {
            if ((w = find(v)) < 0)
                usage();
            i++;
        } else if (v && !strcmp(a, "-f")) {
            if (!strcmp(v, "xrgb8888"))
                f = FMT_XRGB8888;
            else if (!strcmp(v, "rgb565"))
                f = FMT_RGB565;
            else
                usage();
            i++;
        } else if (v && !strcmp(a, "-n")) {
            n = atoi(v);
            i++;
        } else {
            usage();
        }
    }
    if (w < 0 || !(W[w].fmts & (1u << f)))
        usage();
    if (n < 1 || n > W[w].n)
        n = W[w].n;
    struct workloads *wl = calloc(1, sizeof *wl);
    if (!wl)
        return 2;
    bench_generate(wl);
    WL = wl;
    struct target t = {bench_alloc64((size_t)BW * BH * 4), f, BW * (f == FMT_XRGB8888 ? 4 : 2)};
    memset(t.pixels, 0, (size_t)BW * BH * 4);
    void *ctx = peer_fixel.open(&t);
    if (!ctx) {
        fprintf(stderr, "fixel-insn: cannot open the surface\n");
        return 1;
    }
    insn_region(&peer_fixel, ctx, w, n);
    peer_fixel.close(ctx);
    printf("%s.%s %d\n", W[w].name, f == FMT_XRGB8888 ? "xrgb8888" : "rgb565", n);
    return 0;
}
