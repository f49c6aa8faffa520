/* SPDX-License-Identifier: MIT */
/* fixel/files.h (issue #40): user-named inputs are regular files, opened
 * without blocking on a FIFO; outputs never open or replace a FIFO, a
 * device or a directory. Each case runs under alarm(): a blocking open
 * would kill the test run instead of hanging it. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "fixel/files.h"
#include "fx_test.h"

static char dir[64], fifo[96], reg[96];

static void setup(void)
{
    snprintf(dir, sizeof dir, "/tmp/fx_files_%d", (int)getpid());
    mkdir(dir, 0700);
    snprintf(fifo, sizeof fifo, "%s/fifo", dir);
    snprintf(reg, sizeof reg, "%s/reg", dir);
    unlink(fifo);
    mkfifo(fifo, 0600);
    FILE *f = fopen(reg, "w");
    fputs("hello\n", f);
    fclose(f);
}

static void teardown(void)
{
    unlink(fifo);
    unlink(reg);
    rmdir(dir);
}

FX_TEST(files_inputs_are_regular_and_never_block)
{
    setup();
    alarm(10);
    char why[128];
    int64_t size = -1;
    errno = 0;
    FX_CHECK_EQ(fx_open_regular(fifo, &size, why, sizeof why), -1);
    FX_CHECK_EQ(errno, EOPNOTSUPP);
    FX_CHECK_MSG(!strcmp(why, "is a FIFO, not a regular file"), "%s", why);
    FX_CHECK(fx_fopen_regular(dir, NULL, why, sizeof why) == NULL);
    FX_CHECK_EQ(errno, EISDIR);
    FX_CHECK_MSG(!strcmp(why, "is a directory, not a regular file"), "%s", why);
    FX_CHECK(fx_fopen_regular("/dev/null", NULL, why, sizeof why) == NULL);
    FX_CHECK_MSG(!strcmp(why, "is a character device, not a regular file"), "%s", why);
    FX_CHECK(fx_fopen_regular("/nonexistent/x", NULL, why, sizeof why) == NULL);
    FX_CHECK_EQ(errno, ENOENT);
    FX_CHECK(fx_fopen_regular("", NULL, NULL, 0) == NULL);
    FILE *f = fx_fopen_regular(reg, &size, why, sizeof why);
    FX_CHECK(f != NULL && size == 6);
    if (f) {
        char b[8] = "";
        FX_CHECK(fgets(b, sizeof b, f) && !strcmp(b, "hello\n"));
        FX_CHECK(!(fcntl(fileno(f), F_GETFL) & O_NONBLOCK)); /* reads block again */
        fclose(f);
    }
    alarm(0);
    teardown();
}

FX_TEST(files_outputs_never_open_or_replace_special_files)
{
    setup();
    alarm(10);
    char why[128];
    /* a FIFO with no reader, then with one: both refused, neither blocks */
    FX_CHECK(fx_fopen_regular_write(fifo, 0, why, sizeof why) == NULL);
    FX_CHECK_MSG(!strcmp(why, "is a FIFO, not a regular file"), "%s", why);
    int rd = open(fifo, O_RDONLY | O_NONBLOCK);
    FX_CHECK(fx_fopen_regular_write(fifo, 1, why, sizeof why) == NULL);
    FX_CHECK_MSG(!strcmp(why, "is a FIFO, not a regular file"), "%s", why);
    /* and was not even opened: a writer that came and went would have
     * handed the reader a hang-up (Linux reports POLLHUP only once a
     * writer has connected since the reader opened) */
    struct pollfd pfd = {rd, POLLIN, 0};
    FX_CHECK(poll(&pfd, 1, 0) >= 0);
    FX_CHECK_MSG(!(pfd.revents & POLLHUP), "the FIFO's reader saw a writer come and go (revents %#x)", pfd.revents);
    close(rd);
    FX_CHECK(fx_fopen_regular_write(dir, 0, why, sizeof why) == NULL);
    FX_CHECK_EQ(errno, EISDIR);
    FX_CHECK(fx_fopen_regular_write("/dev/null", 0, why, sizeof why) == NULL);
    FX_CHECK_EQ(errno, EOPNOTSUPP);
    struct stat st;
    FX_CHECK(stat(fifo, &st) == 0 && S_ISFIFO(st.st_mode));
    /* rename targets */
    FX_CHECK_EQ(fx_check_replaceable(fifo, why, sizeof why), -1);
    FX_CHECK_MSG(!strcmp(why, "is a FIFO, not a regular file"), "%s", why);
    FX_CHECK_EQ(fx_check_replaceable("/dev/null", why, sizeof why), -1);
    FX_CHECK_EQ(fx_check_replaceable(dir, why, sizeof why), -1);
    FX_CHECK_EQ(fx_check_replaceable(reg, why, sizeof why), 0);
    char missing[128];
    snprintf(missing, sizeof missing, "%s/new", dir);
    FX_CHECK_EQ(fx_check_replaceable(missing, why, sizeof why), 0);
    /* regular files: truncated, or appended to, or created */
    FILE *f = fx_fopen_regular_write(reg, 1, why, sizeof why);
    FX_CHECK(f != NULL);
    if (f) {
        fputs("more\n", f);
        fclose(f);
    }
    FX_CHECK(stat(reg, &st) == 0 && st.st_size == 11);
    f = fx_fopen_regular_write(reg, 0, why, sizeof why);
    FX_CHECK(f != NULL);
    if (f) {
        fputs("x", f);
        fclose(f);
    }
    FX_CHECK(stat(reg, &st) == 0 && st.st_size == 1);
    f = fx_fopen_regular_write(missing, 0, why, sizeof why);
    FX_CHECK(f != NULL);
    if (f)
        fclose(f);
    FX_CHECK(stat(missing, &st) == 0 && S_ISREG(st.st_mode));
    unlink(missing);
    alarm(0);
    teardown();
}

/* fx_mkdir_parents: the tools' mkdir -p (fixel-demo and fixel-kiosk used
 * copies of their own before). */
FX_TEST(files_mkdir_parents)
{
    setup();
    char deep[160], p[200];
    snprintf(deep, sizeof deep, "%s/a//b/c/", dir);
    FX_CHECK_EQ(fx_mkdir_parents(deep), 0);
    snprintf(p, sizeof p, "%s/a/b/c", dir);
    struct stat st;
    FX_CHECK(stat(p, &st) == 0 && S_ISDIR(st.st_mode));
    FX_CHECK_EQ(fx_mkdir_parents(deep), 0); /* already there */
    /* a part that is a file: ENOTDIR, nothing made below it */
    snprintf(p, sizeof p, "%s/x", reg);
    errno = 0;
    FX_CHECK_EQ(fx_mkdir_parents(p), -1);
    FX_CHECK_EQ(errno, ENOTDIR);
    /* longer than PATH_MAX */
    char *big = malloc(5000);
    memset(big, 'a', 4999);
    big[4999] = 0;
    errno = 0;
    FX_CHECK_EQ(fx_mkdir_parents(big), -1);
    FX_CHECK_EQ(errno, ENAMETOOLONG);
    free(big);
    snprintf(p, sizeof p, "%s/a/b/c", dir);
    rmdir(p);
    snprintf(p, sizeof p, "%s/a/b", dir);
    rmdir(p);
    snprintf(p, sizeof p, "%s/a", dir);
    rmdir(p);
    teardown();
}
