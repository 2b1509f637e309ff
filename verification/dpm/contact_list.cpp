// The DPM pair loop with a cell list (DpmSystem::cell_list) visits the same particle pairs in the same order
// as the all-pairs loop: energy, gradient and Hessian of eqs. (9.4)-(9.9) must be bit-identical, for rough
// and smooth polygons and for disks, in a periodic box and in open space.
#include "core/rng.hpp"
#include "dpm/system.hpp"
#include "support/tolerance.hpp"

#include <numbers>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::Tolerance;

namespace {

// n particles of `vertices` vertices (1 = disks) at random places in a square of side L: many overlaps.
struct RandomPacking
{
    DpmSystem system;
    Eigen::VectorXd x;
    RandomPacking(int n, int vertices, double L, bool periodic, InteractionKind kind)
    {
        Rng rng(7);
        system.interaction = kind;
        if (periodic) system.box = Eigen::Vector2d(L, L);
        for (int m = 0; m < n; ++m) {
            const Eigen::Vector2d c(rng.uniform(0, L), rng.uniform(0, L));
            const double sigma = m % 2 == 0 ? 1.0 : 1.4;
            if (vertices == 1)
                system.add_particle(c, sigma, ShapeParameters{}, x);
            else
                system.add_particle(regular_polygon(vertices, 1.2, c, rng.uniform(0, 2 * std::numbers::pi)),
                                    1.0, ShapeParameters{}, x);
        }
    }
};

void check_identical(DpmSystem system, const Eigen::VectorXd& x)
{
    const auto evaluate = [&](bool cell_list, Eigen::VectorXd& g, Eigen::MatrixXd& h) {
        system.cell_list = cell_list;
        g = Eigen::VectorXd::Zero(x.size());
        h = Eigen::MatrixXd::Zero(x.size(), x.size());
        return total_energy(system, x, &g, &h);
    };
    Eigen::VectorXd g_all, g_cells;
    Eigen::MatrixXd h_all, h_cells;
    const double u_all = evaluate(false, g_all, h_all);
    const double u_cells = evaluate(true, g_cells, h_cells);
    REQUIRE(u_all > 0); // the configuration has overlaps: the comparison is not between zeros
    // Same pairs, same order, same arithmetic: zero difference, not round-off.
    const Tolerance identical{0, 0};
    CHECK_CLOSE(u_cells, u_all, identical);
    CHECK_CLOSE((g_cells - g_all).cwiseAbs().maxCoeff(), 0.0, identical);
    CHECK_CLOSE((h_cells - h_all).cwiseAbs().maxCoeff(), 0.0, identical);
}

} // namespace

TEST_CASE("cell list = all pairs, bit for bit: rough and smooth polygons, periodic [DPM eqs. (9.3)-(9.9)]")
{
    for (InteractionKind kind : {InteractionKind::rough, InteractionKind::smooth}) {
        const RandomPacking p(60, 8, 30.0, true, kind); // 6 cells of side >= 5 per box side
        check_identical(p.system, p.x);
    }
}

TEST_CASE(
    "cell list = all pairs, bit for bit: disks in a periodic box and polygons in open space [DPM eq. (9.4)]")
{
    const RandomPacking disks(300, 1, 20.0, true, InteractionKind::rough);
    check_identical(disks.system, disks.x);
    const RandomPacking open(60, 8, 30.0, false, InteractionKind::smooth);
    check_identical(open.system, open.x);
}
