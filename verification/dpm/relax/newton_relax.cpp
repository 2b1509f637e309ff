// The Newton finisher of the relaxation (newton_relax.hpp, issue 19): its minimum against FIRE run to a
// tighter tolerance (2D and 3D), its quadratic convergence (2D and 3D), steps that make and break contacts,
// and its NumericalError.
#include "dpm/relax/newton_relax.hpp"
#include "core/errors.hpp"
#include "dpm/analysis/modes.hpp"
#include "dpm/protocols/jam.hpp"
#include "dpm/protocols/jam3d.hpp"
#include "dpm/system/scale_packing.hpp"
#include "support/tolerance.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <type_traits>

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

// A small jammed 3D packing (4 elastic shell icosahedra at the pressure P k_v v0), FIRE alone.
Jam3dResult small_packing3d(double pressure)
{
    Jam3dOptions o;
    o.model = ShapeModel::shell;
    o.particles = 4;
    o.mesh = "icosahedron";
    o.pressure_onset = o.pressure_max = pressure;
    o.pressures = 0;
    return jam3d(o);
}

template <class System>
constexpr int dimension_of = std::is_same_v<System, DpmSystem> ? 2 : 3;

// The displacement without its uniform translation (an exact zero mode of a periodic packing, along which
// neither minimiser moves the packing except by round-off).
template <int D>
Eigen::VectorXd without_translation(Eigen::VectorXd d)
{
    auto columns = d.reshaped(D, d.size() / D);
    const Eigen::Matrix<double, D, 1> mean = columns.rowwise().mean();
    columns.colwise() -= mean;
    return d;
}

// Every eigenvalue of the dense dynamical matrix (eq. 9.28), ascending.
Eigen::VectorXd eigenvalues_of(const DpmSystem& s, const Eigen::VectorXd& x)
{
    return vibrational_modes(s, x).eigenvalues;
}

Eigen::VectorXd eigenvalues_of(const DpmSystem3d& s, const Eigen::VectorXd& x)
{
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(x.size(), x.size());
    total_energy3d(s, x, nullptr, &m);
    return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(m, Eigen::EigenvaluesOnly).eigenvalues();
}

// The smallest eigenvalue above the zero modes at x, required to be a minimum whose only zero modes are the
// D uniform translations (no rattler, whose place in its cage is not unique).
template <class System>
double lowest_positive_eigenvalue(const System& s, const Eigen::VectorXd& x)
{
    const Eigen::VectorXd eigenvalues = eigenvalues_of(s, x);
    const SpectrumCounts counts = count_modes(eigenvalues, zero_mode_threshold(eigenvalues, 0));
    REQUIRE(counts.negative == 0);
    REQUIRE(counts.zero == dimension_of<System>);
    return eigenvalues(counts.first_positive());
}

// Relaxation with the finisher of the packing (s, x) after an affine compression by 1e-3, against FIRE run
// to a 1000 times tighter tolerance: both states lie within |F| / lambda_min of the minimum (to first order
// the Hessian maps the displacement to the force), |F| <= sqrt(n) times the rms.
template <class System>
void check_against_tight_fire(System s, Eigen::VectorXd x, const FireOptions& fire)
{
    scale_particle_centres<dimension_of<System>>(s, x, 1 - 1e-3);
    const RelaxOptions newton{Relaxation::fire_newton, fire};
    Eigen::VectorXd x_newton = x;
    const RelaxResult r = relax(s, x_newton, newton);
    REQUIRE(r.converged);
    MESSAGE("fire_newton: FIRE " << r.fire_iterations << " iterations, " << r.handovers << " hand-overs, "
                                 << r.newton_steps << " Newton steps, force rms " << r.force_rms);
    CHECK(r.handovers >= 1);
    CHECK(r.kinetic == 0);
    FireOptions tight = fire;
    tight.force_tolerance /= 1000;
    Eigen::VectorXd x_fire = x;
    REQUIRE(relax_fire(s, x_fire, tight).converged);
    const double lambda_min = lowest_positive_eigenvalue(s, x_fire);
    const double n = static_cast<double>(x_fire.size());
    const double allowed = std::sqrt(n) * (fire.force_tolerance + tight.force_tolerance) / lambda_min;
    const double distance = without_translation<dimension_of<System>>(x_newton - x_fire).norm();
    MESSAGE("lambda_min " << lambda_min << ", |x_newton - x_fire| " << distance << ", allowed " << allowed);
    CHECK(distance <= allowed);
}

// Newton from the minimum (s, x) displaced at random by `amplitude` per coordinate: quadratic convergence,
// |F_k+1| <= C |F_k|^2 with C independent of k, at steps that change no contact. The shift
// mu = theta |F| / sigma (theta = 1 once steps are accepted with rho > 3/4) leaves a residual force
// mu |dx| ~ |F|^2 / (sigma lambda), so C >= 1 / (sigma lambda_min); Newton's own error term (third
// derivatives of U times |dx|^2 / 2) is allowed as much again: C = 2 / (sigma lambda_min), lambda_min the
// smallest eigenvalue above the zero modes (sigma = 1). Linear convergence at rate q makes the ratio grow by
// 1/q per step and crosses C within the decades of force crossed here.
// `ratios_needed`: steps above the round-off floor that the check needs.
template <class System>
void check_quadratic_convergence(const System& s, const Eigen::VectorXd& minimum, double amplitude,
                                 std::size_t ratios_needed)
{
    Eigen::VectorXd x = minimum + amplitude * Eigen::VectorXd::Random(minimum.size());
    NewtonOptions options;
    options.force_tolerance = 1e-15; // beyond FIRE's: as far as round-off lets it go
    const NewtonResult r = newton_finish(s, x, options);
    MESSAGE("steps " << r.steps << ", rejections " << r.rejections << ", stop: " << r.stop_reason);
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
    const double bound = 2 / lowest_positive_eigenvalue(s, x);
    MESSAGE("bound on |F_k+1| / |F_k|^2: " << bound);
    REQUIRE(ratios.size() >= ratios_needed);
    CHECK(r.force_norms.front() / r.force_norms.back() > 1e4);
    for (std::size_t k = 0; k < ratios.size(); ++k) {
        CAPTURE(k);
        CHECK(ratios[k] <= bound);
    }
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
          "(tol + tol/1000) / lambda_min, in 2D and 3D [issue 19]")
{
    SUBCASE("2D: 6 shells of 6 and 8 vertices at P = 1e-5 k_a a0")
    {
        const JamResult jammed = small_packing();
        check_against_tight_fire(jammed.system, jammed.x, jammed.fire);
    }
    SUBCASE("3D: 4 shell icosahedra at P = 1e-5 k_v v0")
    {
        const Jam3dResult jammed = small_packing3d(1e-5);
        check_against_tight_fire(jammed.system, jammed.x, jammed.fire);
    }
}

TEST_CASE("Newton finisher: quadratic convergence, |F_k+1| / |F_k|^2 bounded without contact changes, in 2D "
          "and 3D [issue 19]")
{
    SUBCASE("2D")
    {
        // At P = 1e-2 k_a a0 the overlaps (~1e-2 sigma) outlast a random displacement of 1e-4 sigma per
        // coordinate: no contact opens or closes.
        const JamResult jammed = small_packing(1e-2);
        check_quadratic_convergence(jammed.system, jammed.x, 1e-4, 2);
    }
    SUBCASE("3D")
    {
        // At P = 1e-3 k_v v0 the vertex pair of the icosahedra closest to contact is 2.7e-5 sigma from it
        // (touching or not), so a start 1e-6 sigma per coordinate from the minimum changes no contact.
        // From there the force (1e-5) reaches the round-off floor in two steps: one ratio to check.
        const Jam3dResult jammed = small_packing3d(1e-3);
        check_quadratic_convergence(jammed.system, jammed.x, 1e-6, 1);
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
