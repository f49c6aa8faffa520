/* SPDX-License-Identifier: MIT */
/* fixel — the argument table of the scene-script language (issue #26).
 *
 * One entry per command: the type and range of every argument, and where an
 * argument sets the amount of work (iterations, points, vertices), a range
 * that bounds it. fx_scene_exec_line checks each line against its entry
 * before the command runs (fx_scene_check_args in scene.c), fixel-draw
 * --commands prints it, and tests/corners generates its cases from it: a
 * command without an entry fails that test.
 *
 * Ranges are chosen so that every value inside them runs without overflow:
 * 2D coordinates take all of int32 (the rasterisers clip in wide
 * arithmetic), sizes that set the work stay within 2^20, 3D geometry within
 * +-1024 units, fractal views within the Q8.56 limits the iteration needs. */
#include "fixel/scene.h"
#include "fixel/fixed.h"
#include "fixel/fill.h"
#include "fixel/fractal.h"
#include "fixel/ifs.h"
#include "fixel/line.h"
#include "fixel/render3d.h"
#include "fixel/texture.h"
#include "fixel/curve.h"
#include "fixel/mesh.h"
#include "fixel/rt.h"
#include "fixel/vsd.h"
#include "fixel/objects.h"
#include "fixel/collage.h"
#include "fixel/randfract.h"
#include "fixel/turtle.h"
#include "scene_fractal.h"
#include "fixel/anim.h"
#include "fixel/kinematics.h"

#define CO 1048576 /* coordinate bound, 2^20 */
#define G3 1024    /* 3D geometry bound */

#define I(n, lo, hi) {FX_ARG_INT, 0, n, lo, hi}
#define IW(n, lo, hi) {FX_ARG_INT, FX_ARG_WORK, n, lo, hi}
#define XY(n) I(n, INT32_MIN, INT32_MAX)
#define LEN(n) I(n, 0, INT32_MAX)
#define F(n, lo, hi) {FX_ARG_FX16, 0, n, (int64_t)(lo) * 65536, (int64_t)(hi) * 65536}
#define FR(n, lo, hi) {FX_ARG_FX16, 0, n, lo, hi} /* raw Q16.16 bounds */
#define FALL(n) FR(n, INT32_MIN, INT32_MAX)
#define DEG(n) F(n, -32768, 32767)
#define P3(n) F(n, -G3, G3)
#define Q(n, lo, hi) {FX_ARG_FX56, 0, n, (int64_t)(lo) * FX56_ONE, (int64_t)(hi) * FX56_ONE}
#define C(n) {FX_ARG_COLOR, 0, n, 0, 0}
#define W(n) {FX_ARG_WORD, 0, n, 0, 0}
#define S(n) {FX_ARG_STRING, 0, n, 0, 0}
#define OPT {FX_ARG_OPT, 0, 0, 0, 0}
#define FORM(k) {FX_ARG_FORM, 0, k, 0, 0}
#define REP(n, lo, hi) {FX_ARG_REPEAT, FX_ARG_WORK, n, lo, hi}
#define END {FX_ARG_END, 0, 0, 0, 0}
#define A(name, ...) static const fx_scene_arg a_##name[] = {__VA_ARGS__, END}
#define NONE(name) static const fx_scene_arg a_##name[] = {END}

/* ---- core ---- */
A(size, I("W", 1, 16384), I("H", 1, 16384));
A(format, W("XRGB8888|ARGB8888|XBGR8888|RGB565|BGR565|RGB888|BGR888|GRAY8|MONO1"));
A(clear, C("COLOR"));
A(color, C("COLOR"));
A(pixel, XY("X"), XY("Y"));
A(rect, XY("X"), XY("Y"), XY("W"), XY("H"));
A(line4, XY("X0"), XY("Y0"), XY("X1"), XY("Y1"));
NONE(none);
A(coords, W("screen|course"));
/* ---- raster ---- */
A(points1, REP("point", 1, 256), XY("X"), XY("Y"));
A(bezier, REP("control point", 3, FX_BEZIER_MAX_POINTS), XY("X"), XY("Y"));
A(points4, REP("control point", 4, 256), XY("X"), XY("Y"));
A(points2, REP("point", 2, 256), XY("X"), XY("Y"));
A(linestyle, W("solid|dashed|dotted|dashdot|BITS"), OPT, I("UNIT", 0, 65535), I("PHASE", 0, INT32_MAX));
A(linewidth, IW("W", 1, FX_LINE_MAX_WIDTH));
A(linecap, W("butt|square|round"));
A(linejoin, W("miter|round|bevel"), OPT, F("LIMIT", 1, 32767));
A(curvetol, I("T", 1, 65536));
/* ---- conic ---- */
A(circle, XY("CX"), XY("CY"), LEN("R"));
A(arc, XY("CX"), XY("CY"), LEN("R"), DEG("START"), DEG("END"));
A(ellipse, XY("CX"), XY("CY"), LEN("RX"), LEN("RY"));
/* ---- text ---- */
A(font, FORM("builtin"), FORM(0), S("PATH|FAMILY"), OPT, I("SIZE", 1, 1024), W("regular|thin|light|medium|semibold|bold|black|100..1000"), W("tnum|-liga|kern=0|...")); /* features: any number of words */
A(textbox, XY("X"), XY("Y"), I("W", 1, CO), I("H", 1, CO), S("STRING"));
A(text, XY("X"), XY("Y"), S("STRING"));
A(textclip, W("pixel|char|string"));
A(textscale, I("N", 1, 256));
A(textbg, FORM("none"), FORM(0), C("COLOR"));
/* ---- clip and transforms ---- */
A(clip, FORM("off"), FORM("pop"), FORM("push"), XY("X0"), XY("Y0"), XY("X1"), XY("Y1"), FORM(0), XY("X0"),
  XY("Y0"), XY("X1"), XY("Y1"));
A(cliplines, W("direct|cohen|liang|nln"));
A(exterior, FORM("on"), FORM("off"), FORM(0), XY("X0"), XY("Y0"), XY("X1"), XY("Y1"));
A(clippoly, W("sh|wa"), W("fill|outline"), REP("vertex", 3, 64), FALL("X"), FALL("Y"));
A(xpoly, W("fill|outline|open"), REP("vertex", 2, 1024), FALL("X"), FALL("Y"));
A(translate, FALL("TX"), FALL("TY"));
A(scale, F("SX", -1024, 1024), OPT, F("SY", -1024, 1024), FALL("PX"), FALL("PY"));
A(rotate, DEG("DEGREES"), OPT, FALL("PX"), FALL("PY"));
A(shear, W("x|y"), F("SH", -1024, 1024), OPT, FALL("REF"));
A(reflect, FORM("x"), FORM("y"), FORM("origin"), FORM("diagonal"), FORM("line"), FALL("X0"), FALL("Y0"),
  FALL("X1"), FALL("Y1"));
A(window, FALL("WX0"), FALL("WY0"), FALL("WX1"), FALL("WY1"));
A(viewport, FORM("off"), FORM(0), XY("X0"), XY("Y0"), XY("X1"), XY("Y1"), OPT, W("aspect"));
A(pixelaspect, I("NUM", 1, 65536), I("DEN", 1, 65536));
/* ---- fill ---- */
A(gradient, FORM("off"), FORM("linear"), XY("X0"), XY("Y0"), XY("X1"), XY("Y1"),
  REP("colour stop", 2, FX_GRADIENT_MAX_STOPS), C("COLOR"), FORM("radial"), XY("CX"), XY("CY"), I("R", 1, CO),
  REP("colour stop", 2, FX_GRADIENT_MAX_STOPS), C("COLOR"));
A(proctex, FORM("off"), FORM(0), W("fakesphere|noise|turbulence|wood|marble"), XY("X0"), XY("Y0"),
  I("SIZE", 1, CO), C("C0"), C("C1"), OPT, I("SEED", INT32_MIN, INT32_MAX));
A(texture, FORM("filter"), W("nearest|bilinear"), FORM("wrap"), W("repeat|clamp"), FORM("image"), S("PATH"),
  FORM("checker"),
  I("W", 1, 256), I("H", 1, 256), I("CELL", 1, 256), C("C0"), C("C1"), FORM(0),
  W("fakesphere|noise|turbulence|wood|marble"), I("W", 1, 256), I("H", 1, 256), C("C0"), C("C1"), OPT,
  I("SEED", INT32_MIN, INT32_MAX));
A(textri, XY("X0"), XY("Y0"), FALL("S0"), FALL("T0"), XY("X1"), XY("Y1"), FALL("S1"), FALL("T1"), XY("X2"),
  XY("Y2"), FALL("S2"), FALL("T2"));
A(texpoly, REP("vertex", 3, 64), XY("X"), XY("Y"), FALL("S"), FALL("T"));
A(texstyle, FORM("off"), FORM(0), XY("X0"), XY("Y0"), I("SIZE", 1, 65536));
A(flood, XY("X"), XY("Y"), I("CONN", 4, 8));
A(boundaryfill, XY("X"), XY("Y"), C("BOUNDARY"), I("CONN", 4, 8));
A(fillpoly, W("evenodd|nonzero"), REP("vertex", 3, 1024), XY("X"), XY("Y"));
A(fillpolyf, W("evenodd|nonzero"), REP("vertex", 3, 1024), F("X", -32768, 32767), F("Y", -32768, 32767));
A(polygon, REP("vertex", 2, 1024), XY("X"), XY("Y"));
A(filltri, XY("X0"), XY("Y0"), XY("X1"), XY("Y1"), XY("X2"), XY("Y2"));
A(gouraudtri, XY("X0"), XY("Y0"), C("C0"), XY("X1"), XY("Y1"), C("C1"), XY("X2"), XY("Y2"), C("C2"));
A(gouraudpoly, REP("vertex", 3, 1024), XY("X"), XY("Y"), C("C"));
/* issue #44: the copier from any picture */
A(ifscopy, W("sierpinski|fern|user"), XY("X"), XY("Y"), I("W", 1, CO), I("H", 1, CO), IW("DEPTH", 0, 24), C("BG"));
/* issue #44: the orbit of 0 */
A(orbit, Q("C_RE", -16, 16), Q("C_IM", -16, 16), IW("N", 1, 1024), OPT, Q("CENTRE_RE", -16, 16),
  Q("CENTRE_IM", -16, 16), {FX_ARG_FX56, FX_ARG_OPEN_MIN, "WIDTH", 0, 16 * FX56_ONE});
/* issue #44: the notes' scan-line Gouraud */
A(gouraudscan, REP("vertex", 3, FX_GOURAUD_SCAN_MAX), I("X", -FX_GOURAUD_SCAN_COORD, FX_GOURAUD_SCAN_COORD),
  I("Y", -FX_GOURAUD_SCAN_COORD, FX_GOURAUD_SCAN_COORD), C("C"));
A(blend, W("src|over"));
A(pattern, FORM("off"), FORM("bg"), C("COLOR|none"), FORM("anchor"), XY("X"), XY("Y"), FORM(0), I("W", 1, 32),
  I("H", 1, 32), REP("row", 1, 32), W("HEXROW"));
/* ---- fractal ---- */
A(colormap, W("grey|hot|viridis|hsv|w9"), OPT, I("PERIOD", 1, 1048576));
A(mandelbrot, Q("CRE", -16, 16), Q("CIM", -16, 16), {FX_ARG_FX56, FX_ARG_OPEN_MIN, "WIDTH", 0, 16 * FX56_ONE},
  IW("MAXITER", 1, FX_FRACTAL_MAX_ITER));
/* the Julia commands: the view's centre, then c (issue #44: the names say
 * which is which); the c=C_RE,C_IM form the commands also take (c first)
 * is checked by them, since its first token is no number */
A(julia, Q("CENTRE_RE", -16, 16), Q("CENTRE_IM", -16, 16), Q("C_RE", -16, 16), Q("C_IM", -16, 16),
  {FX_ARG_FX56, FX_ARG_OPEN_MIN, "WIDTH", 0, 16 * FX56_ONE}, IW("MAXITER", 1, FX_FRACTAL_MAX_ITER));
A(koch, XY("X0"), XY("Y0"), XY("X1"), XY("Y1"), IW("ORDER", 0, 1000));
A(snowflake, XY("CX"), XY("CY"), I("R", 0, CO), IW("ORDER", 0, 1000));
A(fractline, XY("X0"), XY("Y0"), XY("X1"), XY("Y1"), F("BETA", 0, 3), F("SD", 0, 1),
  I("SEED", INT32_MIN, INT32_MAX));
A(fbmcurve, XY("X0"), XY("Y0"), XY("X1"), XY("Y1"), F("BETA", 0, 4), F("SD", 0, 1), I("SEED", INT32_MIN, INT32_MAX),
  OPT, IW("TERMS", 1, 2048));
A(coastline, F("BETA", 0, 3), F("SD", 0, 1), I("SEED", INT32_MIN, INT32_MAX), REP("vertex", 3, 32), XY("X"),
  XY("Y"));
A(spacefill, XY("X"), XY("Y"), I("SIZE", 1, CO), IW("ORDER", 0, 1000));
A(ifsmap, F("A", -1024, 1024), F("B", -1024, 1024), F("C", -1024, 1024), F("D", -1024, 1024),
  F("E", -1024, 1024), F("F", -1024, 1024), F("P", 0, 1));
A(ifswindow, FALL("X0"), FALL("Y0"), FALL("X1"), FALL("Y1"));
A(ifs, W("sierpinski|fern|user"), FORM("chaos"), XY("X"), XY("Y"), I("W", 1, CO), I("H", 1, CO),
  IW("NPOINTS", 0, 4000000), I("SEED", INT32_MIN, INT32_MAX), FORM("copier"), XY("X"), XY("Y"), I("W", 1, CO),
  I("H", 1, CO), IW("DEPTH", 0, 20));
A(fern, XY("X"), XY("Y"), I("W", 1, CO), I("H", 1, CO), IW("NPOINTS", 0, 4000000),
  I("SEED", INT32_MIN, INT32_MAX));
#define QW {FX_ARG_FX56, FX_ARG_OPEN_MIN, "WIDTH", 0, 16 * FX56_ONE}
#define JV Q("CENTRE_RE", -16, 16), Q("CENTRE_IM", -16, 16), Q("C_RE", -2, 2), Q("C_IM", -2, 2), QW
A(juliaset, FORM("random"), JV, IW("NPOINTS", 0, FX_JULIA_SCENE_POINTS), I("SEED", INT32_MIN, INT32_MAX),
  FORM("tree"), JV, IW("DEPTH", 0, FX_JULIA_SCENE_DEPTH));
A(juliafixed, JV);
A(juliabasins, JV, IW("MAXITER", 1, FX_JULIA_SCENE_ITER));
A(boxdim, XY("X"), XY("Y"), I("W", 1, INT32_MAX), I("H", 1, INT32_MAX), C("BG"), I("SMIN", 1, 1 << 20),
  I("SMAX", 2, 1 << 21), OPT, F("KNOWN", 0, 3));
#define TP(n) F(n, -32767, 32767)
A(turtle, FORM("home"), TP("X"), TP("Y"), DEG("DEG"), FORM("moveto"), TP("X"), TP("Y"), FORM("lineto"), TP("X"),
  TP("Y"), FORM("moverel"), TP("DX"), TP("DY"), FORM("linerel"), TP("DX"), TP("DY"), FORM("turn"), DEG("DEG"),
  FORM("turnto"), DEG("DEG"), FORM("forward"), TP("D"), FORM("jump"), TP("D"), FORM("koch"), TP("LEN"),
  IW("ORDER", 0, FX_TURTLE_MAX_ORDER), FORM("hilbert"), TP("STEP"), IW("ORDER", 0, FX_TURTLE_MAX_ORDER), OPT,
  I("PARITY", -1, 1), FORM("where"));
A(grass, I("X", -16384, 16384), I("Y", -16384, 16384), I("W", 1, 16384), I("H", 1, 16384),
  IW("NBLADES", 0, FX_GRASS_SCENE_BLADES), I("SEED", INT32_MIN, INT32_MAX));
A(fire, I("X", 0, 16384), I("Y", 0, 16384), I("W", 1, 16384), I("H", 1, 16384), F("ROUGH", 0, 1),
  I("SEED", INT32_MIN, INT32_MAX));
A(collage, I("X", 0, 16383), I("Y", 0, 16383), IW("SIZE", 12, FX_COLLAGE_MAX_SIDE), C("BG"),
  IW("MAXMAPS", 1, FX_IFS_MAX_MAPS), XY("DX"), XY("DY"), IW("NPOINTS", 0, 4000000), I("SEED", INT32_MIN, INT32_MAX));
A(fractcompress, I("X", 0, 16383), I("Y", 0, 16383), IW("SIZE", 8, FX_FIC_SCENE_SIDE), XY("DX"), XY("DY"),
  IW("ROUNDS", 0, 100));
A(mountain, FR("SIZE", 1, G3 * 65536), F("HEIGHT", 0, G3), IW("K", 1, FX_TERRAIN_MESH_MAX_K),
  I("SEED", INT32_MIN, INT32_MAX), OPT, F("ROUGH", 0, 1), F("SEA", 0, 1));
/* ---- viz ---- */
A(field, FORM("terrain"), IW("GW", 2, 1025), IW("GH", 2, 1025), I("SEED", INT32_MIN, INT32_MAX), OPT,
  F("ROUGH", 0, 1), FORM(0), W("waves|peaks"), IW("GW", 2, 1025), IW("GH", 2, 1025));
A(vfield, W("vortex|saddle|swirl|dipole"), IW("GW", 2, 1025), IW("GH", 2, 1025));
A(heatmap, XY("X"), XY("Y"), I("W", 1, CO), I("H", 1, CO), OPT, I("LO", INT32_MIN, INT32_MAX),
  I("HI", INT32_MIN, INT32_MAX));
A(colorbar, XY("X"), XY("Y"), I("W", 1, INT32_MAX), I("H", 1, INT32_MAX), OPT, IW("TICKS", 0, 100));
A(contour, XY("X"), XY("Y"), I("W", 1, CO), I("H", 1, CO), IW("N", 1, 64), OPT, REP("level", 0, 64),
  I("LEVEL", INT32_MIN, INT32_MAX));
A(quiver, XY("X"), XY("Y"), I("W", 1, CO), I("H", 1, CO), OPT, IW("STEP", 1, CO));
A(stream, XY("X"), XY("Y"), I("W", 1, CO), I("H", 1, CO), IW("N", 1, 64));
A(tfield, FORM("hessian"), FORM(0), W("rotating"), IW("GW", 2, 1025), IW("GH", 2, 1025));
A(tensorstyle, C("POSITIVE"), C("NEGATIVE"), C("MIXED"));
A(tensor, XY("X"), XY("Y"), I("W", 1, CO), I("H", 1, CO), OPT, IW("STEP", 1, CO));
A(starglyph, XY("CX"), XY("CY"), I("R", 0, CO), C("OUTLINE"), REP("value", 3, 32), F("V", 0, 1));
A(glyphs, XY("X"), XY("Y"), I("W", 1, CO), I("H", 1, CO), IW("STEP", 1, CO));
A(chromaticity, XY("X"), XY("Y"), I("W", 1, CO), I("H", 1, CO), OPT, W("all|fill|lines"));
A(spectrum, XY("X"), XY("Y"), I("W", 1, CO), I("H", 1, CO), OPT, I("NM0", 380, 780), I("NM1", 380, 780));
A(hatch, FORM("off"), FORM(0), I("INTENSITY", 0, 255));
/* ---- 3D ---- */
/* ---- visible-surface detection (fixel/vsd.h bounds: 0..2047) ---- */
A(vsdscene, IW("N", 0, 1000));
A(vsdpoly, C("COLOR"), REP("vertex", 3, FX_VSD_MAX_VERTS), I("X", 0, FX_VSD_COORD_MAX),
  I("Y", 0, FX_VSD_COORD_MAX), I("Z", 0, FX_VSD_COORD_MAX));
A(vsdcull, W("on|off"));
A(vsdoctree, IW("K", 1, 6), IW("SCALE", 1, 64));
A(vsd, W("zbuffer|painter|newell|bsp|scanline|warnock|raycast|abuffer"), OPT, I("ROW", 0, FX_VSD_COORD_MAX));
A(viewport3d, XY("X"), XY("Y"), I("W", 1, 16384), I("H", 1, 16384));
A(depth, W("16|32|off"));
A(painter, OPT, IW("MAXTRIANGLES", 1, 1048576));
A(camera, P3("EX"), P3("EY"), P3("EZ"), P3("LX"), P3("LY"), P3("LZ"), P3("UX"), P3("UY"), P3("UZ"));
A(slide, P3("DU"), P3("DV"), P3("DN"));
A(deg, DEG("DEG"));
A(perspective, F("FOVY", -32768, 32767), P3("NEAR"), P3("FAR"));
A(ortho, P3("L"), P3("R"), P3("B"), P3("T"), P3("NEAR"), P3("FAR"));
A(oblique, W("cavalier|cabinet"), DEG("ALPHA"), P3("L"), P3("R"), P3("B"), P3("T"), P3("NEAR"), P3("FAR"), OPT,
  P3("PLANE"));
A(translate3d, P3("X"), P3("Y"), P3("Z"));
A(scale3d, F("SX", -1024, 1024), OPT, F("SY", -1024, 1024), F("SZ", -1024, 1024));
A(rotate3d, DEG("DEG"), P3("AX"), P3("AY"), P3("AZ"));
A(shear3d, F("A", -1024, 1024), F("B", -1024, 1024));
A(reflect3d, P3("NX"), P3("NY"), P3("NZ"), P3("D"));
A(light, I("N", 0, FX3D_MAX_LIGHTS - 1), FORM("off"), FORM("directional"), P3("X"), P3("Y"), P3("Z"), C("COLOR"),
  FORM("point"), P3("X"), P3("Y"), P3("Z"), C("COLOR"), FORM("spot"), P3("X"), P3("Y"), P3("Z"), P3("DX"),
  P3("DY"), P3("DZ"), F("CUTOFF", 0, 90), F("EXPONENT", 0, 128), C("COLOR"));
A(material, C("AMB"), C("DIFF"), C("SPEC"), I("SHININESS", 0, 128), OPT, C("EMISSION"));
A(shading, W("flat|gouraud|phong|gouraudscan"));
A(cull, W("none|back|front"));
A(polymode, W("fill|wire|hidden"));
A(size3, P3("SIZE"));
A(sphere, P3("R"), IW("SLICES", 0, FX_MESH_MAX_SEG), IW("STACKS", 0, FX_MESH_MAX_SEG));
A(ellipsoid, P3("RX"), P3("RY"), P3("RZ"), IW("SLICES", 0, FX_MESH_MAX_SEG), IW("STACKS", 0, FX_MESH_MAX_SEG));
A(torus, P3("R"), P3("r"), IW("SIDES", 0, FX_MESH_MAX_SEG), IW("RINGS", 0, FX_MESH_MAX_SEG));
A(cone, P3("R"), P3("H"), IW("SLICES", 0, FX_MESH_MAX_SEG));
A(sizen, P3("SIZE"), IW("N", 0, FX_MESH_MAX_SEG));
A(obj, S("FILE"));
A(shadowplane, FORM("off"), FORM(0), P3("A"), P3("B"), P3("C"), P3("D"), I("LIGHT", 0, FX3D_MAX_LIGHTS - 1),
  C("COLOR"));
A(polygon3d, REP("vertex", 3, 16), P3("X"), P3("Y"), P3("Z"), C("COLOR"));
A(solid3d, FORM("off"), FORM(0), W("wood|marble|checker"), C("C0"), C("C1"), FR("SCALE", 4096, 64 * 65536));
A(bump3d, FORM("off"), FORM(0), F("HEIGHT", 0, 1), FR("SCALE", 4096, 64 * 65536));
A(frame3d, FORM("off"), FORM(0), W("brushed|spun"), F("STRENGTH", 0, 1), FR("SCALE", 4096, 64 * 65536));
A(texgen, W("sphere|off"));
A(alpha3d, F("OPACITY", 0, 1), OPT, IW("MAXTRIANGLES", 1, 1048576));
A(texmatrix, FORM("identity"), FORM("push"), FORM("pop"), FORM("translate"), F("S", -1024, 1024), F("T", -1024, 1024),
  FORM("scale"), F("SS", -1024, 1024), OPT, F("ST", -1024, 1024), FORM("rotate"), DEG("DEG"));
A(attenuation, I("LIGHT", 0, FX3D_MAX_LIGHTS - 1), F("KC", 0, 1024), F("KL", 0, 1024), F("KQ", 0, 1024));
A(texture3d, W("modulate|replace|decal|off"));
A(shadowmap, FORM("end"), FORM("off"), FORM("begin"), IW("SIZE", 16, 4096), I("LIGHT", 0, FX3D_MAX_LIGHTS - 1),
  P3("TX"), P3("TY"), P3("TZ"), F("FOV", -32768, 32767), P3("NEAR"), P3("FAR"));
A(pass3d, FORM("off"), FORM("ambient"), OPT, F("DIM", 0, 1), FORM("light"), I("LIGHT", 0, FX3D_MAX_LIGHTS - 1));

/* ---- objects (scene_objects.c): sizes within the 3D bound, exponents in Barr's range ---- */
#define SEG(n, lo) IW(n, lo, FX_MESH_MAX_SEG)
#define SQE(n) FR(n, FX_SQ_EXP_MIN, FX_SQ_EXP_MAX)
A(paraboloid, F("A", 0, G3), F("B", 0, G3), F("H", 0, G3), SEG("SLICES", 3), SEG("ROWS", 2));
A(hyperboloid, I("SHEETS", 1, 2), F("A", 0, G3), F("B", 0, G3), F("C", 0, G3), F("H", 0, G3), SEG("SLICES", 3),
  SEG("ROWS", 2));
A(superellipsoid, F("A", 0, G3), F("B", 0, G3), F("C", 0, G3), SQE("E1"), SQE("E2"), SEG("SLICES", 3),
  SEG("STACKS", 2));
A(supertoroid, F("R", 0, G3), F("r", 0, G3), SQE("E1"), SQE("E2"), SEG("SIDES", 3), SEG("RINGS", 3));
A(blobball, P3("X"), P3("Y"), P3("Z"), F("R", 0, G3), F("W", -64, 64));
A(blobby, F("ISO", 0, 4096), P3("X0"), P3("Y0"), P3("Z0"), F("STEP", 0, G3), IW("NX", 1, 64), IW("NY", 1, 64),
  IW("NZ", 1, 64));
A(patch, W("bezier|bspline"), IW("N", 1, 64), REP("control point", 16, 16), P3("X"), P3("Y"), P3("Z"));
A(ptabcull, W("on|off"));
A(coloursolid, W("rgb|hsv|hls"), {FX_ARG_FX16, FX_ARG_OPEN_MIN, "SIZE", 0, (int64_t)G3 * 65536});
A(octree, FORM("blob"), F("ISO", 0, 4096), IW("K", 1, 6), IW("SCALE", 1, 64), XY("SX"), XY("SY"), P3("X0"), P3("Y0"), P3("Z0"),
  F("SIDE", 0, G3), FORM("supertoroid"), F("R", 0, G3), F("r", 0, G3), SQE("E1"), SQE("E2"), IW("SIDES", 3, 64),
  IW("RINGS", 3, 64), IW("K", 1, 6), IW("SCALE", 1, 64), XY("SX"), XY("SY"), P3("X0"), P3("Y0"), P3("Z0"), F("SIDE", 0, G3));

/* ---- ray tracer (scene_rt.c): world coordinates within the scene limit ---- */
#define WR(n) F(n, -FX_RT_WORLD, FX_RT_WORLD)
A(rtcamera, WR("EX"), WR("EY"), WR("EZ"), WR("LX"), WR("LY"), WR("LZ"), WR("UX"), WR("UY"), WR("UZ"),
  F("FOVY", 1, 179));
A(rtlight, WR("X"), WR("Y"), WR("Z"), C("COLOR"), OPT, F("ATTEN", 0, 1));
A(rtmaterial, C("AMB"), C("DIFF"), C("SPEC"), I("SHININESS", 0, 256), OPT, F("REFLECT", 0, 1), F("TRANSP", 0, 1),
  F("IOR", 1, 4));
A(rttexture, FORM("none"), FORM(0), W("wood|marble|checker"), C("COLOR"), FR("SCALE", 4096, 64 * 65536));
A(rtbump, FORM("none"), FORM(0), F("HEIGHT", 0, 1), FR("SCALE", 4096, 64 * 65536));
A(rtframe, FORM("none"), FORM(0), W("brushed|spun"), F("STRENGTH", 0, 1), FR("SCALE", 4096, 64 * 65536));
A(rtdepth, I("DEPTH", 0, FX_RT_MAX_RECURSION), OPT, F("CUTOFF", 0, 1));
A(rttranslate, WR("X"), WR("Y"), WR("Z"));
A(rtscale, F("SX", -16, 16), F("SY", -16, 16), F("SZ", -16, 16));
A(rtrotate, DEG("DEG"), WR("AX"), WR("AY"), WR("AZ"));
A(rtshape, FORM("taper"), F("S", 0, 2), FORM("torus"), FR("r", 4096, 65536), FORM(0),
  W("sphere|cube|square|plane|cylinder|cone"));
A(rtcsg, W("union|intersection|difference"));
A(rtmesh, FORM("teapot"), IW("N", 1, 16), FORM("torus"), F("R", 0, 16), F("r", 0, 8), IW("SIDES", 3, 256),
  IW("RINGS", 3, 256), FORM("obj"), S("FILE"));
A(sdl, S("FILE"));
A(rtpreview, OPT, W("flat|gouraud|phong"));
A(raytrace, OPT, XY("X"), XY("Y"), I("W", 0, 16384), I("H", 0, 16384));
A(rttrace, I("X", 0, 16383), I("Y", 0, 16383));

/* ---- animation (scene_anim.c): times 0..32767 s; the ball within fixel/anim.h's limits ---- */
#define TM(n) F(n, 0, 32767)
#define EASES "none|in|out|inout|smooth"
A(time, TM("T"));
A(key, W("NAME"), TM("T"), REP("value", 1, FX_ANIM_MAX_CH), FALL("V"));
A(keycolor, W("NAME"), TM("T"), C("COLOR"));
A(interp, W("NAME"), W("linear|spline|step"));
A(ease, W("NAME"), W(EASES));
A(tween, W("NAME"), W("translate|rotate|scale|color|follow|translate3d|rotatex|rotatey|rotatez|camera"));
A(path, W("NAME"), OPT, IW("STEPS", 1, 4096));
A(shape, W("NAME"), REP("vertex", 3, 256), F("X", -32768, 32767), F("Y", -32768, 32767));
A(morph, W("A"), W("B"), W("fill|outline|vertices"), TM("T0"), TM("T1"), OPT, W(EASES));
A(bounce, I("X0", -FX_ANIM_BALL_POS, FX_ANIM_BALL_POS), I("Y0", -FX_ANIM_BALL_POS, FX_ANIM_BALL_POS),
  I("X1", -FX_ANIM_BALL_POS, FX_ANIM_BALL_POS), I("Y1", -FX_ANIM_BALL_POS, FX_ANIM_BALL_POS),
  F("X", -FX_ANIM_BALL_POS, FX_ANIM_BALL_POS), F("Y", -FX_ANIM_BALL_POS, FX_ANIM_BALL_POS),
  F("VX", -FX_ANIM_BALL_SPEED, FX_ANIM_BALL_SPEED), F("VY", -FX_ANIM_BALL_SPEED, FX_ANIM_BALL_SPEED),
  F("G", 0, FX_ANIM_BALL_G), F("E", 0, 1), I("R", 0, 1024), OPT, IW("TRAIL", 1, 4096));
A(blur, IW("N", 1, 64), TM("SHUTTER"));
#define KC(n) I(n, -FX_KIN_COORD, FX_KIN_COORD)
#define KLINKS REP("link", 1, FX_KIN_MAX_JOINTS), I("L", 0, FX_KIN_REACH)
A(arm, KC("X"), KC("Y"), KC("TX"), KC("TY"), KLINKS);
A(armgoal, KC("X"), KC("Y"), KC("GX"), KC("GY"), F("SPEED", 0, FX_KIN_REACH), IW("STEPS", 0, 4096), KLINKS);
#define ARMW "at most 256 CCD sweeps (each N^2 link evaluations, N <= 16 links) per step; the links' total length at most 8192 (FX_KIN_REACH)"
#define BLURW "N runs of the block's lines (at most 1024 lines, 64 KiB), each preceded by a copy of the arena and the pixels"
#define BALLW "at most 4096 impacts solved per position (FX_ANIM_BALL_MAX_BOUNCES), TRAIL + 1 positions"
#define KEYS2 "key a 0 0 0\nkey a 1 10 10"

#define TRIS "at most 262144 triangles (FX_SCENE_MAX_TRIANGLES)"
#define TEX "texture checker 8 8 2 #000000 #FFFFFF"
#define RTWORK                                                                                                \
    "one primary ray per pixel of the tile (clipped to the surface); each at most 2^(DEPTH+1) - 1 rays (rtdepth), " \
    "each with at most 4 shadow feelers, each tested against at most 256 objects"
#define L3 "light 0 point 0 6 0 #FFFFFF"
#define VSDW "at most 1024 polygons (vsdscene, vsdpoly), 16 pieces per polygon"

const fx_scene_argspec fx_scene_argspecs[] = {
    {"size", a_size, 0, 0}, {"format", a_format, 0, 0}, {"clear", a_clear, 0, 0}, {"color", a_color, 0, 0},
    {"pixel", a_pixel, 0, 0}, {"rect", a_rect, 0, 0}, {"fillrect", a_rect, 0, 0}, {"line", a_line4, 0, 0},
    {"present", a_none, 0, 0}, {"coords", a_coords, 0, 0},
    {"dda", a_line4, 0, 0}, {"aaline", a_line4, 0, 0}, {"polyline", a_points1, 0, 0}, {"bezier", a_bezier, 0, 0},
    {"bspline", a_points4, 0, 0}, {"spline", a_points2, 0, 0}, {"linestyle", a_linestyle, 0, 0},
    {"linewidth", a_linewidth, 0, 0}, {"linecap", a_linecap, 0, 0}, {"linejoin", a_linejoin, 0, 0},
    {"curvetol", a_curvetol, 0, 0},
    {"circle", a_circle, 0, 0}, {"disc", a_circle, 0, 0}, {"arc", a_arc, 0, 0}, {"pie", a_arc, 0, 0},
    {"aacircle", a_circle, 0, 0}, {"ellipse", a_ellipse, 0, 0}, {"fillellipse", a_ellipse, 0, 0},
    {"font", a_font, 0, 0}, {"text", a_text, 0, 0}, {"textbox", a_textbox, 0, 0}, {"textclip", a_textclip, 0, 0}, {"textscale", a_textscale, 0, 0},
    {"textbg", a_textbg, 0, 0},
    {"clip", a_clip, 0, 0}, {"cliplines", a_cliplines, 0, 0}, {"exterior", a_exterior, 0, 0},
    {"clippoly", a_clippoly, 0, 0}, {"xpoly", a_xpoly, 0, 0}, {"push", a_none, 0, 0}, {"pop", a_none, "push", 0},
    {"identity", a_none, 0, 0}, {"translate", a_translate, 0, 0}, {"scale", a_scale, 0, 0}, {"rotate", a_rotate, 0, 0},
    {"shear", a_shear, 0, 0}, {"reflect", a_reflect, 0, 0}, {"window", a_window, 0, 0},
    {"viewport", a_viewport, "window 0 0 10 10", 0}, {"pixelaspect", a_pixelaspect, 0, 0},
    {"gradient", a_gradient, 0, 0}, {"proctex", a_proctex, 0, 0}, {"texture", a_texture, 0, 0},
    {"textri", a_textri, TEX, 0}, {"texpoly", a_texpoly, TEX, 0}, {"texstyle", a_texstyle, TEX, 0},
    {"flood", a_flood, 0, 0}, {"boundaryfill", a_boundaryfill, 0, 0}, {"fillpoly", a_fillpoly, 0, 0},
    {"fillpolyf", a_fillpolyf, 0, 0}, {"polygon", a_polygon, 0, 0}, {"filltri", a_filltri, 0, 0},
    {"gouraudtri", a_gouraudtri, 0, 0}, {"gouraudpoly", a_gouraudpoly, 0, 0}, {"blend", a_blend, 0, 0},
    {"pattern", a_pattern, 0, 0}, {"hatch", a_hatch, 0, 0},
    {"colormap", a_colormap, 0, 0}, {"insidecolor", a_color, 0, 0}, {"mandelbrot", a_mandelbrot, 0, 0},
    {"julia", a_julia, 0, 0}, {"koch", a_koch, 0, 0}, {"snowflake", a_snowflake, 0, 0}, {"fractline", a_fractline, 0, 0}, {"fbmcurve", a_fbmcurve, 0, "4 samples per pixel of the chord (at most 65537) x TERMS sines"},
    {"coastline", a_coastline, 0, 0}, {"hilbert", a_spacefill, 0, 0}, {"peano", a_spacefill, 0, 0},
    {"ifsmap", a_ifsmap, 0, 0}, {"ifswindow", a_ifswindow, 0, 0},
    {"ifs", a_ifs, "ifsmap 0.5 0 0 0.5 0 0 0.5\nifsmap 0.5 0 0 0.5 0.5 0 0.5\nifswindow 0 0 1 1", 0},
    {"fern", a_fern, 0, 0},
    {"juliaset", a_juliaset, 0, 0}, {"juliafixed", a_juliafixed, 0, 0}, {"juliabasins", a_juliabasins, 0, 0},
    {"boxdim", a_boxdim, 0, "W x H clipped to the surface, read once per box size (at most 21 sizes)"},
    {"turtle", a_turtle, 0, 0}, {"grass", a_grass, 0, "at most 8 + 5 x 8 + 25 x 8 segments per blade"},
    {"fire", a_fire, 0, "W x H clipped to the surface"},
    {"collage", a_collage, 0, "SIZE a multiple of 12; each of MAXMAPS rounds tries at most 9 x 121 maps over SIZE^2 / 4 px"},
    {"fractcompress", a_fractcompress, 0,
     "SIZE a multiple of 8: (SIZE/4)^2 range blocks x (SIZE/4 - 1)^2 domains x 8 symmetries x 16 px"}, {"mountain", a_mountain, 0, "2 x 4^K triangles"},
    {"field", a_field, 0, 0}, {"vfield", a_vfield, 0, 0}, {"heatmap", a_heatmap, "field waves 8 8", 0},
    {"colorbar", a_colorbar, 0, 0}, {"contour", a_contour, "field waves 8 8", 0},
    {"quiver", a_quiver, "vfield vortex 8 8", 0}, {"stream", a_stream, "vfield vortex 8 8", 0},
    {"tfield", a_tfield, "field waves 8 8", 0}, {"tensorstyle", a_tensorstyle, 0, 0},
    {"tensor", a_tensor, "tfield rotating 8 8", 0}, {"starglyph", a_starglyph, 0, 0},
    {"glyphs", a_glyphs, "field waves 8 8\nvfield vortex 8 8", 0}, {"chromaticity", a_chromaticity, 0, 0},
    {"spectrum", a_spectrum, 0, 0},
    {"viewport3d", a_viewport3d, 0, 0}, {"depth", a_depth, 0, 0}, {"cleardepth", a_none, 0, 0},
    {"painter", a_painter, 0, 0}, {"flush", a_none, 0, 0}, {"camera", a_camera, 0, 0}, {"slide", a_slide, 0, 0},
    {"roll", a_deg, 0, 0}, {"pitch", a_deg, 0, 0}, {"yaw", a_deg, 0, 0}, {"perspective", a_perspective, 0, 0},
    {"ortho", a_ortho, 0, 0}, {"oblique", a_oblique, 0, 0}, {"identity3d", a_none, 0, 0}, {"push3d", a_none, 0, 0},
    {"pop3d", a_none, "push3d", 0}, {"translate3d", a_translate3d, 0, 0}, {"scale3d", a_scale3d, 0, 0},
    {"rotate3d", a_rotate3d, 0, 0}, {"rotatex", a_deg, 0, 0}, {"rotatey", a_deg, 0, 0}, {"rotatez", a_deg, 0, 0},
    {"shear3d", a_shear3d, 0, 0}, {"reflect3d", a_reflect3d, 0, 0}, {"light", a_light, 0, 0},
    {"ambient", a_color, 0, 0}, {"material", a_material, 0, 0}, {"shading", a_shading, 0, 0}, {"cull", a_cull, 0, 0},
    {"polymode", a_polymode, 0, 0}, {"background", a_color, 0, 0}, {"cube", a_size3, 0, TRIS},
    {"tetrahedron", a_size3, 0, TRIS}, {"octahedron", a_size3, 0, TRIS}, {"dodecahedron", a_size3, 0, TRIS},
    {"icosahedron", a_size3, 0, TRIS}, {"sphere", a_sphere, 0, TRIS}, {"ellipsoid", a_ellipsoid, 0, TRIS},
    {"torus", a_torus, 0, TRIS}, {"cone", a_cone, 0, TRIS}, {"cylinder", a_cone, 0, TRIS}, {"teapot", a_sizen, 0, TRIS},
    {"floor", a_sizen, 0, TRIS}, {"obj", a_obj, 0, TRIS}, {"shadowplane", a_shadowplane, L3, 0},
    {"shadowmap", a_shadowmap, L3, 0}, {"pass3d", a_pass3d, 0, 0}, {"texture3d", a_texture3d, TEX, 0},
    {"attenuation", a_attenuation, 0, 0}, {"polygon3d", a_polygon3d, 0, 0},
    {"solid3d", a_solid3d, 0, 0}, {"bump3d", a_bump3d, 0, 0}, {"frame3d", a_frame3d, 0, 0}, {"texgen", a_texgen, 0, 0},
    {"texmatrix", a_texmatrix, 0, 0}, {"alpha3d", a_alpha3d, 0, 0},
    {"rtcamera", a_rtcamera, 0, 0}, {"rtlight", a_rtlight, 0, 0}, {"rtambient", a_color, 0, 0},
    {"rtbackground", a_color, 0, 0}, {"rtmaterial", a_rtmaterial, 0, 0}, {"rttexture", a_rttexture, 0, 0},
    {"rtbump", a_rtbump, 0, 0}, {"rtframe", a_rtframe, 0, 0},
    {"rtdepth", a_rtdepth, 0, 0}, {"rtidentity", a_none, 0, 0}, {"rtpush", a_none, 0, 0},
    {"rtpop", a_none, "rtpush", 0}, {"rttranslate", a_rttranslate, 0, 0}, {"rtscale", a_rtscale, 0, 0},
    {"rtrotate", a_rtrotate, 0, 0}, {"rtshape", a_rtshape, 0, 0},
    {"rtmesh", a_rtmesh, 0, "at most 262144 triangles (FX_SCENE_MAX_TRIANGLES), the BVH 2 nodes a triangle"},
    {"rtcsg", a_rtcsg, "rtshape sphere\nrttranslate 0.5 0 0\nrtshape cube", 0},
    {"sdl", a_sdl, 0, "an SDL file: at most 256 objects, 4 lights, 200000 tokens read from macros, meshes of 20000 triangles (fixel/sdl.h)"},
    {"rtpreview", a_rtpreview, 0, 0},
    {"raytrace", a_raytrace, 0, RTWORK}, {"rttrace", a_rttrace, 0, RTWORK},
    {"vsdscene", a_vsdscene, 0, 0}, {"vsdpoly", a_vsdpoly, 0, 0}, {"vsdclear", a_none, 0, 0},
    {"vsdcull", a_vsdcull, 0, 0}, {"vsdoctree", a_vsdoctree, 0, 0}, {"vsd", a_vsd, "vsdscene 0", VSDW},
    {"paraboloid", a_paraboloid, 0, TRIS}, {"hyperboloid", a_hyperboloid, 0, TRIS},
    {"superellipsoid", a_superellipsoid, 0, TRIS}, {"supertoroid", a_supertoroid, 0, TRIS},
    {"blobball", a_blobball, 0, 0}, {"blobclear", a_none, 0, 0},
    {"blobby", a_blobby, "blobball 0 0 0 1 1", "6 NX NY NZ tetrahedra, each ball evaluated at (NX+1)(NY+1)(NZ+1) points"},
    {"patch", a_patch, 0, 0}, {"ptabcull", a_ptabcull, 0, 0}, {"coloursolid", a_coloursolid, 0, 0},
    {"octree", a_octree, "blobball 0 0 0 1 1",
     "2^(3K) voxels, each (blob) a field evaluation of every ball or (supertoroid) a row test of every triangle"},
    {"time", a_time, 0, 0}, {"key", a_key, 0, 0}, {"keycolor", a_keycolor, 0, 0}, {"interp", a_interp, 0, 0},
    {"ease", a_ease, 0, 0}, {"tween", a_tween, KEYS2, 0}, {"path", a_path, KEYS2, 0}, {"shape", a_shape, 0, 0},
    {"morph", a_morph, "shape a 0 0 10 0 0 10\nshape b 0 0 10 0 10 10 0 10", 0}, {"bounce", a_bounce, 0, BALLW},
    {"arm", a_arm, 0, ARMW}, {"armgoal", a_armgoal, 0, ARMW},
    {"blur", a_blur, 0, BLURW}, {"endblur", a_none, "blur 2 0.1", BLURW},
    /* issue #44 (the course's remaining methods) */
    {"gouraudscan", a_gouraudscan, 0, 0}, {"orbit", a_orbit, 0, 0},
    {"ifscopy", a_ifscopy, 0, "pixels x maps^DEPTH at most 2^24"},
    {0, 0, 0, 0},
};

const fx_scene_argspec *fx_scene_args_find(const char *cmd)
{
    for (const fx_scene_argspec *s = fx_scene_argspecs; s->cmd; s++) {
        const char *a = s->cmd, *b = cmd;
        while (*a && *a == *b)
            a++, b++;
        if (!*a && !*b)
            return s;
    }
    return 0;
}

/* A raw fixed-point value with `shift` fraction bits as a decimal: the
 * integer part, then up to 5 fraction digits (truncated toward zero). */
static int fixed_text(char *buf, size_t size, int64_t raw, unsigned shift)
{
    uint64_t m = raw < 0 ? 0 - (uint64_t)raw : (uint64_t)raw;
    uint64_t ip = m >> shift, fr = m & (((uint64_t)1 << shift) - 1);
    if (shift > 24) { /* keep fr * 100000 inside 64 bits */
        fr >>= shift - 24;
        shift = 24;
    }
    uint64_t d = (fr * 100000u) >> shift;
    int n = fx_fmt(buf, size, "%s%llu", raw < 0 ? "-" : "", (unsigned long long)ip);
    if ((size_t)n >= size)
        return (int)size - 1;
    if (d) {
        char f[8];
        int k = 5;
        f[k] = 0;
        while (k--) {
            f[k] = (char)('0' + d % 10);
            d /= 10;
        }
        k = 5;
        while (k > 1 && f[k - 1] == '0')
            f[--k] = 0;
        n += fx_fmt(buf + n, size - (size_t)n, ".%s", f);
    }
    return n;
}

int fx_scene_arg_range(const fx_scene_arg *a, char *buf, size_t size)
{
    if (!size)
        return 0;
    buf[0] = 0;
    if (a->type == FX_ARG_INT || a->type == FX_ARG_REPEAT)
        return fx_fmt(buf, size, "%lld..%lld", (long long)a->min, (long long)a->max);
    if (a->type != FX_ARG_FX16 && a->type != FX_ARG_FX56)
        return 0;
    unsigned shift = a->type == FX_ARG_FX16 ? 16 : FX56_SHIFT;
    int open = a->flags & FX_ARG_OPEN_MIN;
    size_t n = open ? (size_t)fx_fmt(buf, size, "more than ") : 0;
    if (n < size)
        n += (size_t)fixed_text(buf + n, size - n, a->min, shift);
    if (n < size)
        n += (size_t)fx_fmt(buf + n, size - n, open ? ", at most " : "..");
    if (n < size)
        n += (size_t)fixed_text(buf + n, size - n, a->max, shift);
    return n < size ? (int)n : (int)size - 1;
}
