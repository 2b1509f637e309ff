// dpm.boundary_jam: jammed packings of 4 disks inside a floppy deformable boundary (DPM Fig. 9.18a-e), one
// packing per trial (seed, seed + 1, ...); the distinct packings are counted by their contact number and
// theta. With ka > 0 (Fig. 9.18f) the boundary has an area term and the trials are repeated at each
// preferred shape parameter A0 of a scan; the continuity of theta(A0) is measured by the largest gap.
#include "dpm/boundary_jam_scene.hpp"

#include "core/errors.hpp"
#include "core/output.hpp"
#include "dpm/boundary_jam.hpp"
#include "dpm/vtk_frames.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace softgrain::dpm {

namespace {

// Distinct packings (decision dpm-boundary-jam): same contact number and theta within 1 degree of a
// neighbour in the sorted list (single linkage); packings without a 4-cycle count once per contact number.
int count_distinct(const std::map<int, std::vector<double>>& thetas)
{
    int distinct = 0;
    for (const auto& [contacts, list] : thetas) {
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
    return distinct;
}

// Fig. 9.18(f) measure of continuity: the largest gap between consecutive sorted thetas over their range.
// Five values (the floppy boundary's packings) give at least 1/4; a continuous curve tends to 0.
double largest_gap_over_range(std::vector<double> angles)
{
    std::erase_if(angles, [](double t) { return std::isnan(t); });
    if (angles.size() < 2) return std::numeric_limits<double>::quiet_NaN();
    std::sort(angles.begin(), angles.end());
    double gap = 0;
    for (std::size_t k = 1; k < angles.size(); ++k)
        gap = std::max(gap, angles[k] - angles[k - 1]);
    return gap / (angles.back() - angles.front());
}

} // namespace

void run_boundary_jam(const Parameters& p, RunContext& context)
{
    BoundaryJamOptions o;
    o.boundary_nodes = static_cast<int>(p.integer("boundary_nodes"));
    o.boundary_sigma = p.real("boundary_sigma");
    o.kl = p.real("kl");
    o.ka = p.real("ka");
    const auto seed = static_cast<std::uint64_t>(p.integer("seed"));
    context.record_seed(seed);
    const int trials = static_cast<int>(p.integer("trials"));
    // ka = 0: one A0-free series of trials (Fig. 9.18a-e); ka > 0: trials at each A0 of the scan (9.18f).
    std::vector<double> scan{std::numeric_limits<double>::quiet_NaN()};
    if (o.ka > 0) {
        const int points = static_cast<int>(p.integer("A0_steps"));
        const double low = p.real("A0_min"), high = p.real("A0_max");
        if (!(high >= low))
            throw InputError("A0_max = " + std::to_string(high) +
                             ": must be >= A0_min = " + std::to_string(low));
        scan.clear();
        for (int k = 0; k < points; ++k)
            scan.push_back(points == 1 ? low : low + (high - low) * k / (points - 1));
        for (const double A0 : {low, high}) { // refuse an infeasible scan before running it
            o.A0 = A0;
            initial_boundary(o);
        }
    }
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
    int k = 0;
    for (const double A0 : scan)
        for (int t = 0; t < trials; ++t, ++k) {
            o.seed = seed + static_cast<std::uint64_t>(k);
            o.A0 = A0;
            const BoundaryJamResult r = jam_in_boundary(o);
            iterations += r.iterations;
            packings.row({double(k), double(r.disk_contacts), r.theta, r.energy, A0});
            thetas[r.disk_contacts].push_back(r.theta);
            all_thetas.push_back(r.theta);
            // A ParaView frame per packing (the trial k as the time value): the disks (vertex cells) and the
            // ring (a polygon), the contacts (disk-disk and disk-ring), and the packing's description.
            if (auto* series = context.vtk(); series && series->next()) {
                std::vector<vtk::Part> parts{{"particles", dpm_particles(r.system, r.x)},
                                             {"contacts", dpm_contacts(r.system, r.x)}};
                for (auto& part : parts) {
                    part.data.field("disk_contacts", r.disk_contacts);
                    part.data.field("theta", r.theta);
                    part.data.field("energy", r.energy);
                    part.data.field("A0", A0);
                }
                series->write(k, parts);
            }
            for (std::size_t m = 0; m < r.system.particles.size(); ++m) {
                const Particle& q = r.system.particles[m];
                for (int v = 0; v <= (q.count > 1 ? q.count : 0); ++v) {
                    const int w = q.first + v % q.count;
                    snapshots.row({double(k), double(m), r.x(2 * w), r.x(2 * w + 1), 0.5 * q.sigma});
                }
            }
        }
    context.count_steps(iterations);
    context.summary()["distinct_packings"] = count_distinct(thetas);
    context.summary()["trials"] = k;
    context.summary()["largest_theta_gap_over_range"] = largest_gap_over_range(all_thetas);
    const auto finite =
        std::count_if(all_thetas.begin(), all_thetas.end(), [](double t) { return !std::isnan(t); });
    context.summary()["packings_with_4_cycle"] = finite;
    // The range of theta over every packing with a 4-cycle: touching equal disks bound it to [60, 90] deg
    // (the short diagonal of the rhombus cannot be shorter than d), up to the overlaps U < 2 U_t allows.
    double theta_min = std::numeric_limits<double>::infinity(), theta_max = -theta_min;
    for (double t : all_thetas)
        if (!std::isnan(t)) theta_min = std::min(theta_min, t), theta_max = std::max(theta_max, t);
    context.summary()["theta_min"] = finite > 0 ? nlohmann::json(theta_min) : nlohmann::json(nullptr);
    context.summary()["theta_max"] = finite > 0 ? nlohmann::json(theta_max) : nlohmann::json(nullptr);
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
        ParameterSpec::seed("seed", 1, "seed of the first trial"),
        ParameterSpec::real("ka", 0, "k_c/d^2",
                            "area stiffness k_a of the boundary (eq. 9.1); 0: floppy (Fig. 9.18a-e), > 0: "
                            "fluid-filled boundary scanned over A0 (Fig. 9.18f)")
            .non_negative(),
        ParameterSpec::real("A0_min", 1.04, "1", "ka > 0: first preferred shape parameter A0 of the boundary")
            .at_least(1.0),
        ParameterSpec::real("A0_max", 1.1, "1", "ka > 0: last A0 of the scan").at_least(1.0),
        ParameterSpec::integer("A0_steps", 25, "1", "ka > 0: A0 values, equally spaced").at_least(1),
    };
}

} // namespace softgrain::dpm
