#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Boot the rig's guests under qemu (TCG) and judge what they report.

The guest talks over its serial console (see README.md): CHECK lines are
results, SCREEN/KEYS/TAP/QMP lines are requests the host answers with an
"ACK <word>" line after acting through QMP. Pixels are compared exactly
with the in-memory render of the same scene (host_render).

usage: run.py --render BIN --work DIR GUEST... where GUEST is
       arch=x86_64,kernel=PATH,initrd=PATH  (or arch=aarch64,...)
Prints one line per check and a closing "N passed, N failed".
"""
import argparse
import base64
import json
import os
import select
import socket
import subprocess
import sys
import threading
import time
import zlib

# The second card's output (Virtual-2 once guest/outputs.c loads its driver)
# is a panel mounted turned: its connector gets a "panel orientation"
# property. Nothing else sees Virtual-2 but kms.c's vkms, which always asks
# for a rotation.
PANEL = "video=Virtual-2:panel_orientation=right_side_up"
# x86_64's second card has a second head (guest/heads.c): Virtual-3, a panel
# turned the other way.
PANEL2 = " video=Virtual-3:panel_orientation=left_side_up"
QEMU = {
    "x86_64": lambda k, i: [
        "qemu-system-x86_64", "-accel", "tcg", "-M", "pc", "-m", "256M", "-smp", "1",
        "-vga", "none", "-device", "VGA,xres=800,yres=480",
        "-device", "virtio-tablet-pci", "-device", "virtio-keyboard-pci",
        # a second card (guest/outputs.c loads its driver): SCREEN ... gpu1
        "-device", "virtio-gpu-pci,id=gpu1,addr=0x8,xres=640,yres=400,max_outputs=2",
        "-kernel", k, "-initrd", i,
        "-append", "console=ttyS0 panic=-1 loglevel=4 " + PANEL + PANEL2],
    "aarch64": lambda k, i: [
        "qemu-system-aarch64", "-M", "virt", "-cpu", "cortex-a72", "-m", "256M", "-smp", "1",
        "-device", "virtio-gpu-pci,xres=800,yres=480",
        "-device", "virtio-tablet-pci", "-device", "virtio-keyboard-pci",
        "-device", "bochs-display,id=gpu1,addr=0x8,xres=640,yres=400",
        "-kernel", k, "-initrd", i,
        "-append", "console=ttyAMA0 panic=-1 loglevel=4 " + PANEL],
}
COMMON = ["-no-reboot", "-display", "none", "-serial", "stdio", "-monitor", "none"]


# ---- images ---------------------------------------------------------------

def read_ppm(path):
    with open(path, "rb") as f:
        data = f.read()
    # P6, whitespace-separated header: magic, width, height, maxval, one byte.
    fields, pos = [], 0
    while len(fields) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos)
            continue
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[pos:end])
        pos = end
    if fields[0] != b"P6" or fields[3] != b"255":
        raise ValueError("%s: not an 8-bit P6 PPM" % path)
    w, h = int(fields[1]), int(fields[2])
    return w, h, data[pos + 1:pos + 1 + w * h * 3]


class Renderer:
    def __init__(self, binary, work):
        self.binary, self.work, self.cache = binary, work, {}
        self.lock = threading.Lock()

    def scene(self, name, w, h):
        key = (name, w, h)
        with self.lock:
            if key not in self.cache:
                out = os.path.join(self.work, "expect-%s-%dx%d.ppm" % key)
                subprocess.run([self.binary, name, str(w), str(h), out], check=True)
                rw, rh, px = read_ppm(out)
                assert (rw, rh) == (w, h)
                self.cache[key] = px
            return self.cache[key]

    def expected(self, spec, w, h):
        """spec: SCENE or BASE,PATCH:x0:y0:x1:y1 at logical size w x h."""
        parts = spec.split(",")
        base = bytearray(self.scene(parts[0], w, h))
        for patch in parts[1:]:
            name, x0, y0, x1, y1 = patch.split(":")
            x0, y0, x1, y1 = int(x0), int(y0), int(x1), int(y1)
            src = self.scene(name, w, h)
            for y in range(y0, y1):
                a, b = (y * w + x0) * 3, (y * w + x1) * 3
                base[a:b] = src[a:b]
        return bytes(base)


def first_difference(got, want, w, h):
    """How two w x h RGB pictures of the same size differ, for a check's detail."""
    bad = [i for i in range(0, len(want), 3) if got[i:i + 3] != want[i:i + 3]]
    i = bad[0] // 3
    return "%d of %d pixels differ, first at (%d,%d) got %s want %s" % (
        len(bad), w * h, i % w, i // w, got[bad[0]:bad[0] + 3].hex(), want[bad[0]:bad[0] + 3].hex())


def rotate(px, w, h, rotation):
    """Logical w x h image to the physical screen; rotation is clockwise and
    must agree with fixel/display.h: logical (x, y) lands at
    90: (W-1-y, x), 180: (W-1-x, H-1-y), 270: (y, H-1-x)."""
    if rotation == 0:
        return px
    rows = [px[y * w * 3:(y + 1) * w * 3] for y in range(h)]
    if rotation == 180:
        out = []
        for y in range(h - 1, -1, -1):
            r = rows[y]
            out.append(b"".join(r[x * 3:x * 3 + 3] for x in range(w - 1, -1, -1)))
        return b"".join(out)
    W, H = h, w  # physical size
    out = []
    for py in range(H):
        if rotation == 90:   # physical (px, py) shows logical (py, W-1-px)
            x = py * 3
            out.append(b"".join(rows[W - 1 - p][x:x + 3] for p in range(W)))
        else:                # 270: physical (px, py) shows logical (H-1-py, px)
            x = (H - 1 - py) * 3
            out.append(b"".join(rows[p][x:x + 3] for p in range(W)))
    return b"".join(out)


# ---- QMP ------------------------------------------------------------------

class Qmp:
    def __init__(self, path, timeout=20):
        end = time.time() + timeout
        while True:
            try:
                self.s = socket.socket(socket.AF_UNIX)
                self.s.connect(path)
                break
            except OSError:
                self.s.close()
                if time.time() > end:
                    raise
                time.sleep(0.05)
        self.f = self.s.makefile("rwb")
        self._read()  # greeting
        self.cmd("qmp_capabilities")

    def _read(self):
        while True:
            line = self.f.readline()
            if not line:
                raise EOFError("QMP closed")
            msg = json.loads(line)
            if "event" not in msg:
                return msg

    def cmd(self, name, **args):
        req = {"execute": name}
        if args:
            req["arguments"] = args
        self.f.write(json.dumps(req).encode() + b"\n")
        self.f.flush()
        rep = self._read()
        if "error" in rep:
            raise RuntimeError("%s: %s" % (name, rep["error"]))
        return rep.get("return")


def key_events(text):
    names = {"\n": "ret", " ": "spc", "-": "minus", ".": "dot", "/": "slash"}
    events = []
    for ch in text + "\n":
        q = names.get(ch, ch.lower())
        for down in (True, False):
            events.append([{"type": "key", "data": {"down": down, "key": {"type": "qcode", "data": q}}}])
    return events


# ---- one guest --------------------------------------------------------------

class Guest:
    def __init__(self, arch, kernel, initrd, renderer, work, report, timeout):
        self.arch, self.kernel, self.initrd = arch, kernel, initrd
        self.r, self.work, self.report, self.timeout = renderer, work, report, timeout
        self.log = open(os.path.join(work, "serial-%s.log" % arch), "w")
        self.image = None  # an IMAGE being received

    def check(self, name, ok, detail=""):
        self.report("%s/%s" % (self.arch, name), ok, detail)

    def screen(self, qmp, args):
        name, w, h, rot, spec = args[0], int(args[1]), int(args[2]), int(args[3]), args[4]
        dev = {}
        if len(args) > 5:  # DEVICE or DEVICE@HEAD
            d, _, head = args[5].partition("@")
            dev = {"device": d, "head": int(head)} if head else {"device": d}
        lw, lh = (h, w) if rot in (90, 270) else (w, h)
        negate = spec.startswith("!")
        if negate:
            spec = spec[1:]
        want = rotate(self.r.expected(spec, lw, lh), lw, lh, rot)
        path = os.path.join(self.work, "screen-%s-%s.ppm" % (self.arch, name))
        # fbdev emulation flushes from a deferred worker: a dump right after
        # the guest's writes can be partial, so retry for up to 2 s.
        detail, tries = "", 0
        for tries in range(1, 41):
            qmp.cmd("screendump", filename=path, **dev)
            sw, sh, got = read_ppm(path)
            if (sw, sh) != (w, h):
                detail = "screen is %dx%d, guest said %dx%d" % (sw, sh, w, h)
            elif got == want and not negate:
                self.check(name, True, "%d pixels equal (%s, rotation %d, dump %d)" % (w * h, spec, rot, tries))
                return True
            elif got != want and negate:
                self.check(name, True, "screen differs from %s as expected (dump %d)" % (spec, tries))
                return True
            elif negate:
                detail = "screen still shows %s" % spec
            else:
                detail = first_difference(got, want, w, h)
            time.sleep(0.05)
        with open(path + ".expected.ppm", "wb") as f:
            f.write(b"P6\n%d %d\n255\n" % (w, h) + want)
        self.check(name, False, detail + " (after %d dumps; %s)" % (tries, path))
        return False

    # IMAGE <name> <W> <H> <spec> <chars>, then "IMG <base64>" lines holding
    # <chars> characters of zlib-compressed 8-bit RGB: a picture the guest
    # has in a file (a fixel-shot screenshot), compared with the render of
    # spec like a SCREEN. Answered with ACK PASS|FAIL once complete.
    def image_start(self, args):
        self.image = {"name": args[0], "w": int(args[1]), "h": int(args[2]), "spec": args[3],
                      "left": int(args[4]), "b64": []}

    def image_line(self, qmp, data):
        im = self.image
        im["b64"].append(data)
        im["left"] -= len(data)
        if im["left"] > 0:
            return None
        self.image = None
        name, w, h, spec = im["name"], im["w"], im["h"], im["spec"]
        try:
            got = zlib.decompress(base64.b64decode("".join(im["b64"])))
        except (ValueError, zlib.error) as e:
            self.check(name, False, "undecodable image: %s" % e)
            return "FAIL"
        if spec.startswith("screen@"):
            return self.image_on_screen(qmp, name, w, h, spec, got)
        want = self.r.expected(spec, w, h)
        if got == want:
            self.check(name, True, "%d pixels equal (%s)" % (w * h, spec))
            return "PASS"
        path = os.path.join(self.work, "image-%s-%s" % (self.arch, name))
        for suffix, px in ((".ppm", got), (".expected.ppm", want)):
            with open(path + suffix, "wb") as f:
                f.write(b"P6\n%d %d\n255\n" % (w, h) + px)
        if len(got) != len(want):
            detail = "%d bytes, want %d" % (len(got), len(want))
        else:
            detail = first_difference(got, want, w, h)
        self.check(name, False, "%s (%s.ppm)" % (detail, path))
        return "FAIL"

    # IMAGE <name> <W> <H> screen@X,Y <chars>: the picture must be what the
    # screen shows at X,Y (physical pixels) -- the guest's own expectation of
    # a picture it cannot render from a scene (a GLUT program's window). The
    # screen is dumped until it matches, for up to 2 s, like SCREEN.
    def image_on_screen(self, qmp, name, w, h, spec, got):
        x0, y0 = (int(v) for v in spec[len("screen@"):].split(","))
        path = os.path.join(self.work, "screen-%s-%s.ppm" % (self.arch, name))
        detail, tries = "", 0
        for tries in range(1, 41):
            qmp.cmd("screendump", filename=path)
            sw, sh, scr = read_ppm(path)
            if x0 < 0 or y0 < 0 or x0 + w > sw or y0 + h > sh or len(got) != w * h * 3:
                self.check(name, False, "a %dx%d picture at (%d,%d) is not inside the %dx%d screen" % (
                    w, h, x0, y0, sw, sh))
                return "FAIL"
            crop = b"".join(scr[((y0 + y) * sw + x0) * 3:((y0 + y) * sw + x0 + w) * 3] for y in range(h))
            if crop == got:
                self.check(name, True, "%d pixels equal (the %dx%d rectangle at (%d,%d), dump %d)" % (
                    w * h, w, h, x0, y0, tries))
                return "PASS"
            detail = first_difference(crop, got, w, h) + " in the rectangle"
            time.sleep(0.05)
        with open(path + ".expected.ppm", "wb") as f:
            f.write(b"P6\n%d %d\n255\n" % (w, h) + got)
        self.check(name, False, "%s (after %d dumps; %s)" % (detail, tries, path))
        return "FAIL"

    def run(self):
        sock = os.path.join(self.work, "qmp-%s.sock" % self.arch)
        if os.path.exists(sock):
            os.unlink(sock)
        cmd = QEMU[self.arch](self.kernel, self.initrd) + COMMON + \
            ["-qmp", "unix:%s,server=on,wait=off" % sock]
        t0 = time.time()
        p = subprocess.Popen(cmd, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        qmp = None
        exits, done, booted = {}, False, None
        buf = b""
        try:
            qmp = Qmp(sock)
            while True:
                left = self.timeout - (time.time() - t0)
                if left <= 0:
                    self.check("completed", False, "no RIG DONE within %d s (see %s)" % (self.timeout, self.log.name))
                    break
                ready, _, _ = select.select([p.stdout], [], [], min(left, 1.0))
                if not ready:
                    continue
                chunk = os.read(p.stdout.fileno(), 65536)
                if not chunk:
                    break
                buf += chunk
                while b"\n" in buf:
                    raw, buf = buf.split(b"\n", 1)
                    line = raw.decode("utf-8", "replace").replace("\r", "").strip()
                    self.log.write(line + "\n")
                    self.log.flush()
                    words = line.split()
                    if not words:
                        continue
                    ack = None
                    if self.image is not None and words[0] == "IMG" and len(words) == 2:
                        ack = self.image_line(qmp, words[1])
                    elif words[0] == "IMAGE" and len(words) == 6:
                        self.image_start(words[1:])
                    elif words[0] == "CHECK" and len(words) >= 3:
                        self.check(words[1], words[2] == "PASS", " ".join(words[3:]))
                    elif words[0] == "SCREEN" and len(words) in (6, 7):
                        ack = "PASS" if self.screen(qmp, words[1:]) else "FAIL"
                    elif words[0] == "KEYS" and len(words) == 2:
                        for ev in key_events(words[1]):
                            qmp.cmd("input-send-event", events=ev)
                            time.sleep(0.01)
                        ack = "OK"
                    elif words[0] == "TAP" and len(words) == 3:
                        x, y = int(words[1]), int(words[2])
                        qmp.cmd("input-send-event", events=[
                            {"type": "abs", "data": {"axis": "x", "value": x}},
                            {"type": "abs", "data": {"axis": "y", "value": y}},
                            {"type": "btn", "data": {"down": True, "button": "left"}}])
                        qmp.cmd("input-send-event", events=[
                            {"type": "btn", "data": {"down": False, "button": "left"}}])
                        ack = "OK"
                    elif words[0] == "QMP" and len(words) >= 2:
                        req = json.loads(line[4:])
                        qmp.cmd(req["execute"], **req.get("arguments", {}))
                        ack = "OK"
                    elif words[0] == "RIG" and len(words) >= 2:
                        if words[1] == "BOOTED":
                            booted = time.time() - t0
                        elif words[1] == "EXIT" and len(words) == 4:
                            exits[words[2]] = int(words[3])
                        elif words[1] == "MODULE-FAILED":
                            self.check("module-" + words[2], False, "insmod failed")
                        elif words[1] == "DONE":
                            done = True
                    if ack:
                        p.stdin.write(("ACK %s\n" % ack).encode())
                        p.stdin.flush()
                if done:
                    break
        except Exception as e:  # a broken guest must not hang the rig
            self.check("host", False, "%s: %s" % (type(e).__name__, e))
        finally:
            try:
                p.wait(timeout=10)
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait()
            self.log.close()
        for prog, code in sorted(exits.items()):
            self.check("%s-exit" % prog, code == 0, "exit status %d" % code)
        if done:
            self.check("boot", True, "booted in %.1f s, all guest programs ran, %.1f s total" % (
                booted or 0, time.time() - t0))
        elif not exits:
            self.check("boot", False, "guest never ran its programs (see %s)" % self.log.name)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--render", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--timeout", type=int, default=240)
    ap.add_argument("--parallel", action="store_true")
    ap.add_argument("guests", nargs="+")
    a = ap.parse_args()
    os.makedirs(a.work, exist_ok=True)
    counts = [0, 0]
    lock = threading.Lock()

    def report(name, ok, detail):
        with lock:
            counts[0 if ok else 1] += 1
            print("%s %s%s" % ("PASS" if ok else "FAIL", name, "  " + detail if detail else ""), flush=True)

    renderer = Renderer(a.render, a.work)
    guests = []
    for g in a.guests:
        kv = dict(x.split("=", 1) for x in g.split(","))
        guests.append(Guest(kv["arch"], kv["kernel"], kv["initrd"], renderer, a.work, report, a.timeout))
    if a.parallel:
        ts = [threading.Thread(target=g.run) for g in guests]
        for t in ts:
            t.start()
        for t in ts:
            t.join()
    else:
        for g in guests:
            g.run()
    print("%d passed, %d failed" % tuple(counts))
    return 0 if counts[1] == 0 and counts[0] > 0 else 1


if __name__ == "__main__":
    sys.exit(main())
