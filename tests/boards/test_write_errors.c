/* SPDX-License-Identifier: MIT */
/* Picture writes onto an existing file the caller may not write fail with
 * that file's own error (EACCES) and leave it untouched, instead of the
 * temporary file's or rename's error; and fx_built_without says what this
 * build left out, consistently with the flags it was compiled with. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "fixel/error.h"
#include "fixel/memfb.h"
#include "fx_test.h"

/* Writes the picture as a user who may not write the file: the caller when
 * it is not root (a 0444 file of its own), else a child that becomes
 * nobody (a root-owned 0644 file in a sticky world-writable folder, where
 * the temporary file can be created but rename fails with EPERM). Returns
 * the write's result. */
static int write_unwritable(const char *dir, const char *name, int png)
{
    uint8_t px[4 * 4 * 4] = {0};
    fx_surface s;
    fx_surface_init(&s, px, 4, 4, 16, FX_FMT_XRGB8888);
    char path[512];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    if (!f)
        return 1;
    fputs("old", f);
    fclose(f);
    if (getuid() != 0) {
        chmod(path, 0444);
        return png ? fx_write_png(path, &s) : fx_write_ppm(path, &s);
    }
    chmod(dir, 01777);
    chmod(path, 0644);
    pid_t pid = fork();
    if (pid == 0) {
        if (setgid(65534) != 0 || setuid(65534) != 0)
            _exit(200);
        int r = png ? fx_write_png(path, &s) : fx_write_ppm(path, &s);
        _exit(r == -EACCES ? 0 : r == 0 ? 100 : 101);
    }
    int st = 0;
    waitpid(pid, &st, 0);
    return WIFEXITED(st) && WEXITSTATUS(st) == 0 ? -EACCES : -WEXITSTATUS(st);
}

static int still_old(const char *dir, const char *name)
{
    char path[512], buf[8] = {0};
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "r");
    if (!f)
        return 0;
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    return n == 3 && !strcmp(buf, "old");
}

FX_TEST(write_unwritable_file_reports_eacces)
{
    char dir[] = "/tmp/fixel-wr-XXXXXX";
    FX_CHECK(mkdtemp(dir) != NULL);
    FX_CHECK_EQ(write_unwritable(dir, "a.ppm", 0), -EACCES);
    FX_CHECK(still_old(dir, "a.ppm"));
#ifndef FX_NO_PNG
    FX_CHECK_EQ(write_unwritable(dir, "b.png", 1), -EACCES);
    FX_CHECK(still_old(dir, "b.png"));
#endif
    char cmd[600];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    FX_CHECK_EQ(system(cmd), 0);
}

/* Each library's name is in fx_built_without() exactly when the build's
 * macro says it was left out. */
#ifdef FX_NO_PNG
#define WITHOUT_PNG 1
#else
#define WITHOUT_PNG 0
#endif
#ifdef FX_NO_BOARD_LIBS
#define WITHOUT_OPT 1
#else
#define WITHOUT_OPT 0
#endif
#ifdef FX_NO_TEXT
#define WITHOUT_TEXT 1
#else
#define WITHOUT_TEXT 0
#endif
#ifdef FX_NO_JPEG
#define WITHOUT_JPEG 1
#else
#define WITHOUT_JPEG 0
#endif
#ifdef FX_NO_GIF
#define WITHOUT_GIF 1
#else
#define WITHOUT_GIF 0
#endif
#ifdef FX_NO_WEBP
#define WITHOUT_WEBP 1
#else
#define WITHOUT_WEBP 0
#endif

FX_TEST(built_without_matches_the_build)
{
    static const struct {
        const char *name;
        int without;
    } libs[] = {
        {"libdrm/libevdev/libgpiod", WITHOUT_OPT},
        {"libpng", WITHOUT_PNG},
        {"FreeType/HarfBuzz/FriBiDi/fontconfig/libunibreak", WITHOUT_TEXT},
        {"libjpeg", WITHOUT_JPEG},
        {"giflib", WITHOUT_GIF},
        {"libwebp", WITHOUT_WEBP},
    };
    const char *w = fx_built_without();
    FX_CHECK(w != NULL);
    for (size_t i = 0; i < sizeof libs / sizeof libs[0]; i++)
        FX_CHECK_MSG((strstr(w, libs[i].name) != NULL) == libs[i].without, "%s in '%s'", libs[i].name, w);
    FX_CHECK_EQ(strlen(fx_built_without_hint(-FX_ENOTSUP)) > 0, WITHOUT_PNG);
    if (WITHOUT_PNG)
        FX_CHECK(strstr(fx_built_without_hint(-FX_ENOTSUP), "libpng-dev") != NULL);
    /* no separator at either end, none doubled */
    FX_CHECK(w[0] != '/' && (!*w || w[strlen(w) - 1] != '/') && !strstr(w, "//"));
    FX_CHECK_EQ(strlen(fx_built_without_hint(-FX_EINVAL)), 0);
}
