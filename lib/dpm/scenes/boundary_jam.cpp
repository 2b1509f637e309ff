// dpm.boundary_jam: jammed packings of 4 disks inside a floppy deformable boundary (DPM Fig. 9.18a-e), one
// packing per trial (seed, seed + 1, ...); the distinct packings are counted by their contact number and
// theta. With ka > 0 (Fig. 9.18f) the boundary has an area term and the trials are repeated at each
// preferred shape parameter A0 of a scan; the continuity of theta(A0) is measured by the largest gap.
#include "dpm/scenes/scenes.hpp"

#include "core/errors.hpp"
#include "core/output.hpp"
#include "dpm/analysis/vtk_frames.hpp"
#include "dpm/protocols/boundary_jam.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace softgrain::dpm {

namespace {

// dpm.boundary_jam's options: the boundary, the trials, and with ka > 0 the scan of its A0 (Fig. 9.18f).
struct BoundaryJamSceneOptions
{
    BoundaryJamOptions boundary;
    int trials = 20;
    double A0_min = 1.04, A0_max = 1.1;
    int A0_steps = 25;
};

// ka > 0: the scan's ends must be ordered and each give a feasible ring (initial_boundary refuses one
// below A_min or with edges longer than the vertex diameter), refused before any trial runs.
void check_A0_scan(const BoundaryJamSceneOptions& options)
{
    if (!(options.boundary.ka > 0)) return;
    if (!(options.A0_max >= options.A0_min))
        throw InputError("A0_max = " + std::to_string(options.A0_max) +
                         ": must be >= A0_min = " + std::to_string(options.A0_min));
    for (const auto& [key, A0] : {std::pair{"A0_min", options.A0_min}, std::pair{"A0_max", options.A0_max}}) {
        BoundaryJamOptions ring = options.boundary;
        ring.A0 = A0;
        try {
            initial_boundary(ring);
        } catch (const InputError& error) {
            throw InputError(std::string(key) + " = " + std::to_string(A0) + ": " + error.what());
        }
    }
}

OptionBinding<BoundaryJamSceneOptions> boundary_jam_binding()
{
    const auto boundary = [](auto field) { return path(&BoundaryJamSceneOptions::boundary, field); };
    OptionBinding<BoundaryJamSceneOptions> binding;
    binding
        .integer(&BoundaryJamSceneOptions::trials, "trials", "1",
                 "random initial conditions, one jammed packing each")
        .at_least(1);
    binding
        .integer(boundary(&BoundaryJamOptions::boundary_nodes), "boundary_nodes", "1",
                 "vertices N_mu of the boundary (paper: 100)")
        .at_least(8);
    binding
        .real(boundary(&BoundaryJamOptions::boundary_sigma), "boundary_sigma", "d",
              "boundary vertex diameter")
        .positive();
    binding.real(boundary(&BoundaryJamOptions::kl), "kl", "k_c", "boundary edge stiffness k_l/k_c")
        .positive();
    binding.seed(boundary(&BoundaryJamOptions::seed), "seed", "seed of the first trial");
    binding
        .real(boundary(&BoundaryJamOptions::ka), "ka", "k_c/d^2",
              "area stiffness k_a of the boundary (eq. 9.1); 0: floppy (Fig. 9.18a-e), > 0: fluid-filled "
              "boundary scanned over A0 (Fig. 9.18f)")
        .non_negative();
    binding
        .real(&BoundaryJamSceneOptions::A0_min, "A0_min", "1",
              "ka > 0: first preferred shape parameter A0 of the boundary")
        .at_least(1.0);
    binding.real(&BoundaryJamSceneOptions::A0_max, "A0_max", "1", "ka > 0: last A0 of the scan")
        .at_least(1.0);
    binding.integer(&BoundaryJamSceneOptions::A0_steps, "A0_steps", "1", "ka > 0: A0 values, equally spaced")
        .at_least(1);
    binding.check(check_A0_scan);
    return binding;
}

// ka = 0: one A0-free series of trials (Fig. 9.18a-e); ka > 0: trials at each A0 of the scan (9.18f).
std::vector<double> A0_scan(const BoundaryJamSceneOptions& options)
{
    if (!(options.boundary.ka > 0)) return {std::numeric_limits<double>::quiet_NaN()};
    const int points = options.A0_steps;
    const double low = options.A0_min, high = options.A0_max;
    std::vector<double> scan;
    for (int k = 0; k < points; ++k)
        scan.push_back(points == 1 ? low : low + (high - low) * k / (points - 1));
    return scan;
}

// One jammed packing per trial: `trials` trials at each A0 of the scan, trial k from seed + k.
struct BoundaryTrial
{
    double A0 = 0; // NaN: ka = 0
    BoundaryJamResult packing;
};

std::vector<BoundaryTrial> jam_trials(const BoundaryJamSceneOptions& options)
{
    std::vector<BoundaryTrial> done;
    BoundaryJamOptions trial = options.boundary;
    for (const double A0 : A0_scan(options))
        for (int t = 0; t < options.trials; ++t) {
            trial.seed = options.boundary.seed + done.size();
            trial.A0 = A0;
            done.push_back({A0, jam_in_boundary(trial)});
        }
    return done;
}

// A ParaView frame per packing (the trial k as the time value): the disks (vertex cells) and the ring (a
// polygon), the contacts (disk-disk and disk-ring), and the packing's description.
void write_frames(vtk::Series& series, const std::vector<BoundaryTrial>& trials)
{
    for (std::size_t k = 0; k < trials.size(); ++k) {
        if (!series.next()) continue;
        const BoundaryJamResult& packing = trials[k].packing;
        std::vector<vtk::Part> parts{{"particles", dpm_particles(packing.system, packing.x)},
                                     {"contacts", dpm_contacts(packing.system, packing.x)}};
        for (auto& part : parts) {
            part.data.field("disk_contacts", packing.disk_contacts);
            part.data.field("theta", packing.theta);
            part.data.field("energy", packing.energy);
            part.data.field("A0", trials[k].A0);
        }
        series.write(static_cast<double>(k), parts);
    }
}

void run_boundary_jam(const BoundaryJamSceneOptions& options, RunContext& context)
{
    context.record_seed(options.boundary.seed);
    const std::vector<BoundaryTrial> trials = jam_trials(options);

    auto& packings =
        context.table("packings.dat", {{"trial", "1", "trial k (seed + k), counted over the whole scan"},
                                       {"contacts", "1", "disk-disk contacts"},
                                       {"theta", "deg", "smaller parallelogram angle; NaN: no 4-cycle"},
                                       {"energy", "k_c d^2", "energy at jamming"},
                                       {"A0", "1", "preferred shape parameter of the ring (NaN: ka = 0)"}});
    auto& snapshots = context.table("snapshots.dat", {{"trial", "1", "trial k"},
                                                      {"particle", "1", "0-3 disks, 4 the boundary"},
                                                      {"x", "d", "centre or vertex x"},
                                                      {"y", "d", "centre or vertex y"},
                                                      {"radius", "d", "disk or vertex radius"}});
    std::map<int, std::vector<double>> thetas; // by contact number; NaN without a 4-cycle
    std::vector<double> all_thetas;
    long iterations = 0;
    for (std::size_t k = 0; k < trials.size(); ++k) {
        const BoundaryJamResult& packing = trials[k].packing;
        iterations += packing.iterations;
        packings.row({double(k), double(packing.disk_contacts), packing.theta, packing.energy, trials[k].A0});
        thetas[packing.disk_contacts].push_back(packing.theta);
        all_thetas.push_back(packing.theta);
        for (std::size_t m = 0; m < packing.system.particles.size(); ++m) {
            const Particle& particle = packing.system.particles[m];
            for (int v = 0; v <= (particle.count > 1 ? particle.count : 0); ++v) {
                const int w = particle.first + v % particle.count;
                snapshots.row(
                    {double(k), double(m), packing.x(2 * w), packing.x(2 * w + 1), 0.5 * particle.sigma});
            }
        }
    }
    if (auto* series = context.vtk()) write_frames(*series, trials);
    context.count_steps(iterations);
    auto& summary = context.summary();
    summary["distinct_packings"] = count_distinct_packings(thetas);
    summary["trials"] = trials.size();
    summary["largest_theta_gap_over_range"] = largest_gap_over_range(all_thetas);
    const ThetaRange range = theta_range(all_thetas);
    summary["packings_with_4_cycle"] = range.packings;
    summary["theta_min"] = value_or_null(range.min);
    summary["theta_max"] = value_or_null(range.max);
}

} // namespace

Scene boundary_jam_scene()
{
    return bound_scene("dpm.boundary_jam",
                       "DPM Fig. 9.18(a-e): jammed packings of 4 disks inside a floppy deformable boundary, "
                       "distinct packings by contacts and parallelogram angle",
                       boundary_jam_binding(), run_boundary_jam)
        .needing(boundary_jam_binding().estimate([](const BoundaryJamSceneOptions& options) {
            // The boundary's dense Hessian (4 disks beside it).
            return dense_matrix_memory(2.0 * options.boundary.boundary_nodes + 12, 1,
                                       "2 x boundary_nodes + 12");
        }))
        .with_vtk();
}

} // namespace softgrain::dpm
