/* SPDX-License-Identifier: MIT */
/* Internal: the Utah teapot control data (teapot_data.c). */
#ifndef FIXEL_TEAPOT_DATA_H
#define FIXEL_TEAPOT_DATA_H

#include <stdint.h>

#define FX_TEAPOT_POINTS  306
#define FX_TEAPOT_PATCHES 32
#define FX_TEAPOT_UNIT    8000 /* stored value / 8000 = coordinate */

extern const int16_t fx_teapot_points[FX_TEAPOT_POINTS][3];
extern const uint16_t fx_teapot_patches[FX_TEAPOT_PATCHES][16];

#endif
