/* SPDX-License-Identifier: MIT */
/* DRM plane choices on fake property data (boards/linux/display/formats.c): which
 * rotations a plane's "rotation" bitmask offers, whether the plane or a
 * software copy rotates, and the scanout format (XRGB8888 / RGB565). */
#include <string.h>

#include "../../boards/display/display_int.h"
#include "fx_test.h"

static fx_prop_enum ent(uint64_t v, const char *name)
{
    fx_prop_enum e;
    memset(&e, 0, sizeof e);
    e.value = v;
    strncpy(e.name, name, sizeof e.name - 1);
    return e;
}

/* What vc4 and most atomic drivers list: every rotation and both reflections. */
FX_TEST(plane_rotation_mask_full_property)
{
    fx_prop_enum e[6] = {ent(0, "rotate-0"),   ent(1, "rotate-90"), ent(2, "rotate-180"),
                         ent(3, "rotate-270"), ent(4, "reflect-x"), ent(5, "reflect-y")};
    FX_CHECK_EQ(fx_plane_rotation_mask(e, 6), 0x3fu);
}

/* A panel driver offering only 0 and 180 (e.g. an upside-down mounted
 * DSI panel): 90 and 270 must not be chosen. */
FX_TEST(plane_rotation_mask_partial_and_order)
{
    fx_prop_enum e[3] = {ent(2, "rotate-180"), ent(0, "rotate-0"), ent(4, "reflect-x")};
    uint32_t m = fx_plane_rotation_mask(e, 3);
    FX_CHECK_EQ(m, FX_PLANE_ROTATE_0 | FX_PLANE_ROTATE_180 | (1u << 4));
    FX_CHECK(!(m & FX_PLANE_ROTATE_90));
    FX_CHECK(!(m & FX_PLANE_ROTATE_270));
}

FX_TEST(plane_rotation_mask_rejects_mismatched_or_unknown)
{
    /* A name with the wrong bit, an unknown name, an empty name. */
    fx_prop_enum e[3] = {ent(3, "rotate-90"), ent(1, "rotate-91"), ent(0, "")};
    FX_CHECK_EQ(fx_plane_rotation_mask(e, 3), 0u);
    FX_CHECK_EQ(fx_plane_rotation_mask(NULL, 4), 0u);
    /* A name filling all 32 bytes without a terminator must not be read past. */
    fx_prop_enum full;
    memset(&full, 'r', sizeof full);
    full.value = 0;
    FX_CHECK_EQ(fx_plane_rotation_mask(&full, 1), 0u);
}

/* fixel turns clockwise, DRM's rotate-N counter-clockwise. */
FX_TEST(plane_rotation_bit_direction)
{
    FX_CHECK_EQ(fx_plane_rotation_bit(0), FX_PLANE_ROTATE_0);
    FX_CHECK_EQ(fx_plane_rotation_bit(90), FX_PLANE_ROTATE_270);
    FX_CHECK_EQ(fx_plane_rotation_bit(180), FX_PLANE_ROTATE_180);
    FX_CHECK_EQ(fx_plane_rotation_bit(270), FX_PLANE_ROTATE_90);
    FX_CHECK_EQ(fx_plane_rotation_bit(45), 0u);
}

FX_TEST(plane_rotation_choice)
{
    const uint32_t all = 0xf, half = FX_PLANE_ROTATE_0 | FX_PLANE_ROTATE_180;
    const char *why = NULL;
    static const int rots[] = {90, 180, 270};
    for (int i = 0; i < 3; i++) {
        int r = rots[i];
        FX_CHECK_EQ(fx_plane_rotation_choose(r, 1, all, 0, &why), 1);
        FX_CHECK(!strcmp(why, "by the plane"));
        FX_CHECK_EQ(fx_plane_rotation_choose(r, 1, all, 1, &why), 0);
        FX_CHECK(strstr(why, "forced") != NULL);
        FX_CHECK_EQ(fx_plane_rotation_choose(r, 0, 0, 0, &why), 0);
        FX_CHECK(strstr(why, "no plane rotation property") != NULL);
        FX_CHECK_EQ(fx_plane_rotation_choose(r, 1, half, 0, &why), r == 180);
    }
    /* Rotation 0 never needs the plane, even when offered. */
    FX_CHECK_EQ(fx_plane_rotation_choose(0, 1, all, 0, &why), 0);
    /* A property that lists only rotate-0 cannot rotate at all. */
    FX_CHECK_EQ(fx_plane_rotation_choose(90, 1, FX_PLANE_ROTATE_0, 0, &why), 0);
    FX_CHECK(strstr(why, "cannot rotate") != NULL);
    FX_CHECK_EQ(fx_plane_rotation_choose(90, 1, all, 0, NULL), 1);
}

FX_TEST(drm_format_choice)
{
    const char *why = NULL;
    /* Automatic: XRGB8888 when offered, RGB565 only when it is all there is. */
    FX_CHECK_EQ(fx_drm_format_choose(FX_FMT_COUNT, 1, 1, &why), FX_FMT_XRGB8888);
    FX_CHECK_EQ(fx_drm_format_choose(FX_FMT_COUNT, 1, 0, &why), FX_FMT_XRGB8888);
    FX_CHECK_EQ(fx_drm_format_choose(FX_FMT_COUNT, 0, 1, &why), FX_FMT_RGB565);
    FX_CHECK(strstr(why, "no XRGB8888") != NULL);
    FX_CHECK_EQ(fx_drm_format_choose(FX_FMT_COUNT, 0, 0, &why), FX_FMT_COUNT);
    /* Requested: honoured when offered, the other one otherwise. */
    FX_CHECK_EQ(fx_drm_format_choose(FX_FMT_RGB565, 1, 1, &why), FX_FMT_RGB565);
    FX_CHECK(!strcmp(why, "requested"));
    FX_CHECK_EQ(fx_drm_format_choose(FX_FMT_RGB565, 1, 0, &why), FX_FMT_XRGB8888);
    FX_CHECK_EQ(fx_drm_format_choose(FX_FMT_XRGB8888, 0, 1, &why), FX_FMT_RGB565);
    FX_CHECK_EQ(fx_drm_format_choose(FX_FMT_RGB565, 0, 0, &why), FX_FMT_COUNT);
    /* Formats DRM dumb buffers are not set up for here. */
    FX_CHECK_EQ(fx_drm_format_choose(FX_FMT_BGR565, 1, 1, &why), FX_FMT_COUNT);
    FX_CHECK_EQ(fx_drm_format_choose(FX_FMT_MONO1, 1, 1, NULL), FX_FMT_COUNT);
}

/* The connector's "panel orientation" names, turned the way the kernel's
 * console turns them (drm_client_rotation: right side up is DRM rotate-270,
 * counter-clockwise, so 90 clockwise in fixel's terms). */
FX_TEST(panel_orientation_to_rotation)
{
    FX_CHECK_EQ(fx_panel_orientation_rotation("Normal"), 0);
    FX_CHECK_EQ(fx_panel_orientation_rotation("Upside Down"), 180);
    FX_CHECK_EQ(fx_panel_orientation_rotation("Left Side Up"), 270);
    FX_CHECK_EQ(fx_panel_orientation_rotation("Right Side Up"), 90);
    /* and the DRM bit fixel would set for it is the console's */
    FX_CHECK_EQ(fx_plane_rotation_bit(fx_panel_orientation_rotation("Right Side Up")), FX_PLANE_ROTATE_270);
    FX_CHECK_EQ(fx_plane_rotation_bit(fx_panel_orientation_rotation("Left Side Up")), FX_PLANE_ROTATE_90);
    FX_CHECK_EQ(fx_panel_orientation_rotation("right side up"), -1);
    FX_CHECK_EQ(fx_panel_orientation_rotation(""), -1);
    FX_CHECK_EQ(fx_panel_orientation_rotation(NULL), -1);
}

/* What drm_connector.c lists for every connector. */
FX_TEST(dpms_values_kernel_list)
{
    fx_prop_enum e[4] = {ent(0, "On"), ent(1, "Standby"), ent(2, "Suspend"), ent(3, "Off")};
    uint64_t on = 9, off = 9;
    FX_CHECK_EQ(fx_dpms_values(e, 4, &on, &off), 0);
    FX_CHECK_EQ(on, 0u);
    FX_CHECK_EQ(off, 3u);
}

/* Values are taken from the entries, not assumed; a list without "Off"
 * (or with a near name) is not a usable DPMS property. */
FX_TEST(dpms_values_from_entries_and_incomplete)
{
    fx_prop_enum e[2] = {ent(7, "Off"), ent(5, "On")};
    uint64_t on = 0, off = 0;
    FX_CHECK_EQ(fx_dpms_values(e, 2, &on, &off), 0);
    FX_CHECK_EQ(on, 5u);
    FX_CHECK_EQ(off, 7u);
    fx_prop_enum f[3] = {ent(0, "On"), ent(1, "Standby"), ent(3, "off")};
    FX_CHECK_EQ(fx_dpms_values(f, 3, &on, &off), -1);
    FX_CHECK_EQ(fx_dpms_values(NULL, 0, &on, &off), -1);
}
