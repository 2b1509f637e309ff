// Invariants of the assembled shell forces (SPD eqs. (1), (3), (4), (8)-(9)): in the elastic regime the
// internal forces are minus the gradient of W = sum F^2/(2 k_s) + sum M^2/(2 k_b) + V0 p^2/(2 K_Omega), they
// sum to zero and exert no net moment.
#include "spd/ring.hpp"
#include "spd/shell_model.hpp"
#include "support/tolerance.hpp"

#include <cmath>

using namespace softgrain;
using namespace softgrain::spd;
using softgrain::verification::Tolerance;

namespace {
double total_energy(const ShellModel& model, const RingScales& sc, double V0)
{
    const double p = model.core_pressure(0);
    return model.stretch_energy() + model.bending_energy() + V0 * p * p / (2 * sc.K_Omega);
}
} // namespace

TEST_CASE("shell forces are minus the gradient of the stretch, bending and core energies [SPD eqs. (1)-(4), "
          "(8)-(9)]")
{
    RingSetup setup;
    setup.nodes = 12;
    setup.eta = 3.0;
    setup.material.h = 0.2; // comparable stretch and bending contributions
    const RingScales sc = ring_scales(setup);
    ShellModel model;
    add_ring(model, setup, 0.0);
    const double V0 = setup.material.s * model.area(0);
    // A smooth, large (but elastic) distortion of the ring.
    for (int k = 0; k < setup.nodes; ++k) {
        const Vec2 x = model.vertex(k);
        model.set_vertex(
            k, Vec2(x.x() * (1 + 0.05 * std::sin(3.0 * k)), x.y() * (1 - 0.04 * std::cos(2.0 * k))));
    }
    model.compute_forces(0.0);
    Eigen::VectorXd force(2 * setup.nodes);
    Vec2 net = Vec2::Zero();
    double moment = 0;
    for (int k = 0; k < setup.nodes; ++k) {
        force.segment<2>(2 * k) = model.force(k);
        net += model.force(k);
        moment += cross2(model.vertex(k), model.force(k));
    }
    const double scale = force.cwiseAbs().maxCoeff();
    // Newton's third law and zero net moment of internal forces: round-off of sums of O(scale) terms.
    CHECK_CLOSE(net.norm() / scale, 0.0, (Tolerance{0, 1e3 * softgrain::verification::round_off}));
    CHECK_CLOSE(moment / scale, 0.0, (Tolerance{0, 1e3 * softgrain::verification::round_off}));
    // Central differences of W (the incremental laws telescope exactly in the elastic regime): O(h^2) = 1e-12
    // relative truncation, plus round-off of W / h ~ 1e-16 / 1e-6: 1e-7 of the largest force.
    const double h = 1e-6;
    for (int k = 0; k < setup.nodes; ++k) {
        for (int c = 0; c < 2; ++c) {
            const Vec2 x = model.vertex(k);
            Vec2 e = Vec2::Zero();
            e[c] = h;
            model.set_vertex(k, x + e);
            model.compute_forces(0.0);
            const double plus = total_energy(model, sc, V0);
            model.set_vertex(k, x - e);
            model.compute_forces(0.0);
            const double minus = total_energy(model, sc, V0);
            model.set_vertex(k, x);
            CAPTURE(k);
            CAPTURE(c);
            CHECK_CLOSE(force[2 * k + c], -(plus - minus) / (2 * h), (Tolerance{0, 1e-7 * scale}));
        }
    }
}
