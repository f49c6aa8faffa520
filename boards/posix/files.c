/* SPDX-License-Identifier: MIT */
/* fixel — user-named files: regular files only, never a blocking open
 * (contracts in fixel/files.h). */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include "fixel/files.h"

#include <errno.h>
#include <stdio.h>
#include <fcntl.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

const char *fx_file_kind(unsigned mode)
{
    switch (mode & S_IFMT) {
    case S_IFDIR: return "a directory";
    case S_IFIFO: return "a FIFO";
    case S_IFCHR: return "a character device";
    case S_IFBLK: return "a block device";
    case S_IFSOCK: return "a socket";
    case S_IFREG: return "a regular file";
    default: return "a special file";
    }
}

static void say(char *why, size_t n, const char *fmt, const char *arg)
{
    if (why && n)
        snprintf(why, n, fmt, arg);
}

/* errno and why for a mode that is not a regular file */
static int not_regular(unsigned mode, char *why, size_t n)
{
    say(why, n, "is %s, not a regular file", fx_file_kind(mode));
    errno = S_ISDIR(mode) ? EISDIR : EOPNOTSUPP;
    return -1;
}

static int fail(char *why, size_t n)
{
    int e = errno;
    say(why, n, "%s", strerror(e));
    errno = e;
    return -1;
}

/* fd checked as a regular file, back in blocking mode; closed on failure */
static int keep_regular(int fd, int64_t *size, char *why, size_t n)
{
    struct stat st;
    if (fstat(fd, &st) < 0) {
        fail(why, n);
        int e = errno;
        close(fd);
        errno = e;
        return -1;
    }
    if (!S_ISREG(st.st_mode)) {
        close(fd);
        return not_regular(st.st_mode, why, n);
    }
    int fl = fcntl(fd, F_GETFL);
    if (fl >= 0)
        fcntl(fd, F_SETFL, fl & ~O_NONBLOCK);
    if (size)
        *size = (int64_t)st.st_size;
    return fd;
}

int fx_open_regular(const char *path, int64_t *size, char *why, size_t whylen)
{
    if (!path || !*path) {
        errno = ENOENT;
        return fail(why, whylen);
    }
    /* O_NONBLOCK: open() of a FIFO with no writer returns at once instead
     * of waiting for one; the type check then refuses it */
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0)
        return fail(why, whylen);
    return keep_regular(fd, size, why, whylen);
}

FILE *fx_fopen_regular(const char *path, int64_t *size, char *why, size_t whylen)
{
    int fd = fx_open_regular(path, size, why, whylen);
    if (fd < 0)
        return NULL;
    FILE *f = fdopen(fd, "rb");
    if (!f) {
        fail(why, whylen);
        int e = errno;
        close(fd);
        errno = e;
    }
    return f;
}

FILE *fx_fopen_regular_write(const char *path, int append, char *why, size_t whylen)
{
    if (!path || !*path) {
        errno = ENOENT;
        fail(why, whylen);
        return NULL;
    }
    /* Look before opening: opening a FIFO that has a reader hands it an
     * EOF, and opening a device can act on it (a watchdog arms). What is
     * swapped in between the stat and the open is still refused below,
     * after the open. No O_TRUNC: it would act on a device before the
     * check; O_NONBLOCK: a FIFO with no reader fails with ENXIO instead of
     * blocking. */
    struct stat pre;
    if (stat(path, &pre) == 0 && !S_ISREG(pre.st_mode)) {
        not_regular(pre.st_mode, why, whylen);
        return NULL;
    }
    int fd = open(path, O_WRONLY | O_CREAT | O_NONBLOCK | O_NOCTTY | O_CLOEXEC | (append ? O_APPEND : 0), 0644);
    if (fd < 0) {
        struct stat st;
        int e = errno;
        if (stat(path, &st) == 0 && !S_ISREG(st.st_mode)) {
            not_regular(st.st_mode, why, whylen);
            return NULL;
        }
        errno = e;
        fail(why, whylen);
        return NULL;
    }
    if (keep_regular(fd, NULL, why, whylen) < 0)
        return NULL;
    if (!append && ftruncate(fd, 0) < 0) {
        fail(why, whylen);
        int e = errno;
        close(fd);
        errno = e;
        return NULL;
    }
    FILE *f = fdopen(fd, append ? "ab" : "wb");
    if (!f) {
        fail(why, whylen);
        int e = errno;
        close(fd);
        errno = e;
    }
    return f;
}

int fx_check_replaceable(const char *path, char *why, size_t whylen)
{
    struct stat st;
    if (!path || !*path) {
        errno = ENOENT;
        return fail(why, whylen);
    }
    if (stat(path, &st) < 0)
        return errno == ENOENT ? 0 : fail(why, whylen);
    return S_ISREG(st.st_mode) ? 0 : not_regular(st.st_mode, why, whylen);
}

/* One copy for every tool (fixel-demo and fixel-kiosk had one each). */
int fx_mkdir_parents(const char *path)
{
    char p[4096];
    if (snprintf(p, sizeof p, "%s", path) >= (int)sizeof p) {
        errno = ENAMETOOLONG;
        return -1;
    }
    for (char *s = p + 1;; s++) {
        if (*s != '/' && *s)
            continue;
        char c = *s;
        *s = 0;
        struct stat st;
        if (mkdir(p, 0777) < 0 && (errno != EEXIST || stat(p, &st) < 0 || !S_ISDIR(st.st_mode))) {
            if (errno == EEXIST)
                errno = ENOTDIR;
            return -1;
        }
        *s = c;
        if (!c)
            return 0;
        while (s[1] == '/')
            s++;
    }
}
