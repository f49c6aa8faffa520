/* SPDX-License-Identifier: MIT */
/* fixel-info — what this machine offers fixel: DRM cards, fbdev devices,
 * input devices (classified as fixel classifies them), GPIO chips, and the
 * display fixel would open. Missing hardware is a "none found" line, never
 * an error: the tool is for finding out why a board shows nothing. */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/ioctl.h>
#include <unistd.h>
#include <linux/fb.h>

#include "fixel/cards.h"
#include "fixel/display.h"
#include "fixel/env.h"
#include "fixel/input.h"
#include "fixel/memfb.h"
#include "fixel/scanout.h"

#ifndef FX_BOARD_BACKEND
#define FX_BOARD_BACKEND "auto" /* as boards/display/display.c */
#endif

/* A display device exists that this user may not open: the reason to give
 * when fixel falls back to memory. */
static int display_denied;

#ifdef FX_INFO_HAVE_OPT
#include <gpiod.h>
#include <libevdev/libevdev.h>
#include <xf86drm.h>
#include <xf86drmMode.h>
#endif

/* Sorted device nodes of dir whose names start with prefix. */
static int list_nodes(const char *dir, const char *prefix, char names[][64], int max)
{
    DIR *d = opendir(dir);
    int n = 0;
    if (!d) return 0;
    struct dirent *e;
    while ((e = readdir(d)) && n < max)
        if (!strncmp(e->d_name, prefix, strlen(prefix)) && strlen(e->d_name) < 64)
            snprintf(names[n++], 64, "%s", e->d_name);
    closedir(d);
    /* natural order: card0 < card1 < card10 */
    for (int i = 1; i < n; i++)
        for (int j = i; j > 0; j--) {
            size_t a = strlen(names[j - 1]), b = strlen(names[j]);
            if (a > b || (a == b && strcmp(names[j - 1], names[j]) > 0)) {
                char t[64];
                memcpy(t, names[j], 64);
                memcpy(names[j], names[j - 1], 64);
                memcpy(names[j - 1], t, 64);
            } else break;
        }
    return n;
}

__attribute__((unused)) /* only the DRM and fbdev sections use it */
static void fourcc(uint32_t f, char out[5])
{
    for (int i = 0; i < 4; i++) {
        char c = (char)(f >> (8 * i));
        out[i] = c >= 32 && c < 127 ? c : '?';
    }
    out[4] = 0;
}

#ifdef FX_INFO_HAVE_OPT
/* An enum property's current value by name ("DPMS", "panel orientation"),
 * NULL when the object lacks it. */
static const char *enum_prop(int fd, uint32_t obj, uint32_t type, const char *want, char *out, size_t n)
{
    const char *r = NULL;
    drmModeObjectPropertiesPtr props = drmModeObjectGetProperties(fd, obj, type);
    for (uint32_t k = 0; props && k < props->count_props && !r; k++) {
        drmModePropertyPtr pr = drmModeGetProperty(fd, props->props[k]);
        if (pr && !strcmp(pr->name, want) && (pr->flags & DRM_MODE_PROP_ENUM)) {
            snprintf(out, n, "?%llu", (unsigned long long)props->prop_values[k]);
            for (int e = 0; e < pr->count_enums; e++)
                if (pr->enums[e].value == props->prop_values[k])
                    snprintf(out, n, "%s", pr->enums[e].name);
            r = out;
        }
        drmModeFreeProperty(pr);
    }
    drmModeFreeObjectProperties(props);
    return r;
}

/* The monitor name descriptor (tag 0xFC) of the connector's EDID. */
static const char *edid_name(int fd, uint32_t conn, char *out, size_t n)
{
    const char *r = NULL;
    drmModeObjectPropertiesPtr props = drmModeObjectGetProperties(fd, conn, DRM_MODE_OBJECT_CONNECTOR);
    for (uint32_t k = 0; props && k < props->count_props && !r; k++) {
        drmModePropertyPtr pr = drmModeGetProperty(fd, props->props[k]);
        if (pr && !strcmp(pr->name, "EDID") && (pr->flags & DRM_MODE_PROP_BLOB) && props->prop_values[k]) {
            drmModePropertyBlobPtr b = drmModeGetPropertyBlob(fd, (uint32_t)props->prop_values[k]);
            const unsigned char *e = b ? b->data : NULL;
            for (int d = 54; e && b->length >= 128 && d <= 108 && !r; d += 18)
                if (!e[d] && !e[d + 1] && !e[d + 2] && e[d + 3] == 0xFC) {
                    size_t l = 0;
                    while (l < 13 && e[d + 5 + l] != 0x0A && e[d + 5 + l] >= 32 && e[d + 5 + l] < 127)
                        l++;
                    snprintf(out, n, "%.*s", (int)l, (const char *)e + d + 5);
                    r = out;
                }
            drmModeFreePropertyBlob(b);
        }
        drmModeFreeProperty(pr);
    }
    drmModeFreeObjectProperties(props);
    return r;
}

/* A plane's type and rotation property ("rotate-0 rotate-180", or "none"). */
static void plane_props(int fd, uint32_t plane, const char **type, char *rot, size_t n)
{
    static const char *const types[] = {"overlay", "primary", "cursor"};
    *type = "?";
    snprintf(rot, n, "none");
    drmModeObjectPropertiesPtr props = drmModeObjectGetProperties(fd, plane, DRM_MODE_OBJECT_PLANE);
    for (uint32_t k = 0; props && k < props->count_props; k++) {
        drmModePropertyPtr pr = drmModeGetProperty(fd, props->props[k]);
        if (pr && !strcmp(pr->name, "type") && props->prop_values[k] < 3)
            *type = types[props->prop_values[k]];
        if (pr && !strcmp(pr->name, "rotation") && (pr->flags & DRM_MODE_PROP_BITMASK)) {
            size_t at = 0;
            rot[0] = 0;
            for (int e = 0; e < pr->count_enums && at + 1 < n; e++) {
                int w = snprintf(rot + at, n - at, "%s%s", at ? "|" : "", pr->enums[e].name);
                at += w > 0 ? (size_t)w : 0;
            }
        }
        drmModeFreeProperty(pr);
    }
    drmModeFreeObjectProperties(props);
}
#endif

static void drm_section(void)
{
    char names[32][64];
    printf("DRM cards (/dev/dri):\n");
    int n = list_nodes("/dev/dri", "card", names, 32);
    if (n == 0) { printf("  none found\n"); return; }
#ifdef FX_INFO_HAVE_OPT
    /* driver and by-path names as fixel matches them (FIXEL_DRM_DEVICE) */
    static fx_card_desc cards[FX_CARDS_MAX];
    int ncards = fx_drm_cards(cards, FX_CARDS_MAX);
    for (int i = 0; i < n; i++) {
        char path[128];
        snprintf(path, sizeof path, "/dev/dri/%.63s", names[i]);
        const fx_card_desc *cd = NULL;
        for (int k = 0; k < ncards; k++)
            if (!strcmp(cards[k].path, path)) cd = &cards[k];
        int fd = open(path, O_RDWR | O_CLOEXEC);
        if (fd < 0) {
            display_denied |= errno == EACCES;
            printf("  %s: cannot open (%s)%s\n", path, strerror(errno),
                   errno == EACCES ? " - add the user to group video" : "");
            continue;
        }
        drmVersionPtr v = drmGetVersion(fd);
        printf("  %s: driver %s (%s), by-path %s\n", path, v ? v->name : "?", v ? v->desc : "?",
               cd && cd->path_name[0] ? cd->path_name : "unknown");
        if (v && cd && cd->path_name[0])
            printf("    named by FIXEL_DRM_DEVICE=%s or %s or %s\n", v->name, cd->path_name, names[i]);
        if (v) drmFreeVersion(v);
        uint64_t dumb = 0;
        drmGetCap(fd, DRM_CAP_DUMB_BUFFER, &dumb);
        printf("    dumb buffers: %s\n", dumb ? "yes" : "no (fixel cannot draw here)");
        drmSetClientCap(fd, DRM_CLIENT_CAP_UNIVERSAL_PLANES, 1);
        drmModeResPtr r = drmModeGetResources(fd);
        if (!r) { printf("    no KMS resources (a render-only GPU?)\n"); close(fd); continue; }
        for (int c = 0; c < r->count_connectors; c++) {
            drmModeConnectorPtr con = drmModeGetConnector(fd, r->connectors[c]);
            if (!con) continue;
            const char *st = con->connection == DRM_MODE_CONNECTED ? "connected"
                           : con->connection == DRM_MODE_DISCONNECTED ? "disconnected" : "unknown";
            printf("    connector %u %s-%u: %s, %d modes", con->connector_id,
                   drmModeGetConnectorTypeName(con->connector_type) ? drmModeGetConnectorTypeName(con->connector_type) : "?",
                   con->connector_type_id, st, con->count_modes);
            for (int m = 0; m < con->count_modes; m++)
                if (con->modes[m].type & DRM_MODE_TYPE_PREFERRED) {
                    printf(", preferred %ux%u@%u", con->modes[m].hdisplay, con->modes[m].vdisplay, con->modes[m].vrefresh);
                    break;
                }
            char pv[64];
            if (edid_name(fd, con->connector_id, pv, sizeof pv)) printf(", monitor \"%s\"", pv);
            if (enum_prop(fd, con->connector_id, DRM_MODE_OBJECT_CONNECTOR, "DPMS", pv, sizeof pv))
                printf(", DPMS %s", pv);
            printf(", panel orientation %s\n",
                   enum_prop(fd, con->connector_id, DRM_MODE_OBJECT_CONNECTOR, "panel orientation", pv, sizeof pv)
                       ? pv : "not given");
            for (int m = 0; m < con->count_modes && m < 12; m++)
                printf("      %s %ux%u@%u%s\n", con->modes[m].name, con->modes[m].hdisplay, con->modes[m].vdisplay,
                       con->modes[m].vrefresh, con->modes[m].type & DRM_MODE_TYPE_PREFERRED ? " preferred" : "");
            if (con->count_modes > 12) printf("      ... %d more\n", con->count_modes - 12);
            drmModeFreeConnector(con);
        }
        for (int c = 0; c < r->count_crtcs; c++) {
            drmModeCrtcPtr cr = drmModeGetCrtc(fd, r->crtcs[c]);
            if (!cr) continue;
            if (cr->mode_valid) printf("    crtc %u: %ux%u, fb %u\n", cr->crtc_id, cr->mode.hdisplay, cr->mode.vdisplay, cr->buffer_id);
            else printf("    crtc %u: off\n", cr->crtc_id);
            drmModeFreeCrtc(cr);
        }
        drmModePlaneResPtr pr = drmModeGetPlaneResources(fd);
        for (uint32_t p = 0; pr && p < pr->count_planes; p++) {
            drmModePlanePtr pl = drmModeGetPlane(fd, pr->planes[p]);
            if (!pl) continue;
            const char *ptype;
            char rot[160];
            plane_props(fd, pl->plane_id, &ptype, rot, sizeof rot);
            printf("    plane %u: %s, crtcs 0x%x, rotation %s, formats", pl->plane_id, ptype, pl->possible_crtcs, rot);
            for (uint32_t f = 0; f < pl->count_formats; f++) {
                char cc[5];
                fourcc(pl->formats[f], cc);
                printf(" %s", cc);
            }
            printf("\n");
            drmModeFreePlane(pl);
        }
        if (pr) drmModeFreePlaneResources(pr);
        drmModeFreeResources(r);
        close(fd);
    }
#else
    for (int i = 0; i < n; i++) printf("  /dev/dri/%s (built without libdrm: no details)\n", names[i]);
#endif
}

static void fbdev_section(void)
{
    char names[32][64];
    printf("fbdev devices (/dev/fb*):\n");
    int n = list_nodes("/dev", "fb", names, 32), shown = 0;
    for (int i = 0; i < n; i++) {
        char path[128];
        if (names[i][2] < '0' || names[i][2] > '9') continue;
        snprintf(path, sizeof path, "/dev/%.63s", names[i]);
        shown++;
        int fd = open(path, O_RDONLY | O_CLOEXEC);
        if (fd < 0) {
            display_denied |= errno == EACCES;
            printf("  %s: cannot open (%s)%s\n", path, strerror(errno), errno == EACCES ? " - add the user to group video" : "");
            continue;
        }
        struct fb_var_screeninfo v;
        struct fb_fix_screeninfo f;
        if (ioctl(fd, FBIOGET_VSCREENINFO, &v) < 0 || ioctl(fd, FBIOGET_FSCREENINFO, &f) < 0) {
            printf("  %s: not a framebuffer (%s)\n", path, strerror(errno));
            close(fd);
            continue;
        }
        fx_fb_bitfields b = {v.bits_per_pixel, v.grayscale, v.red.offset, v.red.length, v.green.offset,
                             v.green.length, v.blue.offset, v.blue.length, v.transp.offset, v.transp.length,
                             f.visual == FB_VISUAL_MONO01};
        fx_format fmt = fx_fb_format_from_bitfields(&b);
        const fx_format_info *fi = fmt < FX_FMT_COUNT ? fx_format_get(fmt) : NULL;
        printf("  %s: %s, %ux%u (virtual %ux%u), %u bpp, stride %u, r%u:%u g%u:%u b%u:%u a%u:%u -> %s\n", path,
               f.id, v.xres, v.yres, v.xres_virtual, v.yres_virtual, v.bits_per_pixel, f.line_length, v.red.offset,
               v.red.length, v.green.offset, v.green.length, v.blue.offset, v.blue.length, v.transp.offset,
               v.transp.length, fi ? fi->name : "no fixel format");
        close(fd);
    }
    if (!shown) printf("  none found\n");
}

static void input_section(void)
{
    char names[64][64];
    printf("input devices (/dev/input):\n");
    int n = list_nodes("/dev/input", "event", names, 64);
    if (n == 0) { printf("  none found\n"); return; }
#ifdef FX_INFO_HAVE_OPT
    for (int i = 0; i < n; i++) {
        char path[128];
        snprintf(path, sizeof path, "/dev/input/%.63s", names[i]);
        int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
        struct libevdev *d = NULL;
        if (fd < 0 || libevdev_new_from_fd(fd, &d) < 0) {
            printf("  %s: cannot open (%s)%s\n", path, strerror(errno), errno == EACCES ? " - add the user to group input" : "");
            if (fd >= 0) close(fd);
            continue;
        }
        /* the same tests as boards/linux/input/evdev.c classify() */
        unsigned cls = 0;
        if (libevdev_has_event_code(d, EV_KEY, KEY_A) || libevdev_has_event_code(d, EV_KEY, KEY_ENTER) ||
            libevdev_has_event_code(d, EV_KEY, KEY_UP))
            cls |= FX_DEV_KEYBOARD;
        if (libevdev_has_event_code(d, EV_REL, REL_X) && libevdev_has_event_code(d, EV_REL, REL_Y)) cls |= FX_DEV_MOUSE;
        int direct = libevdev_has_property(d, INPUT_PROP_DIRECT);
        if (libevdev_has_event_code(d, EV_ABS, ABS_X) && libevdev_has_event_code(d, EV_ABS, ABS_Y)) {
            if (libevdev_has_event_code(d, EV_KEY, BTN_TOOL_PEN)) cls |= FX_DEV_TABLET;
            else if (direct || libevdev_has_event_code(d, EV_KEY, BTN_TOUCH)) cls |= FX_DEV_TOUCH;
            else cls |= FX_DEV_TABLET;
        }
        if (libevdev_has_event_code(d, EV_ABS, ABS_MT_SLOT) && libevdev_has_event_code(d, EV_ABS, ABS_MT_POSITION_X))
            cls |= FX_DEV_MT | (direct ? FX_DEV_TOUCH : 0u);
        printf("  %s: \"%s\":%s%s%s%s%s%s\n", path, libevdev_get_name(d), cls & FX_DEV_KEYBOARD ? " keyboard" : "",
               cls & FX_DEV_MOUSE ? " mouse" : "", cls & FX_DEV_TOUCH ? " touchscreen" : "",
               cls & FX_DEV_MT ? " multitouch" : "", cls & FX_DEV_TABLET ? " tablet" : "",
               cls ? "" : " ignored by fixel");
        libevdev_free(d);
        close(fd);
    }
#else
    for (int i = 0; i < n; i++) printf("  /dev/input/%s (built without libevdev: no details)\n", names[i]);
#endif
}

static void gpio_section(void)
{
    printf("GPIO chips:\n");
#ifdef FX_INFO_HAVE_OPT
    char names[32][64];
    int n = list_nodes("/dev", "gpiochip", names, 32);
    if (n == 0) { printf("  none found\n"); return; }
    for (int i = 0; i < n; i++) {
        struct gpiod_chip *c = gpiod_chip_open_by_name(names[i]);
        if (!c) {
            printf("  /dev/%s: cannot open (%s)%s\n", names[i], strerror(errno), errno == EACCES ? " - add the user to group gpio" : "");
            continue;
        }
        unsigned nl = gpiod_chip_num_lines(c);
        printf("  /dev/%s: %s, %u lines\n", gpiod_chip_name(c), gpiod_chip_label(c), nl);
        for (unsigned l = 0; l < nl; l++) {
            struct gpiod_line *line = gpiod_chip_get_line(c, l);
            if (!line) continue;
            const char *nm = gpiod_line_name(line), *cons = gpiod_line_consumer(line);
            printf("    %3u %-20s %s%s%s%s\n", l, nm ? nm : "-",
                   gpiod_line_direction(line) == GPIOD_LINE_DIRECTION_OUTPUT ? "output" : "input",
                   gpiod_line_active_state(line) == GPIOD_LINE_ACTIVE_STATE_LOW ? " active-low" : "",
                   gpiod_line_is_used(line) ? " used by " : "", gpiod_line_is_used(line) && cons ? cons : "");
        }
        gpiod_chip_close(c);
    }
#else
    printf("  (built without libgpiod)\n");
#endif
}

static int choice_section(void)
{
    printf("fixel's choice (FX_BACKEND_AUTO: FIXEL_BACKEND, else DRM, fbdev, memory):\n");
    int nvars;
    const fx_env_var *vars = fx_env_table(&nvars);
    for (int i = 0; i < nvars; i++)
        if (!strcmp(vars[i].who, "library") && getenv(vars[i].name))
            printf("  %s=%.200s\n", vars[i].name, getenv(vars[i].name));
    fx_display_options o;
    fx_display_options_init(&o);
    o.console = 0; /* only looking: leave the VT and its keyboard alone */
    o.signals = 0;
    fx_display *d = NULL;
    fflush(stdout);
    if (fx_display_options_from_env(&o) < 0 || fx_display_open(&d, &o) < 0) {
        printf("  nothing opened (the reasons are logged above on stderr)\n");
        if (display_denied)
            printf("  why: permission denied on the display devices listed above\n");
        /* The automatic order always ends in memory: this is a display
         * asked for (FIXEL_BACKEND, the board profile) that is not there. */
        return 1;
    }
    fx_display_info in;
    fx_display_get_info(d, &in);
    const fx_format_info *fi = fx_format_get(in.format);
    printf("  backend %s, device \"%s\"%s%s, %dx%d", fx_backend_name(in.backend),
           in.backend == FX_BACKEND_MEMORY ? "" : in.device,
           in.connector[0] ? ", connector " : "", in.connector, in.width, in.height);
    if (in.refresh_mhz) printf("@%d.%03d", in.refresh_mhz / 1000, in.refresh_mhz % 1000);
    printf(", %s, %d buffer%s, rotation %d\n", fi ? fi->name : "?", in.buffers, in.buffers == 1 ? "" : "s", in.rotation);
#ifdef FX_INFO_HAVE_OPT
    if (in.backend == FX_BACKEND_DRM) {
        static fx_card_desc cards[FX_CARDS_MAX];
        int nc = fx_drm_cards(cards, FX_CARDS_MAX);
        for (int k = 0; k < nc; k++)
            if (!strcmp(cards[k].path, in.device))
                printf("  card %s: driver %s, by-path %s; by name: FIXEL_CONNECTOR=%s:%s\n", cards[k].path,
                       cards[k].driver[0] ? cards[k].driver : "?", cards[k].path_name[0] ? cards[k].path_name : "unknown",
                       cards[k].path_name[0] ? cards[k].path_name : cards[k].path + 9, in.connector);
    }
#endif
    const char *forced = getenv("FIXEL_BACKEND");
    if (forced && *forced && strcasecmp(forced, "auto"))
        printf("  why: FIXEL_BACKEND=%s asks for it\n", forced);
    else if (strcasecmp(FX_BOARD_BACKEND, "auto"))
        printf("  why: the board profile's default backend (%s)\n", FX_BOARD_BACKEND);
    else if (in.backend == FX_BACKEND_MEMORY && display_denied)
        printf("  why: permission denied on the display devices listed above (add the user to group video), "
               "so programs draw into memory (headless)\n");
    else if (in.backend == FX_BACKEND_MEMORY)
        printf("  why: no usable DRM card or fbdev device here, so programs draw into memory (headless)\n");
    else if (in.backend == FX_BACKEND_FBDEV)
        printf("  why: no DRM card with a connected connector and dumb buffers; fbdev works\n");
    else if (getenv("FIXEL_CONNECTOR") && *getenv("FIXEL_CONNECTOR"))
        printf("  why: FIXEL_CONNECTOR=%s names it\n", getenv("FIXEL_CONNECTOR"));
    else if (getenv("FIXEL_DRM_DEVICE") && *getenv("FIXEL_DRM_DEVICE"))
        printf("  why: FIXEL_DRM_DEVICE=%s names the card, its first connected connector\n", getenv("FIXEL_DRM_DEVICE"));
    else
        printf("  why: a DRM card with a connected connector (preferred over fbdev)\n");
    fx_display_close(d);
    return 0;
}

/* Every FIXEL_* variable from the one table (fixel/env.h): name, who reads
 * it, what it accepts, its value here and whether that value is taken. A
 * tab-separated line each, so tests and README.md's table can follow it. */
static int env_section(void)
{
    int n;
    const fx_env_var *v = fx_env_table(&n);
    printf("variable\tread by\taccepts\tmeaning\tset here\n");
    for (int i = 0; i < n; i++) {
        char want[200];
        fx_env_expect(&v[i], want, sizeof want);
        const char *e = getenv(v[i].name);
        long val;
        char msg[256];
        int r = fx_env_get(v[i].name, &val, msg, sizeof msg);
        printf("%s\t%s\t%s\t%s\t%s\n", v[i].name, v[i].who, want, v[i].meaning,
               !e || !*e ? "-" : r < 0 && v[i].kind <= FX_ENV_INT ? "not taken" : "taken");
    }
    return 0;
}

int main(int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--env"))
            return env_section();
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            printf("usage: fixel-info [--env]\n"
                   "Lists DRM cards (driver, by-path name, connectors with status, modes, preferred\n"
                   "mode, monitor name, DPMS and panel orientation, CRTCs, planes with rotations and\n"
                   "formats), fbdev\n"
                   "devices and their pixel formats, input devices as fixel classifies them, GPIO\n"
                   "chips and lines, and the display fixel would open here and why.\n"
                   "Missing hardware prints \"none found\"; the exit status is 0 unless an option is\n"
                   "wrong (2) or the display asked for (FIXEL_BACKEND=drm|fbdev) cannot open (1).\n"
                   "--env lists every FIXEL_* variable fixel reads, what it accepts and\n"
                   "whether its value here is taken.\n");
            return 0;
        }
        fprintf(stderr, "fixel-info: unknown argument %s (try --help)\n", argv[i]);
        return 2;
    }
    /* first, before sections that would only say "none found" */
    const char *without = fx_built_without();
    if (*without) {
        /* the library names fx_built_without gives, and their Debian packages */
        static const char *const pkgs[][2] = {
            {"libdrm", "libdrm-dev libevdev-dev libgpiod-dev"},
            {"libpng", "libpng-dev zlib1g-dev"},
            {"FreeType", "libfreetype-dev libharfbuzz-dev libfribidi-dev libfontconfig-dev libunibreak-dev"},
            {"libjpeg", "libjpeg62-turbo-dev"},
            {"giflib", "libgif-dev"},
            {"libwebp", "libwebp-dev"},
        };
        printf("fixel-info: this fixel was built without %s\n  (install", without);
        for (size_t i = 0; i < sizeof pkgs / sizeof pkgs[0]; i++)
            if (strstr(without, pkgs[i][0]))
                printf(" %s", pkgs[i][1]);
        printf(" and run make again)\n");
    }
    drm_section();
    fbdev_section();
    input_section();
    gpio_section();
    return choice_section();
}
