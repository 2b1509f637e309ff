// dpm.shear_modulus: shear modulus G of jammed packings against pressure (section 9.4.3, Fig. 9.16a): the
// dpm.jam protocol gives relaxed packings at log-spaced pressures; at each, Lees-Edwards strain steps of
// 5e-9 give G = d(-Sigma_xy)/d gamma. Summary: the fitted exponent of G ~ P^eta over the pressures above
// onset.
#include "dpm/shear_modulus_scene.hpp"

#include "core/errors.hpp"
#include "core/output.hpp"
#include "dpm/jam.hpp"
#include "dpm/jam_scene.hpp"
#include "dpm/shear_modulus.hpp"

#include <gsl/gsl_fit.h>

#include <cmath>
#include <exception>

namespace softgrain::dpm {

namespace {

// One packing of the ensemble: its pressures (onset first) and shear moduli, in the model's unit.
struct Member
{
    std::vector<double> pressure, phi, modulus;
    long fire_iterations = 0;
    double force_max = 0; // largest force after any Newton minimisation
};

Member member(const JamOptions& o, double dgamma, int steps, double force_tolerance)
{
    const JamResult r = jam(o);
    Member m;
    m.fire_iterations = r.fire_iterations;
    DpmSystem system = r.system;
    for (const JamState& state : r.states) {
        *system.box = state.box;
        const ShearModulusResult g =
            shear_modulus(system, state.x, dgamma, steps, force_tolerance * r.pressure_unit);
        m.pressure.push_back(state.pressure);
        m.phi.push_back(state.phi);
        m.modulus.push_back(g.modulus / r.pressure_unit);
        m.force_max = std::max(m.force_max, g.force_max);
    }
    return m;
}

} // namespace

void run_shear_modulus(const Parameters& p, RunContext& context)
{
    const JamOptions o = jam_options(p);
    if (o.model == "rough_disk")
        throw InputError(
            "model = 'rough_disk': dpm.shear_modulus minimises over vertex coordinates; rigid "
            "polygons are not supported (allowed: smooth_disk | shell | floppy | surface_tension)");
    const std::uint64_t first_seed = o.seed;
    const int packings = static_cast<int>(p.integer("packings"));
    context.record_seed(first_seed);
    const double dgamma = p.real("strain_step");
    const int steps = static_cast<int>(p.integer("strain_steps"));
    const double tolerance = p.real("force_tolerance");

    // Independent ensemble members (seeds first_seed, first_seed + 1, ...), in parallel.
    std::vector<Member> members(packings);
    std::vector<std::exception_ptr> errors(packings);
#pragma omp parallel for schedule(dynamic)
    for (int k = 0; k < packings; ++k) {
        try {
            JamOptions mine = o;
            mine.seed = first_seed + static_cast<std::uint64_t>(k);
            members[k] = member(mine, dgamma, steps, tolerance);
        } catch (...) {
            errors[k] = std::current_exception();
        }
    }
    for (const auto& e : errors)
        if (e) std::rethrow_exception(e);

    auto& each = context.table("modulus.dat", {{"packing", "1", "ensemble member (seed - first seed)"},
                                               {"P", "k_c or k_a a0", "pressure Tr(Sigma)/2, eq. (9.26)"},
                                               {"phi", "1", "packing fraction"},
                                               {"G", "k_c or k_a a0", "shear modulus d(-Sigma_xy)/d gamma"}});
    long iterations = 0;
    double force_max = 0;
    const std::size_t levels = members.front().pressure.size();
    std::vector<double> mean_p(levels, 0.0), mean_g(levels, 0.0);
    for (int k = 0; k < packings; ++k) {
        const Member& m = members[k];
        iterations += m.fire_iterations;
        force_max = std::max(force_max, m.force_max);
        for (std::size_t l = 0; l < levels; ++l) {
            each.row({double(k), m.pressure[l], m.phi[l], m.modulus[l]});
            mean_p[l] += m.pressure[l] / packings;
            mean_g[l] += m.modulus[l] / packings;
        }
    }
    auto& mean =
        context.table("mean_modulus.dat", {{"P", "k_c or k_a a0", "ensemble mean pressure"},
                                           {"G", "k_c or k_a a0", "ensemble mean shear modulus <G>"}});
    std::vector<double> log_p, log_g;
    for (std::size_t l = 0; l < levels; ++l) {
        mean.row({mean_p[l], mean_g[l]});
        if (l > 0 && mean_g[l] > 0) { // the fit is over the pressures above onset
            log_p.push_back(std::log(mean_p[l]));
            log_g.push_back(std::log(mean_g[l]));
        }
    }
    context.count_steps(iterations);
    auto& s = context.summary();
    s["packings"] = packings;
    s["force_max"] = force_max;
    s["G_onset"] = mean_g.front();
    s["G_max_pressure"] = mean_g.back();
    if (log_p.size() >= 2) {
        double c0 = 0, c1 = 0, c00 = 0, c01 = 0, c11 = 0, sumsq = 0;
        gsl_fit_linear(log_p.data(), 1, log_g.data(), 1, log_p.size(), &c0, &c1, &c00, &c01, &c11, &sumsq);
        s["shear_modulus_exponent"] = c1;
        s["shear_modulus_exponent_error"] = std::sqrt(c11);
    } else {
        s["shear_modulus_exponent"] = nullptr;
        s["shear_modulus_exponent_error"] = nullptr;
    }
}

std::vector<ParameterSpec> shear_modulus_parameters()
{
    std::vector<ParameterSpec> specs = jam_parameters();
    specs.push_back(
        ParameterSpec::real("strain_step", 5e-9, "1", "Lees-Edwards simple shear step dgamma (sec. 9.4.3)")
            .positive());
    specs.push_back(
        ParameterSpec::integer("packings", 4, "1", "ensemble size (seeds seed, seed + 1, ...)").at_least(1));
    specs.push_back(ParameterSpec::integer("strain_steps", 2, "1", "shear steps per pressure").at_least(1));
    specs.push_back(ParameterSpec::real("force_tolerance", 1e-10, "k_c or k_a a0 (times length)",
                                        "largest force component allowed after each Newton minimisation "
                                        "(Newton stops at round-off, usually far below)")
                        .positive());
    return specs;
}

} // namespace softgrain::dpm
