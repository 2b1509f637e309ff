#include "dpm/protocols/jam3d.hpp"

#include "core/errors.hpp"
#include "core/rng.hpp"
#include "dpm/protocols/jam_schedule.hpp"

#include <Eigen/Geometry>
#include <cmath>

namespace softgrain::dpm {

namespace {

double mean_edge_length(const TriangleMesh& mesh)
{
    double sum = 0;
    for (const MeshEdge& e : mesh.edges)
        sum += (mesh.vertices.col(e.a) - mesh.vertices.col(e.b)).norm();
    return sum / mesh.edge_count();
}

// A rotation from the normalised 4-vector of seeded normal deviates (uniform on SO(3)).
Eigen::Matrix3d random_rotation(Rng& rng)
{
    Eigen::Quaterniond q(rng.normal(1), rng.normal(1), rng.normal(1), rng.normal(1));
    q.normalize();
    return q.toRotationMatrix();
}

// Random centres in the box, each at least R_a + R_b + sigma from the others (minimum image).
std::vector<Eigen::Vector3d> random_centres(const std::vector<double>& radii, double L, Rng& rng)
{
    std::vector<Eigen::Vector3d> centres;
    for (double r : radii) {
        for (int tries = 0;; ++tries) {
            if (tries > 100000)
                throw InputError("start_fraction: no room for the particles at the random start; lower it");
            const Eigen::Vector3d c(rng.uniform(0, L), rng.uniform(0, L), rng.uniform(0, L));
            bool free = true;
            for (std::size_t q = 0; q < centres.size() && free; ++q) {
                const Eigen::Vector3d d = c - centres[q];
                free = (d - L * (d / L).array().round().matrix()).norm() >= r + radii[q] + 1.0;
            }
            if (free) {
                centres.push_back(c);
                break;
            }
        }
    }
    return centres;
}

} // namespace

Jam3dResult jam3d(const Jam3dOptions& options)
{
    if (options.particles < 2 || options.particles % 2)
        throw InputError("particles = " + std::to_string(options.particles) +
                         ": allowed an even number >= 2");
    Jam3dResult out;
    DpmSystem3d& s = out.system;
    s.kc = 1.0;
    s.interaction = options.interaction;
    s.meshes.push_back(mesh_from_name(options.mesh));
    const TriangleMesh& unit = s.meshes[0]; // vertices on the unit sphere

    // Small particles: mean edge 0.85 sigma; large: size_ratio times in diameter (decision
    // dpm-3d-jam-packing).
    const double r_small = 0.85 / mean_edge_length(unit);
    const Eigen::VectorXd small_x = r_small * mesh_coordinates(unit);
    const double v0 = mesh_volume(unit, small_x, 0);
    const double kv = 1.0 / (v0 * v0); // k_v v0^2 = k_c sigma^2
    out.length_unit = std::cbrt(v0);
    out.energy_unit = kv * v0 * v0;
    out.pressure_unit = kv * v0;
    out.eigenvalue_unit = kv * std::pow(v0, 4.0 / 3.0);
    Stiffness3d k;
    k.ka = options.stiffness.ka * kv * std::pow(v0, 2.0 / 3.0);
    k.kb = options.stiffness.kb * kv * v0 * v0;
    k.gamma = options.stiffness.gamma * kv * std::pow(v0, 5.0 / 3.0);
    const auto rest_shape = [&](double r) {
        const Eigen::VectorXd xr = r * mesh_coordinates(unit);
        const double A_mesh = mesh_shape_parameter3d(unit, xr, 0);
        return model_shape3d(options.model, unit, xr,
                             options.model == ShapeModel::floppy ? options.A0_floppy : A_mesh, kv, k);
    };
    const ShapeParameters3d small_shape = rest_shape(r_small),
                            large_shape = rest_shape(options.size_ratio * r_small);

    std::vector<double> radii;
    double boxes = 0;
    for (int m = 0; m < options.particles; ++m) {
        radii.push_back(m < options.particles / 2 ? r_small : options.size_ratio * r_small);
        boxes += std::pow(2 * radii.back() + 1.0, 3);
    }
    const double L = std::cbrt(boxes / options.start_fraction);
    s.box = L;
    Rng rng(options.seed);
    const std::vector<Eigen::Vector3d> centres = random_centres(radii, L, rng);
    for (int m = 0; m < options.particles; ++m) {
        const Eigen::Matrix3Xd v = (radii[m] * random_rotation(rng) * unit.vertices).colwise() + centres[m];
        s.add_particle(0, v, 1.0, m < options.particles / 2 ? small_shape : large_shape, out.x);
    }

    // FIRE: time step from the stiffest mode at the start (as in 2D), tolerance 1e-4 P_t (in k_c sigma).
    FireOptions& fire = out.fire;
    const double stiffest = std::max(s.kc, largest_eigenvalue3d(s, out.x, options.hessian));
    fire.dt_max = std::min(0.5, options.fire_step / std::sqrt(stiffest));
    fire.dt_initial = 0.25 * fire.dt_max;
    fire.force_tolerance = 1e-4 * options.pressure_onset * out.pressure_unit;
    fire.max_iterations = options.fire_budget;
    const RelaxOptions relax_options{options.relaxation, fire};
    const auto relax = [&](long step_index) {
        const RelaxResult r = dpm::relax(s, out.x, relax_options);
        out.add(r);
        if (!r.converged)
            throw NumericalError(
                "relaxation during 3D compression (" + relax_shortfall(r, relax_options) + ")", step_index,
                "force tolerance too small for the pressure; raise pressure_onset or "
                "fire_budget");
        return r.fire_iterations;
    };
    const auto current_pressure = [&] { return pressure3d(stress_tensor3d(s, out.x)) / out.pressure_unit; };
    relax(0);

    // Saddle test and move: energy amplitudes up to 0.1 sigma (sigma = 1), as in the diagnosis of the
    // 16 x 42 shell packing (decision dpm-packing-minimum).
    const std::function<bool()> leave_saddle = [&] {
        return leave_saddle3d(s, out.x, out.pressure_unit, out.eigenvalue_unit, options.zero_threshold, 0.1,
                              options.hessian);
    };

    BoxSchedule schedule;
    schedule.onset = options.pressure_onset;
    schedule.jump_step = options.jump_step;
    Eigen::VectorXd saved_x;
    double saved_box = L;
    const CompressiblePacking packing{current_pressure,
                                      [&](double f) { scale_packing3d(s, out.x, f); },
                                      relax,
                                      [&] {
                                          saved_x = out.x;
                                          saved_box = *s.box;
                                      },
                                      [&] {
                                          out.x = saved_x;
                                          *s.box = saved_box;
                                      },
                                      leave_saddle};
    for (double target : pressure_targets(options.pressure_onset, options.pressure_max, options.pressures)) {
        reach_stable_pressure(target, schedule, packing, options.saddle_escapes, out.saddle_escapes);
        out.states.push_back({packing_fraction3d(s, out.x), current_pressure(), out.x, *s.box});
        if (out.states.size() == 1) out.box_steps = schedule.step_index;
    }
    out.window_jumps = schedule.jumps;
    const Jam3dState& onset = out.states.front();
    out.x = onset.x;
    *s.box = onset.box;
    out.phi = onset.phi;
    out.pressure = onset.pressure;
    return out;
}

MemoryEstimate packing3d_memory(double particles, const std::string& mesh, HessianStorage storage,
                                int dense_matrices)
{
    const double mesh_vertices = mesh_from_name(mesh).vertex_count();
    const double n = 3 * particles * mesh_vertices;
    const std::string what = "3 x particles x mesh vertices";
    // The protocol's Hessian (packing_hessian3d.hpp). Dense: M and the eigensolver's n x n workspace (its
    // eigenvectors). Sparse: the volume term of eq. (9.2) couples every pair of a particle's vertices, so M
    // has at least (3 N_mu)^2 non-zeros per particle (measured: 127 188 for 8 x 42, 8 x 126^2 = 127 008),
    // each held as an assembly triplet (16 B), in M (12 B) and in the lower half of its LDL^T factor (6 B).
    const MemoryEstimate protocol =
        !uses_sparse_hessian(storage, static_cast<Eigen::Index>(n))
            ? dense_matrix_memory(n, 2, what)
            : per_item_memory(particles * std::pow(3 * mesh_vertices, 2), 34.0,
                              "sparse Hessian non-zeros, particles x (3 x mesh vertices)^2");
    if (dense_matrices == 0) return protocol;
    const MemoryEstimate after = dense_matrix_memory(n, dense_matrices, what);
    return after.bytes > protocol.bytes ? after : protocol;
}

} // namespace softgrain::dpm
