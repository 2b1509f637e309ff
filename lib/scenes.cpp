// The catalogue of every scene softgrain knows: each method registers its own.
#include "vsm/scenes/scenes.hpp"
#include "compare/compare_scenes.hpp"
#include "core/core_scenes.hpp"
#include "core/scene.hpp"
#include "dpm/dpm_scenes.hpp"
#include "sd/scenes/scenes.hpp"
#include "spd/spd_scenes.hpp"

namespace softgrain {

SceneRegistry all_scenes()
{
    SceneRegistry registry;
    register_core_scenes(registry);
    register_spd_scenes(registry);
    register_dpm_scenes(registry);
    register_vsm_scenes(registry);
    register_sd_scenes(registry);
    register_compare_scenes(registry);
    return registry;
}

} // namespace softgrain
