// The 3D shape energies summed in parallel over particles (dpm/system/particle_sum.hpp): energy and gradient
// of total_energy3d are bit-identical for 1 and 2 OpenMP threads and to the serial loop over particles, on the 14
// deformed icosahedral particles of random_sheared3d for each model of Table 9.1 (168 vertices, above the
// parallel threshold), with contacts.
#include "core/rng.hpp"
#include "dpm/system/system3d.hpp"
#include "support/jammed3d.hpp"

#include <omp.h>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::random_sheared3d;

TEST_CASE("3D shape energies: the same bits on 1 and 2 threads [DPM eq. (9.2)]")
{
    const int threads_before = omp_get_max_threads();
    Rng rng(41);
    for (ShapeModel model : {ShapeModel::shell, ShapeModel::floppy, ShapeModel::surface_tension}) {
        Eigen::VectorXd x;
        const DpmSystem3d s = random_sheared3d(model, rng, x);
        REQUIRE(interaction_energy3d(s, x, nullptr, nullptr) > 0);
        Eigen::VectorXd gradient[2];
        double energy[2];
        for (int threads : {1, 2}) {
            omp_set_num_threads(threads);
            gradient[threads - 1] = Eigen::VectorXd::Zero(x.size());
            energy[threads - 1] = total_energy3d(s, x, &gradient[threads - 1], nullptr);
        }
        // The serial loop over the particles, as total_energy3d sums them below the threshold.
        Eigen::VectorXd serial_gradient = Eigen::VectorXd::Zero(x.size());
        double serial_energy = 0;
        for (const Particle3d& p : s.particles)
            serial_energy += shape_energy3d(p.shape, s.meshes[p.mesh], x, p.first, &serial_gradient, nullptr);
        serial_energy += interaction_energy3d(s, x, &serial_gradient, nullptr);
        CAPTURE(static_cast<int>(model));
        CHECK(energy[0] == energy[1]);
        CHECK(gradient[0] == gradient[1]);
        CHECK(energy[1] == serial_energy);
        CHECK(gradient[1] == serial_gradient);
        REQUIRE(gradient[0].norm() > 0);
    }
    omp_set_num_threads(threads_before);
}
