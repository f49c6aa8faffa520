/* SPDX-License-Identifier: MIT */
/* fixel-calibrate — touchscreen calibration for fixel (and tslib): draws
 * five targets (corners and centre) on the display fixel opens, reads the
 * raw position of a touch on each, fits the affine map raw -> physical
 * pixels, checks it on a sixth target and writes tslib's pointercal. The
 * file maps to physical pixels, so it stays right whatever rotation a
 * program later uses; the targets are placed in the rotation in force now
 * (FIXEL_ROTATION, the panel's orientation), so the person calibrating sees
 * them upright. --points replaces the touchscreen by six given raw points
 * (tests, scripted set-ups; with FIXEL_BACKEND=memory nothing needs a device). */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include <linux/input.h>
#include <sys/ioctl.h>

#include "fit.h"
#include "fixel/display.h"
#include "fixel/draw.h"
#include "fixel/env.h"
#include "fixel/error.h"
#include "fixel/files.h"

#define NT 6 /* five to fit, the sixth to check */

static void usage(FILE *f)
{
    fprintf(f, "usage: fixel-calibrate [-o FILE] [-i /dev/input/eventN] [--margin PX] [--timeout S]\n"
               "                       [--tolerance PX] [--points X,Y,...]\n"
               "Draws five targets (corners, centre) on the display fixel opens (FIXEL_BACKEND,\n"
               "FIXEL_CONNECTOR, FIXEL_ROTATION... as for every fixel program), reads a touch on each,\n"
               "fits the map from raw touch units to screen pixels, checks it on a sixth target and\n"
               "writes tslib's pointercal (default /etc/pointercal) and a fixel config line.\n"
               "  -o FILE          where to write (\"-\": standard output only)\n"
               "  -i DEVICE        the touchscreen (default: the first direct-touch device)\n"
               "  --margin PX      distance of the corner targets from the edges, 4..1000 (default 30)\n"
               "  --timeout S      seconds to wait for each touch, 1..3600 (default 60)\n"
               "  --tolerance PX   largest error allowed at the check target, 1..1000 (default 12)\n"
               "  --points LIST    twelve integers: raw x,y of the six touches in target order,\n"
               "                   instead of reading a touchscreen\n"
               "Exit status: 0 written, 1 calibration failed (nothing written), 2 bad arguments.\n");
}

static int num(const char *opt, const char *s, long lo, long hi, long *out)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (end == s || *end || errno || v < lo || v > hi) {
        fprintf(stderr, "fixel-calibrate: %s wants a number from %ld to %ld, not '%s'\n", opt, lo, hi, s);
        return -1;
    }
    *out = v;
    return 0;
}

/* ---- the touchscreen ------------------------------------------------------- */

static int test_bit(const unsigned long *b, int n)
{
    return (int)((b[n / (8 * sizeof *b)] >> (n % (8 * sizeof *b))) & 1);
}

static int is_touchscreen(int fd)
{
    unsigned long abs[ABS_CNT / (8 * sizeof(long)) + 1] = {0}, prop[INPUT_PROP_CNT / (8 * sizeof(long)) + 1] = {0};
    if (ioctl(fd, EVIOCGBIT(EV_ABS, sizeof abs), abs) < 0)
        return 0;
    ioctl(fd, EVIOCGPROP(sizeof prop), prop);
    return test_bit(abs, ABS_X) && test_bit(abs, ABS_Y) && test_bit(prop, INPUT_PROP_DIRECT);
}

static int open_touch(const char *want, char *path, size_t n)
{
    if (want) {
        snprintf(path, n, "%s", want);
        int fd = open(want, O_RDONLY | O_CLOEXEC | O_NONBLOCK);
        if (fd < 0)
            fprintf(stderr, "fixel-calibrate: %s: %s%s\n", want, strerror(errno),
                    errno == EACCES ? " (add the user to group input)" : "");
        return fd;
    }
    for (int i = 0; i < 64; i++) {
        snprintf(path, n, "/dev/input/event%d", i);
        int fd = open(path, O_RDONLY | O_CLOEXEC | O_NONBLOCK);
        if (fd < 0)
            continue;
        if (is_touchscreen(fd))
            return fd;
        close(fd);
    }
    fprintf(stderr, "fixel-calibrate: no touchscreen (direct-touch device with ABS_X/ABS_Y) in /dev/input; "
                    "name one with -i\n");
    return -1;
}

/* One touch: the mean raw position over its reports, taken at release. */
static int read_touch(int fd, int timeout_s, double *rx, double *ry)
{
    /* The kernel sends only changed values: a touch where the last one
     * ended reports no ABS_X at all, so start from the device's state. */
    struct input_absinfo ax = {0}, ay = {0};
    ioctl(fd, EVIOCGABS(ABS_X), &ax);
    ioctl(fd, EVIOCGABS(ABS_Y), &ay);
    int x = ax.value, y = ay.value, down = 0;
    double sx = 0, sy = 0;
    long cnt = 0;
    struct timespec t0, t;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    for (;;) {
        clock_gettime(CLOCK_MONOTONIC, &t);
        long left = (long)timeout_s * 1000 - ((t.tv_sec - t0.tv_sec) * 1000 + (t.tv_nsec - t0.tv_nsec) / 1000000);
        if (left <= 0)
            return -ETIMEDOUT;
        struct pollfd p = {.fd = fd, .events = POLLIN};
        int r = poll(&p, 1, (int)left);
        if (r < 0 && errno == EINTR)
            continue;
        if (r <= 0)
            continue;
        struct input_event ev[64];
        ssize_t got = read(fd, ev, sizeof ev);
        if (got < 0 && (errno == EAGAIN || errno == EINTR))
            continue;
        if (got <= 0)
            return -EIO;
        for (size_t i = 0; i < (size_t)got / sizeof ev[0]; i++) {
            const struct input_event *e = &ev[i];
            if (e->type == EV_ABS && e->code == ABS_X)
                x = e->value;
            else if (e->type == EV_ABS && e->code == ABS_Y)
                y = e->value;
            else if (e->type == EV_KEY && e->code == BTN_TOUCH)
                down = e->value ? 1 : down == 1 ? 2 : 0; /* 2: released, decide at SYN */
            else if (e->type == EV_SYN && e->code == SYN_REPORT) {
                if (down == 1) {
                    sx += x, sy += y, cnt++;
                } else if (down == 2) {
                    down = 0;
                    if (cnt) {
                        *rx = sx / (double)cnt;
                        *ry = sy / (double)cnt;
                        return 0;
                    }
                }
            }
        }
    }
}

/* ---- the targets ------------------------------------------------------------- */

static void draw_target(fx_display *d, int32_t x, int32_t y, int done, int total)
{
    fx_surface s = fx_display_surface(d);
    fx_ctx c;
    fx_ctx_init(&c, &s);
    fx_ctx_set_color(&c, 0xFF000000);
    fx_fill_rect(&c, 0, 0, s.w, s.h);
    fx_ctx_set_color(&c, 0xFFFFFFFF);
    fx_fill_rect(&c, x - 12, y, 25, 1); /* a cross: touch its centre */
    fx_fill_rect(&c, x, y - 12, 1, 25);
    fx_ctx_set_color(&c, 0xFFFF4040);
    fx_fill_rect(&c, x - 1, y - 1, 3, 3);
    /* progress along the bottom: one block per target done */
    fx_ctx_set_color(&c, 0xFF40C040);
    for (int i = 0; i < done; i++)
        fx_fill_rect(&c, 4 + i * 14, s.h - 10, 10, 6);
    (void)total;
    fx_display_present(d, NULL, 0);
    fx_display_wait(d, 500);
}

int main(int argc, char **argv)
{
    const char *out = "/etc/pointercal", *input = NULL, *points = NULL;
    long margin = 30, timeout = 60, tolerance = 12;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            usage(stdout);
            return 0;
        } else if (!strcmp(a, "-o") && i + 1 < argc) out = argv[++i];
        else if (!strcmp(a, "-i") && i + 1 < argc) input = argv[++i];
        else if (!strcmp(a, "--points") && i + 1 < argc) points = argv[++i];
        else if (!strcmp(a, "--margin") && i + 1 < argc) {
            if (num(a, argv[++i], 4, 1000, &margin) < 0) return 2;
        } else if (!strcmp(a, "--timeout") && i + 1 < argc) {
            if (num(a, argv[++i], 1, 3600, &timeout) < 0) return 2;
        } else if (!strcmp(a, "--tolerance") && i + 1 < argc) {
            if (num(a, argv[++i], 1, 1000, &tolerance) < 0) return 2;
        } else {
            fprintf(stderr, "fixel-calibrate: unknown argument %s (try --help)\n", a);
            return 2;
        }
    }
    /* checked before the touches: a FIFO with no reader would hang the
     * write at the end, a device node be written to (issue #40) */
    char why[160];
    if (strcmp(out, "-") && fx_check_replaceable(out, why, sizeof why) < 0) {
        fprintf(stderr, "fixel-calibrate: -o %s: %s\n", out, why);
        return 2;
    }
    double given[2 * NT];
    if (points) {
        const char *s = points;
        int k = 0;
        while (k < 2 * NT) {
            char *end;
            errno = 0;
            long v = strtol(s, &end, 10);
            if (end == s || errno || v < -1000000 || v > 1000000)
                break;
            given[k++] = (double)v;
            s = end;
            if (*s == ',' || *s == ' ')
                s++;
            else
                break;
        }
        if (k != 2 * NT || *s) {
            fprintf(stderr, "fixel-calibrate: --points wants twelve integers (raw x,y of six touches, "
                            "each -1000000..1000000), separated by commas; error at character %d of '%s'\n",
                    (int)(s - points) + 1, points);
            return 2;
        }
    }

    fx_display_options o;
    fx_display_options_init(&o);
    if (fx_display_options_from_env(&o) < 0)
        return 2;
    fx_display *d;
    if (fx_display_open(&d, &o) < 0)
        return 1;
    fx_display_info in;
    fx_display_get_info(d, &in);
    fx_surface s = fx_display_surface(d);
    int32_t W = s.w, H = s.h; /* logical */
    if (2 * margin + 2 >= W || 2 * margin + 2 >= H) {
        fprintf(stderr, "fixel-calibrate: --margin %ld leaves no room on a %dx%d screen\n", margin, W, H);
        fx_display_close(d);
        return 2;
    }
    int32_t m = (int32_t)margin;
    const int32_t tx[NT] = {m, W - 1 - m, W - 1 - m, m, W / 2, W / 4};
    const int32_t ty[NT] = {m, m, H - 1 - m, H - 1 - m, H / 2, (3 * H) / 4};
    static const char *const where[NT] = {"top left", "top right", "bottom right", "bottom left", "centre",
                                          "check point"};

    int fd = -1;
    char tpath[64] = "";
    if (!points && (fd = open_touch(input, tpath, sizeof tpath)) < 0) {
        fx_display_close(d);
        return 1;
    }
    printf("fixel-calibrate: %s%s%s, %dx%d, rotation %d; touchscreen %s\n", fx_backend_name(in.backend),
           in.device[0] ? " " : "", in.device, W, H, in.rotation, points ? "(--points)" : tpath);
    cal_point p[NT];
    for (int i = 0; i < NT; i++) {
        draw_target(d, tx[i], ty[i], i, NT);
        int32_t px, py;
        cal_logical_to_physical(in.rotation, in.width, in.height, tx[i], ty[i], &px, &py);
        p[i].sx = px;
        p[i].sy = py;
        if (points) {
            p[i].rx = given[2 * i];
            p[i].ry = given[2 * i + 1];
        } else {
            printf("touch the cross at the %s\n", where[i]);
            fflush(stdout);
            int r = read_touch(fd, (int)timeout, &p[i].rx, &p[i].ry);
            if (r < 0) {
                fprintf(stderr, "fixel-calibrate: no touch at the %s within %ld s%s; nothing written\n", where[i],
                        timeout, r == -EIO ? " (the device went away)" : "");
                close(fd);
                fx_display_close(d);
                return 1;
            }
        }
        printf("  %-12s logical %d,%d physical %d,%d raw %.1f,%.1f\n", where[i], tx[i], ty[i], px, py, p[i].rx,
               p[i].ry);
    }
    if (fd >= 0)
        close(fd);
    fx_display_close(d);

    double a[6];
    int32_t c[7];
    if (cal_fit(p, NT - 1, a) < 0 || cal_pointercal(a, c) < 0) {
        fprintf(stderr, "fixel-calibrate: the touches do not span the screen (on one line, or the same "
                        "point twice); nothing written\n");
        return 1;
    }
    /* the check point, through the integers fixel will use */
    int32_t gx, gy;
    cal_apply(c, (int32_t)lround(p[5].rx), (int32_t)lround(p[5].ry), &gx, &gy);
    double err = hypot(gx - p[5].sx, gy - p[5].sy);
    printf("check point: wanted %.0f,%.0f, the calibration gives %d,%d (%.1f px off, tolerance %ld)\n", p[5].sx,
           p[5].sy, gx, gy, err, tolerance);
    if (err > (double)tolerance) {
        fprintf(stderr, "fixel-calibrate: the check point is %.1f px off (more than %ld); touch more "
                        "precisely and run again; nothing written\n", err, tolerance);
        return 1;
    }
    char line[160];
    snprintf(line, sizeof line, "%d %d %d %d %d %d %d %d %d\n", c[0], c[1], c[2], c[3], c[4], c[5], c[6],
             in.width, in.height);
    if (strcmp(out, "-")) {
        why[0] = 0;
        FILE *f = fx_fopen_regular_write(out, 0, why, sizeof why);
        if (!f || fputs(line, f) < 0 || fclose(f) != 0) {
            fprintf(stderr, "fixel-calibrate: cannot write %s: %s\n", out, why[0] ? why : strerror(errno));
            return 1;
        }
        printf("wrote %s (tslib pointercal: raw to physical pixels of %dx%d)\n", out, in.width, in.height);
    }
    printf("pointercal: %s", line);
    printf("fixel: FIXEL_POINTERCAL=%s\n", strcmp(out, "-") ? out : "<file holding the pointercal line>");
    return 0;
}
