// dpm.boundary_jam: jammed packings of 4 disks inside a floppy deformable boundary (DPM Fig. 9.18a-e), one
// packing per trial (seed, seed + 1, ...); the distinct packings are counted by their contact number and
// theta.
#include "dpm/boundary_jam_scene.hpp"

#include "core/output.hpp"
#include "dpm/boundary_jam.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

namespace softgrain::dpm {

void run_boundary_jam(const Parameters& p, RunContext& context)
{
    BoundaryJamOptions o;
    o.boundary_nodes = static_cast<int>(p.integer("boundary_nodes"));
    o.boundary_sigma = p.real("boundary_sigma");
    o.kl = p.real("kl");
    const auto seed = static_cast<std::uint64_t>(p.integer("seed"));
    context.record_seed(seed);
    const int trials = static_cast<int>(p.integer("trials"));
    auto& packings =
        context.table("packings.dat", {{"trial", "1", "trial k (seed + k)"},
                                       {"contacts", "1", "disk-disk contacts"},
                                       {"theta", "deg", "smaller parallelogram angle; NaN: no 4-cycle"},
                                       {"energy", "k_c d^2", "energy at jamming"}});
    auto& snapshots = context.table("snapshots.dat", {{"trial", "1", "trial k"},
                                                      {"particle", "1", "0-3 disks, 4 the boundary"},
                                                      {"x", "d", "centre or vertex x"},
                                                      {"y", "d", "centre or vertex y"},
                                                      {"radius", "d", "disk or vertex radius"}});
    std::map<int, std::vector<double>> thetas; // by contact number; NaN without a 4-cycle
    long iterations = 0;
    for (int k = 0; k < trials; ++k) {
        o.seed = seed + static_cast<std::uint64_t>(k);
        const BoundaryJamResult r = jam_in_boundary(o);
        iterations += r.iterations;
        packings.row({double(k), double(r.disk_contacts), r.theta, r.energy});
        thetas[r.disk_contacts].push_back(r.theta);
        for (std::size_t m = 0; m < r.system.particles.size(); ++m) {
            const Particle& q = r.system.particles[m];
            for (int v = 0; v <= (q.count > 1 ? q.count : 0); ++v) {
                const int w = q.first + v % q.count;
                snapshots.row({double(k), double(m), r.x(2 * w), r.x(2 * w + 1), 0.5 * q.sigma});
            }
        }
    }
    context.count_steps(iterations);
    // Distinct packings (decision dpm-boundary-jam): same contact number and theta within 1 degree of a
    // neighbour in the sorted list (single linkage); packings without a 4-cycle count once per contact
    // number.
    int distinct = 0;
    for (auto& [contacts, list] : thetas) {
        std::vector<double> angles;
        bool without_cycle = false;
        for (double t : list) {
            if (std::isnan(t))
                without_cycle = true;
            else
                angles.push_back(t);
        }
        distinct += without_cycle;
        std::sort(angles.begin(), angles.end());
        for (std::size_t k = 0; k < angles.size(); ++k)
            distinct += k == 0 || angles[k] - angles[k - 1] > 1.0;
    }
    context.summary()["distinct_packings"] = distinct;
    context.summary()["trials"] = trials;
}

std::vector<ParameterSpec> boundary_jam_parameters()
{
    return {
        ParameterSpec::integer("trials", 20, "1", "random initial conditions, one jammed packing each")
            .at_least(1),
        ParameterSpec::integer("boundary_nodes", 100, "1", "vertices N_mu of the boundary (paper: 100)")
            .at_least(8),
        ParameterSpec::real("boundary_sigma", 0.25, "d", "boundary vertex diameter").positive(),
        ParameterSpec::real("kl", 1.0, "k_c", "boundary edge stiffness k_l/k_c").positive(),
        ParameterSpec::integer("seed", 1, "1", "seed of the first trial").non_negative(),
    };
}

} // namespace softgrain::dpm
