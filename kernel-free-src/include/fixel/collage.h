/* SPDX-License-Identifier: MIT */
/* fixel — the inverse problem of IFS: finding maps for a picture by the
 * collage theorem, and fractal (partitioned-IFS) image compression.
 *
 * Collage theorem: if the union of the images of a target T under the
 * contractions w_1 .. w_n (the collage) is close to T, the attractor of
 * {w_i} is close to T too (within d(T, collage) / (1 - s), s the largest
 * contraction ratio). fx_collage_search finds the maps by brute force
 * over a small grid: axis-aligned contractions of ratio 1/4, 1/3 or 1/2 in
 * x and in y, translated by multiples of 1/12 of the picture, and picks
 * them greedily, each time the one that covers the most target pixels not
 * yet covered less four times the pixels it lights outside the target. The
 * collage distance is the pixel difference |T xor collage| (the symmetric
 * difference: target pixels missed plus collage pixels outside).
 *
 * Fractal compression (Jacquin's partitioned IFS): the picture is cut into
 * 4 x 4 range blocks; each is coded as the best of all 8 x 8 domain blocks
 * (on a 4-pixel grid), averaged down to 4 x 4, under one of the 8
 * rotations and reflections of the square, with a least-squares grey map
 * r ~ s d + o (s quantised to sixteenths in -15/16..15/16, o to integers).
 * Decoding iterates those maps from a flat grey picture; being
 * contractive (|s| < 1) they converge to an approximation of the original
 * whatever the start. All of it is integer arithmetic.
 */
#ifndef FIXEL_COLLAGE_H
#define FIXEL_COLLAGE_H

#include <stdint.h>
#include "fixel/fixed.h"
#include "fixel/ifs.h"

#ifdef __cplusplus
extern "C" {
#endif

/* One collage map in picture units: a picture pixel centre (x + 1/2, y + 1/2)
 * goes to (ax_num / ax_den * (x + 1/2) + ex * w / 12,
 *          ay_num / ay_den * (y + 1/2) + ey * h / 12), floored (y down). */
typedef struct fx_collage_map {
    uint8_t ax_den, ay_den; /* 2, 3 or 4 (ratio 1/den) */
    uint8_t ex, ey;         /* 0..11 */
} fx_collage_map;

typedef struct fx_collage_result {
    int n;              /* maps found */
    fx_collage_map maps[FX_IFS_MAX_MAPS];
    int32_t target;     /* target pixels */
    int32_t missed;     /* target pixels the collage misses */
    int32_t extra;      /* collage pixels outside the target */
} fx_collage_result;

/* The picture side limits (w and h multiples of 12, 12..240). */
#define FX_COLLAGE_MAX_SIDE 240

/* target: w x h bytes (row stride w), nonzero = in the set. work: w * h
 * bytes of scratch. At most maxmaps (1..FX_IFS_MAX_MAPS) maps. Returns the
 * number of maps (>= 0) or -FX_EINVAL. */
int fx_collage_search(const uint8_t *target, int32_t w, int32_t h, int maxmaps, uint8_t *work,
                      fx_collage_result *res);
/* The collage distance |T xor union w_i(T)| of given maps (missed and extra
 * filled into res). Returns it or -FX_EINVAL. */
int32_t fx_collage_distance(const uint8_t *target, int32_t w, int32_t h, const fx_collage_map *maps, int n,
                            uint8_t *work, fx_collage_result *res);
/* The maps as an fx_ifs on the world window [0, 1] x [0, 1] (y up), with
 * probabilities proportional to their areas: fills out[0..n) and *ifs. */
void fx_collage_to_ifs(const fx_collage_map *maps, int n, fx_ifs_map *out, fx_ifs *ifs);

/* ---- fractal image compression ---- */
typedef struct fx_fic_code {
    uint16_t dx, dy; /* domain block's top-left pixel */
    uint8_t iso;     /* 0..7: rotations by 90 degrees (0..3), then the same after a mirror */
    int8_t s;        /* grey scale in sixteenths, -15..15 */
    int16_t o;       /* grey offset */
} fx_fic_code;

/* Side limits: a multiple of 8 in 8..256. */
#define FX_FIC_MAX_SIDE 256
/* Code the n x n grey picture img (row stride n) into codes[(n/4)^2]
 * (row-major range blocks). Returns 0 or -FX_EINVAL. */
int fx_fic_encode(const uint8_t *img, int32_t n, fx_fic_code *codes);
/* Decode: iters rounds from flat grey 128 into out (n x n), with tmp as n x n
 * scratch. Returns 0 or -FX_EINVAL. */
int fx_fic_decode(const fx_fic_code *codes, int32_t n, uint32_t iters, uint8_t *out, uint8_t *tmp);
/* Peak signal-to-noise ratio of b against a (count bytes) in dB, Q16.16:
 * 10 log10(255^2 / MSE); FX16_MAX-like INT32_MAX for identical pictures. */
fx16 fx_psnr(const uint8_t *a, const uint8_t *b, int32_t count);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
