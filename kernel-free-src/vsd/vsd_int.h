/* SPDX-License-Identifier: MIT */
/* fixel — visible-surface detection: what the method files share
 * (fixel/vsd.h explains the model). */
#ifndef FIXEL_VSD_INT_H
#define FIXEL_VSD_INT_H

#include "fixel/vsd.h"
#include "fixel/error.h"

/* A piece of a polygon (depth sort, BSP): the polygon's plane and edges,
 * plus exact screen half-planes cx x + cy y + cc > 0 (>= 0 when cincl)
 * left by the splits, and approximate vertices in 24.8 (x, y, z) for the
 * geometric tests. */
typedef struct vsd_frag {
    int32_t poly, nv, ncut, front, back, mark;
    int32_t x[FX_VSD_FRAG_VERTS], y[FX_VSD_FRAG_VERTS], z[FX_VSD_FRAG_VERTS];
    int64_t ca[FX_VSD_MAX_CUTS], cb[FX_VSD_MAX_CUTS], cc[FX_VSD_MAX_CUTS];
    int8_t cincl[FX_VSD_MAX_CUTS];
    int32_t x0, y0, z0, x1, y1, z1; /* extents of the vertices, 24.8 */
} vsd_frag;

int64_t fx_vsd_floordiv(int64_t n, int64_t d);
/* Narrow [*lo, *hi) to the x where a x + k > 0 (>= 0 when incl). */
void fx_vsd_hspan(int64_t a, int64_t k, int incl, int32_t *lo, int32_t *hi);
/* Pixels of polygon p on row y, within [0, w): [*lo, *hi), maybe empty. */
void fx_vsd_poly_span(const fx_vsd_scene *s, int32_t p, int32_t y, int32_t *lo, int32_t *hi);
void fx_vsd_frag_span(const fx_vsd_scene *s, const vsd_frag *f, int32_t y, int32_t *lo, int32_t *hi);
/* Rows of polygon p within the screen: [*y0, *y1). */
void fx_vsd_poly_rows(const fx_vsd_scene *s, int32_t p, int32_t *y0, int32_t *y1);
/* Numerator of polygon p's depth at (x, y): depth = num / c. */
static inline int64_t vsd_num(const fx_vsd_poly *p, int32_t x, int32_t y)
{
    return -(p->a * x + p->b * y + p->d);
}
/* The z-buffer's rule at one pixel: does p beat q (q < 0: nothing)? */
int fx_vsd_beats(const fx_vsd_scene *s, int32_t p, int32_t q, int32_t x, int32_t y);

void fx_vsd_frag_from_poly(const fx_vsd_scene *s, int32_t p, vsd_frag *f);
/* Signed distance-like value of f's vertex i from polygon q's plane, 24.8
 * units (> 0: behind the plane); eps is the rounding of the vertices. */
int64_t fx_vsd_plane_side(const fx_vsd_poly *q, int32_t x, int32_t y, int32_t z);
int64_t fx_vsd_plane_eps(const fx_vsd_poly *q);
/* Bits: 1 some vertex behind q's plane (beyond eps), 2 some in front. */
int fx_vsd_frag_sides(const fx_vsd_scene *s, const vsd_frag *f, int32_t q);
/* Split f by polygon q's plane into *back (behind, ties in) and *front;
 * back may be f itself. -FX_ENOSPC when f carries FX_VSD_MAX_CUTS cuts. */
int fx_vsd_frag_split(const fx_vsd_scene *s, const vsd_frag *f, int32_t q, vsd_frag *back,
                   vsd_frag *front);
/* Split work for the piece methods: pieces, then 2 int32 per piece.
 * Returns how many pieces fit, -FX_ENOSPC when not even the polygons do. */
int32_t fx_vsd_frag_work(const fx_vsd_scene *s, void *work, size_t bytes, vsd_frag **fr, int32_t **ints);
/* Write f's pixels into ids (painting over what is there). */
void fx_vsd_frag_paint(const fx_vsd_scene *s, const vsd_frag *f, int32_t *ids);

int fx_vsd_newell(const fx_vsd_scene *s, int32_t *ids, void *work, size_t bytes, const fx_ctx *c,
               fx_vsd_stats *st);
int fx_vsd_bsp(const fx_vsd_scene *s, int32_t *ids, void *work, size_t bytes, const fx_ctx *c,
            fx_vsd_stats *st);
int fx_vsd_scanline(const fx_vsd_scene *s, int32_t *ids, void *work, size_t bytes, const fx_ctx *c,
                 int32_t trace_row, fx_vsd_stats *st);
int fx_vsd_warnock(const fx_vsd_scene *s, int32_t *ids, void *work, size_t bytes, const fx_ctx *c,
                fx_vsd_stats *st);
size_t fx_vsd_scanline_bytes(const fx_vsd_scene *s);
size_t fx_vsd_warnock_bytes(const fx_vsd_scene *s);

#endif
