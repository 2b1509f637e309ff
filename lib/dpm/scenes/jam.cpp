// dpm.jam: jamming onset and compression of bidisperse packings (section 9.4, Fig. 9.13): P against
// phi - phi_c, phi_c and the bulk modulus B of <P> = B (phi - phi_c).
#include "dpm/scenes/scenes.hpp"

#include "core/output.hpp"
#include "dpm/jam.hpp"
#include "dpm/vtk_frames.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace softgrain::dpm {

namespace {

OptionBinding<JamOptions> jam_binding()
{
    OptionBinding<JamOptions> binding;
    bind_jam_protocol(binding, [](JamOptions& options) -> JamOptions& { return options; });
    binding.boolean(&JamOptions::decompress, "decompress",
                    "after pressure_max, expand back through the same pressures to onset (Fig. 9.13b-d)");
    return binding;
}

void run_jam(const JamOptions& options, RunContext& context)
{
    context.record_seed(options.seed);
    const JamResult result = jam(options);
    context.count_steps(result.fire_iterations);
    // ParaView frames, one per pressure state (onset, compression, decompression), the state's index as the
    // time value (the pressure goes back down on decompression) with P, phi and the branch as field data:
    // the particles, the box and the contacts between particles.
    if (auto* series = context.vtk()) {
        DpmSystem system = result.system;
        for (std::size_t k = 0; k < result.states.size(); ++k) {
            if (!series->next()) continue;
            const JamState& state = result.states[k];
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
    const double phi_c = result.states.front().phi;
    auto& table = context.table("pressure.dat", {{"phi", "1", "packing fraction (eq. 9.22 or disk area)"},
                                                 {"dphi", "1", "phi - phi_c"},
                                                 {"P", "k_c or k_a a0", "pressure Tr(Sigma)/2, eq. (9.26)"},
                                                 {"decompression", "1", "0 compression, 1 decompression"}});
    for (const JamState& state : result.states)
        table.row({state.phi, state.phi - phi_c, state.pressure, state.decompression ? 1.0 : 0.0});
    auto& summary = context.summary();
    summary["phi_c"] = phi_c;
    summary["states"] = result.states.size();
    // Back at onset after decompression: a different phi_c means an irreversible rearrangement
    // (Fig. 9.13b-d).
    if (options.decompress) {
        summary["phi_c_decompression"] = result.states.back().phi;
        summary["phi_c_shift"] = result.states.back().phi - phi_c;
    } else {
        summary["phi_c_decompression"] = nullptr;
        summary["phi_c_shift"] = nullptr;
    }
    const CompressionBranchFit fit = fit_compression_branch(result.states);
    summary["bulk_modulus"] = value_or_null(fit.bulk_modulus);
    summary["pressure_exponent"] = value_or_null(fit.pressure_exponent);
}

} // namespace

// The bidisperse packings of dpm.jam's parameters, also those of dpm.compress_box, dpm.shear_modulus and
// dpm.slump.
BidispersePacking bidisperse_packing(const JamOptions& options)
{
    return {options.particles, options.nodes_small, options.nodes_large,
            options.model == JamModel::smooth_disk};
}

double bidisperse_vertices(const BidispersePacking& packing)
{
    const auto particles = static_cast<double>(packing.particles);
    if (packing.disks) return particles;
    return particles * (static_cast<double>(packing.nodes_small) + packing.nodes_large) / 2;
}

const char* bidisperse_basis(const BidispersePacking& packing)
{
    return packing.disks ? "disks (particles)" : "vertices (particles x (nodes_small + nodes_large) / 2)";
}

MemoryEstimate bidisperse_memory(const BidispersePacking& packing)
{
    return dpm_vertex_memory(bidisperse_vertices(packing), bidisperse_basis(packing));
}

Scene jam_scene()
{
    return bound_scene(
               "dpm.jam",
               "DPM sec. 9.4: jamming onset of bidisperse disks or deformable particles by compression "
               "+ FIRE with bisection on the pressure; P against phi - phi_c (Fig. 9.13)",
               jam_binding(), run_jam)
        .needing(jam_binding().estimate(
            [](const JamOptions& options) { return bidisperse_memory(bidisperse_packing(options)); }))
        .with_vtk();
}

} // namespace softgrain::dpm
