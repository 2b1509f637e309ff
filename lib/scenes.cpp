// The catalogue of every scene softgrain knows: each method registers its own.
#include "core/core_scenes.hpp"
#include "core/scene.hpp"
#include "spd/spd_scenes.hpp"

namespace softgrain {

SceneRegistry all_scenes()
{
    SceneRegistry registry;
    register_core_scenes(registry);
    register_spd_scenes(registry);
    return registry;
}

} // namespace softgrain
