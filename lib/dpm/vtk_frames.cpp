#include "dpm/vtk_frames.hpp"

#include "dpm/shape_energy.hpp"

#include <cmath>

namespace softgrain::dpm {

vtk::PolyData dpm_particles(const DpmSystem& system, const Eigen::VectorXd& x)
{
    vtk::PolyData data;
    Eigen::VectorXd gradient = Eigen::VectorXd::Zero(x.size());
    total_energy(system, x, &gradient, nullptr);
    std::vector<double> radius, force, area_ratio, vertices;
    std::vector<std::int64_t> ids;
    for (std::size_t k = 0; k < system.particles.size(); ++k) {
        const Particle& p = system.particles[k];
        Eigen::Vector2d centre = Eigen::Vector2d::Zero();
        for (int v = p.first; v < p.first + p.count; ++v)
            centre += x.segment<2>(2 * v) / p.count;
        const Eigen::Vector2d shift = system.box
                                          ? Eigen::Vector2d(wrap_into_box(centre, *system.box) - centre)
                                          : Eigen::Vector2d::Zero();
        std::vector<std::int64_t> cell;
        for (int v = p.first; v < p.first + p.count; ++v) {
            const Eigen::Vector2d r = x.segment<2>(2 * v) + shift;
            cell.push_back(data.add_point(r.x(), r.y()));
            radius.push_back(0.5 * p.sigma);
            force.insert(force.end(), {-gradient(2 * v), -gradient(2 * v + 1), 0.0});
        }
        if (p.count == 1)
            data.add_vertex(cell.front());
        else
            data.add_polygon(cell);
        ids.push_back(static_cast<std::int64_t>(k));
        area_ratio.push_back(p.count >= 3 && p.shape.a0 > 0 ? particle_area(x, p.first, p.count) / p.shape.a0
                                                            : NAN);
        vertices.push_back(p.count);
    }
    data.point_scalars("radius", std::move(radius));
    data.point_vectors("force", std::move(force));
    data.cell_scalars("area_ratio", std::move(area_ratio));
    data.cell_ids("particle_id", std::move(ids));
    data.cell_scalars("vertices", std::move(vertices));
    return data;
}

vtk::PolyData box_outline(const Eigen::Vector2d& box)
{
    vtk::PolyData data;
    const std::int64_t a = data.add_point(0, 0), b = data.add_point(box.x(), 0),
                       c = data.add_point(box.x(), box.y()), d = data.add_point(0, box.y());
    data.add_line({a, b, c, d, a});
    return data;
}

vtk::PolyData plates(double x_min, double x_max, double y_bottom, double y_top)
{
    vtk::PolyData data;
    for (const double y : {y_bottom, y_top}) {
        const std::int64_t a = data.add_point(x_min, y), b = data.add_point(x_max, y);
        data.add_line({a, b});
    }
    data.cell_ids("plate_id", {0, 1});
    return data;
}

} // namespace softgrain::dpm
