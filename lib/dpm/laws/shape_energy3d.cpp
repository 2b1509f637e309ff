#include "dpm/laws/shape_energy3d.hpp"

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

} // namespace

double shape_energy3d(const ShapeParameters3d& shape, const TriangleMesh& mesh, const Eigen::VectorXd& x,
                      int first, Eigen::VectorXd* gradient, HessianSink hessian, unsigned terms)
{
    const auto face_of = [&mesh, first](int f) { return face_points(mesh.faces[f], first); };
    return with_dense_block(hessian, 3 * first, 3 * mesh.vertex_count(), [&](HessianSink block) {
        double energy = 0;
        if ((terms & volume_term3d) && shape.kv != 0)
            energy +=
                penalty_of_sum<3, 3>(shape.kv, shape.v0, face_volume, face_volume_slope, mesh.face_count(),
                                     face_of, first, mesh.vertex_count(), x, gradient, block);
        const double ka = (terms & face_area_term3d) ? shape.ka : 0;
        const double gamma = (terms & surface_tension_term3d) ? shape.gamma : 0;
        if (ka != 0 || gamma != 0)
            for (int f = 0; f < mesh.face_count(); ++f)
                energy += measure_term<3, 3>(triangle_area, triangle_area_slope, face_of(f), x, ka,
                                             ka != 0 ? shape.a0[f] : 0.0, gamma, gradient, block);
        if ((terms & bending_term3d) && shape.kb != 0)
            for (int e = 0; e < mesh.edge_count(); ++e)
                energy += measure_term<3, 4>(dihedral_angle, dihedral_angle_slope,
                                             edge_points(mesh.edges[e], first), x, shape.kb, shape.theta0[e],
                                             0.0, gradient, block);
        return energy;
    });
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
