// DPM Fig. 9.18: the reductions dpm.boundary_jam reports over its jammed packings
// (dpm/protocols/boundary_jam.hpp), on hand-made lists of parallelogram angles theta [deg] (NaN: a packing
// without a 4-cycle of contacts) whose answers are known: the distinct packings (decision dpm-boundary-jam:
// same contact number and theta within 1 degree of a neighbour, single linkage), the largest gap of theta
// over its range (Fig. 9.18f) and the range of theta over the packings with a 4-cycle. Counts and extremes
// are exact; the gap is one division of exact differences of small integers and halves, exact too.
#include "dpm/protocols/boundary_jam.hpp"
#include "support/tolerance.hpp"

#include <cmath>
#include <limits>

using namespace softgrain::dpm;

namespace {
const double none = std::numeric_limits<double>::quiet_NaN();
}

TEST_CASE("distinct packings: same contacts, theta within 1 degree by single linkage; one per contact number "
          "without a 4-cycle [DPM Fig. 9.18(a-e), decision dpm-boundary-jam]")
{
    // 5 contacts: 60, 60.5 and 61.4 chain (steps below 1 degree) into one packing, 75 is another; 4
    // contacts: two packings without a 4-cycle are one; 6 contacts: 90 and one without a 4-cycle.
    const std::map<int, std::vector<double>> thetas{
        {5, {61.4, 60.0, 75.0, 60.5}}, {4, {none, none}}, {6, {90.0, none}}};
    CHECK(count_distinct_packings(thetas) == 2 + 1 + 2);
    // The same angles under different contact numbers are different packings.
    CHECK(count_distinct_packings({{4, {70.0}}, {5, {70.0}}}) == 2);
    // A step of more than 1 degree separates.
    CHECK(count_distinct_packings({{5, {70.0, 71.5}}}) == 2);
}

TEST_CASE("largest theta gap over the range: 1/4 for five evenly spread values, NaN ignored, NaN below two "
          "values [DPM Fig. 9.18(f)]")
{
    CHECK(largest_gap_over_range({60.0, 67.5, none, 75.0, 82.5, 90.0}) == 0.25);
    CHECK(largest_gap_over_range({90.0, 65.0, 60.0, 70.0}) == 20.0 / 30.0); // gaps 5, 5, 20 over 30
    CHECK(std::isnan(largest_gap_over_range({70.0, none})));
}

TEST_CASE("theta range over the packings with a 4-cycle: their count, smallest and largest theta; nothing "
          "without one [DPM Fig. 9.18]")
{
    const ThetaRange range = theta_range({none, 72.0, 64.0, none, 88.0});
    CHECK(range.packings == 3);
    CHECK(range.min.value() == 64.0);
    CHECK(range.max.value() == 88.0);
    const ThetaRange without = theta_range({none, none});
    CHECK(without.packings == 0);
    CHECK_FALSE(without.min);
    CHECK_FALSE(without.max);
    CHECK(theta_range({}).packings == 0);
}
