/* SPDX-License-Identifier: MIT */
/* Doubles here: this is a tool, and the fit runs once. The library reads
 * the result as integers (tslib's pointercal). */
#include <math.h>

#include "fit.h"

int cal_fit(const cal_point *p, int n, double a[6])
{
    if (n < 3)
        return -1;
    /* centred sums keep large raw ranges (0..65535) well conditioned */
    double mx = 0, my = 0, msx = 0, msy = 0;
    for (int i = 0; i < n; i++) {
        mx += p[i].rx;
        my += p[i].ry;
        msx += p[i].sx;
        msy += p[i].sy;
    }
    mx /= n, my /= n, msx /= n, msy /= n;
    double xx = 0, xy = 0, yy = 0, xs = 0, ys = 0, xt = 0, yt = 0;
    for (int i = 0; i < n; i++) {
        double x = p[i].rx - mx, y = p[i].ry - my, s = p[i].sx - msx, t = p[i].sy - msy;
        xx += x * x, xy += x * y, yy += y * y;
        xs += x * s, ys += y * s, xt += x * t, yt += y * t;
    }
    double det = xx * yy - xy * xy;
    /* relative test: collinear raw points leave det ~ 0 next to xx*yy */
    if (!(fabs(det) > 1e-9 * xx * yy) || xx <= 0 || yy <= 0)
        return -1;
    a[0] = (xs * yy - ys * xy) / det;
    a[1] = (ys * xx - xs * xy) / det;
    a[3] = (xt * yy - yt * xy) / det;
    a[4] = (yt * xx - xt * xy) / det;
    a[2] = msx - a[0] * mx - a[1] * my;
    a[5] = msy - a[3] * mx - a[4] * my;
    return 0;
}

int cal_pointercal(const double a[6], int32_t out[7])
{
    for (int i = 0; i < 6; i++) {
        double v = nearbyint(a[i] * 65536.0);
        if (!(v > -2147483648.0 && v < 2147483647.0))
            return -1;
        out[i] = (int32_t)v;
    }
    out[6] = 65536;
    return 0;
}

void cal_apply(const int32_t c[7], int32_t rx, int32_t ry, int32_t *sx, int32_t *sy)
{
    *sx = (int32_t)(((int64_t)c[2] + (int64_t)c[0] * rx + (int64_t)c[1] * ry) / c[6]);
    *sy = (int32_t)(((int64_t)c[5] + (int64_t)c[3] * rx + (int64_t)c[4] * ry) / c[6]);
}

void cal_logical_to_physical(int rot, int32_t pw, int32_t ph, int32_t x, int32_t y, int32_t *px, int32_t *py)
{
    switch (rot) {
    case 90: *px = pw - 1 - y, *py = x; break;
    case 180: *px = pw - 1 - x, *py = ph - 1 - y; break;
    case 270: *px = y, *py = ph - 1 - x; break;
    default: *px = x, *py = y; break;
    }
}
