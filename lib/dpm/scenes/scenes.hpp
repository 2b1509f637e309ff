// The scenes of the deformable particle model (MacKeith, Wang, Shattuck, O'Hern): dpm.*, one file each in
// lib/dpm/scenes/ named after the scene, registered by register_dpm_scenes in the order `softgrain list`
// shows them.
#pragma once

#include "core/scene.hpp"

namespace softgrain {

void register_dpm_scenes(SceneRegistry& registry);

} // namespace softgrain

namespace softgrain::dpm {

Scene modes_scene();
Scene shear_friction_scene();
Scene packing_fraction_scene();
Scene crystal_modes_scene();
Scene jam_scene();
Scene bench_scene();
Scene rearrangement_scene();
Scene compress2d_scene();
Scene compress3d_scene();
Scene compress_box_scene();
Scene boundary_jam_scene();
Scene shape3d_scene();
Scene modes3d_scene();
Scene shear_modulus_scene();
Scene shear_modulus3d_scene();
Scene slump_scene();
Scene slide3d_scene();

} // namespace softgrain::dpm
