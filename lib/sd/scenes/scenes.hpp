// The scenes of Soft Dynamics (Rognon & Gay), one file per scene in this folder.
#pragma once

#include "core/scene.hpp"

namespace softgrain {

namespace sd {

Scene approach_scene();      // sd.approach (approach.cpp): Fig. 3
Scene phase_diagram_scene(); // sd.phase_diagram (phase_diagram.cpp): Fig. 3b
Scene many_scene();          // sd.many (many.cpp): note [20]

} // namespace sd

// The SD scenes in the order of `softgrain list` (registry.cpp).
void register_sd_scenes(SceneRegistry& registry);

} // namespace softgrain
