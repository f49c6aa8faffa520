/* SPDX-License-Identifier: MIT */
/* fixel — random fractals of nature: grass, fire, and the diamond-square
 * terrain (koch.h's fx_terrain) as a 3D mesh coloured by height.
 *
 * All randomness is xorshift32 (fx_rand32, fx_gauss16) from the caller's
 * seed, so a seed reproduces a picture bit for bit on every target.
 *
 * Grass: each blade is a random turtle walk (fixel/turtle.h) of eight
 * steps upward, its heading bent a little at every step by one persistent
 * curvature plus Gaussian jitter, and at each step a 1-in-8 chance of a side
 * shoot (a smaller blade, two levels deep at most): a stochastic L-system
 * F -> F[+F]F with random angles. Blades take the context's colour with a
 * random brightness of 60 .. 124 %.
 *
 * Fire: the flame's outline is an upward midpoint-displacement profile
 * (the 1D fract() of koch.h over 257 samples across the rectangle: tongue
 * heights 1/8 .. 1 of the rectangle, roughness H = rough, under a
 * parabolic envelope falling to 0.3 at the sides), and inside it
 * the heat falls off linearly with height, perturbed by three octaves of
 * seeded value noise (a fractal sum, amplitude halving per octave); heat
 * maps to black - red - yellow - white. Pixels below a heat of 24/255 are
 * left as they were, so the fire burns over any background.
 */
#ifndef FIXEL_RANDFRACT_H
#define FIXEL_RANDFRACT_H

#include <stdint.h>
#include "fixel/draw.h"
#include "fixel/fixed.h"
#include "fixel/mesh.h"

#ifdef __cplusplus
extern "C" {
#endif

/* nblades blades rooted on the bottom row of r as the picture shows it
 * (r.y1 - 1 on the screen, r.y0 after 'coords course') and reaching up to its
 * height (at most FX_GRASS_MAX_BLADES; r within +-32767, the turtle's
 * range). Returns the segments drawn or -FX_EINVAL. */
#define FX_GRASS_MAX_BLADES 65536
int32_t fx_grass(const fx_ctx *c, fx_rect r, uint32_t nblades, uint32_t seed);

/* Fire filling r from its bottom edge (clipped to the context), rough in
 * 0..1 (Q16.16). Returns 0 or -FX_EINVAL. */
int fx_fire(const fx_ctx *c, fx_rect r, fx16 rough, uint32_t seed);
/* The fire palette: heat 0..255 to black, red, yellow, white. */
fx_color fx_fire_color(int32_t heat);

/* Raise a (2^k + 1)^2 height grid (fx_terrain's layout, k = 1..12) into a
 * mountain: add amp (|amp| <= 2^28) at the centre falling off as
 * 1 - d^2 / R^2 to 0 at the inscribed circle (R half the side); sums
 * saturate at the int32 range.
 * Returns 0 or -FX_EINVAL. */
int fx_terrain_peak(int32_t *h, int32_t stride, int k, int32_t amp);

/* A height-coloured terrain mesh from a (2^k + 1)^2 height grid (fx_terrain's
 * layout, k = 1..FX_TERRAIN_MESH_MAX_K): vertex (i, j) at
 * x = -size/2 + i size/2^k, z = -size/2 + j size/2^k, y = (h - lo) / (hi - lo) * height
 * (lo, hi the grid's extremes), with heights under the fraction `sea` of the
 * range flattened to the sea's level and coloured as water; the land takes
 * fx_terrain_color. Triangles face +y; smooth normals (fx_mesh_compute_normals).
 * m needs pos, nrm, tri and col with room for fx_terrain_mesh_size's counts.
 * Returns 0 or -FX_EINVAL. */
#define FX_TERRAIN_MESH_MAX_K 8
int fx_terrain_mesh_size(int k, int32_t *nverts, int32_t *ntris);
int fx_terrain_mesh(fx_mesh *m, const int32_t *h, int32_t stride, int k, fx16 size, fx16 height, fx16 sea);
/* Colour of land at height t (0: the shore .. 1: the highest peak, Q16.16):
 * sand, grass, forest, rock, snow, interpolated. */
fx_color fx_terrain_color(fx16 t);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
