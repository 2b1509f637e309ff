// Scenes that solve one physical problem with several methods, side by side: compare.ring (a ring between
// two plates, SPD and DPM against the elastica).
#pragma once

#include "core/scene.hpp"

namespace softgrain {
void register_compare_scenes(SceneRegistry& registry);
} // namespace softgrain
