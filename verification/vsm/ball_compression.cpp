// The VSM ball of compare.solid: ghosts across a sphere (Frenning 2022, section 2.1 with a curved boundary)
// and the rigid plate (decision vsm-plate-contact).
#include "vsm/ball_compression.hpp"
#include "support/tolerance.hpp"
#include "vsm/reference_cells.hpp"

#include <cmath>

using namespace softgrain;
using namespace softgrain::vsm;
using softgrain::verification::Tolerance;

namespace {

constexpr double R = 0.5;

double volume_excess(int per_radius)
{
    const Domain domain = ball_octant_domain(R);
    const ReferenceCells cells =
        build_reference_cells(octant_lattice(R, per_radius), domain, 2 * R / per_radius);
    double volume = 0;
    for (double V : cells.volume)
        volume += V;
    return volume / domain.volume - 1;
}

// The octant with a free sphere carrying a plate at `height`, symmetric planes, no contact stabilisation.
Model plate_model(int per_radius, double height, double penalty)
{
    const Domain domain = ball_octant_domain(R);
    BoundaryConditions bc;
    bc.kind = {BoundaryKind::symmetric, BoundaryKind::symmetric, BoundaryKind::symmetric, BoundaryKind::free};
    bc.displacement = [](int, const Vec3&, double) { return Vec3::Zero(); };
    bc.plates = {RigidPlate{3, Vec3::UnitZ(), [height](double) { return height; }, penalty}};
    return Model(build_reference_cells(octant_lattice(R, per_radius), domain, 2 * R / per_radius), domain, bc,
                 Material{1e6, 0.3, 1e3}, ModelOptions{InternalForce::eq43, 0, 0});
}

} // namespace

TEST_CASE("the cells of a ball cover it and exceed it by the slivers of second order in h/R [VSM sec. 2.1]")
{
    // Every point of the ball lies below every tangent plane, so the cells cover it; each spherical facet
    // of width ~h stands at most ~h^2/R above the sphere, over the whole surface: excess ~ (h/R)^2.
    const double coarse = volume_excess(6), fine = volume_excess(12);
    CHECK(coarse > 0);
    CHECK(fine > 0);
    // Second order: halving h divides the excess by 4; the facets' shapes vary with the lattice's cut of the
    // sphere, so the order is asserted within 0.5.
    CHECK_CLOSE(std::log2(coarse / fine), 2.0, (Tolerance{0, 0.5}));
}

TEST_CASE("spherical ghosts keep VSM linearly complete: F_a is exact for an affine deformation [VSM eq. (6)]")
{
    // Every cell is closed (its sphere facet included), so sum_b X_ab (x) B_ab = V_a I; the least-squares
    // ghosts of eq. (22) extrapolate an affine field exactly, and the symmetric ghosts prescribe it. F_a = G then holds to round-off for every
    // particle, including those whose ghost lies across the sphere.
    // G is diagonal so that the symmetric planes X_i = 0 keep their zero normal displacement.
    const Model model = plate_model(6, R, 1);
    const Mat3 G = Vec3(1.02, 0.97, 1.05).asDiagonal();
    const Points<3> x = G * model.cells().X;
    double largest = 0;
    for (std::size_t a = 0; a < model.size(); ++a)
        largest = std::max(largest, (model.deformation_gradient(x, static_cast<int>(a), 0) - G).norm());
    CHECK(largest < 1e-12); // round-off of sums over ~15 neighbours of O(1) terms
}

TEST_CASE("the plate's forces are the gradient of its penalty energy and sum to its load [decision "
          "vsm-plate-contact]")
{
    // Push the plate 0.03 D into the undeformed ball so that several boundary points touch it.
    const Model model = plate_model(6, R - 0.03, 100);
    const Points<3> x = model.cells().X;
    const Model::PlateLoad load = model.plate_load(x, 0, 0);
    REQUIRE(load.contacts >= 3);
    const Points<3> f = model.forces(x, 0) - plate_model(6, 2 * R, 100).forces(x, 0); // plate part alone
    // The forces on all particles add up to the load along -normal: the coefficients of w_ab sum to 1.
    CHECK_CLOSE(f.rowwise().sum().z(), -load.force, (Tolerance{1e-12, 0}));
    CHECK_CLOSE(f.rowwise().sum().head<2>().norm(), 0.0, (Tolerance{0, 1e-12 * load.force}));
    // f = -dE/dx by central differences (E is piecewise quadratic: exact away from a contact's switch; the
    // step 1e-7 R is far below every gap, so no contact switches).
    const double step = 1e-7 * R;
    double worst = 0;
    for (Eigen::Index a = 0; a < x.cols(); ++a)
        for (int i = 0; i < 3; ++i) {
            Points<3> plus = x, minus = x;
            plus(i, a) += step;
            minus(i, a) -= step;
            const double derivative =
                (model.plate_energy(plus, 0) - model.plate_energy(minus, 0)) / (2 * step);
            worst = std::max(worst, std::abs(f(i, a) + derivative));
        }
    // Round-off of the energy difference: ~1e-16 E_plate / step, E_plate ~ load * gap ~ 1e-2 load R.
    CHECK(worst < 1e-6 * load.force);
}
