// DPM eq. (9.28), Fig. 9.5(a): the dynamical matrix of a compressed triangular (hexagonal) crystal of soft
// disks, purely repulsive springs k/2 (sigma - r)^2 (eq. 9.3 for one-vertex particles), against the exact
// phonon spectrum of the lattice. A pair at distance a < sigma has the Hessian block
//   U'' e e^T + (U'/a)(I - e e^T),  U'' = k,  U' = -k (sigma - a),
// so the Bloch matrix for a wavevector q is D(q) = sum over the 6 bonds of (1 - cos q.a_b) times that block,
// and its eigenvalues at the n x n wavevectors of a periodic n x n crystal (unit masses) are the 2 n^2
// eigenvalues of the whole Hessian (the two at q = 0 are the zero modes of the translations).
#include "dpm/modes.hpp"
#include "dpm/system.hpp"
#include "support/tolerance.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

using namespace softgrain;
using namespace softgrain::dpm;
using softgrain::verification::Tolerance;

namespace {

// The periodic n x n triangular crystal of spacing a, disks of diameter sigma, contact stiffness k.
DpmSystem triangular_crystal(int n, double a, double sigma, double k, Eigen::VectorXd& x)
{
    DpmSystem s;
    s.interaction = InteractionKind::rough;
    s.kc = k;
    s.box = Eigen::Vector2d(n * a, n * a * std::sqrt(3.0) / 2);
    for (int row = 0; row < n; ++row)
        for (int col = 0; col < n; ++col) {
            Eigen::Matrix2Xd c(2, 1);
            c << (col + 0.5 * (row % 2)) * a, row * a * std::sqrt(3.0) / 2;
            s.add_particle(c, sigma, ShapeParameters{}, x);
        }
    return s;
}

// The exact spectrum: eigenvalues of D(q) for the n^2 wavevectors of the periodic box, q = 2 pi (j/L_x,
// l/L_y) with j, l = 0 ... n-1 (distinct modulo the reciprocal lattice); a1 = a (1, 0), a2 = a (1/2,
// sqrt(3)/2).
std::vector<double> phonon_spectrum(int n, double a, double sigma, double k)
{
    const double pi = std::numbers::pi;
    const Eigen::Vector2d a1(a, 0), a2(0.5 * a, 0.5 * std::sqrt(3.0) * a);
    const double Lx = n * a, Ly = n * a * std::sqrt(3.0) / 2;
    const double tension = k * (sigma - a) / a; // -U'/a
    std::vector<double> lambda;
    for (int j = 0; j < n; ++j)
        for (int l = 0; l < n; ++l) {
            const Eigen::Vector2d q(2 * pi * j / Lx, 2 * pi * l / Ly);
            Eigen::Matrix2d D = Eigen::Matrix2d::Zero();
            for (const Eigen::Vector2d& bond : {a1, a2, Eigen::Vector2d(a2 - a1)}) {
                const Eigen::Vector2d e = bond.normalized();
                const Eigen::Matrix2d block =
                    k * e * e.transpose() - tension * (Eigen::Matrix2d::Identity() - e * e.transpose());
                D += 2 * (1 - std::cos(q.dot(bond))) * block; // the bonds +bond and -bond
            }
            const Eigen::Vector2d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(D).eigenvalues();
            lambda.push_back(ev(0));
            lambda.push_back(ev(1));
        }
    std::sort(lambda.begin(), lambda.end());
    return lambda;
}

} // namespace

TEST_CASE("triangular soft-disk crystal: the dynamical matrix has the exact phonon spectrum [DPM eq. (9.28), "
          "Fig. 9.5(a)]")
{
    const double sigma = 1.0, k = 1.0;
    for (double a : {0.999, 0.99}) { // compressions 1e-3 and 1e-2 sigma: the tension term matters at 1e-2
        CAPTURE(a);
        const int n = 6;
        Eigen::VectorXd x;
        const DpmSystem s = triangular_crystal(n, a, sigma, k, x);
        const Eigen::VectorXd lambda = vibrational_modes(s, x).eigenvalues;
        const std::vector<double> exact = phonon_spectrum(n, a, sigma, k);
        REQUIRE(lambda.size() == static_cast<Eigen::Index>(exact.size()));
        // Dense eigensolver round-off: a few ulp of the largest eigenvalue (about 6 k).
        for (std::size_t m = 0; m < exact.size(); ++m)
            CHECK_CLOSE(lambda(static_cast<Eigen::Index>(m)), exact[m], (Tolerance{0, 1e-12}));
        // The two translations are the only zero modes; the lowest phonon is at |q| = 2 pi/(n a).
        CHECK(std::abs(exact[1]) < 1e-14);
        CHECK(exact[2] > 1e-2);
    }
}
