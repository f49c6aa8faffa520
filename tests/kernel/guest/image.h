/* SPDX-License-Identifier: MIT */
/* IMAGE requests (../README.md): a picture the guest holds, sent to the host
 * zlib'd and base64'd and compared there with the render of a spec or with
 * a rectangle of the screen. Header-only, like guest.h; link -lz. */
#ifndef FIXEL_GUEST_IMAGE_H
#define FIXEL_GUEST_IMAGE_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "guest.h"

/* Sends 8-bit RGB to the host as an IMAGE (zlib, base64, 76 per line). */
static int send_image(const char *name, const char *spec, const uint8_t *rgb, int32_t w, int32_t h) __attribute__((unused));
static int send_image(const char *name, const char *spec, const uint8_t *rgb, int32_t w, int32_t h)
{
    uLongf zn = compressBound((uLong)w * (uLong)h * 3);
    uint8_t *z = malloc(zn);
    if (!z || compress2(z, &zn, rgb, (uLong)w * (uLong)h * 3, 6) != Z_OK) {
        free(z);
        guest_check(name, 0, "compress failed");
        return 0;
    }
    static const char b64[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    size_t chars = (zn + 2) / 3 * 4;
    printf("IMAGE %s %d %d %s %zu\n", name, w, h, spec, chars);
    char row[80];
    int k = 0;
    for (size_t i = 0; i < zn; i += 3) {
        uint32_t v = (uint32_t)z[i] << 16 | (i + 1 < zn ? (uint32_t)z[i + 1] << 8 : 0) | (i + 2 < zn ? z[i + 2] : 0);
        row[k++] = b64[v >> 18 & 63];
        row[k++] = b64[v >> 12 & 63];
        row[k++] = i + 1 < zn ? b64[v >> 6 & 63] : '=';
        row[k++] = i + 2 < zn ? b64[v & 63] : '=';
        if (k == 76 || i + 3 >= zn) {
            printf("IMG %.*s\n", k, row);
            k = 0;
        }
    }
    free(z);
    fflush(stdout);
    char ack[256];
    while (fgets(ack, sizeof ack, stdin))
        if (!strncmp(ack, "ACK ", 4))
            return !strncmp(ack + 4, "PASS", 4);
    return 0;
}

#endif
