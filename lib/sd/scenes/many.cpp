// sd.many: several particles (Rognon & Gay, note [20]): centre velocities from the linear system, gaps from
// eq. (7), each bond against the pair it would be alone.
#include "sd/many.hpp"
#include "core/errors.hpp"
#include "core/option_binding.hpp"
#include "core/output.hpp"
#include "sd/scenes/scenes.hpp"
#include "sd/vtk_frames.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace softgrain::sd {

namespace {

struct ManyOptions
{
    int particles = 2;
    bool line = true;              // a line compressed at its ends, else a triangle pushed to its centre
    double force = 1e-3;           // [E R^2]
    double h0 = 1.0, h_min = 1e-4; // [R]
    double tolerance = 1e-10;
    int outputs = 120;
};

OptionBinding<ManyOptions> many_binding()
{
    OptionBinding<ManyOptions> binding;
    binding.integer(&ManyOptions::particles, "particles", "1", "number of particles").at_least(2).at_most(64);
    binding.choice(&ManyOptions::line, "geometry", {{"line", true}, {"cluster", false}},
                   "a line compressed at its ends, or a triangle (particles = 3) pushed to its centre");
    binding.real(&ManyOptions::force, "force", "E R^2", "external force on each loaded particle (kappa)")
        .positive()
        .at_most(1.0);
    binding.real(&ManyOptions::h0, "h0", "R", "initial gap of every bond").positive();
    binding.real(&ManyOptions::h_min, "h_min", "R", "stop when the smallest gap reaches h_min").positive();
    binding
        .real(&ManyOptions::tolerance, "tolerance", "1",
              "rk8pd relative (and delta-scaled absolute) tolerance")
        .positive()
        .below(1e-2);
    binding
        .integer(&ManyOptions::outputs, "outputs", "1",
                 "output times, log-spaced over the 7 decades before the pair reaches h_min")
        .at_least(4);
    binding.check([](const ManyOptions& options) {
        if (!options.line && options.particles != 3)
            throw InputError(
                "geometry = cluster needs particles = 3 (an equilateral triangle); got particles = " +
                std::to_string(options.particles));
        if (!(options.h_min < options.h0)) throw InputError("h_min must be below h0");
    });
    return binding;
}

// The centres carry the deflection through eq. (2), |X_ij| = 2R + h - 2 delta: a deflection below what the
// centre distance resolves to the integration tolerance (|X| ulp / tolerance) would give F_ela = 0 and a
// system that never moves (force = 1e-30 once ran to exit 0 with the gaps unchanged).
void refuse_unresolved_deflection(double delta0, double distance0, double tolerance, double force)
{
    const double resolved = (std::nextafter(distance0, 2 * distance0) - distance0) / tolerance;
    if (!(delta0 >= resolved))
        throw InputError("'force' = " + number_text(force) +
                         " gives the elastic deflection delta0 = " + number_text(delta0) +
                         " R, which the centre distance |X| = " + number_text(distance0) +
                         " R resolves only to " + number_text(resolved) +
                         " R at tolerance = " + number_text(tolerance) +
                         "; allowed: a force whose deflection is resolved (a larger force or tolerance)");
}

// The run is asked to bring the smallest gap to h_min (the integration stops there, or at the pair
// reference's approach time, which the integration tolerance lets it miss by far less than 1e-6 h_min);
// a run that stops short ends as a diagnosed failure, never as a summary.
void require_approach_completed(double gap_final, double h_min, long steps)
{
    if (!(gap_final <= h_min * (1 + 1e-6)))
        throw NumericalError("the smallest gap, h = " + number_text(gap_final) + " R", steps,
                             "it did not reach h_min = " + number_text(h_min) +
                                 " R by the pair reference's approach time");
}

// `outputs` times log-spaced over the 7 decades before t_end, the last a little beyond it so that the run
// reaches h_min.
std::vector<double> output_times(double t_end, long long outputs)
{
    std::vector<double> times;
    for (long long k = 1; k <= outputs; ++k)
        times.push_back(t_end * std::pow(1e-7, 1.0 - static_cast<double>(k) / outputs) *
                        (k == outputs ? 1.0 + 1e-9 : 1.0));
    return times;
}

// One run: the balanced start, its samples, and their maxima against the pair reference.
struct ManyOutcome
{
    BalancedStart start;
    std::vector<ManySample> samples;
    long steps = 0;
    ManyMaxima maxima;
};

ManyOutcome many(const ManyOptions& options)
{
    const Material material;
    ManyOutcome outcome;
    outcome.start = options.line ? compressed_line(material, options.particles, options.force, options.h0)
                                 : pushed_triangle(material, options.force, options.h0);
    const BalancedStart& start = outcome.start;
    refuse_unresolved_deflection(start.deflection, start.distance, options.tolerance, options.force);
    const std::vector<double> gaps(start.system.bonds.size(), options.h0);
    // The pair reference: the same bond alone under pair_force (eq. 7 with eq. 1), by quadrature.
    const ApproachProblem pair{material, start.system.laws, constant_loading(start.pair_force), options.h0,
                               options.h_min};
    const double t_end = approach_time_reference(pair, options.h0, options.h_min);
    outcome.samples =
        integrate_many(start.system, start.positions, gaps, output_times(t_end, options.outputs),
                       options.h_min, options.tolerance, start.deflection, outcome.steps);
    outcome.maxima = many_maxima(outcome.samples, start.system.dimension, pair, start.pair_force);
    return outcome;
}

// ParaView frames, one per output sample (--vtk-every N: every N-th) as in many.dat, time value t in R/V:
// the particles and the pairs, field data time t [s] and gap_min h [m].
void write_many_frames(const ManyOutcome& outcome, double force, RunContext& context)
{
    auto* series = context.vtk();
    if (!series) return;
    for (const ManySample& sample : outcome.samples) {
        if (!series->next()) continue;
        std::vector<vtk::Part> parts = many_particle_frame(outcome.start.system, sample);
        for (auto& part : parts) {
            part.data.field("time", sample.t);
            part.data.field("gap_min", *std::min_element(sample.gaps.begin(), sample.gaps.end()));
        }
        series->write(sample.t * force, parts);
    }
}

void write_many_table(const ManyOutcome& outcome, int particles, double force, RunContext& context)
{
    const ManyParticleSystem& system = outcome.start.system;
    std::vector<Column> columns{{"t", "R/V", "time, V = force/(eta R)"}};
    for (std::size_t bond = 0; bond < system.bonds.size(); ++bond)
        columns.push_back({"h_" + std::to_string(bond), "R", "gap of bond " + std::to_string(bond)});
    for (int i = 0; i < particles; ++i)
        for (int c = 0; c < system.dimension; ++c)
            columns.push_back({"v_" + std::to_string(i) + (c == 0 ? "x" : "y"), "V", "centre velocity"});
    auto& table = context.table("many.dat", columns);
    for (const ManySample& sample : outcome.samples) {
        std::vector<double> row{sample.t * force};
        row.insert(row.end(), sample.gaps.begin(), sample.gaps.end());
        for (double velocity : sample.rates.velocity)
            row.push_back(velocity / force);
        table.row(row);
    }
}

void run_many(const ManyOptions& options, RunContext& context)
{
    const ManyOutcome outcome = many(options);
    context.count_steps(outcome.steps);
    const std::vector<double>& final_gaps = outcome.samples.back().gaps;
    const double gap_final = *std::min_element(final_gaps.begin(), final_gaps.end());
    require_approach_completed(gap_final, options.h_min, outcome.steps);
    write_many_frames(outcome, options.force, context);
    write_many_table(outcome, options.particles, options.force, context);
    auto& summary = context.summary();
    summary["particles"] = options.particles;
    summary["bonds"] = outcome.start.system.bonds.size();
    summary["pair_force"] = outcome.start.pair_force;
    summary["mean_velocity_max"] = outcome.maxima.mean_velocity;
    summary["symmetry_deviation_max"] = outcome.maxima.symmetry_deviation;
    summary["pair_reference_error_max"] = outcome.maxima.pair_reference_error;
    summary["pair_force_residual_max"] = outcome.maxima.pair_force_residual;
    summary["linear_system_residual_max"] = outcome.maxima.linear_system_residual;
    summary["gap_final_min"] = gap_final;
    summary["t_final"] = outcome.samples.back().t * options.force;
}

} // namespace

Scene many_scene()
{
    return bound_scene("sd.many",
                       "several particles, note [20]: centre velocities from the linear system, gaps "
                       "from eq. (7)",
                       many_binding(), run_many)
        .with_vtk();
}

} // namespace softgrain::sd
