#pragma once

#include "core/scene.hpp"

namespace softgrain {

// VSM (Frenning 2022): vsm.patch, vsm.swinging_cube, vsm.lblock.
void register_vsm_scenes(SceneRegistry& registry);

} // namespace softgrain
