/* SPDX-License-Identifier: MIT */
/* Scene state shared by the fractal and viz commands (private to the core). */
#ifndef FIXEL_SCENE_FRACTAL_H
#define FIXEL_SCENE_FRACTAL_H

#include "fixel/colormap.h"
#include "fixel/ifs.h"
#include "fixel/scene.h"
#include "fixel/turtle.h"

/* Work bounds of the scene commands (argument table, scene_args.c): each
 * keeps its work within these (the corner tests run the maxima). */
#define FX_JULIA_SCENE_POINTS (1 << 20)
#define FX_JULIA_SCENE_DEPTH 18
#define FX_JULIA_SCENE_ITER 4096
#define FX_GRASS_SCENE_BLADES 16384
#define FX_FIC_SCENE_SIDE 128

typedef struct fx_scene_fractal {
    fx_cmap cmap;    /* FX_CMAP_COUNT: the W9 grey ramp */
    uint32_t period; /* 0: the map spans the value range once */
    fx_color inside; /* escape-time points that never escape */
    int nmaps;       /* user IFS ('ifsmap', 'ifswindow') */
    fx_ifs_map maps[FX_IFS_MAX_MAPS];
    fx16 win[4];
    fx_turtle turtle; /* 'turtle': its ctx is re-pointed at the scene's each time */
    void *buf;        /* 'mountain': height grid and vertex colours, reused */
    size_t buf_bytes;
} fx_scene_fractal;

/* The current settings (defaults when the script set none). */
const fx_scene_fractal *fx_scene_fractal_state(fx_scene *sc);

#endif
