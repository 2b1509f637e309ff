// Registration of the spd.* scenes, in the order `softgrain list` shows them.
#include "spd/scenes/scenes.hpp"

namespace softgrain {

void register_spd_scenes(SceneRegistry& registry)
{
    registry.add(spd::beam_scene());
    registry.add(spd::ring_pressure_scene());
    registry.add(spd::ring_compression_scene());
    registry.add(spd::bench_scene());
    registry.add(spd::compaction_scene());
    registry.add(spd::tissue_scene());
}

} // namespace softgrain
