// The one pair traversal of 3D contacts (eqs. 9.3-9.4 in 3D, system3d.hpp, and the smooth vertex-surface
// contacts, interactions3d.hpp): a vertex-level Verlet list.
//
// Candidates are the vertex pairs (i < j) of different particles within reach + skin, found by core's cell
// list (NeighbourList<3>) in the coordinates u = (x - gamma y, y, z) with the Lees-Edwards shear undone
// (gamma wrapped into [-1/2, 1/2]; decision dpm-3d-lees-edwards), whose images form the plain cubic
// lattice. A pair r apart in space is at most r (1 + |gamma|) apart there, so reach = c (1 + |gamma|) finds
// every pair closer than c in space, with c the contact range of the interaction:
//   rough (eq. 9.4): sigma_max, the largest sigma_mb = (sigma_mu + sigma_beta)/2;
//   smooth: a vertex within sigma_mb of a closed triangle is within sigma_mb + l/sqrt(3) of one of its
//     corners, l its longest edge: a point of the triangle is farthest from its nearest corner at the
//     circumcentre, R = l/(2 sin A) <= l/sqrt(3) for an acute triangle (A >= 60 degrees the largest angle),
//     and on an edge otherwise, at most half the edge from a corner. So c = sigma_max + (l_max + (1 +
//     |gamma|) skin)/sqrt(3) with l_max the longest edge at the build: while the list is valid each end of an
//     edge moves less than (1 + |gamma|) skin/2 in space, so no edge grows by more than (1 + |gamma|) skin.
// Rough contacts need one image per vertex pair within reach (box side L > 2 reach). A smooth contact may
// see several images of one particle in a small box: the list then needs only L > reach, under which every
// image of a vertex within reach in u lies among the nearest image in u and its 26 neighbours (two images
// within reach of one point are closer than 2 reach < 2 L, one lattice step in each index);
// interactions3d.cpp enumerates them.
// The list stays valid until some vertex has moved more than skin/2 in u since the build (the
// minimum-image distance moves by at most the displacement, so a pair within reach now was within reach +
// skin then); a different box, strain, particle layout or interaction invalidates it too.
// The rough contact loop measures r_ij = image(r_j - r_i) at every evaluation and takes the listed pairs in
// (i, j) order, as a fresh cell list of reach alone would give them (NeighbourList sorts its pairs); the
// smooth one takes (vertex, image of a particle) in an order of their indices alone. So energies, forces,
// Hessians and virials do not depend on the skin or on when the list was built: they are bit-identical to a
// search made at every evaluation.
#pragma once

#include "core/neighbour_list.hpp"

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace softgrain::dpm {

struct DpmSystem3d;

// A candidate pair of vertices i < j of different particles; sigma = sigma_mb of the pair.
struct CandidatePair3d
{
    int i = 0, j = 0;
    double sigma = 0;
};

class VertexPairList3d
{
  public:
    // Builds the list of `system` at x. NumericalError if the periodic box is not above twice the reach
    // for rough contacts (one image per vertex pair within reach, decision dpm-3d-vertex-image), or not
    // above the reach for smooth ones.
    VertexPairList3d(const DpmSystem3d& system, const Eigen::VectorXd& x);

    // Whether the list holds every contact of `system` at x (same box, strain and particles, and no vertex
    // moved more than skin/2 in u since the build).
    bool valid_for(const DpmSystem3d& system, const Eigen::VectorXd& x) const;

    // Candidate pairs, sorted by (i, j).
    const std::vector<CandidatePair3d>& pairs() const { return pairs_; }
    int particle_of(int vertex) const { return owner_[vertex]; }
    double skin() const { return skin_; }
    // The contact range c in space (header): every vertex pair of a contact term is closer, while valid.
    double contact_range() const { return range_; }
    // Whether no vertex pair has two images within reach (L > 2 reach), so the nearest one is the only one.
    bool one_image() const { return one_image_; }

  private:
    bool same_layout(const DpmSystem3d& system) const;

    std::vector<Eigen::Vector3d> particles_; // (first, count, sigma) at the build
    std::optional<double> box_;
    double strain_ = 0;
    bool smooth_ = false;
    double skin_ = 0;
    double range_ = 0;
    bool one_image_ = true;
    std::vector<CandidatePair3d> pairs_;
    std::vector<int> owner_;    // particle of each vertex
    Eigen::Matrix3Xd built_at_; // u at the build
};

// The Lees-Edwards strain gamma wrapped into [-1/2, 1/2]: gamma and gamma - 1 give the same images of the
// cube.
double wrapped_strain3d(const DpmSystem3d& system);

} // namespace softgrain::dpm
