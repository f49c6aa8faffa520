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
 * would open it. The driver is unloaded at the end. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <xf86drm.h>

#include "fixel/display.h"
#include "fixel/env.h"
#include "fixel/error.h"
#include "guest.h"
#include "scenes.h"

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

static int load_card_modules(char *detail, size_t n)
{
    FILE *f = fopen("/modules.cards", "r");
    char line[200], cmd[300];
    int bad = 0;
    detail[0] = 0;
    if (!f) {
        snprintf(detail, n, "no /modules.cards");
        return -1;
    }
    while (fgets(line, sizeof line, f)) {
        line[strcspn(line, "\n")] = 0;
        if (!*line)
            continue;
        /* kms.c may have loaded a shared helper (drm_shmem_helper) already */
        char mod[200], sys[240];
        const char *b = strrchr(line, '/');
        snprintf(mod, sizeof mod, "%s", b ? b + 1 : line);
        mod[strcspn(mod, ".")] = 0;
        for (char *q = mod; *q; q++)
            if (*q == '-')
                *q = '_';
        snprintf(sys, sizeof sys, "/sys/module/%s", mod);
        if (access(sys, F_OK) == 0)
            continue;
        snprintf(cmd, sizeof cmd, "insmod /lib/modules/%s 2>&1", line);
        int st = system(cmd);
        size_t l = strlen(detail);
        snprintf(detail + l, n - l, "%s%s%s", l ? " " : "", mod, st == 0 ? "" : "(failed)");
        bad += st != 0;
    }
    fclose(f);
    return bad ? -1 : 0;
}

static const char *driver_of(const char *dev, char *out, size_t n)
{
    snprintf(out, n, "?");
    int fd = open(dev, O_RDWR | O_CLOEXEC);
    if (fd < 0)
        return out;
    drmVersionPtr v = drmGetVersion(fd);
    if (v) {
        snprintf(out, n, "%s", v->name);
        drmFreeVersion(v);
    }
    close(fd);
    return out;
}

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
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
        fn(arg);
        fflush(stdout);
        _exit(guest_failed);
    }
    int st = 0;
    waitpid(pid, &st, 0);
    if (!WIFEXITED(st) || WEXITSTATUS(st))
        guest_failed = 1;
}

/* ---- fixel-info ------------------------------------------------------------ */

static char out[1 << 16];

static const char *line_with(const char *text, const char *needle, char *line, size_t n)
{
    const char *p = strstr(text, needle);
    if (!p)
        return NULL;
    while (p > text && p[-1] != '\n')
        p--;
    size_t l = strcspn(p, "\n");
    snprintf(line, n, "%.*s", (int)(l < n ? l : n - 1), p);
    return p;
}

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

int main(void)
{
    setvbuf(stdout, NULL, _IOLBF, 0);
    char detail[300], drv[32];
    int lr = load_card_modules(detail, sizeof detail);
    int ok = 0;
    for (int t = 0; t < 50 && !ok; t++) {
        DIR *dir = opendir("/sys/class/drm");
        struct dirent *e;
        while (dir && (e = readdir(dir)))
            if (!strncmp(e->d_name, "card0-", 6) || !strncmp(e->d_name, "card1-", 6))
                snprintf(e->d_name[4] == '0' ? conn0 : conn1, sizeof conn0, "%s", e->d_name + 6);
        if (dir)
            closedir(dir);
        ok = access("/dev/dri/card1", F_OK) == 0 && conn0[0] && conn1[0];
        if (!ok)
            msleep(100);
    }
    driver_of("/dev/dri/card1", drv, sizeof drv);
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

    char cmd[64];
    snprintf(cmd, sizeof cmd, "rmmod %s 2>&1", CARD1_MODULE);
    int rm = system(cmd);
    int gone = 0;
    for (int t = 0; t < 30 && !gone; t++) {
        gone = access("/dev/dri/card1", F_OK) != 0;
        if (!gone)
            msleep(100);
    }
    guest_check("outputs-second-card-removed", rm == 0 && gone, "rmmod %s: %d, card1 %s", CARD1_MODULE, rm,
                gone ? "gone" : "still there");
    return guest_failed;
}
