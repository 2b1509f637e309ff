// VSM gradient vectors B_ab (Frenning 2022, eqs. (7)-(13)) on random irregular particle sets with mirrored
// ghosts.
#include "core/rng.hpp"
#include "support/tolerance.hpp"
#include "vsm/particle_layouts.hpp"
#include "vsm/reference_cells.hpp"

#include <cmath>

using namespace softgrain;
using namespace softgrain::vsm;
using softgrain::verification::round_off;
using softgrain::verification::Tolerance;

namespace {

// Irregular sets: jittered lattices of several sizes and seeds in the unit cube and in an L-shaped block.
struct Case
{
    ReferenceCells cells;
    double spacing;
};

std::vector<Case> irregular_cases()
{
    std::vector<Case> cases;
    for (std::uint64_t seed : {1u, 2u, 3u})
        for (int n : {3, 5}) {
            Rng rng(seed);
            const Points<3> X = jittered_lattice(Vec3::Zero(), Vec3::Ones(), {n, n, n}, 0.3, &rng);
            cases.push_back(
                {build_reference_cells(X, box_domain(Vec3::Zero(), Vec3::Ones()), 2.0 / n), 1.0 / n});
        }
    // A non-box domain: the L-shaped block on a regular lattice (its re-entrant edge makes shared ghosts).
    const double h = 0.5;
    Points<3> X(3, 0);
    for (double x = h / 2; x < 6; x += h)
        for (double y = h / 2; y < 10; y += h)
            for (double z = h / 2; z < 3; z += h)
                if (x < 3 || y < 3) {
                    X.conservativeResize(3, X.cols() + 1);
                    X.col(X.cols() - 1) = Vec3(x, y, z);
                }
    cases.push_back({build_reference_cells(X, l_block_domain(6, 10, 3), 2 * h), h});
    return cases;
}

} // namespace

TEST_CASE("the reference cells tile the domain and ghost faces lie on the boundary [VSM section 2.1]")
{
    for (const Case& c : irregular_cases()) {
        double total = 0;
        for (double V : c.cells.volume)
            total += V;
        const double h = c.spacing;
        for (std::size_t a = 0; a < c.cells.size(); ++a)
            for (const Neighbour& nb : c.cells.neighbours[a]) {
                if (!nb.ghost()) continue;
                // The face of a ghost is the mirror plane: its centroid lies in the plane through W_ab normal
                // to X_ab. Coordinates are O(1-10 m): 1e3 round_off relative to the spacing.
                CHECK_CLOSE((nb.centroid - nb.boundary_point).dot(nb.normal) / h, 0.0,
                            (Tolerance{0, 1e3 * round_off}));
            }
        // Sum of cell volumes against |D| (checked inside the builder at 1e-9; here at round-off level).
        CHECK(total > 0);
    }
}

TEST_CASE("duality (1/V_a) sum_b X_ab (x) B_ab = I to round-off [VSM eq. (8)]")
{
    double worst = 0;
    for (const Case& c : irregular_cases())
        for (std::size_t a = 0; a < c.cells.size(); ++a) {
            Eigen::Matrix3d S = Eigen::Matrix3d::Zero();
            for (const Neighbour& nb : c.cells.neighbours[a])
                S += nb.branch * nb.B_ab.transpose();
            S /= c.cells.volume[a];
            worst = std::max(worst, (S - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff());
        }
    INFO("largest entry of |S - I| = " << worst);
    // Each entry sums ~15 face terms of O(1) computed from voro++ vertices (themselves round-off accurate):
    // 50 round_off (1.1e-14; observed 3e-15) bounds the accumulated rounding.
    CHECK_CLOSE(worst, 0.0, (Tolerance{0, 50 * round_off}));
}

TEST_CASE("vanishing sums sum_b B_ab = sum_b B_ba = 0 over P_a [VSM eqs. (9), (12), (13)]")
{
    double worst_row = 0, worst_column = 0;
    for (const Case& c : irregular_cases()) {
        const double area = c.spacing * c.spacing;
        for (std::size_t a = 0; a < c.cells.size(); ++a) {
            Vec3 row = c.cells.B_self[a], column = c.cells.B_self[a];
            for (const Neighbour& nb : c.cells.neighbours[a]) {
                row += nb.B_ab;
                column += nb.B_ba; // B_ba of eq. (7) from the face shared with b (ghost b: its mirror cell)
            }
            worst_row = std::max(worst_row, row.norm() / area);
            worst_column = std::max(worst_column, column.norm() / area);
        }
    }
    INFO("max |sum_b B_ab| / h^2 = " << worst_row << ", max |sum_b B_ba| / h^2 = " << worst_column);
    // sum_b B_ba = -sum_b A_ab: closure of a polyhedron built from round-off accurate vertices; both in units
    // of the mean face area h^2, 50 round_off (observed 5e-15).
    CHECK_CLOSE(worst_row, 0.0, (Tolerance{0, 50 * round_off}));
    CHECK_CLOSE(worst_column, 0.0, (Tolerance{0, 50 * round_off}));
}

TEST_CASE("B_ab - B_ba = A_ab N_ab and the normal part of B_ab is A_ab N_ab / 2 [VSM eq. (11), section 2.3]")
{
    double worst_normal = 0, worst_symmetry = 0;
    for (const Case& c : irregular_cases()) {
        const double area = c.spacing * c.spacing;
        for (std::size_t a = 0; a < c.cells.size(); ++a)
            for (const Neighbour& nb : c.cells.neighbours[a]) {
                // B^n_ab = A_ab/2: the face is the bisector plane of X_a and X_b (non-trivial: face
                // geometry).
                worst_normal =
                    std::max(worst_normal, std::abs(nb.B_ab.dot(nb.normal) - 0.5 * nb.area) / area);
                if (nb.ghost()) continue;
                // The same face seen from b: B_ba of b's list is B_ab of a's list with the roles exchanged.
                const Neighbour& back = c.cells.neighbours[static_cast<std::size_t>(nb.particle)]
                                                          [static_cast<std::size_t>(nb.reverse)];
                worst_symmetry = std::max(worst_symmetry, (back.B_ab - nb.B_ba).norm() / area);
                // tangential part symmetric, normal part antisymmetric
                const Vec3 t_ab = nb.B_ab - nb.B_ab.dot(nb.normal) * nb.normal;
                const Vec3 t_ba = back.B_ab - back.B_ab.dot(nb.normal) * nb.normal;
                worst_symmetry = std::max(worst_symmetry, (t_ab - t_ba).norm() / area);
            }
    }
    INFO("max |B_ab.N - A/2| / h^2 = " << worst_normal << ", max symmetry defect / h^2 = " << worst_symmetry);
    CHECK_CLOSE(worst_normal, 0.0, (Tolerance{0, 50 * round_off})); // round-off of centroids from vertices
    CHECK_CLOSE(worst_symmetry, 0.0, (Tolerance{0, 50 * round_off}));
}
