// DPM section 9.3.3: effective friction of two particles in simple shear. Rough particles: the maximum
// mu_eff approaches eq. (9.13) (the rigid, zero-overlap limit) for several (C, N); smooth elastic shells
// give a much smaller maximum, 0.190 in the paper.
#include "dpm/protocols/shear_friction.hpp"
#include "dpm/protocols/frozen_contact.hpp"
#include "support/tolerance.hpp"

#include <numbers>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::Tolerance;

TEST_CASE("rough shells: max mu_eff -> ([1/(C sin(pi/N))]^2 - 1)^(-1/2) for several (C, N) [DPM eq. (9.13)]")
{
    const std::pair<int, double> cases[] = {{8, 1.3}, {8, 0.71}, {6, 1.0}, {10, 1.0}, {16, 0.8}};
    for (const auto& [n, c] : cases) {
        ShearTestOptions o;
        o.nodes = n;
        o.C = c;
        o.overlap = 1e-4;
        o.dx = 2e-4;
        o.x_start = -0.01;
        o.x_end = 0.02;
        const ShearTestResult r = simple_shear_test(o);
        const double theory = rough_friction_maximum(c, n);
        CAPTURE(n);
        CAPTURE(c);
        // Eq. (9.13) is the rigid limit at zero overlap. At overlap delta the groove contact breaks after a
        // shift Delta ~ sigma^2 delta/(l/2), l/2 = C sigma sin(pi/N), which lowers sin(alpha) by Delta/(l/2)
        // <= 0.4 % here (worst: N = 16, C = 0.8); the first sample after the break is up to dx = 2e-4 D
        // later, on a branch of slope |d mu/d(x/D)| < 4: <= 0.3 %. 1 % covers both with a margin of 1.4.
        CHECK_CLOSE(r.mu_eff_max, theory, (Tolerance{1e-2, 0}));
        CHECK(r.mu_eff_max <= theory * (1 + 1e-3)); // the rigid zero-overlap limit is an upper bound
    }
}

TEST_CASE("rough shells: the deviation from eq. (9.13) shrinks with the overlap [DPM eq. (9.13)]")
{
    ShearTestOptions o;
    o.nodes = 10;
    o.C = 1.0;
    o.dx = 2e-4;
    o.x_start = -0.01;
    o.x_end = 0.03;
    const double theory = rough_friction_maximum(o.C, o.nodes);
    o.overlap = 1e-2;
    const double coarse = theory - simple_shear_test(o).mu_eff_max;
    o.overlap = 1e-3;
    const double fine = theory - simple_shear_test(o).mu_eff_max;
    CAPTURE(coarse);
    CAPTURE(fine);
    // Deviation ~ delta at small delta (plus the fixed sampling part): ten times less overlap must cut it
    // by well over half.
    CHECK(fine > 0);
    CHECK(fine < 0.5 * coarse);
}

TEST_CASE("smooth elastic shells: max mu_eff = 0.190, far below rough shells [DPM Fig. 9.8(d), Appendix A]")
{
    ShearTestOptions o; // stiff shells, N = 8, C = 1.3 (Fig. 9.8c)
    o.interaction = InteractionKind::smooth;
    o.overlap = 1e-3;
    o.dx = 0.004;
    const ShearTestResult r = simple_shear_test(o);
    // The paper's vertical separation is unstated; our maximum grows with the overlap (0.193 at 1e-3,
    // 0.196 at 1e-2, 0.209 at 5e-2). In the small-overlap limit we require the paper's 0.190 within 3 %.
    CHECK_CLOSE(r.mu_eff_max, 0.190, (Tolerance{3e-2, 0}));
    // The maximum sits at x/D ~ 0.1 (paper), not at the groove.
    CHECK_CLOSE(r.x_at_max, 0.1, (Tolerance{0, 0.04}));
    CHECK(r.mu_eff_max < 0.5 * rough_friction_maximum(o.C, o.nodes));
}

TEST_CASE(
    "smooth shells frozen at the maximum, mu translated: mu_eff^max = 0.190 [DPM Appendix A, Fig. 9.19(e)]")
{
    ShearTestOptions o; // as above
    o.interaction = InteractionKind::smooth;
    o.overlap = 1e-3;
    o.dx = 0.004;
    const ShearTestResult r = simple_shear_test(o);
    const FrozenContactScan scan = frozen_contact_scan(r.system, r.x_star, 21, 21);
    // The starred configuration evaluated again: the same forces to round-off.
    CHECK_CLOSE(scan.mu_eff_star, r.mu_eff_max, (Tolerance{1e-12, 0}));
    // The shear test samples x every 0.004 D_beta on a smooth curve, so the frozen maximum along the line
    // through the star is the paper's 0.190 within the same 3 %. (That it is not below the star's value holds
    // by construction, frozen_contact_scan starts its maximum there, so it is not checked.)
    CHECK_CLOSE(scan.mu_eff_max_at_star_height, 0.190, (Tolerance{3e-2, 0}));
    // The paper: F_mb != 0 over the whole range, and mu_eff finite (not zero) in the zero-overlap limit.
    CHECK(scan.min_force > 0);
    CHECK(scan.mu_eff_zero_overlap > 0.01);
    CHECK(scan.mu_eff_zero_overlap < rough_friction_maximum(o.C, o.nodes));
}
