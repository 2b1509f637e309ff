// Scenes of the deformable particle model (MacKeith, Wang, Shattuck, O'Hern): dpm.*
#pragma once

#include "core/scene.hpp"

namespace softgrain {

void register_dpm_scenes(SceneRegistry& registry);

} // namespace softgrain
