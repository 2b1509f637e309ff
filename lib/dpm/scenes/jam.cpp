// dpm.jam: jamming onset and compression of bidisperse packings (section 9.4, Fig. 9.13): P against
// phi - phi_c, phi_c and the bulk modulus B of <P> = B (phi - phi_c), for one packing or an ensemble
// (`packings`, spread over MPI ranks under mpirun) with the ensemble means and their standard errors.
#include "dpm/scenes/scenes.hpp"

#include "core/ensemble.hpp"
#include "core/fits.hpp"
#include "core/output.hpp"
#include "dpm/analysis/vtk_frames.hpp"
#include "dpm/protocols/jam.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace softgrain::dpm {

namespace {

// dpm.jam's options: the protocol of each packing and the ensemble's size.
struct JamSceneOptions
{
    JamOptions jam;
    int packings = 1;
};

OptionBinding<JamSceneOptions> jam_binding()
{
    OptionBinding<JamSceneOptions> binding;
    bind_jam_protocol(binding, &JamSceneOptions::jam);
    binding.boolean(path(&JamSceneOptions::jam, &JamOptions::decompress), "decompress",
                    "after pressure_max, expand back through the same pressures to onset (Fig. 9.13b-d)");
    binding
        .integer(&JamSceneOptions::packings, "packings", "1",
                 "ensemble size: packings seeded seed, seed + 1, ... (under mpirun spread over the ranks)")
        .at_least(1);
    return binding;
}

// One packing of the ensemble: its pressure states (onset first) and the fits of its compression branch, in
// the model's pressure unit. It travels between MPI ranks as JSON (core/ensemble.hpp).
struct JamPacking
{
    std::vector<double> phi, pressure;
    std::vector<int> decompression;                 // 1: reached by expanding from pressure_max
    double bulk_modulus = 0, pressure_exponent = 0; // NaN: no fit (fewer than two states above onset)
    long fire_iterations = 0;
};
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(JamPacking, phi, pressure, decompression, bulk_modulus, pressure_exponent,
                                   fire_iterations)

JamPacking jam_packing(const JamResult& result)
{
    JamPacking packing;
    for (const JamState& state : result.states) {
        packing.phi.push_back(state.phi);
        packing.pressure.push_back(state.pressure);
        packing.decompression.push_back(state.decompression ? 1 : 0);
    }
    const CompressionBranchFit fit = fit_compression_branch(result.states);
    const double none = std::numeric_limits<double>::quiet_NaN();
    packing.bulk_modulus = fit.bulk_modulus.value_or(none);
    packing.pressure_exponent = fit.pressure_exponent.value_or(none);
    packing.fire_iterations = result.fire_iterations;
    return packing;
}

// ParaView frames, one per pressure state (onset, compression, decompression), the state's index as the
// time value (the pressure goes back down on decompression) with P, phi and the branch as field data: the
// particles, the box and the contacts between particles.
void write_frames(const JamResult& result, vtk::Series& series)
{
    DpmSystem system = result.system;
    for (std::size_t k = 0; k < result.states.size(); ++k) {
        if (!series.next()) continue;
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
        series.write(static_cast<double>(k), parts);
    }
}

// The ensemble mean of one quantity of the packings, with its spread (null below two packings).
void write_mean(const std::string& key, const std::vector<double>& values, nlohmann::json& summary)
{
    const SampleMean mean = sample_mean(values);
    summary[key] = finite_or_null(mean.mean);
    summary[key + "_standard_deviation"] = finite_or_null(mean.standard_deviation);
    summary[key + "_standard_error"] = finite_or_null(mean.standard_error);
}

void run_jam(const JamSceneOptions& options, RunContext& context)
{
    const std::uint64_t first_seed = options.jam.seed;
    context.record_seed(first_seed);
    // Independent packings (seeds first_seed, first_seed + 1, ...); ParaView frames of the first only, which
    // always runs on the first rank, the one that writes (core/ensemble.hpp: member k on rank k mod R).
    const std::vector<JamPacking> packings = run_ensemble<JamPacking>(options.packings, [&](int k) {
        JamOptions mine = options.jam;
        mine.seed = first_seed + static_cast<std::uint64_t>(k);
        const JamResult result = jam(mine);
        if (k == 0 && context.vtk()) write_frames(result, *context.vtk());
        return jam_packing(result);
    });

    auto& table = context.table("pressure.dat", {{"packing", "1", "k: the packing of seed seed + k"},
                                                 {"phi", "1", "packing fraction (eq. 9.22 or disk area)"},
                                                 {"dphi", "1", "phi - phi_c of this packing"},
                                                 {"P", "k_c or k_a a0", "pressure Tr(Sigma)/2, eq. (9.26)"},
                                                 {"decompression", "1", "0 compression, 1 decompression"}});
    auto& per_packing = context.table(
        "packings.dat", {{"packing", "1", "k"},
                         {"seed", "1", "seed + k"},
                         {"phi_c", "1", "packing fraction at onset"},
                         {"bulk_modulus", "k_c or k_a a0", "B of P = B (phi - phi_c), NaN without a fit"},
                         {"pressure_exponent", "1", "log-log slope of P against phi - phi_c"},
                         {"phi_c_shift", "1", "phi at onset after decompression - phi_c (NaN without)"},
                         {"fire_iterations", "1", "FIRE iterations of the whole protocol"}});
    std::vector<double> phi_c, bulk_modulus, pressure_exponent, phi_c_back, phi_c_shift;
    long fire_iterations = 0;
    std::size_t states = 0;
    for (std::size_t k = 0; k < packings.size(); ++k) {
        const JamPacking& packing = packings[k];
        const double onset = packing.phi.front();
        for (std::size_t s = 0; s < packing.phi.size(); ++s)
            table.row({static_cast<double>(k), packing.phi[s], packing.phi[s] - onset, packing.pressure[s],
                       static_cast<double>(packing.decompression[s])});
        // Back at onset after decompression: a different phi_c means an irreversible rearrangement
        // (Fig. 9.13b-d).
        const double shift =
            options.jam.decompress ? packing.phi.back() - onset : std::numeric_limits<double>::quiet_NaN();
        per_packing.row({static_cast<double>(k), static_cast<double>(first_seed + k), onset,
                         packing.bulk_modulus, packing.pressure_exponent, shift,
                         static_cast<double>(packing.fire_iterations)});
        phi_c.push_back(onset);
        bulk_modulus.push_back(packing.bulk_modulus);
        pressure_exponent.push_back(packing.pressure_exponent);
        phi_c_back.push_back(packing.phi.back());
        phi_c_shift.push_back(shift);
        fire_iterations += packing.fire_iterations;
        states += packing.phi.size();
    }
    context.count_steps(fire_iterations);

    // Ensemble means over the packings (one packing: its own values); a quantity that one packing lacks
    // (no fit) has no mean (null).
    auto& summary = context.summary();
    summary["packings"] = options.packings;
    summary["states"] = states;
    write_mean("phi_c", phi_c, summary);
    if (options.jam.decompress) {
        summary["phi_c_decompression"] = sample_mean(phi_c_back).mean;
        summary["phi_c_shift"] = sample_mean(phi_c_shift).mean;
    } else {
        summary["phi_c_decompression"] = nullptr;
        summary["phi_c_shift"] = nullptr;
    }
    write_mean("bulk_modulus", bulk_modulus, summary);
    write_mean("pressure_exponent", pressure_exponent, summary);
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
               "+ FIRE with bisection on the pressure; P against phi - phi_c (Fig. 9.13), one packing or an "
               "ensemble over MPI ranks",
               jam_binding(), run_jam)
        .needing(jam_binding().estimate([](const JamSceneOptions& options) {
            return bidisperse_memory(bidisperse_packing(options.jam));
        }))
        .with_vtk();
}

} // namespace softgrain::dpm
