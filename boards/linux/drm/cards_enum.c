/* SPDX-License-Identifier: MIT */
/* fx_drm_cards: what each /dev/dri/cardN is (driver, udev by-path name,
 * connectors), read with libdrm and sysfs, for the choice in
 * boards/linux/display/cards.c and for fixel-info. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <xf86drm.h>
#include <xf86drmMode.h>

#include "fixel/cards.h"

/* The name udev's path_id builtin gives the card (its /dev/dri/by-path link
 * without "-card"), computed from sysfs because small systems run without
 * udev: walking from the device to the root, every pci, platform or amba
 * ancestor adds "<subsystem>-<name>", runs of the same subsystem counting
 * once (their nearest member names them); other buses (virtio) add nothing.
 * So x86 bochs is "pci-0000:00:02.0" and a Pi 4's vc4 "platform-gpu". */
static void by_path_name(int minor, char *out, size_t n)
{
    char link[64], dev[PATH_MAX];
    out[0] = 0;
    snprintf(link, sizeof link, "/sys/class/drm/card%d/device", minor);
    if (!realpath(link, dev))
        return;
    char name[160] = "";
    const char *last = "";
    for (;;) {
        char *slash = strrchr(dev, '/');
        if (!slash || slash == dev || !strcmp(dev, "/sys/devices"))
            break;
        char sub[PATH_MAX + 16], target[PATH_MAX];
        snprintf(sub, sizeof sub, "%s/subsystem", dev);
        ssize_t k = readlink(sub, target, sizeof target - 1);
        const char *s = "";
        if (k > 0) {
            target[k] = 0;
            const char *b = strrchr(target, '/');
            s = b ? b + 1 : target;
        }
        int named = !strcmp(s, "pci") || !strcmp(s, "platform") || !strcmp(s, "amba");
        if (named && strcmp(s, last)) {
            char t[sizeof name];
            size_t need = strlen(s) + strlen(slash + 1) + strlen(name) + 3;
            if (need > sizeof t)
                return; /* deeper than any real board: no name rather than a cut one */
            t[0] = 0;
            strcat(strcat(strcat(t, s), "-"), slash + 1);
            if (name[0])
                strcat(strcat(t, "-"), name);
            memcpy(name, t, sizeof name);
        }
        last = named ? (!strcmp(s, "pci") ? "pci" : !strcmp(s, "platform") ? "platform" : "amba") : "";
        *slash = 0;
    }
    snprintf(out, n, "%s", name);
}

static int by_minor(const void *a, const void *b)
{
    const fx_card_desc *x = a, *y = b;
    return (x->minor > y->minor) - (x->minor < y->minor);
}

static void describe(fx_card_desc *c)
{
    int fd = open(c->path, O_RDWR | O_CLOEXEC);
    if (fd < 0)
        fd = open(c->path, O_RDONLY | O_CLOEXEC);
    int e = errno; /* before the sysfs walk, whose failed readlinks set it */
    by_path_name(c->minor, c->path_name, sizeof c->path_name);
    if (fd < 0) {
        c->error = -e;
        return;
    }
    drmVersionPtr v = drmGetVersion(fd);
    if (v) {
        snprintf(c->driver, sizeof c->driver, "%s", v->name);
        drmFreeVersion(v);
    }
    drmModeResPtr res = drmModeGetResources(fd);
    if (!res) {
        c->error = errno ? -errno : -ENODEV; /* render-only GPU (v3d) */
        close(fd);
        return;
    }
    for (int i = 0; i < res->count_connectors && c->nconn < FX_CARD_CONNECTORS_MAX; i++) {
        drmModeConnectorPtr m = drmModeGetConnector(fd, res->connectors[i]);
        if (!m)
            continue;
        fx_connector_desc *o = &c->conn[c->nconn++];
        const char *t = drmModeGetConnectorTypeName(m->connector_type);
        snprintf(o->name, sizeof o->name, "%s-%u", t ? t : "Unknown", m->connector_type_id);
        o->id = m->connector_id;
        o->connected = m->connection == DRM_MODE_CONNECTED ? 1 : m->connection == DRM_MODE_DISCONNECTED ? 0 : -1;
        o->modes = m->count_modes;
        drmModeFreeConnector(m);
    }
    drmModeFreeResources(res);
    close(fd);
}

int fx_drm_cards(fx_card_desc *out, int max)
{
    DIR *dir = opendir("/dev/dri");
    if (!dir)
        return 0;
    int n = 0;
    struct dirent *e;
    while ((e = readdir(dir)) && n < max) {
        const char *s = e->d_name;
        if (strncmp(s, "card", 4) || s[4] < '0' || s[4] > '9' || strlen(s) > 12)
            continue;
        char *end;
        long minor = strtol(s + 4, &end, 10);
        if (*end)
            continue;
        memset(&out[n], 0, sizeof out[n]);
        out[n].minor = (int)minor;
        snprintf(out[n].path, sizeof out[n].path, "/dev/dri/%s", s);
        n++;
    }
    closedir(dir);
    qsort(out, (size_t)n, sizeof *out, by_minor);
    for (int i = 0; i < n; i++)
        describe(&out[i]);
    return n;
}
