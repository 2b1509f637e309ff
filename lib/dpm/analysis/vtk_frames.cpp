#include "dpm/analysis/vtk_frames.hpp"

#include "dpm/laws/interactions.hpp"
#include "dpm/laws/shape_energy.hpp"
#include "dpm/laws/shape_energy3d.hpp"

#include <cmath>
#include <set>

namespace softgrain::dpm {

namespace {

// The shift by whole periods that moves point p into the drawn box: [0, L_x) x [0, L_y), or under a
// Lees-Edwards strain gamma the parallelogram spanned by a = (L_x, 0) and b = (gamma L_y, L_y), the lattice
// of the periodic images (the image above is shifted by gamma L_y); p = s a + t b. Zero without a box.
Eigen::Vector2d shift_into_box(const DpmSystem& system, const Eigen::Vector2d& p)
{
    if (!system.box) return Eigen::Vector2d::Zero();
    const Eigen::Vector2d& L = *system.box;
    const double gamma = system.lees_edwards_strain;
    const double t = std::floor(p.y() / L.y()), s = std::floor((p.x() - gamma * p.y()) / L.x());
    return -s * Eigen::Vector2d(L.x(), 0) - t * Eigen::Vector2d(gamma * L.y(), L.y());
}

} // namespace

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
        const Eigen::Vector2d shift = shift_into_box(system, centre);
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

std::vector<double> vertex_vectors(const Eigen::VectorXd& u)
{
    std::vector<double> xyz;
    xyz.reserve(static_cast<std::size_t>(3 * u.size() / 2));
    for (Eigen::Index v = 0; v < u.size() / 2; ++v)
        xyz.insert(xyz.end(), {u(2 * v), u(2 * v + 1), 0.0});
    return xyz;
}

vtk::PolyData dpm_contacts(const DpmSystem& system, const Eigen::VectorXd& x)
{
    vtk::PolyData data;
    std::vector<double> normal_force, tangential_force, force;
    std::vector<std::int64_t> first, second;
    const auto centre = [&](const Particle& p) {
        Eigen::Vector2d c = Eigen::Vector2d::Zero();
        for (int v = p.first; v < p.first + p.count; ++v)
            c += x.segment<2>(2 * v) / p.count;
        return c;
    };
    // Candidate particle pairs (m < b) from the contact list: every touching pair has a listed vertex pair.
    std::set<std::pair<int, int>> candidates;
    if (!system.particles.empty()) {
        const std::shared_ptr<const ContactList> list = system.contacts.list(system, x);
        for (const VertexPair& p : list->pairs())
            candidates.insert({list->particle_of(p.i), list->particle_of(p.neighbour.j)});
    }
    // The pair alone: a system of the two particles (b shifted to its nearest image of m), same interaction.
    DpmSystem pair;
    pair.interaction = system.interaction;
    pair.kc = system.kc;
    for (const auto& [m, b] : candidates) {
        const Particle &pm = system.particles[m], &pb = system.particles[b];
        const Eigen::Vector2d cm = centre(pm), d = system.image(centre(pb) - cm), shift = cm + d - centre(pb);
        pair.particles = {pm, pb};
        pair.particles[0].first = 0;
        pair.particles[1].first = pm.count;
        Eigen::VectorXd local(2 * (pm.count + pb.count));
        local << x.segment(2 * pm.first, 2 * pm.count), x.segment(2 * pb.first, 2 * pb.count);
        for (int v = pm.count; v < pm.count + pb.count; ++v)
            local.segment<2>(2 * v) += shift;
        Eigen::VectorXd gradient = Eigen::VectorXd::Zero(local.size());
        if (interaction_energy(pair, local, &gradient, nullptr) <= 0) continue; // not touching
        Eigen::Vector2d f = Eigen::Vector2d::Zero();
        for (int v = 0; v < pm.count; ++v)
            f -= gradient.segment<2>(2 * v);
        const Eigen::Vector2d n = d.normalized();
        const Eigen::Vector2d wrap = shift_into_box(system, cm);
        data.add_line({data.add_point(cm + wrap), data.add_point(cm + d + wrap)});
        normal_force.push_back(-f.dot(n));
        tangential_force.push_back((f - f.dot(n) * n).norm());
        force.insert(force.end(), {f.x(), f.y(), 0.0});
        first.push_back(m);
        second.push_back(b);
    }
    data.cell_scalars("normal_force", std::move(normal_force));
    data.cell_scalars("tangential_force", std::move(tangential_force));
    data.cell_vectors("force", std::move(force));
    data.cell_ids("particle", std::move(first));
    data.cell_ids("other_particle", std::move(second));
    return data;
}

vtk::PolyData box_outline(const Eigen::Vector2d& box, double lees_edwards_strain)
{
    vtk::PolyData data;
    const double top_shift = lees_edwards_strain * box.y();
    const std::int64_t a = data.add_point(0, 0), b = data.add_point(box.x(), 0),
                       c = data.add_point(box.x() + top_shift, box.y()),
                       d = data.add_point(top_shift, box.y());
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

vtk::PolyData mesh_particles(const std::vector<MeshParticle>& particles, const Eigen::VectorXd& x,
                             const Eigen::VectorXd& gradient)
{
    vtk::PolyData data;
    std::vector<double> radius, force, volume_ratio;
    std::vector<std::int64_t> ids;
    for (std::size_t k = 0; k < particles.size(); ++k) {
        const MeshParticle& p = particles[k];
        const std::int64_t base = data.points();
        for (int v = p.first; v < p.first + p.mesh->vertex_count(); ++v) {
            const Eigen::Vector3d r = x.segment<3>(3 * v) + p.shift;
            data.add_point(r.x(), r.y(), r.z());
            radius.push_back(0.5 * p.sigma);
            force.insert(force.end(), {-gradient(3 * v), -gradient(3 * v + 1), -gradient(3 * v + 2)});
        }
        const double ratio = mesh_volume(*p.mesh, x, p.first) / p.v0;
        for (const auto& face : p.mesh->faces) {
            data.add_polygon({base + face[0], base + face[1], base + face[2]});
            ids.push_back(static_cast<std::int64_t>(k));
            volume_ratio.push_back(ratio);
        }
    }
    data.point_scalars("radius", std::move(radius));
    data.point_vectors("force", std::move(force));
    data.cell_ids("particle_id", std::move(ids));
    data.cell_scalars("volume_ratio", std::move(volume_ratio));
    return data;
}

vtk::PolyData dpm_particles3d(const DpmSystem3d& system, const Eigen::VectorXd& x)
{
    Eigen::VectorXd gradient = Eigen::VectorXd::Zero(x.size());
    total_energy3d(system, x, &gradient, nullptr);
    std::vector<MeshParticle> particles;
    for (const Particle3d& p : system.particles) {
        MeshParticle m{&system.meshes[static_cast<std::size_t>(p.mesh)], p.first, p.sigma, p.shape.v0,
                       Eigen::Vector3d::Zero()};
        if (system.box) {
            const Eigen::Vector3d centre = system.vertices(p, x).rowwise().mean();
            m.shift = -*system.box * (centre / *system.box).array().floor().matrix();
        }
        particles.push_back(m);
    }
    return mesh_particles(particles, x, gradient);
}

vtk::PolyData spring_network_body(const SpringNetwork& network, const Eigen::VectorXd& x)
{
    vtk::PolyData body;
    const int d = network.dim;
    // Cells: the nodes (vertex cells) first, then the springs (lines); spring_strain is NaN on the nodes.
    for (int v = 0; v < network.node_count(); ++v)
        body.add_vertex(body.add_point(x(d * v), x(d * v + 1), d == 3 ? x(d * v + 2) : 0.0));
    std::vector<double> strain(static_cast<std::size_t>(network.node_count()), NAN);
    for (const Spring& spring : network.springs) {
        body.add_line({spring.i, spring.j});
        strain.push_back(
            (x.segment(d * spring.j, d) - x.segment(d * spring.i, d)).norm() / spring.rest_length - 1);
    }
    body.point_scalars("radius", std::vector<double>(static_cast<std::size_t>(network.node_count()), 0.5));
    body.cell_scalars("spring_strain", std::move(strain));
    return body;
}

vtk::PolyData box_outline3d(double L)
{
    vtk::PolyData data;
    for (int c = 0; c < 8; ++c)
        data.add_point(L * (c & 1), L * ((c >> 1) & 1), L * ((c >> 2) & 1));
    for (int c = 0; c < 8; ++c)
        for (const int bit : {1, 2, 4})
            if (!(c & bit)) data.add_line({c, c | bit});
    return data;
}

vtk::PolyData plates3d(const Eigen::Vector2d& low, const Eigen::Vector2d& high, double z_bottom, double z_top)
{
    vtk::PolyData data;
    for (const double z : {z_bottom, z_top})
        data.add_polygon({data.add_point(low.x(), low.y(), z), data.add_point(high.x(), low.y(), z),
                          data.add_point(high.x(), high.y(), z), data.add_point(low.x(), high.y(), z)});
    data.cell_ids("plate_id", {0, 1});
    return data;
}

} // namespace softgrain::dpm
