// ctest-label: slow
// SPD section 5: the compaction protocol of spd.compaction — the deposited packing is at rest (force
// balance with the weight), the loading is quasi-static (top and bottom wall forces balance), and the solid
// volume V_s (shells dilated by r, Steiner's formula) plus the void volume fills the box.
#include "spd/compaction.hpp"
#include "core/geometry.hpp"
#include "support/tolerance.hpp"

#include <algorithm>
#include <cmath>

using namespace softgrain;
using namespace softgrain::spd;
using softgrain::verification::Tolerance;

namespace {

CompactionSetup small_setup()
{
    CompactionSetup setup = compaction_scene_defaults();
    setup.assembly.particles = 12;
    setup.strain_max = 0.3;
    setup.records = 30;
    setup.wall_speed = 3e-4;
    return setup;
}

// Area of the union of the particles (each shell polygon dilated by its vertex radius r), counted on a grid
// of spacing `cell` (cell centres inside a polygon or within r of its boundary), and the count's standard
// error: each of the ~ P/cell boundary cells is mis-counted by at most cell^2/2 with a random sign.
struct UnionArea
{
    double area, standard_error;
};
UnionArea union_area(const Assembly& a, double cell)
{
    const ShellModel& m = a.model;
    double x_min = INFINITY, x_max = -INFINITY, y_min = INFINITY, y_max = -INFINITY, perimeter = 0;
    std::vector<Points<2>> polygons;
    double r = 0;
    for (int p : a.particles) {
        const Shell& s = m.shells()[p];
        r = s.radius;
        Points<2> poly(2, s.count);
        for (int k = 0; k < s.count; ++k)
            poly.col(k) = m.vertex(s.first + k);
        x_min = std::min(x_min, poly.row(0).minCoeff() - r),
        x_max = std::max(x_max, poly.row(0).maxCoeff() + r);
        y_min = std::min(y_min, poly.row(1).minCoeff() - r),
        y_max = std::max(y_max, poly.row(1).maxCoeff() + r);
        perimeter += polygon_perimeter(poly) + 2 * M_PI * r;
        polygons.push_back(std::move(poly));
    }
    const auto covered = [&](const Vec2& c, const Points<2>& poly) {
        bool inside = false;
        const Eigen::Index n = poly.cols();
        for (Eigen::Index k = 0, j = n - 1; k < n; j = k++) {
            const Vec2 A = poly.col(j), B = poly.col(k);
            if ((B.y() > c.y()) != (A.y() > c.y()) &&
                c.x() < (A.x() - B.x()) * (c.y() - B.y()) / (A.y() - B.y()) + B.x())
                inside = !inside;
            if (point_segment_proximity(c, A, B).distance <= r) return true;
        }
        return inside;
    };
    long count = 0;
    for (double y = y_min + 0.5 * cell; y < y_max; y += cell)
        for (double x = x_min + 0.5 * cell; x < x_max; x += cell) {
            const Vec2 c(x, y);
            for (const Points<2>& poly : polygons) {
                if (x < poly.row(0).minCoeff() - r || x > poly.row(0).maxCoeff() + r ||
                    y < poly.row(1).minCoeff() - r || y > poly.row(1).maxCoeff() + r)
                    continue;
                if (covered(c, poly)) {
                    ++count;
                    break;
                }
            }
        }
    return {count * cell * cell, 0.5 * cell * cell * std::sqrt(perimeter / cell)};
}

} // namespace

TEST_CASE("deposition at rest: bottom-wall force = total weight within the rest criterion [SPD section 5]")
{
    const CompactionSetup setup = small_setup();
    const Deposit d = deposit(setup);
    const int vertices = particle_vertices(d.assembly);
    const double tolerance = setup.rest_tolerance * d.weight;
    REQUIRE(d.residual_force < tolerance);
    // Static balance of all free vertices: sum of (weight + wall reactions + residual) = 0; the side walls
    // are frictionless and vertical, the top wall is out of reach, so |F_bottom - n W_p| <= (vertices) x
    // (largest residual) <= vertices x rest_tolerance x W_p.
    CHECK(std::abs(d.assembly.model.contact_force_on(d.assembly.top).y()) == 0.0);
    CHECK_CLOSE(d.bottom_force, setup.assembly.particles * d.weight, (Tolerance{0, vertices * tolerance}));
}

TEST_CASE("the four parameter sets share one deposited disk packing (deterministic from the seed)")
{
    CompactionSetup elastic = small_setup(), incompressible = small_setup(), plastic = small_setup();
    incompressible.assembly.ring.eta = INFINITY;
    plastic.assembly.ring.plastic_ratio = 5e-5;
    const DiskPacking a = deposit(elastic).disks, b = deposit(incompressible).disks,
                      c = deposit(plastic).disks;
    REQUIRE(a.centres.size() == b.centres.size());
    for (std::size_t i = 0; i < a.centres.size(); ++i) {
        CHECK((a.centres[i] - b.centres[i]).norm() == 0.0);
        CHECK((a.centres[i] - c.centres[i]).norm() == 0.0);
    }
}

TEST_CASE("quasi-static loading: top and bottom wall forces agree; V_s + void area = box area")
{
    const CompactionSetup setup = small_setup();
    double worst = 0, union_checked = 0;
    const RingScales sc = ring_scales(setup.assembly.ring);
    const double omega2 = ring_damping(setup.assembly.ring) / (2 * setup.assembly.ring.vertex_mass);
    const double R = setup.assembly.ring.radius;
    const double mass =
        setup.assembly.particles * setup.assembly.ring.nodes * setup.assembly.ring.vertex_mass;
    // Momentum balance of the particles (no bulk damping): F_top - F_bottom = -dP/dt. At wall speed V the
    // inertial force is of order M V / tau over the ovalisation time tau = 1/omega_2: M V omega_2.
    const double inertial_force = mass * setup.wall_speed * R * omega2 * omega2;
    const CompactionResult r = compaction(
        setup,
        [&](const Assembly& a, const CompactionState& st) {
            if (st.loading && st.strain >= setup.strain_max - 1e-12) {
                // Grid count of the union of the dilated shells at the most compacted state.
                const UnionArea u = union_area(a, 0.005 * R);
                CAPTURE(u.standard_error);
                CHECK_CLOSE(st.solid_area, u.area, (Tolerance{0, 5 * u.standard_error}));
                union_checked = u.area;
                // The void is what remains of the box: e = (W H - V_s)/V_s > 0.
                CHECK(a.width * st.height > st.solid_area);
            }
        },
        [](double) {});
    double force_max = 0;
    for (const CompactionState& st : r.states)
        force_max = std::max(force_max, st.force_top);
    // The load-bearing (jammed) part of the loading: a loose sample of 12 rings transmits the first contacts
    // of the top wall as impacts. Within it, rearrangement avalanches unbalance the walls for short times by
    // amounts that do not vanish with V (measured max 36% at V = 1e-3 R omega_2, 25% at 3e-4): the test
    // asserts that the sample is in balance between them, i.e. the median mismatch is within 5% plus the
    // inertial scale, and that avalanches are rare (at most a quarter of the states beyond 10%).
    std::vector<double> mismatch;
    for (const CompactionState& st : r.states)
        if (st.loading && st.force_top >= 0.1 * force_max)
            mismatch.push_back(std::abs(st.force_top - st.force_bottom) / st.force_top);
    REQUIRE(mismatch.size() >= 10);
    std::sort(mismatch.begin(), mismatch.end());
    worst = mismatch.back();
    const double median = mismatch[mismatch.size() / 2];
    CHECK(median <= 0.05 + inertial_force / (0.1 * force_max));
    const auto beyond = std::count_if(mismatch.begin(), mismatch.end(), [](double m) { return m > 0.1; });
    CHECK(beyond <= static_cast<long>(mismatch.size()) / 4);
    MESSAGE("median wall-force mismatch " << median << " over " << mismatch.size() << " states");
    MESSAGE("largest relative wall-force mismatch where F_top >= 0.1 max F_top: "
            << worst << ", inertial force scale " << inertial_force / sc.characteristic.F_star << " F*");
    CHECK(union_checked > 0);
    CHECK(r.states.back().height == doctest::Approx(r.height0).epsilon(1e-12));
}
