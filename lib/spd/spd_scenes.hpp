// Scenes of the SPD method (Trivino et al.): spd.beam, spd.ring_pressure, spd.ring_compression;
// assemblies (section 5, assembly_scenes.cpp): spd.bench, spd.compaction; tissue (section 6): spd.tissue.
#pragma once

#include "core/scene.hpp"

namespace softgrain {
void register_spd_scenes(SceneRegistry& registry);
void register_spd_assembly_scenes(SceneRegistry& registry);
void register_spd_tissue_scenes(SceneRegistry& registry); // section 6, tissue_scenes.cpp
} // namespace softgrain
