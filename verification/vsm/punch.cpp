// Punch test (Frenning 2022, section 6.4, Fig. 10): the contact forces of eq. (46) suppress zero-energy
// modes.
#include "vsm/punch.hpp"
#include "support/tolerance.hpp"

#include <cmath>

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

TEST_CASE(
    "punch: without stabilisation the total load is the paper's reaction [VSM eqs. (39), (46); issue 22]")
{
    // punch_load_total adds the load of the contact stabilisation, dV^cnt/d(punch displacement); with xi = 0
    // there is no V^cnt, so the two definitions coincide to the last bit.
    const PunchSnapshot free_modes = punch(0.0), stabilised = punch(1.0);
    CHECK(free_modes.punch_load_total == free_modes.punch_force);
    // With xi = 1 the stabilisation carries a share of the load (about -2 % at 10-15 % indentation, issue 22's
    // measurement); it must be present, and smaller than the elastic reaction.
    CHECK(stabilised.punch_load_total != stabilised.punch_force);
    CHECK(std::abs(stabilised.punch_load_total / stabilised.punch_force - 1) < 0.1);
}
