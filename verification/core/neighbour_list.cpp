// Cell-list neighbour search with a skin against brute force, open and periodic, 2D and 3D.
#include "core/neighbour_list.hpp"
#include "core/rng.hpp"
#include "support/tolerance.hpp"

#include <set>

using namespace softgrain;
using softgrain::verification::Tolerance;

namespace {

template <int Dim>
Points<Dim> random_points(Rng& rng, int n, double side)
{
    Points<Dim> x(Dim, n);
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < Dim; ++k)
            x(k, i) = rng.uniform(0.0, side);
    return x;
}

// Every pair closer than `range` by O(N^2) search.
template <int Dim>
std::set<std::pair<int, int>> brute_force_pairs(const NeighbourList<Dim>& list, const Points<Dim>& x,
                                                double range)
{
    std::set<std::pair<int, int>> pairs;
    for (int i = 0; i < x.cols(); ++i)
        for (int j = i + 1; j < x.cols(); ++j)
            if (list.separation(x.col(i), x.col(j)).norm() < range) pairs.emplace(i, j);
    return pairs;
}

template <int Dim>
void check_against_brute_force(bool periodic)
{
    Rng rng(17);
    const double side = 10.0, cutoff = 1.0, skin = 0.3;
    std::optional<Vec<Dim>> box;
    if (periodic) box = Vec<Dim>::Constant(side);
    NeighbourList<Dim> list(cutoff, skin, box);
    Points<Dim> x = random_points<Dim>(rng, Dim == 2 ? 600 : 1200, side);
    list.update(x);
    const std::set<std::pair<int, int>> listed(list.pairs().begin(), list.pairs().end());
    // Exactly the pairs within cutoff + skin: a set comparison, no tolerance.
    CHECK(listed == brute_force_pairs(list, x, cutoff + skin));
    CHECK(listed.size() == list.pairs().size()); // no duplicates

    // Moves smaller than skin/2 keep the list; every pair within the cutoff is still listed.
    for (int i = 0; i < x.cols(); ++i)
        x.col(i) += Vec<Dim>::NullaryExpr([&] { return rng.normal(1.0); }).normalized() * (0.49 * skin) *
                    rng.uniform();
    CHECK_FALSE(list.update(x));
    for (const auto& pair : brute_force_pairs(list, x, cutoff))
        CHECK(listed.count(pair) == 1);

    // A larger move forces a rebuild.
    x.col(0) += Vec<Dim>::Constant(skin);
    CHECK(list.update(x));
}

} // namespace

TEST_CASE("cell list lists exactly the pairs within cutoff + skin (2D and 3D, open and periodic)")
{
    check_against_brute_force<2>(false);
    check_against_brute_force<2>(true);
    check_against_brute_force<3>(false);
    check_against_brute_force<3>(true);
}

TEST_CASE("periodic box with fewer than three cells per side lists each pair once")
{
    NeighbourList<2> list(1.0, 0.2, Vec2(2.0, 2.0)); // one or two cells per side: offsets alias
    Rng rng(3);
    const Points<2> x = random_points<2>(rng, 40, 2.0);
    list.update(x);
    const std::set<std::pair<int, int>> listed(list.pairs().begin(), list.pairs().end());
    CHECK(listed.size() == list.pairs().size());
    CHECK(listed == brute_force_pairs(list, x, 1.2));
}

TEST_CASE("a rebuild costs O(N): distance evaluations per point do not grow with N at fixed density")
{
    // Periodic boxes of side 10 and 40 with 5 points per unit area; reach 1.25 divides both sides, so both
    // grids have cells of the same size and the expected evaluations per point are equal (9 cells x 7.8
    // points / 2). Brute force would grow 16-fold. Tolerance 5%: the count over N = 500 points fluctuates by
    // ~1% (Poisson statistics of ~17,000 evaluations).
    const auto evaluations_per_point = [](double side) {
        Rng rng(11);
        const int n = static_cast<int>(5.0 * side * side);
        NeighbourList<2> list(1.0, 0.25, Vec2(side, side));
        list.update(random_points<2>(rng, n, side));
        return static_cast<double>(list.distance_evaluations()) / n;
    };
    CHECK_CLOSE(evaluations_per_point(40.0), evaluations_per_point(10.0), (Tolerance{0.05, 0}));
}
