/* SPDX-License-Identifier: MIT */
/* A replay (FIXEL_REPLAY) on a program that asks for its next frame from
 * every frame, as fixel-demo's animated pages do when a frame outlasts the
 * tick: a frame is then always due, and the replay, which used to run only
 * when none was, never advanced (the run hung; fixel-demo --display =anim
 * under load). Frames and replay statements must alternate. */
#include "fx_test.h"

#include "fixel/app.h"

#include <stdio.h>
#include <string.h>
#include <unistd.h>
#include <fcntl.h>
#include <sys/stat.h>

#include "fixel/error.h"

typedef struct {
    fx_app *app;
    int frames, keys;
    char typed[8];
} anim;

static void anim_draw(void *user)
{
    anim *s = user;
    s->frames++;
    fx_display *d = fx_app_display(s->app);
    fx_surface sf = fx_display_screen(d);
    fx_surface_clear(&sf, 0xFF000000u | (uint32_t)s->frames);
    fx_display_present(d, NULL, 0);
    fx_app_post_redisplay(s->app); /* the next frame, at once */
}

static void anim_key(void *user, unsigned char key, int x, int y)
{
    (void)x, (void)y;
    anim *s = user;
    if (s->keys < (int)sizeof s->typed - 1)
        s->typed[s->keys] = (char)key;
    s->keys++;
}

FX_TEST(replay_advances_while_a_frame_is_always_due)
{
    char path[64];
    snprintf(path, sizeof path, "/tmp/fixel-replay-anim-%d.txt", (int)getpid());
    FILE *f = fopen(path, "w");
    FX_CHECK(f != NULL);
    if (!f)
        return;
    fputs("device 0 keyboard\n"
          "ev 0 KEY KEY_A 1\nsyn 0\nev 0 KEY KEY_A 0\nsyn 0\nframe\n"
          "ev 0 KEY KEY_B 1\nsyn 0\nev 0 KEY KEY_B 0\nsyn 0\nframe\n"
          "ev 0 KEY KEY_C 1\nsyn 0\nev 0 KEY KEY_C 0\nsyn 0\nframe\n",
          f);
    fclose(f);
    fx_app_options o;
    fx_app_options_init(&o);
    o.display.backend = FX_BACKEND_MEMORY;
    o.display.memory_w = 32;
    o.display.memory_h = 24;
    o.display.log_priority = -1;
    o.replay = path;
    o.frames = 500; /* the old loop drew these and never read the replay */
    anim s;
    memset(&s, 0, sizeof s);
    FX_CHECK_EQ(fx_app_open(&s.app, &o), 0);
    if (s.app) {
        fx_callbacks cb;
        memset(&cb, 0, sizeof cb);
        cb.display = anim_draw;
        cb.keyboard = anim_key;
        fx_app_set_callbacks(s.app, &cb, &s);
        FX_CHECK_EQ(fx_app_main_loop(s.app), 0);
        fx_app_close(s.app);
    }
    unlink(path);
    FX_CHECK_MSG(s.keys == 3 && !strcmp(s.typed, "abc"), "keys %d '%s'", s.keys, s.typed);
    /* the end of the file ended the run, a few frames in, not the limit */
    FX_CHECK_MSG(s.frames >= 3 && s.frames < 20, "frames %d", s.frames);
}

/* Issue #40: FIXEL_REPLAY naming a FIFO opened (O_NONBLOCK) and then the
 * main loop's read blocked for as long as its writer stayed silent. A
 * replay is a regular file: a FIFO (here with a writer that never writes)
 * and a directory are refused when the program opens. */
FX_TEST(replay_is_a_regular_file)
{
    char fifo[64];
    snprintf(fifo, sizeof fifo, "/tmp/fixel-replay-fifo-%d", (int)getpid());
    unlink(fifo);
    FX_CHECK_EQ(mkfifo(fifo, 0600), 0);
    int writer = open(fifo, O_RDWR | O_NONBLOCK);
    FX_CHECK(writer >= 0);
    const char *paths[] = {fifo, "/tmp"};
    const int want[] = {-FX_ENOTSUP, -FX_EISDIR};
    for (int i = 0; i < 2; i++) {
        fx_app_options o;
        fx_app_options_init(&o);
        o.display.backend = FX_BACKEND_MEMORY;
        o.display.memory_w = 8;
        o.display.memory_h = 8;
        o.display.log_priority = -1;
        o.replay = paths[i];
        fx_app *app = NULL;
        int r = fx_app_open(&app, &o);
        FX_CHECK_MSG(r == want[i], "replay %s: %d", paths[i], r);
        if (r == 0 && app)
            fx_app_close(app);
    }
    close(writer);
    unlink(fifo);
}
