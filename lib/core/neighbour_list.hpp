// Verlet neighbour list built with a cell list (linked cells), in 2D or 3D, open, periodic or periodic with
// Lees-Edwards shear.
//
// Pairs (i < j) closer than cutoff + skin are listed. The list stays valid, i.e. contains every pair
// closer than `cutoff`, until some point has moved more than skin/2 since the last build; `update`
// checks this and rebuilds only then. A rebuild costs O(N): points are binned into cells of side
// >= cutoff + skin and each point is compared with the points of its own and adjacent cells.
//
// Lees-Edwards (shear strain gamma, x sheared along y): unshear, bin, reshear. In the unsheared coordinates
// (x - gamma y, y, z) the images form the plain rectangular lattice of the box, so points are binned there;
// a separation d of real length r has unsheared x part d_x - gamma d_y, at most r sqrt(1 + gamma^2) long
// (Cauchy-Schwarz), so cells that wide along x (and cutoff + skin along the others) keep every pair within
// reach in adjacent cells. Distances are then measured in real space by the Lees-Edwards minimum image.
#pragma once

#include "core/vector.hpp"

#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace softgrain {

// Minimum image under Lees-Edwards boundaries with shear strain gamma (x sheared along y), in 2D or 3D: the
// row of images n_y boxes up is shifted by n_y gamma L_y in x. First the y image, then the others:
// d - n_y (gamma L_y, L_y, 0) - n_x (L_x, 0, 0) - n_z (0, 0, L_z). gamma = 0: the plain minimum image.
template <int Dim>
Eigen::Matrix<double, Dim, 1> lees_edwards_image(Eigen::Matrix<double, Dim, 1> d,
                                                 const Eigen::Matrix<double, Dim, 1>& L, double gamma)
{
    const double ny = std::round(d.y() / L.y());
    d.x() -= ny * (gamma * L.y());
    d.y() -= ny * L.y();
    for (int a = 0; a < Dim; ++a)
        if (a != 1) d(a) -= L(a) * std::round(d(a) / L(a));
    return d;
}

template <int Dim>
class NeighbourList
{
  public:
    // `periodic_box`: side lengths of a periodic box with its corner at the origin (minimum image);
    // absent for open boundaries. `shear_strain`: Lees-Edwards strain gamma of the periodic box.
    NeighbourList(double cutoff, double skin, std::optional<Vec<Dim>> periodic_box = std::nullopt,
                  double shear_strain = 0);

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

    double shear_strain() const { return shear_strain_; }
    const std::optional<Vec<Dim>>& box() const { return box_; }

    // x_j - x_i, by the (Lees-Edwards) minimum image in a periodic box.
    Vec<Dim> separation(const Vec<Dim>& x_i, const Vec<Dim>& x_j) const
    {
        return box_ ? lees_edwards_image<Dim>(x_j - x_i, *box_, shear_strain_) : Vec<Dim>(x_j - x_i);
    }

    // Writes or reads the whole list for a checkpoint (core/checkpoint.hpp): a resumed run rebuilds it at the
    // same steps as an uninterrupted one.
    template <class Archive>
    void transfer(Archive& archive)
    {
        archive(cutoff_);
        archive(skin_);
        archive(box_);
        archive(shear_strain_);
        archive(reference_positions_);
        archive(pairs_);
        archive(builds_);
        archive(distance_evaluations_);
    }

  private:
    bool needs_rebuild(const Points<Dim>& positions) const;

    double cutoff_, skin_;
    std::optional<Vec<Dim>> box_;
    double shear_strain_;
    Points<Dim> reference_positions_;
    std::vector<std::pair<int, int>> pairs_;
    int builds_ = 0;
    long distance_evaluations_ = 0;
};

extern template class NeighbourList<2>;
extern template class NeighbourList<3>;

} // namespace softgrain
