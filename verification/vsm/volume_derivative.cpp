// B_ab = -dV_b/dX_a (Frenning 2022, eqs. (61)-(62), Appendix B) against central finite differences of voro++
// cell volumes.
#include "core/rng.hpp"
#include "support/tolerance.hpp"
#include "vsm/particle_layouts.hpp"
#include "vsm/reference_cells.hpp"

#include <cmath>

using namespace softgrain;
using namespace softgrain::vsm;
using softgrain::verification::Tolerance;

TEST_CASE(
    "gradient vectors are volume derivatives B_ab = -dV_b/dX_a, B_aa = -dV_a/dX_a [VSM eqs. (61), (62)]")
{
    const int n = 7;
    const double h = 1.0 / n, step = 1e-5 * h;
    const Domain domain = box_domain(Vec3::Zero(), Vec3::Ones());
    for (std::uint64_t seed : {11u, 12u, 13u}) {
        Rng rng(seed);
        const Points<3> X = jittered_lattice(Vec3::Zero(), Vec3::Ones(), {n, n, n}, 0.3, &rng);
        const ReferenceCells cells = build_reference_cells(X, domain, 2 * h);
        // The central particle: farther than the mirror distance from the boundary, so it has no ghost and
        // moving it moves no ghost.
        const int a = (n / 2) + n * (n / 2) + n * n * (n / 2);
        const auto ua = static_cast<std::size_t>(a);
        for (int axis = 0; axis < 3; ++axis) {
            Points<3> plus = X, minus = X;
            plus(axis, a) += step;
            minus(axis, a) -= step;
            const ReferenceCells cp = build_reference_cells(plus, domain, 2 * h);
            const ReferenceCells cm = build_reference_cells(minus, domain, 2 * h);
            const auto derivative = [&](std::size_t b) { return (cp.volume[b] - cm.volume[b]) / (2 * step); };
            // Central differences of a volume that is smooth in X_a (no topology change at 1e-5 h):
            // truncation ~ (step/h)^2 ~ 1e-10, rounding ~ eps h^3 / step ~ 2e-11 h^2; 1e-8 h^2 bounds both.
            const Tolerance tolerance{0, 1e-8 * h * h};
            for (const Neighbour& nb : cells.neighbours[ua]) {
                CAPTURE(seed);
                CAPTURE(axis);
                CHECK_CLOSE(-derivative(static_cast<std::size_t>(nb.particle)), nb.B_ab[axis], tolerance);
            }
            CHECK_CLOSE(-derivative(ua), cells.B_self[ua][axis], tolerance);
        }
    }
}
