// Vibrational modes, DPM section 9.4.3: the dynamical matrix M = d^2 U / dr dr (eq. 9.28, unit vertex
// masses) is the exact Hessian of the total energy; its eigenvalues (ascending) and unit eigenvectors come
// from Eigen's SelfAdjointEigenSolver. Dimensionless eigenvalues lambda~ = lambda/(k_a a0) in 2D; a mode
// with lambda~ below the threshold (1e-13 in 2D, Fig. 9.14a; 1e-10 in 3D, Fig. 9.15a), or below the
// eigensolver's round-off bound where that is larger (zero_mode_threshold), counts as a zero mode.
//
// Also: relaxation to a mechanical equilibrium exact to round-off (needed for exact zero-mode counts: a
// residual force f on a particle of size R lifts its rotation to lambda ~ f/R) and the energy change along
// a mode (Fig. 9.14c).
#pragma once

#include "dpm/system/system.hpp"
#include "dpm/system/system3d.hpp"

#include <functional>
#include <optional>
#include <vector>

namespace softgrain::dpm {

struct ModeSpectrum
{
    Eigen::VectorXd eigenvalues;  // ascending [E/L^2]
    Eigen::MatrixXd eigenvectors; // columns, unit norm
};

// Eq. (9.28): the dynamical matrix of the system at x.
Eigen::MatrixXd dynamical_matrix(const DpmSystem& system, const Eigen::VectorXd& x);
ModeSpectrum vibrational_modes(const DpmSystem& system, const Eigen::VectorXd& x);

// Number of zero modes, |lambda| below the threshold, and of negative modes, lambda below minus it (an
// instability: the state is a saddle, not a minimum; decision dpm-packing-minimum). Same units.
int count_zero_modes(const Eigen::VectorXd& eigenvalues, double threshold);
int count_negative_modes(const Eigen::VectorXd& eigenvalues, double threshold);
// Both for an ascending spectrum: the negative modes come first, then the zero ones, then the positive
// ones from index first_positive().
struct SpectrumCounts
{
    int negative = 0, zero = 0;
    int first_positive() const { return negative + zero; }
};
SpectrumCounts count_modes(const Eigen::VectorXd& eigenvalues, double threshold);
// The threshold a zero mode is counted against (decision dpm-zero-mode-count): the paper's threshold, or
// n eps max|lambda| where that is larger. A backward-stable dense eigensolver returns each eigenvalue of the
// n x n symmetric M to within p(n) eps ||M||_2 (Weyl's inequality with the backward error of the symmetric
// QR algorithm, Golub & Van Loan, Matrix Computations, ch. 8), so an exact zero mode (the translations of a
// periodic packing, the rigid motions of a rattler) can come out anywhere below that bound; n eps ||M||_2 is
// the usual numerical-rank tolerance (numpy's matrix_rank, MATLAB's rank). For a
// single 2D particle (n = 20) it stays below 1e-13; for N = 16 packings (n = 384, max lambda~ 17-25) it is
// 1.5e-12 - 2.2e-12. Same units as the eigenvalues.
double zero_mode_threshold(const Eigen::VectorXd& eigenvalues, double threshold);
// The same from the matrix size n and max|lambda| alone (the lowest modes of sparse_modes.hpp, where
// max|lambda| comes from a separate Lanczos run).
double zero_mode_threshold(Eigen::Index n, double largest_magnitude, double threshold);
// Zero modes of an isolated particle at its equilibrium (DPM sec. 9.4.3): a one-vertex disk has its
// `dimension` translations; a floppy polygon N_dof - N_c = N - 1 (Fig. 9.14a), a floppy polyhedron
// N_dof - N_f - 1 = N + 3 (Fig. 9.15a); an elastic shell or a surface-tension particle its rigid motions,
// 3 in 2D and 6 in 3D. A rattler of a packing keeps these.
int free_particle_zero_modes(ShapeModel model, int vertices, int dimension);
// Rattlers of a packing at an equilibrium resolved to `force_resolution` (its largest unbalanced force
// component, e.g. what polish_for_modes returns): the particles on which no contact force component exceeds
// N_mu force_resolution, N_mu the particle's vertex count. A particle held by a single contact is one,
// however small its overlap: its shape forces sum to zero, so that contact's force equals minus the sum of
// the unbalanced forces on its N_mu vertices, at most N_mu force_resolution per component (decision
// dpm-zero-mode-count). A particle without contacts is one too.
std::vector<bool> rattlers(const DpmSystem& system, const Eigen::VectorXd& x, double force_resolution);

// Zero modes of a packing that are not motions of its rattlers alone: the rank of the zero eigenvectors
// (orthonormal columns of zero_modes) restricted to the coordinates of the other particles, i.e.
// dim Z - dim(Z and the rattlers' coordinate subspace). A rattler's own zero modes (3 rigid motions when
// free, 2 when a contact of vanishing force but full stiffness holds it, a floppy rattler's shape modes)
// vanish there up to the error of the computed subspace, eps ||M|| / gap (Davis-Kahan; 1e-11 on the
// packings of Fig. 9.14b), while a mode that moves the other particles keeps at least sqrt(n_B / n) of its
// norm there (the uniform translations; n_B of the n coordinates off the rattlers), above 0.3 while the
// rattlers hold less than 90 % of the vertices. Singular values above 1e-4 count, decades from both.
int zero_modes_beyond_rattlers(const DpmSystem& system, const Eigen::MatrixXd& zero_modes,
                               const std::vector<bool>& rattling);

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

// Where the zero modes of a periodic 3D packing beyond its uniform translations live (Fig. 9.15b: the
// paper counts 3 besides the rattlers'). `zero_modes` holds the zero eigenvectors as
// columns; their span minus the 3 uniform translations is spanned by the left singular vectors
// of (1 - T T^T) Z with singular value above 1/2 (T the unit translations; a translation in span Z gives
// a singular value 0, a mode orthogonal to T gives 1). Returned per particle are the parts (decompose_mode)
// of that subspace, each summed over an orthonormal basis of it and divided by its dimension, so that they
// add up to 1 over all particles and do not depend on the basis; `dimension_out` is the subspace's
// dimension. A rattler's rigid motions show as its translation and rotation, a particle that can turn
// about the line through its contacts as its rotation alone.
std::vector<ModeParts> nontrivial_zero_mode_parts(const DpmSystem3d& system, const Eigen::VectorXd& x,
                                                  const Eigen::MatrixXd& zero_modes, int& dimension_out);

// Quartic mode (sec. 9.4.3, Fig. 9.14c): along the unit eigenvector e with eigenvalue lambda [E/L^2],
// Delta U(dr) = U(x + dr e) - U(x) exceeds the harmonic lambda dr^2 / 2 by more than `factor` (decision
// dpm-quartic-criterion). Quadratic modes stay at the harmonic value until the contacts change. On a measured
// Delta U(dr) (any dimension); mode_energy.hpp applies it to every mode of a spectrum.
inline bool quartic_energy_change(double delta_u, double lambda, double dr, double factor)
{
    return delta_u > factor * 0.5 * lambda * dr * dr;
}

// energy(x, gradient, hessian): the value, adding the gradient and the Hessian when they are not null.
using EnergyWithDerivatives =
    std::function<double(const Eigen::VectorXd&, Eigen::VectorXd*, Eigen::MatrixXd*)>;
// The total energy of a 2D system (system.hpp total_energy) as one; `system` must outlive it.
EnergyWithDerivatives system_energy(const DpmSystem& system);

// The pseudo-inverse of M in Newton's step (and in the linear-response shear modulus,
// linear_shear_modulus.hpp) leaves out the eigenvalues below this fraction of the largest |lambda|.
constexpr double pseudo_inverse_cut = 1e-10;

// Newton steps x -= M^+ grad U (pseudo-inverse over the eigenvalues above pseudo_inverse_cut times the
// largest) until the
// largest force component is below force_tolerance or `max_steps` is reached; returns that force.
// Converges quadratically from a FIRE-relaxed state, also on manifolds of minima (floppy particles). A step
// to a largest force above that of the start is halved until it is below (damped Newton; the polish ends
// where 20 halvings do not help, and the returned force says how far it got): a full Newton step outside
// the quadratic basin can throw a floppy packing far from its minimum.
double polish_newton(const EnergyWithDerivatives& energy, Eigen::VectorXd& x, double force_tolerance,
                     int max_steps);
// The largest force component max_i |dU/dx_i| at x.
double largest_force(const EnergyWithDerivatives& energy, const Eigen::VectorXd& x);
// The damping of polish_newton: the largest fraction 2^-k, k < 20, of `step` at which x - fraction step has
// a largest force below `start_force`; 0 where none has.
double damped_step_fraction(const EnergyWithDerivatives& energy, const Eigen::VectorXd& x,
                            const Eigen::VectorXd& step, double start_force);
// The same on the total energy of a 2D system.
double polish_newton(const DpmSystem& system, Eigen::VectorXd& x, double force_tolerance, int max_steps);
// The equilibrium a packing's spectrum is taken at (decision dpm-zero-mode-count): polish_newton to a largest
// force below 1e-14 force_unit, at most 30 steps; returns the largest force reached. FIRE stops the jamming
// protocol at an rms force of 1e-4 P_t, which leaves forces of ~1e-10 on rattlers: their rotations (exact
// zero modes only where the particle's force vanishes) then sit at |lambda~| ~ 1e-12 - 1e-9, and a particle
// held by one contact of vanishing force is not yet a rattler.
double polish_for_modes(const EnergyWithDerivatives& energy, Eigen::VectorXd& x, double force_unit);
double polish_for_modes(const DpmSystem& system, Eigen::VectorXd& x, double force_unit);

// Moves a packing off a saddle (decision dpm-packing-minimum). A Newton-polished copy of x
// (polish_for_modes) is a saddle when the lowest eigenvalue of its Hessian lies below minus the zero-mode
// threshold (zero_mode_threshold of `threshold`, both in eigenvalue_unit). Then x becomes that copy moved
// along the lowest mode to the lowest energy among the amplitudes +-a, a = 1e-6 sigma doubled up to
// `max_amplitude`, and the function returns true. It returns false, x unchanged, at a minimum and where no
// amplitude lowers U by more than its round-off n eps |U| (a saddle whose negative curvature is cut off by
// quartic terms within 1e-6 sigma, as on the 2D floppy packing of DPM-Fig9.14def). Stepping only to the
// first lower amplitude is not enough: FIRE then falls back to the saddle (4 of 4 tries on the 16 x 42
// shell packing).
bool leave_saddle(const EnergyWithDerivatives& energy, Eigen::VectorXd& x, double force_unit,
                  double eigenvalue_unit, double threshold, double max_amplitude);

// The move of leave_saddle once the saddle is found: x becomes `polished` (a critical point, energy
// U(polished) = u0) moved along its unit lowest mode to the lowest energy among the amplitudes +-a,
// a = 1e-6 sigma doubled up to max_amplitude, and true is returned; false, x unchanged, where no amplitude
// lowers U by more than n eps |u0|.
bool step_off_saddle(const EnergyWithDerivatives& energy, const Eigen::VectorXd& polished, double u0,
                     const Eigen::VectorXd& lowest, double max_amplitude, Eigen::VectorXd& x);

// U(x + amplitude e) - U(x), for any energy (2D or 3D) and for a 2D system.
double energy_change_along(const EnergyWithDerivatives& energy, const Eigen::VectorXd& x,
                           const Eigen::VectorXd& mode, double amplitude);
double energy_change_along(const DpmSystem& system, const Eigen::VectorXd& x, const Eigen::VectorXd& mode,
                           double amplitude);

// Local exponent d ln dU / d ln dr between two amplitudes (Figs. 9.14c, 9.15c); NaN where dU is not above
// `floor` (round-off level).
double local_exponent(double du1, double du2, double dr1, double dr2, double floor);

// The median of the local exponents that are not NaN (the upper middle one of an even count), nothing when
// every one is NaN: the summary's zero_mode_exponent and quadratic_mode_exponent (Figs. 9.14c, 9.15c).
std::optional<double> median_exponent(std::vector<double> exponents);

} // namespace softgrain::dpm
