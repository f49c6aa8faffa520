# SPDX-License-Identifier: MIT
# Pixel checks for tests/mqtt/run.sh on fixel's own output (8-bit RGB/RGBA
# PNG as fx_write_image writes it, or binary PPM), with only the standard
# library: a fresh machine has python3 but not PIL.
#   img.py same A B X0 Y0 X1 Y1     exit 0 when the rectangles are identical
#   img.py count A X0 Y0 X1 Y1 RRGGBB   print how many pixels have that colour
#   img.py ppm A OUT                 A as a binary PPM (decoded once, compared often)
import struct, sys, zlib

def load(path):
    d = open(path, 'rb').read()
    if d[:2] == b'P6':
        parts, i = [], 2
        while len(parts) < 3:
            while d[i:i + 1].isspace(): i += 1
            if d[i:i + 1] == b'#':
                while d[i:i + 1] != b'\n': i += 1
                continue
            j = i
            while not d[j:j + 1].isspace(): j += 1
            parts.append(int(d[i:j])); i = j
        w, h = parts[0], parts[1]
        return w, h, 3, d[i + 1:i + 1 + w * h * 3]
    assert d[:8] == b'\x89PNG\r\n\x1a\n', path
    i, idat = 8, b''
    while i < len(d):
        n, t = struct.unpack('>I4s', d[i:i + 8])
        c = d[i + 8:i + 8 + n]
        if t == b'IHDR':
            w, h, depth, ctype = struct.unpack('>IIBB', c[:10])
            assert depth == 8 and ctype in (2, 6), 'only 8-bit RGB/RGBA'
            bpp = 3 if ctype == 2 else 4
        elif t == b'IDAT':
            idat += c
        i += 12 + n
    raw, stride, out, prev = zlib.decompress(idat), w * bpp, bytearray(), bytearray(w * bpp)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b = prev[x]
            c = prev[x - bpp] if x >= bpp else 0
            if f == 1: line[x] = (line[x] + a) & 255
            elif f == 2: line[x] = (line[x] + b) & 255
            elif f == 3: line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        out += line
        prev = line
    return w, h, bpp, bytes(out)

def rect(img, x0, y0, x1, y1):
    w, h, bpp, px = img
    return [px[(y * w + x) * bpp:(y * w + x) * bpp + 3] for y in range(y0, y1) for x in range(x0, x1)]

cmd = sys.argv[1]
if cmd == 'same':
    a, b = load(sys.argv[2]), load(sys.argv[3])
    r = [int(v) for v in sys.argv[4:8]]
    sys.exit(0 if rect(a, *r) == rect(b, *r) else 1)
elif cmd == 'ppm':
    w, h, bpp, px = load(sys.argv[2])
    rgb = px if bpp == 3 else b''.join(px[i:i + 3] for i in range(0, len(px), 4))
    open(sys.argv[3], 'wb').write(b'P6\n%d %d\n255\n' % (w, h) + rgb)
elif cmd == 'count':
    a = load(sys.argv[2])
    r = [int(v) for v in sys.argv[3:7]]
    col = bytes.fromhex(sys.argv[7])
    print(sum(1 for p in rect(a, *r) if p == col))
