// dpm.jam: jamming onset and compression of bidisperse packings (section 9.4, Fig. 9.13): P against
// phi - phi_c, phi_c and the bulk modulus B of <P> = B (phi - phi_c).
#include "dpm/jam_scene.hpp"

#include "core/fits.hpp"
#include "core/output.hpp"
#include "dpm/jam.hpp"
#include "dpm/vtk_frames.hpp"

#include <cmath>

namespace softgrain::dpm {

JamOptions jam_options(const Parameters& p)
{
    JamOptions o;
    o.model = p.choice("model");
    o.particles = static_cast<int>(p.integer("particles"));
    o.nodes_small = static_cast<int>(p.integer("nodes_small"));
    o.nodes_large = static_cast<int>(p.integer("nodes_large"));
    o.pressure_onset = p.real("pressure_onset");
    o.pressure_max = p.real("pressure_max");
    o.pressures = static_cast<int>(p.integer("pressures"));
    o.seed = static_cast<std::uint64_t>(p.integer("seed"));
    o.A0_floppy = p.real("A0_floppy");
    o.kl_surface = p.real("kl_surface");
    o.relaxation = relaxation_from_name(p.choice("relaxation"));
    return o;
}

void run_jam(const Parameters& p, RunContext& context)
{
    JamOptions o = jam_options(p);
    o.decompress = p.boolean("decompress");
    context.record_seed(o.seed);
    const JamResult r = jam(o);
    context.count_steps(r.fire_iterations);
    // ParaView frames, one per pressure state (onset, compression, decompression), the state's index as the
    // time value (the pressure goes back down on decompression) with P, phi and the branch as field data:
    // the particles, the box and the contacts between particles.
    if (auto* series = context.vtk()) {
        DpmSystem system = r.system;
        for (std::size_t k = 0; k < r.states.size(); ++k) {
            if (!series->next()) continue;
            const JamState& state = r.states[k];
            system.box = state.box;
            std::vector<vtk::Part> parts{{"particles", dpm_particles(system, state.x)},
                                         {"box", box_outline(state.box)},
                                         {"contacts", dpm_contacts(system, state.x)}};
            for (auto& part : parts) {
                part.data.field("pressure", state.pressure);
                part.data.field("phi", state.phi);
                part.data.field("decompression", state.decompression ? 1.0 : 0.0);
            }
            series->write(static_cast<double>(k), parts);
        }
    }
    const double phi_c = r.states.front().phi;
    auto& table = context.table("pressure.dat", {{"phi", "1", "packing fraction (eq. 9.22 or disk area)"},
                                                 {"dphi", "1", "phi - phi_c"},
                                                 {"P", "k_c or k_a a0", "pressure Tr(Sigma)/2, eq. (9.26)"},
                                                 {"decompression", "1", "0 compression, 1 decompression"}});
    std::vector<double> dphi, pressure;
    for (const JamState& s : r.states) {
        table.row({s.phi, s.phi - phi_c, s.pressure, s.decompression ? 1.0 : 0.0});
        if (&s == &r.states.front() || s.decompression) continue; // the fits: the compression branch
        dphi.push_back(s.phi - phi_c);
        pressure.push_back(s.pressure);
    }
    auto& s = context.summary();
    s["phi_c"] = phi_c;
    s["states"] = r.states.size();
    // Back at onset after decompression: a different phi_c means an irreversible rearrangement
    // (Fig. 9.13b-d).
    if (o.decompress) {
        s["phi_c_decompression"] = r.states.back().phi;
        s["phi_c_shift"] = r.states.back().phi - phi_c;
    } else {
        s["phi_c_decompression"] = nullptr;
        s["phi_c_shift"] = nullptr;
    }
    // Both from two states on: P = B dphi through the origin, and the exponent of P against dphi.
    const bool fitted = dphi.size() >= 2;
    s["bulk_modulus"] = value_or_null(fitted ? fit_slope_through_origin(dphi, pressure) : std::nullopt);
    s["pressure_exponent"] = value_or_null(fit_power_law_exponent(dphi, pressure));
}

std::vector<ParameterSpec> jam_parameters()
{
    return {
        ParameterSpec::integer("particles", 16, "1", "particles N, half small, half large").at_least(2),
        ParameterSpec::integer("nodes_small", 10, "1", "vertices of the small particles").at_least(3),
        ParameterSpec::integer("nodes_large", 14, "1", "vertices of the large particles").at_least(3),
        ParameterSpec::choice("model", "smooth_disk",
                              {"smooth_disk", "rough_disk", "shell", "floppy", "surface_tension"},
                              "smooth bidisperse disks, rigid rough polygons (rough disks) or rough "
                              "deformable particles of Table 9.1"),
        ParameterSpec::seed("seed", 1, "seed of the random initial placement"),
        ParameterSpec::real("pressure_onset", 1e-7, "k_c or k_a a0", "P_t: jamming onset pressure")
            .positive(),
        ParameterSpec::real("pressure_max", 1e-3, "k_c or k_a a0", "largest pressure of the compression")
            .positive(),
        ParameterSpec::integer("pressures", 5, "1", "pressures log-spaced above onset").at_least(1),
        ParameterSpec::real("A0_floppy", 1.04, "1", "floppy: preferred shape parameter A0 (Fig. 9.14: 1.04)")
            .at_least(1.0),
        ParameterSpec::real(
            "kl_surface", 0.01, "k_c",
            "surface_tension: edge stiffness k_l (Table 9.1: ~0; decision dpm-jam-surface-kl)")
            .non_negative(),
        ParameterSpec::choice("relaxation", "fire", {"fire", "fire_newton"},
                              "minimiser after each box step: FIRE alone, or FIRE handing over to a "
                              "regularised Newton finisher on the sparse Hessian where it crawls "
                              "(newton_relax.hpp; rough_disk: fire only)"),
    };
}

std::vector<ParameterSpec> jam_scene_parameters()
{
    std::vector<ParameterSpec> specs = jam_parameters();
    specs.push_back(ParameterSpec::boolean(
        "decompress", false,
        "after pressure_max, expand back through the same pressures to onset (Fig. 9.13b-d)"));
    return specs;
}

} // namespace softgrain::dpm
