/* SPDX-License-Identifier: MIT */
/* fixel-kiosk's screen schedule and idle blanking (tools/fixel-kiosk/
 * kiosk_power.c) on a made-up clock: the transitions, and that the touch
 * that wakes a dark screen is swallowed while the next one is delivered. */
#include <stddef.h>

#include "fx_test.h"

#include "../../tools/fixel-kiosk/kiosk_power.c"

#define MON 0
#define THU 3
#define FRI 4
#define SAT 5
#define HM(h, m) ((h) * 60 + (m))
#define MIN_MS 60000LL

FX_TEST(kiosk_sched_weekday_window)
{
    kiosk_sched s = {HM(7, 0), HM(22, 30), 0x1f}; /* mon-fri */
    FX_CHECK_EQ(kiosk_sched_on(&s, 1, MON, HM(6, 59)), 0);
    FX_CHECK_EQ(kiosk_sched_on(&s, 1, MON, HM(7, 0)), 1);
    FX_CHECK_EQ(kiosk_sched_on(&s, 1, FRI, HM(22, 29)), 1);
    FX_CHECK_EQ(kiosk_sched_on(&s, 1, FRI, HM(22, 30)), 0);
    FX_CHECK_EQ(kiosk_sched_on(&s, 1, SAT, HM(12, 0)), 0);
    FX_CHECK_EQ(kiosk_sched_on(NULL, 0, SAT, HM(3, 0)), 1); /* no schedule: always on */
}

FX_TEST(kiosk_sched_past_midnight_and_several)
{
    kiosk_sched s[2] = {{HM(22, 0), HM(6, 0), 1u << FRI}, {HM(12, 0), HM(13, 0), 1u << SAT}};
    FX_CHECK_EQ(kiosk_sched_on(s, 2, FRI, HM(23, 0)), 1);
    FX_CHECK_EQ(kiosk_sched_on(s, 2, SAT, HM(5, 59)), 1); /* Friday's night */
    FX_CHECK_EQ(kiosk_sched_on(s, 2, SAT, HM(6, 0)), 0);
    FX_CHECK_EQ(kiosk_sched_on(s, 2, FRI, HM(5, 0)), 0);  /* Thursday is not listed */
    FX_CHECK_EQ(kiosk_sched_on(s, 2, THU, HM(23, 0)), 0);
    FX_CHECK_EQ(kiosk_sched_on(s, 2, SAT, HM(12, 30)), 1);
    /* Sunday night runs into Monday morning */
    kiosk_sched sun = {HM(20, 0), HM(2, 0), 1u << 6};
    FX_CHECK_EQ(kiosk_sched_on(&sun, 1, MON, HM(1, 0)), 1);
}

FX_TEST(kiosk_idle_blank_and_swallowed_wake)
{
    kiosk_power p;
    kiosk_power_init(&p, 10 * MIN_MS, 0);
    FX_CHECK_EQ(kiosk_power_want(&p, 0, 1), 1);
    FX_CHECK_EQ(kiosk_power_input(&p, 5 * MIN_MS), 0); /* lit: delivered */
    FX_CHECK_EQ(kiosk_power_want(&p, 15 * MIN_MS - 1, 1), 1);
    FX_CHECK_EQ(kiosk_power_want(&p, 15 * MIN_MS, 1), 0); /* ten minutes after the last touch */
    FX_CHECK_EQ(kiosk_power_want(&p, 20 * MIN_MS, 1), 0);
    FX_CHECK_EQ(kiosk_power_input(&p, 20 * MIN_MS), 1);  /* the waking touch: swallowed */
    FX_CHECK_EQ(kiosk_power_want(&p, 20 * MIN_MS + 1, 1), 1);
    FX_CHECK_EQ(kiosk_power_input(&p, 20 * MIN_MS + 300), 0); /* the next one is a click */
    FX_CHECK_EQ(kiosk_power_want(&p, 30 * MIN_MS + 299, 1), 1);
    FX_CHECK_EQ(kiosk_power_want(&p, 30 * MIN_MS + 300, 1), 0);
}

FX_TEST(kiosk_schedule_edges_manual_and_night_touch)
{
    kiosk_power p;
    kiosk_power_init(&p, 0, 0); /* no idle blanking */
    FX_CHECK_EQ(kiosk_power_want(&p, 0, 1), 1);
    FX_CHECK_EQ(kiosk_power_want(&p, 100 * MIN_MS, 1), 1); /* never blanks by itself */
    FX_CHECK_EQ(kiosk_power_want(&p, 101 * MIN_MS, 0), 0); /* the schedule's off */
    /* a touch at night: swallowed, lights it for a minute (no idle=) */
    FX_CHECK_EQ(kiosk_power_input(&p, 102 * MIN_MS), 1);
    FX_CHECK_EQ(kiosk_power_want(&p, 103 * MIN_MS - 1, 0), 1);
    FX_CHECK_EQ(kiosk_power_input(&p, 102 * MIN_MS + 500), 0); /* in use: delivered, kept lit */
    FX_CHECK_EQ(kiosk_power_want(&p, 103 * MIN_MS + 499, 0), 1);
    FX_CHECK_EQ(kiosk_power_want(&p, 103 * MIN_MS + 500, 0), 0);
    /* set/screen on at night holds until the schedule changes */
    kiosk_power_manual(&p, 1, 110 * MIN_MS);
    FX_CHECK_EQ(kiosk_power_want(&p, 200 * MIN_MS, 0), 1);
    FX_CHECK_EQ(kiosk_power_want(&p, 201 * MIN_MS, 1), 1);
    kiosk_power_manual(&p, 0, 202 * MIN_MS);
    FX_CHECK_EQ(kiosk_power_want(&p, 203 * MIN_MS, 1), 0);
    FX_CHECK_EQ(kiosk_power_want(&p, 204 * MIN_MS, 0), 0); /* edge: back to the schedule */
    FX_CHECK_EQ(kiosk_power_want(&p, 205 * MIN_MS, 1), 1);
}
