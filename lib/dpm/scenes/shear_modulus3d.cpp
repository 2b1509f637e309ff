// dpm.shear_modulus3d: shear modulus G of jammed 3D packings against pressure (section 9.4.3, Fig. 9.16b):
// the 3D jamming protocol (jam3d.hpp) gives relaxed packings at P_t and at log-spaced pressures above it; at
// each, Lees-Edwards strain steps (x sheared along y) give G = d(-Sigma_xy)/d gamma (shear_modulus.hpp), in
// units k_v v0. Floppy, shell and surface-tension particles (or all three, same seeds and starts). Tables
// modulus_<model>.dat (every packing) and mean_modulus_<model>.dat (<P>, <G>); summary: the exponent of
// <G> ~ P^eta per model (shear_modulus_ensemble.hpp).
#include "dpm/shear_modulus3d_scene.hpp"

#include "core/ensemble.hpp"
#include "core/errors.hpp"
#include "core/output.hpp"
#include "dpm/jam3d.hpp"
#include "dpm/shear_modulus_ensemble.hpp"
#include "dpm/vtk_frames.hpp"

#include <optional>
#include <string>

namespace softgrain::dpm {

namespace {

const std::vector<std::string> model_names{"floppy", "shell", "surface_tension"};

Jam3dOptions jam3d_options(const Parameters& p)
{
    Jam3dOptions o;
    o.particles = static_cast<int>(p.integer("particles"));
    o.mesh = p.choice("mesh");
    o.pressure_onset = p.real("pressure_onset");
    o.pressure_max = p.real("pressure_max");
    o.pressures = static_cast<int>(p.integer("pressures"));
    o.A0_floppy = p.real("A0_floppy");
    o.interaction = interaction_from_name(p.choice("contact"));
    o.seed = static_cast<std::uint64_t>(p.integer("seed"));
    if (o.pressure_max <= o.pressure_onset)
        throw InputError("pressure_max = " + std::to_string(o.pressure_max) +
                         ": allowed a pressure above pressure_onset = " + std::to_string(o.pressure_onset));
    return o;
}

// Floppy particles need A0 above the mesh's own A^3D (A_min^3D, sec. 9.3.1). Checked here, before any
// packing is jammed, so that the message names this scene's key (jam3d would name model_shape3d's A0, and
// only after the other models' members of the ensemble had run).
void check_A0_floppy(const Parameters& p)
{
    if (p.choice("model") != "floppy" && p.choice("model") != "all") return;
    const TriangleMesh mesh = mesh_from_name(p.choice("mesh"));
    const double A_min = mesh_shape_parameter3d(mesh, mesh_coordinates(mesh), 0);
    if (p.real("A0_floppy") < A_min)
        throw InputError("parameter 'A0_floppy' = '" + std::to_string(p.real("A0_floppy")) +
                         "' is below the " + p.choice("mesh") + "'s own shape parameter A_min^3D = " +
                         std::to_string(A_min) + "; allowed: a real number >= it");
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

} // namespace

void run_shear_modulus3d(const Parameters& p, RunContext& context)
{
    check_A0_floppy(p);
    const Jam3dOptions o = jam3d_options(p);
    const std::string chosen = p.choice("model");
    const std::vector<std::string> models = chosen == "all" ? model_names : std::vector<std::string>{chosen};
    const int packings = static_cast<int>(p.integer("packings"));
    context.record_seed(o.seed);
    const double dgamma = p.real("strain_step");
    const int steps = static_cast<int>(p.integer("strain_steps"));
    const double tolerance = p.real("force_tolerance");

    // Every (model, packing) pair is an independent member, run in parallel: packing k of every model starts
    // from the same seed, seed + k (the same random centres and orientations). With --vtk, member 0 (the
    // first packing of the first model, always on the first rank, which writes) keeps its packing for the
    // frames, written once every member is done.
    std::optional<Jam3dResult> drawn;
    const std::vector<ModulusMember> all =
        run_ensemble<ModulusMember>(packings * static_cast<int>(models.size()), [&](int i) {
            Jam3dOptions mine = o;
            mine.model = shape_model_from_name(models[i / packings]);
            mine.seed = o.seed + static_cast<std::uint64_t>(i % packings);
            const Jam3dResult r = jam3d(mine);
            ModulusMember m = moduli_at_states(r.system, r.states, r.pressure_unit, dgamma, steps, tolerance);
            m.fire_iterations = r.fire_iterations;
            if (i == 0 && context.vtk()) drawn = r;
            return m;
        });
    if (drawn) write_pressure_frames(*drawn, all.front(), *context.vtk());
    auto& s = context.summary();
    s["packings"] = packings;
    s["particles"] = o.particles;
    long iterations = 0;
    for (std::size_t k = 0; k < models.size(); ++k) {
        const std::vector<ModulusMember> members(all.begin() + k * packings,
                                                 all.begin() + (k + 1) * packings);
        const EnsembleModulus e =
            report_ensemble(members,
                            {"modulus_" + models[k] + ".dat", "mean_modulus_" + models[k] + ".dat", "k_v v0",
                             "pressure Tr(Sigma)/3, eq. (9.26) in 3D"},
                            context);
        iterations += e.fire_iterations;
        write_modulus_summary(e, "_" + models[k], s);
    }
    context.count_steps(iterations);
}

std::vector<ParameterSpec> shear_modulus3d_parameters()
{
    return {
        ParameterSpec::choice(
            "model", "all", {"floppy", "shell", "surface_tension", "all"},
            "particle type of Table 9.1 in 3D (jam3d.hpp), or all three with the same seeds"),
        ParameterSpec::integer("particles", 8, "1", "particles N, half small, half large (even)").at_least(2),
        ParameterSpec::choice(
            "mesh", "icosahedron",
            {"tetrahedron", "octahedron", "icosahedron", "geodesic42", "geodesic162", "geodesic642"},
            "surface mesh of every particle; icosahedron (12 vertices) by default: the "
            "paper's 42-vertex packings take minutes each to jam (decision "
            "dpm-3d-shear-modulus)"),
        ParameterSpec::integer("packings", 2, "1", "ensemble size per model (seeds seed, seed + 1, ...)")
            .at_least(1),
        ParameterSpec::real("pressure_onset", 1e-5, "k_v v0", "P_t: jamming onset pressure").positive(),
        ParameterSpec::real("pressure_max", 1e-2, "k_v v0", "largest pressure of the compression").positive(),
        ParameterSpec::integer("pressures", 3, "1", "pressures log-spaced in (P_t, pressure_max]")
            .at_least(1),
        ParameterSpec::real("A0_floppy", 1.12, "1",
                            "floppy: preferred shape parameter A0^3D, above the mesh's own (icosahedron "
                            "1.098; 1.12 as Fig. 9.15b)")
            .at_least(1.0),
        ParameterSpec::choice(
            "contact", "rough", {"rough", "smooth"},
            "contacts between particles: rough = vertex spheres of diameter sigma (eqs. "
            "9.3-9.4), smooth = each vertex sphere against the faces of the other particle's "
            "mesh (decision dpm-3d-smooth-inclusion-exclusion)"),
        ParameterSpec::real("strain_step", 5e-9, "1", "Lees-Edwards simple shear step dgamma (sec. 9.4.3)")
            .positive(),
        ParameterSpec::integer("strain_steps", 2, "1", "shear steps per pressure").at_least(1),
        ParameterSpec::real("force_tolerance", 1e-10, "k_v v0 sigma",
                            "largest force component allowed after each Newton minimisation (Newton stops "
                            "at round-off, usually far below)")
            .positive(),
        ParameterSpec::seed("seed", 1, "seed of the random placement of the first packing"),
    };
}

} // namespace softgrain::dpm
