/* SPDX-License-Identifier: MIT */
/* fixel-demo's orbit-of-0 overlay (tools/fixel-demo/orbit.c): the line it
 * prints names the classification fx_orbit0 gives, with the first values. */
#include <string.h>

#include "fx_test.h"
#include "../../tools/fixel-demo/orbit.c"

static fx56 zre[1000], zim[1000];

static void check_orbit(fx56 cre, fx56 cim, int kind, const char *what, const char *first)
{
    fx_orbit0_info info, core;
    char head[96], vals[96];
    FX_CHECK_EQ(demo_orbit_text(cre, cim, zre, zim, 1000, &info, head, sizeof head, vals, sizeof vals), kind);
    FX_CHECK_EQ(fx_orbit0(cre, cim, 1000, NULL, NULL, &core), kind);
    FX_CHECK_EQ((int)info.kind, (int)core.kind);
    FX_CHECK_EQ(info.period, core.period);
    FX_CHECK_MSG(strstr(head, what) != NULL, "'%s' lacks '%s'", head, what);
    FX_CHECK_MSG(!strncmp(vals, first, strlen(first)), "'%s' does not start '%s'", vals, first);
}

FX_TEST(demo_orbit_text_names_the_core_classification)
{
    check_orbit(0, 0, FX_ORBIT0_FIXED, "c = +0.000 +0.000i: fixed point", "z1..: 0.00+0.00i 0.00+0.00i");
    check_orbit(-FX56_ONE, 0, FX_ORBIT0_CYCLE, "c = -1.000 +0.000i: cycle of period 2",
                "z1..: -1.00+0.00i 0.00+0.00i -1.00+0.00i 0.00+0.00i ...");
    /* 0, 1, 2, 5: |z3| > 2 */
    check_orbit(FX56_ONE, 0, FX_ORBIT0_ESCAPES, "c = +1.000 +0.000i: explodes (|z3| > 2)",
                "z1..: 1.00+0.00i 2.00+0.00i 5.00+0.00i");
    /* Douady's rabbit, the page's headless c: its attracting 3-cycle */
    check_orbit(-FX56_ONE / 8, 3 * FX56_ONE / 4, FX_ORBIT0_CYCLE, "cycle of period 3", "z1..: -0.12+0.75i");
    char head[8], vals[8];
    fx_orbit0_info info;
    /* truncated buffers stay terminated */
    FX_CHECK_EQ(demo_orbit_text(-FX56_ONE, 0, zre, zim, 1000, &info, head, sizeof head, vals, sizeof vals),
                FX_ORBIT0_CYCLE);
    FX_CHECK_EQ(strlen(head), 7u);
    FX_CHECK_EQ(strlen(vals), 7u);
    FX_CHECK(demo_orbit_text(17 * FX56_ONE, 0, zre, zim, 1000, &info, head, sizeof head, vals, sizeof vals) < 0);
}
