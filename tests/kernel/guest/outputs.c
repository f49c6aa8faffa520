/* SPDX-License-Identifier: MIT */
/* Guest program: outputs by name across two DRM cards (issue #25). qemu
 * has a second display device (run.py: id gpu1 at PCI slot 8, 640x400); its
 * driver is loaded here from /modules.cards (x86_64: virtio-gpu next to
 * bochs; aarch64: bochs next to virtio-gpu), so card1 is the second card.
 * Both outputs are of type Virtual and the kernel numbers a type across all
 * cards, so card1's is Virtual-2 (read from sysfs). Checked: the connector
 * named alone or with its card opens on the second card and the picture appears on that device
 * (host screendump of gpu1, every pixel); the unqualified name takes the
 * first card; FIXEL_DRM_DEVICE by driver and by by-path name (the expected
 * names come from qemu's layout, not from fixel's code); an unknown name is
 * one clear error listing the cards; fixel-info lists the second card with
 * its driver, by-path name, connector status/modes/preferred mode (against
 * sysfs), its EDID monitor name (against sysfs's edid file) and says it
 * would open it. Orientation: run.py gives card1's connector a "panel
 * orientation" of right side up on the kernel command line; opened without
 * a rotation the picture is turned 90 (host screendump), FIXEL_ROTATION=0
 * overrides it, and a uinput touchscreen's corners land on the logical
 * corners of the turned picture. fixel-calibrate driven by uinput touches.
 * Headless boot: with card1's connector forced off a program waits in
 * fx_display_wait_connected (one log line) and draws once it is forced on. The driver is unloaded at the end. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <libevdev/libevdev-uinput.h>
#include <libevdev/libevdev.h>

#include "fixel/app.h"
#include "fixel/display.h"
#include "fixel/env.h"
#include "fixel/error.h"
#include "guest.h"
#include "guest_drm.h"
#include "scenes.h"
#include "uinput.h"

#if defined(__x86_64__)
#define CARD1_DRIVER "virtio_gpu"
#define CARD1_DRIVER_ALT "virtio-gpu" /* '-' for '_' */
#define CARD1_MODULE "virtio_gpu"
#define CARD1_PATH "pci-0000:00:08.0"
#define CARD0_DRIVER "bochs-drm"
#else
#define CARD1_DRIVER "bochs-drm"
#define CARD1_DRIVER_ALT "bochs_drm"
#define CARD1_MODULE "bochs"
/* virt's PCIe host bridge is the platform device of its ECAM window */
#define CARD1_PATH "platform-4010000000.pcie-pci-0000:00:08.0"
#define CARD0_DRIVER "virtio_gpu"
#endif



/* ---- opening by name, in a child each (DRM master, console) ------------- */

struct open_case {
    const char *name;
    const char *var;
    char value[160];          /* the environment variable under test */
    const char *want_device;  /* NULL: the open must fail */
    const char *want_conn;
    const char *scene;        /* drawn and checked on gpu1 when set */
};

static char conn0[32], conn1[32]; /* card0's and card1's connector */

static void open_child(void *arg)
{
    const struct open_case *c = arg;
    setenv(c->var, c->value, 1);
    fx_display_options o;
    fx_display_options_init(&o);
    o.backend = FX_BACKEND_DRM;
    o.log = capture_log;
    o.log_priority = FX_LOG_DEBUG;
    int r = fx_display_options_from_env(&o);
    fx_display *d = NULL;
    if (r == 0)
        r = fx_display_open(&d, &o);
    if (!c->want_device) {
        int named = strstr(logbuf, c->value) && strstr(logbuf, "card1 " CARD1_DRIVER);
        guest_check(c->name, r < 0 && named,
                    "open %s with %s=%s; the log names it and lists the cards: %s", r < 0 ? "failed" : "succeeded",
                    c->var, c->value, named ? "yes" : "no");
        fx_display_close(d);
        return;
    }
    if (r < 0) {
        guest_check(c->name, 0, "%s=%s: open failed: %s", c->var, c->value, fx_strerror(r));
        return;
    }
    fx_display_info in;
    fx_display_get_info(d, &in);
    guest_check(c->name, !strcmp(in.device, c->want_device) && !strcmp(in.connector, c->want_conn),
                "%s=%s opened %s %s, want %s %s", c->var, c->value, in.device, in.connector, c->want_device,
                c->want_conn);
    if (c->scene) {
        fx_surface s = fx_display_surface(d);
        scene_draw(c->scene, &s);
        fx_display_present(d, NULL, 0);
        fx_display_wait(d, 1000);
        char n2[96];
        snprintf(n2, sizeof n2, "%s-picture", c->name);
        guest_request("SCREEN %s %d %d %d %s gpu1", n2, in.width, in.height, in.rotation, c->scene);
    }
    fx_display_close(d);
}

static void in_child(void (*fn)(void *), void *arg)
{
    int st = guest_in_child(fn, arg);
    if (!WIFEXITED(st) || WEXITSTATUS(st))
        guest_failed = 1;
}

/* ---- fixel-info ------------------------------------------------------------ */

static char out[1 << 16];

#define line_with guest_line_with

/* The monitor name descriptor of an EDID read from sysfs. */
static void edid_monitor(const char *path, char *name, size_t n)
{
    unsigned char e[256];
    name[0] = 0;
    int fd = open(path, O_RDONLY);
    ssize_t len = fd >= 0 ? read(fd, e, sizeof e) : -1;
    if (fd >= 0)
        close(fd);
    for (int d = 54; len >= 128 && d <= 108; d += 18)
        if (e[d] == 0 && e[d + 1] == 0 && e[d + 2] == 0 && e[d + 3] == 0xFC) {
            int l = 0;
            while (l < 13 && e[d + 5 + l] != '\n')
                l++;
            snprintf(name, n, "%.*s", l, (const char *)e + d + 5);
        }
}

static void info_checks(void)
{
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
        int fd = open("/tmp/outputs-info.out", O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd < 0 || dup2(fd, 1) < 0)
            _exit(125);
        setenv("FIXEL_CONNECTOR", conn1, 1);
        execl("/bin/fixel-info", "fixel-info", (char *)NULL);
        _exit(127);
    }
    int st = 0;
    waitpid(pid, &st, 0);
    read_file("/tmp/outputs-info.out", out, sizeof out);
    char line[512], want[256];
    snprintf(want, sizeof want, "/dev/dri/card1: driver %s (", CARD1_DRIVER);
    const char *at = line_with(out, want, line, sizeof line);
    snprintf(want, sizeof want, ", by-path %s", CARD1_PATH);
    guest_check("outputs-info-card", at && strstr(line, want), "fixel-info \"%s\", want driver %s and%s",
                at ? line : "(no card1 line)", CARD1_DRIVER, want);
    const char *at0 = line_with(out, "/dev/dri/card0: driver " CARD0_DRIVER " (", line, sizeof line);
    guest_check("outputs-info-card0", at0 != NULL, "fixel-info \"%s\"", at0 ? line : "(no card0 line)");

    /* card1's connector against sysfs: status, mode count, preferred = first */
    char st1[32] = "", modes[4096] = "", first[64] = "", edid[32];
    char sp[96], pat[48];
    snprintf(sp, sizeof sp, "/sys/class/drm/card1-%s/status", conn1);
    read_file(sp, st1, sizeof st1);
    st1[strcspn(st1, "\n")] = 0;
    snprintf(sp, sizeof sp, "/sys/class/drm/card1-%s/modes", conn1);
    read_file(sp, modes, sizeof modes);
    int nmodes = 0;
    for (const char *q = modes; *q; q++)
        nmodes += *q == '\n';
    sscanf(modes, "%63s", first);
    snprintf(sp, sizeof sp, "/sys/class/drm/card1-%s/edid", conn1);
    edid_monitor(sp, edid, sizeof edid);
    snprintf(pat, sizeof pat, " %s: ", conn1);
    const char *c1 = at ? strstr(at, pat) : NULL;
    char cl[512] = "";
    if (c1)
        line_with(c1, pat, cl, sizeof cl);
    char gst[32] = "", gpref[64] = "";
    int gmodes = -1;
    const char *colon = strstr(cl, pat);
    if (colon)
        sscanf(colon + strlen(pat), "%31[^,], %d modes, preferred %63[^,@]", gst, &gmodes, gpref);
    guest_check("outputs-info-connector", c1 && !strcmp(gst, st1) && gmodes == nmodes && !strcmp(gpref, first),
                "fixel-info \"%s\"; sysfs %s, %d modes, first %s", cl, st1, nmodes, first);
    snprintf(want, sizeof want, "monitor \"%s\"", edid);
    guest_check("outputs-info-monitor", edid[0] && strstr(cl, want) != NULL, "want %s (sysfs edid) in \"%s\"",
                want, cl);
    guest_check("outputs-info-properties", strstr(cl, ", DPMS On") && strstr(cl, ", panel orientation "),
                "DPMS and panel orientation in \"%s\"", cl);
    snprintf(want, sizeof want, "  backend drm, device \"/dev/dri/card1\", connector %s,", conn1);
    const char *ch = line_with(out, want, line, sizeof line);
    char cline[512] = "";
    const char *cc = line_with(out, "  card /dev/dri/card1: driver " CARD1_DRIVER ", by-path " CARD1_PATH ";",
                               cline, sizeof cline);
    guest_check("outputs-info-choice", WIFEXITED(st) && WEXITSTATUS(st) == 0 && ch && cc,
                "exit %d; choice \"%s\"; card \"%s\"", WIFEXITED(st) ? WEXITSTATUS(st) : -1, ch ? line : "(none)",
                cc ? cline : "(none)");
}

/* ---- the panel's orientation ----------------------------------------------- */

static void panel_child(void *arg)
{
    const char *rot = arg; /* FIXEL_ROTATION or NULL */
    setenv("FIXEL_CONNECTOR", conn1, 1);
    if (rot)
        setenv("FIXEL_ROTATION", rot, 1);
    fx_display_options o;
    fx_display_options_init(&o);
    o.backend = FX_BACKEND_DRM;
    o.console = 0;
    o.log = capture_log;
    o.log_priority = FX_LOG_DEBUG;
    fx_display_options_from_env(&o);
    logbuf[0] = 0;
    const char *name = rot ? "outputs-panel-rotation-overridden" : "outputs-panel-orientation";
    fx_display *d;
    if (guest_open(name, &d, &o) < 0)
        return;
    fx_display_info in;
    fx_display_get_info(d, &in);
    int want = rot ? 0 : 90;
    int said = rot ? strstr(logbuf, "rotation 0 was asked for") != NULL
                   : strstr(logbuf, "panel orientation \"Right Side Up\": rotation 90") != NULL;
    fx_surface s = fx_display_surface(d); /* logical: turned for 90 */
    guest_check(name, in.rotation == want && s.w == (want ? 400 : 640) && s.h == (want ? 640 : 400) && said,
                "%s %s: rotation %d (want %d), logical %dx%d, log says why: %s", in.device, in.connector, in.rotation,
                want, s.w, s.h, said ? "yes" : "no");
    scene_draw(rot ? "checker" : "bars", &s);
    fx_display_present(d, NULL, 0);
    fx_display_wait(d, 1000);
    /* the host turns its render by the rotation given here, not the guest's */
    guest_request("SCREEN %s-picture 640 400 %d %s gpu1", name, want, rot ? "checker" : "bars");
    fx_display_close(d);
}

struct rec {
    char ev[16][48];
    int n;
    fx_app *app;
    struct libevdev_uinput *ts;
};
static void rec_add(struct rec *r, const char *kind, int x, int y)
{
    if (r->n < 16)
        snprintf(r->ev[r->n++], 48, "%s %d %d", kind, x, y);
    printf("  event: %s %d %d\n", kind, x, y);
}
static void on_touch(void *u, int id, int x, int y, int ph)
{
    (void)id;
    rec_add(u, ph == 0 ? "down" : ph == 1 ? "move" : "up", x, y);
}
static void tw(struct libevdev_uinput *u, unsigned t, unsigned c, int v) { libevdev_uinput_write_event(u, t, c, v); }
static void touch_step(void *u, int k)
{
    struct rec *r = u;
    /* raw 0..4095 spans the physical 640x400 panel */
    if (k == 0)
        uinput_tap(r->ts, 4095, 0);    /* the panel's top-right corner: the viewer's top-left */
    else if (k == 1)
        uinput_tap(r->ts, 0, 4095);    /* bottom-left: the viewer's bottom-right */
    else if (k == 2)
        uinput_tap(r->ts, 4095, 4095); /* bottom-right: the viewer's top-right */
    else
        fx_app_quit(r->app);
}

static void panel_touch_child(void *arg)
{
    (void)arg;
    struct libevdev *dev = libevdev_new();
    libevdev_set_name(dev, "fixel outputs touchscreen");
    uinput_enable_multitouch(dev, 1);
    static struct rec r;
    r.ts = uinput_create(dev);
    if (!r.ts) {
        guest_check("outputs-panel-touch", 0, "no uinput touchscreen");
        return;
    }
    setenv("FIXEL_CONNECTOR", conn1, 1);
    fx_app_options o;
    fx_app_options_init(&o);
    fx_app_options_from_env(&o);
    o.display.backend = FX_BACKEND_DRM;
    o.display.console = 0;
    o.display.log = capture_log;
    o.display.log_priority = FX_LOG_DEBUG;
    o.pointercal = NULL; /* the guest has no /etc/pointercal: range scaling */
    if (fx_app_open(&r.app, &o) < 0) {
        guest_check("outputs-panel-touch", 0, "fx_app_open failed");
        return;
    }
    fx_callbacks cb = {.touch = on_touch};
    fx_app_set_callbacks(r.app, &cb, &r);
    for (int k = 0; k < 4; k++)
        fx_app_timer(r.app, (unsigned)(100 + 150 * k), touch_step, k);
    fx_app_main_loop(r.app);
    int32_t w, h;
    fx_app_size(r.app, &w, &h);
    static const char *const want[] = {"down 0 0", "up 0 0", "down 399 639", "up 399 639", "down 399 0", "up 399 0"};
    int ok = r.n == 6 && w == 400 && h == 640;
    for (int i = 0; ok && i < 6; i++)
        ok = !strcmp(r.ev[i], want[i]);
    char got[400] = "";
    for (int i = 0; i < r.n; i++)
        snprintf(got + strlen(got), sizeof got - strlen(got), "%s%s", i ? "; " : "", r.ev[i]);
    guest_check("outputs-panel-touch", ok, "logical %dx%d; touches [%s], want [down 0 0; up 0 0; down 399 639; "
                "up 399 639; down 399 0; up 399 0]", w, h, got);
    fx_app_close(r.app);
    libevdev_uinput_destroy(r.ts);
}

/* ---- fixel-calibrate on the turned panel ------------------------------------ */

/* The touchscreen's wiring, known here: raw = 6*px + 100, 4000 - 9*py for
 * the physical pixel (px, py) of the 640x400 panel. */
static int raw_x(int px) { return 6 * px + 100; }
static int raw_y(int py) { return 4000 - 9 * py; }

static void calibrate_checks(void)
{
    struct libevdev *dev = libevdev_new();
    libevdev_set_name(dev, "fixel calibrate touchscreen");
    uinput_enable_multitouch(dev, 1);
    struct libevdev_uinput *ts = uinput_create(dev);
    if (!ts) {
        guest_check("outputs-calibrate", 0, "no uinput touchscreen");
        return;
    }
    /* the targets fixel-calibrate places, worked out here: logical 400x640
     * (rotation 90 from the panel), margin 30, then turned to physical */
    const int lw = 400, lh = 640, m = 30;
    const int lx[6] = {m, lw - 1 - m, lw - 1 - m, m, lw / 2, lw / 4};
    const int ly[6] = {m, m, lh - 1 - m, lh - 1 - m, lh / 2, (3 * lh) / 4};
    int fds[2];
    if (pipe(fds) < 0)
        return;
    unlink("/tmp/pointercal");
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
        dup2(fds[1], 1);
        close(fds[0]);
        setenv("FIXEL_CONNECTOR", conn1, 1);
        execl("/bin/fixel-calibrate", "fixel-calibrate", "-i", libevdev_uinput_get_devnode(ts), "-o",
              "/tmp/pointercal", "--timeout", "20", (char *)NULL);
        _exit(127);
    }
    close(fds[1]);
    FILE *f = fdopen(fds[0], "r");
    char line[256], said[2048] = "";
    int k = 0;
    while (f && fgets(line, sizeof line, f)) {
        printf("  calibrate: %s", line);
        if (strlen(said) + strlen(line) < sizeof said)
            strcat(said, line);
        if (!strncmp(line, "touch the cross", 15) && k < 6) {
            int px = 640 - 1 - ly[k], py = lx[k]; /* rotation 90: (W-1-y, x) */
            if (k == 0)
                guest_request("SCREEN outputs-calibrate-target 640 400 90 !black gpu1");
            for (int rep = 0; rep < 3; rep++) { /* a touch of three reports */
                tw(ts, EV_ABS, ABS_MT_SLOT, 0);
                tw(ts, EV_ABS, ABS_MT_TRACKING_ID, 21);
                tw(ts, EV_ABS, ABS_MT_POSITION_X, raw_x(px));
                tw(ts, EV_ABS, ABS_MT_POSITION_Y, raw_y(py));
                tw(ts, EV_ABS, ABS_X, raw_x(px));
                tw(ts, EV_ABS, ABS_Y, raw_y(py));
                if (rep == 0)
                    tw(ts, EV_KEY, BTN_TOUCH, 1);
                tw(ts, EV_SYN, SYN_REPORT, 0);
            }
            tw(ts, EV_ABS, ABS_MT_TRACKING_ID, -1);
            tw(ts, EV_KEY, BTN_TOUCH, 0);
            tw(ts, EV_SYN, SYN_REPORT, 0);
            k++;
        }
    }
    if (f)
        fclose(f);
    int st = 0;
    waitpid(pid, &st, 0);
    libevdev_uinput_destroy(ts);
    /* the inverse of the wiring, as tslib stores it */
    long want[9] = {lround(65536.0 / 6), 0, lround(-100 * 65536.0 / 6), 0, lround(-65536.0 / 9),
                    lround(4000 * 65536.0 / 9), 65536, 640, 400};
    long got[9] = {0};
    char file[256] = "";
    read_file("/tmp/pointercal", file, sizeof file);
    int n = sscanf(file, "%ld %ld %ld %ld %ld %ld %ld %ld %ld", &got[0], &got[1], &got[2], &got[3], &got[4], &got[5],
                   &got[6], &got[7], &got[8]);
    int same = n == 9;
    for (int i = 0; same && i < 9; i++)
        same = got[i] == want[i];
    guest_check("outputs-calibrate", WIFEXITED(st) && WEXITSTATUS(st) == 0 && k == 6 && same,
                "exit %d, %d touches asked, file \"%.*s\", want %ld %ld %ld %ld %ld %ld %ld %ld %ld",
                WIFEXITED(st) ? WEXITSTATUS(st) : -1, k, (int)strcspn(file, "\n"), file, want[0], want[1], want[2],
                want[3], want[4], want[5], want[6], want[7], want[8]);
    guest_check("outputs-calibrate-said", strstr(said, "rotation 90") && strstr(said, "FIXEL_POINTERCAL=/tmp/pointercal"),
                "the tool names the rotation and the config line");
}

/* ---- headless boot: waiting for the display ---------------------------------- */

static void wait_child(void)
{
    fx_display_options o;
    fx_display_options_init(&o);
    o.backend = FX_BACKEND_DRM;
    o.connector = conn1;
    o.console = 0;
    o.log = capture_log;
    o.log_priority = FX_LOG_DEBUG;
    logbuf[0] = 0;
    int r = fx_display_wait_connected(&o, 20000);
    int lines = 0;
    for (const char *q = logbuf; (q = strstr(q, "waiting for one")); q++)
        lines++;
    guest_check("outputs-wait-connected", r == 0 && lines == 1 && strstr(logbuf, "display connected: /dev/dri/card1"),
                "returned %d once the connector came back; %d waiting line(s); log: %.200s", r, lines, logbuf);
    fx_display *d;
    if (r != 0 || guest_open("outputs-wait-open", &d, &o) < 0)
        return;
    fx_display_info in;
    fx_display_get_info(d, &in);
    fx_surface s = fx_display_surface(d);
    scene_draw("bars", &s);
    fx_display_present(d, NULL, 0);
    fx_display_wait(d, 1000);
    guest_request("SCREEN outputs-wait-picture %d %d %d bars gpu1", in.width, in.height, in.rotation);
    fx_display_close(d);
}

/* The connector forced off through sysfs (with the card's change uevent a
 * hotplug interrupt would send), a program waits; forced on, it draws. */
static void wait_checks(void)
{
    char status[96];
    snprintf(status, sizeof status, "/sys/class/drm/card1-%s/status", conn1);
    int w = write_file(status, "off");
    if (w == 0)
        w = write_file("/sys/class/drm/card1/uevent", "change");
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
        wait_child();
        fflush(stdout);
        _exit(guest_failed);
    }
    msleep(1500);
    int st = 0;
    pid_t done = waitpid(pid, &st, WNOHANG);
    guest_check("outputs-wait-blocks", w == 0 && done == 0, "connector forced off (%d); after 1.5 s the program %s",
                w, done == 0 ? "still waits" : "returned");
    w = write_file(status, "on");
    if (w == 0)
        w = write_file("/sys/class/drm/card1/uevent", "change");
    if (done == 0)
        waitpid(pid, &st, 0);
    if (!WIFEXITED(st) || WEXITSTATUS(st))
        guest_failed = 1;
    write_file(status, "detect");
    write_file("/sys/class/drm/card1/uevent", "change");
}

int main(void)
{
    setvbuf(stdout, NULL, _IOLBF, 0);
    char detail[300], drv[32];
    int lr = 0;
    int ok = guest_second_card(conn0, conn1, detail, sizeof detail, &lr);
    guest_drm_driver("/dev/dri/card1", drv, sizeof drv);
    /* one pool of numbers per connector type, across cards */
    guest_check("outputs-second-card", lr == 0 && ok && !strcmp(drv, CARD1_DRIVER) && !strcmp(conn1, "Virtual-2"),
                "loaded %s; card1 %s, driver %s, connectors: card0 %s, card1 %s", detail, ok ? "present" : "missing",
                drv, conn0, conn1);
    if (!ok) {
        system("ls /sys/class/drm /dev/dri");
        return 1;
    }
    msleep(300); /* the new card's fbdev emulation and fbcon settle */

    static struct open_case cases[] = {
        {"outputs-connector-alone", "FIXEL_CONNECTOR", "", "/dev/dri/card1", conn1, "bars"},
        {"outputs-connector-with-driver", "FIXEL_CONNECTOR", "", "/dev/dri/card1", conn1, NULL},
        {"outputs-connector-with-by-path", "FIXEL_CONNECTOR", "", "/dev/dri/card1", conn1, "checker"},
        {"outputs-connector-first-card", "FIXEL_CONNECTOR", "", "/dev/dri/card0", conn0, NULL},
        {"outputs-connector-wrong-card", "FIXEL_CONNECTOR", "", NULL, NULL, NULL},
        {"outputs-device-by-driver", "FIXEL_DRM_DEVICE", CARD1_DRIVER_ALT, "/dev/dri/card1", conn1, NULL},
        {"outputs-device-by-path", "FIXEL_DRM_DEVICE", CARD1_PATH, "/dev/dri/card1", conn1, NULL},
        {"outputs-device-by-path-link", "FIXEL_DRM_DEVICE", CARD1_PATH "-card", "/dev/dri/card1", conn1, NULL},
        {"outputs-device-by-number", "FIXEL_DRM_DEVICE", "card1", "/dev/dri/card1", conn1, NULL},
        {"outputs-device-unknown", "FIXEL_DRM_DEVICE", "no-such-gpu", NULL, NULL, NULL},
        {"outputs-connector-unknown", "FIXEL_CONNECTOR", "HDMI-A-9", NULL, NULL, NULL},
    };
    snprintf(cases[0].value, sizeof cases[0].value, "%s", conn1);
    snprintf(cases[1].value, sizeof cases[1].value, "%s:%s", CARD1_DRIVER, conn1);
    snprintf(cases[2].value, sizeof cases[2].value, "%s:%s", CARD1_PATH, conn1);
    snprintf(cases[3].value, sizeof cases[3].value, "%s", conn0);
    snprintf(cases[4].value, sizeof cases[4].value, "card0:%s", conn1); /* it is on card1 */
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        logbuf[0] = 0;
        in_child(open_child, (void *)&cases[i]);
    }
    info_checks();
    in_child(panel_child, NULL);
    in_child(panel_child, "0");
    in_child(panel_touch_child, NULL);
    calibrate_checks();
    wait_checks();

    guest_remove_second_card("outputs-second-card-removed", CARD1_MODULE);
    return guest_failed;
}
