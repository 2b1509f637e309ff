// The catalogue of every scene softgrain knows: each method registers its own.
#include "compare/scenes/scenes.hpp"
#include "core/core_scenes.hpp"
#include "core/scene.hpp"
#include "dpm/scenes/scenes.hpp"
#include "sd/scenes/scenes.hpp"
#include "spd/scenes/scenes.hpp"
#include "vsm/scenes/scenes.hpp"

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
