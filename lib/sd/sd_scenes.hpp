#pragma once

#include "core/scene.hpp"

namespace softgrain {

// sd.approach, sd.phase_diagram, sd.many (Rognon & Gay, Soft Dynamics).
void register_sd_scenes(SceneRegistry& registry);

} // namespace softgrain
