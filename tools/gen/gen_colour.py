#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Constants of kernel-free-src/base/colour.c: the sRGB decoding table and the
inverse matrices, computed exactly (fractions) from the Q16 forward matrices
so that integer round trips are as tight as the forward rounding allows."""
from fractions import Fraction as F

def q16(x): return int((F(x) * 65536).__round__())

def inverse(m):
    a, b, c = m[0]; d, e, f = m[1]; g, h, i = m[2]
    det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)
    adj = [[e * i - f * h, c * h - b * i, b * f - c * e],
           [f * g - d * i, a * i - c * g, c * d - a * f],
           [d * h - e * g, b * g - a * h, a * e - b * d]]
    return [[F(x) / det for x in row] for row in adj]

yiq = [[19595, 38470, 7471], [39060, -17957, -21103], [13828, -34275, 20447]]
xyz = [[q16(F(s)) for s in row] for row in
       [["0.4124", "0.3576", "0.1805"], ["0.2126", "0.7152", "0.0722"], ["0.0193", "0.1192", "0.9505"]]]
for name, m in (("yiq", yiq), ("xyz", xyz)):
    inv = inverse([[F(x, 65536) for x in row] for row in m])
    print(f"/* {name} forward Q16 */ {m}")
    print(f"/* {name} inverse Q16 */ {[[q16(x) for x in row] for row in inv]}")

def srgb_to_linear(c):
    c = c / 255.0
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4
print("srgb_lin =", [round(srgb_to_linear(c) * 65536) for c in range(256)])
