// The 3D shape energies summed in parallel over particles (dpm/system/particle_sum.hpp): energy and gradient
// of total_energy3d are bit-identical for 1 and 2 OpenMP threads and to the serial loop over particles, on the 14
// deformed icosahedral particles of random_sheared3d for each model of Table 9.1 (168 vertices, above the
// parallel threshold), with contacts.
#include "core/rng.hpp"
#include "dpm/system/system3d.hpp"
#include "support/jammed3d.hpp"
#include "support/thread_bits.hpp"

using namespace softgrain;
using namespace softgrain::dpm;
using namespace softgrain::verification;

TEST_CASE("3D shape energies: the same bits on 1 and 2 threads [DPM eq. (9.2)]")
{
    Rng rng(41);
    for (ShapeModel model : {ShapeModel::shell, ShapeModel::floppy, ShapeModel::surface_tension}) {
        Eigen::VectorXd x;
        const DpmSystem3d s = random_sheared3d(model, rng, x);
        REQUIRE(interaction_energy3d(s, x, nullptr, nullptr) > 0);
        const auto threaded = on_one_and_two_threads(
            x.size(), [&](Eigen::VectorXd& gradient) { return total_energy3d(s, x, &gradient, nullptr); });
        // The serial loop over the particles, as total_energy3d sums them below the threshold.
        EnergyAndGradient serial{0, Eigen::VectorXd::Zero(x.size())};
        for (const Particle3d& p : s.particles)
            serial.energy += shape_energy3d(p.shape, s.meshes[p.mesh], x, p.first, &serial.gradient, nullptr);
        serial.energy += interaction_energy3d(s, x, &serial.gradient, nullptr);
        CAPTURE(static_cast<int>(model));
        check_same_bits(threaded, serial);
    }
}
