// vsm.compress_ball: a VSM ball between two rigid frictionless plates, F~ = F (1 - nu^2)/(E D^2) against
// delta/D (compare.solid, issue 22; the plates are our extension of the paper, decision vsm-plate-contact).
#include "core/errors.hpp"
#include "core/fits.hpp"
#include "core/option_binding.hpp"
#include "core/output.hpp"
#include "vsm/ball_compression.hpp"
#include "vsm/scenes/parameters.hpp"
#include "vsm/scenes/scenes.hpp"

#include <chrono>
#include <cmath>
#include <optional>
#include <vector>

namespace softgrain::vsm {

namespace {

// The window of the large-strain exponent, as dpm.compress3d's: delta/D from 0.05 to 0.2.
constexpr double fit_min = 0.05, fit_max = 0.2;

OptionBinding<BallCompressionSetup> compress_ball_binding()
{
    using S = BallCompressionSetup;
    OptionBinding<S> binding;
    binding.integer(&S::per_radius, "per_radius", "1", "lattice spacing h = R / per_radius (R = D/2)")
        .at_least(3);
    binding.real(&S::diameter, "diameter", "m", "ball diameter D").positive();
    bind_material(binding, &S::material);
    const auto model_options = [](auto field) { return path(&S::options, field); };
    binding.real(model_options(&ModelOptions::xi_n), "xi_n", "1", "normal contact factor of eq. (50)")
        .non_negative();
    binding.real(model_options(&ModelOptions::xi_t), "xi_t", "1", "tangential contact factor of eq. (50)")
        .non_negative();
    bind_internal_force(binding, model_options(&ModelOptions::internal));
    binding
        .real(&S::penalty, "penalty", "1",
              "plate penalty c_pen: a boundary point beyond a plate by g stores A kappa g^2/2, kappa = c_pen "
              "E/L "
              "(A its face area, L its ghost branch length)")
        .positive();
    binding.real(&S::delta_min, "delta_min", "1", "first compression delta / D (total plate approach)")
        .positive();
    binding.real(&S::delta_max, "delta_max", "1", "last compression delta / D").positive().below(1.0);
    binding
        .integer(&S::compressions, "compressions", "1",
                 "compressions, log-spaced from delta_min to delta_max")
        .at_least(1);
    binding
        .real(&S::plate_speed, "plate_speed", "c_s",
              "speed of the plate between compressions (slow against the waves: no impact on the ball)")
        .positive()
        .below(1.0);
    binding
        .real(&S::relax_tolerance, "relax_tolerance", "1",
              "relaxation ends when the unbalanced and the damping force of every particle are below this "
              "times "
              "the plate load")
        .positive()
        .below(1.0);
    binding
        .real(&S::damping, "damping", "c_s/R",
              "mass-proportional damping of the relaxation (critical for the slowest mode near 2 omega_1, "
              "omega_1 about 2.5 c_s/R)")
        .positive();
    binding
        .real(&S::cfl, "cfl", "1",
              "time step dt = cfl min(L_min / c_eff, sqrt(m_a / k_ab)), k_ab the stiffest plate spring")
        .positive()
        .at_most(2.0);
    bind_time_step_check(binding, &S::time_step_check);
    binding.check([](const S& setup) {
        if (setup.delta_min > setup.delta_max)
            throw InputError("delta_min = " + std::to_string(setup.delta_min) + " exceeds delta_max = " +
                             std::to_string(setup.delta_max) + ": allowed delta_min <= delta_max");
    });
    return binding;
}

std::optional<double> large_strain_exponent(const std::vector<BallCompressionSample>& samples)
{
    std::vector<double> delta, force;
    for (const BallCompressionSample& sample : samples)
        if (sample.delta_over_d >= fit_min * (1 - 1e-12) && sample.delta_over_d <= fit_max * (1 + 1e-12) &&
            sample.force > 0) {
            delta.push_back(sample.delta_over_d);
            force.push_back(sample.force);
        }
    return fit_power_law_exponent(delta, force, 3);
}

void report_compress_ball(const BallCompressionSetup& setup, const BallCompressionResult& result,
                          double wall_time, RunContext& context)
{
    context.count_steps(result.steps);
    const double E = setup.material.young, nu = setup.material.poisson, D = setup.diameter;
    const double scale = (1 - nu * nu) / (E * D * D);
    auto& table =
        context.table("force.dat", {{"delta", "D", "compression delta~ = delta / D"},
                                    {"F", "N", "load of the top plate"},
                                    {"F_tilde", "1", "F~ = F (1 - nu^2)/(E D^2)"},
                                    {"contacts", "1", "boundary points of the octant on the plate"},
                                    {"steps", "1", "leapfrog steps of this compression"},
                                    {"residual", "1", "largest particle force over the load at the end"}});
    std::vector<double> delta_tilde, force_tilde;
    for (const BallCompressionSample& sample : result.samples) {
        table.row({sample.delta_over_d, sample.force, sample.force * scale, double(sample.contacts),
                   double(sample.steps), sample.residual});
        delta_tilde.push_back(sample.delta_over_d);
        force_tilde.push_back(sample.force * scale);
    }
    auto& summary = context.summary();
    summary["diameter"] = D;
    summary["E"] = E;
    summary["nu"] = nu;
    summary["particles"] = result.particles;
    summary["volume_excess"] = result.volume_excess;
    summary["dt"] = result.dt;
    summary["dt_over_limit"] = result.dt / result.dt_elastic_limit;
    summary["large_strain_exponent"] = value_or_null(large_strain_exponent(result.samples));
    summary["contacts_at_max"] = result.samples.back().contacts;
    summary["F_tilde_at_max"] = force_tilde.back();
    summary["delta_tilde"] = delta_tilde;
    summary["F_tilde"] = force_tilde;
    summary["cost_per_step_per_particle_s"] = wall_time / (double(result.steps) * result.particles);
}

void run_compress_ball(const BallCompressionSetup& setup, RunContext& context)
{
    const auto start = std::chrono::steady_clock::now();
    const BallCompressionResult result = compress_ball(setup);
    report_compress_ball(setup, result, seconds_since(start), context);
}

} // namespace

Scene compress_ball_scene()
{
    return bound_scene(
               "vsm.compress_ball",
               "VSM ball between two rigid frictionless plates (compare.solid; plates are our penalty "
               "extension): F~ against delta/D",
               compress_ball_binding(), run_compress_ball)
        .advised_by(
            {"compare",
             "compare-solid-vsm",
             "method_index",
             {"vsm"},
             "penalty",
             "vsm",
             "per_radius",
             "R / h of the octant lattice",
             "fe_error_max",
             "largest |F~/F~_FE - 1| over 0.01 <= delta/D <= 0.2 against the neo-Hookean finite-element "
             "ball (data/compare/solid_fe.toml)"})
        .needing(compress_ball_binding().estimate([](const BallCompressionSetup& setup) {
            const double n = setup.per_radius;
            return vsm_particle_memory(std::acos(-1.0) / 6 * cube(n), "particles (pi/6 per_radius^3)");
        }));
}

} // namespace softgrain::vsm
