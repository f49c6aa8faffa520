/* SPDX-License-Identifier: MIT */
/* Guest program: the fixel-info and fixel-shot binaries (in /bin, built by
 * tools.mk) on real drivers.
 *
 * fixel-info's report is checked against what the kernel says elsewhere:
 * sysfs (/sys/class/drm, /sys/class/graphics, /sys/class/input), libdrm
 * queried here for the planes, the gpio-sim chip configured here through
 * configfs, and the uinput devices created here as a keyboard, a relative
 * mouse, a multitouch screen and a pen tablet.
 *
 * fixel-shot saves what fixel's own display shows (fbdev, then DRM); the
 * file is decoded here and sent to the host (IMAGE marker), which compares
 * it with its render of the scene, as it compares the screen itself. The
 * error paths run as uid 1000. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <gpiod.h>
#include <grp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include <drm_fourcc.h>
#include <xf86drm.h>
#include <xf86drmMode.h>
#include <zlib.h>

#include "fixel/display.h"
#include "fixel/error.h"
#include "fixel/memfb.h"
#include "guest.h"
#include "image.h"
#include "scenes.h"
#include "uinput.h"

static char out[1 << 16], err[1 << 13];

/* Elapsed time in the log, to keep this program's share of the rig small. */
static void stamp(const char *what)
{
    static struct timespec t0;
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    if (!t0.tv_sec)
        t0 = t;
    printf("  t=%ldms %s\n", (long)((t.tv_sec - t0.tv_sec) * 1000 + (t.tv_nsec - t0.tv_nsec) / 1000000), what);
}

enum { ROOT, USER_NO_GROUPS, USER_VIDEO_INPUT };

/* Runs a tool with stdout and stderr captured into out and err, as root or
 * as uid 1000 (without groups, or in video and input as a kiosk user would
 * be). env: one NAME=value or NULL. Returns the exit status, -1 for a
 * signal. */
static int run(int who, const char *env, const char *const *argv)
{
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
        int o = open("/tmp/tool.out", O_WRONLY | O_CREAT | O_TRUNC, 0644);
        int e = open("/tmp/tool.err", O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (o < 0 || e < 0 || dup2(o, 1) < 0 || dup2(e, 2) < 0)
            _exit(125);
        if (env)
            putenv((char *)env);
        static const gid_t groups[] = {44, 101};
        if (who != ROOT && (setgid(1000) || setgroups(who == USER_VIDEO_INPUT ? 2 : 0, groups) || setuid(1000)))
            _exit(126);
        execv(argv[0], (char *const *)argv);
        _exit(127);
    }
    int st = 0;
    waitpid(pid, &st, 0);
    read_file("/tmp/tool.out", out, sizeof out);
    read_file("/tmp/tool.err", err, sizeof err);
    for (char *q = err; *q; q++) /* one CHECK line */
        if (*q == '\n')
            *q = q[1] ? '|' : 0;
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

#define line_with guest_line_with

/* Names in dir matching prefix followed by a digit, in readdir order. */
static int list(const char *dir, const char *prefix, char names[][64], int max)
{
    DIR *d = opendir(dir);
    int n = 0;
    struct dirent *e;
    size_t pl = strlen(prefix);
    while (d && (e = readdir(d)) && n < max)
        if (!strncmp(e->d_name, prefix, pl) && e->d_name[pl] >= '0' && e->d_name[pl] <= '9' &&
            strlen(e->d_name) < 64)
            snprintf(names[n++], 64, "%s", e->d_name);
    if (d)
        closedir(d);
    return n;
}

/* ---- devices this program creates ---------------------------------------- */

static struct libevdev_uinput *make_input(const char *name, int kind)
{
    struct libevdev *d = libevdev_new();
    libevdev_set_name(d, name);
    struct input_absinfo ai = {.minimum = 0, .maximum = 4095};
    if (kind == 0) { /* keyboard */
        for (unsigned k = KEY_ESC; k <= KEY_KPDOT; k++)
            libevdev_enable_event_code(d, EV_KEY, k, NULL);
    } else if (kind == 1) { /* relative mouse */
        libevdev_enable_event_code(d, EV_REL, REL_X, NULL);
        libevdev_enable_event_code(d, EV_REL, REL_Y, NULL);
        libevdev_enable_event_code(d, EV_REL, REL_WHEEL, NULL);
        libevdev_enable_event_code(d, EV_KEY, BTN_LEFT, NULL);
        libevdev_enable_event_code(d, EV_KEY, BTN_RIGHT, NULL);
    } else if (kind == 2) { /* multitouch screen */
        uinput_enable_multitouch(d, 9);
    } else { /* pen tablet (not on the screen: no INPUT_PROP_DIRECT) */
        libevdev_enable_property(d, INPUT_PROP_POINTER);
        libevdev_enable_event_code(d, EV_KEY, BTN_TOOL_PEN, NULL);
        libevdev_enable_event_code(d, EV_KEY, BTN_TOUCH, NULL);
        libevdev_enable_event_code(d, EV_KEY, BTN_STYLUS, NULL);
        libevdev_enable_event_code(d, EV_ABS, ABS_X, &ai);
        libevdev_enable_event_code(d, EV_ABS, ABS_Y, &ai);
        libevdev_enable_event_code(d, EV_ABS, ABS_PRESSURE, &ai);
    }
    struct libevdev_uinput *u = uinput_create(d);
    if (!u)
        return NULL;
    /* init.sh gives input nodes to group input the way udev would */
    chown(libevdev_uinput_get_devnode(u), 0, 101);
    chmod(libevdev_uinput_get_devnode(u), 0660);
    return u;
}

#define SIM "/sys/kernel/config/gpio-sim/fxtools"
#define SIM_LINES 6
static const char *const sim_names[SIM_LINES] = {"TOOLS_BUTTON", NULL, NULL, "TOOLS_LED", NULL, "TOOLS_LAST"};
static char sim_chip[64];

static int sim_create(void)
{
    char p[256];
    mkdir(SIM, 0755);
    mkdir(SIM "/bank0", 0755);
    write_file(SIM "/bank0/label", "fixel-tools");
    char nl[8];
    snprintf(nl, sizeof nl, "%d", SIM_LINES);
    write_file(SIM "/bank0/num_lines", nl);
    for (int i = 0; i < SIM_LINES; i++) {
        if (!sim_names[i])
            continue;
        snprintf(p, sizeof p, SIM "/bank0/line%d", i);
        mkdir(p, 0755);
        snprintf(p, sizeof p, SIM "/bank0/line%d/name", i);
        write_file(p, sim_names[i]);
    }
    if (write_file(SIM "/live", "1") < 0)
        return -1;
    read_line(SIM "/bank0/chip_name", sim_chip, sizeof sim_chip);
    return sim_chip[0] ? 0 : -1;
}

static void sim_remove(void)
{
    char p[256];
    write_file(SIM "/live", "0");
    for (int i = 0; i < SIM_LINES; i++) {
        snprintf(p, sizeof p, SIM "/bank0/line%d", i);
        rmdir(p);
    }
    rmdir(SIM "/bank0");
    rmdir(SIM);
}

/* ---- fixel-info ------------------------------------------------------------ */

static const char *info_argv[] = {"/bin/fixel-info", NULL};

/* The connected connector fixel should pick: card, name and preferred mode
 * (the first line of sysfs "modes": the kernel sorts the preferred first). */
static char want_card[64], want_conn[64], want_mode[64];

static void check_drm(void)
{
    char cards[8][64], all[64][64], line[512], path[512], buf[4096];
    int nc = list("/sys/class/drm", "card", cards, 8), na = list("/sys/class/drm", "card", all, 64);
    int ncards = 0;
    for (int c = 0; c < nc; c++) {
        if (strchr(cards[c], '-'))
            continue;
        ncards++;
        char drv[256] = "", name[64];
        snprintf(path, sizeof path, "/sys/class/drm/%s/device/driver", cards[c]);
        ssize_t l = readlink(path, drv, sizeof drv - 1);
        drv[l > 0 ? l : 0] = 0;
        const char *base = strrchr(drv, '/') ? strrchr(drv, '/') + 1 : drv;
        if (!strcmp(base, "virtio-pci")) {
            /* virtio-gpu is bound to the virtio device below the PCI function */
            char v[8][64];
            snprintf(path, sizeof path, "/sys/class/drm/%s/device", cards[c]);
            if (list(path, "virtio", v, 8) == 1) {
                snprintf(path, sizeof path, "/sys/class/drm/%s/device/%s/driver", cards[c], v[0]);
                l = readlink(path, drv, sizeof drv - 1);
                drv[l > 0 ? l : 0] = 0;
                base = strrchr(drv, '/') ? strrchr(drv, '/') + 1 : drv;
            }
        }
        snprintf(name, sizeof name, "info-drm-%s", cards[c]);
        char want[160];
        snprintf(want, sizeof want, "/dev/dri/%s: driver %s ", cards[c], base);
        guest_check(name, base[0] && strstr(out, want) != NULL, "want \"%s\" (sysfs driver link)", want);

        /* connectors: /sys/class/drm/cardN-NAME/{status,modes} */
        size_t cl = strlen(cards[c]);
        for (int k = 0; k < na; k++) {
            if (strncmp(all[k], cards[c], cl) || all[k][cl] != '-')
                continue;
            const char *conn = all[k] + cl + 1;
            char st[32], pat[96];
            snprintf(path, sizeof path, "/sys/class/drm/%s/status", all[k]);
            if (read_line(path, st, sizeof st) < 0)
                continue;
            snprintf(path, sizeof path, "/sys/class/drm/%s/modes", all[k]);
            read_file(path, buf, sizeof buf);
            int nmodes = 0;
            for (const char *q = buf; *q; q++)
                nmodes += *q == '\n';
            char first[64] = "";
            sscanf(buf, "%63s", first);
            snprintf(name, sizeof name, "info-connector-%s", all[k]);
            snprintf(pat, sizeof pat, " %s: ", conn);
            const char *at = line_with(out, pat, line, sizeof line);
            char gst[32] = "";
            int gmodes = -1;
            const char *colon = at ? strstr(line, pat) : NULL;
            if (colon)
                sscanf(colon + strlen(pat), "%31[^,], %d modes", gst, &gmodes);
            guest_check(name, colon && strstr(line, "connector ") && !strcmp(gst, st) && gmodes == nmodes,
                        "fixel-info \"%s\"; sysfs status %s, %d modes", at ? line : "(missing)", st, nmodes);
            if (!at || strcmp(st, "connected"))
                continue;
            /* the mode lines under it: exactly one preferred, the kernel's first */
            const char *m = strchr(at, '\n');
            int npref = 0;
            char pref[64] = "";
            while (m && !strncmp(m + 1, "      ", 6)) {
                char ml[128];
                size_t ll = strcspn(m + 1, "\n");
                snprintf(ml, sizeof ml, "%.*s", (int)(ll < sizeof ml ? ll : sizeof ml - 1), m + 1);
                if (strstr(ml, " preferred")) {
                    npref++;
                    sscanf(ml, "%63s", pref);
                }
                m = strchr(m + 1, '\n');
            }
            snprintf(name, sizeof name, "info-preferred-%s", all[k]);
            guest_check(name, npref == 1 && first[0] && !strcmp(pref, first),
                        "fixel-info marks %d preferred (%s), sysfs lists %s first", npref, pref, first);
            if (!want_card[0]) {
                snprintf(want_card, sizeof want_card, "%s", cards[c]);
                snprintf(want_conn, sizeof want_conn, "%s", conn);
                snprintf(want_mode, sizeof want_mode, "%s", first);
            }
        }

        /* planes: the same query made here (sysfs has no planes) */
        snprintf(path, sizeof path, "/dev/dri/%s", cards[c]);
        int fd = open(path, O_RDWR | O_CLOEXEC);
        drmSetClientCap(fd, DRM_CLIENT_CAP_UNIVERSAL_PLANES, 1);
        drmModePlaneResPtr pr = fd >= 0 ? drmModeGetPlaneResources(fd) : NULL;
        int nplanes = pr ? (int)pr->count_planes : 0, ok = nplanes > 0, xr24 = 0;
        char detail[400] = "";
        for (int p = 0; p < nplanes; p++) {
            drmModePlanePtr pl = drmModeGetPlane(fd, pr->planes[p]);
            if (!pl)
                continue;
            char pat[48];
            snprintf(pat, sizeof pat, "plane %u: ", pl->plane_id);
            int has = 0;
            for (uint32_t f = 0; f < pl->count_formats; f++)
                has |= pl->formats[f] == DRM_FORMAT_XRGB8888;
            xr24 |= has;
            int tokens = -1;
            const char *fs = line_with(out, pat, line, sizeof line) ? strstr(line, " formats") : NULL;
            if (fs) {
                tokens = 0;
                for (const char *q = fs + 8; *q; q++)
                    tokens += *q == ' ';
            }
            int good = fs && tokens == (int)pl->count_formats && !!strstr(fs, " XR24") == has;
            ok &= good;
            size_t dl = strlen(detail);
            snprintf(detail + dl, sizeof detail - dl, "plane %u: %d formats (fixel-info %d)%s; ", pl->plane_id,
                     (int)pl->count_formats, tokens, has ? " XR24" : "");
            drmModeFreePlane(pl);
        }
        if (pr)
            drmModeFreePlaneResources(pr);
        if (fd >= 0)
            close(fd);
        snprintf(name, sizeof name, "info-planes-%s", cards[c]);
        guest_check(name, ok && xr24, "%s", detail);
    }
    guest_check("info-drm-cards", ncards > 0, "%d cards in /sys/class/drm", ncards);
}

static void check_fbdev(void)
{
    char fbs[8][64], path[256], name[64], want[256], line[512];
    int n = list("/sys/class/graphics", "fb", fbs, 8);
    for (int i = 0; i < n; i++) {
        char id[64], vs[32], bpp[16], stride[16], mode[64];
        int vw = 0, vh = 0, w = 0, h = 0;
        snprintf(path, sizeof path, "/sys/class/graphics/%s/name", fbs[i]);
        read_line(path, id, sizeof id);
        snprintf(path, sizeof path, "/sys/class/graphics/%s/virtual_size", fbs[i]);
        read_line(path, vs, sizeof vs);
        sscanf(vs, "%d,%d", &vw, &vh);
        snprintf(path, sizeof path, "/sys/class/graphics/%s/bits_per_pixel", fbs[i]);
        read_line(path, bpp, sizeof bpp);
        snprintf(path, sizeof path, "/sys/class/graphics/%s/stride", fbs[i]);
        read_line(path, stride, sizeof stride);
        snprintf(path, sizeof path, "/sys/class/graphics/%s/modes", fbs[i]); /* "U:800x480p-0" */
        read_line(path, mode, sizeof mode);
        sscanf(mode, "%*[^:]:%dx%d", &w, &h);
        snprintf(want, sizeof want, "/dev/%s: %s, %dx%d (virtual %dx%d), %s bpp, stride %s, ", fbs[i], id, w, h, vw,
                 vh, bpp, stride);
        const char *at = line_with(out, want, line, sizeof line);
        /* DRM's fbdev emulation is XRGB8888 at 32 bpp */
        int fmt_ok = at && (strcmp(bpp, "32") || strstr(line, "-> XRGB8888"));
        snprintf(name, sizeof name, "info-fbdev-%s", fbs[i]);
        guest_check(name, at && w > 0 && fmt_ok, "want \"%s...\" (sysfs); fixel-info \"%s\"", want,
                    at ? line : "(missing)");
    }
    guest_check("info-fbdev-devices", n > 0, "%d in /sys/class/graphics", n);
}

static const struct {
    const char *name, *classes;
} input_kinds[] = {
    {"fixel-rig-keyboard", " keyboard"},
    {"fixel-rig-mouse", " mouse"},
    {"fixel-rig-touchscreen", " touchscreen multitouch"},
    {"fixel-rig-tablet", " tablet"},
    {"QEMU Virtio Keyboard", " keyboard"},
    {"QEMU Virtio Tablet", " tablet"},
};

static void check_input(void)
{
    char ev[64][64], path[256], devname[128], want[256], line[512];
    int n = list("/sys/class/input", "event", ev, 64), listed = 0, kinds = 0;
    char missing[400] = "";
    for (int i = 0; i < n; i++) {
        snprintf(path, sizeof path, "/sys/class/input/%s/device/name", ev[i]);
        read_line(path, devname, sizeof devname);
        snprintf(want, sizeof want, "/dev/input/%s: \"%s\":", ev[i], devname);
        const char *at = line_with(out, want, line, sizeof line);
        if (at)
            listed++;
        else {
            size_t l = strlen(missing);
            snprintf(missing + l, sizeof missing - l, "%s ", want);
        }
        for (size_t k = 0; k < sizeof input_kinds / sizeof input_kinds[0]; k++) {
            if (strcmp(devname, input_kinds[k].name))
                continue;
            kinds++;
            char name[80];
            snprintf(name, sizeof name, "info-input-%s", devname[0] == 'Q' ? devname + 12 : devname + 10);
            for (char *q = name; *q; q++)
                if (*q == ' ')
                    *q = '-';
            const char *cls = at ? strstr(line, "\":") + 2 : "";
            guest_check(name, at && !strcmp(cls, input_kinds[k].classes), "%s is%s; fixel-info says \"%s\"", ev[i],
                        input_kinds[k].classes, at ? line : "(missing)");
        }
    }
    guest_check("info-input-all", n > 0 && listed == n && kinds == 6,
                "%d of %d event nodes in sysfs listed with their names, %d of 6 known devices seen; missing: %s",
                listed, n, kinds, missing[0] ? missing : "none");
}

static void check_gpio(void)
{
    char chips[16][64], line[512], want[128], detail[400] = "";
    int n = list("/sys/bus/gpio/devices", "gpiochip", chips, 16), listed = 0;
    for (int i = 0; i < n; i++) {
        snprintf(want, sizeof want, "/dev/%s: ", chips[i]);
        listed += line_with(out, want, line, sizeof line) != NULL;
    }
    guest_check("info-gpio-chips", n > 0 && listed == n, "%d of %d chips in /sys/bus/gpio listed", listed, n);

    snprintf(want, sizeof want, "/dev/%s: fixel-tools, %d lines\n", sim_chip, SIM_LINES);
    const char *at = strstr(out, want);
    int ok = at != NULL, rows = 0;
    const char *p = at ? strchr(at, '\n') : NULL;
    /* one row per line: "    N NAME  input|output [used by CONSUMER]" */
    while (ok && p && !strncmp(p + 1, "    ", 4) && p[5] != '/') {
        unsigned idx = 99;
        char nm[64] = "", dir[16] = "";
        size_t ll = strcspn(p + 1, "\n");
        snprintf(line, sizeof line, "%.*s", (int)ll, p + 1);
        sscanf(line, "%u %63s %15s", &idx, nm, dir);
        int want_out = idx == 3;
        int good = idx == (unsigned)rows && idx < SIM_LINES &&
                   !strcmp(nm, sim_names[idx] ? sim_names[idx] : "-") &&
                   !strcmp(dir, want_out ? "output" : "input") &&
                   !!strstr(line, "used by rig-tools") == want_out;
        if (!good) {
            ok = 0;
            snprintf(detail, sizeof detail, "row \"%s\" ", line);
        }
        rows++;
        p = strchr(p + 1, '\n');
    }
    size_t dl = strlen(detail);
    snprintf(detail + dl, sizeof detail - dl, "%d rows", rows);
    guest_check("info-gpio-sim", ok && rows == SIM_LINES,
                "want \"/dev/%s: fixel-tools, %d lines\" (configfs) with names, line 3 output used by rig-tools: %s",
                sim_chip, SIM_LINES, at ? detail : "header missing");
}

static void check_choice(void)
{
    char want[256], line[512];
    snprintf(want, sizeof want, "  backend drm, device \"/dev/dri/%s\", connector %s, %s@", want_card, want_conn,
             want_mode);
    const char *at = strstr(out, want);
    const char *why = at ? line_with(at, "  why: ", line, sizeof line) : NULL;
    guest_check("info-choice-drm", want_card[0] && at && why && strstr(line, "DRM"),
                "want \"%s\" (first connected connector, preferred mode) and a reason; got: %s", want,
                strstr(out, "fixel's choice") ? strstr(out, "fixel's choice") : "(no choice section)");

    /* FIXEL_BACKEND=fbdev: echoed, obeyed, and given as the reason */
    const char *env = "FIXEL_BACKEND=fbdev";
    int rc = run(ROOT, env, info_argv);
    char vs[32], mode[64];
    int w = 0, h = 0;
    read_line("/sys/class/graphics/fb0/modes", mode, sizeof mode);
    sscanf(mode, "%*[^:]:%dx%d", &w, &h);
    read_line("/sys/class/graphics/fb0/virtual_size", vs, sizeof vs);
    snprintf(want, sizeof want, "  backend fbdev, device \"/dev/fb0\", %dx%d, ", w, h);
    at = strstr(out, want);
    why = at ? line_with(at, "  why: ", line, sizeof line) : NULL;
    guest_check("info-choice-env", rc == 0 && strstr(out, "\n  FIXEL_BACKEND=fbdev\n") && at && why &&
                                       strstr(line, "FIXEL_BACKEND"),
                "exit %d, want \"%s\" (sysfs fb0 mode %s) and FIXEL_BACKEND as the reason; got: %s", rc, want, mode,
                strstr(out, "fixel's choice") ? strstr(out, "fixel's choice") : "(no choice section)");
}

static void check_nonroot(void)
{
    int rc = run(USER_NO_GROUPS, NULL, info_argv);
    char line[512];
    const char *drm = line_with(out, "/dev/dri/card0: cannot open (Permission denied)", line, sizeof line);
    int drm_ok = drm && strstr(line, "group video");
    const char *fb = line_with(out, "/dev/fb0: cannot open (Permission denied)", line, sizeof line);
    int fb_ok = fb && strstr(line, "group video");
    const char *in = line_with(out, "/dev/input/event0: cannot open (Permission denied)", line, sizeof line);
    int in_ok = in && strstr(line, "group input");
    const char *ch = strstr(out, "fixel's choice");
    int choice_ok = ch && !strstr(ch, "backend drm") && !strstr(ch, "backend fbdev") && strstr(ch, "permission");
    guest_check("info-nonroot", rc == 0 && drm_ok && fb_ok && in_ok && choice_ok,
                "exit %d; DRM %s, fbdev %s, input %s (each names the group), choice names permissions %s: %s", rc,
                drm_ok ? "ok" : "bad", fb_ok ? "ok" : "bad", in_ok ? "ok" : "bad", choice_ok ? "ok" : "bad",
                ch ? ch : out);
}

static void info_tests(void)
{
    static const char *names[] = {"fixel-rig-keyboard", "fixel-rig-mouse", "fixel-rig-touchscreen",
                                  "fixel-rig-tablet"};
    struct libevdev_uinput *u[4];
    for (int i = 0; i < 4; i++)
        u[i] = make_input(names[i], i);
    int sim = sim_create();
    guest_check("info-setup", u[0] && u[1] && u[2] && u[3] && sim == 0, "uinput devices and gpio-sim chip %s",
                sim_chip);
    struct gpiod_chip *chip = sim == 0 ? gpiod_chip_open_by_name(sim_chip) : NULL;
    struct gpiod_line *led = chip ? gpiod_chip_get_line(chip, 3) : NULL;
    if (led && gpiod_line_request_output(led, "rig-tools", 0) < 0)
        led = NULL;

    int rc = run(ROOT, NULL, info_argv);
    printf("%s", out);
    guest_check("info-exit", rc == 0 && !strstr(err, "fixel-info:"), "exit %d, stderr: %s", rc, err);
    stamp("fixel-info");
    check_drm();
    check_fbdev();
    check_input();
    check_gpio();
    check_choice(); /* runs it again */
    check_nonroot();

    if (led)
        gpiod_line_release(led);
    if (chip)
        gpiod_chip_close(chip);
    if (sim == 0)
        sim_remove();
    for (int i = 0; i < 4; i++)
        if (u[i])
            libevdev_uinput_destroy(u[i]);
}

/* ---- fixel-shot ------------------------------------------------------------ */

static int shot_file_to_host(const char *name, const char *spec, const char *path)
{
    uint8_t *rgb = NULL;
    int32_t w = 0, h = 0;
    size_t l = strlen(path);
    int r = l > 4 && !strcmp(path + l - 4, ".ppm") ? fx_read_ppm_rgb(path, &rgb, &w, &h)
                                                   : fx_read_png_rgb(path, &rgb, &w, &h);
    if (r < 0) {
        guest_check(name, 0, "cannot read %s: %s", path, fx_strerror(r));
        return 0;
    }
    int ok = send_image(name, spec, rgb, w, h);
    free(rgb);
    return ok;
}

/* The PPM writer against the PNG the host has checked. */
static void same_pixels(const char *name, const char *ppm, const char *png)
{
    uint8_t *a = NULL, *b = NULL;
    int32_t aw = 0, ah = 0, bw = 0, bh = 0;
    int ra = fx_read_ppm_rgb(ppm, &a, &aw, &ah), rb = fx_read_png_rgb(png, &b, &bw, &bh);
    guest_check(name, ra == 0 && rb == 0 && aw == bw && ah == bh && !memcmp(a, b, (size_t)aw * (size_t)ah * 3),
                "%s %dx%d (%d), %s %dx%d (%d): %s", ppm, aw, ah, ra, png, bw, bh, rb,
                ra || rb ? "unreadable" : "compared every pixel");
    free(a);
    free(b);
}

/* A scanout format fixel lacks (BGRX8888, which bochs offers): refused with
 * a message naming it. Only where a plane has the format. */
static void shot_foreign_format(void)
{
    int fd = open("/dev/dri/card0", O_RDWR | O_CLOEXEC);
    drmSetClientCap(fd, DRM_CLIENT_CAP_UNIVERSAL_PLANES, 1);
    drmModeResPtr r = fd >= 0 ? drmModeGetResources(fd) : NULL;
    drmModePlaneResPtr pr = r ? drmModeGetPlaneResources(fd) : NULL;
    int has = 0;
    for (uint32_t p = 0; pr && p < pr->count_planes && !has; p++) {
        drmModePlanePtr pl = drmModeGetPlane(fd, pr->planes[p]);
        for (uint32_t f = 0; pl && f < pl->count_formats; f++)
            has |= pl->formats[f] == DRM_FORMAT_BGRX8888;
        drmModeFreePlane(pl);
    }
    drmModeConnectorPtr con = NULL;
    for (int c = 0; has && r && c < r->count_connectors && !con; c++) {
        con = drmModeGetConnector(fd, r->connectors[c]);
        if (con && (con->connection != DRM_MODE_CONNECTED || !con->count_modes)) {
            drmModeFreeConnector(con);
            con = NULL;
        }
    }
    if (con) {
        struct drm_mode_create_dumb cd = {.width = con->modes[0].hdisplay, .height = con->modes[0].vdisplay, .bpp = 32};
        uint32_t fb = 0, h[4] = {0}, pitch[4] = {0}, off[4] = {0};
        int ok = drmIoctl(fd, DRM_IOCTL_MODE_CREATE_DUMB, &cd) == 0;
        h[0] = cd.handle;
        pitch[0] = cd.pitch;
        ok = ok && drmModeAddFB2(fd, cd.width, cd.height, DRM_FORMAT_BGRX8888, h, pitch, off, &fb, 0) == 0;
        ok = ok && drmModeSetCrtc(fd, r->crtcs[0], fb, 0, 0, &con->connector_id, 1, &con->modes[0]) == 0;
        const char *a[] = {"/bin/fixel-shot", "-d", "/dev/dri/card0", "-o", "/tmp/bx24.png", NULL};
        int rc = ok ? run(ROOT, NULL, a) : -2;
        guest_check("shot-drm-foreign-format", rc == 1 && strstr(err, "BX24") && strstr(err, "not supported") &&
                                                    access("/tmp/bx24.png", F_OK) != 0,
                    "BGRX8888 on the CRTC (%s): exit %d: %s", ok ? "set" : "setup failed", rc, err);
        drmModeFreeConnector(con);
    } else
        printf("  no plane offers BGRX8888 here: the foreign-format case is not run\n");
    if (pr)
        drmModeFreePlaneResources(pr);
    if (r)
        drmModeFreeResources(r);
    if (fd >= 0)
        close(fd); /* removes the framebuffer; the console comes back */
}

static void shot_tests(void)
{
    mkdir("/tmp/u", 0755);
    chown("/tmp/u", 1000, 1000);
    fx_display *d;
    fx_display_options o;

    /* fbdev: fixel's fbdev display shows bars; fixel-shot -d /dev/fb0 saves them */
    fx_display_options_init(&o);
    fx_display_options_from_env(&o); /* the variables the rig sets, as the tools do */
    o.backend = FX_BACKEND_FBDEV;
    int r = fx_display_open(&d, &o);
    if (r < 0) {
        guest_check("shot-fbdev", 0, "open fbdev: %s", fx_strerror(r));
    } else {
        fx_surface s = fx_display_surface(d);
        scene_draw("bars", &s);
        fx_display_present(d, NULL, 0);
        fx_display_wait(d, 1000);
        fx_display_info in;
        fx_display_get_info(d, &in);
        stamp("fbdev display open");
        guest_request("SCREEN shot-fbdev-screen %d %d 0 bars", in.width, in.height);
        const char *a1[] = {"/bin/fixel-shot", "-d", "/dev/fb0", "-o", "/tmp/fb.png", NULL};
        int rc = run(ROOT, NULL, a1);
        guest_check("shot-fbdev-exit", rc == 0 && strstr(out, "/tmp/fb.png"), "exit %d: %s%s", rc, out, err);
        stamp("fixel-shot fbdev");
        if (rc == 0)
            shot_file_to_host("shot-fbdev", "bars", "/tmp/fb.png");
        stamp("image sent");
        /* a kiosk user in group video may read fbdev; PPM by extension */
        const char *a2[] = {"/bin/fixel-shot", "-d", "/dev/fb0", "-o", "/tmp/u/fb.ppm", NULL};
        rc = run(USER_VIDEO_INPUT, NULL, a2);
        guest_check("shot-fbdev-user-exit", rc == 0, "exit %d: %s%s", rc, out, err);
        if (rc == 0)
            same_pixels("shot-fbdev-user-ppm", "/tmp/u/fb.ppm", "/tmp/fb.png");
        rc = run(USER_NO_GROUPS, NULL, a2);
        guest_check("shot-fbdev-denied", rc == 1 && strstr(err, "Permission denied") && strstr(err, "group video"),
                    "exit %d: %s", rc, err);
        fx_display_close(d);
    }

    /* DRM: fixel's DRM display (page flipping) shows checker */
    fx_display_options_init(&o);
    fx_display_options_from_env(&o); /* the variables the rig sets, as the tools do */
    o.backend = FX_BACKEND_DRM;
    r = fx_display_open(&d, &o);
    if (r < 0) {
        guest_check("shot-drm", 0, "open drm: %s", fx_strerror(r));
        return;
    }
    fx_surface s = fx_display_surface(d);
    scene_draw("bars", &s);
    fx_display_present(d, NULL, 0);
    fx_display_wait(d, 1000);
    s = fx_display_surface(d); /* the second buffer: the shot must follow the flip */
    scene_draw("checker", &s);
    fx_display_present(d, NULL, 0);
    fx_display_wait(d, 1000);
    fx_display_info in;
    fx_display_get_info(d, &in);
    guest_request("SCREEN shot-drm-screen %d %d 0 checker", in.width, in.height);
    const char *a3[] = {"/bin/fixel-shot", "-o", "/tmp/drm.png", NULL};
    int rc = run(ROOT, NULL, a3);
    guest_check("shot-drm-exit", rc == 0 && strstr(out, "/dev/dri/card0"), "exit %d (no -d: DRM first): %s%s", rc,
                out, err);
    if (rc == 0)
        shot_file_to_host("shot-drm", "checker", "/tmp/drm.png");
    /* not root: the kernel withholds the buffer handle */
    const char *a4[] = {"/bin/fixel-shot", "-d", "/dev/dri/card0", "-o", "/tmp/u/drm.png", NULL};
    rc = run(USER_VIDEO_INPUT, NULL, a4);
    guest_check("shot-drm-denied", rc == 1 && strstr(err, "not allowed to map the scanout buffer") &&
                                       access("/tmp/u/drm.png", F_OK) != 0,
                "exit %d: %s", rc, err);
    /* not root, no -d: /dev/fb0 is the console's buffer, not this picture;
     * saving it would be a wrong screenshot */
    const char *a5[] = {"/bin/fixel-shot", "-o", "/tmp/u/auto.png", NULL};
    rc = run(USER_VIDEO_INPUT, NULL, a5);
    guest_check("shot-drm-owned", rc == 1 && strstr(err, "another program") && access("/tmp/u/auto.png", F_OK) != 0,
                "exit %d: %s", rc, err);
    fx_display_close(d);

    /* nothing of fixel's on screen: the console's framebuffer is the CRTC's */
    const char *a6[] = {"/bin/fixel-shot", "-d", "/dev/dri/card0", "-o", "/tmp/con.png", NULL};
    rc = run(ROOT, NULL, a6);
    printf("  console scanout via DRM: exit %d: %s%s\n", rc, out, err);
    shot_foreign_format();
}

int main(void)
{
    setvbuf(stdout, NULL, _IOLBF, 0);
    stamp("start");
    info_tests();
    stamp("fixel-info checks");
    shot_tests();
    stamp("fixel-shot checks");
    return guest_failed;
}
