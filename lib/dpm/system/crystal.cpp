#include "dpm/system/crystal.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace softgrain::dpm {

DpmSystem triangular_crystal(int n, double a, double sigma, double k, Eigen::VectorXd& x)
{
    const double row_height = a * std::sqrt(3.0) / 2;
    DpmSystem s;
    s.interaction = InteractionKind::rough;
    s.kc = k;
    s.box = Eigen::Vector2d(n * a, n * row_height);
    for (int row = 0; row < n; ++row)
        for (int col = 0; col < n; ++col) {
            Eigen::Matrix2Xd c(2, 1);
            c << (col + 0.5 * (row % 2)) * a, row * row_height;
            s.add_particle(c, sigma, ShapeParameters{}, x);
        }
    return s;
}

std::vector<Phonon> phonon_spectrum(int n, double a, double sigma, double k)
{
    const double pi = std::numbers::pi;
    const Eigen::Vector2d a1(a, 0), a2(0.5 * a, 0.5 * std::sqrt(3.0) * a);
    const double Lx = n * a, Ly = n * a * std::sqrt(3.0) / 2;
    const double tension = k * (sigma - a) / a; // -U'/a
    std::vector<Phonon> phonons;
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
            phonons.push_back({q, ev(0)});
            phonons.push_back({q, ev(1)});
        }
    std::sort(phonons.begin(), phonons.end(),
              [](const Phonon& u, const Phonon& v) { return u.lambda < v.lambda; });
    return phonons;
}

} // namespace softgrain::dpm
