// The VSM scenes, in the order of `softgrain list`.
#include "vsm/scenes/scenes.hpp"

namespace softgrain {

void register_vsm_scenes(SceneRegistry& registry)
{
    registry.add(vsm::patch_scene());
    registry.add(vsm::swinging_cube_scene());
    registry.add(vsm::lblock_scene());
    registry.add(vsm::punch_scene());
    registry.add(vsm::compress_ball_scene());
}

} // namespace softgrain
