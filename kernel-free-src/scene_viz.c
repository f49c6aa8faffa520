/* fixel — scene commands of the viz module (filled in by that module's work). */
#include "fixel/scene.h"

const fx_scene_cmd fx_scene_cmds_viz[] = {
    {0, 0, 0, 0},
};
