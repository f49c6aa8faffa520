/* SPDX-License-Identifier: MIT */
/* kbench: message-to-pixels latency of fixel-kiosk over MQTT (make
 * bench-kiosk, docs/BENCHMARK.md section 8).
 *
 * Publishes the sequence numbers 1..N as plain payloads on one topic at a
 * fixed rate (QoS 1 by default; each message at a random point of its
 * period) to a broker on 127.0.0.1, taking
 * CLOCK_MONOTONIC just before each mosquitto_publish, and reads the trace
 * every kiosk writes with FIXEL_KIOSK_TRACE (one line per presented frame,
 * the same clock, the value each widget drew). Message s counts as
 * presented by the first frame whose value is s or a later one (a frame
 * shows the newest value; older ones it replaced in the same frame are
 * "coalesced"); its latency is that frame's time minus s's publish time.
 * Before timing, probe values -1, -2, ... are published until every kiosk
 * presents one, so each is subscribed and drawing. Lost messages come from
 * the kiosk's own line counter (every MQTT message it took counts one),
 * mismatched ones are values presented that were never published, that
 * could not be read, or that went backwards. CPU is utime + stime from
 * /proc/PID/stat between the first publish and the last value presented,
 * as a percentage of one core; RSS is VmRSS at the end.
 *
 * --lockstep publishes the next value only after every kiosk presented the
 * previous one (the test suite's smoke run: every value must be on screen
 * by itself). Every wait is bounded. Exit status 0 only when every kiosk
 * presented every value, none lost or mismatched.
 */
#include <errno.h>
#include <fcntl.h>
#include <mosquitto.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define MAX_KIOSKS 64
#define MAX_COUNT 1000000
#define MAX_PROBES 30

typedef struct kiosk {
    int pid;
    const char *path;
    int fd;
    char buf[8192];
    size_t blen;
    int skip;              /* the first line read is the rest of one begun before */
    /* what the trace said so far */
    long long last;        /* newest value presented (0: none yet; negative: a probe) */
    long long lines0;      /* the kiosk's line count when it presented the last probe */
    long long lines;       /* its line count in the newest frame */
    long long frames;      /* frames presented */
    long long frames0;
    long long exact;       /* values presented by themselves */
    long long mismatched;
    char bad[160];         /* the first mismatch, for the report */
    int64_t *lat;          /* ns per sequence number, -1: not presented */
    unsigned long long cpu0, cpu1; /* utime + stime, clock ticks */
    long rss_kb;
} kiosk;

static const char *source = "v";
static int64_t *tpub;           /* publish time of each sequence number */
static long long published;     /* sequence numbers published so far */
static atomic_int acked, connected;

static int64_t mono_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (int64_t)ts.tv_sec * 1000000000 + ts.tv_nsec;
}

static void nap_ms(int ms)
{
    struct timespec ts = {ms / 1000, (long)(ms % 1000) * 1000000L};
    nanosleep(&ts, NULL);
}

static void on_connect(struct mosquitto *m, void *u, int rc)
{
    (void)m; (void)u;
    if (rc == 0) atomic_store(&connected, 1);
}

static void on_publish(struct mosquitto *m, void *u, int mid)
{
    (void)m; (void)u; (void)mid;
    atomic_fetch_add(&acked, 1);
}

/* A value as a widget draws it: an integer, or one with a fraction of zeros
 * ("17.0" from decimals=1). 0 and *v, or -1. */
static int parse_value(const char *s, size_t n, long long *v)
{
    char t[64];
    if (n == 0 || n >= sizeof t) return -1;
    memcpy(t, s, n);
    t[n] = 0;
    char *e;
    errno = 0;
    long long x = strtoll(t, &e, 10);
    if (e == t || errno) return -1;
    if (*e == '.') {
        e++;
        if (!*e) return -1;
        while (*e == '0') e++;
    }
    if (*e) return -1;
    *v = x;
    return 0;
}

__attribute__((format(printf, 2, 3))) static void mismatch(kiosk *k, const char *fmt, ...)
{
    if (!k->mismatched) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(k->bad, sizeof k->bad, fmt, ap);
        va_end(ap);
    }
    k->mismatched++;
}

/* One trace line: MONO_NS TAB FRAME TAB LINES (TAB NAME=VALUE)* */
static void trace_line(kiosk *k, char *l)
{
    char *f[3], *p = l;
    for (int i = 0; i < 3; i++) {
        f[i] = p;
        p = strchr(p, '\t');
        if (p) *p++ = 0;
        else if (i < 2) { mismatch(k, "unreadable trace line '%s'", l); return; }
    }
    int64_t t = strtoll(f[0], NULL, 10);
    k->frames = strtoll(f[1], NULL, 10);
    k->lines = strtoll(f[2], NULL, 10);
    size_t sl = strlen(source);
    long long shown = 0;
    int have = 0;
    while (p && *p) {
        char *tok = p;
        p = strchr(p, '\t');
        if (p) *p++ = 0;
        if (strncmp(tok, source, sl) || tok[sl] != '=') continue;
        long long v;
        if (!strcmp(tok + sl + 1, "--") && k->last <= 0) continue; /* no value yet */
        if (parse_value(tok + sl + 1, strlen(tok + sl + 1), &v) < 0) {
            mismatch(k, "presented '%s', not a published value", tok);
            continue;
        }
        if (have && v != shown) mismatch(k, "two widgets of one frame show %lld and %lld", shown, v);
        shown = v;
        have = 1;
    }
    if (!have) return;
    if (shown < 0) { /* a probe: the timed run starts after it */
        if (k->last <= 0) k->last = shown;
        return;
    }
    if (shown == k->last) return; /* redrawn (stale marking, a reload): nothing new */
    if (shown < k->last || shown > published || shown == 0) {
        mismatch(k, "%s %lld after %lld", shown < k->last ? "went back to" : "presented unpublished", shown, k->last);
        return;
    }
    for (long long s = k->last < 0 ? 1 : k->last + 1; s <= shown; s++) k->lat[s] = t - tpub[s];
    k->exact++;
    k->last = shown;
}

/* Read what the kiosk appended since the last call. */
static void poll_trace(kiosk *k)
{
    for (;;) {
        ssize_t r = read(k->fd, k->buf + k->blen, sizeof k->buf - 1 - k->blen);
        if (r <= 0) return;
        k->blen += (size_t)r;
        k->buf[k->blen] = 0;
        char *s = k->buf, *nl;
        while ((nl = strchr(s, '\n'))) {
            *nl = 0;
            if (k->skip) k->skip = 0;
            else trace_line(k, s);
            s = nl + 1;
        }
        k->blen -= (size_t)(s - k->buf);
        memmove(k->buf, s, k->blen);
        if (k->blen == sizeof k->buf - 1) k->blen = 0; /* a line longer than the buffer: dropped */
    }
}

static unsigned long long cpu_ticks(int pid)
{
    char p[64], b[1024];
    snprintf(p, sizeof p, "/proc/%d/stat", pid);
    FILE *f = fopen(p, "r");
    if (!f) return 0;
    size_t n = fread(b, 1, sizeof b - 1, f);
    fclose(f);
    b[n] = 0;
    char *c = strrchr(b, ')'); /* the command name may hold spaces */
    unsigned long long ut = 0, st = 0;
    if (c && sscanf(c + 2, "%*c %*d %*d %*d %*d %*d %*u %*u %*u %*u %*u %llu %llu", &ut, &st) == 2) return ut + st;
    return 0;
}

static long rss_kb(int pid)
{
    char p[64], l[256];
    long kb = -1;
    snprintf(p, sizeof p, "/proc/%d/status", pid);
    FILE *f = fopen(p, "r");
    if (!f) return -1;
    while (fgets(l, sizeof l, f))
        if (sscanf(l, "VmRSS: %ld", &kb) == 1) break;
    fclose(f);
    return kb;
}

static int cmp64(const void *a, const void *b)
{
    int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return x < y ? -1 : x > y;
}

/* nearest rank: the smallest value with at least p percent at or below it */
static int64_t pct(const int64_t *s, long long n, int p)
{
    long long r = (n * p + 99) / 100;
    return s[r < 1 ? 0 : r - 1];
}

static void usage(void)
{
    fprintf(stderr, "usage: kbench --port P [--topic T] [--rate R] [--count N] [--qos Q] [--source NAME]\n"
                    "              [--lockstep] [--drain-ms MS] [--broker PID] [--label TEXT] PID:TRACE...\n");
    exit(2);
}

int main(int argc, char **argv)
{
    static kiosk ks[MAX_KIOSKS];
    int nk = 0, port = 0, qos = 1, lockstep = 0, broker = 0, drain_ms = 20000;
    long long count = 100;
    double rate = 10;
    const char *topic = "kbench/seq", *label = "";
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--lockstep")) lockstep = 1;
        else if (!v && a[0] == '-') usage();
        else if (!strcmp(a, "--port")) port = atoi(v), i++;
        else if (!strcmp(a, "--topic")) topic = v, i++;
        else if (!strcmp(a, "--rate")) rate = atof(v), i++;
        else if (!strcmp(a, "--count")) count = atoll(v), i++;
        else if (!strcmp(a, "--qos")) qos = atoi(v), i++;
        else if (!strcmp(a, "--source")) source = v, i++;
        else if (!strcmp(a, "--drain-ms")) drain_ms = atoi(v), i++;
        else if (!strcmp(a, "--broker")) broker = atoi(v), i++;
        else if (!strcmp(a, "--label")) label = v, i++;
        else if (a[0] != '-' && strchr(a, ':') && nk < MAX_KIOSKS) {
            ks[nk].pid = atoi(a);
            ks[nk].path = strchr(a, ':') + 1;
            nk++;
        } else usage();
    }
    if (port < 1 || port > 65535 || count < 1 || count > MAX_COUNT || rate <= 0 || rate > 100000 || qos < 0 ||
        qos > 2 || nk == 0 || drain_ms < 100)
        usage();
    tpub = calloc((size_t)count + 1, sizeof *tpub);
    for (int i = 0; i < nk; i++) {
        ks[i].lat = malloc(((size_t)count + 1) * sizeof *ks[i].lat);
        if (!tpub || !ks[i].lat) { fprintf(stderr, "kbench: out of memory\n"); return 1; }
        for (long long s = 0; s <= count; s++) ks[i].lat[s] = -1;
        /* the kiosk creates its trace when it starts: give it 20 s */
        for (int w = 0; w < 200 && (ks[i].fd = open(ks[i].path, O_RDONLY | O_CLOEXEC)) < 0; w++) nap_ms(100);
        if (ks[i].fd < 0) { fprintf(stderr, "kbench: %s: %s\n", ks[i].path, strerror(errno)); return 1; }
        /* an earlier run's frames are not this run's: read from the end
         * (from the next line, if the kiosk is in the middle of one) */
        off_t end = lseek(ks[i].fd, 0, SEEK_END);
        char last = '\n';
        if (end > 0 && pread(ks[i].fd, &last, 1, end - 1) == 1 && last != '\n') ks[i].skip = 1;
    }

    mosquitto_lib_init();
    struct mosquitto *m = mosquitto_new(NULL, true, NULL);
    if (!m) { fprintf(stderr, "kbench: mosquitto_new failed\n"); return 1; }
    mosquitto_connect_callback_set(m, on_connect);
    mosquitto_publish_callback_set(m, on_publish);
    /* QoS 1 at 1000/s: the default 20 unacknowledged messages would queue
     * the publisher behind the broker's round trips */
    mosquitto_int_option(m, MOSQ_OPT_SEND_MAXIMUM, 1000);
    int rc = mosquitto_connect(m, "127.0.0.1", port, 30);
    if (rc != MOSQ_ERR_SUCCESS || mosquitto_loop_start(m) != MOSQ_ERR_SUCCESS) {
        fprintf(stderr, "kbench: 127.0.0.1:%d: %s\n", port, mosquitto_strerror(rc));
        return 1;
    }
    for (int w = 0; w < 100 && !atomic_load(&connected); w++) nap_ms(100);
    if (!atomic_load(&connected)) { fprintf(stderr, "kbench: no CONNACK from 127.0.0.1:%d in 10 s\n", port); return 1; }

    /* probes until every kiosk draws one: subscribed, connected, drawing */
    int probed = 0;
    for (int p = 1; p <= MAX_PROBES && !probed; p++) {
        char pl[16];
        snprintf(pl, sizeof pl, "-%d", p);
        mosquitto_publish(m, NULL, topic, (int)strlen(pl), pl, qos, false);
        for (int w = 0; w < 200 && !probed; w++) {
            nap_ms(5);
            probed = 1;
            for (int i = 0; i < nk; i++) {
                poll_trace(&ks[i]);
                if (ks[i].last >= 0) probed = 0;
            }
        }
    }
    if (!probed) {
        for (int i = 0; i < nk; i++)
            if (ks[i].last >= 0) fprintf(stderr, "kbench: kiosk pid %d (%s) presented no probe value in %d s\n", ks[i].pid, ks[i].path, MAX_PROBES);
        return 1;
    }
    /* probes still in flight would count as lines of the timed run */
    for (int w = 0; w < 100 && atomic_load(&acked) < probed; w++) nap_ms(10);
    nap_ms(300);
    for (int i = 0; i < nk; i++) {
        poll_trace(&ks[i]);
        ks[i].lines0 = ks[i].lines;
        ks[i].frames0 = ks[i].frames;
    }
    int acked0 = atomic_load(&acked);

    unsigned long long bcpu0 = broker ? cpu_ticks(broker) : 0;
    for (int i = 0; i < nk; i++) ks[i].cpu0 = cpu_ticks(ks[i].pid);
    int64_t period = (int64_t)(1e9 / rate), t0 = mono_ns(), tlate = 0, due = t0;
    long long late = 0;
    uint32_t rng = 12345; /* xorshift32: the same schedule every run */
    for (long long s = 1; s <= count; s++) {
        char pl[24];
        if (!lockstep) {
            /* message s at a uniformly random point of its period: sensors
             * do not keep time with the kiosk, and a strict 100 ms period
             * would lock to the kiosk's 100 ms tick at one phase */
            rng ^= rng << 13, rng ^= rng >> 17, rng ^= rng << 5;
            due = t0 + (s - 1) * period + (int64_t)(rng % 1000000u) * period / 1000000;
            struct timespec ts = {(time_t)(due / 1000000000), (long)(due % 1000000000)};
            while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, NULL) == EINTR) {}
        }
        snprintf(pl, sizeof pl, "%lld", s);
        tpub[s] = mono_ns();
        if (!lockstep && tpub[s] - due > 1000000) late++, tlate += tpub[s] - due;
        published = s;
        rc = mosquitto_publish(m, NULL, topic, (int)strlen(pl), pl, qos, false);
        if (rc != MOSQ_ERR_SUCCESS) { fprintf(stderr, "kbench: publish %lld: %s\n", s, mosquitto_strerror(rc)); return 1; }
        if (lockstep) {
            int all = 0;
            for (int w = 0; w < 2000 && !all; w++) { /* 10 s per value */
                all = 1;
                for (int i = 0; i < nk; i++) {
                    poll_trace(&ks[i]);
                    if (ks[i].last < s) all = 0;
                }
                if (!all) nap_ms(5);
            }
            if (!all) break; /* reported below as not presented */
        }
    }
    int64_t tpubend = mono_ns();
    /* drain: until every kiosk presented the last value (bounded) */
    int64_t tend = 0;
    for (int w = 0; w * 5 < drain_ms; w++) {
        int all = 1;
        for (int i = 0; i < nk; i++) {
            poll_trace(&ks[i]);
            if (ks[i].last < published) all = 0;
        }
        if (all) { tend = mono_ns(); break; }
        nap_ms(5);
    }
    if (!tend) tend = mono_ns();
    for (int i = 0; i < nk; i++) {
        ks[i].cpu1 = cpu_ticks(ks[i].pid);
        ks[i].rss_kb = rss_kb(ks[i].pid);
    }
    unsigned long long bcpu1 = broker ? cpu_ticks(broker) : 0;
    long brss = broker ? rss_kb(broker) : 0;
    /* the broker acknowledged every QoS 1/2 message (bounded) */
    for (int w = 0; w < 500 && qos && atomic_load(&acked) - acked0 < published; w++) nap_ms(10);
    /* the kiosks' line counters settle in the frames after the last value */
    nap_ms(400);
    for (int i = 0; i < nk; i++) poll_trace(&ks[i]);
    int nacked = atomic_load(&acked) - acked0;
    mosquitto_disconnect(m);
    mosquitto_loop_stop(m, false);
    mosquitto_destroy(m);
    mosquitto_lib_cleanup();

    double wall = (double)(tend - t0) / 1e9, hz = (double)sysconf(_SC_CLK_TCK);
    printf("kbench: %s%srate %.0f/s, %lld published in %.2f s (%.1f/s), %d acknowledged by the broker, %lld late by > 1 ms (mean %.1f ms)%s\n",
           label, label[0] ? ": " : "", rate, published, (double)(tpubend - t0) / 1e9,
           published / ((double)(tpubend - t0) / 1e9 > 0 ? (double)(tpubend - t0) / 1e9 : 1), nacked, late,
           late ? (double)tlate / late / 1e6 : 0.0, lockstep ? " (lockstep)" : "");
    int fail = published < count || (qos && nacked < published);
    int64_t *all = malloc(((size_t)count + 1) * sizeof *all * (size_t)nk), worst50 = 0, worst99 = 0;
    long long nall = 0, lost_total = 0, mism_total = 0, unshown_total = 0;
    double cpu_total = 0;
    long rss_total = 0;
    int w50 = 0, w99 = 0;
    for (int i = 0; i < nk; i++) {
        kiosk *k = &ks[i];
        int64_t *v = all + nall;
        long long n = 0;
        for (long long s = 1; s <= published; s++)
            if (k->lat[s] >= 0) v[n++] = k->lat[s];
        qsort(v, (size_t)n, sizeof *v, cmp64);
        long long unshown = published - n, got = k->lines - k->lines0, lost = published - got;
        double cpu = (double)(k->cpu1 - k->cpu0) / hz / wall * 100;
        int64_t p50 = n ? pct(v, n, 50) : -1, p99 = n ? pct(v, n, 99) : -1;
        printf("kbench:   kiosk %2d pid %d: presented %lld/%lld (%lld frames with a new value, %lld coalesced), "
               "lost %lld, mismatched %lld, latency p50 %.1f ms p99 %.1f ms max %.1f ms, %lld frames, cpu %.1f %% of a core, rss %ld KiB\n",
               i + 1, k->pid, n, published, k->exact, n - k->exact, lost < 0 ? 0 : lost, k->mismatched,
               p50 / 1e6, p99 / 1e6, n ? v[n - 1] / 1e6 : -1.0, k->frames - k->frames0, cpu, k->rss_kb);
        if (k->mismatched) printf("kbench:   kiosk %2d: first mismatch: %s\n", i + 1, k->bad);
        if (lost) printf("kbench:   kiosk %2d: counted %lld messages of %lld (lines %lld -> %lld)\n", i + 1, got, published, k->lines0, k->lines);
        if (lockstep && k->exact < published) printf("kbench:   kiosk %2d: %lld values were not presented by themselves\n", i + 1, published - k->exact);
        if (p50 > worst50) worst50 = p50, w50 = i + 1;
        if (p99 > worst99) worst99 = p99, w99 = i + 1;
        fail |= unshown || lost || k->mismatched || (lockstep && k->exact < published);
        lost_total += lost < 0 ? 0 : lost;
        mism_total += k->mismatched;
        unshown_total += unshown;
        cpu_total += cpu;
        rss_total += k->rss_kb;
        nall += n;
    }
    qsort(all, (size_t)nall, sizeof *all, cmp64);
    printf("kbench: %s%s%d kiosk(s): p50 %.1f ms p99 %.1f ms over all, worst kiosk p50 %.1f ms (#%d) p99 %.1f ms (#%d); "
           "kiosks cpu %.1f %% of a core, rss %ld KiB; broker cpu %.1f %%, rss %ld KiB; lost %lld, mismatched %lld, not presented %lld\n",
           label, label[0] ? ": " : "", nk, nall ? pct(all, nall, 50) / 1e6 : -1.0, nall ? pct(all, nall, 99) / 1e6 : -1.0,
           worst50 / 1e6, w50, worst99 / 1e6, w99, cpu_total, rss_total,
           broker ? (double)(bcpu1 - bcpu0) / hz / wall * 100 : 0.0, brss, lost_total, mism_total, unshown_total);
    /* one machine-readable row for the harness's table */
    printf("KBENCH\t%s\t%.0f\t%lld\t%d\t%.1f\t%.1f\t%.1f\t%.1f\t%.1f\t%ld\t%.1f\t%ld\t%lld\t%lld\t%lld\n", label, rate,
           published, nk, nall ? pct(all, nall, 50) / 1e6 : -1.0, nall ? pct(all, nall, 99) / 1e6 : -1.0, worst50 / 1e6,
           worst99 / 1e6, cpu_total, rss_total, broker ? (double)(bcpu1 - bcpu0) / hz / wall * 100 : 0.0, brss,
           lost_total, mism_total, unshown_total);
    free(all);
    for (int i = 0; i < nk; i++) free(ks[i].lat), close(ks[i].fd);
    free(tpub);
    return fail;
}
