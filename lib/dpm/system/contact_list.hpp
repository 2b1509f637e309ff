// The one pair traversal of 2D DPM contacts (section 9.3.2): a vertex-level Verlet list.
//
// Candidates are the vertex pairs of different particles closer than cutoff + skin, found by core's cell
// list (NeighbourList<2>), which also handles the periodic box and Lees-Edwards shear (unshear, bin,
// reshear). Each pair carries the lattice translation of its nearest image at the build, so the contact
// loops measure r_j + shift - r_i without rounding. The list stays valid, i.e. holds every pair within
// `cutoff`, until some vertex has moved more than skin/2 (also by a box vector); a different box, strain, particle layout or
// interaction kind invalidates it too. The cutoff is the contact reach of the interaction:
//   rough (eq. 9.4): sigma_max, the largest sigma_mb = (sigma_mu + sigma_beta)/2;
//   smooth (eqs. 9.6-9.9): a corner term needs |r_i - r_j| < sigma_mb; an edge term needs vertex i within
//     sigma_mb of the edge and projecting inside it, so its nearer end is within sqrt(sigma^2 + l^2/4) for
//     an edge of length l. Edges grow by less than the skin while the list is valid (both ends move less
//     than skin/2), so the cutoff sqrt(sigma_max^2 + (l_max + skin)^2/4), with l_max the longest edge at
//     the build, keeps every active edge with one end in the list.
// Every contact loop visits the active terms in vertex-index order (pairs by (i, j)), and inactive
// candidates add nothing, so energies, forces, Hessians and virials do not depend on when the list was
// built: they are bit-identical for any skin or build history.
#pragma once

#include "core/neighbour_list.hpp"
#include "dpm/system/list_cache.hpp"

#include <Eigen/Core>
#include <memory>
#include <span>
#include <vector>

namespace softgrain::dpm {

struct DpmSystem;

// A candidate vertex j of another particle near vertex i; r_j + shift - r_i is their separation (the
// nearest image while the list is valid); sigma = sigma_mb of the pair.
struct VertexNeighbour
{
    int j = 0;
    Eigen::Vector2d shift = Eigen::Vector2d::Zero();
    double sigma = 0;
};

// A candidate pair i < j of different particles.
struct VertexPair
{
    int i = 0;
    VertexNeighbour neighbour;
};

class ContactList
{
  public:
    // Builds the list of `system` at coordinates x. NumericalError if the periodic box is too small for one
    // image per particle pair (side below twice the largest pair reach 2 R + sigma, R the largest vertex
    // distance from a particle's vertex mean).
    ContactList(const DpmSystem& system, const Eigen::VectorXd& x);

    // Whether the list holds every contact of `system` at x (same box, strain, particles and interaction,
    // and no vertex moved more than skin/2 since the build).
    bool valid_for(const DpmSystem& system, const Eigen::VectorXd& x) const;

    // Candidate pairs, sorted by (i, j).
    const std::vector<VertexPair>& pairs() const { return pairs_; }
    // Candidates of vertex i from both sides (j > i and j < i), sorted by j; only for smooth interactions
    // (empty otherwise): the vertex-edge terms are ordered pairs.
    std::span<const VertexNeighbour> neighbours(int i) const
    {
        if (row_.empty()) return {};
        return {neighbours_.data() + row_[i], neighbours_.data() + row_[i + 1]};
    }
    int particle_of(int vertex) const { return owner_[vertex]; }
    double cutoff() const { return list_.cutoff(); }
    double skin() const { return list_.skin(); }

  private:
    struct Layout // what the list depends on besides the coordinates
    {
        std::vector<Eigen::Vector3d> particles; // (first, count, sigma)
        bool smooth = false;
        std::optional<Eigen::Vector2d> box;
        double strain = 0;
    };
    static Layout layout_of(const DpmSystem& system);
    bool same_layout(const DpmSystem& system) const; // without building a Layout: checked every evaluation

    Layout layout_;
    NeighbourList<2> list_;
    std::vector<int> owner_;
    std::vector<VertexPair> pairs_;
    std::vector<int> row_;
    std::vector<VertexNeighbour> neighbours_;
    // x at the build. The skin test compares unwrapped positions directly, not by the minimum image as
    // NeighbourList does: a particle moved by a box vector keeps its distances but not the image
    // translations stored with its pairs, so it must invalidate the list.
    Eigen::VectorXd built_at_;
};

// The contact list of a 2D system, kept between energy evaluations (list_cache.hpp).
using ContactCache = ListCache<ContactList, DpmSystem>;

// A touching vertex pair (i < j, of particles a != b): r = r_j - r_i by the nearest image, r < sigma_mb.
struct VertexContact
{
    int i = 0, j = 0;
    int a = 0, b = 0;
    Eigen::Vector2d r = Eigen::Vector2d::Zero();
    double sigma = 0;
};

// The rough contacts of eq. (9.4) at x, from the system's contact list, sorted by (i, j).
std::vector<VertexContact> vertex_contacts(const DpmSystem& system, const Eigen::VectorXd& x);

} // namespace softgrain::dpm
