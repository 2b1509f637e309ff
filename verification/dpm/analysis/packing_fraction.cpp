// DPM section 9.4.1, eqs. (9.18)-(9.22): packing fraction of rough deformable particles in a periodic box.
// The circular segment (9.20) against the closed-form lens; the A_sector identity; the analytic area and
// each of its four terms against Monte-Carlo integration within three standard errors (Table 9.2).
#include "dpm/analysis/packing_fraction.hpp"
#include "dpm/protocols/packing.hpp"
#include "support/tolerance.hpp"

#include <numbers>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::round_off;
using softgrain::verification::Tolerance;

TEST_CASE(
    "eq. (9.20): the two circular segments of an overlapping pair add up to the lens area [DPM eq. (9.20)]")
{
    // Lens of two disks of radii a, b at distance r (standard formula, e.g. Weisstein, Circle-Circle
    // Intersection): a^2 acos((r^2 + a^2 - b^2)/(2ra)) + b^2 acos((r^2 + b^2 - a^2)/(2rb))
    //                - sqrt((-r+a+b)(r+a-b)(r-a+b)(r+a+b))/2.
    for (const auto& [r, sa, sb] : {std::tuple{0.9, 1.0, 1.0}, std::tuple{0.5, 1.0, 1.0},
                                    std::tuple{0.8, 1.0, 1.4}, std::tuple{1.1, 1.4, 1.0}}) {
        const double a = sa / 2, b = sb / 2;
        const double lens = a * a * std::acos((r * r + a * a - b * b) / (2 * r * a)) +
                            b * b * std::acos((r * r + b * b - a * a) / (2 * r * b)) -
                            0.5 * std::sqrt((-r + a + b) * (r + a - b) * (r - a + b) * (r + a + b));
        CAPTURE(r);
        // Two closed forms of the same area: agreement to round-off of acos near its argument.
        CHECK_CLOSE(vertex_overlap_segment(r, sa, sb) + vertex_overlap_segment(r, sb, sa), lens,
                    (Tolerance{1e-12, 0}));
    }
    CHECK(vertex_overlap_segment(1.2, 1.0, 1.4) == 0.0); // r = sigma_mb: touching, no overlap
}

TEST_CASE("analytic packing fraction and every area term against Monte-Carlo within 3 standard errors [DPM "
          "Table 9.2]")
{
    for (std::uint64_t seed : {12u, 3u}) {
        PackingOptions o; // Fig. 9.12: 7 rough elastic shells with 5 vertices
        o.seed = seed;
        const Packing p = jam_packing(o);
        const PackingAreas a = packing_areas_analytic(p.system, p.x);
        const PackingAreasEstimate mc = packing_areas_monte_carlo(p.system, p.x, 1000000, seed + 100);
        CAPTURE(seed);
        // Three standard errors of the Monte-Carlo estimate (1e6 points): a 0.3 % chance per term of a false
        // alarm if eqs. (9.18)-(9.20) are exact for the packing (no triple vertex overlaps).
        const auto within_3se = [](double analytic, double estimate, double error) {
            CHECK_CLOSE(analytic, estimate, (Tolerance{0, 3 * error}));
        };
        within_3se(a.phi, mc.value.phi, mc.error.phi);
        within_3se(a.polygon, mc.value.polygon, mc.error.polygon);
        within_3se(a.vertices, mc.value.vertices, mc.error.vertices);
        within_3se(a.sector, mc.value.sector, mc.error.sector);
        within_3se(a.pair, mc.value.pair, mc.error.pair);
        // A_sector = A_vertices (N - 2)/(2N) for simple polygons (sum of interior angles (N - 2) pi).
        CHECK_CLOSE(a.sector, a.vertices * 3.0 / 10.0, (Tolerance{1e3 * round_off, 0}));
        // The packing is at jamming onset: a few particles in contact, overlaps tiny.
        CHECK(a.phi > 0.6);
        CHECK(a.phi < 0.95);
    }
}
