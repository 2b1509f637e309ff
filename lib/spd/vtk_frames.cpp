#include "spd/vtk_frames.hpp"

#include <cmath>

namespace softgrain::spd {

namespace {
// Points of the shells' vertices in order, with the point data both kinds share.
struct ShellPoints
{
    std::vector<Vec2> velocity, force;
    std::vector<std::vector<std::int64_t>> cells; // the point indices of each shell
};

ShellPoints add_shell_points(vtk::PolyData& data, const ShellModel& model, const std::vector<int>& shells)
{
    ShellPoints out;
    for (const int p : shells) {
        const Shell& s = model.shells()[p];
        std::vector<std::int64_t> cell;
        for (int i = s.first; i < s.first + s.count; ++i) {
            cell.push_back(data.add_point(model.vertex(i)));
            out.velocity.push_back(model.velocity(i));
            out.force.push_back(model.force(i));
        }
        out.cells.push_back(std::move(cell));
    }
    return out;
}
} // namespace

vtk::PolyData shell_particles(const ShellModel& model, const std::vector<int>& shells)
{
    vtk::PolyData data;
    ShellPoints points = add_shell_points(data, model, shells);
    std::vector<double> contact, torque, plastic, area_ratio, pressure, energy;
    std::vector<std::int64_t> ids;
    for (std::size_t k = 0; k < shells.size(); ++k) {
        const int p = shells[k];
        const Shell& s = model.shells()[p];
        data.add_polygon(points.cells[k]);
        for (int i = s.first; i < s.first + s.count; ++i) {
            contact.push_back(model.contact_normal(i));
            torque.push_back(model.hinge_torque(i));
            plastic.push_back(std::isfinite(s.laws.M_Y) ? std::abs(model.hinge_torque(i)) / s.laws.M_Y : 0.0);
        }
        ids.push_back(p);
        area_ratio.push_back(model.area(p) / model.reference_area(p));
        pressure.push_back(model.core_pressure(p));
        energy.push_back(model.elastic_energy(p));
    }
    data.point_vectors("velocity", points.velocity);
    data.point_vectors("force", points.force);
    data.point_scalars("contact_force", std::move(contact));
    data.point_scalars("hinge_torque", std::move(torque));
    data.point_scalars("plastic_ratio", std::move(plastic));
    data.cell_scalars("area_ratio", std::move(area_ratio));
    data.cell_ids("particle_id", std::move(ids));
    data.cell_scalars("core_pressure", std::move(pressure));
    data.cell_scalars("elastic_energy", std::move(energy));
    return data;
}

vtk::PolyData shell_walls(const ShellModel& model, const std::vector<int>& shells)
{
    vtk::PolyData data;
    ShellPoints points = add_shell_points(data, model, shells);
    std::vector<std::int64_t> ids;
    for (std::size_t k = 0; k < shells.size(); ++k) {
        std::vector<std::int64_t> line = points.cells[k];
        if (model.shells()[shells[k]].closed) line.push_back(line.front());
        data.add_line(line);
        ids.push_back(shells[k]);
    }
    data.point_vectors("velocity", points.velocity);
    data.point_vectors("force", points.force);
    data.cell_ids("wall_id", std::move(ids));
    return data;
}

vtk::PolyData shell_contacts(const ShellModel& model)
{
    vtk::PolyData data;
    std::vector<double> normal, tangential, force;
    std::vector<std::int64_t> vertex, particle, other;
    // The shell of each vertex, from the shells' ranges.
    std::vector<int> shell_of(static_cast<std::size_t>(model.vertices()), 0);
    for (std::size_t p = 0; p < model.shells().size(); ++p) {
        const Shell& s = model.shells()[p];
        for (int i = s.first; i < s.first + s.count; ++i)
            shell_of[static_cast<std::size_t>(i)] = static_cast<int>(p);
    }
    for (const ShellModel::ContactView& c : model.active_contacts()) {
        data.add_line({data.add_point(model.vertex(c.vertex)), data.add_point(c.point)});
        normal.push_back(c.normal_force);
        tangential.push_back(c.tangential_force);
        force.insert(force.end(), {c.force.x(), c.force.y(), 0.0});
        vertex.push_back(c.vertex);
        particle.push_back(shell_of[static_cast<std::size_t>(c.vertex)]);
        other.push_back(shell_of[static_cast<std::size_t>(c.a)]);
    }
    data.cell_scalars("normal_force", std::move(normal));
    data.cell_scalars("tangential_force", std::move(tangential));
    data.cell_vectors("force", std::move(force));
    data.cell_ids("vertex", std::move(vertex));
    data.cell_ids("particle", std::move(particle));
    data.cell_ids("other_particle", std::move(other));
    return data;
}

std::vector<vtk::Part> shell_frame(const ShellModel& model, const std::vector<int>& particles,
                                   const std::vector<int>& walls,
                                   const std::vector<std::pair<std::string, double>>& fields)
{
    std::vector<vtk::Part> parts{{"particles", shell_particles(model, particles)},
                                 {"walls", shell_walls(model, walls)},
                                 {"contacts", shell_contacts(model)}};
    for (auto& part : parts)
        for (const auto& [name, value] : fields)
            part.data.field(name, value);
    return parts;
}

} // namespace softgrain::spd
