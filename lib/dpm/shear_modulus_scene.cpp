// dpm.shear_modulus: shear modulus G of jammed packings against pressure (section 9.4.3, Fig. 9.16a): the
// dpm.jam protocol gives relaxed packings at log-spaced pressures; at each, Lees-Edwards strain steps of
// 5e-9 give G = d(-Sigma_xy)/d gamma. Summary: the fitted exponent of G ~ P^eta over the pressures above
// onset.
#include "dpm/shear_modulus_scene.hpp"

#include "core/ensemble.hpp"
#include "core/errors.hpp"
#include "core/output.hpp"
#include "dpm/jam.hpp"
#include "dpm/jam_scene.hpp"
#include "dpm/shear_modulus_ensemble.hpp"

namespace softgrain::dpm {

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

    // Independent ensemble members (seeds first_seed, first_seed + 1, ...).
    const std::vector<ModulusMember> members = run_ensemble<ModulusMember>(packings, [&](int k) {
        JamOptions mine = o;
        mine.seed = first_seed + static_cast<std::uint64_t>(k);
        const JamResult r = jam(mine);
        ModulusMember m = moduli_at_states(r.system, r.states, r.pressure_unit, dgamma, steps, tolerance);
        m.fire_iterations = r.fire_iterations;
        return m;
    });
    const EnsembleModulus e = report_ensemble(
        members, {"modulus.dat", "mean_modulus.dat", "k_c or k_a a0", "pressure Tr(Sigma)/2, eq. (9.26)"},
        context);
    context.count_steps(e.fire_iterations);
    auto& s = context.summary();
    s["packings"] = packings;
    write_modulus_summary(e, "", s);
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
