#include "spd/shell_contacts.hpp"

#include "core/checkpoint.hpp"
#include "core/errors.hpp"
#include "core/geometry.hpp"
#include "spd/force_laws.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <string>
#include <utility>

namespace softgrain::spd {

void ShellContacts::add_vertices(int count)
{
    const Eigen::Index old_dofs = contact_force_.size();
    contact_force_.conservativeResize(old_dofs + 2 * count);
    contact_force_.tail(2 * count).setZero();
    contact_normal_.resize(contact_normal_.size() + count, 0.0);
    neighbours_.reset(); // the vertex set changed: a new contact list
}

// Contact candidates (decision spd-contact-detection): a vertex c within r_i + r_j of an element AB of length
// l is within sqrt((r_i + r_j)^2 + (l/2)^2) of A or B. A Verlet list of all vertices
// (core/neighbour_list.hpp: cell list with a skin) with that cutoff, l bounded by L + skin (L the longest
// deformable element at the build, each end moving less than skin/2 before the next one), therefore lists a
// vertex of every element it can touch; its candidates are the elements adjacent to its listed neighbours of
// other shells. Rigid shells (walls) have long elements: every free vertex is a candidate of every rigid
// element (O(N) per wall). The candidates are rebuilt with the list only, O(N) at fixed density; friction
// histories carry over.
void ShellContacts::update_candidates(const ShellView& model, std::int64_t step)
{
    const std::vector<Shell>& shells = model.shells;
    const auto shell_of = [&](int i) { return model.shell_of[i]; };
    const int n = static_cast<int>(model.x.size() / 2);
    double r_all = 0, r_free = 0;
    for (const Shell& s : shells) {
        r_all = std::max(r_all, s.radius);
        if (!s.rigid) r_free = std::max(r_free, s.radius);
    }
    const double reach = r_all + r_free;
    const auto longest_element = [&] {
        double L = 0;
        for (const Shell& s : shells)
            if (!s.rigid)
                for (int k = 0; k < s.elements(); ++k)
                    L = std::max(L, (model.vertex(next_vertex(s, k)) - model.vertex(s.first + k)).norm());
        return L;
    };
    const Eigen::Map<const Points<2>> positions(model.x.data(), 2, n);
    const auto make_list = [&](double L) {
        list_length_ = 1.25 * L; // headroom: element growth up to 25% keeps the list
        const double skin = std::max(reach, 0.5 * list_length_);
        const double l_bound = list_length_ + skin;
        neighbours_.emplace(std::sqrt(reach * reach + 0.25 * l_bound * l_bound), skin);
    };
    // Called when the list is stale (a vertex beyond half the skin, or there is none).
    if (!neighbours_)
        make_list(longest_element());
    else if (const double L = longest_element(); L > list_length_) // an element outgrew the cutoff's bound
        make_list(L);
    neighbours_->build(positions);
    ++list_builds_;

    std::vector<Candidate> fresh;
    const auto add = [&](int i, int a, int b) {
        fresh.push_back({i, a, b, shells[shell_of(i)].radius + shells[shell_of(a)].radius});
    };
    const auto add_adjacent_elements = [&](int i, int j) { // elements of shell_of(j) that end at j
        const Shell& s = shells[shell_of(j)];
        const int local = j - s.first;
        if (local < s.elements()) add(i, j, next_vertex(s, local));
        if (s.closed || local > 0) add(i, previous_vertex(s, local), j);
    };
    // Each vertex's list neighbours (compressed rows), so that the candidates are made vertex by vertex and
    // only each vertex's few need sorting by element: the order (vertex, a) of the friction carry-over and
    // of the gather.
    std::vector<int> row(n + 1, 0);
    for (const auto& [i, j] : neighbours_->pairs()) {
        ++row[i + 1];
        ++row[j + 1];
    }
    std::partial_sum(row.begin(), row.end(), row.begin());
    std::vector<int> neighbour(row.back()), fill(row.begin(), row.end() - 1);
    for (const auto& [i, j] : neighbours_->pairs()) {
        neighbour[fill[i]++] = j;
        neighbour[fill[j]++] = i;
    }
    // Walls have few, long elements that a vertex list does not see: each free vertex is paired with the wall
    // elements within reach + skin (neither moves more than skin/2 before the next rebuild).
    const double wall_reach = reach + neighbours_->skin();
    std::vector<const Shell*> walls;
    for (const Shell& s : shells)
        if (s.rigid) walls.push_back(&s);
    const auto by_element = [](const Candidate& u, const Candidate& w) { return u.a < w.a; };
    const auto same_element = [](const Candidate& u, const Candidate& w) { return u.a == w.a; };
    for (int i = 0; i < n; ++i) {
        const auto begin = static_cast<std::ptrdiff_t>(fresh.size());
        for (int k = row[i]; k < row[i + 1]; ++k) {
            const int j = neighbour[k];
            if (shell_of(i) != shell_of(j) && !shells[shell_of(j)].rigid) add_adjacent_elements(i, j);
        }
        if (!shells[shell_of(i)].rigid)
            for (const Shell* wall : walls)
                for (int k = 0; k < wall->elements(); ++k) {
                    const int a = wall->first + k, b = next_vertex(*wall, k);
                    if (point_segment_proximity(model.vertex(i), model.vertex(a), model.vertex(b)).distance <
                        wall_reach)
                        add(i, a, b);
                }
        std::sort(fresh.begin() + begin, fresh.end(), by_element);
        fresh.erase(std::unique(fresh.begin() + begin, fresh.end(), same_element), fresh.end());
    }
    const auto key = [](const Candidate& c) { return std::make_pair(c.vertex, c.a); };
    // Both lists are sorted: carry the friction history of pairs that stay candidates.
    auto old = candidates_.begin();
    for (Candidate& c : fresh) {
        while (old != candidates_.end() && key(*old) < key(c))
            ++old;
        if (old != candidates_.end() && key(*old) == key(c)) c.friction = old->friction;
    }
    candidates_.swap(fresh);
    index_candidates(model.shell_of, step);
}

// The two indexes of the candidates: the contact groups (runs of one vertex against one other shell), and
// per vertex the candidates acting on it in candidate order (a counting sort by vertex, stable in m).
void ShellContacts::index_candidates(const std::vector<int>& shell_of, std::int64_t step)
{
    contact_groups_.clear();
    for (std::size_t m = 0; m < candidates_.size(); ++m)
        if (m == 0 || candidates_[m].vertex != candidates_[m - 1].vertex ||
            shell_of[candidates_[m].a] != shell_of[candidates_[m - 1].a])
            contact_groups_.push_back(m);
    contact_groups_.push_back(candidates_.size());

    if (candidates_.size() >= (std::size_t{1} << 30))
        throw NumericalError("contact candidates", step,
                             std::to_string(candidates_.size()) + " candidates, above the 2^30 of the index");
    const std::size_t vertices = shell_of.size();
    touched_.assign(vertices, 0);
    gather_offsets_.assign(vertices + 1, 0);
    for (const Candidate& c : candidates_)
        for (const int i : {c.vertex, c.a, c.b})
            ++gather_offsets_[i + 1];
    std::partial_sum(gather_offsets_.begin(), gather_offsets_.end(), gather_offsets_.begin());
    gather_terms_.resize(gather_offsets_.back());
    std::vector<std::size_t> fill(gather_offsets_.begin(), gather_offsets_.end() - 1);
    for (std::size_t m = 0; m < candidates_.size(); ++m) {
        const Candidate& c = candidates_[m];
        const auto term = static_cast<std::uint32_t>(m << 2);
        gather_terms_[fill[c.vertex]++] = term | role_vertex;
        gather_terms_[fill[c.a]++] = term | role_end_a;
        gather_terms_[fill[c.b]++] = term | role_end_b;
    }
}

// The cheap rejection before the exact distance: the vertex lies outside the bounding box of the
// sphero-segment (the case of nearly all candidates at a step).
inline bool ShellContacts::outside_bounding_box(const ShellView& model, const Candidate& cand) const
{
    const double reach = cand.reach;
    const Vec2 c = model.vertex(cand.vertex), A = model.vertex(cand.a), B = model.vertex(cand.b);
    return c.x() < std::min(A.x(), B.x()) - reach || c.x() > std::max(A.x(), B.x()) + reach ||
           c.y() < std::min(A.y(), B.y()) - reach || c.y() > std::max(A.y(), B.y()) + reach;
}

// Section 2.3: one vertex against one element of another shell (a sphero-segment), written into the
// candidate's record. A contact with an element end (branches a < 0, a > l of Fig. 4) is a vertex-vertex
// contact; it is counted once, with the element that starts at that end (or, for the last vertex of an open
// shell, that ends there). Called for a candidate inside the bounding box, its record reset; old_friction is
// its tangential force of the previous step.
void ShellContacts::evaluate(const ShellView& model, Candidate& cand, double old_friction, double dt) const
{
    const int i = cand.vertex, a = cand.a, b = cand.b;
    const Shell& sq = model.shells[model.shell_of[a]];
    const double reach = cand.reach;
    const Vec2 c = model.vertex(i), A = model.vertex(a), B = model.vertex(b);
    const SegmentProximity prox = point_segment_proximity(c, A, B);
    if (prox.distance >= reach) return;
    // The sphero-segment law holds while the vertex centre stays on its side of the element: at distance
    // 0 the normal flips and the vertex tunnels through (a wall cannot hold it).
    if (prox.distance < 0.05 * reach) {
        cand.overlap = true;
        return;
    }
    const bool last_end = !sq.closed && b == sq.first + sq.count - 1;
    if (prox.branch == SegmentBranch::end_b && !last_end) return; // counted with the next element
    const auto w = transfer_weights(std::clamp(prox.a, 0.0, prox.length), prox.length);
    const Eigen::VectorXd& v = model.v;
    const Vec2 v_rel = v.segment<2>(2 * i) - w[0] * v.segment<2>(2 * a) - w[1] * v.segment<2>(2 * b);
    const double fn = std::max(0.0, normal_contact_force(law_.k_n, prox.distance, reach) -
                                        law_.normal_damping * v_rel.dot(prox.normal));
    Vec2 F = fn * prox.normal;
    if (law_.mu > 0) {
        const Vec2 t(prox.normal.y(), -prox.normal.x()); // t = n x z (section 2.3)
        cand.friction = coulomb_friction_update(old_friction, law_.k_t, v_rel.dot(t) * dt, law_.mu, fn);
        F += cand.friction * t;
    }
    cand.active = true;
    cand.distance = prox.distance;
    cand.fn = fn;
    cand.w_a = w[0];
    cand.w_b = w[1];
    cand.force = F;
}

std::vector<ContactView> ShellContacts::active(const ShellView& model) const
{
    std::vector<ContactView> out;
    for (const Candidate& cand : candidates_)
        if (cand.active)
            out.push_back({cand.vertex, cand.a, cand.b,
                           point_segment_proximity(model.vertex(cand.vertex), model.vertex(cand.a),
                                                   model.vertex(cand.b))
                               .closest,
                           cand.fn, cand.friction, cand.force});
    return out;
}

// One contact per (vertex, other shell): the nearest of its touching elements (decision
// spd-contact-nearest-element). At a concave corner of the other shell a vertex lies within reach of both
// adjacent elements and projects inside both; counting both doubles the force there, and the second term
// vanishes abruptly when the projection leaves its element: a jump of the contact energy that injects
// energy into a vertex sliding across the corner. The distance to the nearest element is continuous, so is
// the energy. The group holds the candidates of one vertex against the elements of one other shell. A
// friction history dropped here restarts at zero (the scenes of section 5 are frictionless).
bool ShellContacts::evaluate_group(const ShellView& model, long g, double dt)
{
    const std::size_t begin = contact_groups_[g], end = contact_groups_[g + 1];
    std::size_t nearest = end;
    bool overlap = false;
    for (std::size_t k = begin; k < end; ++k) {
        Candidate& cand = candidates_[k];
        const double old_friction = cand.friction;
        cand.friction = 0; // a contact that opened loses its history
        cand.active = cand.overlap = false;
        if (outside_bounding_box(model, cand)) continue;
        evaluate(model, cand, old_friction, dt);
        overlap = overlap || cand.overlap;
        if (cand.active && (nearest == end || cand.distance < candidates_[nearest].distance)) nearest = k;
    }
    for (std::size_t k = begin; k < end; ++k)
        if (k != nearest && candidates_[k].active) {
            candidates_[k].active = false;
            candidates_[k].friction = 0;
        }
    if (nearest != end) {
        const Candidate& cand = candidates_[nearest];
        for (const int i : {cand.vertex, cand.a, cand.b})
#pragma omp atomic write
            touched_[i] = 1;
    }
    return overlap;
}

// The contact force on vertex i (its own contacts, and the reactions on it as an element end) and the
// normal force it receives as the contacting vertex, summed in candidate order: the order of a serial loop
// over the candidates, whatever the number of threads, so the forces do not depend on it, bit for bit.
Vec2 ShellContacts::gather(int i)
{
    Vec2 F = Vec2::Zero();
    double fn = 0;
    if (touched_[i])
        for (std::size_t t = gather_offsets_[i]; t < gather_offsets_[i + 1]; ++t) {
            const std::uint32_t term = gather_terms_[t];
            const Candidate& cand = candidates_[term >> 2];
            if (!cand.active) continue;
            switch (term & 3u) {
            case role_vertex:
                F += cand.force;
                fn += cand.fn;
                break;
            case role_end_a:
                F -= cand.w_a * cand.force;
                break;
            default:
                F -= cand.w_b * cand.force;
                break;
            }
        }
    touched_[i] = 0;
    contact_force_.segment<2>(2 * i) = F;
    contact_normal_[i] = fn;
    return F;
}

void ShellContacts::throw_overlap(const ShellView& model, std::int64_t step) const
{
    for (const Candidate& cand : candidates_) {
        if (!cand.overlap) continue;
        const int shell = model.shell_of[cand.vertex];
        const double reach = model.shells[shell].radius + model.shells[model.shell_of[cand.a]].radius;
        const double distance =
            point_segment_proximity(model.vertex(cand.vertex), model.vertex(cand.a), model.vertex(cand.b))
                .distance;
        std::ostringstream cause;
        cause << "contact overlap " << reach - distance << " m above 95% of r_i + r_j = " << reach
              << " m (vertex " << cand.vertex << " of particle " << shell
              << "): the load per contact vertex exceeds what k_n = " << law_.k_n
              << " N/m can hold before the vertex crosses the element; use more nodes (more contact "
                 "vertices share the load) or a stiffer contact";
        throw NumericalError("contact overlap", step, cause.str());
    }
}

Vec2 ShellContacts::force_on(const Shell& s) const
{
    Vec2 F = Vec2::Zero();
    for (int i = s.first; i < s.first + s.count; ++i)
        F += contact_force_.segment<2>(2 * i);
    return F;
}

void ShellContacts::Candidate::transfer(Archive& archive)
{
    archive(vertex);
    archive(a);
    archive(b);
    archive(reach);
    archive(friction);
    archive(active);
    archive(overlap);
    archive(fn);
    archive(w_a);
    archive(w_b);
    archive(distance);
    archive(force);
}

void ShellContacts::transfer_forces(Archive& archive)
{
    archive(contact_force_);
}

void ShellContacts::transfer_normals(Archive& archive)
{
    archive(contact_normal_);
}

void ShellContacts::transfer_candidates(Archive& archive, const std::vector<int>& shell_of, std::int64_t step)
{
    archive(candidates_);
    if (archive.loading()) index_candidates(shell_of, step); // the candidates' indexes follow from them
    bool listed = neighbours_.has_value();
    archive(listed);
    if (archive.loading()) {
        neighbours_.reset();
        if (listed) neighbours_.emplace(1.0, 0.0); // cutoff and skin are read next
    }
    if (listed) archive(*neighbours_);
    archive(list_length_);
    archive(list_builds_);
}

void ShellContacts::transfer_law(Archive& archive)
{
    archive(law_);
}

} // namespace softgrain::spd
