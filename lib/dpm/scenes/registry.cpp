// Registration of the dpm.* scenes, in the order `softgrain list` shows them.
#include "dpm/scenes/scenes.hpp"

namespace softgrain {

void register_dpm_scenes(SceneRegistry& registry)
{
    registry.add(dpm::modes_scene());
    registry.add(dpm::shear_friction_scene());
    registry.add(dpm::packing_fraction_scene());
    registry.add(dpm::crystal_modes_scene());
    registry.add(dpm::jam_scene());
    registry.add(dpm::bench_scene());
    registry.add(dpm::rearrangement_scene());
    registry.add(dpm::compress2d_scene());
    registry.add(dpm::compress3d_scene());
    registry.add(dpm::compress_box_scene());
    registry.add(dpm::boundary_jam_scene());
    registry.add(dpm::shape3d_scene());
    registry.add(dpm::modes3d_scene());
    registry.add(dpm::shear_modulus_scene());
    registry.add(dpm::shear_modulus3d_scene());
    registry.add(dpm::slump_scene());
    registry.add(dpm::slide3d_scene());
}

} // namespace softgrain
