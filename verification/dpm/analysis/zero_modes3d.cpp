// DPM section 9.4.3 and Fig. 9.15(a): zero modes of the dynamical matrix (eq. 9.28) of single 3D
// particles. A floppy particle (k_v, k_a > 0, A0 > A_min) has N_dof - N_f - 1 = 3N - (2N - 4) - 1 = N + 3
// zero modes (45 for N = 42); an elastic shell and a surface-tension particle only the 6 rigid-body modes.
// Counts are exact integers; a mode is zero below the paper's threshold lambda~ < 1e-10 (in k_v v0^(4/3)).
#include "dpm/protocols/single_particle3d.hpp"
#include "support/tolerance.hpp"

#include <Eigen/Eigenvalues>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::Tolerance;

namespace {

Eigen::VectorXd spectrum(const SingleParticle3d& p)
{
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(p.x.size(), p.x.size());
    shape_energy3d(p.shape, p.mesh, p.x, 0, nullptr, &m);
    return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(m, Eigen::EigenvaluesOnly).eigenvalues();
}

int zero_modes(const Eigen::VectorXd& lambda)
{
    return static_cast<int>((lambda.array() < 1e-10).count());
}

} // namespace

TEST_CASE("zero modes of single 3D particles: floppy N + 3, shell and surface tension 6 [DPM Fig. 9.15a]")
{
    const Stiffness3d k; // k_a = 1, k_b = 0.1, gamma = 0.01 (k_v = 1)
    struct Case
    {
        ShapeModel model;
        const char* mesh;
        std::optional<double> A0; // none: the mesh's own A^3D
        int expected;
    };
    const Case cases[] = {{ShapeModel::floppy, "geodesic42", 1.04, 45},
                          {ShapeModel::shell, "geodesic42", std::nullopt, 6},
                          {ShapeModel::surface_tension, "geodesic42", std::nullopt, 6},
                          {ShapeModel::floppy, "icosahedron", 1.12, 15}};
    for (const auto& c : cases) {
        CAPTURE(std::string(c.mesh));
        CAPTURE(static_cast<int>(c.model));
        const SingleParticle3d p = single_particle3d_equilibrium(c.model, mesh_from_name(c.mesh), c.A0, k, 7);
        // Equilibrium to round-off (a residual force f would lift rotations to lambda ~ f).
        CHECK_CLOSE(p.force_max, 0.0, (Tolerance{0, 1e-13}));
        const Eigen::VectorXd lambda = spectrum(p);
        const int zero = zero_modes(lambda);
        CHECK(zero == c.expected);
        // The count is robust: the gap between the largest zero mode and the softest non-zero mode spans
        // several decades either side of the threshold (no eigenvalue near 1e-10).
        CHECK(lambda(zero - 1) < 1e-12);
        CHECK(lambda(zero) > 1e-6);
        CHECK(lambda(0) > -1e-12); // a minimum: no negative eigenvalue beyond round-off
    }
}
