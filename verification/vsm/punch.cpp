// Punch test (Frenning 2022, section 6.4, Fig. 10): the contact forces of eq. (46) suppress zero-energy
// modes.
#include "vsm/punch.hpp"
#include "support/tolerance.hpp"

using namespace softgrain;
using namespace softgrain::vsm;

namespace {
PunchSnapshot punch(double xi)
{
    PunchSetup s;
    s.counts = {15, 8, 3}; // coarser than the paper's 21 x 11 x 3 to keep the test fast
    s.options.xi_n = s.options.xi_t = xi;
    s.snapshot_strains = {0.15};
    return run_punch(s, [](const PunchSnapshot&) {}).snapshots.back();
}
} // namespace

TEST_CASE(
    "punch: hourglass modes without stabilisation (xi = 0), none with xi = 1 [VSM section 6.4, eq. (46)]")
{
    const PunchSnapshot stabilised = punch(1.0), free_modes = punch(0.0);
    INFO("non-affine ratio: xi = 1 " << stabilised.nonaffine_ratio << ", xi = 0 "
                                     << free_modes.nonaffine_ratio);
    // Zero-energy modes make the local (non-affine) displacement of a bond as large as the bond's
    // displacement itself (ratio -> O(1); observed 0.81); with xi = 1 the field is smooth away from the punch
    // edge (observed 0.22; the edge singularity sets this floor). A factor 2 separates the two regimes with
    // margin.
    CHECK(free_modes.nonaffine_ratio > 0.6);
    CHECK(free_modes.nonaffine_ratio > 2 * stabilised.nonaffine_ratio);
    // The stabilised specimen carries the punch: a compressive load of order E A strain (1 MPa x 0.033 m^2 x
    // 0.15 = 5 kN; the contact springs and the edge concentration raise it) is reached.
    CHECK(stabilised.punch_force > 5e3);
}
