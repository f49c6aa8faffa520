/* SPDX-License-Identifier: MIT */
/* Built instead of boards/linux/drm/ when libdrm is not there (a board
 * toolchain without the target's libraries): the DRM backend reports
 * itself unavailable, so the automatic order goes on to fbdev and memory. */
#include "../../display/display_int.h"
#include "fixel/cards.h"
#include "fixel/error.h"

int fx_drm_open(fx_display *d)
{
    /* asked for by name (FIXEL_BACKEND=drm): an error that names the library */
    fx_log(&d->log, d->opt.backend == FX_BACKEND_DRM ? FX_LOG_ERROR : FX_LOG_DEBUG,
           "drm: this build has no libdrm (install libdrm-dev and rebuild fixel)");
    return -FX_ENOTSUP;
}

int fx_display_wait_connected(const fx_display_options *o, int timeout_ms)
{
    (void)timeout_ms;
    return o->backend == FX_BACKEND_DRM || o->backend == FX_BACKEND_AUTO ? -FX_ENODEV : 0;
}

int fx_drm_cards(fx_card_desc *out, int max)
{
    (void)out, (void)max;
    return 0;
}
