/* SPDX-License-Identifier: MIT */
/* libFuzzer target (issue #26): PNG files generated chunk by chunk for the
 * kiosk's image reader (fx_read_png_rgb_stream, boards/memory/memfb.c):
 * IHDR fields at their corners (choice.h: sizes 0, 1, 2^15, 2^16, 2^24,
 * 2^31, bit depths and colour types legal or not), PLTE, tRNS, tEXt / zTXt
 * / iCCP chunks declaring up to 4 GiB, IDAT streams of the right size, cut
 * short or too long, chunks with correct CRCs (or, by choice, wrong ones).
 * Whatever is accepted must have the size the header declared.
 * FUZZ_GRAMMAR_PRINT=1 prints each header and the reader's answer. */
#include <stdlib.h>
#include <zlib.h>

#include "choice.h"
#include "fixel/memfb.h"

static uint8_t buf[1 << 17];
static size_t len;

static void raw(const void *p, size_t n)
{
    if (n && len + n <= sizeof buf) {
        memcpy(buf + len, p, n);
        len += n;
    }
}

static void be32(uint8_t *d, uint32_t v)
{
    d[0] = (uint8_t)(v >> 24), d[1] = (uint8_t)(v >> 16), d[2] = (uint8_t)(v >> 8), d[3] = (uint8_t)v;
}

/* One chunk; declared: the length field (normally n); bad_crc: flip it. */
static void chunk(const char *type, const uint8_t *p, uint32_t n, uint32_t declared, int bad_crc)
{
    uint8_t h[8];
    be32(h, declared);
    memcpy(h + 4, type, 4);
    raw(h, 8);
    raw(p, n);
    uint32_t c = (uint32_t)crc32(0, h + 4, 4);
    if (n) /* crc32(c, NULL, 0) is not c but zlib's initial value, 0 */
        c = (uint32_t)crc32(c, p, n);
    be32(h, c ^ (bad_crc ? 1u : 0u));
    raw(h, 4);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static uint8_t rows[1 << 16], z[1 << 17];
    in s = {data, size};
    len = 0;
    uint32_t flags = take(&s, 2);
    raw(flags & 1 ? "\x89PNG\r\n\x1b\n" : "\x89PNG\r\n\x1a\n", 8);
    static const uint8_t depths[] = {1, 2, 4, 8, 16, 3, 0, 255};
    static const uint8_t ctypes[] = {0, 2, 3, 4, 6, 1, 7, 255};
    uint32_t w = take(&s, 1) & 1 ? 1 + take(&s, 1) % 40 : (uint32_t)corner(&s, 0, 0x7FFFFFFF);
    uint32_t h = take(&s, 1) & 1 ? 1 + take(&s, 1) % 40 : (uint32_t)corner(&s, 0, 0x7FFFFFFF);
    uint8_t depth = depths[take(&s, 1) % 8], ct = ctypes[take(&s, 1) % 8];
    uint8_t ihdr[13];
    be32(ihdr, w);
    be32(ihdr + 4, h);
    ihdr[8] = depth, ihdr[9] = ct, ihdr[10] = 0, ihdr[11] = 0, ihdr[12] = (uint8_t)(flags >> 1 & 1);
    chunk("IHDR", ihdr, 13, 13, flags >> 2 & 1 && flags >> 3 & 1);
    uint32_t extra = take(&s, 1) % 6;
    for (uint32_t i = 0; i < extra; i++) {
        static const char *const types[] = {"PLTE", "tRNS", "tEXt", "zTXt", "iCCP", "gAMA", "sBIT", "bKGD"};
        const char *t = types[take(&s, 1) % 8];
        uint8_t body[96];
        uint32_t n = take(&s, 1) % sizeof body;
        for (uint32_t k = 0; k < n; k++)
            body[k] = (uint8_t)(k % 7 ? k * 3 : 0);
        uint32_t declared = take(&s, 1) % 4 == 0 ? (uint32_t)corner(&s, 0, UINT32_MAX) : n;
        chunk(t, body, n, declared, 0);
    }
    /* image data for the declared size when it is small, else a few rows */
    uint32_t channels = ct == 2 ? 3 : ct == 4 ? 2 : ct == 6 ? 4 : 1;
    uint64_t rowbytes = 1 + ((uint64_t)w * channels * (depth ? depth : 8) + 7) / 8;
    uint64_t want = rowbytes * h;
    size_t nraw = want < sizeof rows ? (size_t)want : sizeof rows;
    if (flags >> 4 & 1)
        nraw = nraw ? take(&s, 2) % nraw : 0; /* cut short */
    for (size_t k = 0; k < nraw; k++)
        rows[k] = (uint8_t)(k % rowbytes == 0 ? take(&s, 1) % 6 : k * 13 + (k >> 5)); /* filter bytes 0..5 */
    uLongf zn = sizeof z;
    if (compress2(z, &zn, rows, nraw, 1) == Z_OK) {
        uint32_t parts = 1 + (flags >> 5 & 3);
        size_t at = 0;
        for (uint32_t p = 0; p < parts; p++) {
            size_t n = p + 1 == parts ? zn - at : zn / parts;
            chunk("IDAT", z + at, (uint32_t)n, (uint32_t)n, flags >> 7 & 1 && p == 0);
            at += n;
        }
    }
    if (!(flags >> 8 & 1))
        chunk("IEND", NULL, 0, 0, 0);
    FILE *f = fmemopen(buf, len, "rb");
    if (!f)
        return 0;
    uint8_t *rgb = NULL;
    int32_t ow = -1, oh = -1;
    int r = fx_read_png_rgb_stream(f, 4096, (size_t)1 << 22, &rgb, &ow, &oh);
    fclose(f);
    static int print = -1;
    if (print < 0)
        print = getenv("FUZZ_GRAMMAR_PRINT") != NULL; /* triage: what was generated, what came out */
    if (print)
        fprintf(stderr, "png %zu bytes, IHDR %ux%u depth %u type %u: %d (%dx%d)\n", len, w, h, depth, ct, r, ow, oh);
    if (r == 0) {
        if (ow != (int32_t)w || oh != (int32_t)h || !rgb)
            abort(); /* accepted with a size other than the header's */
        volatile uint8_t sum = 0;
        for (size_t k = 0; k < (size_t)ow * (size_t)oh * 3; k++)
            sum ^= rgb[k]; /* the whole buffer is there (ASan) */
        (void)sum;
    }
    free(rgb);
    return 0;
}
