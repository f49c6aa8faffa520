/* SPDX-License-Identifier: MIT */
/* fbdev backend: format from the bitfields, stride from line_length, the
 * whole smem mapped once. Double buffering by panning where the driver
 * offers a virtual height of two screens; vsync waits that cannot hang the
 * program; FB_ACTIVATE_FORCE for drivers that only refresh on a mode set. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <errno.h>
#include <fcntl.h>
#include <linux/fb.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <unistd.h>

#include "../../display/display_int.h"
#include "fixel/error.h"

/* Longer than any real frame (10 Hz panels included): a wait that takes
 * this long means the driver never signals vblank. */
#define VSYNC_TIMEOUT_MS 150

struct fb_priv {
    int fd;
    struct fb_var_screeninfo var, saved;
    struct fb_fix_screeninfo fix;
    uint8_t *map;
    size_t map_len;
    int vsync;       /* 1: try FBIO_WAITFORVSYNC, 0: unsupported or never signals */
    fx_waiter *vsync_waiter;
    int vsync_stuck; /* its call timed out and may still be inside the driver */
    int restore_var; /* we changed the virtual size or the pan offset */
};

static int vsync_call(void *arg)
{
    struct fb_priv *p = arg;
    uint32_t crtc = 0;
    return ioctl(p->fd, FBIO_WAITFORVSYNC, &crtc) < 0 ? -errno : 0;
}

static void wait_vsync(fx_display *d, struct fb_priv *p)
{
    int result = 0;
    if (!p->vsync)
        return;
    if (!p->vsync_waiter && fx_waiter_create(&p->vsync_waiter, vsync_call, p) < 0) {
        p->vsync = 0;
        return;
    }
    if (fx_waiter_run(p->vsync_waiter, VSYNC_TIMEOUT_MS, &result) != 0) {
        fx_log(&d->log, FX_LOG_INFO, "FBIO_WAITFORVSYNC did not return within %d ms; "
                       "presenting without waiting for vsync", VSYNC_TIMEOUT_MS);
        p->vsync = 0;
        p->vsync_stuck = 1;
    } else if (result < 0) {
        fx_log(&d->log, FX_LOG_DEBUG, "FBIO_WAITFORVSYNC unsupported (%s)", strerror(-result));
        p->vsync = 0;
    }
}

static int fb_show(fx_display *d, int buf, const fx_rect *phys, int n)
{
    struct fb_priv *p = d->priv;
    (void)phys, (void)n;
    if (d->nbuf == 2 && buf != d->shown) {
        struct fb_var_screeninfo v = p->var;
        v.xoffset = 0;
        v.yoffset = (uint32_t)buf * p->var.yres;
        /* Pan at the next vblank: wait first so the old page stops being
         * scanned out before the program draws into it. */
        wait_vsync(d, p);
        if (ioctl(p->fd, FBIOPAN_DISPLAY, &v) < 0) {
            int e = errno;
            fx_log(&d->log, FX_LOG_ERROR, "FBIOPAN_DISPLAY failed: %s", strerror(e));
            return -e;
        }
        p->var.yoffset = v.yoffset;
        p->restore_var = 1;
    }
    if (d->opt.fb_force_refresh) {
        struct fb_var_screeninfo v = p->var;
        v.activate = FB_ACTIVATE_NOW | FB_ACTIVATE_FORCE;
        if (ioctl(p->fd, FBIOPUT_VSCREENINFO, &v) < 0)
            fx_log(&d->log, FX_LOG_DEBUG, "FB_ACTIVATE_FORCE refused: %s", strerror(errno));
    }
    return 0;
}

static int fb_wait(fx_display *d, int t) { (void)d, (void)t; return 0; }
static int fb_dispatch(fx_display *d) { (void)d; return 0; }
static int fb_fd(const fx_display *d) { (void)d; return -1; }

static void fb_close(fx_display *d)
{
    struct fb_priv *p = d->priv;
    if (!p)
        return;
    if (p->restore_var) {
        p->saved.activate = FB_ACTIVATE_NOW;
        ioctl(p->fd, FBIOPUT_VSCREENINFO, &p->saved);
        ioctl(p->fd, FBIOPAN_DISPLAY, &p->saved);
    }
    if (p->map)
        munmap(p->map, p->map_len);
    fx_waiter_destroy(p->vsync_waiter);
    if (p->vsync_stuck) {
        /* The stuck call still uses p and its fd: leave both to it. */
        d->priv = NULL;
        return;
    }
    if (p->fd >= 0)
        close(p->fd);
    free(p);
    d->priv = NULL;
}

static int fb_resume(fx_display *d)
{
    struct fb_priv *p = d->priv;
    /* The console may have panned; put our shown page back. */
    if (d->nbuf == 2) {
        struct fb_var_screeninfo v = p->var;
        v.xoffset = 0;
        v.yoffset = (uint32_t)(d->shown < 0 ? 0 : d->shown) * p->var.yres;
        if (ioctl(p->fd, FBIOPAN_DISPLAY, &v) < 0)
            return -errno;
    }
    /* The console unblanks the screen it takes; switched off before the
     * VT switch means off after it. */
    if (d->power_off && ioctl(p->fd, FBIOBLANK, FB_BLANK_POWERDOWN) < 0)
        return -errno;
    return 0;
}

/* POWERDOWN rather than NORMAL: drivers that can, cut the signal (the
 * monitor sleeps); the others at least blank. */
static int fb_set_power(fx_display *d, int on)
{
    struct fb_priv *p = d->priv;
    return ioctl(p->fd, FBIOBLANK, on ? FB_BLANK_UNBLANK : FB_BLANK_POWERDOWN) < 0 ? -errno : 0;
}

/* The signal path: a crash while the screen is off must not leave the
 * console dark (fx_display_close unblanks on the way out too). */
static void fb_emergency_restore(fx_display *d)
{
    struct fb_priv *p = d->priv;
    if (p && p->fd >= 0 && d->power_off)
        ioctl(p->fd, FBIOBLANK, FB_BLANK_UNBLANK);
}

static const struct fx_backend_ops fb_ops = {fb_show, fb_wait, fb_dispatch, fb_fd, fb_close, NULL,
                                             fb_resume, NULL, fb_emergency_restore, fb_set_power};

static int try_double_buffer(struct fb_priv *p)
{
    size_t page = (size_t)p->fix.line_length * p->var.yres;
    if (p->fix.ypanstep == 0 || p->fix.smem_len < 2 * page)
        return 0;
    if (p->var.yres_virtual < 2 * p->var.yres) {
        struct fb_var_screeninfo v = p->var;
        v.yres_virtual = 2 * p->var.yres;
        v.activate = FB_ACTIVATE_NOW;
        if (ioctl(p->fd, FBIOPUT_VSCREENINFO, &v) < 0 ||
            ioctl(p->fd, FBIOGET_VSCREENINFO, &v) < 0 || v.yres_virtual < 2 * p->var.yres)
            return 0;
        p->restore_var = 1;
        p->var = v;
        /* The virtual resize may change the stride. */
        if (ioctl(p->fd, FBIOGET_FSCREENINFO, &p->fix) < 0)
            return 0;
    }
    struct fb_var_screeninfo v = p->var;
    v.xoffset = 0;
    v.yoffset = 0;
    if (ioctl(p->fd, FBIOPAN_DISPLAY, &v) < 0)
        return 0;
    p->var.xoffset = p->var.yoffset = 0;
    p->restore_var = 1;
    return 1;
}

int fx_fbdev_open(fx_display *d)
{
    const char *path = d->opt.device;
    if (path && (path[0] != '/' || !strstr(path, "fb")))
        path = NULL; /* a /dev/dri/cardN device or a card name is for the DRM backend */
    if (!path)
        path = d->opt.fb_device;
    if (!path || !*path)
        path = "/dev/fb0";
    snprintf(d->device, sizeof d->device, "%s", path);

    int fd = open(path, O_RDWR | O_CLOEXEC);
    if (fd < 0) {
        int e = errno;
        if (e == EACCES || e == EPERM)
            fx_log_access_hint(&d->log, path);
        else
            fx_log(&d->log, FX_LOG_DEBUG, "%s: %s", path, strerror(e));
        return -e;
    }
    struct fb_priv *p = calloc(1, sizeof *p);
    if (!p) {
        close(fd);
        return -FX_ENOMEM;
    }
    p->fd = fd;
    p->vsync = 1;
    d->priv = p;
    d->ops = &fb_ops;
    d->power_method = "fbblank";

    if (ioctl(fd, FBIOGET_VSCREENINFO, &p->var) < 0 || ioctl(fd, FBIOGET_FSCREENINFO, &p->fix) < 0) {
        int e = errno;
        fx_log(&d->log, FX_LOG_ERROR, "%s: not a framebuffer: %s", path, strerror(e));
        return -e;
    }
    p->saved = p->var;
    if (p->fix.type != FB_TYPE_PACKED_PIXELS) {
        fx_log(&d->log, FX_LOG_ERROR, "%s: framebuffer type %u is not packed pixels", path,
                       p->fix.type);
        return -FX_ENOTSUP;
    }
    fx_fb_bitfields bf = {
        .bits_per_pixel = p->var.bits_per_pixel, .grayscale = p->var.grayscale == 1,
        .red_offset = p->var.red.offset, .red_length = p->var.red.length,
        .green_offset = p->var.green.offset, .green_length = p->var.green.length,
        .blue_offset = p->var.blue.offset, .blue_length = p->var.blue.length,
        .transp_offset = p->var.transp.offset, .transp_length = p->var.transp.length,
        .mono_inverted = p->fix.visual == FB_VISUAL_MONO01,
    };
    fx_format f = fx_fb_format_from_bitfields(&bf);
    if (f == FX_FMT_COUNT) {
        fx_log(&d->log, FX_LOG_ERROR,
                       "%s: unsupported pixel layout %u bpp r%u/%u g%u/%u b%u/%u gray %u visual %u",
                       path, bf.bits_per_pixel, bf.red_offset, bf.red_length, bf.green_offset,
                       bf.green_length, bf.blue_offset, bf.blue_length, p->var.grayscale,
                       p->fix.visual);
        return -FX_ENOTSUP;
    }

    int dbl = try_double_buffer(p);
    p->map_len = p->fix.smem_len;
    p->map = mmap(NULL, p->map_len, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
    if (p->map == MAP_FAILED) {
        int e = errno;
        p->map = NULL;
        fx_log(&d->log, FX_LOG_ERROR, "%s: mmap of %zu bytes failed: %s", path, p->map_len, strerror(e));
        return -e;
    }

    int32_t w = (int32_t)p->var.xres, h = (int32_t)p->var.yres, stride = (int32_t)p->fix.line_length;
    uint32_t bpp = p->var.bits_per_pixel;
    /* Single-buffered: draw into the page currently shown, wherever the
     * console left the pan offset. */
    size_t first = dbl ? 0 : (size_t)p->var.yoffset * stride + (size_t)p->var.xoffset * bpp / 8;
    size_t need = first + (size_t)stride * (size_t)h * (dbl ? 2 : 1);
    if (need > p->map_len || fx_format_min_stride(f, w) > stride) {
        fx_log(&d->log, FX_LOG_ERROR, "%s: %dx%d stride %d does not fit smem_len %zu", path, w, h,
                       stride, p->map_len);
        return -FX_EINVAL;
    }
    for (int i = 0; i < (dbl ? 2 : 1); i++) {
        int r = fx_surface_init(&d->scan[i], p->map + first + (size_t)i * (size_t)h * stride, w, h,
                                stride, f);
        if (r < 0)
            return r;
        if (f == FX_FMT_MONO1)
            d->scan[i].bit_offset = (uint8_t)((p->var.xoffset * bpp) & 7);
        fx_surface_clear(&d->scan[i], 0xFF000000u);
    }
    d->nbuf = dbl ? 2 : 1;
    d->shown = 0;
    d->back = dbl ? 1 : 0;
    d->info.width = w;
    d->info.height = h;
    d->info.format = f;
    if (p->var.pixclock && p->var.xres && p->var.yres) {
        uint64_t ht = (uint64_t)p->var.xres + p->var.left_margin + p->var.right_margin + p->var.hsync_len;
        uint64_t vt = (uint64_t)p->var.yres + p->var.upper_margin + p->var.lower_margin + p->var.vsync_len;
        /* pixclock is in picoseconds per pixel. */
        d->info.refresh_mhz = (int32_t)(1000000000000000ull / ((uint64_t)p->var.pixclock * ht * vt));
    }
    return 0;
}
