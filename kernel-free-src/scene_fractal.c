/* fixel — scene commands of the fractal module (filled in by that module's work). */
#include "fixel/scene.h"

const fx_scene_cmd fx_scene_cmds_fractal[] = {
    {0, 0, 0, 0},
};
