// dpm.compress_box: soft disks or deformable particles compressed uniaxially by 20 % in a square box with
// repulsive walls (DPM Fig. 9.4): snapshots, wall pressures, overlaps and facets.
#include "dpm/box_compress_scene.hpp"

#include "core/output.hpp"
#include "dpm/box_compress.hpp"
#include "dpm/vtk_frames.hpp"

namespace softgrain::dpm {

void run_compress_box(const Parameters& p, RunContext& context)
{
    BoxCompressOptions o;
    o.deformable = p.choice("model") == "deformable";
    o.particles = static_cast<int>(p.integer("particles"));
    o.nodes_small = static_cast<int>(p.integer("nodes_small"));
    o.nodes_large = static_cast<int>(p.integer("nodes_large"));
    o.pressure_start = p.real("pressure_start");
    o.strain = p.real("strain");
    o.steps = static_cast<int>(p.integer("steps"));
    o.seed = static_cast<std::uint64_t>(p.integer("seed"));
    context.record_seed(o.seed);
    const BoxCompressResult r = compress_in_box(o);
    context.count_steps(r.iterations);
    const DpmSystem& s = r.system;

    auto& pressures = context.table(
        "pressure.dat",
        {{"strain", "1", "1 - h/h0 of the uniaxial stage"},
         {"P_x", "k_a a0", "force per length on the side walls"},
         {"P_y", "k_a a0", "force per length on the top wall"},
         {"max_overlap", "D_small", "deepest overlap of vertices (disks) of different particles"}});
    const double h0 = r.states.front().height;
    for (const BoxState& state : r.states)
        pressures.row({1 - state.height / h0, state.pressure_x, state.pressure_y,
                       largest_interparticle_overlap(s, state.x) / r.diameter_small});

    // ParaView frames, one per state (P0 reached, then each uniaxial step), the strain 1 - h/h0 as the time
    // value: the particles, the walls (the box [0, w] x [0, h]) and the contacts, with the strain and the wall
    // pressures [k_a a0] as field data.
    if (auto* series = context.vtk())
        for (const BoxState& state : r.states) {
            if (!series->next()) continue;
            const double strain = 1 - state.height / h0;
            std::vector<vtk::Part> parts{{"particles", dpm_particles(s, state.x)},
                                         {"walls", box_outline({state.width, state.height})},
                                         {"contacts", dpm_contacts(s, state.x)}};
            for (auto& part : parts) {
                part.data.field("strain", strain);
                part.data.field("pressure_x", state.pressure_x);
                part.data.field("pressure_y", state.pressure_y);
            }
            series->write(strain, parts);
        }

    // Snapshots before (frame 1) and after (frame 2) the uniaxial compression: disks as circles, deformable
    // particles as edges (vectors) and vertex disks; the box as four edges with particle = -1.
    auto& snapshots = context.table("snapshots.dat", {{"frame", "1", "1 = start (P0), 2 = after the strain"},
                                                      {"particle", "1", "index; -1 = box wall"},
                                                      {"x", "sigma", "vertex or edge start x"},
                                                      {"y", "sigma", "vertex or edge start y"},
                                                      {"dx", "sigma", "edge vector x (0 for a disk)"},
                                                      {"dy", "sigma", "edge vector y"},
                                                      {"radius", "sigma", "vertex (disk) radius"}});
    for (int frame : {1, 2}) {
        const BoxState& state = frame == 1 ? r.states.front() : r.states.back();
        const double w = state.width, h = state.height;
        for (const auto& [x0, y0, ex, ey] :
             {std::array<double, 4>{0, 0, w, 0}, {w, 0, 0, h}, {w, h, -w, 0}, {0, h, 0, -h}})
            snapshots.row({double(frame), -1, x0, y0, ex, ey, 0});
        for (std::size_t m = 0; m < s.particles.size(); ++m) {
            const Particle& q = s.particles[m];
            for (int k = 0; k < q.count; ++k) {
                const int v = q.first + k, next = q.first + (k + 1) % q.count;
                const Eigen::Vector2d a = state.x.segment<2>(2 * v), e = state.x.segment<2>(2 * next) - a;
                snapshots.row({double(frame), double(m), a.x(), a.y(), e.x(), e.y(), 0.5 * q.sigma});
            }
        }
    }

    const BoxState &start = r.states.front(), &end = r.states.back();
    double polygon_area = 0;
    for (const Particle& q : s.particles)
        polygon_area += q.count > 2 ? particle_area(end.x, q.first, q.count) : 0.0;
    auto& summary = context.summary();
    summary["pressure_start"] = 0.5 * (start.pressure_x + start.pressure_y);
    summary["pressure_end_y"] = end.pressure_y;
    summary["pressure_end_x"] = end.pressure_x;
    summary["max_overlap_start"] = largest_interparticle_overlap(s, start.x) / r.diameter_small;
    summary["max_overlap_end"] = largest_interparticle_overlap(s, end.x) / r.diameter_small;
    summary["diameter_small"] = r.diameter_small;
    summary["vertex_contacts_per_contact_end"] = vertex_contacts_per_particle_contact(s, end.x);
    summary["polygon_area_fraction_end"] = polygon_area / (end.width * end.height);
    summary["pressure_unit_over_kc"] = r.pressure_unit;
}

std::vector<ParameterSpec> compress_box_parameters()
{
    return {
        ParameterSpec::choice("model", "disks", {"disks", "deformable"},
                              "soft disks (Fig. 9.4a) or rough elastic-shell deformable particles (9.4b)"),
        ParameterSpec::integer("particles", 32, "1", "particles, 50:50 bidisperse with size ratio 1.4")
            .at_least(2),
        ParameterSpec::integer("nodes_small", 16, "1", "deformable: vertices of the small particles")
            .at_least(3),
        ParameterSpec::integer("nodes_large", 22, "1", "deformable: vertices of the large particles")
            .at_least(3),
        ParameterSpec::real("pressure_start", 1e-2, "k_a a0", "wall pressure P0 reached isotropically first")
            .positive(),
        ParameterSpec::real("strain", 0.2, "1", "uniaxial compression of the box height (paper: 20 %)")
            .positive()
            .below(1.0),
        ParameterSpec::integer("steps", 20, "1", "steps of the uniaxial compression").at_least(1),
        ParameterSpec::seed("seed", 1, "seed of the random placement and orientations"),
    };
}

} // namespace softgrain::dpm
