// Registration of the dpm.* scenes; each scene lives in its own file.
#include "dpm/dpm_scenes.hpp"

#include "dpm/modes_scene.hpp"

namespace softgrain {

void register_dpm_scenes(SceneRegistry& registry)
{
    registry.add(
        Scene{"dpm.modes",
              "DPM eq. (9.28): eigenvalues of the dynamical matrix of a floppy / shell / surface-tension "
              "particle, zero modes, Delta U along each mode (Figs. 9.14a, c)",
              dpm::modes_parameters(), dpm::run_modes});
}

} // namespace softgrain
