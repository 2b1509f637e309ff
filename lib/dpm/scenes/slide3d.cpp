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
#include "core/errors.hpp"
#include "core/option_binding.hpp"
#include "core/output.hpp"
#include "dpm/analysis/vtk_frames.hpp"
#include "dpm/laws/interactions3d.hpp"
#include "dpm/scenes/scenes.hpp"
#include "dpm/system/system3d.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>

namespace softgrain::dpm {

namespace {

struct Slide3dOptions
{
    std::string mesh = "geodesic42"; // the slider's, mesh_from_name
    double radius = 2.0;             // [sigma]
    double spacing = 1.0;            // [sigma]
    double gap = 0.5;                // [sigma]
    double offset = 0.3;             // [sigma]
    double length = 2.0;             // [sigma]
    int steps = 200;
};

OptionBinding<Slide3dOptions> slide3d_binding()
{
    OptionBinding<Slide3dOptions> binding;
    binding.word(&Slide3dOptions::mesh, "mesh", {"icosahedron", "geodesic42", "geodesic162", "geodesic642"},
                 "surface mesh of the slider (vertex 0 turned down)");
    binding
        .real(&Slide3dOptions::radius, "radius", "sigma",
              "slider circumradius R (its vertices on this sphere)")
        .positive();
    binding
        .real(&Slide3dOptions::spacing, "spacing", "sigma",
              "distance of neighbouring vertices of the slab's top grid")
        .positive();
    binding
        .real(&Slide3dOptions::gap, "gap", "sigma",
              "height of the slider's lowest vertex above the slab's top plane (overlap sigma - "
              "gap)")
        .positive();
    binding.real(&Slide3dOptions::offset, "offset", "sigma",
                 "the path's offset in y from a grid line of the slab (0: over a row of vertices)");
    binding
        .real(&Slide3dOptions::length, "length", "sigma",
              "length of the path along x, centred on a slab vertex")
        .positive();
    binding.integer(&Slide3dOptions::steps, "steps", "1", "positions along the path minus one").at_least(2);
    return binding;
}

struct PathPoint
{
    double energy = 0;
    Eigen::Vector3d force = Eigen::Vector3d::Zero(); // on the slider (particle 1)
};

PathPoint evaluate(DpmSystem3d& system, InteractionKind kind, const Eigen::VectorXd& x)
{
    system.interaction = kind;
    Eigen::VectorXd gradient = Eigen::VectorXd::Zero(x.size());
    PathPoint point;
    point.energy = interaction_energy3d(system, x, &gradient, nullptr);
    const Particle3d& slider = system.particles[1];
    point.force =
        -gradient.segment(3 * slider.first, 3 * slider.count).reshaped(3, slider.count).rowwise().sum();
    return point;
}

// One position of the path: the slider centre x along it, both interactions, and the smooth half of the
// slider's vertices against the slab's surface.
struct SlideSample
{
    double along = 0;
    PathPoint rough, smooth;
    double slider_half = 0;
};

struct Slide3dResult
{
    std::vector<SlideSample> path;
    double plane_half = 0; // the smooth slider half on a plane, from the vertex heights alone
    int slider_vertices = 0, slab_vertices = 0;
};

using SlideFrame = std::function<void(const DpmSystem3d&, const Eigen::VectorXd&, const SlideSample&)>;

// The slider moved along the path, each position handed to `frame` (ParaView).
Slide3dResult slide(const Slide3dOptions& options, const SlideFrame& frame)
{
    const double sigma = 1.0;
    DpmSystem3d system;
    system.kc = 1.0;
    // The slab reaches beyond the path by the slider's radius and two grid squares (the rim far away).
    const int n =
        2 * static_cast<int>(std::ceil((0.5 * options.length + options.radius + std::abs(options.offset)) /
                                       options.spacing)) +
        5;
    system.meshes.push_back(slab_mesh(n, options.spacing, 2 * sigma));
    const TriangleMesh ball = vertex_down(mesh_from_name(options.mesh));
    system.meshes.push_back(ball);
    Eigen::VectorXd x;
    system.add_particle(0, system.meshes[0].vertices, sigma, ShapeParameters3d{}, x);
    const Eigen::Matrix3Xd slider = options.radius * ball.vertices;
    system.add_particle(1, slider, sigma, ShapeParameters3d{}, x);
    const double top = sigma; // the slab's top face, z = thickness/2
    const auto place = [&](double along) {
        const Eigen::Vector3d centre(along, options.offset, top + options.gap + options.radius);
        x.segment(3 * system.particles[1].first, 3 * slider.cols()) = (slider.colwise() + centre).reshaped();
    };

    Slide3dResult result;
    result.slider_vertices = static_cast<int>(slider.cols());
    result.slab_vertices = system.meshes[0].vertex_count();
    // The smooth slider half on a plane, from the vertex heights alone (decision
    // dpm-3d-smooth-inclusion-exclusion).
    for (Eigen::Index v = 0; v < slider.cols(); ++v) {
        const double height = options.gap + options.radius + slider(2, v);
        if (height < sigma) result.plane_half += 0.5 * 0.5 * system.kc * (sigma - height) * (sigma - height);
    }
    for (int k = 0; k <= options.steps; ++k) {
        SlideSample sample;
        sample.along = -0.5 * options.length + options.length * k / options.steps;
        place(sample.along);
        sample.rough = evaluate(system, InteractionKind::rough, x);
        sample.smooth = evaluate(system, InteractionKind::smooth, x);
        sample.slider_half = smooth_vertex_surface_energy3d(system, 1, 0, x);
        if (sample.rough.force.z() <= 0 || sample.smooth.force.z() <= 0)
            throw InputError("gap = " + std::to_string(options.gap) +
                             ": the slider loses contact on the path; allowed gap below sigma minus the "
                             "depth of the slab's vertex lattice under the slider");
        result.path.push_back(sample);
        frame(system, x, sample);
    }
    return result;
}

// ParaView: the slab (particle_id 0) and the slider (1) as their meshes at one position of the path, force
// -dU/dx of the smooth interaction (the slab's force on the slider's vertices and back), volume_ratio 1 (both
// rigid: v0 their own volume); field data x (the slider centre), U and F_x/F_z of both interactions.
std::vector<vtk::Part> slide_frame(const DpmSystem3d& system, const Eigen::VectorXd& x,
                                   const SlideSample& sample)
{
    DpmSystem3d contact = system;
    contact.interaction = InteractionKind::smooth;
    Eigen::VectorXd gradient = Eigen::VectorXd::Zero(x.size());
    interaction_energy3d(contact, x, &gradient, nullptr);
    std::vector<MeshParticle> bodies;
    for (const Particle3d& particle : system.particles) {
        const TriangleMesh& mesh = system.meshes[static_cast<std::size_t>(particle.mesh)];
        bodies.push_back({&mesh, particle.first, particle.sigma, mesh_volume(mesh, x, particle.first),
                          Eigen::Vector3d::Zero()});
    }
    vtk::PolyData particles = mesh_particles(bodies, x, gradient);
    particles.field("x", sample.along);
    particles.field("U_rough", sample.rough.energy);
    particles.field("U_smooth", sample.smooth.energy);
    particles.field("mu_rough", sample.rough.force.x() / sample.rough.force.z());
    particles.field("mu_smooth", sample.smooth.force.x() / sample.smooth.force.z());
    return {{"particles", std::move(particles)}};
}

// (max - min)/mean of a series (0 for a constant one).
double corrugation(const std::vector<double>& series)
{
    double mean = 0;
    for (double value : series)
        mean += value / series.size();
    return (*std::max_element(series.begin(), series.end()) -
            *std::min_element(series.begin(), series.end())) /
           mean;
}

double mean(const std::vector<double>& series)
{
    return std::accumulate(series.begin(), series.end(), 0.0) / series.size();
}

// The largest |F_x/F_z| on the slider along the path.
double largest_friction_ratio(const std::vector<SlideSample>& path, PathPoint SlideSample::*interaction)
{
    double largest = 0;
    for (const SlideSample& sample : path) {
        const PathPoint& point = sample.*interaction;
        largest = std::max(largest, std::abs(point.force.x() / point.force.z()));
    }
    return largest;
}

void report_slide3d(const Slide3dResult& result, RunContext& context)
{
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
    std::vector<double> rough, smooth, slider_half;
    for (const SlideSample& sample : result.path) {
        const PathPoint &rough_point = sample.rough, &smooth_point = sample.smooth;
        rough.push_back(rough_point.energy);
        smooth.push_back(smooth_point.energy);
        slider_half.push_back(sample.slider_half);
        table.row({sample.along, rough_point.energy, smooth_point.energy, sample.slider_half,
                   smooth_point.energy - sample.slider_half, rough_point.force.x() / rough_point.force.z(),
                   smooth_point.force.x() / smooth_point.force.z()});
    }
    auto& summary = context.summary();
    summary["rough_corrugation"] = corrugation(rough);
    summary["smooth_corrugation"] = corrugation(smooth);
    summary["smooth_slider_half_corrugation"] = corrugation(slider_half);
    summary["smooth_slider_half_mean"] = mean(slider_half);
    summary["smooth_slider_half_plane"] = result.plane_half;
    summary["rough_energy_mean"] = mean(rough);
    summary["smooth_energy_mean"] = mean(smooth);
    summary["rough_mu_max"] = largest_friction_ratio(result.path, &SlideSample::rough);
    summary["smooth_mu_max"] = largest_friction_ratio(result.path, &SlideSample::smooth);
    summary["slider_vertices"] = result.slider_vertices;
    summary["slab_vertices"] = result.slab_vertices;
}

void run_slide3d(const Slide3dOptions& options, RunContext& context)
{
    // ParaView: every 10th position (--vtk-every N: every N-th), time value x [sigma].
    const auto frame = [&context](const DpmSystem3d& system, const Eigen::VectorXd& x,
                                  const SlideSample& sample) {
        if (context.vtk() && context.vtk()->next(10))
            context.vtk()->write(sample.along, slide_frame(system, x, sample));
    };
    report_slide3d(slide(options, frame), context);
}

} // namespace

Scene slide3d_scene()
{
    return bound_scene(
               "dpm.slide3d",
               "DPM sec. 9.3.2 in 3D: a rigid 3D particle slid over a flat slab at fixed height, "
               "energy and F_x/F_z along the path for rough (vertex spheres) and smooth (vertex-face) "
               "contacts",
               slide3d_binding(), run_slide3d)
        .with_vtk();
}

} // namespace softgrain::dpm
