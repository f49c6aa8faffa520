/* SPDX-License-Identifier: MIT */
/* DRM/KMS backend: one connector, one CRTC, two dumb buffers flipped with
 * vblank events. Falls back to SetCrtc where flips are refused, calls
 * DIRTYFB for drivers that need it (SPI/MIPI-DBI panels) and restores the
 * CRTC it found on close, or from the emergency path on a fatal signal. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <sys/socket.h>
#include <linux/netlink.h>
#include <stdint.h>
#include <time.h>
#include <unistd.h>

#include <drm_fourcc.h>
#include <xf86drm.h>
#include <xf86drmMode.h>

#include "../../display/display_int.h"
#include "fixel/cards.h"
#include "fixel/error.h"

struct drm_buf {
    uint32_t handle, fb_id, pitch;
    uint64_t size;
    void *map;
};

struct drm_priv {
    int fd;
    uint32_t conn_id, crtc_id;
    drmModeModeInfo mode;
    drmModeCrtcPtr saved;
    struct drm_buf buf[2];
    int nbuf;
    int flip_ok;
    int dirty;                       /* -1 untried, 0 refused, 1 accepted */
    int uevent_fd;                   /* kernel uevents (hotplug), -1 if unavailable */
    char card[64];                   /* "card0": matches DEVNAME=dri/card0 */
    int connected;
    int reprobe_pending;             /* a hotplug arrived while our VT was away */
    /* Plane rotation: the primary plane's "rotation" property, the value
     * found and the one we set (rot_apply: they differ, restore on exit). */
    uint32_t plane_id, rot_prop;
    uint64_t rot_saved, rot_want;
    int rot_apply;
    /* Pre-built for the signal path, which may not allocate. */
    struct drm_mode_crtc emergency;
    uint32_t emergency_conn;
    struct drm_mode_crtc emergency_off;
    struct drm_mode_obj_set_property emergency_rot;
    /* Screen power: the connector's DPMS property (dpms_prop 0: none, the
     * CRTC is switched off instead). */
    uint32_t dpms_prop;
    uint64_t dpms_on, dpms_off;
};

static int neg_errno(void)
{
    return errno ? -errno : -FX_EIO;
}

/* ---- cards shared by several displays ------------------------------------ */

/* Two displays on one card (two heads of a virtio-gpu, HDMI-A-1 and
 * HDMI-A-2 of a vc4) must share one open file: DRM master belongs to an
 * open file, so a second open() of the card could not become master while
 * the first holds it. Each display gets a dup() of the card's file (one
 * master for both) and takes a CRTC no other display of ours drives. */
#define MAX_CARDS 8
static struct shared_card {
    char path[64];
    int fd;              /* the registry's own dup, closed with the last user */
    int users;
    uint32_t crtcs[8];   /* CRTC ids in use by our displays on this card */
    uint32_t conns[8];   /* the connector each of those CRTCs drives */
} cards_open[MAX_CARDS];

static struct shared_card *card_find(const char *path)
{
    for (int i = 0; i < MAX_CARDS; i++)
        if (cards_open[i].users && !strcmp(cards_open[i].path, path))
            return &cards_open[i];
    return NULL;
}

static int crtc_taken(const char *path, uint32_t id)
{
    struct shared_card *c = card_find(path);
    for (int i = 0; c && i < 8; i++)
        if (c->crtcs[i] == id)
            return 1;
    return 0;
}

/* Count a display in (fd: its own file, already open; crtc 0 before one
 * is chosen). */
static void card_hold(const char *path, int fd)
{
    struct shared_card *c = card_find(path);
    if (!c)
        for (int i = 0; i < MAX_CARDS && !c; i++)
            if (!cards_open[i].users) {
                c = &cards_open[i];
                memset(c, 0, sizeof *c);
                snprintf(c->path, sizeof c->path, "%s", path);
                c->fd = fcntl(fd, F_DUPFD_CLOEXEC, 0);
            }
    if (c)
        c->users++;
}

static void card_crtc(const char *path, uint32_t old, uint32_t id, uint32_t conn)
{
    struct shared_card *c = card_find(path);
    for (int i = 0; c && i < 8; i++)
        if (c->crtcs[i] == old) {
            c->crtcs[i] = id;
            c->conns[i] = id ? conn : 0;
            return;
        }
}

/* 1 when one of our displays drives connector conn of card path. */
static int conn_taken(const char *path, uint32_t conn)
{
    struct shared_card *c = card_find(path);
    for (int i = 0; c && conn && i < 8; i++)
        if (c->crtcs[i] && c->conns[i] == conn)
            return 1;
    return 0;
}

/* 1 when this was the last display on the card (master is to be dropped). */
static int card_release(const char *path, uint32_t crtc)
{
    struct shared_card *c = card_find(path);
    if (!c)
        return 1;
    if (crtc)
        card_crtc(path, crtc, 0, 0);
    if (--c->users)
        return 0;
    if (c->fd >= 0)
        close(c->fd);
    c->fd = -1;
    return 1;
}

/* ---- choosing card, connector, mode, CRTC ------------------------------- */

static int pick_mode(fx_display *d, drmModeConnectorPtr c, drmModeModeInfo *out)
{
    const char *want = d->opt.mode;
    if (want && *want) {
        int32_t w, h, hz;
        if (fx_mode_parse(want, &w, &h, &hz) < 0) {
            fx_log(&d->log, FX_LOG_ERROR, "mode '%s' is not WxH or WxH@Hz", want);
            return -FX_EINVAL;
        }
        for (int i = 0; i < c->count_modes; i++) {
            const drmModeModeInfo *m = &c->modes[i];
            if (m->hdisplay == w && m->vdisplay == h && (!hz || (int32_t)m->vrefresh == hz)) {
                *out = *m;
                return 0;
            }
        }
        fx_log(&d->log, FX_LOG_ERROR, "connector %s has no mode %s", d->connector, want);
        return -FX_ENOENT;
    }
    for (int i = 0; i < c->count_modes; i++)
        if (c->modes[i].type & DRM_MODE_TYPE_PREFERRED) {
            *out = c->modes[i];
            return 0;
        }
    *out = c->modes[0];
    return 0;
}

static uint32_t pick_crtc(const char *card, int fd, drmModeResPtr res, drmModeConnectorPtr c,
                          int *index)
{
    /* Keep the CRTC already driving this connector: no needless re-route. */
    if (c->encoder_id) {
        drmModeEncoderPtr e = drmModeGetEncoder(fd, c->encoder_id);
        if (e) {
            uint32_t id = e->crtc_id;
            drmModeFreeEncoder(e);
            for (int i = 0; id && !crtc_taken(card, id) && i < res->count_crtcs; i++)
                if (res->crtcs[i] == id) {
                    *index = i;
                    return id;
                }
        }
    }
    for (int k = 0; k < c->count_encoders; k++) {
        drmModeEncoderPtr e = drmModeGetEncoder(fd, c->encoders[k]);
        if (!e)
            continue;
        uint32_t possible = e->possible_crtcs;
        drmModeFreeEncoder(e);
        for (int i = 0; i < res->count_crtcs; i++)
            if ((possible & (1u << i)) && !crtc_taken(card, res->crtcs[i])) {
                *index = i;
                return res->crtcs[i];
            }
    }
    return 0;
}

/* What the primary plane of CRTC index ci offers: formats and rotation. */
struct plane_info {
    int known;          /* 0: no plane API, formats unknown (callers just try) */
    uint32_t id;
    int has_xrgb, has_565;
    uint32_t rot_prop;  /* 0: no rotation property */
    uint32_t rot_mask;
    uint64_t rot_value;
};

static void probe_plane(int fd, int ci, struct plane_info *pi)
{
    memset(pi, 0, sizeof *pi);
    drmModePlaneResPtr pr = drmModeGetPlaneResources(fd);
    if (!pr)
        return;
    for (uint32_t i = 0; i < pr->count_planes && !pi->known; i++) {
        drmModePlanePtr p = drmModeGetPlane(fd, pr->planes[i]);
        if (!p)
            continue;
        if (p->possible_crtcs & (1u << ci)) {
            int primary = 0;
            uint32_t rot_prop = 0, rot_mask = 0;
            uint64_t rot_value = 0;
            drmModeObjectPropertiesPtr props =
                drmModeObjectGetProperties(fd, p->plane_id, DRM_MODE_OBJECT_PLANE);
            for (uint32_t k = 0; props && k < props->count_props; k++) {
                drmModePropertyPtr prop = drmModeGetProperty(fd, props->props[k]);
                if (prop && !strcmp(prop->name, "type") &&
                    props->prop_values[k] == DRM_PLANE_TYPE_PRIMARY)
                    primary = 1;
                if (prop && !strcmp(prop->name, "rotation") && (prop->flags & DRM_MODE_PROP_BITMASK) &&
                    prop->count_enums > 0) {
                    fx_prop_enum e[16];
                    int n = prop->count_enums < 16 ? prop->count_enums : 16;
                    for (int j = 0; j < n; j++) {
                        e[j].value = prop->enums[j].value;
                        memcpy(e[j].name, prop->enums[j].name, sizeof e[j].name);
                        e[j].name[sizeof e[j].name - 1] = 0;
                    }
                    rot_prop = prop->prop_id;
                    rot_mask = fx_plane_rotation_mask(e, n);
                    rot_value = props->prop_values[k];
                }
                drmModeFreeProperty(prop);
            }
            drmModeFreeObjectProperties(props);
            if (primary) {
                pi->known = 1;
                pi->id = p->plane_id;
                for (uint32_t f = 0; f < p->count_formats; f++) {
                    pi->has_xrgb |= p->formats[f] == DRM_FORMAT_XRGB8888;
                    pi->has_565 |= p->formats[f] == DRM_FORMAT_RGB565;
                }
                pi->rot_prop = rot_prop;
                pi->rot_mask = rot_mask;
                pi->rot_value = rot_value;
            }
        }
        drmModeFreePlane(p);
    }
    drmModeFreePlaneResources(pr);
}

/* A panel mounted turned (DSI panels in portrait, tablets) says so in its
 * connector's "panel orientation" property, from the panel driver, the
 * device tree's rotation or video=<connector>:panel_orientation=...; unless
 * the program or FIXEL_ROTATION asked for a rotation, show it upright. */
static void panel_orientation(fx_display *d, int fd, uint32_t conn)
{
    drmModeObjectPropertiesPtr props = drmModeObjectGetProperties(fd, conn, DRM_MODE_OBJECT_CONNECTOR);
    for (uint32_t k = 0; props && k < props->count_props; k++) {
        drmModePropertyPtr pr = drmModeGetProperty(fd, props->props[k]);
        if (pr && !strcmp(pr->name, "panel orientation") && (pr->flags & DRM_MODE_PROP_ENUM)) {
            for (int e = 0; e < pr->count_enums; e++) {
                if (pr->enums[e].value != props->prop_values[k])
                    continue;
                int rot = fx_panel_orientation_rotation(pr->enums[e].name);
                if (rot < 0)
                    break;
                if (d->rotation_asked) {
                    if (rot != d->opt.rotation)
                        fx_log(&d->log, FX_LOG_INFO, "%s: panel orientation \"%s\" would be rotation %d; "
                               "rotation %d was asked for", d->connector, pr->enums[e].name, rot,
                               d->opt.rotation);
                } else {
                    if (rot != d->opt.rotation)
                        fx_log(&d->log, FX_LOG_INFO, "%s: panel orientation \"%s\": rotation %d "
                               "(FIXEL_ROTATION overrides)", d->connector, pr->enums[e].name, rot);
                    d->opt.rotation = d->sw_rotation = rot;
                }
            }
        }
        drmModeFreeProperty(pr);
    }
    drmModeFreeObjectProperties(props);
}

/* ---- buffers ------------------------------------------------------------ */

static int create_buf(int fd, struct drm_buf *b, uint32_t w, uint32_t h, uint32_t fourcc, int bpp)
{
    struct drm_mode_create_dumb cr = {.width = w, .height = h, .bpp = (uint32_t)bpp};
    struct drm_mode_map_dumb mr = {0};
    uint32_t handles[4] = {0}, pitches[4] = {0}, offsets[4] = {0};

    if (drmIoctl(fd, DRM_IOCTL_MODE_CREATE_DUMB, &cr) < 0)
        return neg_errno();
    b->handle = cr.handle;
    b->pitch = cr.pitch;
    b->size = cr.size;
    handles[0] = cr.handle;
    pitches[0] = cr.pitch;
    if (drmModeAddFB2(fd, w, h, fourcc, handles, pitches, offsets, &b->fb_id, 0) < 0)
        return neg_errno();
    mr.handle = cr.handle;
    if (drmIoctl(fd, DRM_IOCTL_MODE_MAP_DUMB, &mr) < 0)
        return neg_errno();
    b->map = mmap(NULL, (size_t)cr.size, PROT_READ | PROT_WRITE, MAP_SHARED, fd, (off_t)mr.offset);
    if (b->map == MAP_FAILED) {
        b->map = NULL;
        return neg_errno();
    }
    memset(b->map, 0, (size_t)cr.size);
    return 0;
}

static void destroy_buf(int fd, struct drm_buf *b)
{
    if (b->map)
        munmap(b->map, (size_t)b->size);
    if (b->fb_id)
        drmModeRmFB(fd, b->fb_id);
    if (b->handle) {
        struct drm_mode_destroy_dumb dr = {.handle = b->handle};
        drmIoctl(fd, DRM_IOCTL_MODE_DESTROY_DUMB, &dr);
    }
    memset(b, 0, sizeof *b);
}

/* ---- ops ---------------------------------------------------------------- */

static void on_flip(int fd, unsigned seq, unsigned sec, unsigned usec, void *data)
{
    (void)fd, (void)seq, (void)sec, (void)usec;
    fx_display_flip_done(data);
}

static void reprobe(fx_display *d);

/* Kernel uevents are "ACTION@DEVPATH" then NUL-separated KEY=VALUE pairs.
 * Any change event of our card re-probes the connector: cheap, and it also
 * covers drivers that announce hotplug without HOTPLUG=1. */
static void read_uevents(fx_display *d)
{
    struct drm_priv *p = d->priv;
    char buf[4096], devname[96];
    ssize_t n;
    int ours = 0;
    snprintf(devname, sizeof devname, "DEVNAME=dri/%s", p->card);
    while ((n = recv(p->uevent_fd, buf, sizeof buf - 1, 0)) > 0) {
        buf[n] = 0;
        int drm = 0, dev = 0, change = 0;
        for (char *k = buf; k < buf + n; k += strlen(k) + 1) {
            drm |= !strcmp(k, "SUBSYSTEM=drm");
            dev |= !strcmp(k, devname);
            change |= !strcmp(k, "ACTION=change");
        }
        ours |= drm && dev && change;
    }
    if (ours) {
        d->info.hotplugs++;
        if (d->away)
            p->reprobe_pending = 1;
        else
            reprobe(d);
    }
}

static int drm_hotplug_fd(const fx_display *d)
{
    const struct drm_priv *p = d->priv;
    return p->uevent_fd;
}

static int drm_dispatch(fx_display *d)
{
    struct drm_priv *p = d->priv;
    struct pollfd pfd = {.fd = p->fd, .events = POLLIN};
    if (p->uevent_fd >= 0)
        read_uevents(d);
    drmEventContext ev = {.version = 2, .page_flip_handler = on_flip};
    /* drmHandleEvent reads, which would block on an empty queue. */
    if (poll(&pfd, 1, 0) <= 0)
        return 0;
    if (drmHandleEvent(p->fd, &ev) < 0)
        return neg_errno();
    return 0;
}

static int64_t now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (int64_t)t.tv_sec * 1000 + t.tv_nsec / 1000000;
}

static int drm_wait(fx_display *d, int timeout_ms)
{
    struct drm_priv *p = d->priv;
    int64_t end = now_ms() + timeout_ms;
    while (d->flip_pending) {
        int64_t left = end - now_ms();
        struct pollfd pfd = {.fd = p->fd, .events = POLLIN};
        int r = left > 0 ? poll(&pfd, 1, (int)left) : 0;
        if (r < 0 && errno == EINTR)
            continue;
        if (r <= 0) {
            /* A flip that never completes would freeze every later frame;
             * give up on flips for good and present with SetCrtc. */
            fx_log(&d->log, FX_LOG_ERROR,
                           "page flip did not complete within %d ms; presenting with SetCrtc",
                           timeout_ms);
            d->flip_pending = 0;
            p->flip_ok = 0;
            return -FX_EIO;
        }
        int e = drm_dispatch(d);
        if (e < 0)
            return e;
    }
    return 0;
}

static int drm_fd(const fx_display *d)
{
    const struct drm_priv *p = d->priv;
    return p->fd;
}

static int set_crtc(struct drm_priv *p, int buf)
{
    return drmModeSetCrtc(p->fd, p->crtc_id, p->buf[buf].fb_id, 0, 0, &p->conn_id, 1, &p->mode);
}

/* Set the plane's rotation, then the mode. The kernel checks a rotated
 * plane's fb against the swapped mode size, so the property cannot change
 * while an fb of the other orientation is shown: switch the CRTC off first
 * when the direct attempt is refused. Also used on return to our VT, where
 * the console has put its own rotation back. */
static int modeset(struct drm_priv *p, int buf)
{
    if (p->rot_apply &&
        drmModeObjectSetProperty(p->fd, p->plane_id, DRM_MODE_OBJECT_PLANE, p->rot_prop, p->rot_want) < 0) {
        drmModeSetCrtc(p->fd, p->crtc_id, 0, 0, 0, NULL, 0, NULL);
        if (drmModeObjectSetProperty(p->fd, p->plane_id, DRM_MODE_OBJECT_PLANE, p->rot_prop,
                                     p->rot_want) < 0)
            return -1;
    }
    return set_crtc(p, buf);
}

static void restore_rotation(struct drm_priv *p)
{
    if (!p->rot_apply)
        return;
    drmModeSetCrtc(p->fd, p->crtc_id, 0, 0, 0, NULL, 0, NULL);
    drmModeObjectSetProperty(p->fd, p->plane_id, DRM_MODE_OBJECT_PLANE, p->rot_prop, p->rot_saved);
}

static int drm_show(fx_display *d, int buf, const fx_rect *phys, int n)
{
    struct drm_priv *p = d->priv;
    int r;

    /* Screen off: a flip (or its SetCrtc fallback) would switch the CRTC
     * back on; the buffer is shown when the screen comes on. The front end
     * paces these presents (and calls the flip callback) as vblank would. */
    if (d->power_off)
        return 0;

    if (p->dirty != 0 && n > 0) {
        drmModeClip clips[FX_DAMAGE_MAX];
        for (int i = 0; i < n && i < FX_DAMAGE_MAX; i++) {
            clips[i].x1 = (uint16_t)phys[i].x0;
            clips[i].y1 = (uint16_t)phys[i].y0;
            clips[i].x2 = (uint16_t)phys[i].x1;
            clips[i].y2 = (uint16_t)phys[i].y1;
        }
        r = drmModeDirtyFB(p->fd, p->buf[buf].fb_id, clips, (uint32_t)(n < FX_DAMAGE_MAX ? n : FX_DAMAGE_MAX));
        if (r == 0) {
            p->dirty = 1;
        } else {
            /* Most drivers scan out memory directly and have no dirty hook
             * (ENOSYS); any refusal just means they do not need it. */
            fx_log(&d->log, FX_LOG_DEBUG, "driver refused DIRTYFB (%s); not calling it again",
                           strerror(-r));
            p->dirty = 0;
        }
        d->info.dirtyfb = p->dirty;
    }
    if (buf == d->shown)
        return 0; /* single buffer: the store (and DIRTYFB) was the present */

    if (p->flip_ok) {
        r = drmModePageFlip(p->fd, p->crtc_id, p->buf[buf].fb_id, DRM_MODE_PAGE_FLIP_EVENT, d);
        if (r == 0) {
            d->flip_pending = 1;
            return 0;
        }
        if (r == -EACCES || r == -EPERM) {
            fx_log(&d->log, FX_LOG_ERROR, "page flip refused: lost DRM master (%s)", strerror(-r));
            return r;
        }
        fx_log(&d->log, FX_LOG_INFO, "page flip not available (%s); presenting with SetCrtc",
                       strerror(-r));
        p->flip_ok = 0;
    }
    r = set_crtc(p, buf);
    if (r < 0) {
        fx_log(&d->log, FX_LOG_ERROR, "SetCrtc failed: %s", strerror(errno));
        return neg_errno();
    }
    d->info.fallbacks++;
    if (d->flip_cb)
        d->flip_cb(d, d->flip_user);
    return 0;
}

static void drm_close(fx_display *d)
{
    struct drm_priv *p = d->priv;
    if (!p)
        return;
    restore_rotation(p);
    if (p->saved) {
        /* Give the screen back as found (fbcon, a splash, another mode). */
        if (p->saved->mode_valid && p->saved->buffer_id)
            drmModeSetCrtc(p->fd, p->crtc_id, p->saved->buffer_id, p->saved->x, p->saved->y,
                           &p->conn_id, 1, &p->saved->mode);
        else
            drmModeSetCrtc(p->fd, p->crtc_id, 0, 0, 0, NULL, 0, NULL);
        drmModeFreeCrtc(p->saved);
    }
    for (int i = 0; i < 2; i++)
        destroy_buf(p->fd, &p->buf[i]);
    if (p->uevent_fd >= 0)
        close(p->uevent_fd);
    if (p->fd >= 0) {
        if (card_release(d->device, p->crtc_id))
            drmDropMaster(p->fd);
        close(p->fd);
    }
    free(p);
    d->priv = NULL;
}

/* The emergency (signal) path: only ioctls on prepared structures. */
static void drm_emergency_restore(fx_display *d)
{
    struct drm_priv *p = d->priv;
    if (p && p->fd >= 0 && p->rot_apply) {
        ioctl(p->fd, DRM_IOCTL_MODE_SETCRTC, &p->emergency_off);
        ioctl(p->fd, DRM_IOCTL_MODE_OBJ_SETPROPERTY, &p->emergency_rot);
    }
    if (p && p->fd >= 0 && p->emergency.crtc_id)
        ioctl(p->fd, DRM_IOCTL_MODE_SETCRTC, &p->emergency);
}

static int drm_suspend(fx_display *d)
{
    struct drm_priv *p = d->priv;
    /* Without master the console (or the next program) can set its mode.
     * Another of our displays on this card may have dropped it already. */
    if (!drmIsMaster(p->fd))
        return 0;
    return drmDropMaster(p->fd) < 0 ? neg_errno() : 0;
}

static int drm_resume(fx_display *d)
{
    struct drm_priv *p = d->priv;
    if (!drmIsMaster(p->fd) && drmSetMaster(p->fd) < 0) {
        fx_log(&d->log, FX_LOG_ERROR, "%s: cannot retake DRM master: %s", d->device, strerror(errno));
        return neg_errno();
    }
    if (modeset(p, d->shown < 0 ? 0 : d->shown) < 0) {
        fx_log(&d->log, FX_LOG_ERROR, "SetCrtc after VT switch: %s", strerror(errno));
        return neg_errno();
    }
    if (p->reprobe_pending) {
        p->reprobe_pending = 0;
        reprobe(d);
    }
    return 0;
}

/* Our connector after a hotplug: gone (wait for it), back or with another
 * preferred mode (modeset again, new buffers when the size changed). */
static void reprobe(fx_display *d)
{
    struct drm_priv *p = d->priv;
    drmModeConnectorPtr c = drmModeGetConnector(p->fd, p->conn_id);
    int now = c && c->connection == DRM_MODE_CONNECTED && c->count_modes > 0;
    drmModeModeInfo m;
    if (!now || pick_mode(d, c, &m) < 0) {
        if (p->connected)
            fx_log(&d->log, FX_LOG_INFO, "%s disconnected; waiting for it to come back", d->connector);
        p->connected = d->info.connected = 0;
        drmModeFreeConnector(c);
        return;
    }
    drmModeFreeConnector(c);
    int same_size = m.hdisplay == p->mode.hdisplay && m.vdisplay == p->mode.vdisplay;
    /* A plane rotated by 90/270 scans out an fb of the swapped size. */
    int swap = d->opt.rotation != d->sw_rotation && (d->opt.rotation == 90 || d->opt.rotation == 270);
    uint32_t bw = swap ? m.vdisplay : m.hdisplay, bh = swap ? m.hdisplay : m.vdisplay;
    int same_mode = same_size && m.clock == p->mode.clock && m.vrefresh == p->mode.vrefresh;
    if (p->connected && same_mode)
        return;
    fx_log(&d->log, FX_LOG_INFO, "%s %s: %ux%u@%u", d->connector,
                   p->connected ? "changed mode" : "connected", m.hdisplay, m.vdisplay, m.vrefresh);
    drm_wait(d, 200);
    if (!same_size) {
        fx_format f = d->info.format;
        const fx_format_info *fi = fx_format_get(f);
        for (int i = 0; i < p->nbuf; i++) {
            destroy_buf(p->fd, &p->buf[i]);
            if (create_buf(p->fd, &p->buf[i], bw, bh, fi->drm_fourcc, fi->bits_per_pixel) < 0) {
                fx_log(&d->log, FX_LOG_ERROR, "%s: no buffer for %ux%u", d->device, m.hdisplay, m.vdisplay);
                destroy_buf(p->fd, &p->buf[i]);
                p->connected = d->info.connected = 0;
                return;
            }
            fx_surface_init(&d->scan[i], p->buf[i].map, (int32_t)bw, (int32_t)bh, (int32_t)p->buf[i].pitch, f);
        }
        d->shown = 0;
        d->back = p->nbuf == 2 ? 1 : 0;
        d->info.width = (int32_t)bw;
        d->info.height = (int32_t)bh;
    }
    p->mode = m;
    if (set_crtc(p, d->shown < 0 ? 0 : d->shown) < 0)
        fx_log(&d->log, FX_LOG_ERROR, "modeset after hotplug failed: %s", strerror(errno));
    p->connected = d->info.connected = 1;
    if (!same_size)
        d->resized(d);
}

/* The connector's DPMS enum (legacy, but atomic drivers map it to the
 * CRTC's ACTIVE, so the monitor gets no signal and sleeps). */
static void find_dpms(fx_display *d, struct drm_priv *p)
{
    drmModeObjectPropertiesPtr props = drmModeObjectGetProperties(p->fd, p->conn_id, DRM_MODE_OBJECT_CONNECTOR);
    for (uint32_t k = 0; props && k < props->count_props; k++) {
        drmModePropertyPtr pr = drmModeGetProperty(p->fd, props->props[k]);
        if (pr && !strcmp(pr->name, "DPMS") && (pr->flags & DRM_MODE_PROP_ENUM)) {
            fx_prop_enum e[8];
            int n = pr->count_enums < 8 ? pr->count_enums : 8;
            for (int i = 0; i < n; i++) {
                memset(&e[i], 0, sizeof e[i]);
                e[i].value = pr->enums[i].value;
                snprintf(e[i].name, sizeof e[i].name, "%s", pr->enums[i].name);
            }
            if (fx_dpms_values(e, n, &p->dpms_on, &p->dpms_off) == 0)
                p->dpms_prop = pr->prop_id;
        }
        drmModeFreeProperty(pr);
    }
    drmModeFreeObjectProperties(props);
    d->power_method = p->dpms_prop ? "dpms" : "crtc";
}

static int drm_set_power(fx_display *d, int on)
{
    struct drm_priv *p = d->priv;
    if (p->dpms_prop &&
        drmModeConnectorSetProperty(p->fd, p->conn_id, p->dpms_prop, on ? p->dpms_on : p->dpms_off) < 0)
        return neg_errno();
    if (on) {
        /* The newest frame (drm_show skipped the flips while off); also
         * what brings the CRTC back when it was switched off. */
        if (set_crtc(p, d->shown < 0 ? 0 : d->shown) < 0)
            return neg_errno();
    } else if (!p->dpms_prop && drmModeSetCrtc(p->fd, p->crtc_id, 0, 0, 0, NULL, 0, NULL) < 0) {
        return neg_errno();
    }
    return 0;
}

static const struct fx_backend_ops drm_ops = {drm_show, drm_wait, drm_dispatch, drm_fd, drm_close,
                                              drm_suspend, drm_resume, drm_hotplug_fd,
                                              drm_emergency_restore, drm_set_power};

/* ---- open --------------------------------------------------------------- */

static int open_card(fx_display *d, const char *path, int quiet_enoent)
{
    int fd = open(path, O_RDWR | O_CLOEXEC);
    if (fd < 0) {
        int e = errno;
        if (e == EACCES || e == EPERM)
            fx_log_access_hint(&d->log, path);
        else if (!quiet_enoent && e != ENOENT)
            /* a device the user named: say why at error level, with a
             * path too long to print cut so the reason still shows */
            fx_log(&d->log, FX_LOG_ERROR, "%.200s%s: %s", path, strlen(path) > 200 ? "..." : "",
                   strerror(e));
        else if (!quiet_enoent)
            fx_log(&d->log, FX_LOG_DEBUG, "%s: %s", path, strerror(e));
        return -e;
    }
    return fd;
}

/* A device given as a path: /dev/dri/cardN itself or a link to it (the
 * udev by-path links). Other paths are opened only to report why not. */
static int path_to_card(fx_display *d, const char *path, char *spec, size_t n)
{
    char real[PATH_MAX];
    const char *base;
    if (realpath(path, real) && !strncmp(real, "/dev/dri/card", 13) && (base = strrchr(real, '/'))) {
        snprintf(spec, n, "%s", base + 1);
        return 0;
    }
    snprintf(d->device, sizeof d->device, "%s", path); /* named in errors */
    int fd = open_card(d, path, 0);
    if (fd < 0)
        return fd;
    close(fd);
    fx_log(&d->log, FX_LOG_ERROR, "%.200s is not a DRM card (/dev/dri/cardN or a link to one)", path);
    return -FX_ENODEV;
}

static void list_cards(const fx_card_desc *c, int n, char *out, size_t len)
{
    size_t at = 0;
    out[0] = 0;
    for (int i = 0; i < n && at < len; i++) {
        int k = snprintf(out + at, len - at, "%s%s %s %s", i ? ", " : "", c[i].path + 9,
                         c[i].driver[0] ? c[i].driver : "?", c[i].path_name[0] ? c[i].path_name : "-");
        if (k < 0)
            break;
        at += (size_t)k;
    }
    if (!n)
        snprintf(out, len, "none");
}

/* Enumerate every card, choose the output by name (fixel/cards.h), open
 * the chosen card. */
static int find_card(fx_display *d, int *fd_out, uint32_t *conn_id)
{
    const char *want = d->opt.device;
    if (want && (!*want || (want[0] == '/' && !strstr(want, "/dri/"))))
        want = NULL; /* a /dev/fbN device is for the fbdev backend */
    if (!want)
        want = d->opt.drm_device;
    if (want && !*want)
        want = NULL;
    const char *cwant = d->opt.connector && *d->opt.connector ? d->opt.connector : NULL;
    char spec[64];
    if (want && want[0] == '/') {
        int r = path_to_card(d, want, spec, sizeof spec);
        if (r < 0)
            return r;
        want = spec;
    }
    fx_card_desc cards[FX_CARDS_MAX];
    int n = fx_drm_cards(cards, FX_CARDS_MAX), ci = -1, ki = -1;
    /* Outputs our other displays drive are not there for the automatic
     * choice (a second display opened without a name takes the next
     * output); a named one is refused below. */
    char taken[128] = "";
    int named = cwant && cwant[strlen(cwant) - 1] != ':'; /* "NAME", "CARD:NAME"; not "CARD:" */
    for (int i = 0; i < n && !named; i++)
        for (int k = 0; k < cards[i].nconn; k++)
            if (conn_taken(cards[i].path, cards[i].conn[k].id)) {
                size_t l = strlen(taken);
                snprintf(taken + l, sizeof taken - l, "%s%s", l ? ", " : "", cards[i].conn[k].name);
                cards[i].conn[k].connected = 0;
                cards[i].conn[k].modes = 0;
            }
    fx_card_pick pk = fx_card_pick_output(cards, n, want, cwant, &ci, &ki);
    if (pk == FX_PICK_OK && conn_taken(cards[ci].path, cards[ci].conn[ki].id)) {
        fx_log(&d->log, FX_LOG_ERROR,
               "connector %s (%s) is already driven by another display of this program: "
               "name a different connector for each display", cards[ci].conn[ki].name, cards[ci].path);
        snprintf(d->device, sizeof d->device, "%s", cards[ci].path);
        return -FX_EBUSY;
    }
    if (pk == FX_PICK_NONE_CONNECTED && taken[0]) {
        fx_log(&d->log, FX_LOG_ERROR,
               "every connected output is driven by another display of this program (%s)", taken);
        return -FX_EBUSY;
    }
    if (pk != FX_PICK_OK) {
        /* A card we may not open explains it best (the group to join). */
        int err = 0;
        for (int i = 0; i < n; i++) {
            int e = cards[i].error;
            if (!e || (want && !fx_card_matches(&cards[i], want)))
                continue;
            if (e == -EACCES || e == -EPERM)
                fx_log_access_hint(&d->log, cards[i].path);
            else if (want)
                fx_log(&d->log, FX_LOG_ERROR, "%s: %s", cards[i].path, strerror(-e));
            if (!err || e == -EACCES || e == -EPERM)
                err = e;
        }
        char names[512];
        list_cards(cards, n, names, sizeof names);
        snprintf(d->device, sizeof d->device, "%s", want ? want : "/dev/dri");
        if (err && pk != FX_PICK_DISCONNECTED)
            return err;
        if (pk == FX_PICK_NO_CARD)
            fx_log(&d->log, FX_LOG_ERROR, "no DRM card named %s%s%s (cards: %s)", want ? want : "",
                   want && cwant && strchr(cwant, ':') ? " with " : "",
                   want && cwant && strchr(cwant, ':') ? cwant : (!want && cwant ? cwant : ""), names);
        else if (pk == FX_PICK_NO_CONNECTOR)
            fx_log(&d->log, FX_LOG_ERROR, "no connector named %s on %s (cards: %s)", cwant,
                   want ? want : "any DRM card", names);
        else if (pk == FX_PICK_DISCONNECTED)
            fx_log(&d->log, FX_LOG_ERROR, "%s: connector %s is disconnected (no modes)", cards[ci].path,
                   cards[ci].conn[ki].name);
        else if (want || n)
            fx_log(&d->log, want ? FX_LOG_ERROR : FX_LOG_DEBUG, "%s: no connected connector (cards: %s)",
                   want ? want : "DRM", names);
        return -FX_ENODEV;
    }
    snprintf(d->device, sizeof d->device, "%s", cards[ci].path);
    snprintf(d->connector, sizeof d->connector, "%s", cards[ci].conn[ki].name);
    struct shared_card *sc = card_find(cards[ci].path);
    int fd = sc && sc->fd >= 0 ? fcntl(sc->fd, F_DUPFD_CLOEXEC, 0) : open_card(d, cards[ci].path, 0);
    if (fd < 0)
        return sc ? neg_errno() : fd;
    card_hold(cards[ci].path, fd);
    if (want || cwant)
        fx_log(&d->log, FX_LOG_DEBUG, "%s%s%s%s chose %s (%s, %s) connector %s", want ? "card " : "",
               want ? want : "", want && cwant ? ", " : "", cwant ? cwant : "", cards[ci].path,
               cards[ci].driver, cards[ci].path_name[0] ? cards[ci].path_name : "no by-path name",
               d->connector);
    *conn_id = cards[ci].conn[ki].id;
    *fd_out = fd;
    return 0;
}

int fx_drm_open(fx_display *d)
{
    int fd = -1, r, ci = 0;
    uint32_t conn_id = 0;
    r = find_card(d, &fd, &conn_id);
    if (r < 0)
        return r;

    struct drm_priv *p = calloc(1, sizeof *p);
    if (!p) {
        card_release(d->device, 0);
        close(fd);
        return -FX_ENOMEM;
    }
    p->fd = fd;
    p->uevent_fd = -1;
    p->dirty = -1;
    p->flip_ok = 1;
    d->priv = p;
    d->ops = &drm_ops;
    d->info.dirtyfb = -1;

    uint64_t cap = 0;
    if (drmGetCap(fd, DRM_CAP_DUMB_BUFFER, &cap) < 0 || !cap) {
        fx_log(&d->log, FX_LOG_ERROR, "%s has no dumb buffers", d->device);
        return -FX_ENOTSUP;
    }
    drmSetClientCap(fd, DRM_CLIENT_CAP_UNIVERSAL_PLANES, 1);

    /* The first opener becomes master by itself; otherwise try to take it.
     * Failure means a desktop, another fixel program or a logind session
     * owns the display. */
    if (!drmIsMaster(fd) && drmSetMaster(fd) != 0) {
        fx_log(&d->log, FX_LOG_ERROR,
                       "%s: another process holds DRM master (a desktop session or another "
                       "graphics program): stop it, or use the fbdev backend (FIXEL_BACKEND=fbdev)",
                       d->device);
        return -FX_EBUSY;
    }

    drmModeResPtr res = drmModeGetResources(fd);
    if (!res) {
        fx_log(&d->log, FX_LOG_ERROR, "%s: cannot read KMS resources: %s", d->device, strerror(errno));
        return neg_errno();
    }
    drmModeConnectorPtr c = drmModeGetConnector(fd, conn_id);
    if (!c || c->count_modes <= 0) {
        fx_log(&d->log, FX_LOG_ERROR, "%s: connector %s went away", d->device, d->connector);
        drmModeFreeConnector(c);
        drmModeFreeResources(res);
        return -FX_ENODEV;
    }
    p->conn_id = c->connector_id;
    panel_orientation(d, fd, c->connector_id);
    find_dpms(d, p);
    r = pick_mode(d, c, &p->mode);
    if (r == 0) {
        p->crtc_id = pick_crtc(d->device, fd, res, c, &ci);
        if (!p->crtc_id) {
            fx_log(&d->log, FX_LOG_ERROR, "%s: no CRTC can drive %s%s", d->device, d->connector,
                   card_find(d->device) && card_find(d->device)->users > 1
                       ? " (the free ones drive our other displays)" : "");
            r = -FX_ENODEV;
        } else {
            card_crtc(d->device, 0, p->crtc_id, p->conn_id);
        }
    }
    drmModeFreeConnector(c);
    drmModeFreeResources(res);
    if (r < 0)
        return r;

    fx_format fwant = d->opt.format != FX_FMT_COUNT ? d->opt.format : d->opt.drm_format;
#ifdef FX_BOARD_DRM_FORMAT_RGB565
    if (fwant == FX_FMT_COUNT)
        fwant = FX_FMT_RGB565; /* the board profile's 16-bit panel */
#endif
    struct plane_info pl;
    probe_plane(fd, ci, &pl);
    const char *fwhy;
    fx_format f = fx_drm_format_choose(fwant, !pl.known || pl.has_xrgb, !pl.known || pl.has_565, &fwhy);
    if (f == FX_FMT_COUNT) {
        fx_log(&d->log, FX_LOG_ERROR, "%s: %s", d->device, fwhy);
        return -FX_ENOTSUP;
    }
    if (fwant != FX_FMT_COUNT && f != fwant)
        fx_log(&d->log, FX_LOG_INFO, "primary plane has no %s; using %s", fx_format_get(fwant)->name,
                       fx_format_get(f)->name);

    int force_sw = d->opt.sw_rotation;
    int hw = fx_plane_rotation_choose(d->opt.rotation, pl.rot_prop != 0, pl.rot_mask, force_sw,
                                      &d->rotation_why);
    if (pl.rot_prop) {
        p->plane_id = pl.id;
        p->rot_prop = pl.rot_prop;
        p->rot_saved = pl.rot_value;
        /* Without plane rotation the plane must not be left rotated by
         * someone else either: rotate-0 is then the wanted value. */
        p->rot_want = hw ? fx_plane_rotation_bit(d->opt.rotation) : FX_PLANE_ROTATE_0;
        p->rot_apply = (pl.rot_mask & p->rot_want) && p->rot_want != p->rot_saved;
        p->emergency_off.crtc_id = p->crtc_id;
        p->emergency_rot.value = p->rot_saved;
        p->emergency_rot.prop_id = p->rot_prop;
        p->emergency_rot.obj_id = p->plane_id;
        p->emergency_rot.obj_type = DRM_MODE_OBJECT_PLANE;
    }
    if (hw)
        d->sw_rotation = 0;
    const fx_format_info *fi = fx_format_get(f);
    uint32_t w = p->mode.hdisplay, h = p->mode.vdisplay;
    if (hw && (d->opt.rotation == 90 || d->opt.rotation == 270)) {
        w = p->mode.vdisplay; /* the fb has the logical size */
        h = p->mode.hdisplay;
    }

    for (int i = 0; i < 2; i++) {
        r = create_buf(fd, &p->buf[i], w, h, fi->drm_fourcc, fi->bits_per_pixel);
        if (r < 0) {
            if (i == 1) {
                /* Tiny-VRAM devices: one buffer still works, shadowed. */
                fx_log(&d->log, FX_LOG_INFO, "second dumb buffer failed (%s); single-buffered",
                               strerror(-r));
                destroy_buf(fd, &p->buf[1]);
                break;
            }
            fx_log(&d->log, FX_LOG_ERROR, "%s: dumb buffer %ux%u: %s", d->device, w, h, strerror(-r));
            return r;
        }
        fx_surface_init(&d->scan[i], p->buf[i].map, (int32_t)w, (int32_t)h, (int32_t)p->buf[i].pitch, f);
        p->nbuf = i + 1;
    }

    p->saved = drmModeGetCrtc(fd, p->crtc_id);
    if (p->saved) {
        p->emergency.crtc_id = p->crtc_id;
        p->emergency_conn = p->conn_id;
        if (p->saved->mode_valid && p->saved->buffer_id) {
            p->emergency.fb_id = p->saved->buffer_id;
            p->emergency.x = p->saved->x;
            p->emergency.y = p->saved->y;
            p->emergency.set_connectors_ptr = (uint64_t)(uintptr_t)&p->emergency_conn;
            p->emergency.count_connectors = 1;
            p->emergency.mode_valid = 1;
            memcpy(&p->emergency.mode, &p->saved->mode, sizeof p->emergency.mode);
        }
    }

    if (modeset(p, 0) < 0) {
        int e = errno;
        fx_log(&d->log, FX_LOG_ERROR, "%s: modeset %ux%u on %s failed: %s%s", d->device, w, h,
                       d->connector, strerror(e),
                       hw ? " (with plane rotation; FIXEL_SW_ROTATION=1 rotates in software)" : "");
        return -e;
    }
    d->nbuf = p->nbuf;
    d->shown = 0;
    d->back = p->nbuf == 2 ? 1 : 0;
    p->connected = d->info.connected = 1;
    const char *slash = strrchr(d->device, '/');
    snprintf(p->card, sizeof p->card, "%s", slash ? slash + 1 : d->device);
    p->uevent_fd = socket(AF_NETLINK, SOCK_DGRAM | SOCK_CLOEXEC | SOCK_NONBLOCK, NETLINK_KOBJECT_UEVENT);
    if (p->uevent_fd >= 0) {
        struct sockaddr_nl a = {.nl_family = AF_NETLINK, .nl_groups = 1}; /* kernel events */
        if (bind(p->uevent_fd, (struct sockaddr *)&a, sizeof a) < 0) {
            fx_log(&d->log, FX_LOG_DEBUG, "no uevents (%s): hotplug is not followed", strerror(errno));
            close(p->uevent_fd);
            p->uevent_fd = -1;
        }
    }
    d->info.width = (int32_t)w;
    d->info.height = (int32_t)h;
    d->info.format = f;
    int64_t frame = (int64_t)p->mode.htotal * p->mode.vtotal; /* pixels per frame */
    if (frame > 0) /* clock is in kHz */
        d->info.refresh_mhz = (int32_t)((int64_t)p->mode.clock * 1000000 / frame);
    return 0;
}

/* ---- waiting for a display (headless boot) ------------------------------- */

static int uevent_socket(void)
{
    int fd = socket(AF_NETLINK, SOCK_DGRAM | SOCK_CLOEXEC | SOCK_NONBLOCK, NETLINK_KOBJECT_UEVENT);
    struct sockaddr_nl a = {.nl_family = AF_NETLINK, .nl_groups = 1};
    if (fd >= 0 && bind(fd, (struct sockaddr *)&a, sizeof a) < 0) {
        close(fd);
        fd = -1;
    }
    return fd;
}

/* 1 when a drm uevent was among those queued (all are read). */
static int drain_drm_uevents(int fd)
{
    char buf[4096];
    ssize_t n;
    int drm = 0;
    while ((n = recv(fd, buf, sizeof buf - 1, 0)) > 0) {
        buf[n] = 0;
        for (char *k = buf; k < buf + n; k += strlen(k) + 1)
            drm |= !strcmp(k, "SUBSYSTEM=drm");
    }
    return drm;
}

int fx_display_wait_connected(const fx_display_options *o, int timeout_ms)
{
    if (o->backend == FX_BACKEND_FBDEV || o->backend == FX_BACKEND_MEMORY)
        return 0;
    fx_logger l = {o->log ? o->log : fx_log_stderr, o->log_user, o->log_priority ? o->log_priority : FX_LOG_INFO};
    const char *want = o->device;
    if (want && (!*want || (want[0] == '/' && !strstr(want, "/dri/"))))
        want = NULL;
    if (!want)
        want = o->drm_device && *o->drm_device ? o->drm_device : NULL;
    char spec[64], real[PATH_MAX];
    const char *base;
    if (want && want[0] == '/' && realpath(want, real) && (base = strrchr(real, '/'))) {
        snprintf(spec, sizeof spec, "%s", base + 1);
        want = spec;
    }
    const char *cwant = o->connector && *o->connector ? o->connector : NULL;
    int ufd = uevent_socket(); /* before the first look: no event slips between */
    int64_t end = timeout_ms < 0 ? INT64_MAX : now_ms() + timeout_ms;
    int waited = 0, r;
    for (;;) {
        fx_card_desc cards[FX_CARDS_MAX];
        int n = fx_drm_cards(cards, FX_CARDS_MAX), ci, ki, kms = 0, denied = 0;
        for (int i = 0; i < n; i++) {
            kms += !cards[i].error;
            denied += cards[i].error == -EACCES || cards[i].error == -EPERM;
        }
        if (fx_card_pick_output(cards, n, want, cwant, &ci, &ki) == FX_PICK_OK) {
            if (waited)
                fx_log(&l, FX_LOG_INFO, "display connected: %s %s", cards[ci].path, cards[ci].conn[ki].name);
            r = 0;
            break;
        }
        if (denied && !kms) {
            fx_log_access_hint(&l, cards[0].path);
            r = -FX_EACCES;
            break;
        }
        if (!kms && !want && !cwant) {
            r = -FX_ENODEV; /* no KMS card: fbdev or memory is the display */
            break;
        }
        if (!waited)
            fx_log(&l, FX_LOG_INFO, "no display connected%s%s%s%s; waiting for one", want ? " on " : "",
                   want ? want : "", cwant ? " at " : "", cwant ? cwant : "");
        waited = 1;
        int64_t left = end - now_ms();
        if (left <= 0) {
            r = 1; /* timed out: still none */
            break;
        }
        /* uevents, else a look every 5 s (drivers without hotplug interrupts) */
        int64_t slice = left < 5000 ? left : 5000;
        int64_t until = now_ms() + slice;
        int drm = 0;
        while (!drm && now_ms() < until) {
            struct pollfd p = {.fd = ufd, .events = POLLIN};
            int64_t w = until - now_ms();
            if (ufd < 0) {
                struct timespec ts = {(time_t)(w / 1000), (long)(w % 1000) * 1000000L};
                nanosleep(&ts, NULL);
                break;
            }
            if (poll(&p, 1, (int)(w > 0 ? w : 0)) > 0)
                drm = drain_drm_uevents(ufd);
        }
    }
    if (ufd >= 0)
        close(ufd);
    return r;
}
