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
// k_v (grad v grad v^T + (v - v0) hess v); grad v and hess v are assembled from the local face volumes over
// the particle's own coordinates (the rank-one term couples every pair of them, and only them).
double volume_energy(const ShapeParameters3d& shape, const TriangleMesh& mesh, const Eigen::VectorXd& x,
                     int first, Eigen::VectorXd* gradient, HessianSink hessian)
{
    const int dofs = 3 * mesh.vertex_count();
    const Eigen::VectorXd own_x = x.segment(3 * first, dofs);
    Eigen::VectorXd grad_v = Eigen::VectorXd::Zero(gradient || hessian ? dofs : 0);
    Eigen::MatrixXd hess_v = Eigen::MatrixXd::Zero(hessian ? dofs : 0, hessian ? dofs : 0);
    const auto term = [](const auto& local) { return face_volume(local); };
    double volume = 0;
    for (const auto& f : mesh.faces) {
        const auto points = face_points(f, 0);
        volume += add_local_term<3, 3>(term, points, gather<3, 3>(own_x, points),
                                       gradient || hessian ? &grad_v : nullptr, hessian ? &hess_v : nullptr);
    }
    const double deviation = volume - shape.v0;
    if (gradient) gradient->segment(3 * first, dofs) += shape.kv * deviation * grad_v;
    if (hessian)
        hessian.add(3 * first, 3 * first, shape.kv * (grad_v * grad_v.transpose() + deviation * hess_v));
    return harmonic_penalty(shape.kv, volume, shape.v0);
}

// Eq. (9.2) with its gradient through the analytic local gradients (decision dpm-3d-analytic-gradient):
// the same terms in the same order as the AutoDiff path below; the face area is computed once per face for
// both k_a and gamma, d U/d x = (k_a (a_f - a_f0) + gamma) d a_f/d x.
double shape_energy_with_gradient3d(const ShapeParameters3d& shape, const TriangleMesh& mesh,
                                    const Eigen::VectorXd& x, int first, Eigen::VectorXd& gradient,
                                    unsigned terms)
{
    double energy = 0;
    if ((terms & volume_term3d) && shape.kv != 0) {
        Eigen::VectorXd grad_v = Eigen::VectorXd::Zero(3 * mesh.vertex_count()); // this particle's dofs
        double volume = 0;
        for (const auto& f : mesh.faces) {
            const LocalGradient<9> d = face_volume_gradient(gather<3, 3>(x, face_points(f, first)));
            volume += d.value;
            scatter_gradient<3, 3>(d.gradient, face_points(f, 0), 1.0, grad_v);
        }
        gradient.segment(3 * first, grad_v.size()) += shape.kv * (volume - shape.v0) * grad_v;
        energy += harmonic_penalty(shape.kv, volume, shape.v0);
    }
    const bool areas = (terms & face_area_term3d) && shape.ka != 0;
    const bool tension = (terms & surface_tension_term3d) && shape.gamma != 0;
    if (areas || tension)
        for (int f = 0; f < mesh.face_count(); ++f) {
            const auto points = face_points(mesh.faces[f], first);
            const LocalGradient<9> d = triangle_area_gradient(gather<3, 3>(x, points));
            double slope = 0; // d U/d a_f
            if (areas) {
                energy += harmonic_penalty(shape.ka, d.value, shape.a0[f]);
                slope += shape.ka * (d.value - shape.a0[f]);
            }
            if (tension) {
                energy += shape.gamma * d.value;
                slope += shape.gamma;
            }
            scatter_gradient<3, 3>(d.gradient, points, slope, gradient);
        }
    if ((terms & bending_term3d) && shape.kb != 0)
        for (int e = 0; e < mesh.edge_count(); ++e) {
            const auto points = edge_points(mesh.edges[e], first);
            const LocalGradient<12> d = dihedral_angle_gradient(gather<3, 4>(x, points));
            energy += harmonic_penalty(shape.kb, d.value, shape.theta0[e]);
            scatter_gradient<3, 4>(d.gradient, points, shape.kb * (d.value - shape.theta0[e]), gradient);
        }
    return energy;
}

} // namespace

LocalGradient<9> face_volume_gradient(const Eigen::Matrix<double, 9, 1>& x)
{
    const Eigen::Vector3d r0 = x.segment<3>(0), r1 = x.segment<3>(3), r2 = x.segment<3>(6);
    LocalGradient<9> d;
    d.value = face_volume(x);
    d.gradient << r1.cross(r2) / 6.0, r2.cross(r0) / 6.0, r0.cross(r1) / 6.0;
    return d;
}

LocalGradient<9> triangle_area_gradient(const Eigen::Matrix<double, 9, 1>& x)
{
    const Eigen::Vector3d r0 = x.segment<3>(0), r1 = x.segment<3>(3), r2 = x.segment<3>(6);
    const Eigen::Vector3d m = (r1 - r0).cross(r2 - r0).normalized();
    const Eigen::Vector3d g1 = 0.5 * (r2 - r0).cross(m), g2 = 0.5 * m.cross(r1 - r0);
    LocalGradient<9> d;
    d.value = triangle_area(x);
    d.gradient << -(g1 + g2), g1, g2;
    return d;
}

LocalGradient<12> dihedral_angle_gradient(const Eigen::Matrix<double, 12, 1>& x)
{
    const Eigen::Vector3d a = x.segment<3>(0), b = x.segment<3>(3), c = x.segment<3>(6), dd = x.segment<3>(9);
    const Eigen::Vector3d e = b - a;
    const Eigen::Vector3d n1 = e.cross(c - a), n2 = (a - b).cross(dd - b);
    const double e2 = e.squaredNorm(), length = std::sqrt(e2);
    const Eigen::Vector3d gc = -length / n1.squaredNorm() * n1, gd = -length / n2.squaredNorm() * n2;
    const Eigen::Vector3d gb = -((c - a).dot(e) / e2 * gc + (dd - a).dot(e) / e2 * gd);
    LocalGradient<12> d;
    d.value = dihedral_angle(x);
    d.gradient << -(gb + gc + gd), gb, gc, gd;
    return d;
}

double shape_energy3d(const ShapeParameters3d& shape, const TriangleMesh& mesh, const Eigen::VectorXd& x,
                      int first, Eigen::VectorXd* gradient, HessianSink hessian, unsigned terms)
{
    if (gradient && !hessian) return shape_energy_with_gradient3d(shape, mesh, x, first, *gradient, terms);
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
