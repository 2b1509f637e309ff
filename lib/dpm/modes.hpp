// Vibrational modes, DPM section 9.4.3: the dynamical matrix M = d^2 U / dr dr (eq. 9.28, unit vertex
// masses) is the exact Hessian of the total energy; its eigenvalues (ascending) and unit eigenvectors come
// from Eigen's SelfAdjointEigenSolver. Dimensionless eigenvalues lambda~ = lambda/(k_a a0) in 2D; a mode
// with lambda~ below the threshold (1e-13 in 2D, Fig. 9.14a) counts as a zero mode.
//
// Also: relaxation to a mechanical equilibrium exact to round-off (needed for exact zero-mode counts: a
// residual force f gives rotation "modes" of order f R) and the energy change along a mode (Fig. 9.14c).
#pragma once

#include "core/fire.hpp"
#include "dpm/system.hpp"
#include "dpm/system3d.hpp"

#include <functional>

namespace softgrain::dpm {

struct ModeSpectrum
{
    Eigen::VectorXd eigenvalues;  // ascending [E/L^2]
    Eigen::MatrixXd eigenvectors; // columns, unit norm
};

// Eq. (9.28): the dynamical matrix of the system at x.
Eigen::MatrixXd dynamical_matrix(const DpmSystem& system, const Eigen::VectorXd& x);
ModeSpectrum vibrational_modes(const DpmSystem& system, const Eigen::VectorXd& x);

// Number of eigenvalues below the threshold (in the same units).
int count_zero_modes(const Eigen::VectorXd& eigenvalues, double threshold);
// Participation ratio (sum_i |u_i|^2)^2 / (N sum_i |u_i|^4) of a mode over its N vertices: about 1 for a
// plane wave (2/3 for a standing one), of order 1/N for a mode on a few vertices (Fig. 9.5b's quasi-localised
// mode).
double participation_ratio(const Eigen::VectorXd& mode);

// Decomposition of a mode u (Fig. 9.5c, d: "modes ... include particle translations, rotations, and
// deformations"), particle by particle: u_i = t + omega z x (r_i - c) + d_i with c the vertex mean,
// t = mean of u_i (rigid translation), omega = sum (r_i - c) x u_i / sum |r_i - c|^2 (rigid rotation, the
// least-squares fit) and d_i the rest (deformation). The three parts are orthogonal; returned are their
// shares of |u|^2 summed over the particles (they add up to 1). One-vertex particles have no rotation part.
// In 3D the same with u_i = t + omega x (r_i - c) + d_i, omega the least-squares rigid rotation (a vector).
struct ModeParts
{
    double translation = 0, rotation = 0, deformation = 0;
};
ModeParts decompose_mode(const DpmSystem& system, const Eigen::VectorXd& x, const Eigen::VectorXd& mode);
ModeParts decompose_mode(const DpmSystem3d& system, const Eigen::VectorXd& x, const Eigen::VectorXd& mode);

// Quartic mode (sec. 9.4.3, Fig. 9.14c): along the unit eigenvector e with eigenvalue lambda [E/L^2],
// Delta U(dr) = U(x + dr e) - U(x) exceeds the harmonic lambda dr^2 / 2 by more than `factor` (decision
// dpm-quartic-criterion). Quadratic modes stay at the harmonic value until the contacts change.
// The same criterion on a measured Delta U(dr) (any dimension): Delta U > factor lambda dr^2 / 2.
inline bool quartic_energy_change(double delta_u, double lambda, double dr, double factor)
{
    return delta_u > factor * 0.5 * lambda * dr * dr;
}
bool is_quartic_mode(const DpmSystem& system, const Eigen::VectorXd& x, const Eigen::VectorXd& mode,
                     double lambda, double dr, double factor);

// FIRE (core) on the total energy; returns its result. Iterations are the cost measure.
FireResult relax_fire(const DpmSystem& system, Eigen::VectorXd& x, const FireOptions& options);

// energy(x, gradient, hessian): the value, adding the gradient and the Hessian when they are not null.
using EnergyWithDerivatives =
    std::function<double(const Eigen::VectorXd&, Eigen::VectorXd*, Eigen::MatrixXd*)>;

// Newton steps x -= M^+ grad U (pseudo-inverse over the eigenvalues above 1e-10 times the largest) until the
// largest force component is below force_tolerance or `max_steps` is reached; returns that force.
// Converges quadratically from a FIRE-relaxed state, also on manifolds of minima (floppy particles). A step
// to a largest force above that of the start is halved until it is below (damped Newton; the polish ends
// where 20 halvings do not help, and the returned force says how far it got): a full Newton step outside
// the quadratic basin can throw a floppy packing far from its minimum.
double polish_newton(const EnergyWithDerivatives& energy, Eigen::VectorXd& x, double force_tolerance,
                     int max_steps);
// The same on the total energy of a 2D system.
double polish_newton(const DpmSystem& system, Eigen::VectorXd& x, double force_tolerance, int max_steps);

// U(x + amplitude e) - U(x), for any energy (2D or 3D) and for a 2D system.
double energy_change_along(const EnergyWithDerivatives& energy, const Eigen::VectorXd& x,
                           const Eigen::VectorXd& mode, double amplitude);
double energy_change_along(const DpmSystem& system, const Eigen::VectorXd& x, const Eigen::VectorXd& mode,
                           double amplitude);

// Local exponent d ln dU / d ln dr between two amplitudes (Figs. 9.14c, 9.15c); NaN where dU is not above
// `floor` (round-off level).
double local_exponent(double du1, double du2, double dr1, double dr2, double floor);

} // namespace softgrain::dpm
