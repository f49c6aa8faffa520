/* SPDX-License-Identifier: MIT */
/* fixel — scene commands of the input module (filled in by that module's work). */
#include "fixel/scene.h"

const fx_scene_cmd fx_scene_cmds_input[] = {
    {0, 0, 0, 0},
};
