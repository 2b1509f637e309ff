// The pair traversal of 3D rough contacts (eqs. 9.3-9.4 in 3D, system3d.hpp): a vertex-level Verlet list.
//
// Candidates are the vertex pairs (i < j) of different particles within reach + skin, found by core's cell
// list (NeighbourList<3>) in the coordinates u = (x - gamma y, y, z) with the Lees-Edwards shear undone
// (gamma wrapped into [-1/2, 1/2]; decision dpm-3d-lees-edwards), whose images form the plain cubic
// lattice. A pair r apart in space is at most r (1 + |gamma|) apart there, so reach = sigma_max (1 + |gamma|)
// finds every contact. The list stays valid until some vertex has moved more than skin/2 in u since the
// build (the minimum-image distance moves by at most the displacement, so a pair within reach now was within
// reach + skin then); a different box, strain or particle layout invalidates it too.
// The contact loop measures r_ij = image(r_j - r_i) at every evaluation and takes the listed pairs in
// (i, j) order, as a fresh cell list of reach alone would give them (NeighbourList sorts its pairs), so
// energies, forces, Hessians and virials do not depend on the skin or on when the list was built: they are
// bit-identical to a search made at every evaluation.
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
    // (one image per vertex pair, decision dpm-3d-vertex-image).
    VertexPairList3d(const DpmSystem3d& system, const Eigen::VectorXd& x);

    // Whether the list holds every contact of `system` at x (same box, strain and particles, and no vertex
    // moved more than skin/2 in u since the build).
    bool valid_for(const DpmSystem3d& system, const Eigen::VectorXd& x) const;

    // Candidate pairs, sorted by (i, j).
    const std::vector<CandidatePair3d>& pairs() const { return pairs_; }
    double skin() const { return skin_; }

  private:
    bool same_layout(const DpmSystem3d& system) const;

    std::vector<Eigen::Vector3d> particles_; // (first, count, sigma) at the build
    std::optional<double> box_;
    double strain_ = 0;
    double skin_ = 0;
    std::vector<CandidatePair3d> pairs_;
    Eigen::Matrix3Xd built_at_; // u at the build
};

} // namespace softgrain::dpm
