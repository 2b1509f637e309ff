// Registration of the compare.* scenes, in the order `softgrain list` shows them.
#include "compare/scenes/scenes.hpp"

namespace softgrain {

void register_compare_scenes(SceneRegistry& registry)
{
    registry.add(compare::ring_scene());
}

} // namespace softgrain
