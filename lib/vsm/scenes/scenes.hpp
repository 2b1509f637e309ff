// The scenes of the Voronoi strain-based method (Frenning 2022), one file per scene in this folder.
#pragma once

#include "core/scene.hpp"

namespace softgrain {

namespace vsm {

Scene patch_scene();         // vsm.patch (patch.cpp): patch tests A, B, C, Table 1
Scene swinging_cube_scene(); // vsm.swinging_cube (swinging_cube.cpp): Fig. 5
Scene lblock_scene();        // vsm.lblock (lblock.cpp): Figs. 6-8
Scene punch_scene();         // vsm.punch (punch.cpp): Figs. 9-10
Scene compress_ball_scene(); // vsm.compress_ball (compress_ball.cpp): compare.solid, a ball between plates

} // namespace vsm

// The VSM scenes in the order of `softgrain list` (registry.cpp).
void register_vsm_scenes(SceneRegistry& registry);

} // namespace softgrain
