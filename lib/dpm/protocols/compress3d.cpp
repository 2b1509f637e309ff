#include "dpm/protocols/compress3d.hpp"

#include "dpm/laws/shape_energy3d.hpp"
#include "dpm/laws/spring_network.hpp"

#include <Eigen/Geometry>

#include <numbers>

namespace softgrain::dpm {

namespace {
// The plate driver's observer for a body observer: adds the body's energy gradient.
PlateObserver with_gradient(const BodyEnergy& energy, const BodyObserver& observe)
{
    if (!observe) return {};
    return [&energy, &observe](const Eigen::VectorXd& x, double top, const CompressionSample& sample) {
        Eigen::VectorXd gradient = Eigen::VectorXd::Zero(x.size());
        energy(x, &gradient);
        observe(x, top, sample, gradient);
    };
}
} // namespace

TriangleMesh compression_mesh(const std::string& name)
{
    TriangleMesh mesh = mesh_from_name(name);
    const Eigen::Quaterniond to_pole =
        Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d(mesh.vertices.col(0)), Eigen::Vector3d::UnitZ());
    mesh.vertices = to_pole.toRotationMatrix() * mesh.vertices;
    double edge = 0;
    for (const MeshEdge& e : mesh.edges)
        edge += (mesh.vertices.col(e.a) - mesh.vertices.col(e.b)).norm();
    mesh.vertices /= edge / mesh.edge_count();
    return mesh;
}

double mean_face_area(const TriangleMesh& mesh)
{
    return mesh_surface_area(mesh, mesh_coordinates(mesh), 0) / mesh.face_count();
}

double gershgorin_bound(const Eigen::MatrixXd& m)
{
    return m.cwiseAbs().rowwise().sum().maxCoeff();
}

Compression3dResult compress3d_tetrahedra(const Compression3dOptions& options, const BodyObserver& observe)
{
    const ElasticTetrahedra body = elastic_tetrahedra(compression_mesh(options.mesh),
                                                      IsotropicElasticity::from_young(options.E, options.nu));
    const BodyEnergy energy = [&body](const Eigen::VectorXd& y, Eigen::VectorXd* gradient) {
        return tetrahedra_energy(body, y, gradient, nullptr);
    };
    Eigen::MatrixXd hessian = Eigen::MatrixXd::Zero(body.reference.size(), body.reference.size());
    tetrahedra_energy(body, body.reference, nullptr, &hessian);
    Compression3dResult out;
    out.compression = compress_between_plates<3>(body.reference, energy, 1.0, gershgorin_bound(hessian),
                                                 options.schedule, with_gradient(energy, observe));
    out.E = options.E;
    out.nu = options.nu;
    out.vertices = body.centre() + 1;
    return out;
}

Compression3dResult compress3d_shell(const Compression3dOptions& options, const BodyObserver& observe)
{
    const TriangleMesh mesh = compression_mesh(options.mesh);
    const Eigen::VectorXd x = mesh_coordinates(mesh);
    // A0 = A_min: the mesh's own areas, angles and volume are the rest state (decision dpm-3d-rest-state).
    const ShapeParameters3d shape = rest_shape_from_mesh(mesh, x, options.kv, options.ka, options.kb, 0.0);
    const BodyEnergy energy = [&shape, &mesh](const Eigen::VectorXd& y, Eigen::VectorXd* gradient) {
        return shape_energy3d(shape, mesh, y, 0, gradient, nullptr);
    };
    Eigen::MatrixXd hessian = Eigen::MatrixXd::Zero(x.size(), x.size());
    shape_energy3d(shape, mesh, x, 0, nullptr, &hessian);
    Compression3dResult out;
    out.compression = compress_between_plates<3>(x, energy, 1.0, gershgorin_bound(hessian), options.schedule,
                                                 with_gradient(energy, observe));
    // A plate of thickness sigma whose 2D area modulus K_2D = k_a a0 equals E sigma/(2 (1 - nu)), nu = 0.
    out.E = 2 * options.ka * mean_face_area(mesh);
    out.nu = 0;
    out.vertices = mesh.vertex_count();
    return out;
}

Compression3dResult compress3d_network(const Compression3dOptions& options, const BodyObserver& observe)
{
    const SpringNetwork network =
        disordered_sphere_network(options.network_nodes, options.cutoff, options.network_k, options.seed);
    const BodyEnergy energy = [&network](const Eigen::VectorXd& y, Eigen::VectorXd* gradient) {
        return spring_network_energy(network, y, gradient);
    };
    // Gershgorin bound of the rest-state Hessian: spring k n n^T enters the rows of both ends twice (diagonal
    // and off-diagonal block), row c of node i sums 2 k |n_c| (|n_x| + |n_y| + |n_z|) over its springs.
    Eigen::MatrixXd rows = Eigen::MatrixXd::Zero(3, network.node_count());
    for (const Spring& s : network.springs) {
        const Eigen::Vector3d n =
            (network.x.segment<3>(3 * s.j) - network.x.segment<3>(3 * s.i)).cwiseAbs() / s.rest_length;
        const Eigen::Vector3d row = 2 * network.k * n * n.sum();
        rows.col(s.i) += row;
        rows.col(s.j) += row;
    }
    Compression3dResult out;
    out.compression = compress_between_plates<3>(network.x, energy, 1.0, rows.maxCoeff(), options.schedule,
                                                 with_gradient(energy, observe));
    const double radius = network.x.reshaped(3, network.node_count()).colwise().norm().maxCoeff();
    out.E = affine_network_young_modulus(network, 4.0 / 3.0 * std::numbers::pi * radius * radius * radius);
    out.nu = affine_network_poisson_ratio;
    out.vertices = network.node_count();
    out.springs = static_cast<int>(network.springs.size());
    return out;
}

} // namespace softgrain::dpm
