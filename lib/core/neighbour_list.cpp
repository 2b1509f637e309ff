#include "core/neighbour_list.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace softgrain {

template <int Dim>
NeighbourList<Dim>::NeighbourList(double cutoff, double skin, std::optional<Vec<Dim>> periodic_box,
                                  double shear_strain)
    : cutoff_(cutoff), skin_(skin), box_(periodic_box), shear_strain_(shear_strain)
{
    if (!(cutoff > 0) || !(skin >= 0))
        throw std::invalid_argument("NeighbourList: need cutoff > 0, skin >= 0");
    if (shear_strain != 0 && !periodic_box)
        throw std::invalid_argument("NeighbourList: a shear strain needs a periodic box");
}

template <int Dim>
bool NeighbourList<Dim>::needs_rebuild(const Points<Dim>& positions) const
{
    if (builds_ == 0 || positions.cols() != reference_positions_.cols()) return true;
    for (Eigen::Index i = 0; i < positions.cols(); ++i)
        if (moved_beyond_half_skin(i, positions.col(i))) return true;
    return false;
}

template <int Dim>
bool NeighbourList<Dim>::update(const Points<Dim>& positions)
{
    if (!needs_rebuild(positions)) return false;
    build(positions);
    return true;
}

template <int Dim>
void NeighbourList<Dim>::build(const Points<Dim>& positions)
{
    const Eigen::Index n = positions.cols();
    const double reach = cutoff_ + skin_;
    Vec<Dim> origin, extent;
    if (box_) {
        origin.setZero();
        extent = *box_;
    } else if (n > 0) {
        origin = positions.rowwise().minCoeff();
        extent = (positions.rowwise().maxCoeff() - origin).array() + 1e-12 * reach;
    } else {
        origin.setZero();
        extent.setOnes();
    }

    // Cells of side >= reach (along x >= reach sqrt(1 + gamma^2) under shear: the unsheared separation of
    // a pair within reach); in a periodic box the side divides the box exactly.
    Eigen::Matrix<int, Dim, 1> cells;
    Vec<Dim> side;
    for (int k = 0; k < Dim; ++k) {
        const double least_side = k == 0 ? reach * std::sqrt(1 + shear_strain_ * shear_strain_) : reach;
        cells[k] = std::max(1, static_cast<int>(std::floor(extent[k] / least_side)));
        side[k] = extent[k] / cells[k];
    }
    const auto cell_of = [&](Vec<Dim> x) {
        x.x() -= shear_strain_ * x.y(); // unshear: the images form a rectangular lattice
        Eigen::Matrix<int, Dim, 1> c;
        for (int k = 0; k < Dim; ++k) {
            double u = (x[k] - origin[k]) / side[k];
            if (box_) u -= cells[k] * std::floor(u / cells[k]);
            // The clamp guards round-off at the edge.
            c[k] = std::clamp(static_cast<int>(std::floor(u)), 0, cells[k] - 1);
        }
        return c;
    };
    const auto flat = [&](const Eigen::Matrix<int, Dim, 1>& c) {
        int index = 0;
        for (int k = Dim - 1; k >= 0; --k)
            index = index * cells[k] + c[k];
        return index;
    };

    const int total_cells = cells.prod();
    std::vector<int> head(static_cast<std::size_t>(total_cells), -1), next(static_cast<std::size_t>(n), -1);
    std::vector<Eigen::Matrix<int, Dim, 1>> cell_index(static_cast<std::size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i) {
        cell_index[i] = cell_of(positions.col(i));
        const int f = flat(cell_index[i]);
        next[i] = head[f];
        head[f] = static_cast<int>(i);
    }

    // Offsets of the 3^Dim adjacent cells.
    std::vector<Eigen::Matrix<int, Dim, 1>> offsets;
    const int adjacent = Dim == 2 ? 9 : 27;
    for (int m = 0; m < adjacent; ++m) {
        Eigen::Matrix<int, Dim, 1> o;
        int rest = m;
        for (int k = 0; k < Dim; ++k) {
            o[k] = rest % 3 - 1;
            rest /= 3;
        }
        offsets.push_back(o);
    }

    pairs_.clear();
    distance_evaluations_ = 0;
    const double reach_squared = reach * reach;
    std::vector<int> visited;
    for (Eigen::Index i = 0; i < n; ++i) {
        const auto first_of_i = static_cast<std::ptrdiff_t>(pairs_.size());
        visited.clear();
        for (const auto& o : offsets) {
            Eigen::Matrix<int, Dim, 1> c = cell_index[i] + o;
            bool outside = false;
            for (int k = 0; k < Dim; ++k) {
                if (box_)
                    c[k] = (c[k] + cells[k]) % cells[k];
                else
                    outside = outside || c[k] < 0 || c[k] >= cells[k];
            }
            if (outside) continue;
            const int f = flat(c);
            // With fewer than three cells along a periodic side, two offsets can name the same cell.
            if (std::find(visited.begin(), visited.end(), f) != visited.end()) continue;
            visited.push_back(f);
            for (int j = head[f]; j >= 0; j = next[j]) {
                if (j <= i) continue;
                ++distance_evaluations_;
                if (separation(positions.col(i), positions.col(j)).squaredNorm() < reach_squared)
                    pairs_.emplace_back(static_cast<int>(i), j);
            }
        }
        // Deterministic order, independent of binning: the pairs come by i, each i's sorted by j.
        std::sort(pairs_.begin() + first_of_i, pairs_.end());
    }
    reference_positions_ = positions;
    ++builds_;
}

template class NeighbourList<2>;
template class NeighbourList<3>;

} // namespace softgrain
