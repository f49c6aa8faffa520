/* SPDX-License-Identifier: MIT */
/* Shared test helper: refline_lights (tests/lib/refline.h). */
#include "refline.h"

#include <stdlib.h>

int refline_lights(int32_t x0, int32_t y0, int32_t x1, int32_t y1, int64_t x, int64_t y)
{
    int64_t dx = (int64_t)x1 - x0, dy = (int64_t)y1 - y0;
    uint64_t adx = (uint64_t)llabs(dx), ady = (uint64_t)llabs(dy);
    int steep = ady > adx;
    uint64_t major = steep ? ady : adx, minor = steep ? adx : ady;
    int64_t a = steep ? y : x, a0 = steep ? y0 : x0, b = steep ? x : y, b0 = steep ? x0 : y0;
    int64_t sa = steep ? (dy > 0) - (dy < 0) : (dx > 0) - (dx < 0);
    int64_t sb = steep ? (dx > 0) - (dx < 0) : (dy > 0) - (dy < 0);
    int64_t k = sa ? (a - a0) * sa : (a == a0 ? 0 : -1);
    if (k < 0 || (uint64_t)k > major)
        return 0;
    uint64_t t = (uint64_t)k * minor; /* k, minor < 2^32 */
    uint64_t m = major ? t / major + (2 * (t % major) >= major) : 0;
    return b == b0 + sb * (int64_t)m;
}
