// The SD scenes, in the order of `softgrain list`.
#include "sd/scenes/scenes.hpp"

namespace softgrain {

void register_sd_scenes(SceneRegistry& registry)
{
    registry.add(sd::approach_scene());
    registry.add(sd::phase_diagram_scene());
    registry.add(sd::many_scene());
}

} // namespace softgrain
