// dpm.packing_fraction: a jammed packing of rough deformable particles and its packing fraction from
// eqs. (9.18)-(9.22) against Monte-Carlo integration, term by term (Table 9.2, Fig. 9.12).
#include "dpm/scenes/scenes.hpp"

#include "core/output.hpp"
#include "dpm/analysis/packing_fraction.hpp"
#include "dpm/analysis/vtk_frames.hpp"
#include "dpm/protocols/packing.hpp"

namespace softgrain::dpm {

namespace {

// dpm.packing_fraction's options: the packing (Fig. 9.12) and the Monte-Carlo points that check its areas.
struct PackingFractionOptions
{
    PackingOptions packing;
    int samples = 1000000;
    std::uint64_t mc_seed = 1;
};

// The packing of Fig. 9.12 from seed 12 (PackingOptions' other defaults are the figure's).
PackingFractionOptions packing_fraction_defaults()
{
    PackingFractionOptions defaults;
    defaults.packing.seed = 12;
    return defaults;
}

OptionBinding<PackingFractionOptions> packing_fraction_binding()
{
    const auto packing = [](auto field) { return path(&PackingFractionOptions::packing, field); };
    OptionBinding<PackingFractionOptions> binding(packing_fraction_defaults());
    binding.seed(packing(&PackingOptions::seed), "seed",
                 "seed of the random initial placement (the packing)");
    binding.integer(packing(&PackingOptions::particles), "particles", "1", "particles N (Fig. 9.12: 7)")
        .at_least(2);
    binding
        .integer(packing(&PackingOptions::nodes), "nodes", "1", "vertices per particle N_mu (Fig. 9.12: 5)")
        .at_least(3);
    binding
        .real(packing(&PackingOptions::C), "C", "1",
              "R/sigma: circumradius over vertex diameter (Table 9.2 implies 0.726)")
        .positive();
    binding.real(packing(&PackingOptions::kl), "kl", "k_c", "edge stiffness k_l/k_c (Fig. 9.12: 2)")
        .positive();
    binding
        .real(packing(&PackingOptions::kb), "kb", "k_c sigma^2",
              "bending stiffness k_b/(k_c sigma^2) (Fig. 9.12: 0.3)")
        .positive();
    binding
        .real(packing(&PackingOptions::ka), "ka", "k_c sigma^2/a0^2",
              "area stiffness k_a a0^2/(k_c sigma^2) (Fig. 9.12: 0.9)")
        .positive();
    binding.integer(&PackingFractionOptions::samples, "samples", "1", "Monte-Carlo points").at_least(1000);
    binding.seed(&PackingFractionOptions::mc_seed, "mc_seed", "seed of the Monte-Carlo points");
    return binding;
}

void run_packing_fraction(const PackingFractionOptions& options, RunContext& context)
{
    context.record_seed(options.packing.seed);
    const Packing packing = jam_packing(options.packing);
    context.count_steps(packing.fire_iterations);
    const PackingAreas analytic = packing_areas_analytic(packing.system, packing.x);
    const PackingAreasEstimate monte_carlo =
        packing_areas_monte_carlo(packing.system, packing.x, options.samples, options.mc_seed);

    auto& summary = context.summary();
    summary["phi_analytic"] = analytic.phi;
    summary["phi_monte_carlo"] = monte_carlo.value.phi;
    summary["phi_monte_carlo_error"] = monte_carlo.error.phi;
    const std::pair<const char*, double PackingAreas::*> terms[] = {{"A_polygon", &PackingAreas::polygon},
                                                                    {"A_vertices", &PackingAreas::vertices},
                                                                    {"A_sector", &PackingAreas::sector},
                                                                    {"A_pair", &PackingAreas::pair}};
    for (const auto& [name, field] : terms) {
        summary[std::string(name) + "_analytic"] = analytic.*field;
        summary[std::string(name) + "_monte_carlo"] = monte_carlo.value.*field;
        summary[std::string(name) + "_monte_carlo_error"] = monte_carlo.error.*field;
    }
    summary["box"] = packing.system.box->x();
    summary["compression_steps"] = packing.compression_steps;
    // One ParaView frame (time 0) of the jammed packing: the particles, the box and the contacts, with the
    // analytic phi of eq. (9.22) as field data.
    if (auto* series = context.vtk(); series && series->next()) {
        std::vector<vtk::Part> parts{{"particles", dpm_particles(packing.system, packing.x)},
                                     {"box", box_outline(*packing.system.box)},
                                     {"contacts", dpm_contacts(packing.system, packing.x)}};
        for (auto& part : parts)
            part.data.field("phi", analytic.phi);
        series->write(0.0, parts);
    }

    auto& vertices = context.table(
        "vertices.dat", {{"particle", "1", "particle index"},
                         {"x", "sigma", "vertex x (particle unwrapped)"},
                         {"y", "sigma", "vertex y"},
                         {"L", "sigma", "box side"},
                         {"closing", "1", "1 on the repeated first vertex that closes the outline"}});
    for (std::size_t m = 0; m < packing.system.particles.size(); ++m) {
        const Particle& particle = packing.system.particles[m];
        for (int v = 0; v <= particle.count; ++v) {
            const int w = particle.first + v % particle.count;
            vertices.row({double(m), packing.x(2 * w), packing.x(2 * w + 1), packing.system.box->x(),
                          v == particle.count ? 1.0 : 0.0});
        }
    }
}

} // namespace

Scene packing_fraction_scene()
{
    return bound_scene("dpm.packing_fraction",
                       "DPM eqs. (9.18)-(9.22): packing fraction of a jammed packing of rough particles, "
                       "analytic against Monte-Carlo, term by term (Table 9.2)",
                       packing_fraction_binding(), run_packing_fraction)
        .needing(packing_fraction_binding().estimate([](const PackingFractionOptions& options) {
            return dpm_vertex_memory(double(options.packing.particles) * double(options.packing.nodes),
                                     "vertices (particles x nodes)");
        }))
        .with_vtk();
}

} // namespace softgrain::dpm
