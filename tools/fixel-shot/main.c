/* SPDX-License-Identifier: MIT */
/* fixel-shot — save what is on the screen to a PNG: the visible part of an
 * fbdev framebuffer, or the scanout buffer of a DRM CRTC when the driver
 * lets this process map it. */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include <linux/fb.h>

#include "fixel/memfb.h"
#include "fixel/surface.h"
#include "fixel/scanout.h"

#ifdef FX_SHOT_HAVE_DRM
#include <xf86drm.h>
#include <xf86drmMode.h>
#endif

static int save(const char *out, void *pixels, int32_t w, int32_t h, int32_t stride, fx_format f, const char *what)
{
    fx_surface s;
    if (fx_surface_init(&s, pixels, w, h, stride, f) < 0) {
        fprintf(stderr, "fixel-shot: %s: unusable layout %dx%d stride %d\n", what, w, h, stride);
        return 1;
    }
    int r = fx_write_image(out, &s);
    if (r < 0) {
        fprintf(stderr, "fixel-shot: cannot write %s: %s%s\n", out, strerror(-r), fx_built_without_hint(r));
        return 1;
    }
    printf("fixel-shot: %s %dx%d %s -> %s\n", what, w, h, fx_format_get(f)->name, out);
    return 0;
}

/* open(dev, flags | O_CLOEXEC); a failure is said on stderr, with the group
 * to join when it is a permission. */
static int open_device(const char *dev, int flags)
{
    /* O_NONBLOCK: a FIFO with no writer would block the open forever;
     * anything but a character device is refused before it is used. */
    int fd = open(dev, flags | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
    if (fd < 0) {
        fprintf(stderr, "fixel-shot: %s: %s%s\n", dev, strerror(errno),
                errno == EACCES ? " (add the user to group video)" : "");
        return -1;
    }
    struct stat st = {0};
    if (fstat(fd, &st) < 0 || !S_ISCHR(st.st_mode)) {
        fprintf(stderr, "fixel-shot: %s: not a device (%s)\n", dev,
                S_ISFIFO(st.st_mode) ? "a FIFO" : S_ISDIR(st.st_mode) ? "a directory"
                : S_ISREG(st.st_mode) ? "a regular file" : "not a character device");
        close(fd);
        return -1;
    }
    fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    return fd;
}

static int shot_fbdev(const char *dev, const char *out)
{
    int fd = open_device(dev, O_RDONLY);
    if (fd < 0)
        return 1;
    struct fb_var_screeninfo v;
    struct fb_fix_screeninfo fi;
    if (ioctl(fd, FBIOGET_VSCREENINFO, &v) < 0 || ioctl(fd, FBIOGET_FSCREENINFO, &fi) < 0) {
        fprintf(stderr, "fixel-shot: %s: not a framebuffer (%s)\n", dev, strerror(errno));
        close(fd);
        return 1;
    }
    fx_fb_bitfields b = {v.bits_per_pixel, v.grayscale, v.red.offset, v.red.length, v.green.offset,
                         v.green.length, v.blue.offset, v.blue.length, v.transp.offset, v.transp.length,
                         fi.visual == FB_VISUAL_MONO01};
    fx_format f = fx_fb_format_from_bitfields(&b);
    if (f == FX_FMT_COUNT) {
        fprintf(stderr, "fixel-shot: %s: pixel layout (%u bpp) has no fixel format\n", dev, v.bits_per_pixel);
        close(fd);
        return 1;
    }
    uint8_t *map = mmap(NULL, fi.smem_len, PROT_READ, MAP_SHARED, fd, 0);
    close(fd);
    if (map == MAP_FAILED) {
        fprintf(stderr, "fixel-shot: %s: mmap: %s\n", dev, strerror(errno));
        return 1;
    }
    /* the visible page starts at the pan offset */
    size_t off = (size_t)v.yoffset * fi.line_length + (size_t)v.xoffset * v.bits_per_pixel / 8;
    int rc;
    if (off + (size_t)v.yres * fi.line_length > fi.smem_len) {
        fprintf(stderr, "fixel-shot: %s: visible area lies outside the mapped memory\n", dev);
        rc = 1;
    } else
        rc = save(out, map + off, (int32_t)v.xres, (int32_t)v.yres, (int32_t)fi.line_length, f, dev);
    munmap(map, fi.smem_len);
    return rc;
}

#ifdef FX_SHOT_HAVE_DRM
/* shot_drm's result when it may not map the buffer and a program other than
 * the console owns the card: /dev/fb0 then holds the console's picture. */
enum { SHOT_DRM_OWNED = 3 };

static int shot_drm(const char *dev, const char *out)
{
    int fd = open_device(dev, O_RDWR);
    if (fd < 0)
        return 1;
    /* The first opener of a card nobody owns becomes its master; anyone
     * else is not, so this tells whether a program drives the screen. */
    int owned_by_other = !drmIsMaster(fd);
    drmModeResPtr r = drmModeGetResources(fd);
    int rc = 1, found = 0;
    for (int c = 0; r && c < r->count_crtcs && !found; c++) {
        drmModeCrtcPtr cr = drmModeGetCrtc(fd, r->crtcs[c]);
        if (!cr) continue;
        if (cr->mode_valid && cr->buffer_id) {
            found = 1;
            drmModeFB2Ptr fb = drmModeGetFB2(fd, cr->buffer_id);
            fx_format f = FX_FMT_COUNT;
            for (int k = 0; fb && k < FX_FMT_COUNT; k++)
                if (fx_format_get((fx_format)k)->drm_fourcc == fb->pixel_format && fb->pixel_format) f = (fx_format)k;
            if (!fb)
                fprintf(stderr, "fixel-shot: %s: crtc %u: cannot read framebuffer %u (%s)\n", dev, cr->crtc_id,
                        cr->buffer_id, strerror(errno));
            else if (!fb->handles[0]) {
                /* the kernel hands buffer handles only to root/the DRM master */
                fprintf(stderr, "fixel-shot: %s: not allowed to map the scanout buffer: run as root "
                                "(CAP_SYS_ADMIN)%s\n", dev, owned_by_other ? "" : ", or use the fbdev device");
                if (owned_by_other) rc = SHOT_DRM_OWNED;
            }
            else if (f == FX_FMT_COUNT || fb->modifier != 0) {
                char cc[5];
                for (int k = 0; k < 4; k++) {
                    char ch = (char)(fb->pixel_format >> (8 * k));
                    cc[k] = ch >= 32 && ch < 127 ? ch : '?';
                }
                cc[4] = 0;
                fprintf(stderr, "fixel-shot: %s: scanout format %s (modifier 0x%llx) is not supported: fixel reads "
                                "linear buffers in its own formats only\n", dev, cc, (unsigned long long)fb->modifier);
            }
            else {
                struct drm_mode_map_dumb md = {.handle = fb->handles[0]};
                size_t size = (size_t)fb->pitches[0] * fb->height + fb->offsets[0];
                void *map = MAP_FAILED;
                if (drmIoctl(fd, DRM_IOCTL_MODE_MAP_DUMB, &md) == 0)
                    map = mmap(NULL, size, PROT_READ, MAP_SHARED, fd, (off_t)md.offset);
                if (map == MAP_FAILED)
                    fprintf(stderr, "fixel-shot: %s: the driver does not let the scanout buffer be mapped (%s)\n",
                            dev, strerror(errno));
                else {
                    rc = save(out, (uint8_t *)map + fb->offsets[0], (int32_t)fb->width, (int32_t)fb->height,
                              (int32_t)fb->pitches[0], f, dev);
                    munmap(map, size);
                }
            }
            if (fb) drmModeFreeFB2(fb);
        }
        drmModeFreeCrtc(cr);
    }
    if (r && !found) fprintf(stderr, "fixel-shot: %s: no active CRTC (nothing on screen)\n", dev);
    if (!r) fprintf(stderr, "fixel-shot: %s: no KMS resources\n", dev);
    if (r) drmModeFreeResources(r);
    close(fd);
    return rc;
}
#endif

int main(int argc, char **argv)
{
    const char *dev = NULL, *out = "shot.png";
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            printf("usage: fixel-shot [-d /dev/fbN|/dev/dri/cardN] [-o OUT.png]\n"
                   "Save what is on the screen to a PNG (.ppm: PPM). Without -d: the first DRM card\n"
                   "with an active CRTC whose buffer can be mapped, else /dev/fb0. DRM needs root\n"
                   "(the kernel hides scanout buffers from other processes); fbdev needs group video.\n"
                   "Exit status: 0 saved, 1 no device or not allowed, 2 bad arguments.\n");
            return 0;
        } else if (!strcmp(argv[i], "-d") && i + 1 < argc) dev = argv[++i];
        else if (!strcmp(argv[i], "-o") && i + 1 < argc) out = argv[++i];
        else {
            fprintf(stderr, "fixel-shot: unknown argument %s (try --help)\n", argv[i]);
            return 2;
        }
    }
    if (dev) {
        if (!strncmp(dev, "/dev/dri/", 9)) {
#ifdef FX_SHOT_HAVE_DRM
            return shot_drm(dev, out) ? 1 : 0;
#else
            fprintf(stderr, "fixel-shot: built without libdrm\n");
            return 1;
#endif
        }
        return shot_fbdev(dev, out);
    }
#ifdef FX_SHOT_HAVE_DRM
    for (int i = 0; i < 16; i++) {
        char p[32];
        snprintf(p, sizeof p, "/dev/dri/card%d", i);
        if (access(p, F_OK) == 0) {
            int r = shot_drm(p, out);
            if (r == 0) return 0;
            if (r == SHOT_DRM_OWNED) {
                fprintf(stderr, "fixel-shot: another program owns the display through %s; /dev/fb0 holds the "
                                "console's picture, not what is on screen, so it is not saved instead\n", p);
                return 1;
            }
        }
    }
#endif
    if (access("/dev/fb0", F_OK) != 0) {
        fprintf(stderr, "fixel-shot: no display device here (no usable /dev/dri/card*, no /dev/fb0)\n");
        return 1;
    }
    return shot_fbdev("/dev/fb0", out);
}
