// The contacts of the SPD shell model (Trivino et al., sections 2.3 and 2.4): the candidate (vertex,
// element) pairs from a vertex neighbour list, the sphero-segment contact law of eqs. (6)-(7) on each, one
// contact per vertex and other shell, and the contact force each vertex receives, gathered in candidate
// order so that it does not depend on the number of threads. Part of ShellModel (spd/shell_model.hpp),
// which owns the vertex state and calls these from its force evaluation.
#pragma once

#include "core/neighbour_list.hpp"
#include "core/vector.hpp"
#include "spd/shell.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <vector>

namespace softgrain {
class Archive;
}

namespace softgrain::spd {

// Contact law between shells: normal eq. (6), incremental Coulomb friction eq. (7) when mu > 0 (the scenes of
// sections 3-4 are frictionless: decision spd-ring-walls).
struct ContactLaw
{
    double k_n = 0; // [N/m]
    double k_t = 0; // [N/m]
    double mu = 0;  // friction coefficient
    // Normal viscous damping c_n [N s/m] for quasi-static relaxation only (decision spd-contact-damping): a
    // force -c_n (v_rel . n) while in contact, the total normal force kept repulsive. It vanishes at rest and
    // removes the chatter of a vertex at the edge of a flat contact (not part of eq. (6)).
    double normal_damping = 0;
};

// What the parts of ShellModel (its cores, contacts and links) read of it: positions and velocities (x and y
// of each vertex, interleaved), the shells and the shell of each vertex.
struct ShellView
{
    const Eigen::VectorXd& x;
    const Eigen::VectorXd& v;
    const std::vector<Shell>& shells;
    const std::vector<int>& shell_of;
    Vec2 vertex(int i) const { return {x[2 * i], x[2 * i + 1]}; }
};

// A contact of the last force evaluation: vertex against the element (a, b) of another shell, the closest
// point of the element [m], the normal force f_n (eq. (6)) and tangential force f_t (eq. (7)) [N] and the
// force on the vertex [N] (the element's ends receive its opposite).
struct ContactView
{
    int vertex, a, b;
    Vec2 point;
    double normal_force, tangential_force;
    Vec2 force;
};

class ShellContacts
{
  public:
    void set_law(ContactLaw law) { law_ = law; }
    const ContactLaw& law() const { return law_; }
    bool enabled() const { return law_.k_n > 0; }

    // The model gained `count` vertices (a new shell): zero contact forces for them, and a new list.
    void add_vertices(int count);

    // Whether the candidates must be rebuilt before the next evaluation: no list yet, or vertex i (at
    // `position`) moved beyond half the skin since the list was built.
    bool listed() const { return neighbours_.has_value(); }
    bool moved_beyond_half_skin(int i, const Vec2& position) const
    {
        return neighbours_->moved_beyond_half_skin(i, position);
    }
    void update_candidates(const ShellView& model, std::int64_t step);

    // The contact groups (runs of one vertex against one other shell) evaluated by the force loop.
    long groups() const { return static_cast<long>(contact_groups_.size()) - 1; }
    // Evaluates group g; returns whether one of its candidates overlaps beyond 95% (exit 3, throw_overlap).
    bool evaluate_group(const ShellView& model, long g, double dt);
    // The contact force on vertex i, summed in candidate order and recorded (force_on, normal); added by
    // the caller to the vertex's force.
    Vec2 gather(int i);
    // No contact force on vertex i (contacts disabled).
    void clear(int i)
    {
        contact_force_.segment<2>(2 * i).setZero();
        contact_normal_[i] = 0;
    }
    // Throws NumericalError (exit 3) naming the first overlapping candidate, if any.
    void throw_overlap(const ShellView& model, std::int64_t step) const;

    // Measures of the last evaluation.
    Vec2 force_on(const Shell& shell) const; // sum of the contact forces received by its vertices [N]
    double normal(int vertex) const { return contact_normal_[vertex]; }
    std::vector<ContactView> active(const ShellView& model) const; // in candidate order
    std::size_t candidates() const { return candidates_.size(); }
    int list_builds() const { return list_builds_; }
    double skin() const { return neighbours_ ? neighbours_->skin() : 0.0; }

    // The parts of the checkpoint state, each where ShellModel::transfer has always written it.
    void transfer_forces(Archive& archive);
    void transfer_normals(Archive& archive);
    void transfer_candidates(Archive& archive, const std::vector<int>& shell_of, std::int64_t step);
    void transfer_law(Archive& archive);

  private:
    // A (vertex, element) pair that may touch: the element (a, b) of another shell. It keeps the tangential
    // force f_t of eq. (7) [N] (0 while the pair is not in contact) and, per step, the contact it carries.
    struct Candidate
    {
        int vertex, a, b;
        double reach = 0; // r_i + r_j of the vertex and the element [m]
        double friction = 0;
        bool active = false, overlap = false; // in contact; overlap beyond 95% of r_i + r_j (exit 3)
        double fn = 0, w_a = 0, w_b = 0;      // normal force [N], transfer weights of Fig. 5
        double distance = 0;                  // vertex-element distance while active [m]
        Vec2 force = Vec2::Zero();            // force on the vertex [N]
        void transfer(Archive& archive);
    };
    bool outside_bounding_box(const ShellView& model, const Candidate& candidate) const;
    void evaluate(const ShellView& model, Candidate& candidate, double old_friction, double dt) const;
    void index_candidates(const std::vector<int>& shell_of, std::int64_t step);

    ContactLaw law_;
    Eigen::VectorXd contact_force_;      // per dof: contact force received [N]
    std::vector<double> contact_normal_; // per vertex: normal contact force received [N]
    std::vector<Candidate> candidates_;  // sorted by (vertex, a)
    // Start of each run of candidates of one vertex against one other shell, then candidates_.size().
    std::vector<std::size_t> contact_groups_;
    std::optional<NeighbourList<2>> neighbours_;
    double list_length_ = 0; // element length bound L of the list's cutoff [m]
    int list_builds_ = 0;
    // Per vertex, the candidates whose contact acts on it (as the contacting vertex or as an end of the
    // element), in candidate order: gather_terms_[gather_offsets_[i] ... gather_offsets_[i + 1]), each the
    // candidate index m shifted left by 2 with its ContactRole in the low bits. touched_[i] is set when a
    // contact acting on vertex i became active in this step (most vertices touch nothing: their gather is
    // one test) and cleared by its gather.
    enum ContactRole : std::uint32_t { role_vertex = 0, role_end_a = 1, role_end_b = 2 };
    std::vector<std::size_t> gather_offsets_;
    std::vector<std::uint32_t> gather_terms_;
    std::vector<unsigned char> touched_;
};

} // namespace softgrain::spd
