// Verlet neighbour list built with a cell list (linked cells), in 2D or 3D, open or periodic.
//
// Pairs (i < j) closer than cutoff + skin are listed. The list stays valid, i.e. contains every pair
// closer than `cutoff`, until some point has moved more than skin/2 since the last build; `update`
// checks this and rebuilds only then. A rebuild costs O(N): points are binned into cells of side
// >= cutoff + skin and each point is compared with the points of its own and adjacent cells.
#pragma once

#include "core/vector.hpp"

#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace softgrain {

template <int Dim>
class NeighbourList
{
  public:
    // `periodic_box`: side lengths of a periodic box with its corner at the origin (minimum image);
    // absent for open boundaries.
    NeighbourList(double cutoff, double skin, std::optional<Vec<Dim>> periodic_box = std::nullopt);

    // Rebuilds the list if needed; returns true if it did.
    bool update(const Points<Dim>& positions);
    // Whether point i, now at x, makes the list stale: it has moved more than skin/2 since the last build
    // (always true before the first build or for a point the list has not seen). `update` rebuilds exactly
    // when this holds for some point; a caller that already visits every point can test it there, in
    // parallel, and skip `update` otherwise.
    // Builds the list now (for a caller that knows it is stale: no second check of every point).
    void build(const Points<Dim>& positions);
    bool moved_beyond_half_skin(Eigen::Index i, const Vec<Dim>& x) const
    {
        if (builds_ == 0 || i >= reference_positions_.cols()) return true;
        return separation(reference_positions_.col(i), x).squaredNorm() > 0.25 * skin_ * skin_;
    }
    const std::vector<std::pair<int, int>>& pairs() const { return pairs_; }
    int builds() const { return builds_; }
    double cutoff() const { return cutoff_; }
    double skin() const { return skin_; }
    // Distance evaluations of the last build: the cost measure of a rebuild, O(N) at fixed density.
    long distance_evaluations() const { return distance_evaluations_; }

    // x_j - x_i, by the minimum image in a periodic box.
    Vec<Dim> separation(const Vec<Dim>& x_i, const Vec<Dim>& x_j) const
    {
        Vec<Dim> d = x_j - x_i;
        if (box_)
            for (int k = 0; k < Dim; ++k)
                d[k] -= (*box_)[k] * std::round(d[k] / (*box_)[k]);
        return d;
    }

    // Writes or reads the whole list for a checkpoint (core/checkpoint.hpp): a resumed run rebuilds it at the
    // same steps as an uninterrupted one.
    template <class Archive>
    void transfer(Archive& archive)
    {
        archive(cutoff_);
        archive(skin_);
        archive(box_);
        archive(reference_positions_);
        archive(pairs_);
        archive(builds_);
        archive(distance_evaluations_);
    }

  private:
    bool needs_rebuild(const Points<Dim>& positions) const;

    double cutoff_, skin_;
    std::optional<Vec<Dim>> box_;
    Points<Dim> reference_positions_;
    std::vector<std::pair<int, int>> pairs_;
    int builds_ = 0;
    long distance_evaluations_ = 0;
};

extern template class NeighbourList<2>;
extern template class NeighbourList<3>;

} // namespace softgrain
