// Scenes that solve one physical problem with several methods, side by side: compare.*, one file each in
// lib/compare/scenes/ named after the scene, registered by register_compare_scenes.
#pragma once

#include "core/scene.hpp"

namespace softgrain {

void register_compare_scenes(SceneRegistry& registry);

} // namespace softgrain

namespace softgrain::compare {

Scene ring_scene(); // a ring between two plates, SPD and DPM against the elastica

} // namespace softgrain::compare
