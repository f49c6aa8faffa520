/* fixel — scene commands of the raster module (filled in by that module's work). */
#include "fixel/scene.h"

const fx_scene_cmd fx_scene_cmds_raster[] = {
    {0, 0, 0, 0},
};
