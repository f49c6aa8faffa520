/* SPDX-License-Identifier: MIT */
/* Helpers for programs that run inside the qemu guest (see ../README.md for
 * the marker protocol). Header-only so each guest program stays one .c file. */
#ifndef FIXEL_GUEST_H
#define FIXEL_GUEST_H

#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include <sys/wait.h>

#include "fixel/display.h"
#include "fixel/env.h"
#include "fixel/error.h"

static int guest_failed;

/* CHECK <name> PASS|FAIL <detail>: one result line for the host. */
static void guest_check(const char *name, int ok, const char *fmt, ...)
    __attribute__((format(printf, 3, 4), unused));
static void guest_check(const char *name, int ok, const char *fmt, ...)
{
    char detail[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(detail, sizeof detail, fmt, ap);
    va_end(ap);
    if (!ok)
        guest_failed = 1;
    printf("CHECK %s %s %s\n", name, ok ? "PASS" : "FAIL", detail);
    fflush(stdout);
}

/* fx_display_open, its failure reported as CHECK <name> FAIL "open: <why>";
 * returns what fx_display_open returned. */
static int guest_open(const char *name, fx_display **d, const fx_display_options *o) __attribute__((unused));
static int guest_open(const char *name, fx_display **d, const fx_display_options *o)
{
    int r = fx_display_open(d, o);
    if (r < 0)
        guest_check(name, 0, "open: %s", fx_strerror(r));
    return r;
}

/* Send a request marker and wait for the host's "ACK <word>" line on
 * stdin; returns 1 when the word is PASS or OK. */
static int guest_request(const char *fmt, ...) __attribute__((format(printf, 1, 2), unused));
static int guest_request(const char *fmt, ...)
{
    char line[256];
    va_list ap;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    printf("\n");
    fflush(stdout);
    while (fgets(line, sizeof line, stdin)) {
        if (!strncmp(line, "ACK ", 4))
            return !strncmp(line + 4, "PASS", 4) || !strncmp(line + 4, "OK", 2);
    }
    return 0;
}

/* The library's log: echoed to the console (the serial log shows it) and
 * kept in logbuf for checks on what it said; errors are counted. */
static char logbuf[8192] __attribute__((unused));
static int log_errors __attribute__((unused));
static void capture_log(fx_log_priority p, void *user, const char *fmt, va_list ap)
    __attribute__((unused));
static void capture_log(fx_log_priority p, void *user, const char *fmt, va_list ap)
{
    (void)user;
    char line[512];
    vsnprintf(line, sizeof line, fmt, ap);
    printf("  log(%d): %s\n", (int)p, line);
    size_t l = strlen(logbuf);
    snprintf(logbuf + l, sizeof logbuf - l, "%s\n", line);
    if (p == FX_LOG_ERROR)
        log_errors++;
}

static void msleep(int ms) __attribute__((unused));
static void msleep(int ms)
{
    struct timespec t = {ms / 1000, (long)(ms % 1000) * 1000000L};
    nanosleep(&t, NULL);
}

/* Small sysfs/configfs helpers: 0 or -errno (-EIO for a short write). */
static int write_file(const char *path, const char *s) __attribute__((unused));
static int write_file(const char *path, const char *s)
{
    int fd = open(path, O_WRONLY);
    if (fd < 0)
        return -errno;
    ssize_t n = write(fd, s, strlen(s));
    int e = errno;
    close(fd);
    if (n < 0)
        return -e;
    return n == (ssize_t)strlen(s) ? 0 : -EIO;
}

/* The whole file (up to n - 1 bytes); buf is "" when it cannot be read. */
static int read_file(const char *path, char *buf, size_t n) __attribute__((unused));
static int read_file(const char *path, char *buf, size_t n)
{
    buf[0] = 0;
    int fd = open(path, O_RDONLY);
    if (fd < 0)
        return -errno;
    ssize_t r = read(fd, buf, n - 1);
    int e = errno;
    close(fd);
    if (r < 0)
        return -e;
    buf[r] = 0;
    return 0;
}

/* The first line of a file, as sysfs attributes are read. */
static int read_line(const char *path, char *buf, size_t n) __attribute__((unused));
static int read_line(const char *path, char *buf, size_t n)
{
    int r = read_file(path, buf, n);
    buf[strcspn(buf, "\n")] = 0;
    return r;
}


/* Run fn in a forked child (DRM master, console state and crashes stay
 * there); returns its wait status. */
static int guest_in_child(void (*fn)(void *), void *arg) __attribute__((unused));
static int guest_in_child(void (*fn)(void *), void *arg)
{
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
        fn(arg);
        fflush(stdout);
        _exit(guest_failed);
    }
    int st = 0;
    waitpid(pid, &st, 0);
    return st;
}

/* The whole line of text containing needle (copied into line), or NULL. */
static const char *guest_line_with(const char *text, const char *needle, char *line, size_t n)
    __attribute__((unused));
static const char *guest_line_with(const char *text, const char *needle, char *line, size_t n)
{
    const char *p = strstr(text, needle);
    if (!p)
        return NULL;
    while (p > text && p[-1] != '\n')
        p--;
    size_t l = strcspn(p, "\n");
    snprintf(line, n, "%.*s", (int)(l < n ? l : n - 1), p);
    return p;
}

/* insmod every module a list (/modules.optional, /modules.cards) names,
 * in order, skipping those already loaded (a helper two lists share);
 * detail lists what was loaded, "(failed)" after a refusal. Returns how
 * many were loaded, -1 without the list. */
static int guest_load_modules(const char *list, char *detail, size_t n) __attribute__((unused));
static int guest_load_modules(const char *list, char *detail, size_t n)
{
    FILE *f = fopen(list, "r");
    char line[200], cmd[300], mod[200], sys[240];
    int loaded = 0;
    detail[0] = 0;
    if (!f) {
        snprintf(detail, n, "no %s", list);
        return -1;
    }
    while (fgets(line, sizeof line, f)) {
        line[strcspn(line, "\n")] = 0;
        if (!*line)
            continue;
        const char *b = strrchr(line, '/');
        snprintf(mod, sizeof mod, "%s", b ? b + 1 : line);
        mod[strcspn(mod, ".")] = 0;
        for (char *q = mod; *q; q++)
            if (*q == '-')
                *q = '_';
        snprintf(sys, sizeof sys, "/sys/module/%s", mod);
        if (access(sys, F_OK) == 0)
            continue;
        snprintf(cmd, sizeof cmd, "insmod /lib/modules/%s 2>&1", line);
        int st = system(cmd);
        size_t l = strlen(detail);
        snprintf(detail + l, n - l, "%s%s%s", l ? " " : "", line, st == 0 ? "" : "(failed)");
        loaded += st == 0;
    }
    fclose(f);
    return loaded;
}

#endif
