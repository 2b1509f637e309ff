// The Newton finisher of the relaxation (newton_relax.hpp, issue 19): its minimum against FIRE run to a
// tighter tolerance, its quadratic convergence, steps that make and break contacts, and its NumericalError.
#include "dpm/relax/newton_relax.hpp"
#include "core/errors.hpp"
#include "dpm/analysis/modes.hpp"
#include "dpm/protocols/jam.hpp"
#include "support/tolerance.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::round_off;
using softgrain::verification::Tolerance;

namespace {

// A small jammed packing (6 elastic shells of 6 and 8 vertices at the pressure P k_a a0), FIRE alone.
JamResult small_packing(double pressure = 1e-5)
{
    JamOptions o;
    o.model = JamModel::shell;
    o.particles = 6;
    o.nodes_small = 6;
    o.nodes_large = 8;
    o.pressure_onset = o.pressure_max = pressure;
    o.pressures = 0;
    return jam(o);
}

// The displacement without its uniform translation (an exact zero mode of a periodic packing, along which
// neither minimiser moves the packing except by round-off).
Eigen::VectorXd without_translation(Eigen::VectorXd d)
{
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    for (Eigen::Index v = 0; v < d.size() / 2; ++v)
        mean += d.segment<2>(2 * v);
    mean /= static_cast<double>(d.size() / 2);
    for (Eigen::Index v = 0; v < d.size() / 2; ++v)
        d.segment<2>(2 * v) -= mean;
    return d;
}

// Two one-vertex disks (sigma = 1, k_c = 1) in open space: disk 0 held at the origin by a stiff anchor,
// disk 1 at (start, 0) pulled towards (anchor, 0) by a soft one.
DpmSystem anchored_pair(double start, double anchor, Eigen::VectorXd& x)
{
    DpmSystem s;
    s.interaction = InteractionKind::rough;
    s.kc = 1;
    for (const double position : {0.0, start}) {
        Eigen::Matrix2Xd c(2, 1);
        c << position, 0;
        s.add_particle(c, 1.0, ShapeParameters{}, x);
    }
    s.anchors.push_back({0, Eigen::Vector2d::Zero(), 10.0});
    s.anchors.push_back({1, Eigen::Vector2d(anchor, 0), 1e-2});
    return s;
}

// Along the accepted steps the energy never rises beyond its round-off, the end meets the tolerance and at
// least one step changed the contacts.
void check_contact_change(const DpmSystem& system, const Eigen::VectorXd& x, const NewtonResult& r,
                          double tolerance)
{
    const double noise = energy_round_off(system, x, r.energy);
    MESSAGE("steps " << r.steps << ", rejections " << r.rejections << ", contact changes "
                     << r.contact_changes << ", force rms " << r.force_rms << ", energy round-off " << noise);
    CHECK(r.converged);
    CHECK(r.force_rms < tolerance);
    CHECK(r.contact_changes >= 1);
    for (std::size_t k = 1; k < r.energies.size(); ++k) {
        CAPTURE(k);
        CHECK(r.energies[k] <= r.energies[k - 1] + noise);
    }
}

} // namespace

TEST_CASE("Newton finisher: the minimum of FIRE run to a 1000 times tighter tolerance, within 2 sqrt(n) "
          "(tol + tol/1000) / lambda_min [issue 19]")
{
    JamResult jammed = small_packing();
    DpmSystem& s = jammed.system;
    // A new relaxation problem from the jammed state: an affine compression by 1e-3.
    scale_packing(s, jammed.x, 1 - 1e-3);
    RelaxOptions newton{Relaxation::fire_newton, jammed.fire};
    Eigen::VectorXd x_newton = jammed.x;
    const RelaxResult r = relax(s, x_newton, newton);
    REQUIRE(r.converged);
    MESSAGE("fire_newton: FIRE " << r.fire_iterations << " iterations, " << r.handovers << " hand-overs, "
                                 << r.newton_steps << " Newton steps, force rms " << r.force_rms);
    CHECK(r.handovers >= 1);
    CHECK(r.kinetic == 0);
    FireOptions tight = jammed.fire;
    tight.force_tolerance /= 1000;
    Eigen::VectorXd x_fire = jammed.x;
    REQUIRE(relax_fire(s, x_fire, tight).converged);
    // Both states lie within |F| / lambda_min of the minimum (to first order: the Hessian maps the
    // displacement to the force), |F| <= sqrt(n) times the rms; lambda_min the smallest eigenvalue above
    // the zero-mode threshold, defined only where the zero modes are the 2 uniform translations (no
    // rattler, whose place in its cage is not unique).
    const ModeSpectrum modes = vibrational_modes(s, x_fire);
    const double threshold = zero_mode_threshold(modes.eigenvalues, 0);
    const SpectrumCounts counts = count_modes(modes.eigenvalues, threshold);
    REQUIRE(counts.negative == 0);
    REQUIRE(counts.zero == 2);
    const double lambda_min = modes.eigenvalues(counts.first_positive());
    const double n = static_cast<double>(x_fire.size());
    const double allowed = std::sqrt(n) * (newton.fire.force_tolerance + tight.force_tolerance) / lambda_min;
    const double distance = without_translation(x_newton - x_fire).norm();
    MESSAGE("lambda_min " << lambda_min << ", |x_newton - x_fire| " << distance << ", allowed " << allowed);
    CHECK(distance <= allowed);
}

TEST_CASE("Newton finisher: quadratic convergence, |F_k+1| / |F_k|^2 bounded without contact changes "
          "[issue 19]")
{
    // At P = 1e-2 k_a a0 the overlaps (~1e-2 sigma) outlast a random displacement of 1e-4 sigma per
    // coordinate: no contact opens or closes.
    JamResult jammed = small_packing(1e-2);
    const DpmSystem& s = jammed.system;
    Eigen::VectorXd x = jammed.x + 1e-4 * Eigen::VectorXd::Random(jammed.x.size());
    NewtonOptions options;
    options.force_tolerance = 1e-15; // beyond FIRE's 1e-9: as far as round-off lets it go
    const NewtonResult r = newton_finish(s, x, options);
    REQUIRE(r.contact_changes == 0);
    // The force at round-off: eps times the largest force of one term, ~ k_c sigma (contacts) and the
    // shape forces of the same order; 1e3 eps for the sums over a vertex's terms. Steps ending there
    // say nothing about the convergence order.
    const double floor = 1e3 * round_off * s.kc;
    std::vector<double> ratios;
    for (std::size_t k = 1; k < r.force_norms.size(); ++k) {
        MESSAGE("step " << k << ": |F| " << r.force_norms[k - 1] << " -> " << r.force_norms[k]);
        if (r.force_norms[k] > floor) ratios.push_back(r.force_norms[k] / std::pow(r.force_norms[k - 1], 2));
    }
    // Quadratic: |F_k+1| <= C |F_k|^2 with C independent of k. The shift mu = theta |F| / sigma (theta = 1
    // once steps are accepted with rho > 3/4) leaves a residual force mu |dx| ~ |F|^2 / (sigma lambda), so
    // C >= 1 / (sigma lambda_min); Newton's own error term (third derivatives of U times |dx|^2 / 2) is
    // allowed as much again: C = 2 / (sigma lambda_min), lambda_min the smallest eigenvalue above the zero
    // modes. Linear convergence at rate q makes the ratio grow by 1/q per step and crosses C within the
    // decades of force crossed here.
    const ModeSpectrum modes = vibrational_modes(s, x);
    const SpectrumCounts counts = count_modes(modes.eigenvalues, zero_mode_threshold(modes.eigenvalues, 0));
    const double lambda_min = modes.eigenvalues(counts.first_positive());
    const double bound = 2 / lambda_min; // sigma = 1
    MESSAGE("lambda_min " << lambda_min << ", bound on |F_k+1| / |F_k|^2: " << bound);
    REQUIRE(ratios.size() >= 2);
    CHECK(r.force_norms.front() / r.force_norms.back() > 1e4);
    for (std::size_t k = 0; k < ratios.size(); ++k) {
        CAPTURE(k);
        CHECK(ratios[k] <= bound);
    }
}

TEST_CASE("Newton finisher: a step that makes a contact is rejected and shortened, the energy never rises "
          "[issue 19]")
{
    // Disk 1 starts 0.5 sigma from contact; its anchor lies 0.5 sigma inside disk 0. The quadratic model
    // without the contact steps into a deep overlap (energy 0.125 against 0.005 at the start).
    Eigen::VectorXd x;
    const DpmSystem s = anchored_pair(1.5, 0.5, x);
    NewtonOptions options;
    options.force_tolerance = 1e-12;
    const NewtonResult r = newton_finish(s, x, options);
    check_contact_change(s, x, r, options.force_tolerance);
    CHECK(r.rejections >= 1);
    // The equilibrium lies in contact, overlap c = 1 - d: disk 0 at -c/10 (its anchor 10 against the
    // contact force c), disk 1 at 1 - 1.1 c with 1e-2 (1.1 c - 0.5) + c = 0, c = 0.005/1.011. Its error is
    // the residual force over the softest stiffness, 1e-12 / 1e-2 = 1e-10 per coordinate.
    const double overlap = 0.005 / 1.011;
    CHECK_CLOSE(x(2) - x(0), 1 - overlap, (Tolerance{0, 1e-9}));
}

TEST_CASE("Newton finisher: a step that breaks a contact is accepted, the energy never rises [issue 19]")
{
    // Disk 1 overlaps disk 0 by 0.1 sigma; its anchor lies beyond contact: the model with the contact
    // steps just past it, where the contact is gone.
    Eigen::VectorXd x;
    const DpmSystem s = anchored_pair(0.9, 2.0, x);
    NewtonOptions options;
    options.force_tolerance = 1e-12;
    const NewtonResult r = newton_finish(s, x, options);
    check_contact_change(s, x, r, options.force_tolerance);
    // Out of contact both disks sit at their anchors, within residual force / stiffness 1e-12 / 1e-2.
    CHECK_CLOSE(x(2) - x(0), 2.0, (Tolerance{0, 1e-9}));
}

TEST_CASE("Newton finisher: non-finite coordinates or energies end in NumericalError, not a hang [issue 19]")
{
    JamResult jammed = small_packing();
    Eigen::VectorXd x = jammed.x;
    x(3) = std::numeric_limits<double>::quiet_NaN();
    NewtonOptions options;
    options.force_tolerance = jammed.fire.force_tolerance;
    Eigen::VectorXd y = x;
    CHECK_THROWS_AS(newton_finish(jammed.system, y, options), NumericalError);
    // Through the relaxation: FIRE hands a non-finite force over at once instead of iterating on it.
    y = x;
    CHECK_THROWS_AS(relax(jammed.system, y, {Relaxation::fire_newton, jammed.fire}), NumericalError);
    // An infinite contact stiffness: the energy of the overlapping packing is infinite.
    DpmSystem stiff = jammed.system;
    stiff.kc = std::numeric_limits<double>::infinity();
    y = jammed.x;
    CHECK_THROWS_AS(newton_finish(stiff, y, options), NumericalError);
}

TEST_CASE("relaxation = fire_newton with rigid rough disks is refused with InputError [issue 19]")
{
    JamOptions o;
    o.model = JamModel::rough_disk;
    o.relaxation = Relaxation::fire_newton;
    CHECK_THROWS_AS(jam(o), InputError);
}
