// dpm.compress_box: soft disks or deformable particles compressed uniaxially by 20 % in a square box with
// repulsive walls (DPM Fig. 9.4): snapshots, wall pressures, overlaps and facets.
#include "dpm/scenes/scenes.hpp"

#include "core/output.hpp"
#include "dpm/analysis/vtk_frames.hpp"
#include "dpm/protocols/box_compress.hpp"

namespace softgrain::dpm {

namespace {

OptionBinding<BoxCompressOptions> compress_box_binding()
{
    OptionBinding<BoxCompressOptions> binding;
    binding.choice(&BoxCompressOptions::deformable, "model", {{"disks", false}, {"deformable", true}},
                   "soft disks (Fig. 9.4a) or rough elastic-shell deformable particles (9.4b)");
    binding
        .integer(&BoxCompressOptions::particles, "particles", "1",
                 "particles, 50:50 bidisperse with size ratio 1.4")
        .at_least(2);
    binding
        .integer(&BoxCompressOptions::nodes_small, "nodes_small", "1",
                 "deformable: vertices of the small particles")
        .at_least(3);
    binding
        .integer(&BoxCompressOptions::nodes_large, "nodes_large", "1",
                 "deformable: vertices of the large particles")
        .at_least(3);
    binding
        .real(&BoxCompressOptions::pressure_start, "pressure_start", "k_a a0",
              "wall pressure P0 reached isotropically first")
        .positive();
    binding
        .real(&BoxCompressOptions::strain, "strain", "1",
              "uniaxial compression of the box height (paper: 20 %)")
        .positive()
        .below(1.0);
    binding.integer(&BoxCompressOptions::steps, "steps", "1", "steps of the uniaxial compression")
        .at_least(1);
    binding.seed(&BoxCompressOptions::seed, "seed", "seed of the random placement and orientations");
    return binding;
}

void run_compress_box(const BoxCompressOptions& options, RunContext& context)
{
    context.record_seed(options.seed);
    const BoxCompressResult result = compress_in_box(options);
    context.count_steps(result.iterations);
    const DpmSystem& system = result.system;

    auto& pressures = context.table(
        "pressure.dat",
        {{"strain", "1", "1 - h/h0 of the uniaxial stage"},
         {"P_x", "k_a a0", "force per length on the side walls"},
         {"P_y", "k_a a0", "force per length on the top wall"},
         {"max_overlap", "D_small", "deepest overlap of vertices (disks) of different particles"}});
    const double h0 = result.states.front().height;
    for (const BoxState& state : result.states)
        pressures.row({1 - state.height / h0, state.pressure_x, state.pressure_y,
                       largest_interparticle_overlap(system, state.x) / result.diameter_small});

    // ParaView frames, one per state (P0 reached, then each uniaxial step), the strain 1 - h/h0 as the time
    // value: the particles, the walls (the box [0, w] x [0, h]) and the contacts, with the strain and the wall
    // pressures [k_a a0] as field data.
    if (auto* series = context.vtk())
        for (const BoxState& state : result.states) {
            if (!series->next()) continue;
            const double strain = 1 - state.height / h0;
            std::vector<vtk::Part> parts{{"particles", dpm_particles(system, state.x)},
                                         {"walls", box_outline({state.width, state.height})},
                                         {"contacts", dpm_contacts(system, state.x)}};
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
        const BoxState& state = frame == 1 ? result.states.front() : result.states.back();
        const double w = state.width, h = state.height;
        for (const auto& [x0, y0, ex, ey] :
             {std::array<double, 4>{0, 0, w, 0}, {w, 0, 0, h}, {w, h, -w, 0}, {0, h, 0, -h}})
            snapshots.row({double(frame), -1, x0, y0, ex, ey, 0});
        for (std::size_t m = 0; m < system.particles.size(); ++m) {
            const Particle& particle = system.particles[m];
            for (int k = 0; k < particle.count; ++k) {
                const int v = particle.first + k, next = particle.first + (k + 1) % particle.count;
                const Eigen::Vector2d a = state.x.segment<2>(2 * v), e = state.x.segment<2>(2 * next) - a;
                snapshots.row({double(frame), double(m), a.x(), a.y(), e.x(), e.y(), 0.5 * particle.sigma});
            }
        }
    }

    const BoxState &start = result.states.front(), &end = result.states.back();
    double polygon_area = 0;
    for (const Particle& particle : system.particles)
        polygon_area += particle.count > 2 ? particle_area(end.x, particle.first, particle.count) : 0.0;
    auto& summary = context.summary();
    summary["pressure_start"] = 0.5 * (start.pressure_x + start.pressure_y);
    summary["pressure_end_y"] = end.pressure_y;
    summary["pressure_end_x"] = end.pressure_x;
    summary["max_overlap_start"] = largest_interparticle_overlap(system, start.x) / result.diameter_small;
    summary["max_overlap_end"] = largest_interparticle_overlap(system, end.x) / result.diameter_small;
    summary["diameter_small"] = result.diameter_small;
    summary["vertex_contacts_per_contact_end"] = vertex_contacts_per_particle_contact(system, end.x);
    summary["polygon_area_fraction_end"] = polygon_area / (end.width * end.height);
    summary["pressure_unit_over_kc"] = result.pressure_unit;
}

} // namespace

Scene compress_box_scene()
{
    return bound_scene(
               "dpm.compress_box",
               "DPM Fig. 9.4: soft disks or deformable particles compressed uniaxially by 20 % in a box "
               "with repulsive walls: snapshots, overlaps, facets",
               compress_box_binding(), run_compress_box)
        .needing(compress_box_binding().estimate([](const BoxCompressOptions& options) {
            return bidisperse_memory(
                {options.particles, options.nodes_small, options.nodes_large, !options.deformable});
        }))
        .with_vtk();
}

} // namespace softgrain::dpm
