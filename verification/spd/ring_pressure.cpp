// SPD eqs. (19)-(25): a regular N-gon ring under a small internal pressure.
#include "core/errors.hpp"
#include "spd/calibration.hpp"
#include "spd/ring.hpp"
#include "support/tolerance.hpp"

using namespace softgrain::spd;
using softgrain::verification::Tolerance;

namespace {
RingSetup ring(int nodes, double eta)
{
    RingSetup r;
    r.nodes = nodes;
    r.eta = eta;
    return r;
}
} // namespace

TEST_CASE("ring shell modulus p/(dV/V0) = (k_s/s) tan(pi/N) [SPD eq. (23)]")
{
    for (int nodes : {16, 64, 256}) {
        const RingSetup setup = ring(nodes, 0.0);
        const RingScales sc = ring_scales(setup);
        const double p = 1e-5 * sc.K_shell; // dV/V0 ~ 1e-5
        CAPTURE(nodes);
        // Eq. (22) is the linearisation of p = (k_s/s) 2 tan(pi/N) x/(1+x), dV/V0 = 2x + x^2 (x = dl/l0): the
        // measured modulus is K (1 - 1.5 x) with x = 5e-6, and the relaxation stops at an unbalanced force of
        // 1e-5 p s l0 (a relative error of that order in dV): 1e-4 bounds both (the issue asks for 0.5%).
        CHECK_CLOSE(ring_under_pressure(setup, p).K_measured, sc.K_shell, (Tolerance{1e-4, 0}));
    }
}

TEST_CASE("effective bulk modulus with an undrained core is (1 + eta) K_shell [SPD eqs. (4), (24)-(25)]")
{
    for (double eta : {1.0, 10.0, 1e5}) {
        const RingSetup setup = ring(64, eta);
        const RingScales sc = ring_scales(setup);
        const double K_e = effective_bulk_modulus(eta, sc.K_shell);
        CAPTURE(eta);
        // Same linearisation error as above (now at dV/V0 = 1e-5 of the stiffer particle); the core pressure
        // p = -K_Omega dV/V0 is exact (accumulated increments telescope up to round-off).
        CHECK_CLOSE(ring_under_pressure(setup, 1e-5 * K_e).K_measured, K_e, (Tolerance{1e-4, 0}));
    }
}

TEST_CASE(
    "the largest stable time step sits at dt_c = sqrt(m/k_max); above it the run stops [SPD section 2.4]")
{
    // For a ring dominated by k_s the stiffest mode (alternating stretch) has omega^2 = 4 k_s/m (1 +
    // O(h^2/l^2)), so velocity Verlet is stable up to dt = sqrt(m/k_s) = dt_c: 0.95 dt_c relaxes, 1.1 dt_c
    // is refused before the run (check_time_step, spd/time_step_limits.hpp) with a NumericalError (exit 3);
    // that it would diverge is shown in stability.cpp (bounded at 0.99 dt_c, blow-up at 1.01 dt_c).
    RingSetup setup = ring(32, 0.0);
    const double p = 1e-5 * ring_scales(setup).K_shell;
    setup.dt_factor = 0.95;
    CHECK_NOTHROW(ring_under_pressure(setup, p));
    setup.dt_factor = 1.1;
    CHECK_THROWS_AS(ring_under_pressure(setup, p), softgrain::NumericalError);
}
