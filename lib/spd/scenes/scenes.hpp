// The scenes of the soft particle dynamics method (Trivino et al.): spd.*, one file each in lib/spd/scenes/
// named after the scene, registered by register_spd_scenes in the order `softgrain list` shows them.
#pragma once

#include "core/scene.hpp"

namespace softgrain {

void register_spd_scenes(SceneRegistry& registry);

} // namespace softgrain

namespace softgrain::spd {

Scene beam_scene();             // section 3
Scene ring_pressure_scene();    // eqs. (19)-(25)
Scene ring_compression_scene(); // section 4
Scene bench_scene();            // the cost of the time-step loop
Scene compaction_scene();       // section 5
Scene tissue_scene();           // section 6

} // namespace softgrain::spd
