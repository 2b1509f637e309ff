#include "dpm/shape_energy3d.hpp"

namespace softgrain::dpm {

namespace {

std::array<int, 3> face_points(const std::array<int, 3>& f, int first)
{
    return {first + f[0], first + f[1], first + f[2]};
}

std::array<int, 4> edge_points(const MeshEdge& e, int first)
{
    return {first + e.a, first + e.b, first + e.c, first + e.d};
}

// k_v/2 (v - v0)^2 with v = sum of the face volumes: gradient k_v (v - v0) grad v, Hessian
// k_v (grad v grad v^T + (v - v0) hess v); grad v and hess v are assembled from the local face volumes.
double volume_energy(const ShapeParameters3d& shape, const TriangleMesh& mesh, const Eigen::VectorXd& x,
                     int first, Eigen::VectorXd* gradient, Eigen::MatrixXd* hessian)
{
    const auto dofs = x.size();
    Eigen::VectorXd grad_v = Eigen::VectorXd::Zero(gradient || hessian ? dofs : 0);
    Eigen::MatrixXd hess_v = Eigen::MatrixXd::Zero(hessian ? dofs : 0, hessian ? dofs : 0);
    const auto term = [](const auto& local) { return face_volume(local); };
    double volume = 0;
    for (const auto& f : mesh.faces) {
        const auto points = face_points(f, first);
        volume += add_local_term<3, 3>(term, points, gather<3, 3>(x, points),
                                       gradient || hessian ? &grad_v : nullptr, hessian ? &hess_v : nullptr);
    }
    const double deviation = volume - shape.v0;
    if (gradient) *gradient += shape.kv * deviation * grad_v;
    if (hessian) *hessian += shape.kv * (grad_v * grad_v.transpose() + deviation * hess_v);
    return harmonic_penalty(shape.kv, volume, shape.v0);
}

} // namespace

double shape_energy3d(const ShapeParameters3d& shape, const TriangleMesh& mesh, const Eigen::VectorXd& x,
                      int first, Eigen::VectorXd* gradient, Eigen::MatrixXd* hessian, unsigned terms)
{
    double energy = 0;
    if ((terms & volume_term3d) && shape.kv != 0)
        energy += volume_energy(shape, mesh, x, first, gradient, hessian);
    const SurfaceTensionEnergy tension{shape.gamma};
    for (int f = 0; f < mesh.face_count(); ++f) {
        const auto points = face_points(mesh.faces[f], first);
        if ((terms & face_area_term3d) && shape.ka != 0)
            energy += add_local_term<3, 3>(FaceAreaEnergy{shape.ka, shape.a0[f]}, points,
                                           gather<3, 3>(x, points), gradient, hessian);
        if ((terms & surface_tension_term3d) && shape.gamma != 0)
            energy += add_local_term<3, 3>(tension, points, gather<3, 3>(x, points), gradient, hessian);
    }
    if ((terms & bending_term3d) && shape.kb != 0)
        for (int e = 0; e < mesh.edge_count(); ++e) {
            const auto points = edge_points(mesh.edges[e], first);
            energy += add_local_term<3, 4>(DihedralEnergy{shape.kb, shape.theta0[e]}, points,
                                           gather<3, 4>(x, points), gradient, hessian);
        }
    return energy;
}

double mesh_volume(const TriangleMesh& mesh, const Eigen::VectorXd& x, int first)
{
    double volume = 0;
    for (const auto& f : mesh.faces)
        volume += face_volume(gather<3, 3>(x, face_points(f, first)));
    return volume;
}

std::vector<double> mesh_face_areas(const TriangleMesh& mesh, const Eigen::VectorXd& x, int first)
{
    std::vector<double> areas;
    for (const auto& f : mesh.faces)
        areas.push_back(triangle_area(gather<3, 3>(x, face_points(f, first))));
    return areas;
}

double mesh_surface_area(const TriangleMesh& mesh, const Eigen::VectorXd& x, int first)
{
    double surface = 0;
    for (double a : mesh_face_areas(mesh, x, first))
        surface += a;
    return surface;
}

std::vector<double> mesh_bending_angles(const TriangleMesh& mesh, const Eigen::VectorXd& x, int first)
{
    std::vector<double> angles;
    for (const auto& e : mesh.edges)
        angles.push_back(dihedral_angle(gather<3, 4>(x, edge_points(e, first))));
    return angles;
}

Eigen::VectorXd mesh_coordinates(const TriangleMesh& mesh)
{
    return mesh.vertices.reshaped();
}

ShapeParameters3d rest_shape_from_mesh(const TriangleMesh& mesh, const Eigen::VectorXd& x, double kv,
                                       double ka, double kb, double gamma, double area_scale)
{
    ShapeParameters3d shape;
    shape.kv = kv;
    shape.v0 = mesh_volume(mesh, x, 0);
    shape.ka = ka;
    shape.a0 = mesh_face_areas(mesh, x, 0);
    for (double& a : shape.a0)
        a *= area_scale;
    shape.kb = kb;
    shape.theta0 = mesh_bending_angles(mesh, x, 0);
    shape.gamma = gamma;
    return shape;
}

} // namespace softgrain::dpm
