/* SPDX-License-Identifier: MIT */
/* Guest program: DRM plane features on real drivers — the scanout format
 * (XRGB8888 / RGB565) and plane rotation versus software rotation.
 *
 * RGB565 is proven on vkms (loaded here from /modules.optional; Debian's
 * kernel lacks it): vkms has no visible output, but it computes a CRC of
 * every composed frame (debugfs crtc-0/crc). The same picture made only of
 * exactly representable colours (channels 0 or 255) must give the same CRC
 * in XRGB8888 and RGB565, and a different picture a different CRC.
 *
 * Plane rotation: the plane properties are read here with libdrm, apart from
 * the library, and the library's choice (info.rotation_hw) must agree. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <drm_fourcc.h>
#include <xf86drm.h>
#include <xf86drmMode.h>

#include "fixel/display.h"
#include "fixel/error.h"
#include "guest.h"
#include "guest_drm.h"

static void opts(fx_display_options *o, const char *device, int rotation)
{
    fx_display_options_init(o);
    fx_display_options_from_env(o); /* the variables the rig sets, as the tools do */
    o->backend = FX_BACKEND_DRM;
    o->device = device;
    o->rotation = rotation;
    o->console = 0; /* display.c covers the console; leave the VT alone here */
    o->log = capture_log;
    o->log_priority = FX_LOG_DEBUG;
}

/* ---- what the primary plane offers, read without the library ------------ */

struct plane_facts {
    int found;
    int xrgb, rgb565;
    int has_rot;
    char rot_names[128];
    uint64_t rot_value;
};

static void plane_facts(const char *dev, struct plane_facts *pf)
{
    memset(pf, 0, sizeof *pf);
    int fd = open(dev, O_RDWR | O_CLOEXEC);
    if (fd < 0)
        return;
    drmSetClientCap(fd, DRM_CLIENT_CAP_UNIVERSAL_PLANES, 1);
    drmModePlaneResPtr pr = drmModeGetPlaneResources(fd);
    for (uint32_t i = 0; pr && i < pr->count_planes && !pf->found; i++) {
        drmModePlanePtr p = drmModeGetPlane(fd, pr->planes[i]);
        if (!p || !(p->possible_crtcs & 1)) {
            drmModeFreePlane(p);
            continue;
        }
        drmModeObjectPropertiesPtr props = drmModeObjectGetProperties(fd, p->plane_id, DRM_MODE_OBJECT_PLANE);
        int primary = 0;
        struct plane_facts t;
        memset(&t, 0, sizeof t);
        for (uint32_t k = 0; props && k < props->count_props; k++) {
            drmModePropertyPtr prop = drmModeGetProperty(fd, props->props[k]);
            if (prop && !strcmp(prop->name, "type") && props->prop_values[k] == DRM_PLANE_TYPE_PRIMARY)
                primary = 1;
            if (prop && !strcmp(prop->name, "rotation")) {
                t.has_rot = 1;
                t.rot_value = props->prop_values[k];
                for (int j = 0; j < prop->count_enums; j++) {
                    size_t l = strlen(t.rot_names);
                    snprintf(t.rot_names + l, sizeof t.rot_names - l, "%s%s", l ? "," : "",
                             prop->enums[j].name);
                }
            }
            drmModeFreeProperty(prop);
        }
        drmModeFreeObjectProperties(props);
        if (primary) {
            *pf = t;
            pf->found = 1;
            for (uint32_t f = 0; f < p->count_formats; f++) {
                pf->xrgb |= p->formats[f] == DRM_FORMAT_XRGB8888;
                pf->rgb565 |= p->formats[f] == DRM_FORMAT_RGB565;
            }
        }
        drmModeFreePlane(p);
    }
    drmModeFreePlaneResources(pr);
    close(fd);
}

#define driver_name guest_drm_driver

/* ---- plane rotation vs software ------------------------------------------ */

static void rotation_checks(const char *dev, const char *tag)
{
    struct plane_facts pf;
    char drv[32], name[64];
    plane_facts(dev, &pf);
    driver_name(dev, drv, sizeof drv);
    printf("  %s (%s): primary plane %s, XRGB8888 %d, RGB565 %d, rotation property %s [%s] value %llu\n",
           dev, drv, pf.found ? "found" : "missing", pf.xrgb, pf.rgb565, pf.has_rot ? "yes" : "no",
           pf.rot_names, (unsigned long long)pf.rot_value);

    /* 90 degrees, automatic: the plane rotates exactly when it offers
     * rotate-270 (DRM's counter-clockwise name for fixel's 90). */
    int expect_hw = pf.has_rot && strstr(pf.rot_names, "rotate-270") != NULL;
    fx_display *d;
    fx_display_options o;
    opts(&o, dev, 90);
    logbuf[0] = 0;
    snprintf(name, sizeof name, "%s-rotation-choice", tag);
    if (guest_open(name, &d, &o) < 0)
        return;
    fx_display_info info;
    fx_display_get_info(d, &info);
    fx_surface s = fx_display_surface(d);
    const char *said = "rotation 90 in software (no plane rotation property)";
    if (expect_hw)
        said = "rotation 90 by the plane";
    else if (pf.has_rot)
        said = "rotation 90 in software (the plane cannot rotate";
    guest_check(name,
                info.rotation_hw == expect_hw && strstr(logbuf, said) &&
                    info.present == (expect_hw ? FX_PRESENT_DIRECT : FX_PRESENT_SHADOW) &&
                    s.w == info.height && s.h == info.width,
                "%s: property %s, rotation_hw %d, %s presentation, surface %dx%d on %dx%d, log says \"%s\": %s",
                drv, pf.has_rot ? pf.rot_names : "none", info.rotation_hw,
                info.present == FX_PRESENT_DIRECT ? "direct" : "shadow", s.w, s.h, info.width, info.height,
                said, strstr(logbuf, said) ? "yes" : "no");
    fx_display_close(d);

    /* Forcing software must win over any plane. */
    setenv("FIXEL_SW_ROTATION", "1", 1);
    opts(&o, dev, 270);
    logbuf[0] = 0;
    snprintf(name, sizeof name, "%s-rotation-forced-software", tag);
    int r = guest_open(name, &d, &o);
    unsetenv("FIXEL_SW_ROTATION");
    if (r < 0)
        return;
    fx_display_get_info(d, &info);
    guest_check(name, info.rotation_hw == 0 && strstr(logbuf, "rotation 270 in software (forced)"),
                "rotation_hw %d, log %s", info.rotation_hw,
                strstr(logbuf, "(forced)") ? "names the override" : "lacks the override");
    fx_display_close(d);
}

/* ---- scanout format ------------------------------------------------------- */

/* Opening with FIXEL_DRM_FORMAT=RGB565 gives RGB565 where the plane offers
 * it and falls back to XRGB8888 (logged) where not. */
static void format_choice_check(const char *dev, const char *tag)
{
    struct plane_facts pf;
    char name[64];
    plane_facts(dev, &pf);
    setenv("FIXEL_DRM_FORMAT", "RGB565", 1);
    fx_display *d;
    fx_display_options o;
    opts(&o, dev, 0);
    logbuf[0] = 0;
    snprintf(name, sizeof name, "%s-format-rgb565-choice", tag);
    int r = guest_open(name, &d, &o);
    unsetenv("FIXEL_DRM_FORMAT");
    if (r < 0)
        return;
    fx_display_info info;
    fx_display_get_info(d, &info);
    fx_format want = pf.rgb565 ? FX_FMT_RGB565 : FX_FMT_XRGB8888;
    int logged = pf.rgb565 || strstr(logbuf, "primary plane has no RGB565; using XRGB8888") != NULL;
    guest_check(name, info.format == want && logged, "plane offers RGB565: %s; got %s%s",
                pf.rgb565 ? "yes" : "no", fx_format_get(info.format)->name,
                logged ? "" : " (fallback not logged)");
    fx_display_close(d);
}

/* ---- vkms CRCs ------------------------------------------------------------ */

static const fx_color colours[8] = {0xFFFFFFFF, 0xFFFFFF00, 0xFF00FFFF, 0xFF00FF00,
                                    0xFFFF00FF, 0xFFFF0000, 0xFF0000FF, 0xFF000000};

/* Eight bars over the top half, eight smaller in the bottom half in another
 * order; variant 1 swaps two bottom bars (a small change must show). */
static void exact_scene(const fx_surface *s, int variant)
{
    int32_t w = s->w, h = s->h;
    for (int i = 0; i < 8; i++) {
        fx_rect top = {w * i / 8, 0, w * (i + 1) / 8, h / 2};
        fx_surface_fill(s, top, colours[i]);
        int j = (i * 3 + 1) & 7;
        if (variant && (i == 2 || i == 5))
            j = (((i == 2 ? 5 : 2) * 3) + 1) & 7;
        fx_rect bot = {w * i / 8, h / 2, w * (i + 1) / 8, h};
        fx_surface_fill(s, bot, colours[j]);
    }
}

/* What vkms computes for a frame: the kernel's crc32_le (reflected
 * 0xEDB88320, seed 0, no inversions) over each composed row of 16-bit
 * a, r, g, b little-endian pixels; an 8-bit channel v becomes v * 257. */
static uint32_t crc32_le(uint32_t crc, const uint8_t *p, size_t n)
{
    static uint32_t table[256];
    if (!table[1])
        for (uint32_t i = 0; i < 256; i++) {
            uint32_t c = i;
            for (int k = 0; k < 8; k++)
                c = c & 1 ? (c >> 1) ^ 0xEDB88320u : c >> 1;
            table[i] = c;
        }
    while (n--)
        crc = (crc >> 8) ^ table[(crc ^ *p++) & 0xff];
    return crc;
}

static uint32_t model_crc(int32_t w, int32_t h, int variant)
{
    static uint32_t px[640 * 480];
    static uint8_t row[640 * 8];
    if (w > 640 || h > 480)
        return 0;
    fx_surface s;
    fx_surface_init(&s, px, w, h, w * 4, FX_FMT_XRGB8888);
    exact_scene(&s, variant);
    uint32_t crc = 0;
    for (int32_t y = 0; y < h; y++) {
        for (int32_t x = 0; x < w; x++) {
            uint32_t c = px[y * w + x];
            uint16_t v[4] = {0xffff, (uint16_t)(((c >> 16) & 255) * 257), (uint16_t)(((c >> 8) & 255) * 257),
                             (uint16_t)((c & 255) * 257)};
            for (int k = 0; k < 4; k++) {
                row[x * 8 + k * 2] = (uint8_t)(v[k] & 255);
                row[x * 8 + k * 2 + 1] = (uint8_t)(v[k] >> 8);
            }
        }
        crc = crc32_le(crc, row, (size_t)w * 8);
    }
    return crc;
}

static int64_t now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (int64_t)t.tv_sec * 1000 + t.tv_nsec / 1000000;
}

/* Show the scene and read frame CRCs until three consecutive frames agree
 * (the first frames may still be the previous picture). 0 on success. */
static int crc_of(const char *dev, const char *crcdir, fx_format f, int variant, uint32_t *crc, char *err,
                  size_t errn)
{
    fx_display *d;
    fx_display_options o;
    opts(&o, dev, 0);
    o.format = f;
    o.mode = "640x480";
    logbuf[0] = 0;
    int r = fx_display_open(&d, &o);
    if (r < 0) {
        snprintf(err, errn, "open: %s", fx_strerror(r));
        return -1;
    }
    fx_display_info info;
    fx_display_get_info(d, &info);
    if (info.format != f) {
        snprintf(err, errn, "asked %s, got %s", fx_format_get(f)->name, fx_format_get(info.format)->name);
        fx_display_close(d);
        return -1;
    }
    fx_surface s = fx_display_surface(d);
    exact_scene(&s, variant);
    fx_display_present(d, NULL, 0);
    fx_display_wait(d, 1000);

    char path[160];
    snprintf(path, sizeof path, "%s/control", crcdir);
    int cfd = open(path, O_WRONLY);
    if (cfd < 0 || write(cfd, "auto", 4) != 4) {
        snprintf(err, errn, "%.100s: %.40s", path, strerror(errno));
        if (cfd >= 0)
            close(cfd);
        fx_display_close(d);
        return -1;
    }
    close(cfd);
    snprintf(path, sizeof path, "%s/data", crcdir);
    int dfd = open(path, O_RDONLY);
    if (dfd < 0) {
        snprintf(err, errn, "%.100s: %.40s", path, strerror(errno));
        fx_display_close(d);
        return -1;
    }
    char buf[128];
    uint32_t last = 0;
    int same = 0, frames = 0, ret = -1;
    int64_t end = now_ms() + 8000;
    snprintf(err, errn, "no stable CRC within 8 s");
    while (now_ms() < end && same < 3) {
        struct pollfd p = {.fd = dfd, .events = POLLIN};
        if (poll(&p, 1, 500) <= 0)
            continue;
        /* One entry per read: "0x<frame> 0x<crc>\n" and a NUL. */
        ssize_t n = read(dfd, buf, sizeof buf - 1);
        if (n <= 0) {
            snprintf(err, errn, "read crc data: %zd %.40s", n, strerror(errno));
            break;
        }
        buf[n] = 0;
        unsigned long long frame = 0, c = 0;
        if (sscanf(buf, "%llx %llx", &frame, &c) == 2) {
            frames++;
            same = frames > 1 && (uint32_t)c == last ? same + 1 : 1;
            last = (uint32_t)c;
        }
    }
    close(dfd);
    if (same >= 3) {
        *crc = last;
        ret = 0;
        snprintf(err, errn, "%d frames read", frames);
    }
    fx_display_close(d);
    return ret;
}

static int load_optional_modules(char *detail, size_t n)
{
    return guest_load_modules("/modules.optional", detail, n);
}

static void vkms_checks(void)
{
    char detail[300];
    load_optional_modules(detail, sizeof detail);
    /* Find the vkms card (it registers after the real one). */
    char dev[32] = "", drv[32];
    int minor = -1;
    for (int t = 0; t < 30 && minor < 0; t++) {
        for (int i = 0; i < 8; i++) {
            char p[32];
            snprintf(p, sizeof p, "/dev/dri/card%d", i);
            if (access(p, F_OK) == 0 && !strcmp(driver_name(p, drv, sizeof drv), "vkms")) {
                snprintf(dev, sizeof dev, "%s", p);
                minor = i;
            }
        }
        if (minor < 0)
            usleep(100000);
    }
    guest_check("vkms-loaded", minor >= 0, "modules: %s; card %s", detail, minor >= 0 ? dev : "none");
    if (minor < 0)
        return;
    rotation_checks(dev, "vkms");
    format_choice_check(dev, "vkms");

    mkdir("/sys/kernel/debug", 0755);
    mount("debugfs", "/sys/kernel/debug", "debugfs", 0, NULL);
    char crcdir[96];
    snprintf(crcdir, sizeof crcdir, "/sys/kernel/debug/dri/%d/crtc-0/crc", minor);
    struct plane_facts pf;
    plane_facts(dev, &pf);
    if (!pf.rgb565) {
        guest_check("vkms-crc-rgb565-equals-xrgb8888", 0, "vkms primary plane lacks RGB565");
        return;
    }
    uint32_t cx = 0, c5 = 0, cv = 0;
    char ex[160], e5[160], ev[160];
    int rx = crc_of(dev, crcdir, FX_FMT_XRGB8888, 0, &cx, ex, sizeof ex);
    int r5 = crc_of(dev, crcdir, FX_FMT_RGB565, 0, &c5, e5, sizeof e5);
    int rv = crc_of(dev, crcdir, FX_FMT_XRGB8888, 1, &cv, ev, sizeof ev);
    uint32_t model = model_crc(640, 480, 0);
    guest_check("vkms-crc-xrgb8888-matches-model", rx == 0 && cx == model,
                "vkms %08x, computed from the intended picture %08x", cx, model);
    guest_check("vkms-crc-rgb565-equals-xrgb8888", rx == 0 && r5 == 0 && cx == c5,
                "XRGB8888 %08x (%s), RGB565 %08x (%s)", cx, ex, c5, e5);
    guest_check("vkms-crc-other-picture-differs", rx == 0 && rv == 0 && cv != cx,
                "picture %08x, two bars swapped %08x (%s)", cx, cv, ev);
    /* Same picture, 16 bits, second run: the CRC is a property of the
     * picture, not of the run. */
    uint32_t c5b = 0;
    int r5b = crc_of(dev, crcdir, FX_FMT_RGB565, 1, &c5b, e5, sizeof e5);
    guest_check("vkms-crc-rgb565-other-picture", r5b == 0 && c5b == cv && c5b != c5,
                "RGB565 swapped %08x, XRGB8888 swapped %08x", c5b, cv);
}

int main(void)
{
    setvbuf(stdout, NULL, _IOLBF, 0);
    rotation_checks("/dev/dri/card0", "card0");
    format_choice_check("/dev/dri/card0", "card0");
    vkms_checks();
    system("rmmod vkms 2>/dev/null");
    return guest_failed;
}
