/* SPDX-License-Identifier: MIT */
/* The pure helpers of the Linux display backends: the pixel format of an
 * fbdev bitfield layout, mode strings, a DRM plane's rotation property and
 * its scanout format. No OS headers and no allocation, so tests can feed
 * them fake device state. */
#include <stddef.h>
#include <string.h>

#include "../../display/display_int.h"
#include "fixel/error.h"

/* ---- formats --------------------------------------------------------- */

static int bf_is(const fx_fb_bitfields *b, uint32_t ro, uint32_t rl, uint32_t go, uint32_t gl,
                 uint32_t bo, uint32_t bl)
{
    return b->red_offset == ro && b->red_length == rl && b->green_offset == go &&
           b->green_length == gl && b->blue_offset == bo && b->blue_length == bl;
}

fx_format fx_fb_format_from_bitfields(const fx_fb_bitfields *b)
{
    switch (b->bits_per_pixel) {
    case 32:
        if (b->grayscale)
            return FX_FMT_COUNT;
        /* An alpha channel the scanout honours would make X=0 pixels
         * transparent, so a real alpha field selects ARGB and we write 0xFF. */
        if (bf_is(b, 16, 8, 8, 8, 0, 8))
            return b->transp_length == 8 && b->transp_offset == 24 ? FX_FMT_ARGB8888
                                                                   : FX_FMT_XRGB8888;
        if (bf_is(b, 0, 8, 8, 8, 16, 8) && b->transp_length == 0)
            return FX_FMT_XBGR8888;
        return FX_FMT_COUNT;
    case 24:
        if (b->grayscale)
            return FX_FMT_COUNT;
        if (bf_is(b, 16, 8, 8, 8, 0, 8))
            return FX_FMT_RGB888;
        if (bf_is(b, 0, 8, 8, 8, 16, 8))
            return FX_FMT_BGR888;
        return FX_FMT_COUNT;
    case 16:
        if (b->grayscale)
            return FX_FMT_COUNT;
        if (bf_is(b, 11, 5, 5, 6, 0, 5))
            return FX_FMT_RGB565;
        if (bf_is(b, 0, 5, 5, 6, 11, 5))
            return FX_FMT_BGR565;
        return FX_FMT_COUNT;
    case 8:
        /* Only true gray: an 8-bit pseudocolour map would need a palette. */
        return b->grayscale ? FX_FMT_GRAY8 : FX_FMT_COUNT;
    case 1:
        /* MONO1 lights set bits; a MONO01 visual (set = black) would draw a
         * negative, so it is refused rather than silently inverted. */
        return b->mono_inverted ? FX_FMT_COUNT : FX_FMT_MONO1;
    default:
        return FX_FMT_COUNT;
    }
}

/* ---- mode strings ---------------------------------------------------- */

static const char *parse_dec(const char *s, int32_t *out)
{
    int32_t v = 0;
    if (*s < '0' || *s > '9')
        return NULL;
    while (*s >= '0' && *s <= '9') {
        if (v > 99999)
            return NULL;
        v = v * 10 + (*s++ - '0');
    }
    *out = v;
    return s;
}

int fx_mode_parse(const char *s, int32_t *w, int32_t *h, int32_t *hz)
{
    int32_t a, b, r = 0;
    if (!s)
        return -FX_EINVAL;
    s = parse_dec(s, &a);
    if (!s || (*s != 'x' && *s != 'X'))
        return -FX_EINVAL;
    s = parse_dec(s + 1, &b);
    if (!s)
        return -FX_EINVAL;
    if (*s == '@') {
        s = parse_dec(s + 1, &r);
        if (!s || r == 0)
            return -FX_EINVAL;
    }
    if (*s || a == 0 || b == 0)
        return -FX_EINVAL;
    *w = a;
    *h = b;
    *hz = r;
    return 0;
}

/* ---- plane rotation and pixel format choice --------------------------- */

/* The names the kernel gives the bits of a plane's "rotation" bitmask
 * (drm_plane_create_rotation_property); index = bit number. */
static const char *const rot_names[] = {"rotate-0", "rotate-90", "rotate-180", "rotate-270",
                                        "reflect-x", "reflect-y"};

uint32_t fx_plane_rotation_mask(const fx_prop_enum *e, int n)
{
    uint32_t mask = 0;
    for (int i = 0; e && i < n; i++) {
        for (uint32_t b = 0; b < sizeof rot_names / sizeof rot_names[0]; b++) {
            /* A value that disagrees with the name is not a rotation
             * property this code understands: ignore the entry. */
            if (!strncmp(e[i].name, rot_names[b], sizeof e[i].name) && e[i].value == b)
                mask |= 1u << b;
        }
    }
    return mask;
}

int fx_panel_orientation_rotation(const char *name)
{
    /* The kernel's console turns "right side up" by DRM rotate-270 (counter-
     * clockwise), i.e. 90 clockwise: the picture's top goes to the panel's
     * right edge, which is the viewer's up. */
    static const struct {
        const char *name;
        int rotation;
    } map[] = {{"Normal", 0}, {"Upside Down", 180}, {"Left Side Up", 270}, {"Right Side Up", 90}};
    for (size_t i = 0; name && i < sizeof map / sizeof map[0]; i++)
        if (!strcmp(name, map[i].name))
            return map[i].rotation;
    return -1;
}

uint32_t fx_plane_rotation_bit(int rotation)
{
    /* fixel turns the picture clockwise; DRM's rotate-N is counter-clockwise. */
    switch (rotation) {
    case 0: return FX_PLANE_ROTATE_0;
    case 90: return FX_PLANE_ROTATE_270;
    case 180: return FX_PLANE_ROTATE_180;
    case 270: return FX_PLANE_ROTATE_90;
    default: return 0;
    }
}

int fx_plane_rotation_choose(int rotation, int has_property, uint32_t mask, int force_software,
                             const char **why)
{
    uint32_t bit = fx_plane_rotation_bit(rotation);
    const char *w;
    int hw = 0;
    if (rotation == 0)
        w = "none needed";
    else if (force_software)
        w = "in software (forced)";
    else if (!has_property)
        w = "in software (no plane rotation property)";
    else if (!bit || !(mask & bit))
        w = "in software (the plane cannot rotate by this angle)";
    else {
        w = "by the plane";
        hw = 1;
    }
    if (why)
        *why = w;
    return hw;
}

fx_format fx_drm_format_choose(fx_format want, int has_xrgb, int has_565, const char **why)
{
    const char *w;
    fx_format f;
    if (want != FX_FMT_COUNT && want != FX_FMT_XRGB8888 && want != FX_FMT_RGB565) {
        f = FX_FMT_COUNT;
        w = "DRM draws XRGB8888 or RGB565";
    } else if (want == FX_FMT_COUNT) {
        /* XRGB8888 is exact for every colour; 16 bits only when forced. */
        if (has_xrgb) {
            f = FX_FMT_XRGB8888;
            w = "default";
        } else if (has_565) {
            f = FX_FMT_RGB565;
            w = "plane offers no XRGB8888";
        } else {
            f = FX_FMT_COUNT;
            w = "plane takes neither XRGB8888 nor RGB565";
        }
    } else {
        int have = want == FX_FMT_XRGB8888 ? has_xrgb : has_565;
        int other = want == FX_FMT_XRGB8888 ? has_565 : has_xrgb;
        if (have) {
            f = want;
            w = "requested";
        } else if (other) {
            f = want == FX_FMT_XRGB8888 ? FX_FMT_RGB565 : FX_FMT_XRGB8888;
            w = "requested format not offered by the plane";
        } else {
            f = FX_FMT_COUNT;
            w = "plane takes neither XRGB8888 nor RGB565";
        }
    }
    if (why)
        *why = w;
    return f;
}

int fx_dpms_values(const fx_prop_enum *e, int n, uint64_t *on, uint64_t *off)
{
    int have_on = 0, have_off = 0;
    for (int i = 0; e && i < n; i++) {
        if (!strncmp(e[i].name, "On", sizeof e[i].name))
            *on = e[i].value, have_on = 1;
        else if (!strncmp(e[i].name, "Off", sizeof e[i].name))
            *off = e[i].value, have_off = 1;
    }
    return have_on && have_off ? 0 : -1;
}
