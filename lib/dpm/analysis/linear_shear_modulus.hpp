// Linear-response shear modulus of a jammed periodic packing (DPM sec. 9.4.3, issue 19): the second derivative
// of the relaxed energy E(gamma) = min_x U(x, gamma) at gamma = 0, next to the finite-strain G of
// shear_modulus.hpp. U is the total energy (shape terms, eqs. 9.1/9.2, and contacts), gamma the Lees-Edwards
// strain, V the box area (2D) or volume (3D). Expanding U to second order in (dx, dgamma) and minimising over
// dx (first order: H dx = -Xi dgamma) gives
//
//   sigma_xy = (1/V) dU/dgamma,
//   G = (1/V) d^2E/dgamma^2 = (1/V) [ d^2U/dgamma^2 - Xi^T H^+ Xi ],
//   Xi_i = d^2U/(dx_i dgamma) [E/L],   H = d^2U/dx dx [E/L^2] (eq. 9.28),
//
// i.e. G = G_affine - Xi~^T H^+ Xi~ with G_affine = (1/V) d^2U/dgamma^2 and Xi~ = Xi / V^(1/2). H^+ is the
// pseudo-inverse on the complement of the zero modes (global translations, rattlers, floppy shape modes):
// a zero mode u with u . Xi = 0 (translations and rattlers exactly, by symmetry) does not relax; one with
// u . Xi != 0 would make E(gamma) not quadratic (reported as zero_mode_load).
//
// Convention (local_derivatives.hpp, StrainDerivatives): the derivatives are taken at fixed unwrapped
// coordinates, gamma acting only through the image translations (the image-shift convention). The
// finite-strain procedure shears the coordinates affinely (x_i += dgamma y_i, then relaxes); that is the
// change of variables x -> x + gamma A (A_i = y_i e_x), under which d^2U/dgamma^2 and Xi change (by
// 2 A.Xi + A^T H A and H A) but, at an equilibrium (grad U = 0, Xi in the range of H), G does not:
// E(gamma) is the same function of gamma.
//
// The solve is sparse: the zero modes N (shift-and-invert Lanczos, sparse_modes.hpp; counted by the inertia
// of H -+ tau) are removed from Xi (b = (1 - N N^T) Xi), and H z = b is solved with the coordinates of
// dim N coordinates pinned (column-pivoted QR of N^T picks those where N is best conditioned): the pinned
// equations follow from the others because u^T H = 0 and u^T b = 0 for every zero mode u, so the sparse
// LDL^T of the remaining principal submatrix (definite at a minimum) gives a z with H z = b, and
// b^T z = b^T H^+ b whatever null component z has. The relative residual |H z - b| / |b| is returned.
#pragma once

#include "dpm/analysis/modes.hpp"
#include "dpm/laws/local_derivatives.hpp"
#include "dpm/system/system.hpp"
#include "dpm/system/system3d.hpp"

#include <Eigen/SparseCore>

namespace softgrain::dpm {

struct LinearShearModulus
{
    double modulus = 0;    // G [stress unit: E/L^2 in 2D, E/L^3 in 3D]
    double affine = 0;     // (1/V) d^2U/dgamma^2 at fixed x (image-shift convention)
    double relaxation = 0; // (1/V) Xi^T H^+ Xi (>= 0 at a minimum)
    double stress = 0;     // sigma_xy = (1/V) dU/dgamma = -Sigma_xy of eq. (9.26)
    // Eigenvalues within +- pseudo_inverse_cut lambda_max (modes.hpp) are zero modes, left out of H^+ as
    // polish_newton leaves them out, so that the linear and the finite-strain G leave out the same modes.
    int zero_modes = 0;     // eigenvalues of H within +- pseudo_inverse_cut lambda_max
    int negative_modes = 0; // eigenvalues below -pseudo_inverse_cut lambda_max: a saddle, not a minimum
    double largest_eigenvalue = 0; // lambda_max of H
    double zero_mode_load = 0;     // |N^T Xi| / |Xi|: Xi's part along the zero modes
    double residual = 0;           // |H z - b| / |b| of the solve
};

// G from the sparse Hessian h, the strain derivatives of the same terms and the box volume.
// NumericalError where a sparse factor breaks down.
LinearShearModulus linear_shear_modulus(const Eigen::SparseMatrix<double>& h, const StrainDerivatives& strain,
                                        double volume);

// The same for a 2D or 3D periodic system at x (an equilibrium: the formula assumes grad U = 0).
// InputError without a box.
LinearShearModulus linear_shear_modulus(const DpmSystem& system, const Eigen::VectorXd& x);
LinearShearModulus linear_shear_modulus(const DpmSystem3d& system, const Eigen::VectorXd& x);

} // namespace softgrain::dpm
