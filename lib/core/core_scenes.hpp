#pragma once

#include "core/scene.hpp"

namespace softgrain {

void register_core_scenes(SceneRegistry& registry);

} // namespace softgrain
