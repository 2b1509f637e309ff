// DPM section 9.4, Fig. 9.13(a): jamming of bidisperse smooth disks (diameter ratio 1.4, purely repulsive
// linear springs) by compression + FIRE with bisection on the pressure. phi_c close to 0.84 and P linear in
// phi - phi_c (zeta = 1, O'Hern et al. 2003).
// ctest-label: slow
#include "core/fits.hpp"
#include "dpm/protocols/jam.hpp"
#include "support/tolerance.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::round_off;
using softgrain::verification::Tolerance;

// zeta = 1 for linear springs holds on a branch of fixed contact network. A single packing that rearranges
// on its branch (phi jumps at fixed P) fits a lower exponent: among seeds 1-20 of this setting, 2 packings
// did (0.86 and 0.82 with FIRE's step 0.3; 0.77 and 0.88 with 1), the other 18 lay within 0.025 of 1. So the
// test takes the median over 20 packings, the typical branch, as the paper's ensemble mean <P> is over
// many. The onset pressure P_t = 1e-6 not being zero (phi_c is the phi at P_t) bends the branch:
// P = B (phi - phi_c + P_t/B) gives at the targets 10, 100, 1000 P_t the excess packing fractions 9, 99, 999
// P_t/B, whose fitted exponent is 0.976; tolerance 0.05, twice that bias.
TEST_CASE(
    "smooth bidisperse disks: phi_c ~ 0.84 and P = B (phi - phi_c)^zeta with zeta = 1 [DPM Fig. 9.13(a)]")
{
    std::vector<double> phi_c, zeta;
    for (int seed = 1; seed <= 20; ++seed) {
        JamOptions o;
        o.particles = 64;
        o.pressure_onset = 1e-6;
        o.pressure_max = 1e-3;
        o.pressures = 3;
        o.seed = static_cast<std::uint64_t>(seed);
        const JamResult r = jam(o);
        CAPTURE(seed);
        // The onset state satisfies the protocol's window 1 <= P/P_t < 1.01.
        CHECK(r.states.front().pressure >= o.pressure_onset);
        CHECK(r.states.front().pressure < 1.01 * o.pressure_onset);
        phi_c.push_back(r.states.front().phi);
        zeta.push_back(fit_compression_branch(r.states).pressure_exponent.value());
    }
    std::vector<double> sorted = zeta;
    std::sort(sorted.begin(), sorted.end());
    const double median = 0.5 * (sorted[9] + sorted[10]);
    MESSAGE("exponents from " << sorted.front() << " to " << sorted.back() << ", median " << median);
    CHECK_CLOSE(median, 1.0, (Tolerance{0, 0.05}));
    // N = 64: the onset of single packings scatters by ~0.01 (finite size); the mean of 20 within 0.015 of
    // the large-N value 0.84 (paper: 0.836 for N = 128 over 500 packings).
    CHECK_CLOSE(std::accumulate(phi_c.begin(), phi_c.end(), 0.0) / 20, 0.84, (Tolerance{0, 0.015}));
}

TEST_CASE(
    "decompression: both branches meet the protocol's window, and a packing compressed within its elastic "
    "branch returns to the same phi_c [DPM section 9.4, Fig. 9.13(b)-(d)]")
{
    for (int seed = 1; seed <= 3; ++seed) {
        CAPTURE(seed);
        JamOptions o;
        o.particles = 32;
        o.pressure_onset = 1e-6;
        o.pressure_max = 2e-6; // a factor 2 in P: no rearrangement expected on so short a branch
        o.pressures = 1;
        o.decompress = true;
        o.seed = static_cast<std::uint64_t>(seed);
        const JamResult r = jam(o);
        REQUIRE(r.states.size() == 3); // onset, P_max, back at onset
        CHECK_FALSE(r.states[1].decompression);
        CHECK(r.states[2].decompression);
        for (const JamState& s : r.states) {
            const double target = s.pressure < 1.5e-6 ? 1e-6 : 2e-6;
            CHECK(s.pressure >= target);
            CHECK(s.pressure < 1.01 * target);
        }
        // Without a rearrangement P(phi) is single valued: the two onset states differ only by the window,
        // |d phi| <= 0.01 P_t / B with B ~ 0.1 k_c for these packings, i.e. 1e-7 (measured ~1e-13).
        CHECK(std::abs(r.states[2].phi - r.states[0].phi) < 1e-7);
    }
}

TEST_CASE("fit_compression_branch: B and the exponent of an exact power law over the compression branch "
          "only, the onset and the decompression states left out [DPM Fig. 9.13(a)]")
{
    // P = 0.3 (phi - phi_c)^1.5 at three states above phi_c = 0.8; the onset (P_t) and a decompression
    // state off the law must not enter either fit.
    const auto state = [](double phi, double pressure, bool decompression) {
        JamState jammed;
        jammed.phi = phi;
        jammed.pressure = pressure;
        jammed.box = Eigen::Vector2d::Zero(); // unused here: set so that copies read no uninitialised memory
        jammed.decompression = decompression;
        return jammed;
    };
    const double phi_c = 0.8;
    const std::vector<double> dphi{1e-3, 2e-3, 4e-3};
    std::vector<JamState> states{state(phi_c, 1e-7, false)};
    double xy = 0, xx = 0; // the slope through the origin, sum(x y)/sum(x^2), computed here independently
    for (const double x : dphi) {
        const double pressure = 0.3 * std::pow(x, 1.5);
        states.push_back(state(phi_c + x, pressure, false));
        xy += x * pressure;
        xx += x * x;
    }
    states.push_back(state(phi_c + 1e-3, 1.0, true));
    const CompressionBranchFit fit = fit_compression_branch(states);
    // Exact data, but phi is stored as phi_c + x: x comes back as (phi_c + x) - phi_c, off by up to
    // round-off x phi_c ~ 1e-16 absolute, 1e-13 relative at x = 1e-3, which moves B and the log-log slope
    // (spacing ln 2) by about as much; 1e-11 is 100 times that.
    REQUIRE(fit.pressure_exponent.has_value());
    CHECK_CLOSE(*fit.pressure_exponent, 1.5, (Tolerance{1e-11, 0}));
    REQUIRE(fit.bulk_modulus.has_value());
    CHECK_CLOSE(*fit.bulk_modulus, xy / xx, (Tolerance{1e-11, 0}));
    // One compressed state: no fit of either (two states at least).
    const CompressionBranchFit single = fit_compression_branch({states[0], states[1], states[4]});
    CHECK_FALSE(single.bulk_modulus.has_value());
    CHECK_FALSE(single.pressure_exponent.has_value());
}

// fire_step sets FIRE's largest step in 2D as in 3D (jamming3d.cpp): dt_max = fire_step / sqrt(lambda_max
// at the start) below the cap 0.5, so 0.9 gives three times the default 0.3 (a quotient of the same square
// root: 2 eps), and the packing still ends in the window 1 <= P/P_t < 1.01 with its rms force below FIRE's
// tolerance.
TEST_CASE("2D jamming with fire_step = 0.9: three times FIRE's default step, and a jammed packing")
{
    JamOptions o;
    o.model = JamModel::shell;
    o.particles = 8;
    o.nodes_small = 6;
    o.nodes_large = 10;
    o.pressure_onset = o.pressure_max = 1e-5;
    o.pressures = 0;
    o.seed = 2;
    const JamResult reference = jam(o);
    o.fire_step = 0.9;
    const JamResult r = jam(o);
    REQUIRE(r.fire.dt_max < 0.5);
    CHECK_CLOSE(r.fire.dt_max, 3 * reference.fire.dt_max, (Tolerance{2 * round_off, 0}));
    MESSAGE("FIRE iterations " << r.fire_iterations << " against " << reference.fire_iterations
                               << " with the default step");
    CHECK(r.states.front().pressure >= o.pressure_onset);
    CHECK(r.states.front().pressure < 1.01 * o.pressure_onset);
    Eigen::VectorXd g = Eigen::VectorXd::Zero(r.x.size());
    total_energy(r.system, r.x, &g, nullptr);
    CHECK(g.norm() / std::sqrt(double(g.size())) < r.fire.force_tolerance);
}
