// dpm.rearrangement: the first irreversible change of the contact network of a compressed smooth-disk
// packing (Fig. 9.13(e, f)); both packings with their contacts, the pressure jump and how many particles
// the change involves.
#include "dpm/scenes/scenes.hpp"

#include "core/output.hpp"
#include "dpm/analysis/vtk_frames.hpp"
#include "dpm/protocols/rearrangement.hpp"

#include <cmath>

namespace softgrain::dpm {

namespace {

// dpm.rearrangement's defaults: a larger packing of smooth disks than dpm.jam's, from a higher onset.
RearrangementOptions rearrangement_defaults()
{
    RearrangementOptions defaults;
    defaults.jam.model = JamModel::smooth_disk;
    defaults.jam.particles = 64;
    defaults.jam.pressure_onset = 1e-6;
    return defaults;
}

OptionBinding<RearrangementOptions> rearrangement_binding()
{
    const auto jam = [](auto field) { return path(&RearrangementOptions::jam, field); };
    OptionBinding<RearrangementOptions> binding(rearrangement_defaults());
    binding
        .integer(jam(&JamOptions::particles), "particles", "1",
                 "smooth disks N, half small (sigma = 1), half large (1.4)")
        .at_least(2);
    binding.seed(jam(&JamOptions::seed), "seed", "seed of the random initial placement");
    bind_fire_step(binding, jam(&JamOptions::fire_step));
    binding
        .real(jam(&JamOptions::pressure_onset), "pressure_onset", "k_c",
              "P_t: jamming onset pressure the search starts at")
        .positive();
    binding
        .real(&RearrangementOptions::dphi, "dphi", "1", "compression step Delta phi (Fig. 9.13e, f: ~1e-5)")
        .positive();
    binding
        .integer(&RearrangementOptions::max_steps, "max_steps", "1",
                 "compression steps searched before giving up")
        .at_least(1);
    return binding;
}

// Disk centres wrapped into the box, for drawing.
void write_disks(Table& table, const DpmSystem& system, const PackingState& state, int which,
                 const NetworkChange& change)
{
    for (std::size_t m = 0; m < system.particles.size(); ++m) {
        const Eigen::Vector2d w = wrap_into_box(state.x.segment<2>(2 * m), state.box);
        table.row({double(which), double(m), w.x(), w.y(), system.particles[m].sigma,
                   change.changed[m] ? 1.0 : 0.0});
    }
}

// One row per contact of `state`: from the wrapped centre of i to the minimum image of j (may leave the
// box); kind 0 kept, 1 only before (broken), 2 only after (formed).
void write_contacts(Table& table, const PackingState& state, int which, const ContactNetwork& other,
                    int own_kind)
{
    for (const auto& [i, j] : state.contacts) {
        const Eigen::Vector2d ci = state.x.segment<2>(2 * i);
        const Eigen::Vector2d wi = wrap_into_box(ci, state.box);
        const Eigen::Vector2d d = minimum_image(state.x.segment<2>(2 * j) - ci, state.box);
        table.row({double(which), double(i), double(j), wi.x(), wi.y(), d.x(), d.y(),
                   other.contains({i, j}) ? 0.0 : double(own_kind)});
    }
}

// ParaView frames: the onset (step 0) and each compression step (--vtk-every N: every N-th, and always the
// rearrangement), the step as the time value: the disks (vertex cells), the box and the contacts (every
// touching pair; the scene's network counts those with overlap above contact_overlap_threshold). Field data:
// step, phi, pressure [k_c], network_contacts (the network's size), network_changed (1 if it differs from
// the previous step's) and irreversible (1 on the step of the rearrangement, the last frame).
RearrangementObserver frame_writer(vtk::Series& series)
{
    return [&series](int step, const DpmSystem& system, const PackingState& state, bool network_changed,
                     bool irreversible) {
        if (!series.next() && !irreversible) return;
        DpmSystem at_state = system;
        at_state.box = state.box;
        std::vector<vtk::Part> parts{{"particles", dpm_particles(at_state, state.x)},
                                     {"box", box_outline(state.box)},
                                     {"contacts", dpm_contacts(at_state, state.x)}};
        for (auto& part : parts) {
            part.data.field("step", step);
            part.data.field("phi", state.phi);
            part.data.field("pressure", state.pressure);
            part.data.field("network_contacts", static_cast<double>(state.contacts.size()));
            part.data.field("network_changed", network_changed ? 1.0 : 0.0);
            part.data.field("irreversible", irreversible ? 1.0 : 0.0);
        }
        series.write(step, parts);
    };
}

void run_rearrangement(const RearrangementOptions& options, RunContext& context)
{
    context.record_seed(options.jam.seed);
    const RearrangementResult result = context.vtk()
                                           ? find_rearrangement(options, frame_writer(*context.vtk()))
                                           : find_rearrangement(options);
    context.count_steps(result.fire_iterations);
    auto& summary = context.summary();
    summary["phi_c"] = result.phi_c;
    summary["contact_overlap_threshold"] = result.min_overlap;
    summary["found"] = result.found;
    summary["elastic_network_changes"] = result.elastic_changes;
    if (!result.found) {
        for (const char* key :
             {"step", "phi_before", "phi_after", "pressure_previous", "pressure_before", "pressure_after",
              "pressure_reversed", "pressure_jump_over_elastic", "contacts_before", "contacts_after",
              "contacts_broken", "contacts_formed", "particles_changed", "fraction_particles_changed"})
            summary[key] = nullptr;
        return;
    }
    const int particles = static_cast<int>(result.system.particles.size());
    const NetworkChange change = compare_networks(result.before.contacts, result.after.contacts, particles);
    summary["step"] = result.step;
    summary["phi_before"] = result.before.phi;
    summary["phi_after"] = result.after.phi;
    summary["pressure_previous"] = result.previous.pressure;
    summary["pressure_before"] = result.before.pressure;
    summary["pressure_after"] = result.after.pressure;
    summary["pressure_reversed"] = result.reversed.pressure;
    // 1 on an elastic branch (P linear in phi over two steps), away from 1 at a discontinuity of P(phi).
    summary["pressure_jump_over_elastic"] = (result.after.pressure - result.before.pressure) /
                                            (result.before.pressure - result.previous.pressure) *
                                            (result.before.phi - result.previous.phi) /
                                            (result.after.phi - result.before.phi);
    summary["contacts_before"] = result.before.contacts.size();
    summary["contacts_after"] = result.after.contacts.size();
    summary["contacts_broken"] = change.only_before.size();
    summary["contacts_formed"] = change.only_after.size();
    summary["particles_changed"] = change.particles_changed;
    summary["fraction_particles_changed"] = double(change.particles_changed) / particles;

    auto& disks = context.table("disks.dat", {{"state", "1", "0 before, 1 after the step"},
                                              {"particle", "1", "index"},
                                              {"x", "sigma_small", "centre wrapped into the box"},
                                              {"y", "sigma_small", "centre wrapped into the box"},
                                              {"diameter", "sigma_small", "disk diameter"},
                                              {"changed", "1", "1 if one of its contacts broke or formed"}});
    write_disks(disks, result.system, result.before, 0, change);
    write_disks(disks, result.system, result.after, 1, change);
    auto& contacts = context.table(
        "contacts.dat", {{"state", "1", "0 before, 1 after the step"},
                         {"i", "1", "particle"},
                         {"j", "1", "particle"},
                         {"x", "sigma_small", "wrapped centre of i"},
                         {"y", "sigma_small", "wrapped centre of i"},
                         {"dx", "sigma_small", "minimum image r_j - r_i"},
                         {"dy", "sigma_small", "minimum image r_j - r_i"},
                         {"kind", "1", "0 in both networks, 1 only before (broken), 2 only after (formed)"}});
    write_contacts(contacts, result.before, 0, result.after.contacts, 1);
    write_contacts(contacts, result.after, 1, result.before.contacts, 2);
    auto& box = context.table("box.dat", {{"state", "1", "0 before, 1 after"},
                                          {"L", "sigma_small", "side of the periodic square box"}});
    box.row({0.0, result.before.box.x()});
    box.row({1.0, result.after.box.x()});
}

} // namespace

Scene rearrangement_scene()
{
    return bound_scene("dpm.rearrangement",
                       "DPM Fig. 9.13(e, f): the first irreversible change of the contact network of a "
                       "smooth-disk packing compressed from onset in steps Delta phi; both networks",
                       rearrangement_binding(), run_rearrangement)
        .needing(rearrangement_binding().estimate([](const RearrangementOptions& options) {
            return dpm_vertex_memory(options.jam.particles, "disks (particles)");
        }))
        .with_vtk();
}

} // namespace softgrain::dpm
