// dpm.shear_modulus3d: shear modulus G of jammed 3D packings against pressure (section 9.4.3, Fig. 9.16b):
// the 3D jamming protocol (jam3d.hpp) gives relaxed packings at P_t and at log-spaced pressures above it; at
// each, Lees-Edwards strain steps (x sheared along y) give G = d(-Sigma_xy)/d gamma (shear_modulus.hpp), in
// units k_v v0. Floppy, shell and surface-tension particles (or all three, same seeds and starts). Tables
// modulus_<model>.dat (every packing) and mean_modulus_<model>.dat (<P>, <G>); summary: the exponent of
// <G> ~ P^eta per model (shear_modulus_ensemble.hpp).
#include "core/ensemble.hpp"
#include "core/errors.hpp"
#include "core/option_binding.hpp"
#include "core/output.hpp"
#include "dpm/analysis/vtk_frames.hpp"
#include "dpm/protocols/jam3d.hpp"
#include "dpm/protocols/shear_modulus_ensemble.hpp"
#include "dpm/scenes/scenes.hpp"

#include <algorithm>
#include <optional>
#include <string>

namespace softgrain::dpm {

namespace {

// dpm.shear_modulus3d's options: the jamming protocol of every packing, the models and ensemble size, and
// the strain steps.
struct ShearModulus3dOptions
{
    Jam3dOptions jam = scene_jam_defaults();
    std::vector<ShapeModel> models{ShapeModel::floppy, ShapeModel::shell, ShapeModel::surface_tension};
    int packings = 2; // per model
    double strain_step = 5e-9;
    int strain_steps = 2;
    double force_tolerance = 1e-10; // [k_v v0 sigma]

    // The scene's defaults where they differ from the library's.
    static Jam3dOptions scene_jam_defaults()
    {
        Jam3dOptions jam;
        jam.mesh = "icosahedron";
        jam.pressure_onset = 1e-5;
        jam.pressure_max = 1e-2;
        jam.pressures = 3;
        jam.A0_floppy = 1.12;
        return jam;
    }
};

// Floppy particles need A0 above the mesh's own A^3D (A_min^3D, sec. 9.3.1). Checked before any packing is
// jammed, so that the message names this scene's key (jam3d would name model_shape3d's A0, and only after
// the other models' members of the ensemble had run).
void check_floppy_A0(const ShearModulus3dOptions& options)
{
    const auto& models = options.models;
    if (std::find(models.begin(), models.end(), ShapeModel::floppy) == models.end()) return;
    const TriangleMesh mesh = mesh_from_name(options.jam.mesh);
    const double A_min = mesh_shape_parameter3d(mesh, mesh_coordinates(mesh), 0);
    if (options.jam.A0_floppy < A_min)
        throw InputError("parameter 'A0' (old name 'A0_floppy') = '" + std::to_string(options.jam.A0_floppy) +
                         "' is below the " + options.jam.mesh + "'s own shape parameter A_min^3D = " +
                         std::to_string(A_min) + "; allowed: a real number >= it");
}

OptionBinding<ShearModulus3dOptions> shear_modulus3d_binding()
{
    const auto jam = [](auto field) { return path(&ShearModulus3dOptions::jam, field); };
    using Models = std::vector<ShapeModel>;
    OptionBinding<ShearModulus3dOptions> binding;
    binding.choice(&ShearModulus3dOptions::models, "model",
                   {{"floppy", Models{ShapeModel::floppy}},
                    {"shell", Models{ShapeModel::shell}},
                    {"surface_tension", Models{ShapeModel::surface_tension}},
                    {"all", Models{ShapeModel::floppy, ShapeModel::shell, ShapeModel::surface_tension}}},
                   "particle type of Table 9.1 in 3D (jam3d.hpp), or all three with the same seeds");
    binding
        .integer(jam(&Jam3dOptions::particles), "particles", "1",
                 "particles N, half small, half large (even)")
        .at_least(2);
    binding.word(jam(&Jam3dOptions::mesh), "mesh", particle_mesh_names(),
                 "surface mesh of every particle; icosahedron (12 vertices) by default: the "
                 "paper's 42-vertex packings take minutes each to jam (decision "
                 "dpm-3d-shear-modulus)");
    binding
        .integer(&ShearModulus3dOptions::packings, "packings", "1",
                 "ensemble size per model (seeds seed, seed + 1, ...)")
        .at_least(1);
    binding
        .real(jam(&Jam3dOptions::pressure_onset), "pressure_onset", "k_v v0", "P_t: jamming onset pressure")
        .positive();
    binding
        .real(jam(&Jam3dOptions::pressure_max), "pressure_max", "k_v v0",
              "largest pressure of the compression")
        .positive();
    binding
        .integer(jam(&Jam3dOptions::pressures), "pressures", "1",
                 "pressures log-spaced in (P_t, pressure_max]")
        .at_least(1);
    binding
        .real(jam(&Jam3dOptions::A0_floppy), "A0", "1",
              "floppy: preferred shape parameter A0^3D, above the mesh's own (icosahedron "
              "1.098; 1.12 as Fig. 9.15b)")
        .at_least(1.0)
        .renamed_from("A0_floppy");
    binding.choice(jam(&Jam3dOptions::interaction), "contact",
                   {{"rough", InteractionKind::rough}, {"smooth", InteractionKind::smooth}},
                   "contacts between particles: rough = vertex spheres of diameter sigma (eqs. "
                   "9.3-9.4), smooth = each vertex sphere against the faces of the other particle's "
                   "mesh (decision dpm-3d-smooth-inclusion-exclusion)");
    binding
        .real(&ShearModulus3dOptions::strain_step, "strain_step", "1",
              "Lees-Edwards simple shear step dgamma (sec. 9.4.3)")
        .positive();
    binding.integer(&ShearModulus3dOptions::strain_steps, "strain_steps", "1", "shear steps per pressure")
        .at_least(1);
    binding
        .real(&ShearModulus3dOptions::force_tolerance, "force_tolerance", "k_v v0 sigma",
              "largest force component allowed after each Newton minimisation (Newton stops "
              "at round-off, usually far below)")
        .positive();
    bind_relaxation(binding, jam(&Jam3dOptions::relaxation), "the jamming protocol");
    bind_fire_step(binding, jam(&Jam3dOptions::fire_step));
    bind_hessian_storage(binding, jam(&Jam3dOptions::hessian), "hessian",
                         "the jamming protocol's FIRE time step and saddle tests and of the Newton steps "
                         "after each shear step");
    binding.seed(jam(&Jam3dOptions::seed), "seed", "seed of the random placement of the first packing");
    binding.check(check_floppy_A0);
    binding.check([](const ShearModulus3dOptions& options) {
        if (options.jam.pressure_max <= options.jam.pressure_onset)
            throw InputError(
                "pressure_max = " + std::to_string(options.jam.pressure_max) +
                ": allowed a pressure above pressure_onset = " + std::to_string(options.jam.pressure_onset));
    });
    return binding;
}

// ParaView frames of one packing: at each pressure state (time value: its index, P_t first) the relaxed
// packing before it is sheared (the strain steps of 5e-9 would not show) and its box; field data pressure
// and phi (as modulus_<model>.dat) and G, the modulus measured there.
void write_pressure_frames(const Jam3dResult& packing, const ModulusMember& measured, vtk::Series& series)
{
    DpmSystem3d system = packing.system;
    for (std::size_t l = 0; l < packing.states.size(); ++l) {
        if (!series.next()) continue;
        const Jam3dState& state = packing.states[l];
        *system.box = state.box;
        std::vector<vtk::Part> parts{{"particles", dpm_particles3d(system, state.x)},
                                     {"box", box_outline3d(state.box)}};
        for (vtk::Part& part : parts) {
            part.data.field("pressure", measured.pressure[l]);
            part.data.field("phi", measured.phi[l]);
            part.data.field("G", measured.modulus[l]);
        }
        series.write(static_cast<double>(l), parts);
    }
}

// Every packing of every model: member i is packing i % packings of model i / packings; with --vtk, member
// 0's packing, for the frames.
struct ShearModulus3dResult
{
    std::vector<ModulusMember> members;
    std::optional<Jam3dResult> drawn;
};

ShearModulus3dResult shear_modulus3d(const ShearModulus3dOptions& options, bool keep_drawn)
{
    // Every (model, packing) pair is an independent member, run in parallel: packing k of every model starts
    // from the same seed, seed + k (the same random centres and orientations). Member 0 (the first packing of
    // the first model, always on the first rank, which writes) keeps its packing for the frames.
    const int packings = options.packings;
    ShearModulus3dResult result;
    result.members =
        run_ensemble<ModulusMember>(packings * static_cast<int>(options.models.size()), [&](int i) {
            Jam3dOptions member = options.jam;
            member.model = options.models[static_cast<std::size_t>(i / packings)];
            member.seed = options.jam.seed + static_cast<std::uint64_t>(i % packings);
            const Jam3dResult packing = jam3d(member);
            ModulusMember measured = moduli_at_states(
                packing.system, packing.states, packing.pressure_unit, options.strain_step,
                options.strain_steps, options.force_tolerance, {}, member.hessian, packing.fire);
            measured.fire_iterations = packing.fire_iterations;
            if (i == 0 && keep_drawn) result.drawn = packing;
            return measured;
        });
    return result;
}

// Tables modulus_<model>.dat and mean_modulus_<model>.dat and the summary keys with suffix _<model>, per model.
void report_shear_modulus3d(const ShearModulus3dOptions& options, const ShearModulus3dResult& result,
                            RunContext& context)
{
    if (result.drawn) write_pressure_frames(*result.drawn, result.members.front(), *context.vtk());
    auto& summary = context.summary();
    summary["packings"] = options.packings;
    summary["particles"] = options.jam.particles;
    const auto packings = static_cast<std::size_t>(options.packings);
    long iterations = 0;
    for (std::size_t k = 0; k < options.models.size(); ++k) {
        const std::string model = shape_model_name(options.models[k]);
        const std::vector<ModulusMember> members(result.members.begin() + k * packings,
                                                 result.members.begin() + (k + 1) * packings);
        const EnsembleModulus ensemble =
            report_ensemble(members,
                            {"modulus_" + model + ".dat", "mean_modulus_" + model + ".dat", "k_v v0",
                             "pressure Tr(Sigma)/3, eq. (9.26) in 3D"},
                            context);
        iterations += ensemble.fire_iterations;
        write_modulus_summary(ensemble, "_" + model, summary);
    }
    context.count_steps(iterations);
}

void run_shear_modulus3d(const ShearModulus3dOptions& options, RunContext& context)
{
    context.record_seed(options.jam.seed);
    report_shear_modulus3d(options, shear_modulus3d(options, context.vtk() != nullptr), context);
}

} // namespace

Scene shear_modulus3d_scene()
{
    return bound_scene("dpm.shear_modulus3d",
                       "DPM sec. 9.4.3: shear modulus G of jammed 3D packings of floppy, shell and "
                       "surface-tension particles from Lees-Edwards strain steps against pressure, fitted "
                       "exponents of G ~ P^eta (Fig. 9.16b)",
                       shear_modulus3d_binding(), run_shear_modulus3d)
        .needing(shear_modulus3d_binding().estimate([](const ShearModulus3dOptions& options) {
            // The shear steps' dense Newton step holds one dense matrix; the sparse one none beyond the
            // protocol's non-zeros.
            const Eigen::Index n =
                3 * Eigen::Index{options.jam.particles} * mesh_from_name(options.jam.mesh).vertex_count();
            return packing3d_memory(options.jam.particles, options.jam.mesh, options.jam.hessian,
                                    uses_sparse_hessian(options.jam.hessian, n) ? 0 : 1);
        }))
        .with_vtk();
}

} // namespace softgrain::dpm
