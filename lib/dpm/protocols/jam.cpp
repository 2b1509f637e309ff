#include "dpm/protocols/jam.hpp"

#include "core/errors.hpp"
#include "core/fits.hpp"
#include "core/rng.hpp"
#include "dpm/analysis/modes.hpp"
#include "dpm/analysis/packing_fraction.hpp"
#include "dpm/analysis/stress.hpp"
#include "dpm/protocols/jam_schedule.hpp"
#include "dpm/relax/rigid.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace softgrain::dpm {

const std::vector<std::pair<std::string, JamModel>>& jam_model_names()
{
    static const std::vector<std::pair<std::string, JamModel>> names{
        {"smooth_disk", JamModel::smooth_disk},
        {"rough_disk", JamModel::rough_disk},
        {"shell", JamModel::shell},
        {"floppy", JamModel::floppy},
        {"surface_tension", JamModel::surface_tension}};
    return names;
}

std::string jam_model_name(JamModel model)
{
    for (const auto& [name, value] : jam_model_names())
        if (value == model) return name;
    throw std::logic_error("jam_model_name: not a JamModel");
}

std::optional<ShapeModel> shape_model(JamModel model)
{
    switch (model) {
    case JamModel::smooth_disk:
    case JamModel::rough_disk:
        return std::nullopt;
    case JamModel::shell:
        return ShapeModel::shell;
    case JamModel::floppy:
        return ShapeModel::floppy;
    case JamModel::surface_tension:
        return ShapeModel::surface_tension;
    }
    throw std::logic_error("shape_model: not a JamModel");
}

JamModel jam_model(ShapeModel model)
{
    switch (model) {
    case ShapeModel::shell:
        return JamModel::shell;
    case ShapeModel::floppy:
        return JamModel::floppy;
    case ShapeModel::surface_tension:
        return JamModel::surface_tension;
    }
    throw std::logic_error("jam_model: not a ShapeModel");
}

double packing_fraction(const DpmSystem& system, const Eigen::VectorXd& x)
{
    bool disks = true;
    for (const Particle& p : system.particles)
        disks = disks && p.count == 1;
    if (!disks) return packing_areas_analytic(system, x).phi;
    double area = 0;
    for (const Particle& p : system.particles)
        area += 0.25 * std::numbers::pi * p.sigma * p.sigma;
    return area / system.box->prod();
}

namespace {

// Floppy particles need A0 >= A_min(N) of each size the packing has (no N-gon has a smaller shape parameter,
// Table 9.1). The one check of it: the scenes bind A0 with its range (>= 1) only, since A_min depends on
// nodes_small and nodes_large, and library callers reach jam() directly. The small particles come first.
void require_floppy_A0(const JamOptions& options)
{
    if (options.model != JamModel::floppy) return;
    const int small = options.particles / 2;
    for (const auto& [n, present] : {std::pair{options.nodes_small, small > 0},
                                     std::pair{options.nodes_large, options.particles > small}})
        if (present && options.A0_floppy < minimum_shape_parameter(n))
            throw InputError("A0 = " + std::to_string(options.A0_floppy) +
                             " of the floppy particles is below A_min(" + std::to_string(n) +
                             ") = " + std::to_string(minimum_shape_parameter(n)));
}

} // namespace

JamResult jam(const JamOptions& options)
{
    require_floppy_A0(options);
    const double pi = std::numbers::pi;
    JamResult out;
    DpmSystem& s = out.system;
    s.interaction = InteractionKind::rough;
    s.kc = 1.0;
    Rng rng(options.seed);
    const bool disks = options.model == JamModel::smooth_disk;
    if (disks) {
        double area = 0;
        for (int m = 0; m < options.particles; ++m)
            area += 0.25 * pi * std::pow(m < options.particles / 2 ? 1.0 : options.size_ratio, 2);
        const double L = std::sqrt(area / options.phi_start);
        s.box = Eigen::Vector2d(L, L);
        for (int m = 0; m < options.particles; ++m) {
            Eigen::Matrix2Xd c(2, 1);
            c << rng.uniform(0, L), rng.uniform(0, L);
            s.add_particle(c, m < options.particles / 2 ? 1.0 : options.size_ratio, ShapeParameters{}, out.x);
        }
    } else {
        // Vertex diameter sigma = 1; small polygons of N_small vertices with R/sigma such that neighbouring
        // vertices overlap as in Fig. 9.12 (edge = 0.85 sigma); large ones scaled by size_ratio in diameter
        // with N_large vertices (decision dpm-jam-polygons).
        const bool rigid = options.model == JamModel::rough_disk;
        const ShapeModel model = rigid ? ShapeModel::shell : *shape_model(options.model);
        const double r_small = 0.85 / (2 * std::sin(pi / options.nodes_small));
        const double a0_small =
            0.5 * options.nodes_small * r_small * r_small * std::sin(2 * pi / options.nodes_small);
        std::vector<std::pair<int, double>> kinds;
        double area = 0;
        for (int m = 0; m < options.particles; ++m) {
            const bool small = m < options.particles / 2;
            const int n = small ? options.nodes_small : options.nodes_large;
            const double r = small ? r_small : options.size_ratio * r_small;
            kinds.push_back({n, r});
            area += std::pow(2 * r + 1.0, 2);
        }
        const double L = std::sqrt(area / 0.25);
        s.box = Eigen::Vector2d(L, L);
        std::vector<Eigen::Vector2d> centres;
        std::vector<double> radii;
        for (const auto& [n, r] : kinds) {
            const double a0 = 0.5 * n * r * r * std::sin(2 * pi / n);
            ShapeStiffness k;
            k.ka = 1.0 / (a0_small * a0_small); // k_a a0^2 = k_c sigma^2 (decision dpm-jam-polygons)
            k.kl = 1.0;
            k.kb = 0.1;
            k.gamma = 0.1 * k.ka * std::pow(a0_small, 1.5);
            k.kl_surface = options.kl_surface;
            const double A0 = model == ShapeModel::floppy ? options.A0_floppy : minimum_shape_parameter(n);
            Eigen::Vector2d c;
            for (int tries = 0;; ++tries) {
                if (tries > 100000)
                    throw InputError("particles = " + std::to_string(options.particles) +
                                     ": no room at the start");
                c = Eigen::Vector2d(rng.uniform(0, L), rng.uniform(0, L));
                bool free = true;
                for (std::size_t q = 0; q < centres.size(); ++q)
                    if (minimum_image(c - centres[q], *s.box).norm() < r + radii[q] + 1.0) free = false;
                if (free) break;
            }
            centres.push_back(c);
            radii.push_back(r);
            Eigen::Matrix2Xd v = regular_polygon(n, r, c, rng.uniform(0, 2 * pi));
            s.add_particle(v, 1.0, rigid ? ShapeParameters{} : table_9_1_parameters(model, n, a0, A0, k),
                           out.x);
        }
        out.pressure_unit = 1.0 / a0_small; // k_a a0 = (1/a0^2) a0
    }

    const bool rough_disks = options.model == JamModel::rough_disk;
    if (rough_disks && options.relaxation == Relaxation::fire_newton)
        throw InputError("relaxation = 'fire_newton' with model = 'rough_disk': rigid polygons relax over "
                         "rigid-body coordinates, with FIRE alone (allowed: fire)");
    FireOptions& fire = out.fire;
    fire.dt_max =
        std::min(0.5, options.fire_step / std::sqrt(vibrational_modes(s, out.x).eigenvalues.maxCoeff()));
    fire.dt_initial = 0.25 * fire.dt_max;
    fire.force_tolerance = 1e-4 * options.pressure_onset * out.pressure_unit;
    const RelaxOptions relax_options{options.relaxation, fire};
    const auto relax_rigid = [&](long step_index) {
        const FireResult r = relax_rigid_fire(s, out.x, fire);
        out.fire_iterations += r.iterations;
        out.force_evaluations += r.force_evaluations;
        out.relax_seconds += r.seconds;
        out.fire_seconds += r.seconds;
        if (!r.converged)
            throw NumericalError("relaxation during compression (" + fire_shortfall(r, fire) + ")",
                                 step_index,
                                 "force tolerance too small for the pressure; raise pressure_onset");
        return r.iterations;
    };
    const auto relax = [&](long step_index) {
        if (rough_disks) return relax_rigid(step_index);
        const RelaxResult r = dpm::relax(s, out.x, relax_options);
        out.add(r);
        if (!r.converged)
            throw NumericalError("relaxation during compression (" + relax_shortfall(r, relax_options) + ")",
                                 step_index,
                                 "force tolerance too small for the pressure; raise pressure_onset");
        return r.fire_iterations;
    };
    const auto current_pressure = [&] {
        return pressure(rough_disks ? rigid_stress_tensor(s, out.x) : stress_tensor(s, out.x)) /
               out.pressure_unit;
    };
    relax(0);

    // Targets: onset, then log-spaced pressures up to pressure_max.
    const std::vector<double> targets =
        pressure_targets(options.pressure_onset, options.pressure_max, options.pressures);
    BoxSchedule schedule; // Delta L/L = 5e-3 (decision dpm-jam-protocol)
    schedule.onset = options.pressure_onset;
    Eigen::VectorXd saved_x;
    Eigen::Vector2d saved_box;
    const CompressiblePacking packing{current_pressure,
                                      [&](double f) { scale_packing(s, out.x, f); },
                                      [&](long step_index) { return relax(step_index); },
                                      [&] {
                                          saved_x = out.x;
                                          saved_box = *s.box;
                                      },
                                      [&] {
                                          out.x = saved_x;
                                          *s.box = saved_box;
                                      },
                                      // no saddle test in 2D: dpm.modes reports one as negative modes
                                      {}};
    const auto reach = [&](double target, bool compressing) {
        const long iterations = reach_pressure(target, compressing, schedule, packing);
        out.states.push_back(
            {packing_fraction(s, out.x), current_pressure(), iterations, out.x, *s.box, !compressing});
    };
    for (double target : targets)
        reach(target, true);
    if (options.decompress)
        for (auto t = targets.rbegin() + 1; t != targets.rend(); ++t)
            reach(*t, false);
    return out;
}

CompressionBranchFit fit_compression_branch(const std::vector<JamState>& states)
{
    if (states.empty()) return {};
    const double phi_c = states.front().phi;
    std::vector<double> dphi, pressure;
    for (std::size_t k = 1; k < states.size(); ++k) {
        if (states[k].decompression) continue;
        dphi.push_back(states[k].phi - phi_c);
        pressure.push_back(states[k].pressure);
    }
    const bool fitted = dphi.size() >= 2;
    return {fitted ? fit_slope_through_origin(dphi, pressure) : std::nullopt,
            fit_power_law_exponent(dphi, pressure)};
}

} // namespace softgrain::dpm
