/* SPDX-License-Identifier: MIT */
/* libFuzzer target (issue #26): a structure-aware generator for scene
 * scripts, driven by the argument table. The input bytes are read as a
 * stream of choices: which command (of fx_scene_argspecs), which form, how
 * many repetitions, and for each argument a value class: one of its corners
 * (min, max, 0, +-1, one past each bound, near 2^15, 2^16, 2^24, 2^31,
 * 2^63) or a random value inside its range. Every generated line is thus a
 * valid command with a hostile argument, what byte-level mutation of
 * scripts rarely forms. Set-up lines of an entry (pre) come first.
 * Surfaces are capped at 128x128 between guard pages, as fuzz_scene.c.
 * FUZZ_GRAMMAR_PRINT=1 prints each generated script (triage of a crash or
 * timeout: run the target on the artifact).
 *
 * Fuzz budget: an argument the table marks FX_ARG_WORK (iterations, points,
 * segments, grid cells, order) takes min, min - 1, max + 1 (both rejected by
 * the range check) or a value in min..min + FUZZ_WORK_BUDGET, never its
 * larger corners; a repeated group (vertices, control points) comes at
 * most min + FUZZ_WORK_BUDGET / 2 times; scripts draw into at most 64x48
 * pixels and have at most 4 commands; the heaviest commands are picked less
 * often (gen_line). Valid
 * commands at their largest work (2^24 iterations, 4M points) run for
 * seconds each: the campaign would reach ~16 executions/s. The real checks
 * are unchanged: tests/corners runs every argument at every corner,
 * FX_ARG_WORK ones at max included, in bounded time. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "choice.h"
#include "fixel/error.h"
#include "fixel/scene.h"
#include "scenehost.h"

/* Exact decimal of raw / 2^shift (up to 20 fraction digits). */
static void fixed(char *buf, size_t size, int64_t raw, unsigned shift)
{
    uint64_t m = raw < 0 ? 0 - (uint64_t)raw : (uint64_t)raw;
    uint64_t ip = m >> shift, fr = m & (((uint64_t)1 << shift) - 1);
    int n = snprintf(buf, size, "%s%llu", raw < 0 ? "-" : "", (unsigned long long)ip);
    if (fr && (size_t)n + 2 < size) {
        buf[n++] = '.';
        for (int d = 0; fr && d < 20 && (size_t)n + 1 < size; d++) {
            fr *= 10;
            buf[n++] = (char)('0' + (fr >> shift));
            fr &= ((uint64_t)1 << shift) - 1;
        }
        buf[n] = 0;
    }
}

#define FUZZ_WORK_BUDGET 16 /* over min, for FX_ARG_WORK values and repetitions */

static void value(in *s, const fx_scene_arg *a, char *t, size_t size)
{
    static const char *const big[] = {"9223372036854775807", "-9223372036854775808", "99999999999999999999",
                                      "2147483648", "-2147483649", "65536", "32768", "-32769", "16777216"};
    uint32_t cls = take(s, 1);
    switch (a->type) {
    case FX_ARG_INT:
    case FX_ARG_FX16:
    case FX_ARG_FX56: {
        unsigned sh = a->type == FX_ARG_INT ? 0 : a->type == FX_ARG_FX16 ? 16 : 56;
        int64_t v;
        if (a->flags & FX_ARG_WORK) {
            int64_t cap = a->max - a->min > FUZZ_WORK_BUDGET ? a->min + FUZZ_WORK_BUDGET : a->max;
            switch (cls % 6) {
            case 0: v = a->min; break;
            case 1: v = a->min > INT64_MIN ? a->min - 1 : a->min; break;
            case 2: v = a->max < INT64_MAX ? a->max + 1 : a->max; break;
            default: v = a->min + (int64_t)(take(s, 1) % (uint64_t)(cap - a->min + 1));
            }
        } else
        switch (cls % 12) {
        case 0: v = a->min; break;
        case 1: v = a->max; break;
        case 2: v = 0; break;
        case 3: v = (int64_t)1 << sh; break;
        case 4: v = -((int64_t)1 << sh); break;
        case 5: v = a->min > INT64_MIN ? a->min - 1 : a->min; break;
        case 6: v = a->max < INT64_MAX ? a->max + 1 : a->max; break;
        case 7: snprintf(t, size, "%s", big[take(s, 1) % (sizeof big / sizeof big[0])]); return;
        default: { /* inside the range, spread over its magnitude */
            uint64_t span = (uint64_t)a->max - (uint64_t)a->min;
            uint64_t r = (uint64_t)take(s, 4) << 32 | take(s, 4);
            unsigned bits = take(s, 1) % 64;
            r &= bits == 63 ? ~(uint64_t)0 : (((uint64_t)1 << (bits + 1)) - 1);
            v = (int64_t)((uint64_t)a->min + (span == UINT64_MAX ? r : r % (span + 1)));
        }
        }
        if (sh)
            fixed(t, size, v, sh);
        else
            snprintf(t, size, "%lld", (long long)v);
        return;
    }
    case FX_ARG_COLOR: snprintf(t, size, "#%08X", take(s, 4)); return;
    case FX_ARG_STRING: snprintf(t, size, cls & 1 ? "\"missing\"" : "\"x\""); return;
    case FX_ARG_WORD: { /* one of the alternatives */
        const char *p = a->name;
        uint32_t k = cls, alts = 1;
        for (const char *q = p; *q; q++)
            alts += *q == '|';
        k %= alts;
        while (k && *p)
            k -= *p++ == '|';
        size_t i = 0;
        while (p[i] && p[i] != '|' && i + 1 < size) {
            t[i] = p[i];
            i++;
        }
        t[i] = 0;
        return;
    }
    default: t[0] = 0;
    }
}

static void gen_line(in *s, out *o)
{
    static int ncmd;
    if (!ncmd)
        while (fx_scene_argspecs[ncmd].cmd)
            ncmd++;
    /* Part of the budget: the commands FUZZ_GRAMMAR_PROFILE=1 shows at tens
     * of ms a line (curves flattened to 2^16 points a piece at +-2^31, the
     * teapot's patches, the fractal lines) come 32 times less often than the
     * others; they would otherwise take 90% of the time. */
    static const char *const heavy[] = {"bezier", "bspline", "spline", "coastline", "fractline", "teapot"};
    uint32_t pick = take(s, 2) % (uint32_t)ncmd;
    for (size_t h = 0; h < sizeof heavy / sizeof heavy[0]; h++)
        if (!strcmp(fx_scene_argspecs[pick].cmd, heavy[h]) && take(s, 1) % 32)
            pick = (pick + 1) % (uint32_t)ncmd;
    const fx_scene_argspec *sp = &fx_scene_argspecs[pick];
    if (sp->pre && (take(s, 1) & 3)) {
        put(o, sp->pre);
        put(o, "\n");
    }
    const fx_scene_arg *forms[32];
    int nf = 0;
    for (const fx_scene_arg *a = sp->args; a->type != FX_ARG_END; a++)
        if (a->type == FX_ARG_FORM && nf < 32)
            forms[nf++] = a;
    const fx_scene_arg *form = nf ? forms[take(s, 1) % (uint32_t)nf] : NULL;
    put(o, sp->cmd);
    char t[96];
    const fx_scene_arg *a = sp->args;
    for (int part = 0; part < 2; part++) {
        if (part == 1) {
            if (!form)
                break;
            if (form->name) {
                put(o, " ");
                put(o, form->name);
            }
            a = form + 1;
        }
        for (; a->type != FX_ARG_END && a->type != FX_ARG_FORM; a++) {
            if (a->type == FX_ARG_OPT) {
                if (take(s, 1) % 4 == 0)
                    return; /* leave the optional rest out */
                continue;
            }
            if (a->type == FX_ARG_REPEAT) {
                const fx_scene_arg *gs = a + 1, *ge = gs;
                while (ge->type != FX_ARG_END && ge->type != FX_ARG_FORM)
                    ge++;
                int64_t max = a->max < a->min + FUZZ_WORK_BUDGET / 2 ? a->max + 1 : a->min + FUZZ_WORK_BUDGET / 2;
                int64_t k = (int64_t)(take(s, 1) % (uint32_t)(max + 1));
                for (int64_t i = 0; i < k; i++)
                    for (const fx_scene_arg *b = gs; b < ge; b++) {
                        value(s, b, t, sizeof t);
                        put(o, " ");
                        put(o, t);
                    }
                a = ge - 1;
                continue;
            }
            value(s, a, t, sizeof t);
            put(o, " ");
            put(o, t);
        }
    }
}

/* FUZZ_GRAMMAR_PROFILE=1: CPU time per command, printed at exit (which
 * commands keep the rate down). */
static struct {
    char cmd[16];
    double sec;
    long n;
} prof[160];

static void prof_print(void)
{
    for (int i = 0; i < 160 && prof[i].cmd[0]; i++)
        fprintf(stderr, "prof %-14s %8ld lines %9.3f s\n", prof[i].cmd, prof[i].n, prof[i].sec);
}

static void prof_add(const char *line, size_t n, double sec)
{
    size_t k = 0;
    while (k < n && k < 15 && line[k] != ' ')
        k++;
    for (int i = 0; i < 160; i++) {
        if (!prof[i].cmd[0]) {
            memcpy(prof[i].cmd, line, k);
            prof[i].cmd[k] = 0;
        }
        if (strlen(prof[i].cmd) == k && !memcmp(prof[i].cmd, line, k)) {
            prof[i].sec += sec;
            prof[i].n++;
            return;
        }
    }
}

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static uint8_t arena[1 << 20];
    static char text[16384];
    static fx_scene sc;
    in s = {data, size};
    out o = {text, 0, sizeof text};
    text[0] = 0;
    put(&o, "size 64 48\n"); /* a small surface keeps each run short */
    for (int lines = 0; lines < 4 && s.n; lines++) {
        gen_line(&s, &o);
        put(&o, "\n");
    }
    static int print = -1;
    if (print < 0)
        print = getenv("FUZZ_GRAMMAR_PRINT") != NULL; /* triage: show the generated script */
    if (print)
        fputs(text, stderr);
    static int profile = -1;
    if (profile < 0 && (profile = getenv("FUZZ_GRAMMAR_PROFILE") != NULL))
        atexit(prof_print);
    max_w = 64, max_h = 48; /* the fuzz budget */
    fx_scene_host host = {NULL, make_surface, load_file, NULL, NULL, NULL};
    fx_scene_init(&sc, &host, arena, sizeof arena);
    /* each line alone, so that one error does not hide the lines after it */
    size_t i = 0;
    int lineno = 1;
    while (i < o.n) {
        size_t e = i;
        while (e < o.n && text[e] != '\n')
            e++;
        sc.err[0] = 0;
        double t0 = profile ? cpu_now() : 0;
        fx_scene_exec_line(&sc, text + i, e - i, lineno++);
        if (profile)
            prof_add(text + i, e - i, cpu_now() - t0);
        i = e + 1;
    }
    free_surface();
    return 0;
}
