/* SPDX-License-Identifier: MIT */
/* libdrm helpers of the guest programs that query cards apart from the
 * library (kms.c, outputs.c). Header-only, like guest.h. */
#ifndef FIXEL_GUEST_DRM_H
#define FIXEL_GUEST_DRM_H

#include <fcntl.h>
#include <stdio.h>
#include <unistd.h>

#include <xf86drm.h>

/* The DRM driver name of a card node ("?" when it cannot be read). */
static const char *guest_drm_driver(const char *dev, char *out, size_t n) __attribute__((unused));
static const char *guest_drm_driver(const char *dev, char *out, size_t n)
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

#endif
