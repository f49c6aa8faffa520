/* SPDX-License-Identifier: MIT */
/* kiosk_power.h: schedules, idle blanking, waking touches. */
#include "kiosk_power.h"

/* A dark screen woken by a touch and no idle= set: this long. */
#define KIOSK_WAKE_DEFAULT_MS 60000

static int in_window(const kiosk_sched *s, int wday, int min)
{
    int prev = (wday + 6) % 7;
    if (s->off_min > s->on_min)
        return (s->days >> wday & 1u) && min >= s->on_min && min < s->off_min;
    /* past midnight: the evening of a listed day or the morning after one */
    return ((s->days >> wday & 1u) && min >= s->on_min) || ((s->days >> prev & 1u) && min < s->off_min);
}

int kiosk_sched_on(const kiosk_sched *s, int n, int wday, int min)
{
    if (n <= 0) return 1;
    for (int i = 0; i < n; i++)
        if (in_window(&s[i], wday, min)) return 1;
    return 0;
}

void kiosk_power_init(kiosk_power *p, int64_t idle_ms, int64_t now)
{
    p->idle_ms = idle_ms > 0 ? idle_ms : 0;
    p->last_input = now;
    p->wake_until = 0;
    p->sched_last = -1;
    p->manual = -1;
    p->idle_off = 0;
    p->on = 1;
}

int kiosk_power_want(kiosk_power *p, int64_t now, int sched_on)
{
    if (sched_on != p->sched_last) {
        /* a schedule edge ends a manual override and starts a fresh idle period */
        if (p->sched_last >= 0) p->manual = -1;
        p->sched_last = sched_on;
        p->last_input = now;
        p->idle_off = 0;
    }
    int base = p->manual >= 0 ? p->manual : sched_on;
    if (base && p->idle_ms && now - p->last_input >= p->idle_ms) p->idle_off = 1;
    p->on = (base && !p->idle_off) || now < p->wake_until;
    return p->on;
}

int kiosk_power_input(kiosk_power *p, int64_t now)
{
    int dark = !p->on;
    p->last_input = now;
    p->idle_off = 0;
    int base = p->manual >= 0 ? p->manual : p->sched_last != 0;
    /* at night a touch lights it for a while; use keeps it lit */
    if (!base && (dark || now < p->wake_until))
        p->wake_until = now + (p->idle_ms ? p->idle_ms : KIOSK_WAKE_DEFAULT_MS);
    p->on = 1;
    return dark;
}

void kiosk_power_manual(kiosk_power *p, int on, int64_t now)
{
    p->manual = on != 0;
    p->last_input = now;
    p->idle_off = 0;
    p->wake_until = 0;
    p->on = p->manual;
}
