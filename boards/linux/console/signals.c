/* SPDX-License-Identifier: MIT */
/* Fatal and terminating signals: run every registered restore function
 * (the display's backend and console restore: async-signal-safe calls
 * only), then hand the signal to whoever had it before, so the exit status
 * still names the signal. Knows nothing of displays or DRM. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <errno.h>
#include <signal.h>
#include <stddef.h>
#include <string.h>

#include "console_int.h"

/* Signal handlers can only find state through globals; this table is the
 * one piece of mutable global state of the boards side (with vt.c's switch
 * pipe). fn is written last on register and cleared first on unregister. */
/* one per open display (display.c opens at most 8), with room to spare: a
 * registration past the end would leave that display without crash restore */
#define MAX_RESTORES 16
static void (*volatile restore_fn[MAX_RESTORES])(void *user);
static void *volatile restore_user[MAX_RESTORES];
static volatile sig_atomic_t restoring;
static int installed;

static const int fatal_sigs[] = {SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL};
static const int term_sigs[] = {SIGINT, SIGTERM, SIGHUP};
static struct sigaction old_act[65];
static unsigned char ours[65];

static void restore_all(void)
{
    if (restoring)
        return;
    restoring = 1;
    for (int i = 0; i < MAX_RESTORES; i++) {
        void (*fn)(void *) = restore_fn[i];
        if (fn)
            fn(restore_user[i]);
    }
}

static void on_signal(int sig, siginfo_t *si, void *uc)
{
    int saved_errno = errno;
    restore_all();
    /* Hand the signal to whoever had it before: the default action (so the
     * exit status still says SIGSEGV/SIGTERM), or a chained handler such as
     * a sanitizer's. Returning from a synchronous fault re-executes the
     * faulting instruction under the restored action. */
    sigaction(sig, &old_act[sig], NULL);
    ours[sig] = 0;
    if (old_act[sig].sa_flags & SA_SIGINFO) {
        if (old_act[sig].sa_sigaction)
            old_act[sig].sa_sigaction(sig, si, uc);
    } else if (old_act[sig].sa_handler == SIG_DFL) {
        if (sig != SIGSEGV && sig != SIGBUS && sig != SIGFPE && sig != SIGILL)
            raise(sig);
    } else if (old_act[sig].sa_handler != SIG_IGN) {
        old_act[sig].sa_handler(sig);
    }
    errno = saved_errno;
}

static void install(int sig, int only_if_default)
{
    struct sigaction sa, cur;
    if (sigaction(sig, NULL, &cur) < 0)
        return;
    /* A program (or event loop) that handles SIGINT/SIGTERM/SIGHUP itself
     * closes the display on its own; only the default "die" needs help. */
    if (only_if_default && (cur.sa_flags & SA_SIGINFO || cur.sa_handler != SIG_DFL))
        return;
    memset(&sa, 0, sizeof sa);
    sa.sa_sigaction = on_signal;
    sa.sa_flags = SA_SIGINFO | SA_NODEFER;
    sigemptyset(&sa.sa_mask);
    if (sigaction(sig, &sa, &old_act[sig]) == 0)
        ours[sig] = 1;
}

static void uninstall_all(void)
{
    for (int s = 1; s < 65; s++)
        if (ours[s]) {
            sigaction(s, &old_act[s], NULL);
            ours[s] = 0;
        }
    installed = 0;
}

void fx_signals_register(void (*restore)(void *user), void *user)
{
    for (int i = 0; i < MAX_RESTORES; i++)
        if (!restore_fn[i]) {
            restore_user[i] = user;
            restore_fn[i] = restore;
            break;
        }
    if (!installed) {
        installed = 1;
        restoring = 0;
        for (size_t i = 0; i < sizeof fatal_sigs / sizeof fatal_sigs[0]; i++)
            install(fatal_sigs[i], 0);
        for (size_t i = 0; i < sizeof term_sigs / sizeof term_sigs[0]; i++)
            install(term_sigs[i], 1);
    }
}

void fx_signals_unregister(void (*restore)(void *user), void *user)
{
    int left = 0;
    for (int i = 0; i < MAX_RESTORES; i++) {
        if (restore_fn[i] == restore && restore_user[i] == user) {
            restore_fn[i] = NULL;
            restore_user[i] = NULL;
        }
        if (restore_fn[i])
            left = 1;
    }
    if (!left && installed)
        uninstall_all();
}
