// Patch tests A, B, C of VSM (Frenning 2022, section 6.1, Table 1; after Taylor et al. [66]).
//
// Unit cube 0 <= X_i <= 1 m, linear displacement u = alpha M X, M = [1 2 3; 4 5 6; 7 8 9], eq. (52);
// neo-Hookean material (48), so the exact solution is the homogeneous state F = I + alpha M with nominal
// stress P(F).
//   A: every particle at its exact position, displacement prescribed on every face; error = max_a |f_a| [N].
//   B: displacement prescribed on every face (total ghosts, D = I), particles free; ramped over ramp_time
//      with damping, held for hold_time; error = max_a |x_a - x_exact(X_a)| [m].
//   C: displacement prescribed on X3 = 0, nominal traction P(F) N on the other five faces; error as in B.
#pragma once

#include "vsm/vsm_model.hpp"

#include <array>
#include <cstdint>
#include <functional>

namespace softgrain::vsm {

enum class PatchVariant { A, B, C };

struct PatchSetup
{
    PatchVariant variant = PatchVariant::A;
    int per_side = 3;
    double jitter = 0.25; // of the lattice spacing
    std::uint64_t seed = 1;
    double alpha = 1e-4;
    Material material{1.0e6, 0.3, 1.0e3};
    ModelOptions options{InternalForce::eq41, 1.0, 1.0};
    double ramp_time = 50;       // s
    double hold_time = 10;       // s
    double cfl = 0.3;            // dt = cfl L_min / c_p
    double damping = 40;         // 1/s, mass-proportional (near critical for the slowest mode)
    bool time_step_check = true; // refuse dt above the predicted limit (vsm/stability.hpp)
};

struct PatchResult
{
    double max_error = 0;      // N (A) or m (B, C)
    double force_scale = 0;    // E alpha h^2: a typical particle force [N]
    double final_residual = 0; // B, C: max_a |f_a| at the end [N]
    long steps = 0;
    int particles = 0;
    double dt = 0;
    Points<3> X; // reference positions of the particles (Fig. 3)
};

Mat3 patch_displacement_gradient(double alpha); // alpha M of eq. (52)

// A state of a patch test for an observer: A's one state, the exact positions (t = 0, step 0, no velocity);
// B and C the start and every time step, leapfrog's half-step velocities. load: the ramp r(t) in [0, 1]
// (the exact solution is X + r alpha M X); final: the state whose error the result reports.
struct PatchState
{
    const Model& model;
    const Points<3>& x;
    const Points<3>& v;
    double t = 0;
    long step = 0;
    double load = 1;
    bool final = false;
};
using PatchObserver = std::function<void(const PatchState&)>;

PatchResult run_patch_test(const PatchSetup& setup, const PatchObserver& observe = {});

// The error of a patch test relative to its scale: A's force error over the typical particle force
// E alpha h^2, B's and C's displacement error over the largest exact displacement |alpha M (1, 1, 1)|
// (eq. (52) at the corner X = (1, 1, 1) m). NumericalError when A's force scale under- or overflows (e.g.
// E = 4.9e-324 Pa): there is then no error to measure, only 0/0.
double patch_relative_error(const PatchSetup& setup, const PatchResult& result);

} // namespace softgrain::vsm
