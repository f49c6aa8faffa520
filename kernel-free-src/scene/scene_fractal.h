/* SPDX-License-Identifier: MIT */
/* Scene state shared by the fractal and viz commands (private to the core). */
#ifndef FIXEL_SCENE_FRACTAL_H
#define FIXEL_SCENE_FRACTAL_H

#include "fixel/colormap.h"
#include "fixel/ifs.h"
#include "fixel/scene.h"

typedef struct fx_scene_fractal {
    fx_cmap cmap;    /* FX_CMAP_COUNT: the W9 grey ramp */
    uint32_t period; /* 0: the map spans the value range once */
    fx_color inside; /* escape-time points that never escape */
    int nmaps;       /* user IFS ('ifsmap', 'ifswindow') */
    fx_ifs_map maps[FX_IFS_MAX_MAPS];
    fx16 win[4];
} fx_scene_fractal;

/* The current settings (defaults when the script set none). */
const fx_scene_fractal *fx_scene_fractal_state(fx_scene *sc);

#endif
