// Scenes of the SPD method (Trivino et al.): spd.beam, spd.ring_pressure, spd.ring_compression.
#pragma once

#include "core/scene.hpp"

namespace softgrain {
void register_spd_scenes(SceneRegistry& registry);
}
