// Compression-induced rearrangement of a jammed packing of smooth disks, DPM section 9.4.2 and
// Fig. 9.13(e, f): "static packings of smooth disks (e) before and (f) after a rearrangement that causes a
// change in the contact network following compression by Delta phi ~ 1e-5".
//
// Protocol (decision dpm-rearrangement-search): jam a bidisperse smooth-disk packing to the onset P_t with
// dpm.jam's protocol (jam.hpp), then compress it in steps of Delta phi (centres scaled, FIRE after each,
// same FIRE settings). After a step that changes the contact network, expand back by the same factor and
// relax again: if the network then differs from the one before the step, the change is irreversible -- a
// rearrangement, a discontinuity of P(phi) (Fig. 9.13b) -- and the search stops; if it is restored, a
// contact only closed or opened elastically and the compression goes on from the compressed state.
// Contact (decision dpm-rearrangement-contact): disks i, j with overlap sigma_ij - r_ij above
// min_overlap [L] (eq. 9.4: their spring force is k_c times the overlap).
#pragma once

#include "dpm/protocols/jam.hpp"

#include <functional>
#include <set>
#include <utility>
#include <vector>

namespace softgrain::dpm {

using ContactPair = std::pair<int, int>; // particle indices i < j
using ContactNetwork = std::set<ContactPair>;

// Contacts of a packing of one-vertex particles (disks): pairs with sigma_ij - r_ij > min_overlap, minimum
// image in the system's box (min_overlap >= 0). Throws InputError if a particle has more than one vertex.
ContactNetwork disk_contacts(const DpmSystem& system, const Eigen::VectorXd& x, double min_overlap);

struct NetworkChange
{
    std::vector<ContactPair> only_before, only_after; // broken and formed contacts
    std::vector<bool> changed;                        // per particle: one of its contacts broke or formed
    int particles_changed = 0;
};
NetworkChange compare_networks(const ContactNetwork& before, const ContactNetwork& after, int particles);

struct RearrangementOptions
{
    JamOptions jam;         // model must be smooth_disk; only the onset is used
    double dphi = 1e-5;     // compression step Delta phi
    int max_steps = 2000;   // steps searched before giving up
    double min_overlap = 0; // contact threshold [L]; <= 0: 10 FIRE force tolerances / k_c
};

struct PackingState
{
    double phi = 0, pressure = 0; // pressure [k_c]
    Eigen::VectorXd x;
    Eigen::Vector2d box{};
    ContactNetwork contacts;
};

struct RearrangementResult
{
    DpmSystem system;
    double phi_c = 0;       // onset of the packing
    double min_overlap = 0; // the contact threshold used [L]
    bool found = false;
    int step = 0;               // compression steps from onset to `after`
    int elastic_changes = 0;    // network changes on the way that reversed when expanded back
    PackingState previous;      // one step before `before` (the elastic slope dP/dphi)
    PackingState before, after; // the step with the rearrangement
    PackingState reversed;      // `after` expanded back to phi(before) and relaxed
    long fire_iterations = 0;
    FireOptions fire; // the FIRE settings used (dpm.jam's)
};

// Called with the onset (step 0) and after each compression step, once the step is classified: the step, the
// system (its box that of `state`), the relaxed state, whether its contact network differs from the previous
// step's and whether that change is irreversible (the rearrangement: the last call).
using RearrangementObserver = std::function<void(int step, const DpmSystem& system, const PackingState& state,
                                                 bool network_changed, bool irreversible)>;

RearrangementResult find_rearrangement(const RearrangementOptions& options,
                                       const RearrangementObserver& observe = {});

} // namespace softgrain::dpm
