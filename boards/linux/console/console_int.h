/* SPDX-License-Identifier: MIT */
/* Internal to boards/: the console layer (vt.c, signals.c). Above the
 * posix layer only: it knows no display and no backend. The display front
 * end hands in its logger and the acquire/release callbacks of VT
 * switching, and registers its own emergency restore with the signals.
 * Not installed. */
#ifndef FIXEL_CONSOLE_INT_H
#define FIXEL_CONSOLE_INT_H

#include "../../posix/posix_int.h"

typedef struct fx_vt fx_vt;

/* What VT switching asks of the program's display. */
typedef struct fx_vt_hooks {
    int (*release)(void *user); /* our VT is being left: 1 allows, 0 refuses */
    void (*acquire)(void *user); /* our VT is back on screen */
    void *user;
} fx_vt_hooks;

/* Console: switch to graphics and mute the keyboard; restore. deny_switch
 * only changes the log line (release decides). The logger and hooks are
 * copied. */
int fx_vt_enter(fx_vt **out, const fx_logger *log, int deny_switch, const fx_vt_hooks *hooks);
void fx_vt_leave(fx_vt *vt);
/* VT_PROCESS switching: the fd that becomes readable when a switch is
 * requested (-1 when switching is not handled), and the handler that reads
 * it and calls the hooks. NULL is accepted. */
int fx_vt_event_fd(const fx_vt *vt);
void fx_vt_handle_events(fx_vt *vt);
int fx_vt_number(const fx_vt *vt);
int fx_vt_activate(fx_vt *vt, int n);
/* The emergency path (async-signal-safe); NULL is accepted. */
void fx_vt_emergency_restore(fx_vt *vt);

/* Fatal/terminating-signal restoration: up to 8 functions, each run once
 * from the signal handler, so async-signal-safe. */
void fx_signals_register(void (*restore)(void *user), void *user);
void fx_signals_unregister(void (*restore)(void *user), void *user);

#endif
