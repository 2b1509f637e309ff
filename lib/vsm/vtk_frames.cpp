#include "vsm/vtk_frames.hpp"

#include "vsm/neo_hookean.hpp"

namespace softgrain::vsm {

vtk::PolyData vsm_particles(const Model& model, const Points<3>& x, const Points<3>& v, double t)
{
    vtk::PolyData data;
    const std::vector<Mat3> F = model.deformation_gradients(x, t);
    const LameParameters lame = model.material().lame();
    const Points<3>& X = model.cells().X;
    std::vector<double> displacement, velocity, gradient, stress, pressure, von_mises, volume_ratio, volume;
    std::vector<std::int64_t> ids;
    for (Eigen::Index a = 0; a < x.cols(); ++a) {
        const auto ua = static_cast<std::size_t>(a);
        data.add_vertex(data.add_point(x(0, a), x(1, a), x(2, a)));
        ids.push_back(a);
        for (int i = 0; i < 3; ++i) {
            displacement.push_back(x(i, a) - X(i, a));
            velocity.push_back(v(i, a));
        }
        const Mat3 sigma = neo_hookean_cauchy_stress(F[ua], lame);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                gradient.push_back(F[ua](i, j));
                stress.push_back(sigma(i, j));
            }
        pressure.push_back(-sigma.trace() / 3.0); // as Model::pressures
        von_mises.push_back(von_mises_stress(sigma));
        volume_ratio.push_back(F[ua].determinant());
        volume.push_back(model.cells().volume[ua]);
    }
    data.point_scalars("pressure", std::move(pressure));
    data.point_vectors("displacement", std::move(displacement));
    data.point_vectors("velocity", std::move(velocity));
    data.point_tensors("deformation_gradient", std::move(gradient));
    data.point_tensors("cauchy_stress", std::move(stress));
    data.point_scalars("von_mises", std::move(von_mises));
    data.point_scalars("volume_ratio", std::move(volume_ratio));
    data.point_scalars("voronoi_volume", std::move(volume));
    data.cell_ids("particle_id", std::move(ids));
    return data;
}

vtk::PolyData vsm_walls(const Model& model, double t)
{
    vtk::PolyData data;
    const BoundaryConditions& bc = model.boundary_conditions();
    std::vector<std::int64_t> labels, kinds;
    for (const BoundaryFace& face : model.domain().faces) {
        const auto label = static_cast<std::size_t>(face.label);
        const BoundaryKind kind = label < bc.kind.size() ? bc.kind[label] : BoundaryKind::free;
        if (kind == BoundaryKind::free) continue;
        const Mat3 D = boundary_projection(kind, face.normal());
        // The rectangle's corners in order around it: the two axes in the face's plane.
        const int u = (face.axis + 1) % 3, w = (face.axis + 2) % 3;
        std::vector<std::int64_t> corners;
        constexpr int along_u[4] = {0, 1, 1, 0}, along_w[4] = {0, 0, 1, 1};
        for (int c = 0; c < 4; ++c) {
            Vec3 W = face.low;
            W(u) = along_u[c] ? face.high(u) : face.low(u);
            W(w) = along_w[c] ? face.high(w) : face.low(w);
            if (bc.displacement) W += D * bc.displacement(face.label, W, t);
            corners.push_back(data.add_point(W.x(), W.y(), W.z()));
        }
        data.add_polygon(corners);
        labels.push_back(face.label);
        kinds.push_back(kind == BoundaryKind::total ? 1 : kind == BoundaryKind::symmetric ? 2 : 3);
    }
    data.cell_ids("face_label", std::move(labels));
    data.cell_ids("boundary_kind", std::move(kinds));
    return data;
}

std::vector<vtk::Part> vsm_frame(const Model& model, const Leapfrog& integrator,
                                 const std::vector<std::pair<std::string, double>>& fields)
{
    return vsm_frame(model, integrator.positions(), integrator.half_step_velocities(), integrator.state().t,
                     integrator.state().step, fields);
}

std::vector<vtk::Part> vsm_frame(const Model& model, const Points<3>& x, const Points<3>& v, double t,
                                 long step, const std::vector<std::pair<std::string, double>>& fields)
{
    std::vector<vtk::Part> parts{{"particles", vsm_particles(model, x, v, t)}};
    vtk::PolyData walls = vsm_walls(model, t);
    if (walls.cells() > 0) parts.push_back({"walls", std::move(walls)});
    for (vtk::Part& part : parts) {
        part.data.field("time", t);
        part.data.field("step", static_cast<double>(step));
        for (const auto& [name, value] : fields)
            part.data.field(name, value);
    }
    return parts;
}

} // namespace softgrain::vsm
