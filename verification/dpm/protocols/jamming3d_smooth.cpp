// ctest-label: slow
// DPM section 9.4 in 3D with smooth contacts (vertex against faces, interactions3d.hpp): the jamming
// protocol (compression, FIRE, bisection on the virial pressure that includes the smooth contact forces)
// ends in force balance at 1 <= P/P_t < 1.01 with both particles in contact, and the dynamical matrix of the
// shell packing has exactly the 3 zero modes of the periodic translations (sec. 9.4.3, as for rough
// contacts in jamming3d.cpp). Two icosahedral shells, P_t = 1e-4 k_v v0: about 7 s.
#include "dpm/protocols/jam3d.hpp"
#include "support/jammed3d.hpp"

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::check_jammed3d;

TEST_CASE("3D jamming with smooth contacts ends in force balance at 1 <= P/P_t < 1.01 [DPM sec. 9.4]")
{
    Jam3dOptions o;
    o.particles = 2;
    o.mesh = "icosahedron";
    o.pressure_onset = 1e-4;
    o.interaction = InteractionKind::smooth;
    Jam3dResult j = jam3d(o);
    CHECK(j.system.interaction == InteractionKind::smooth);
    const auto modes = check_jammed3d(j, o.pressure_onset);
    CHECK(modes.rattlers == 0); // both particles in contact
    CHECK(modes.zero_modes == 3);
}
