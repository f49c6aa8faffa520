/* fixel — scene commands of the 3d module (filled in by that module's work). */
#include "fixel/scene.h"

const fx_scene_cmd fx_scene_cmds_3d[] = {
    {0, 0, 0, 0},
};
