/* SPDX-License-Identifier: MIT */
/* fixel-demo — the text of the Fractals page's orbit-of-0 overlay: c, its
 * classification by fx_orbit0 (fixel/julia.h) and the first values, kept
 * apart from the drawing so tests/tools/test_demo_orbit.c can check it. */
#include <stdio.h>

#include "demo.h"

/* |parts| below 0.005 print as 0.00, never -0.00 */
static double two_places(fx56 v)
{
    double d = (double)v / (double)FX56_ONE;
    return d > -0.005 && d < 0.005 ? 0.0 : d;
}

int demo_orbit_text(fx56 cre, fx56 cim, fx56 *zre, fx56 *zim, uint32_t n, fx_orbit0_info *info, char *head,
                    size_t nhead, char *vals, size_t nvals)
{
    int kind = fx_orbit0(cre, cim, n, zre, zim, info);
    if (kind < 0) {
        snprintf(head, nhead, "orbit of 0: c out of range");
        snprintf(vals, nvals, "%s", "");
        return kind;
    }
    char what[40];
    switch (info->kind) {
    case FX_ORBIT0_ESCAPES: snprintf(what, sizeof what, "explodes (|z%u| > 2)", info->steps); break;
    case FX_ORBIT0_FIXED: snprintf(what, sizeof what, "fixed point"); break;
    case FX_ORBIT0_SPIRAL: snprintf(what, sizeof what, "spiral into a fixed point"); break;
    case FX_ORBIT0_CYCLE: snprintf(what, sizeof what, "cycle of period %d", info->period); break;
    default: snprintf(what, sizeof what, "bounded, no cycle found"); break;
    }
    snprintf(head, nhead, "orbit of 0, c = %+.3f %+.3fi: %s", (double)cre / (double)FX56_ONE,
             (double)cim / (double)FX56_ONE, what);
    /* z0 = 0 always: the line starts at z1 = c */
    size_t at = (size_t)snprintf(vals, nvals, "z1..:");
    for (uint32_t k = 1; k <= info->steps && k <= 4 && at < nvals; k++)
        at += (size_t)snprintf(vals + at, nvals - at, " %.2f%+.2fi", two_places(zre[k]), two_places(zim[k]));
    if (info->steps > 4 && at < nvals)
        snprintf(vals + at, nvals - at, " ...");
    return kind;
}
