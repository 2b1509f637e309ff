// dpm.packing_fraction: a jammed packing of rough deformable particles and its packing fraction from
// eqs. (9.18)-(9.22) against Monte-Carlo integration, term by term (Table 9.2, Fig. 9.12).
#include "dpm/packing_scene.hpp"

#include "core/output.hpp"
#include "dpm/packing.hpp"
#include "dpm/packing_fraction.hpp"
#include "dpm/vtk_frames.hpp"

namespace softgrain::dpm {

void run_packing_fraction(const Parameters& p, RunContext& context)
{
    PackingOptions o;
    o.particles = static_cast<int>(p.integer("particles"));
    o.nodes = static_cast<int>(p.integer("nodes"));
    o.C = p.real("C");
    o.kl = p.real("kl");
    o.kb = p.real("kb");
    o.ka = p.real("ka");
    o.seed = static_cast<std::uint64_t>(p.integer("seed"));
    context.record_seed(o.seed);
    const Packing packing = jam_packing(o);
    context.count_steps(packing.fire_iterations);
    const long samples = p.integer("samples");
    const PackingAreas a = packing_areas_analytic(packing.system, packing.x);
    const PackingAreasEstimate mc = packing_areas_monte_carlo(
        packing.system, packing.x, samples, static_cast<std::uint64_t>(p.integer("mc_seed")));

    auto& s = context.summary();
    s["phi_analytic"] = a.phi;
    s["phi_monte_carlo"] = mc.value.phi;
    s["phi_monte_carlo_error"] = mc.error.phi;
    const std::pair<const char*, double PackingAreas::*> terms[] = {{"A_polygon", &PackingAreas::polygon},
                                                                    {"A_vertices", &PackingAreas::vertices},
                                                                    {"A_sector", &PackingAreas::sector},
                                                                    {"A_pair", &PackingAreas::pair}};
    for (const auto& [name, field] : terms) {
        s[std::string(name) + "_analytic"] = a.*field;
        s[std::string(name) + "_monte_carlo"] = mc.value.*field;
        s[std::string(name) + "_monte_carlo_error"] = mc.error.*field;
    }
    s["box"] = packing.system.box->x();
    s["compression_steps"] = packing.compression_steps;
    // One ParaView frame (time 0) of the jammed packing: the particles, the box and the contacts, with the
    // analytic phi of eq. (9.22) as field data.
    if (auto* series = context.vtk(); series && series->next()) {
        std::vector<vtk::Part> parts{{"particles", dpm_particles(packing.system, packing.x)},
                                     {"box", box_outline(*packing.system.box)},
                                     {"contacts", dpm_contacts(packing.system, packing.x)}};
        for (auto& part : parts)
            part.data.field("phi", a.phi);
        series->write(0.0, parts);
    }

    auto& vertices = context.table(
        "vertices.dat", {{"particle", "1", "particle index"},
                         {"x", "sigma", "vertex x (particle unwrapped)"},
                         {"y", "sigma", "vertex y"},
                         {"L", "sigma", "box side"},
                         {"closing", "1", "1 on the repeated first vertex that closes the outline"}});
    for (std::size_t m = 0; m < packing.system.particles.size(); ++m) {
        const Particle& q = packing.system.particles[m];
        for (int v = 0; v <= q.count; ++v) {
            const int w = q.first + v % q.count;
            vertices.row({double(m), packing.x(2 * w), packing.x(2 * w + 1), packing.system.box->x(),
                          v == q.count ? 1.0 : 0.0});
        }
    }
}

std::vector<ParameterSpec> packing_fraction_parameters()
{
    return {
        ParameterSpec::seed("seed", 12, "seed of the random initial placement (the packing)"),
        ParameterSpec::integer("particles", 7, "1", "particles N (Fig. 9.12: 7)").at_least(2),
        ParameterSpec::integer("nodes", 5, "1", "vertices per particle N_mu (Fig. 9.12: 5)").at_least(3),
        ParameterSpec::real("C", 0.726, "1",
                            "R/sigma: circumradius over vertex diameter (Table 9.2 implies 0.726)")
            .positive(),
        ParameterSpec::real("kl", 2.0, "k_c", "edge stiffness k_l/k_c (Fig. 9.12: 2)").positive(),
        ParameterSpec::real("kb", 0.3, "k_c sigma^2", "bending stiffness k_b/(k_c sigma^2) (Fig. 9.12: 0.3)")
            .positive(),
        ParameterSpec::real("ka", 0.9, "k_c sigma^2/a0^2",
                            "area stiffness k_a a0^2/(k_c sigma^2) (Fig. 9.12: 0.9)")
            .positive(),
        ParameterSpec::integer("samples", 1000000, "1", "Monte-Carlo points").at_least(1000),
        ParameterSpec::seed("mc_seed", 1, "seed of the Monte-Carlo points"),
    };
}

} // namespace softgrain::dpm
