#include "dpm/protocols/rearrangement.hpp"

#include "core/errors.hpp"
#include "dpm/analysis/modes.hpp"
#include "dpm/analysis/stress.hpp"
#include "dpm/relax/newton_relax.hpp"

#include <cmath>
#include <string>

namespace softgrain::dpm {

ContactNetwork disk_contacts(const DpmSystem& system, const Eigen::VectorXd& x, double min_overlap)
{
    for (const Particle& p : system.particles)
        if (p.count != 1)
            throw InputError("disk_contacts: a particle has " + std::to_string(p.count) +
                             " vertices; only disks (one vertex) are allowed");
    if (!(min_overlap >= 0))
        throw InputError("disk_contacts: min_overlap = " + std::to_string(min_overlap) + "; allowed >= 0");
    ContactNetwork contacts; // disks: vertex i is particle i
    for (const VertexContact& c : vertex_contacts(system, x))
        if (c.sigma - c.r.norm() > min_overlap) contacts.insert({c.i, c.j});
    return contacts;
}

NetworkChange compare_networks(const ContactNetwork& before, const ContactNetwork& after, int particles)
{
    NetworkChange change;
    change.changed.assign(particles, false);
    const auto mark = [&](const ContactPair& c) {
        change.changed[c.first] = change.changed[c.second] = true;
    };
    for (const ContactPair& c : before)
        if (!after.contains(c)) {
            change.only_before.push_back(c);
            mark(c);
        }
    for (const ContactPair& c : after)
        if (!before.contains(c)) {
            change.only_after.push_back(c);
            mark(c);
        }
    for (bool b : change.changed)
        change.particles_changed += b ? 1 : 0;
    return change;
}

RearrangementResult find_rearrangement(const RearrangementOptions& options,
                                       const RearrangementObserver& observe)
{
    if (options.jam.model != JamModel::smooth_disk)
        throw InputError("model = " + jam_model_name(options.jam.model) +
                         ": the rearrangement search is for smooth_disk packings");
    JamOptions onset_only = options.jam;
    onset_only.pressures = 0; // stop at the onset P_t
    JamResult jammed = jam(onset_only);
    RearrangementResult out;
    out.system = jammed.system;
    out.fire_iterations = jammed.fire_iterations;
    out.fire = jammed.fire;
    DpmSystem& s = out.system;
    // A contact force must exceed the FIRE residual by a decade to count (decision
    // dpm-rearrangement-contact).
    out.min_overlap = options.min_overlap > 0 ? options.min_overlap : 10 * jammed.fire.force_tolerance / s.kc;

    const auto relax = [&](Eigen::VectorXd& x, int step) {
        const FireResult r = relax_fire(s, x, jammed.fire);
        out.fire_iterations += r.iterations;
        if (!r.converged)
            throw NumericalError(
                "relaxation after a compression step of Delta phi = " + std::to_string(options.dphi) + " (" +
                    fire_shortfall(r, jammed.fire) + ")",
                step, "force tolerance too small for the pressure; raise pressure_onset");
    };
    const auto state_of = [&](const Eigen::VectorXd& x) {
        return PackingState{packing_fraction(s, x), pressure(stress_tensor(s, x)) / jammed.pressure_unit, x,
                            *s.box, disk_contacts(s, x, out.min_overlap)};
    };
    // Moves the system to the packing fraction phi + dphi (box area scales as 1/phi).
    const auto compress_by = [&](Eigen::VectorXd& x, double phi, double dphi) {
        scale_packing(s, x, std::sqrt(phi / (phi + dphi)));
    };

    PackingState current = state_of(jammed.states.front().x);
    out.phi_c = current.phi;
    out.previous = current;
    if (observe) observe(0, s, current, false, false);
    for (int step = 1; step <= options.max_steps; ++step) {
        Eigen::VectorXd x = current.x;
        compress_by(x, current.phi, options.dphi);
        relax(x, step);
        PackingState next = state_of(x);
        if (next.contacts != current.contacts) {
            Eigen::VectorXd back = x;
            compress_by(back, next.phi, current.phi - next.phi);
            relax(back, step);
            PackingState reversed = state_of(back);
            *s.box = next.box;
            if (reversed.contacts != current.contacts) {
                if (observe) observe(step, s, next, true, true);
                out.found = true;
                out.step = step;
                out.before = current;
                out.after = next;
                out.reversed = reversed;
                return out;
            }
            ++out.elastic_changes;
        }
        if (observe) observe(step, s, next, next.contacts != current.contacts, false);
        out.previous = current;
        current = std::move(next);
    }
    return out;
}

} // namespace softgrain::dpm
