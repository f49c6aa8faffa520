#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Pull the uncompressed ELF vmlinux out of an x86 bzImage.

Debian compresses the payload with xz; qemu can boot the bare ELF through its
PVH note, which skips SeaBIOS and the in-guest decompression (about 2 s of a
TCG boot). usage: extract_vmlinux.py bzImage out
"""
import lzma
import sys


def main():
    src, out = sys.argv[1], sys.argv[2]
    data = open(src, "rb").read()
    magic = b"\xfd7zXZ\x00"
    pos = data.find(magic)
    while pos >= 0:
        try:
            elf = lzma.LZMADecompressor().decompress(data[pos:])
        except lzma.LZMAError:
            elf = b""
        if elf[:4] == b"\x7fELF":
            with open(out, "wb") as f:
                f.write(elf)
            return 0
        pos = data.find(magic, pos + 1)
    sys.stderr.write("extract_vmlinux: no xz-compressed ELF found in %s\n" % src)
    return 1


if __name__ == "__main__":
    sys.exit(main())
