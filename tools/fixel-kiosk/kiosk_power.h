/* SPDX-License-Identifier: MIT */
/* When the kiosk's screen should be on: weekly schedules, idle blanking
 * and the touch that wakes it. Pure (the clock is passed in), so tests
 * drive it with made-up times; main.c feeds it the monotonic clock, the
 * local time of day and the input events, and switches the screen. */
#ifndef FIXEL_KIOSK_POWER_H
#define FIXEL_KIOSK_POWER_H

#include <stdint.h>

#define KIOSK_SCHED_MAX 8
/* On from on_min to off_min (minutes after midnight) on the days in the
 * mask (bit 0 Monday .. bit 6 Sunday); off_min <= on_min runs past
 * midnight into the next day. */
typedef struct kiosk_sched {
    int on_min, off_min;
    unsigned days;
} kiosk_sched;

/* 1 when a schedule has the screen on at weekday wday (0 Monday) and
 * minute min, 0 when none does; 1 with no schedules at all. */
int kiosk_sched_on(const kiosk_sched *s, int n, int wday, int min);

typedef struct kiosk_power {
    int64_t idle_ms;      /* 0: no idle blanking */
    int64_t last_input;   /* ms of the last input */
    int64_t wake_until;   /* a touch on a dark screen keeps it on until then */
    int sched_last;       /* the schedule's last verdict, -1 before the first */
    int manual;           /* -1, or 0/1 from set/screen until the schedule next changes */
    int idle_off;         /* dark because nobody touched it for idle_ms */
    int on;               /* the verdict of the last kiosk_power_want */
} kiosk_power;

void kiosk_power_init(kiosk_power *p, int64_t idle_ms, int64_t now);
/* The screen's state at now, given the schedule's verdict (kiosk_sched_on). */
int kiosk_power_want(kiosk_power *p, int64_t now, int sched_on);
/* A touch, click or key at now. Returns 1 when the screen was dark: the
 * event woke it and must not reach the widgets (no blind clicks). */
int kiosk_power_input(kiosk_power *p, int64_t now);
/* set/screen on|off: holds until the schedule next changes its verdict. */
void kiosk_power_manual(kiosk_power *p, int on, int64_t now);

#endif
