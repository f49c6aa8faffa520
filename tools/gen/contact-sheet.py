#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Upscale PNGs (8-bit RGB/RGBA/grey, non-interlaced) by an integer factor and
lay them out in a grid, so that small golden images can be looked at.
usage: contact-sheet.py OUT.png SCALE FILE.png...   (prints the grid order)"""
import struct
import sys
import zlib


def read_png(path):
    d = open(path, "rb").read()
    i, idat = 8, b""
    while i < len(d):
        n = struct.unpack(">I", d[i:i + 4])[0]
        t, c = d[i + 4:i + 8], d[i + 8:i + 8 + n]
        if t == b"IHDR":
            w, h, depth, ctype = struct.unpack(">IIBB", c[:10])
        elif t == b"IDAT":
            idat += c
        i += 12 + n
    assert depth == 8, "only 8-bit PNGs"
    bpp = {0: 1, 2: 3, 4: 2, 6: 4}[ctype]
    raw, stride, rows, prev, k = zlib.decompress(idat), w * bpp, [], bytearray(w * bpp), 0
    for _ in range(h):
        f = raw[k]
        line = bytearray(raw[k + 1:k + 1 + stride])
        k += 1 + stride
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b = prev[x]
            c = prev[x - bpp] if x >= bpp else 0
            if f == 1:
                line[x] = (line[x] + a) & 255
            elif f == 2:
                line[x] = (line[x] + b) & 255
            elif f == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rgb = bytearray()
        for x in range(w):
            px = line[x * bpp:(x + 1) * bpp]
            rgb += bytes([px[0]] * 3) if bpp <= 2 else px[:3]
        rows.append(rgb)
        prev = line
    return w, h, rows


def main():
    out, scale, files = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
    imgs = [read_png(f) for f in files]
    cols = max(1, min(len(imgs), 3))
    cw = max(i[0] for i in imgs) * scale + 8
    chh = max(i[1] for i in imgs) * scale + 8
    nrows = (len(imgs) + cols - 1) // cols
    W, H = cols * cw, nrows * chh
    canvas = [bytearray(b"\x60\x60\x60" * W) for _ in range(H)]
    for n, (w, h, rows) in enumerate(imgs):
        ox, oy = (n % cols) * cw + 4, (n // cols) * chh + 4
        for y in range(h * scale):
            src = rows[y // scale]
            line = bytearray()
            for x in range(w):
                line += src[x * 3:x * 3 + 3] * scale
            canvas[oy + y][ox * 3:ox * 3 + len(line)] = line
        print(f"[{n // cols},{n % cols}] {files[n]}")
    raw = b"".join(b"\0" + bytes(r) for r in canvas)

    def chunk(t, c):
        return struct.pack(">I", len(c)) + t + c + struct.pack(">I", zlib.crc32(t + c))
    open(out, "wb").write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", W, H, 8, 2, 0, 0, 0))
                          + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


main()
