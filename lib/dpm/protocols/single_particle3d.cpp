#include "dpm/protocols/single_particle3d.hpp"

#include "core/errors.hpp"
#include "core/fire.hpp"
#include "core/rng.hpp"
#include "dpm/analysis/modes.hpp"

#include <Eigen/Eigenvalues>

namespace softgrain::dpm {

ShapeParameters3d model_shape3d(ShapeModel model, const TriangleMesh& mesh, const Eigen::VectorXd& x,
                                double A0, double kv, const Stiffness3d& k)
{
    const double A_mesh = mesh_shape_parameter3d(mesh, x, 0);
    if (A0 < A_mesh)
        throw InputError("parameter 'A0' = '" + std::to_string(A0) +
                         "' is below the mesh's own shape parameter " + std::to_string(A_mesh) +
                         "; allowed: min (the mesh's own) or a real number >= it");
    const double scale = std::pow(A0 / A_mesh, 2.0 / 3.0);
    const bool shell = model == ShapeModel::shell, tension = model == ShapeModel::surface_tension;
    return rest_shape_from_mesh(mesh, x, kv, k.ka, shell ? k.kb : 0.0, tension ? k.gamma : 0.0, scale);
}

SingleParticle3d single_particle3d_equilibrium(ShapeModel model, const TriangleMesh& mesh,
                                               std::optional<double> A0, const Stiffness3d& k,
                                               std::uint64_t seed)
{
    SingleParticle3d p;
    p.mesh = mesh;
    // Scale the mesh to unit volume.
    const Eigen::VectorXd unit = mesh_coordinates(mesh);
    p.mesh.vertices /= std::cbrt(mesh_volume(mesh, unit, 0));
    const Eigen::VectorXd reference = mesh_coordinates(p.mesh);
    p.A_mesh = mesh_shape_parameter3d(p.mesh, reference, 0);
    p.A0 = A0.value_or(p.A_mesh);
    p.shape = model_shape3d(model, p.mesh, reference, p.A0, 1.0, k);

    Rng rng(seed);
    double edge = 0;
    for (const auto& e : p.mesh.edges)
        edge += (p.mesh.vertices.col(e.a) - p.mesh.vertices.col(e.b)).norm();
    edge /= p.mesh.edge_count();
    p.x = reference;
    for (Eigen::Index i = 0; i < p.x.size(); ++i)
        p.x(i) += 0.05 * edge * rng.uniform(-1, 1);

    const EnergyWithDerivatives energy = [&p](const Eigen::VectorXd& y, Eigen::VectorXd* g,
                                              Eigen::MatrixXd* h) {
        return shape_energy3d(p.shape, p.mesh, y, 0, g, h);
    };
    FireOptions options;
    options.force_tolerance = 1e-9;
    options.max_iterations = 2000000;
    const FireResult fire = fire_minimise(
        p.x,
        [&energy](const Eigen::VectorXd& y, Eigen::VectorXd& f) {
            f.setZero(y.size());
            const double u = energy(y, &f, nullptr);
            f = -f;
            return u;
        },
        options);
    if (!fire.converged)
        throw NumericalError("relaxation of the 3D particle (" + fire_shortfall(fire, options) + ")",
                             fire.iterations,
                             "no equilibrium within max_iterations (stiffness ratios too extreme?)");
    p.fire_iterations = fire.iterations;
    p.force_max = polish_newton(energy, p.x, 1e-14, 30);
    return p;
}

} // namespace softgrain::dpm
