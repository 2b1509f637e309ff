// dpm.rearrangement: the first irreversible change of the contact network of a compressed smooth-disk
// packing (Fig. 9.13(e, f)); both packings with their contacts, the pressure jump and how many particles
// the change involves.
#include "dpm/rearrangement_scene.hpp"

#include "core/output.hpp"
#include "dpm/rearrangement.hpp"
#include "dpm/vtk_frames.hpp"

#include <cmath>

namespace softgrain::dpm {

namespace {

// Disk centres wrapped into the box, for drawing.
void write_disks(Table& table, const DpmSystem& s, const PackingState& state, int which,
                 const NetworkChange& change)
{
    for (std::size_t m = 0; m < s.particles.size(); ++m) {
        const Eigen::Vector2d w = wrap_into_box(state.x.segment<2>(2 * m), state.box);
        table.row(
            {double(which), double(m), w.x(), w.y(), s.particles[m].sigma, change.changed[m] ? 1.0 : 0.0});
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

} // namespace

void run_rearrangement(const Parameters& p, RunContext& context)
{
    RearrangementOptions o;
    o.jam.model = "smooth_disk";
    o.jam.particles = static_cast<int>(p.integer("particles"));
    o.jam.seed = static_cast<std::uint64_t>(p.integer("seed"));
    o.jam.pressure_onset = p.real("pressure_onset");
    o.dphi = p.real("dphi");
    o.max_steps = static_cast<int>(p.integer("max_steps"));
    context.record_seed(o.jam.seed);
    const RearrangementResult r =
        context.vtk() ? find_rearrangement(o, frame_writer(*context.vtk())) : find_rearrangement(o);
    context.count_steps(r.fire_iterations);
    auto& s = context.summary();
    s["phi_c"] = r.phi_c;
    s["contact_overlap_threshold"] = r.min_overlap;
    s["found"] = r.found;
    s["elastic_network_changes"] = r.elastic_changes;
    if (!r.found) {
        for (const char* key :
             {"step", "phi_before", "phi_after", "pressure_previous", "pressure_before", "pressure_after",
              "pressure_reversed", "pressure_jump_over_elastic", "contacts_before", "contacts_after",
              "contacts_broken", "contacts_formed", "particles_changed", "fraction_particles_changed"})
            s[key] = nullptr;
        return;
    }
    const int n = static_cast<int>(r.system.particles.size());
    const NetworkChange change = compare_networks(r.before.contacts, r.after.contacts, n);
    s["step"] = r.step;
    s["phi_before"] = r.before.phi;
    s["phi_after"] = r.after.phi;
    s["pressure_previous"] = r.previous.pressure;
    s["pressure_before"] = r.before.pressure;
    s["pressure_after"] = r.after.pressure;
    s["pressure_reversed"] = r.reversed.pressure;
    // 1 on an elastic branch (P linear in phi over two steps), away from 1 at a discontinuity of P(phi).
    s["pressure_jump_over_elastic"] = (r.after.pressure - r.before.pressure) /
                                      (r.before.pressure - r.previous.pressure) *
                                      (r.before.phi - r.previous.phi) / (r.after.phi - r.before.phi);
    s["contacts_before"] = r.before.contacts.size();
    s["contacts_after"] = r.after.contacts.size();
    s["contacts_broken"] = change.only_before.size();
    s["contacts_formed"] = change.only_after.size();
    s["particles_changed"] = change.particles_changed;
    s["fraction_particles_changed"] = double(change.particles_changed) / n;

    auto& disks = context.table("disks.dat", {{"state", "1", "0 before, 1 after the step"},
                                              {"particle", "1", "index"},
                                              {"x", "sigma_small", "centre wrapped into the box"},
                                              {"y", "sigma_small", "centre wrapped into the box"},
                                              {"diameter", "sigma_small", "disk diameter"},
                                              {"changed", "1", "1 if one of its contacts broke or formed"}});
    write_disks(disks, r.system, r.before, 0, change);
    write_disks(disks, r.system, r.after, 1, change);
    auto& contacts = context.table(
        "contacts.dat", {{"state", "1", "0 before, 1 after the step"},
                         {"i", "1", "particle"},
                         {"j", "1", "particle"},
                         {"x", "sigma_small", "wrapped centre of i"},
                         {"y", "sigma_small", "wrapped centre of i"},
                         {"dx", "sigma_small", "minimum image r_j - r_i"},
                         {"dy", "sigma_small", "minimum image r_j - r_i"},
                         {"kind", "1", "0 in both networks, 1 only before (broken), 2 only after (formed)"}});
    write_contacts(contacts, r.before, 0, r.after.contacts, 1);
    write_contacts(contacts, r.after, 1, r.before.contacts, 2);
    auto& box = context.table("box.dat", {{"state", "1", "0 before, 1 after"},
                                          {"L", "sigma_small", "side of the periodic square box"}});
    box.row({0.0, r.before.box.x()});
    box.row({1.0, r.after.box.x()});
}

std::vector<ParameterSpec> rearrangement_parameters()
{
    return {
        ParameterSpec::integer("particles", 64, "1",
                               "smooth disks N, half small (sigma = 1), half large (1.4)")
            .at_least(2),
        ParameterSpec::seed("seed", 1, "seed of the random initial placement"),
        ParameterSpec::real("pressure_onset", 1e-6, "k_c", "P_t: jamming onset pressure the search starts at")
            .positive(),
        ParameterSpec::real("dphi", 1e-5, "1", "compression step Delta phi (Fig. 9.13e, f: ~1e-5)")
            .positive(),
        ParameterSpec::integer("max_steps", 2000, "1", "compression steps searched before giving up")
            .at_least(1),
    };
}

} // namespace softgrain::dpm
