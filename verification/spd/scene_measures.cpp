// The reductions that spd.ring_compression and spd.tissue apply to their records (lib/spd/
// compression_measures.hpp, lib/spd/tissue_measures.hpp), on records whose answer is known by hand.
#include "core/fits.hpp"
#include "spd/compression_measures.hpp"
#include "spd/tissue_measures.hpp"
#include "support/tolerance.hpp"

#include <cmath>
#include <vector>

using namespace softgrain::spd;
using softgrain::verification::round_off;
using softgrain::verification::Tolerance;

TEST_CASE("slope_error_bound is the slope change of ordinates moved by delta with the sign of x - mean")
{
    // Least squares is linear in y: moving y_k by e_k changes the slope by sum (x_k - mean) e_k / sum
    // (x_k - mean)^2, largest for e_k = delta sign(x_k - mean). Uneven abscissae, so that the bound is not
    // a symmetric special case.
    const std::vector<double> x = {0.3, 0.35, 0.42, 0.5, 0.61};
    const std::vector<double> y = {1.0, 1.2, 1.1, 1.6, 1.9};
    const double delta = 0.01;
    double mean = 0;
    for (double xi : x)
        mean += xi / x.size();
    std::vector<double> worst = y, other = y;
    for (std::size_t k = 0; k < x.size(); ++k) {
        worst[k] += x[k] > mean ? delta : -delta;
        other[k] += k % 2 == 0 ? delta : -delta; // another pattern of the same size: a smaller change
    }
    const double slope = *softgrain::fit_line_slope(x, y);
    const double bound = slope_error_bound(x, delta);
    CHECK_CLOSE(*softgrain::fit_line_slope(x, worst) - slope, bound, (Tolerance{1e3 * round_off, 0}));
    CHECK(std::abs(*softgrain::fit_line_slope(x, other) - slope) < bound);
    CHECK(std::isnan(slope_error_bound({0.3}, delta))); // one abscissa: no slope
}

TEST_CASE("profile_shape: centre, edge and edge-zone shares of the wall force [SPD Figs. 16, 18, 24]")
{
    CompressionState state{};
    // Five contact vertices l0 = 1 apart, listed out of order: pressures 3 1 2 1 3 from left to right.
    state.profile_x = {0.0, -2.0, 2.0, -1.0, 1.0};
    state.profile_pressure = {2.0, 3.0, 3.0, 1.0, 1.0};
    const ProfileShape shape = profile_shape(state, 1.0);
    CHECK(shape.centre_pressure == 2.0);
    CHECK_CLOSE(shape.centre_share, 2.0 / 10, (Tolerance{4 * round_off, 0}));
    CHECK_CLOSE(shape.edge_share, 6.0 / 10, (Tolerance{4 * round_off, 0}));
    CHECK_CLOSE(shape.edge_zone_share, 8.0 / 10, (Tolerance{4 * round_off, 0}));
    // An even contact has no vertex within l0/2 of its middle: no centre pressure.
    state.profile_x = {-1.5, -0.5, 0.5, 1.5};
    state.profile_pressure = {1.0, 1.0, 1.0, 1.0};
    CHECK(profile_shape(state, 1.0).centre_pressure == 0.0);
    // No contact: shares undefined.
    CHECK(std::isnan(profile_shape(CompressionState{}, 1.0).edge_share));
}

TEST_CASE("loading_state_nearest skips the unloading states")
{
    // Strains exact in binary: 0.25 and 0.5 are equally near 0.375, where an unloading state lies.
    std::vector<CompressionState> states(4);
    const double strains[] = {0.0, 0.25, 0.5, 0.375};
    for (std::size_t k = 0; k < states.size(); ++k)
        states[k].strain = strains[k], states[k].loading = k < 3;
    CHECK(&loading_state_nearest(states, 0.375) == &states[1]); // the first of the two
    CHECK(&loading_state_nearest(states, 0.45) == &states[2]);
}

TEST_CASE("stress_drops counts falls and rises beyond the threshold [decision spd-tissue-measures]")
{
    // Rise to 1, fall to 0.8, rise past 0.85 (drop 0.2), peak 1.2, fall to 0.3, rise past 0.35 (drop 0.9),
    // then a fall to 0.1 still open at the end (drop 0.4 - 0.1 = 0.3); wiggles of 0.04 do not count.
    const std::vector<double> sigma = {0, 0.5, 1.0, 0.96, 1.0, 0.8, 0.9, 1.2, 0.3, 0.4, 0.1};
    const std::vector<double> drops = stress_drops(sigma, 0.05);
    REQUIRE(drops.size() == 3);
    CHECK_CLOSE(drops[0], 0.2, (Tolerance{0, 4 * round_off}));
    CHECK_CLOSE(drops[1], 0.9, (Tolerance{0, 4 * round_off}));
    CHECK_CLOSE(drops[2], 0.3, (Tolerance{0, 4 * round_off}));
}

TEST_CASE("curve_measures: peak, failure strain and drop growth of a stress curve [SPD Fig. 33]")
{
    // sigma = F_top/(W s) with W s = 2: 0, 0.5, 1 (peak), 0.7, 0.8, 0.05 (below 0.1 sigma_max), 0.
    const double forces[] = {0, 1, 2, 1.4, 1.6, 0.1, 0};
    std::vector<TissueRecord> records;
    for (int k = 0; k < 7; ++k)
        records.push_back({0.01 * k, forces[k], 0.0, 0, 0.0});
    const CurveMeasures curve = curve_measures(records, 2.0);
    CHECK(curve.sigma_max == 1.0);
    CHECK(curve.peak == 2);
    CHECK(curve.strain_at_failure == records[5].strain);
    // Drops over sigma_max: 1 -> 0.7 (0.3, closed by the rise to 0.8), then 0.8 -> 0 (0.8, open): growth
    // 0.8/0.3.
    REQUIRE(curve.drops.size() == 2);
    CHECK_CLOSE(curve.growth, 0.8 / 0.3, (Tolerance{16 * round_off, 0}));
}
