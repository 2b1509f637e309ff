// dpm.shear_modulus: shear modulus G of jammed packings against pressure (section 9.4.3, Fig. 9.16a): the
// dpm.jam protocol gives relaxed packings at log-spaced pressures; at each, Lees-Edwards strain steps of
// 5e-9 give G = d(-Sigma_xy)/d gamma. Summary: the fitted exponent of G ~ P^eta over the pressures above
// onset.
#include "dpm/scenes/scenes.hpp"

#include "core/ensemble.hpp"
#include "core/errors.hpp"
#include "core/output.hpp"
#include "dpm/analysis/vtk_frames.hpp"
#include "dpm/protocols/jam.hpp"
#include "dpm/protocols/shear_modulus_ensemble.hpp"

namespace softgrain::dpm {

namespace {

// dpm.shear_modulus's options: the dpm.jam protocol of each packing, the ensemble and the strain steps.
struct ShearModulusOptions
{
    JamOptions jam;
    double strain_step = 5e-9;
    int packings = 4;
    int strain_steps = 2;
    double force_tolerance = 1e-10;
};

OptionBinding<ShearModulusOptions> shear_modulus_binding()
{
    OptionBinding<ShearModulusOptions> binding;
    bind_jam_protocol(binding, &ShearModulusOptions::jam);
    binding
        .real(&ShearModulusOptions::strain_step, "strain_step", "1",
              "Lees-Edwards simple shear step dgamma (sec. 9.4.3)")
        .positive();
    binding
        .integer(&ShearModulusOptions::packings, "packings", "1", "ensemble size (seeds seed, seed + 1, ...)")
        .at_least(1);
    binding.integer(&ShearModulusOptions::strain_steps, "strain_steps", "1", "shear steps per pressure")
        .at_least(1);
    binding
        .real(&ShearModulusOptions::force_tolerance, "force_tolerance", "k_c or k_a a0 (times length)",
              "largest force component allowed after each Newton minimisation (Newton stops at round-off, "
              "usually far below)")
        .positive();
    binding.check([](const ShearModulusOptions& options) {
        if (options.jam.model == JamModel::rough_disk)
            throw InputError(
                "model = 'rough_disk': dpm.shear_modulus minimises over vertex coordinates; rigid "
                "polygons are not supported (allowed: smooth_disk | shell | floppy | surface_tension)");
    });
    return binding;
}

// ParaView frames of the first packing (seed `seed`) only: at every pressure state, each strain step (0: the
// polished, unsheared packing), the running count (steps + 1) x state + step as the time value. The particles
// whole with their centres in the sheared box, the box as the parallelogram of its Lees-Edwards strain, and
// the contacts; field data state, step, gamma (the box's strain), pressure and phi of the state and
// shear_stress Sigma~ = -Sigma_xy [pressure unit]. Member 0 of the ensemble always runs on the first rank
// (core/ensemble.hpp: member k on rank k mod R), the one that writes, and it alone calls this.
StateShearObserver<DpmSystem> frame_writer(vtk::Series& series, const std::vector<JamState>& states,
                                           int steps, double pressure_unit)
{
    return [&series, &states, steps, pressure_unit](std::size_t state, int step, const DpmSystem& system,
                                                    const Eigen::VectorXd& x, double shear_stress) {
        if (!series.next()) return;
        std::vector<vtk::Part> parts{{"particles", dpm_particles(system, x)},
                                     {"box", box_outline(*system.box, system.lees_edwards_strain)},
                                     {"contacts", dpm_contacts(system, x)}};
        for (auto& part : parts) {
            part.data.field("state", static_cast<double>(state));
            part.data.field("step", step);
            part.data.field("gamma", system.lees_edwards_strain);
            part.data.field("pressure", states[state].pressure);
            part.data.field("phi", states[state].phi);
            part.data.field("shear_stress", shear_stress / pressure_unit);
        }
        series.write(static_cast<double>((steps + 1) * static_cast<int>(state) + step), parts);
    };
}

void run_shear_modulus(const ShearModulusOptions& options, RunContext& context)
{
    const std::uint64_t first_seed = options.jam.seed;
    const int packings = options.packings;
    context.record_seed(first_seed);
    const double dgamma = options.strain_step;
    const int steps = options.strain_steps;
    const double tolerance = options.force_tolerance;

    // Independent ensemble members (seeds first_seed, first_seed + 1, ...).
    const std::vector<ModulusMember> members = run_ensemble<ModulusMember>(packings, [&](int k) {
        JamOptions mine = options.jam;
        mine.seed = first_seed + static_cast<std::uint64_t>(k);
        const JamResult jammed = jam(mine);
        const StateShearObserver<DpmSystem> frames =
            k == 0 && context.vtk() ? frame_writer(*context.vtk(), jammed.states, steps, jammed.pressure_unit)
                                    : StateShearObserver<DpmSystem>{};
        ModulusMember member =
            moduli_at_states(jammed.system, jammed.states, jammed.pressure_unit, dgamma, steps, tolerance,
                             frames, HessianStorage::automatic, jammed.fire);
        member.fire_iterations = jammed.fire_iterations;
        return member;
    });
    const EnsembleModulus ensemble = report_ensemble(
        members, {"modulus.dat", "mean_modulus.dat", "k_c or k_a a0", "pressure Tr(Sigma)/2, eq. (9.26)"},
        context);
    context.count_steps(ensemble.fire_iterations);
    auto& summary = context.summary();
    summary["packings"] = packings;
    write_modulus_summary(ensemble, "", summary);
}

} // namespace

Scene shear_modulus_scene()
{
    return bound_scene("dpm.shear_modulus",
                       "DPM sec. 9.4.3: shear modulus G of jammed packings from Lees-Edwards strain steps "
                       "against pressure, fitted exponent of G ~ P^eta (Fig. 9.16a)",
                       shear_modulus_binding(), run_shear_modulus)
        .needing(shear_modulus_binding().estimate([](const ShearModulusOptions& options) {
            // The Newton polish at each pressure uses the dense Hessian of the packing.
            const BidispersePacking packing = bidisperse_packing(options.jam);
            return dense_matrix_memory(2 * bidisperse_vertices(packing), 1,
                                       std::string("2 x ") + bidisperse_basis(packing));
        }))
        .with_vtk();
}

} // namespace softgrain::dpm
