// Swinging cube (Frenning 2022, section 6.2, eq. (53), Fig. 5).
//
// Unit cube 0 <= X_i <= L, symmetric BCs (normal motion fixed) on X_i = 0, antisymmetric BCs (tangential
// motion fixed) on X_i = L. Exact solution of *linear* elastodynamics, eq. (53):
//   u = cos(omega t) [U1 sin(k X1) cos(k X2) cos(k X3); U2 cos sin cos; U3 cos cos sin],
//   k = pi/(2L), omega = sqrt(3) k c_s, c_s = sqrt(mu/rho), valid for U1 + U2 + U3 = 0 (div u = 0).
// The run starts from u(X, 0), v = 0, and reports the normalised L2 error of the particle displacements at
// t_end.
#pragma once

#include "vsm/dynamics.hpp"
#include "vsm/vsm_model.hpp"

#include <cstdint>
#include <functional>
#include <vector>

namespace softgrain::vsm {

struct SwingingCube
{
    double length = 1.0;                     // L [m]
    Vec3 amplitude{5.0e-4, 5.0e-4, -1.0e-3}; // U1, U2, U3 [m]
    Material material{17.0e6, 0.45, 1.1e3};
    double wave_number() const;                                // k = pi / (2 L) [1/m]
    double angular_frequency() const;                          // omega = sqrt(3) k c_s [rad/s]
    Vec3 displacement(const Vec3& X, double t) const;          // eq. (53) [m]
    Mat3 displacement_gradient(const Vec3& X, double t) const; // d u_i / d X_j of eq. (53) [1]
};

struct SwingingCubeSetup
{
    SwingingCube cube;
    int per_side = 8;
    double jitter = 0.1;
    std::uint64_t seed = 1;
    ModelOptions options{InternalForce::eq43, 1.0, 1.0};
    double end_time = 5e-3; // s
    double cfl = 0.3;
    bool time_step_check = true; // refuse dt above the predicted limit (vsm/stability.hpp)
};

// The error of a particle state against eq. (53) at time t, split three ways to tell where it comes from.
struct SwingingCubeError
{
    double t = 0;
    double l2 = 0; // sqrt(sum |u_a - u(X_a,t)|^2) / sqrt(sum |u(X_a,t)|^2), all particles
    // The same over the particles whose reference position lies within one spacing L/n of a face (the
    // boundary layer, where the ghost least squares of eqs. (15)-(24) act) and over the others (interior).
    double boundary_layer = 0, interior = 0;
    // Projection of u_a on the exact mode shape phi_a = u(X_a, 0): u_a = c(t) phi_a + r_a. mode_amplitude is
    // c(t) (exactly cos(omega t)); residual = sqrt(sum |r_a|^2 / sum |phi_a|^2), the part of the error that
    // is not the swinging mode itself (other modes excited by the discrete initial state, jitter noise).
    double mode_amplitude = 0, residual = 0;
};

struct SwingingCubeResult
{
    double displacement_error_l2 = 0;      // sqrt(sum |u_a - u(X_a,t)|^2) / sqrt(sum |u(X_a,t)|^2)
    SwingingCubeError error;               // the split of the final error
    double spacing = 0;                    // mean particle spacing L / per_side [m]
    Points<3> X;                           // reference positions
    std::vector<double> initial_von_mises; // von Mises stress of each particle at t = 0 [Pa] (Fig. 4)
    // sqrt(sum_a (vm_a - vm(X_a))^2 / sum_a vm(X_a)^2): the particles' initial von Mises stress against that
    // of the exact F = I + grad u of eq. (53) at their reference positions, both by eq. (48).
    double initial_von_mises_error_l2 = 0;
    double dt = 0;
    double dt_limit = 0; // predicted stability limit (vsm/stability.hpp) [s]
    long steps = 0;
    int particles = 0;
};

// The particles (jittered cell-centred lattice) and the model of the cube with its boundary conditions.
Points<3> swinging_cube_particles(const SwingingCubeSetup& setup);
Model swinging_cube_model(const SwingingCubeSetup& setup, const Points<3>& X);

// Runs the cube to end_time; observe(error) is called at `samples` evenly spaced steps (and at t = 0) when
// given, for error histories; on_step, if given, sees the start and every time step. Throws NumericalError
// (exit 3) when the displacement leaves the energy bound of a stable run: a leapfrog instability that the
// neo-Hookean law saturates before any J <= 0 (decision swinging-blow-up).
SwingingCubeResult run_swinging_cube(const SwingingCubeSetup& setup,
                                     const std::function<void(const SwingingCubeError&)>& observe = {},
                                     int samples = 0, const StepObserver& on_step = {});

// An error split in two parts, |e|^2 = |c - cos(omega t)|^2 |phi|^2 + |r|^2 (r orthogonal to phi), each
// normalised like the total (by |cos(omega t)| |phi|): the error of the swinging mode itself (phase and
// amplitude) and the rest (other modes).
struct ModeErrorParts
{
    double mode = 0, other = 0;
};
ModeErrorParts mode_error_parts(const SwingingCube& cube, const SwingingCubeError& error);

} // namespace softgrain::vsm
