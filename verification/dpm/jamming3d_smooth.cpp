// ctest-label: slow
// DPM section 9.4 in 3D with smooth contacts (vertex against faces, interactions3d.hpp): the jamming
// protocol (compression, FIRE, bisection on the virial pressure that includes the smooth contact forces)
// ends in force balance at 1 <= P/P_t < 1.01 with both particles in contact, and the dynamical matrix of the
// shell packing has exactly the 3 zero modes of the periodic translations (sec. 9.4.3, as for rough
// contacts in jamming3d.cpp). Two icosahedral shells, P_t = 1e-4 k_v v0: about 7 s.
#include "dpm/jam3d.hpp"
#include "dpm/modes.hpp"
#include "support/tolerance.hpp"

#include <Eigen/Eigenvalues>

using namespace softgrain;
using namespace softgrain::dpm;

TEST_CASE("3D jamming with smooth contacts ends in force balance at 1 <= P/P_t < 1.01 [DPM sec. 9.4]")
{
    Jam3dOptions o;
    o.particles = 2;
    o.mesh = "icosahedron";
    o.pressure_onset = 1e-4;
    o.interaction = InteractionKind::smooth;
    Jam3dResult j = jam3d(o);
    CHECK(j.system.interaction == InteractionKind::smooth);
    CHECK(j.pressure >= 1e-4);
    CHECK(j.pressure < 1.01e-4);
    Eigen::VectorXd g = Eigen::VectorXd::Zero(j.x.size());
    total_energy3d(j.system, j.x, &g, nullptr);
    CHECK(g.norm() / std::sqrt(double(g.size())) < j.fire.force_tolerance); // FIRE's stopping rule
    for (int c : contact_counts3d(j.system, j.x))
        CHECK(c > 0);
    // Zero modes after Newton polishing to round-off forces (threshold 1e-10 as in Fig. 9.15a).
    const EnergyWithDerivatives energy = [&j](const Eigen::VectorXd& y, Eigen::VectorXd* gr,
                                              Eigen::MatrixXd* h) {
        return total_energy3d(j.system, y, gr, h);
    };
    polish_newton(energy, j.x, 1e-14 * j.pressure_unit, 30);
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(j.x.size(), j.x.size());
    total_energy3d(j.system, j.x, nullptr, &m);
    const Eigen::VectorXd lambda =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(m, Eigen::EigenvaluesOnly).eigenvalues() /
        j.eigenvalue_unit;
    CHECK(count_zero_modes(lambda, 1e-10) == 3);
    MESSAGE("phi = " << j.phi << ", box steps " << j.box_steps << ", FIRE iterations " << j.fire_iterations);
}
