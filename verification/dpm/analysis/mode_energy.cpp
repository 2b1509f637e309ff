// DPM sec. 9.4.3, Figs. 9.14(a, c), 9.15(c): the energy change Delta U(dr) along the modes of a spectrum
// (dpm/analysis/mode_energy.hpp mode_energies) on energies whose answer is known in closed form. Along an
// eigenvector of a quadratic energy Delta U = lambda dr^2 / 2 at every amplitude and the local exponent is 2;
// along a quartic direction the exponent is 4; the quartic criterion (Delta U(0.1) > 3 lambda 0.1^2/2) tells
// the two apart. Tolerances are round-off: each Delta U is a handful of floating-point operations on numbers
// of size lambda dr^2 (the energy at the minimum is 0, so Delta U has no cancellation).
#include "dpm/analysis/mode_energy.hpp"
#include "support/tolerance.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::round_off;
using softgrain::verification::Tolerance;

TEST_CASE("Delta U along an eigenvector of a quadratic energy is lambda dr^2/2, exponent 2, not quartic "
          "[DPM eq. 9.28, Fig. 9.14(c)]")
{
    // U = x^T A x / 2 with a symmetric positive A, eigenvalues in [0.7, 4.8] (Gershgorin), minimum at x = 0.
    Eigen::Matrix3d A;
    A << 3, 1, 0.5, 1, 2, 0.3, 0.5, 0.3, 4;
    const EnergyWithDerivatives energy = [&A](const Eigen::VectorXd& y, Eigen::VectorXd*, Eigen::MatrixXd*) {
        return 0.5 * y.dot(A * y);
    };
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(Eigen::MatrixXd{A});
    const ModeSpectrum spectrum{solver.eigenvalues(), solver.eigenvectors()};
    ModeEnergyOptions options;
    options.length_unit =
        2.0; // amplitudes in units of 2, energies in units of 3: Delta U = lambda (2 dr)^2/6
    options.energy_unit = 3.0;
    options.soft_end = 3; // every mode soft: the large-amplitude exponent too
    const ModeEnergies along = mode_energies(energy, Eigen::VectorXd::Zero(3), spectrum, options);
    REQUIRE(along.amplitudes.size() == 25);
    CHECK_CLOSE(along.amplitudes.front(), 1e-3, (Tolerance{4 * round_off, 0}));
    CHECK_CLOSE(along.amplitudes.back(), 1.0, (Tolerance{4 * round_off, 0}));
    CHECK(along.energy == 0.0);
    REQUIRE(along.modes.size() == 3);
    for (int k = 0; k < 3; ++k) {
        CAPTURE(k);
        const ModeEnergy& mode = along.modes[static_cast<std::size_t>(k)];
        const double lambda = spectrum.eigenvalues(k);
        // e^T A e = lambda to the eigensolver's backward error, a few eps ||A|| <= a few eps 7 lambda_min.
        for (std::size_t s = 0; s < along.amplitudes.size(); ++s) {
            const double dr = 2.0 * along.amplitudes[s];
            CHECK_CLOSE(mode.delta_u[s], lambda * dr * dr / 2 / 3.0, (Tolerance{200 * round_off, 0}));
        }
        // ln(Delta U(2e-3) / Delta U(1e-3)) / ln 2 with both to 200 eps: 2 to 400 eps / ln 2.
        CHECK_CLOSE(mode.exponent_small, 2.0, (Tolerance{0, 1e3 * round_off}));
        CHECK_CLOSE(mode.exponent_large, 2.0, (Tolerance{0, 1e3 * round_off}));
        CHECK_FALSE(mode.quartic); // Delta U(0.1) = lambda 0.1^2 / 2 exactly: 1, not above 3
    }
    CHECK_CLOSE(median_exponent(along.modes, 0, 3, &ModeEnergy::exponent_small).value(), 2.0,
                (Tolerance{0, 1e3 * round_off}));
}

TEST_CASE("a quartic mode: exponent 4, Delta U above 3 lambda dr^2/2; a zero mode gets no quartic test "
          "[DPM Figs. 9.14(c), 9.15(c)]")
{
    // Two independent directions: y0 a zero mode with U = c y0^4 (the floppy particle's zero modes,
    // Fig. 9.14c), y1 a soft mode with U = a y1^2 / 2 + c y1^4, a << c (Fig. 9.15c: quadratic below
    // dr ~ sqrt(a / c) = 1e-3, quartic beyond).
    const double a = 1e-6, c = 1.0;
    const EnergyWithDerivatives energy = [&](const Eigen::VectorXd& y, Eigen::VectorXd*, Eigen::MatrixXd*) {
        return c * std::pow(y(0), 4) + 0.5 * a * y(1) * y(1) + c * std::pow(y(1), 4);
    };
    const ModeSpectrum spectrum{Eigen::Vector2d(0.0, a), Eigen::Matrix2d::Identity()};
    ModeEnergyOptions options;
    options.first_positive = 1;
    options.soft_end = 2;
    const ModeEnergies along = mode_energies(energy, Eigen::VectorXd::Zero(2), spectrum, options);
    const ModeEnergy &zero = along.modes[0], &soft = along.modes[1];
    for (std::size_t s = 0; s < along.amplitudes.size(); ++s)
        CHECK_CLOSE(zero.delta_u[s], c * std::pow(along.amplitudes[s], 4), (Tolerance{10 * round_off, 0}));
    // c (1e-3)^4 = 1e-12 is above the round-off floor 1e3 eps = 2.2e-13: the pure quartic's exponent is 4.
    CHECK_CLOSE(zero.exponent_small, 4.0, (Tolerance{0, 100 * round_off}));
    CHECK(std::isnan(zero.exponent_large)); // a zero mode: neither the large-amplitude exponent
    CHECK_FALSE(zero.quartic);              // nor the quartic test (its lambda is 0)
    // The soft mode between 0.1 and 0.2: ln(U(0.2)/U(0.1)) / ln 2 exactly, within 1e-3 of 4 (a 0.01/2 is
    // 5e-5 of c 0.1^4).
    const auto U = [&](double dr) { return 0.5 * a * dr * dr + c * std::pow(dr, 4); };
    CHECK_CLOSE(soft.exponent_large, std::log(U(0.2) / U(0.1)) / std::log(2.0),
                (Tolerance{0, 100 * round_off}));
    CHECK_CLOSE(soft.exponent_large, 4.0, (Tolerance{0, 1e-3}));
    CHECK(soft.quartic); // U(0.1) = 1e-4 against 3 a 0.1^2 / 2 = 1.5e-8
}

TEST_CASE("a harmonic anchor has no quartic mode; seen with an eigenvalue 4 times too small it is quartic "
          "[DPM Fig. 9.14(c)]")
{
    // One vertex held by an anchor: U = k/2 |r - r0|^2 exactly, Delta U = lambda dr^2 / 2 at every dr.
    DpmSystem system;
    Eigen::VectorXd x;
    Eigen::Matrix2Xd vertex(2, 1);
    vertex << 1.0, 2.0;
    system.add_particle(vertex, 1.0, ShapeParameters{}, x);
    system.anchors.push_back({0, Eigen::Vector2d(1.0, 2.0), 4.0});
    const Eigen::MatrixXd e = Eigen::Vector2d(0.6, 0.8);
    const ModeEnergies right =
        mode_energies(system_energy(system), x, {Eigen::VectorXd::Constant(1, 4.0), e}, {});
    CHECK_FALSE(right.modes[0].quartic);
    // The same growth is "beyond harmonic" by 4 > 3.
    const ModeEnergies wrong =
        mode_energies(system_energy(system), x, {Eigen::VectorXd::Constant(1, 1.0), e}, {});
    CHECK(wrong.modes[0].quartic);
}
