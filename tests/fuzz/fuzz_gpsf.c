/* SPDX-License-Identifier: MIT */
/* libFuzzer target (issue #26): PSF1 and PSF2 fonts generated field by
 * field: header fields at their corners (choice.h: 0, 1, 2^15, 2^16, 2^24,
 * 2^31, UINT32_MAX), glyph bitmaps shorter or longer than declared, and
 * Unicode tables of PSF1 UCS-2 or PSF2 UTF-8 entries, sequences (0xFFFE /
 * 0xFE), overlong and truncated UTF-8, missing terminators. Then
 * fuzz_psf.c's checks load the font and draw with it. */
#include <stdlib.h>

#include "choice.h"

#define LLVMFuzzerTestOneInput psf_checks
#include "fuzz_psf.c"
#undef LLVMFuzzerTestOneInput

static uint8_t buf[1 << 16];
static size_t len;

static void b1(uint32_t v)
{
    if (len < sizeof buf)
        buf[len++] = (uint8_t)v;
}

static void b4(uint32_t v)
{
    for (int i = 0; i < 4; i++)
        b1(v >> (8 * i));
}

static uint32_t u32(in *s, uint32_t sane)
{
    return take(s, 1) & 1 ? sane : (uint32_t)corner(s, 0, UINT32_MAX);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    in s = {data, size};
    len = 0;
    uint32_t kind = take(&s, 1);
    uint32_t nglyph, charsize, unicode;
    if (kind & 1) { /* PSF2 */
        uint32_t h = 1 + take(&s, 1) % 20, w = 1 + take(&s, 1) % 20;
        nglyph = 1 + take(&s, 1) % 300;
        charsize = h * ((w + 7) / 8);
        unicode = kind >> 1 & 1;
        b4(0x864ab572);
        b4(u32(&s, 0));
        b4(u32(&s, 32));
        b4(u32(&s, unicode));
        b4(u32(&s, nglyph));
        b4(u32(&s, charsize));
        b4(u32(&s, h));
        b4(u32(&s, w));
    } else {
        static const uint8_t modes[] = {0, 1, 2, 3, 4, 6, 7, 0xFF};
        uint8_t mode = modes[take(&s, 1) % 8];
        charsize = take(&s, 1) % 33;
        nglyph = mode & 1 ? 512 : 256;
        unicode = (mode & 6) != 0;
        b1(0x36);
        b1(0x04);
        b1(mode);
        b1(charsize);
    }
    /* glyphs: all of them, or cut short */
    size_t glyph_bytes = (size_t)nglyph * charsize;
    if (take(&s, 1) & 3)
        glyph_bytes -= glyph_bytes ? take(&s, 2) % glyph_bytes : 0;
    for (size_t i = 0; i < glyph_bytes && len < sizeof buf; i++)
        b1(i * 37 + (i >> 3));
    if (unicode) {
        uint32_t entries = take(&s, 1) % 40;
        for (uint32_t e = 0; e < entries; e++) {
            uint32_t how = take(&s, 1) % 8;
            uint32_t cp = (uint32_t)corner(&s, 0, 0x10FFFF);
            if (kind & 1) {
                switch (how) {
                case 0: b1(0xFF); break;
                case 1: b1(0xFE); break;
                case 2: b1(0xC0); b1(0x80); break; /* overlong */
                case 3: b1(0xF4); break;           /* truncated */
                default:
                    if (cp < 0x80) b1(cp);
                    else if (cp < 0x800) { b1(0xC0 | cp >> 6); b1(0x80 | (cp & 63)); }
                    else if (cp < 0x10000) { b1(0xE0 | cp >> 12); b1(0x80 | (cp >> 6 & 63)); b1(0x80 | (cp & 63)); }
                    else { b1(0xF0 | (cp >> 18 & 7)); b1(0x80 | (cp >> 12 & 63)); b1(0x80 | (cp >> 6 & 63)); b1(0x80 | (cp & 63)); }
                }
            } else {
                uint32_t v = how == 0 ? 0xFFFF : how == 1 ? 0xFFFE : cp & 0xFFFF;
                b1(v);
                b1(v >> 8);
            }
        }
    }
    return psf_checks(buf, len);
}
