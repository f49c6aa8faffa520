/* SPDX-License-Identifier: MIT */
/* Corner tests generated from the scene-script argument table (issue #26).
 *
 * For every command of fx_scene_tables (a command without an entry in
 * fx_scene_argspecs fails), every form, every numeric argument: min, max,
 * 0, +-1, min-1, max+1, values near +-2^15, 2^16, 2^24, 2^31 and 2^63, and for
 * fractions the exact bounds and one unit beyond them; for every repetition,
 * one more than its maximum. Each case is one line (after the entry's set-up
 * lines) run in a child process under a time limit and a memory limit:
 *  - inside the range: the line runs, or fails with a message of its own
 *    (not a range error, not "expected an integer" or "missing": those would
 *    mean the table and the command disagree);
 *  - outside: the message names the declared range, at the token's column.
 * Built plain and with ASan+UBSan (-fno-sanitize-recover=all): any report
 * kills the child and fails the case.
 *   corners [-v] [-t SECONDS] [-m MIB] [COMMAND...]
 * Prints "corners: N passed, N failed". */
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include "fixel/error.h"
#include "fixel/scene.h"
#include "fixel/surface.h"

#if defined(__SANITIZE_ADDRESS__)
#define SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SANITIZED 1
#endif
#endif
#ifndef SANITIZED
#define SANITIZED 0
#endif

static int verbose;
static double limit_s = SANITIZED ? 3.0 : 1.0;
static long limit_mib = 512;
static int passed, failed;

/* ---- the child: run one script on a small surface ---- */
static int make_surface(void *u, int32_t w, int32_t h, fx_format f, fx_surface *out)
{
    (void)u;
    size_t stride = (size_t)w * 4 + 4;
    void *px = calloc((size_t)h, stride);
    if (!px)
        return -FX_ENOMEM;
    return fx_surface_init(out, px, w, h, (int32_t)stride, f);
}

static int load_file(void *u, const char *path, const uint8_t **data, size_t *len)
{
    (void)u;
    (void)path;
    (void)data;
    (void)len;
    return -FX_ENOENT;
}

/* Exit 10: ran; 11: a scene error (the message on fd). */
static void child(const char *script, int fd)
{
    if (!SANITIZED) {
        struct rlimit rl = {(rlim_t)limit_mib << 20, (rlim_t)limit_mib << 20};
        setrlimit(RLIMIT_AS, &rl);
    }
    /* The arena is mapped, not malloc'd, with a page that faults on each
     * side: an overrun still crashes the child, and the sanitizer's
     * allocator no longer sets up a fresh 128 MB chunk and its 16 MB of
     * shadow in every child (53 ms of a case's 61, mostly memset and page
     * faults: the sanitized run took 1,028 s with malloc, 107 s mapped). */
    size_t arena_size = (size_t)128 << 20, page = (size_t)sysconf(_SC_PAGESIZE);
    uint8_t *map = mmap(NULL, arena_size + 2 * page, PROT_READ | PROT_WRITE,
                        MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
    if (map == MAP_FAILED || mprotect(map, page, PROT_NONE) < 0 ||
        mprotect(map + page + arena_size, page, PROT_NONE) < 0)
        _exit(12);
    uint8_t *arena = map + page;
    fx_scene sc;
    fx_scene_host host = {0, make_surface, load_file, 0, 0, NULL};
    fx_scene_init(&sc, &host, arena, arena_size);
    fx_scene_fix_size(&sc, 64, 48);
    int r = fx_scene_run(&sc, script, strlen(script));
    if (r < 0) {
        char msg[300];
        int n = snprintf(msg, sizeof msg, "%d:%d: %s", sc.err_line, sc.err_col, sc.err);
        if (write(fd, msg, (size_t)n) < 0)
            _exit(13);
        _exit(11);
    }
    _exit(10);
}

/* Runs the script; returns the child's code (10/11), or -signal, or -1000 on
 * a time-out, -1001 over the memory limit. msg gets the error text. */
static int run(const char *script, char *msg, size_t size)
{
    int p[2];
    if (pipe(p) < 0)
        return -2000;
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
        close(p[0]);
        /* CPU time (SIGPROF) is the limit: the machine may be shared, and
         * wall time would measure the neighbours; a wall-clock alarm of 10x
         * catches a run that blocks. */
        struct itimerval it = {{0, 0}, {(time_t)limit_s, (suseconds_t)((limit_s - (time_t)limit_s) * 1e6)}};
        setitimer(ITIMER_PROF, &it, 0);
        alarm((unsigned)(limit_s * 10) + 1);
        child(script, p[1]);
    }
    close(p[1]);
    size_t n = 0;
    ssize_t k;
    while (n + 1 < size && (k = read(p[0], msg + n, size - 1 - n)) > 0)
        n += (size_t)k;
    msg[n] = 0;
    close(p[0]);
    int st;
    struct rusage ru;
    if (wait4(pid, &st, 0, &ru) < 0)
        return -2000;
    if (WIFSIGNALED(st))
        return WTERMSIG(st) == SIGALRM || WTERMSIG(st) == SIGPROF ? -1000 : -WTERMSIG(st);
    if (ru.ru_maxrss > limit_mib * 1024)
        return -1001;
    return WEXITSTATUS(st);
}

/* ---- generating lines ---- */
typedef struct slot {
    const fx_scene_arg *a; /* NULL: a literal keyword */
    const char *kw;
} slot;

#define MAXSLOTS 2200

static void first_alt(const char *choices, char *out, size_t size)
{
    size_t i = 0;
    while (choices[i] && choices[i] != '|' && i + 1 < size) {
        out[i] = choices[i];
        i++;
    }
    out[i] = 0;
}

/* Exact decimal of raw / 2^shift. */
static void exact(char *buf, size_t size, int64_t raw, unsigned shift)
{
    uint64_t m = raw < 0 ? 0 - (uint64_t)raw : (uint64_t)raw;
    uint64_t ip = m >> shift, fr = m & (((uint64_t)1 << shift) - 1);
    int n = snprintf(buf, size, "%s%llu", raw < 0 ? "-" : "", (unsigned long long)ip);
    if (fr && (size_t)n + 2 < size) {
        buf[n++] = '.';
        while (fr && (size_t)n + 1 < size) {
            fr *= 10;
            buf[n++] = (char)('0' + (fr >> shift));
            fr &= ((uint64_t)1 << shift) - 1;
        }
        buf[n] = 0;
    }
}

static void typical(const fx_scene_arg *a, char *out, size_t size)
{
    int64_t v;
    switch (a->type) {
    case FX_ARG_INT:
        v = 8;
        if (v < a->min)
            v = a->min;
        if (v > a->max)
            v = a->max;
        snprintf(out, size, "%lld", (long long)v);
        break;
    case FX_ARG_FX16:
    case FX_ARG_FX56: {
        unsigned sh = a->type == FX_ARG_FX16 ? 16 : 56;
        int64_t one = (int64_t)1 << sh;
        v = 2 * one;
        if (v > a->max)
            v = a->max;
        if (v < a->min || ((a->flags & FX_ARG_OPEN_MIN) && v <= a->min))
            v = a->min + ((a->flags & FX_ARG_OPEN_MIN) ? one / 4 : 0);
        exact(out, size, v, sh);
        break;
    }
    case FX_ARG_COLOR: snprintf(out, size, "#FF8040"); break;
    case FX_ARG_WORD: first_alt(a->name, out, size); break;
    case FX_ARG_STRING: snprintf(out, size, "\"x\""); break;
    default: out[0] = 0;
    }
}

/* The slots of one form: prefix (entries before the first FORM), then the
 * form's own entries; a repetition expanded `reps` times (0: its minimum,
 * at least once). */
static int form_slots(const fx_scene_arg *args, const fx_scene_arg *form, int64_t reps, slot *sl,
                      const fx_scene_arg **rep_out)
{
    int n = 0;
    *rep_out = 0;
    const fx_scene_arg *a = args;
    for (int part = 0; part < 2; part++) {
        if (part == 1) {
            if (!form)
                break;
            if (form->name)
                sl[n++] = (slot){0, form->name};
            a = form + 1;
        }
        for (; a->type != FX_ARG_END && a->type != FX_ARG_FORM; a++) {
            if (a->type == FX_ARG_OPT)
                continue;
            if (a->type == FX_ARG_REPEAT) {
                *rep_out = a;
                int64_t k = reps ? reps : a->min; /* 0: an optional list left out */
                const fx_scene_arg *g = a + 1, *e = g;
                while (e->type != FX_ARG_END && e->type != FX_ARG_FORM)
                    e++;
                for (int64_t i = 0; i < k && n + (e - g) < MAXSLOTS; i++)
                    for (const fx_scene_arg *b = g; b < e; b++)
                        sl[n++] = (slot){b, 0};
                a = e - 1;
                continue;
            }
            sl[n++] = (slot){a, 0};
        }
    }
    return n;
}

/* Builds "pre\ncmd tok tok ..." with slot `which` replaced by `val`; *col
 * gets the 1-based column of that token, *line its line number. */
static char *build(const fx_scene_argspec *sp, const slot *sl, int n, int which, const char *val, int *line,
                   int *col)
{
    size_t cap = 64 + (size_t)n * 80 + (sp->pre ? strlen(sp->pre) : 0) + strlen(val);
    char *s = malloc(cap);
    size_t o = 0;
    *line = 1;
    if (sp->pre) {
        o += (size_t)snprintf(s + o, cap - o, "%s\n", sp->pre);
        for (const char *p = sp->pre; *p; p++)
            *line += *p == '\n';
        (*line)++;
    }
    size_t line_start = o;
    o += (size_t)snprintf(s + o, cap - o, "%s", sp->cmd);
    for (int i = 0; i < n; i++) {
        char t[128];
        if (!sl[i].a)
            snprintf(t, sizeof t, "%s", sl[i].kw);
        else if (i == which)
            snprintf(t, sizeof t, "%s", val);
        else
            typical(sl[i].a, t, sizeof t);
        if (i == which)
            *col = (int)(o - line_start) + 2;
        o += (size_t)snprintf(s + o, cap - o, " %s", t);
    }
    return s;
}

static void report(int ok, const char *what, const char *script, const char *detail)
{
    if (ok) {
        passed++;
        if (verbose)
            printf("ok   %s\n", what);
        return;
    }
    failed++;
    if (failed <= 300) {
        const char *last = strrchr(script, '\n');
        printf("FAIL %s: %s\n     line: %s\n", what, detail, last ? last + 1 : script);
    }
}

static const char *outcome(int rc, char *buf, size_t size)
{
    if (rc == -1000)
        snprintf(buf, size, "over the time limit (%.1f s of CPU)", limit_s);
    else if (rc == -1001)
        snprintf(buf, size, "over the memory limit (%ld MiB)", limit_mib);
    else if (rc < 0)
        snprintf(buf, size, "killed by signal %d (a sanitizer report or a crash)", -rc);
    else
        snprintf(buf, size, "exit %d", rc);
    return buf;
}

static int disagrees(const char *msg)
{
    static const char *const bad[] = {"out of range, expected", "expected an integer", "expected a decimal",
                                      "missing ", "unexpected argument", "argument table", "expected a colour",
                                      "expected a double-quoted", 0};
    for (int i = 0; bad[i]; i++)
        if (strstr(msg, bad[i]))
            return 1;
    return 0;
}

static void one(const fx_scene_argspec *sp, const slot *sl, int n, int which, const char *val, int in_range,
                const char *range)
{
    int line, col;
    char *script = build(sp, sl, n, which, val, &line, &col);
    char msg[400], what[300], why[600], o[100];
    int rc = run(script, msg, sizeof msg);
    snprintf(what, sizeof what, "%s %s=%s", sp->cmd, which >= 0 ? sl[which].a->name : "", val);
    if (in_range) {
        int ok = rc == 10 || (rc == 11 && !disagrees(msg));
        snprintf(why, sizeof why, "inside %s: %s %s", range, outcome(rc, o, sizeof o), msg);
        report(ok, what, script, why);
    } else {
        char want[200];
        snprintf(want, sizeof want, "%d:%d: %s ", line, col, sl[which].a->name);
        int ok = rc == 11 && !strncmp(msg, want, strlen(want)) && strstr(msg, range) &&
                 strstr(msg, "out of range, expected");
        snprintf(why, sizeof why, "outside %s: wanted '%s... expected %s', got %s '%s'", range, want, range,
                 outcome(rc, o, sizeof o), msg);
        report(ok, what, script, why);
    }
    free(script);
}

static int in(const fx_scene_arg *a, int64_t raw)
{
    if (raw > a->max)
        return 0;
    return (a->flags & FX_ARG_OPEN_MIN) ? raw > a->min : raw >= a->min;
}

/* The corner values of one numeric slot. */
static void corners(const fx_scene_argspec *sp, const slot *sl, int n, int k)
{
    const fx_scene_arg *a = sl[k].a;
    char range[64], v[128];
    fx_scene_arg_range(a, range, sizeof range);
    static const char *const big[] = {"9223372036854775807", "9223372036854775808", "-9223372036854775808",
                                      "-9223372036854775809", "99999999999999999999999"};
    static const int64_t near[] = {0, 1, -1, 32767, 32768, -32768, -32769, 65535, 65536, -65536, 16777215,
                                   16777216, -16777216, 2147483647, 2147483648LL, -2147483647 - 1, -2147483649LL};
    if (a->type == FX_ARG_INT) {
        int64_t vals[40];
        int nv = 0;
        for (size_t i = 0; i < sizeof near / sizeof near[0]; i++)
            vals[nv++] = near[i];
        vals[nv++] = a->min;
        vals[nv++] = a->max;
        vals[nv++] = a->min - 1;
        vals[nv++] = a->max + 1;
        for (int i = 0; i < nv; i++) {
            int dup = 0;
            for (int j = 0; j < i; j++)
                dup |= vals[j] == vals[i];
            if (dup)
                continue;
            snprintf(v, sizeof v, "%lld", (long long)vals[i]);
            one(sp, sl, n, k, v, vals[i] >= a->min && vals[i] <= a->max, range);
        }
        for (size_t i = 0; i < sizeof big / sizeof big[0]; i++)
            one(sp, sl, n, k, big[i], 0, range);
        return;
    }
    unsigned sh = a->type == FX_ARG_FX16 ? 16 : 56;
    int64_t lim = sh == 16 ? 32768 : 128; /* whole values beyond the type */
    for (size_t i = 0; i < sizeof near / sizeof near[0]; i++) {
        int64_t w = near[i];
        snprintf(v, sizeof v, "%lld", (long long)w);
        int inr = 0;
        if (w > -lim && w < lim)
            inr = in(a, w * ((int64_t)1 << sh));
        else if (w == -lim)
            inr = in(a, sh == 16 ? (int64_t)INT32_MIN : INT64_MIN);
        one(sp, sl, n, k, v, inr, range);
    }
    int64_t raws[4] = {a->min, a->max, a->min - 1, a->max + 1};
    int64_t tmax = sh == 16 ? INT32_MAX : INT64_MAX, tmin = sh == 16 ? INT32_MIN : INT64_MIN;
    for (int i = 0; i < 4; i++) {
        if ((i == 2 && a->min == tmin) || (i == 3 && a->max == tmax))
            continue; /* beyond the type: covered by the whole values */
        exact(v, sizeof v, raws[i], sh);
        one(sp, sl, n, k, v, in(a, raws[i]), range);
    }
    one(sp, sl, n, k, "0.5", in(a, (int64_t)1 << (sh - 1)), range);
    for (size_t i = 0; i < sizeof big / sizeof big[0]; i++)
        one(sp, sl, n, k, big[i], 0, range);
}

static int selected(const char *cmd, int argc, char **argv, int first)
{
    if (first >= argc)
        return 1;
    for (int i = first; i < argc; i++)
        if (!strcmp(argv[i], cmd))
            return 1;
    return 0;
}

int main(int argc, char **argv)
{
    int i = 1;
    for (; i < argc && argv[i][0] == '-'; i++) {
        if (!strcmp(argv[i], "-v"))
            verbose = 1;
        else if (!strcmp(argv[i], "-t") && i + 1 < argc)
            limit_s = atof(argv[++i]);
        else if (!strcmp(argv[i], "-m") && i + 1 < argc)
            limit_mib = atol(argv[++i]);
    }
    static slot sl[MAXSLOTS];
    int ncmd = 0, nargs = 0;
    /* every command has an entry, every entry a command */
    for (int t = 0; fx_scene_tables[t]; t++)
        for (const fx_scene_cmd *c = fx_scene_tables[t]; c->name; c++) {
            ncmd++;
            if (!selected(c->name, argc, argv, i))
                continue;
            const fx_scene_argspec *sp = fx_scene_args_find(c->name);
            if (!sp) {
                report(0, c->name, c->name, "no entry in the argument table");
                continue;
            }
            passed++;
        }
    for (const fx_scene_argspec *sp = fx_scene_argspecs; sp->cmd; sp++)
        if (!fx_scene_find(sp->cmd, strlen(sp->cmd)))
            report(0, sp->cmd, sp->cmd, "table entry for a command that does not exist");
    for (const fx_scene_argspec *sp = fx_scene_argspecs; sp->cmd; sp++) {
        if (!selected(sp->cmd, argc, argv, i))
            continue;
        /* the forms: each FORM entry, or the whole entry when it has none */
        const fx_scene_arg *forms[32];
        int nf = 0;
        for (const fx_scene_arg *a = sp->args; a->type != FX_ARG_END; a++)
            if (a->type == FX_ARG_FORM && nf < 32)
                forms[nf++] = a;
        if (!nf)
            forms[nf++] = 0;
        for (int f = 0; f < nf; f++) {
            const fx_scene_arg *rep;
            int n = form_slots(sp->args, forms[f], 0, sl, &rep);
            one(sp, sl, n, -1, "", 1, "the typical values"); /* the baseline itself */
            for (int k = 0; k < n; k++)
                if (sl[k].a && (sl[k].a->type == FX_ARG_INT || sl[k].a->type == FX_ARG_FX16 ||
                                sl[k].a->type == FX_ARG_FX56)) {
                    /* a slot of a shared prefix is covered by the first form */
                    if (f > 0 && sl[k].a < forms[0])
                        continue;
                    nargs++;
                    corners(sp, sl, n, k);
                }
            if (rep && rep->max < MAXSLOTS / 4) {
                int m = form_slots(sp->args, forms[f], rep->max + 1, sl, &rep);
                int line, col;
                char *script = build(sp, sl, m, -1, "", &line, &col);
                char msg[400], why[600], o[100], range[64], what[200];
                fx_scene_arg_range(rep, range, sizeof range);
                int rc = run(script, msg, sizeof msg);
                snprintf(what, sizeof what, "%s %s x%lld", sp->cmd, rep->name, (long long)rep->max + 1);
                snprintf(why, sizeof why, "wanted '... expected %s', got %s '%s'", range, outcome(rc, o, sizeof o),
                         msg);
                report(rc == 11 && strstr(msg, "out of range, expected") && strstr(msg, range), what, script,
                       why);
                free(script);
            }
        }
    }
    printf("corners: %d commands, %d numeric arguments%s\n", ncmd, nargs, SANITIZED ? " (ASan+UBSan)" : "");
    printf("corners: %d passed, %d failed\n", passed, failed);
    return failed != 0;
}
