/* SPDX-License-Identifier: MIT */
/* Logging for the boards side: one function and level (the display's,
 * usually), handed to each layer as an fx_logger; and the hint that names
 * the group a device node belongs to when opening it is refused. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "posix_int.h"

void fx_log_stderr(fx_log_priority p, void *user, const char *fmt, va_list ap)
{
    (void)p;
    (void)user;
    char line[512];
    vsnprintf(line, sizeof line, fmt, ap);
    /* values from the environment and from files are quoted in messages:
     * a control character (ESC, CR) must not reach the terminal */
    for (char *c = line; *c; c++)
        if ((unsigned char)*c < 0x20 || *c == 0x7f)
            *c = '?';
    fprintf(stderr, "fixel: %s\n", line);
}

void fx_logv(const fx_logger *l, fx_log_priority p, const char *fmt, va_list ap)
{
    if ((int)p > l->priority)
        return;
    l->fn(p, l->user, fmt, ap);
}

void fx_log(const fx_logger *l, fx_log_priority p, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fx_logv(l, p, fmt, ap);
    va_end(ap);
}

/* ---- permission hints --------------------------------------------------- */

static int group_name(gid_t gid, char *out, size_t n)
{
    /* /etc/group read directly: getgrgid() drags NSS in, which static
     * builds (the qemu rig, small Pi images) cannot load. */
    FILE *f = fopen("/etc/group", "re");
    char line[512];
    int found = 0;
    if (!f)
        return 0;
    while (!found && fgets(line, sizeof line, f)) {
        char *name = strtok(line, ":");
        char *pw = name ? strtok(NULL, ":") : NULL;
        char *id = pw ? strtok(NULL, ":") : NULL;
        if (id && (gid_t)strtoul(id, NULL, 10) == gid) {
            snprintf(out, n, "%s", name);
            found = 1;
        }
    }
    fclose(f);
    return found;
}

void fx_log_access_hint(const fx_logger *l, const char *path)
{
    struct stat st;
    char name[64];
    if (stat(path, &st) < 0) {
        fx_log(l, FX_LOG_ERROR, "%s: permission denied", path);
        return;
    }
    if (!group_name(st.st_gid, name, sizeof name))
        snprintf(name, sizeof name, "%u", (unsigned)st.st_gid);
    if (st.st_gid == 0 || !(st.st_mode & S_IRWXG))
        fx_log(l, FX_LOG_ERROR, "%s: permission denied (owned by root, mode %03o): run as root "
                       "or give the device a group such as 'video' with a udev rule",
                       path, (unsigned)(st.st_mode & 0777));
    else
        fx_log(l, FX_LOG_ERROR, "%s: permission denied: the user must be in group '%s' "
                       "(usermod -aG %s USER, then log in again) or run as root",
                       path, name, name);
}
