/* SPDX-License-Identifier: MIT */
/* sysfs backlight (fixel/backlight.h). Small text files, read and written
 * whole; the class directory is a parameter so tests can build a fake one. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "fixel/backlight.h"
#include "fixel/error.h"

static int path_of(char *out, size_t size, const char *dir, const char *file)
{
    int n = snprintf(out, size, "%s/%s", dir, file);
    return n < 0 || (size_t)n >= size ? -FX_EINVAL : 0;
}

/* A non-negative decimal integer (sysfs ends it with a newline). */
static int read_int(const char *dir, const char *file)
{
    char path[320], buf[32];
    if (path_of(path, sizeof path, dir, file) < 0)
        return -FX_EINVAL;
    int fd = open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return -errno;
    ssize_t n = read(fd, buf, sizeof buf - 1);
    int e = errno;
    close(fd);
    if (n < 0)
        return -e;
    buf[n] = 0;
    char *end;
    errno = 0;
    long v = strtol(buf, &end, 10);
    if (end == buf || errno || v < 0 || v > 0x7fffffff || (*end && *end != '\n'))
        return -FX_EINVAL;
    return (int)v;
}

static int write_int(const char *dir, const char *file, int v)
{
    char path[320], buf[16];
    if (path_of(path, sizeof path, dir, file) < 0)
        return -FX_EINVAL;
    int fd = open(path, O_WRONLY | O_CLOEXEC);
    if (fd < 0)
        return -errno;
    int n = snprintf(buf, sizeof buf, "%d\n", v);
    ssize_t w = write(fd, buf, (size_t)n);
    int e = errno;
    close(fd);
    if (w < 0)
        return -e;
    return w == n ? 0 : -FX_EIO;
}

int fx_backlight_open(fx_backlight *b, const char *root, const char *name)
{
    char first[256] = "";
    memset(b, 0, sizeof *b);
    if (!root || !*root)
        root = "/sys/class/backlight";
    if (!name || !*name) {
        /* Several (a laptop's acpi_video0 beside intel_backlight): the first
         * by name, as ls shows them; config names the right one. */
        DIR *dp = opendir(root);
        if (!dp)
            return errno == ENOENT ? -FX_ENOENT : -errno;
        struct dirent *e;
        while ((e = readdir(dp)))
            if (e->d_name[0] != '.' && strlen(e->d_name) < sizeof first &&
                (!first[0] || strcmp(e->d_name, first) < 0))
                memcpy(first, e->d_name, strlen(e->d_name) + 1);
        closedir(dp);
        if (!first[0])
            return -FX_ENOENT;
        name = first;
    }
    int n = snprintf(b->dir, sizeof b->dir, "%s/%s", root, name);
    if (n < 0 || (size_t)n >= sizeof b->dir || strchr(name, '/'))
        return -FX_EINVAL;
    b->max = read_int(b->dir, "max_brightness");
    if (b->max == -ENOENT)
        return -FX_ENOENT;
    if (b->max <= 0)
        return b->max < 0 ? b->max : -FX_EINVAL;
    b->saved = read_int(b->dir, "brightness");
    if (b->saved < 0)
        return b->saved;
    b->saved_power = read_int(b->dir, "bl_power");
    if (b->saved_power < 0)
        b->saved_power = -1;
    return 0;
}

int fx_backlight_set_brightness(const fx_backlight *b, int pct)
{
    if (pct < 0 || pct > 100 || b->max <= 0)
        return -FX_EINVAL;
    /* 64-bit: max_brightness can be large (some panels report 120000). */
    return write_int(b->dir, "brightness", (int)(((long long)pct * b->max + 50) / 100));
}

int fx_backlight_brightness(const fx_backlight *b)
{
    int v = read_int(b->dir, "brightness");
    if (v < 0)
        return v;
    return (int)(((long long)v * 100 + b->max / 2) / b->max);
}

int fx_backlight_set_power(const fx_backlight *b, int on)
{
    if (b->saved_power < 0)
        return -FX_ENOTSUP;
    return write_int(b->dir, "bl_power", on ? 0 : 4);
}

void fx_backlight_restore(const fx_backlight *b)
{
    if (b->max <= 0)
        return;
    write_int(b->dir, "brightness", b->saved);
    /* The light on, not as found: found off means a program before us (a
     * kiosk that crashed at night) left it dark, and the console after us
     * must be seen, as fx_display_close leaves the display's power on. */
    if (b->saved_power >= 0)
        write_int(b->dir, "bl_power", 0);
}
