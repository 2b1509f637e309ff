// The 2D total energy does not depend on the number of OpenMP threads: energy and gradient of total_energy
// are bit-identical for 1 and 2 threads and to the serial loop over particles (shape energies, then
// contacts, then anchors), on 24 randomly deformed 16-gons of each model of Table 9.1 (384 vertices) with
// rough contacts across a Lees-Edwards boundary and an anchor. The 2D shape energies are summed serially:
// summed over particles in parallel (dpm/system/particle_sum.hpp, as in 3D), two threads were slower than
// one at every size measured (reproductions/dpm/README.md); this test guards the sum when that changes.
#include "core/rng.hpp"
#include "dpm/system/system.hpp"
#include "support/thread_bits.hpp"

#include <numbers>

using namespace softgrain;
using namespace softgrain::dpm;
using namespace softgrain::verification;

namespace {

// Twenty-four 16-gons of the model (Table 9.1 with A0 = 1.05, a0 = 1.77), vertices jittered by up to 0.03,
// at random centres in a periodic 8 x 7 box under a Lees-Edwards strain of 0.23, vertex diameters 0.25-0.35:
// dense enough for many contacts, also across the boundary.
DpmSystem random_sheared_polygons(ShapeModel model, Rng& rng, Eigen::VectorXd& x)
{
    DpmSystem s;
    s.interaction = InteractionKind::rough;
    s.box = Eigen::Vector2d(8.0, 7.0);
    s.lees_edwards_strain = 0.23;
    const int n = 16;
    const double radius = 0.75;
    const ShapeParameters shape =
        table_9_1_parameters(model, n, std::numbers::pi * radius * radius, 1.05, ShapeStiffness{});
    for (int m = 0; m < 24; ++m) {
        const Eigen::Vector2d c(rng.uniform(0, 8), rng.uniform(0, 7));
        Eigen::Matrix2Xd v = regular_polygon(n, radius, c, rng.uniform(0, 2 * std::numbers::pi));
        for (Eigen::Index k = 0; k < v.size(); ++k)
            v(k) += 0.03 * rng.uniform(-1, 1);
        s.add_particle(v, rng.uniform(0.25, 0.35), shape, x);
    }
    s.anchors.push_back(Anchor{5, x.segment<2>(10) + Eigen::Vector2d(0.1, -0.05), 2.0});
    return s;
}

} // namespace

TEST_CASE("2D total energy: the same bits on 1 and 2 threads [DPM eqs. (9.1), (9.3)-(9.4)]")
{
    Rng rng(43);
    for (ShapeModel model : {ShapeModel::shell, ShapeModel::floppy, ShapeModel::surface_tension}) {
        Eigen::VectorXd x;
        const DpmSystem s = random_sheared_polygons(model, rng, x);
        REQUIRE(total_energy(s, x, nullptr, nullptr, interaction_part) > 0);
        const auto threaded = on_one_and_two_threads(
            x.size(), [&](Eigen::VectorXd& gradient) { return total_energy(s, x, &gradient, nullptr); });
        // The serial loop over the particles, then the interaction and the anchor.
        EnergyAndGradient serial{0, Eigen::VectorXd::Zero(x.size())};
        for (const Particle& p : s.particles)
            serial.energy += shape_energy(p.shape, x, p.first, p.count, &serial.gradient, nullptr);
        serial.energy += total_energy(s, x, &serial.gradient, nullptr, interaction_part);
        serial.energy += total_energy(s, x, &serial.gradient, nullptr, anchor_part);
        CAPTURE(shape_model_name(model));
        check_same_bits(threaded, serial);
    }
}
