/* SPDX-License-Identifier: MIT */
/* fixel — the whole core API in one include, and the naming rule every
 * public name of the core follows.
 *
 *   #include <fixel/fixel.h>
 *
 * pulls in every public header of kernel-free-src/include/fixel/ (the
 * freestanding core: no libc I/O, no floats, no allocation, no mutable
 * globals). The boards' headers (display, app, memfb, fractal_mt, ...) are
 * not included: they need an operating system.
 *
 * ---- Naming rule ----
 *
 * Prefix. Every external name of the library starts with fx_ (types,
 * functions), FX_ (macros, enumerators) or fx3d_ / FX3D_ (the 3D pipeline of
 * render3d.h). Fixed-point types are named by format: fx16 (Q16.16), fx8
 * (24.8), fx56 (Q8.56), fx_angle (binary angle, one turn = 2^32). Helpers
 * shared between core files but not installed (base/fx_internal.h,
 * base/fx_wide.h, ...) use the same prefixes; file-local functions have
 * none.
 *
 * Verb order. An operation on an object is fx_<object>_<verb>: the object
 * first, the verb after (fx_surface_init, fx_ctx_set_color, fx_clip_push,
 * fx_bres_seek, fx_mesh_make, fx_fractal_render, fx3d_draw). A drawing
 * primitive is named by what it draws, outlines by the bare shape and area
 * fills with fill_ in front (fx_line, fx_circle, fx_polygon / fx_fill_rect,
 * fx_fill_poly, fx_fill_tri); fill is the verb of area primitives and comes
 * first. Conversions read fx_<to>_from_<from> or fx_<from>_to_<to>
 * (fx16_from_ratio, fx_angle_to_deg16, fx3d_rgb_from_color); a quantity is
 * fx_<type>_<what> for the type it returns (fx16_sqrt, fx56_mul). Named
 * algorithms keep their textbook names (fx_flood_fill, fx_boundary_fill,
 * fx_dda, fx_koch).
 *
 * Numeric suffixes. A suffix that is a fixed-point format names the format
 * of the arguments (or the result when there is none):
 *   8   24.8 coordinates (fx_fill_tri8, fx_fill_poly8: fx8 vertices)
 *   16  Q16.16 (fx_poly_fill16: fx_pt16 pieces, fx_gauss16, fx_angle_to_deg16)
 *   56  Q8.56 (fx56_parse)
 * a suffix on an integer operation names the width of its integers:
 *   32, 64 (fx_isqrt32 / fx_isqrt64: the operand; fx_rand32: the result;
 *   fx_umul64_wide: 64-bit operands, a wider result).
 *   (fx_sat32: saturate to int32).
 * The one format suffix that is neither is fx_sin30 / fx_cos30: a Q2.30
 * result, written as its fraction bits. A digit inside a type or module
 * name is a dimension, not a format: fx_vec3, fx_mat4, fx_xform2 (2D, 3x3
 * homogeneous), fx3d. A name without a suffix takes integer pixel
 * coordinates (int32, pixel centres, docs/CONVENTIONS.md).
 *
 * Colour vs color. Identifiers spell "color" (fx_color, fx_ctx_set_color,
 * fx_colorbar, fx3d_rgb_to_color) and prose says "colour". The header
 * fixel/colour.h keeps its name, so existing includes keep working.
 *
 * Where helpers go. A helper that is not about one module's subject
 * belongs to the base header of its kind, not to the first module that
 * needed it: integer maths, fixed-point conversions, exponentials and the
 * pseudo-random generators (fx_rand32, fx_gauss16, fx16_exp2) are in
 * fixed.h; pixel formats and packing in surface.h; colour arithmetic in
 * colour.h and colormap.h. Benchmark-only code is not library API: it lives
 * in tools/fixel-bench/.
 *
 * Known exception, kept for API stability: fx_poly_fill16 (fill.h) reads
 * object-verb where the rule says fx_fill_<shape>16.
 */
#ifndef FIXEL_FIXEL_H
#define FIXEL_FIXEL_H

#include "fixel/anim.h"
#include "fixel/boxdim.h"
#include "fixel/circle.h"
#include "fixel/clip.h"
#include "fixel/collage.h"
#include "fixel/colormap.h"
#include "fixel/colour.h"
#include "fixel/curve.h"
#include "fixel/draw.h"
#include "fixel/error.h"
#include "fixel/event.h"
#include "fixel/fill.h"
#include "fixel/fixed.h"
#include "fixel/font.h"
#include "fixel/fractal.h"
#include "fixel/glcore.h"
#include "fixel/ifs.h"
#include "fixel/input.h"
#include "fixel/julia.h"
#include "fixel/kinematics.h"
#include "fixel/koch.h"
#include "fixel/line.h"
#include "fixel/mask.h"
#include "fixel/mat3d.h"
#include "fixel/mesh.h"
#include "fixel/objects.h"
#include "fixel/randfract.h"
#include "fixel/render3d.h"
#include "fixel/rt.h"
#include "fixel/scene.h"
#include "fixel/sdl.h"
#include "fixel/sprite.h"
#include "fixel/surface.h"
#include "fixel/texture.h"
#include "fixel/turtle.h"
#include "fixel/version.h"
#include "fixel/viz.h"
#include "fixel/vsd.h"
#include "fixel/xform.h"

#ifdef __cplusplus
extern "C" {
#endif

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
