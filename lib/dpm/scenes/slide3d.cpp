// dpm.slide3d: friction-free sliding in 3D, rough against smooth contacts (DPM sec. 9.3.2-9.3.3 carried to
// 3D; the 2D test is Fig. 9.8). A rigid slider, a geodesic sphere of radius R with a vertex pointing down,
// is translated parallel to a flat slab (slab_mesh: the top a square grid of vertices `spacing` apart) at a
// fixed height: its lowest vertex `gap` above the top plane (gap < sigma: overlap sigma - gap). Nothing
// relaxes, so the energy along the path is the contact law's own landscape. At each position: U rough
// (vertex spheres, eqs. 9.3-9.4 in 3D) and U smooth (vertex against faces, interactions3d.hpp) split into
// its two ordered halves (the slider's vertices against the slab's surface; the slab's vertices against
// the slider's surface), and the force on the slider, F_x along the path and F_z normal to the slab.
// Units: sigma = 1 (vertex diameter, both particles), k_c = 1; energies k_c sigma^2, forces k_c sigma.
// A flat face makes the first smooth half independent of the position (decision
// dpm-3d-smooth-inclusion-exclusion): 1/2 sum_i k_c/2 (sigma - h_i)^2 over the slider's vertex heights h_i.
#include "dpm/slide3d_scene.hpp"

#include "core/errors.hpp"
#include "core/output.hpp"
#include "dpm/interactions3d.hpp"
#include "dpm/system3d.hpp"
#include "dpm/vtk_frames.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numeric>

namespace softgrain::dpm {

namespace {

struct PathPoint
{
    double energy = 0;
    Eigen::Vector3d force = Eigen::Vector3d::Zero(); // on the slider (particle 1)
};

PathPoint evaluate(DpmSystem3d& s, InteractionKind kind, const Eigen::VectorXd& x)
{
    s.interaction = kind;
    Eigen::VectorXd g = Eigen::VectorXd::Zero(x.size());
    PathPoint out;
    out.energy = interaction_energy3d(s, x, &g, nullptr);
    const Particle3d& slider = s.particles[1];
    out.force = -g.segment(3 * slider.first, 3 * slider.count).reshaped(3, slider.count).rowwise().sum();
    return out;
}

// ParaView: the slab (particle_id 0) and the slider (1) as their meshes at one position of the path, force
// -dU/dx of the smooth interaction (the slab's force on the slider's vertices and back), volume_ratio 1 (both
// rigid: v0 their own volume); field data x (the slider centre), U and F_x/F_z of both interactions.
std::vector<vtk::Part> slide_frame(const DpmSystem3d& s, const Eigen::VectorXd& x, double along,
                                   const PathPoint& rough, const PathPoint& smooth)
{
    DpmSystem3d contact = s;
    contact.interaction = InteractionKind::smooth;
    Eigen::VectorXd gradient = Eigen::VectorXd::Zero(x.size());
    interaction_energy3d(contact, x, &gradient, nullptr);
    std::vector<MeshParticle> bodies;
    for (const Particle3d& p : s.particles) {
        const TriangleMesh& mesh = s.meshes[static_cast<std::size_t>(p.mesh)];
        bodies.push_back({&mesh, p.first, p.sigma, mesh_volume(mesh, x, p.first), Eigen::Vector3d::Zero()});
    }
    vtk::PolyData particles = mesh_particles(bodies, x, gradient);
    particles.field("x", along);
    particles.field("U_rough", rough.energy);
    particles.field("U_smooth", smooth.energy);
    particles.field("mu_rough", rough.force.x() / rough.force.z());
    particles.field("mu_smooth", smooth.force.x() / smooth.force.z());
    return {{"particles", std::move(particles)}};
}

// (max - min)/mean of a series (0 for a constant one).
double corrugation(const std::vector<double>& v)
{
    double mean = 0;
    for (double e : v)
        mean += e / v.size();
    return (*std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end())) / mean;
}

double largest_ratio(const std::vector<double>& num, const std::vector<double>& den)
{
    double m = 0;
    for (std::size_t k = 0; k < num.size(); ++k)
        m = std::max(m, std::abs(num[k] / den[k]));
    return m;
}

} // namespace

void run_slide3d(const Parameters& p, RunContext& context)
{
    const double radius = p.real("radius"), spacing = p.real("spacing"), gap = p.real("gap"),
                 offset = p.real("offset"), length = p.real("length");
    const int steps = static_cast<int>(p.integer("steps"));
    const double sigma = 1.0;
    DpmSystem3d s;
    s.kc = 1.0;
    // The slab reaches beyond the path by the slider's radius and two grid squares (the rim far away).
    const int n = 2 * static_cast<int>(std::ceil((0.5 * length + radius + std::abs(offset)) / spacing)) + 5;
    s.meshes.push_back(slab_mesh(n, spacing, 2 * sigma));
    TriangleMesh ball = mesh_from_name(p.choice("mesh"));
    // Vertex 0 down.
    ball.vertices = Eigen::Quaterniond::FromTwoVectors(ball.vertices.col(0), -Eigen::Vector3d::UnitZ())
                        .toRotationMatrix() *
                    ball.vertices;
    s.meshes.push_back(ball);
    Eigen::VectorXd x;
    s.add_particle(0, s.meshes[0].vertices, sigma, ShapeParameters3d{}, x);
    const Eigen::Matrix3Xd slider = radius * ball.vertices;
    s.add_particle(1, slider, sigma, ShapeParameters3d{}, x);
    const double top = sigma; // the slab's top face, z = thickness/2
    const auto place = [&](double along) {
        const Eigen::Vector3d centre(along, offset, top + gap + radius);
        x.segment(3 * s.particles[1].first, 3 * slider.cols()) = (slider.colwise() + centre).reshaped();
    };

    // The smooth slider half on a plane, from the vertex heights alone (decision
    // dpm-3d-smooth-inclusion-exclusion).
    double plane_half = 0;
    for (Eigen::Index v = 0; v < slider.cols(); ++v) {
        const double h = gap + radius + slider(2, v);
        if (h < sigma) plane_half += 0.5 * 0.5 * s.kc * (sigma - h) * (sigma - h);
    }

    auto& table = context.table(
        "path.dat",
        {{"x", "sigma",
          "slider centre along the path (0: lowest vertex above a slab vertex when offset = 0)"},
         {"U_rough", "k_c sigma^2", "rough interaction energy (vertex spheres)"},
         {"U_smooth", "k_c sigma^2", "smooth interaction energy (vertex against faces, both halves)"},
         {"U_smooth_slider", "k_c sigma^2", "smooth half: slider vertices against the slab's surface"},
         {"U_smooth_slab", "k_c sigma^2", "smooth half: slab vertices against the slider's surface"},
         {"mu_rough", "1", "F_x/F_z on the slider, rough"},
         {"mu_smooth", "1", "F_x/F_z on the slider, smooth"}});
    std::vector<double> rough, smooth, slider_half, rough_fx, rough_fz, smooth_fx, smooth_fz;
    for (int k = 0; k <= steps; ++k) {
        const double along = -0.5 * length + length * k / steps;
        place(along);
        const PathPoint r = evaluate(s, InteractionKind::rough, x),
                        m = evaluate(s, InteractionKind::smooth, x);
        const double half = smooth_vertex_surface_energy3d(s, 1, 0, x);
        if (r.force.z() <= 0 || m.force.z() <= 0)
            throw InputError("gap = " + std::to_string(gap) +
                             ": the slider loses contact on the path; allowed gap below sigma minus the "
                             "depth of the slab's vertex lattice under the slider");
        rough.push_back(r.energy);
        smooth.push_back(m.energy);
        slider_half.push_back(half);
        rough_fx.push_back(r.force.x());
        rough_fz.push_back(r.force.z());
        smooth_fx.push_back(m.force.x());
        smooth_fz.push_back(m.force.z());
        table.row({along, r.energy, m.energy, half, m.energy - half, r.force.x() / r.force.z(),
                   m.force.x() / m.force.z()});
        // ParaView: every 10th position (--vtk-every N: every N-th), time value x [sigma].
        if (context.vtk() && context.vtk()->next(10))
            context.vtk()->write(along, slide_frame(s, x, along, r, m));
    }
    auto& out = context.summary();
    out["rough_corrugation"] = corrugation(rough);
    out["smooth_corrugation"] = corrugation(smooth);
    out["smooth_slider_half_corrugation"] = corrugation(slider_half);
    out["smooth_slider_half_mean"] =
        std::accumulate(slider_half.begin(), slider_half.end(), 0.0) / slider_half.size();
    out["smooth_slider_half_plane"] = plane_half;
    out["rough_energy_mean"] = std::accumulate(rough.begin(), rough.end(), 0.0) / rough.size();
    out["smooth_energy_mean"] = std::accumulate(smooth.begin(), smooth.end(), 0.0) / smooth.size();
    out["rough_mu_max"] = largest_ratio(rough_fx, rough_fz);
    out["smooth_mu_max"] = largest_ratio(smooth_fx, smooth_fz);
    out["slider_vertices"] = static_cast<int>(slider.cols());
    out["slab_vertices"] = s.meshes[0].vertex_count();
}

std::vector<ParameterSpec> slide3d_parameters()
{
    return {
        ParameterSpec::choice("mesh", "geodesic42",
                              {"icosahedron", "geodesic42", "geodesic162", "geodesic642"},
                              "surface mesh of the slider (vertex 0 turned down)"),
        ParameterSpec::real("radius", 2.0, "sigma", "slider circumradius R (its vertices on this sphere)")
            .positive(),
        ParameterSpec::real("spacing", 1.0, "sigma",
                            "distance of neighbouring vertices of the slab's top grid")
            .positive(),
        ParameterSpec::real(
            "gap", 0.5, "sigma",
            "height of the slider's lowest vertex above the slab's top plane (overlap sigma - "
            "gap)")
            .positive(),
        ParameterSpec::real(
            "offset", 0.3, "sigma",
            "the path's offset in y from a grid line of the slab (0: over a row of vertices)"),
        ParameterSpec::real("length", 2.0, "sigma", "length of the path along x, centred on a slab vertex")
            .positive(),
        ParameterSpec::integer("steps", 200, "1", "positions along the path minus one").at_least(2),
    };
}

} // namespace softgrain::dpm
