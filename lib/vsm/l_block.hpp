// L-shaped block (Frenning 2022, section 6.3, Figs. 6-8; after Simo & Tarnow [63]).
//
// A free block, union of [0,6]x[0,3]x[0,3] and [0,3]x[0,10]x[0,3] m (the usual Simo-Tarnow geometry; the
// paper gives it only in Fig. 6a), loaded by nominal tractions T1 = -T2 = p(t) [150, 300, 900] N/m^2 on the
// faces X1 = 6 and X2 = 10, p(t) = max(2.5 - |k t - 2.5|, 0), k = 1/s. After t = 5 s no external force acts:
// linear and angular momentum must stay constant (exactly with eq. (43); eq. (41) breaks angular momentum).
#pragma once

#include "vsm/dynamics.hpp"
#include "vsm/vsm_model.hpp"

#include <functional>

namespace softgrain::vsm {

struct LBlockSetup
{
    double spacing = 0.5; // regular cell-centred lattice [m]
    Material material{50.0e3, 0.3, 1.0e3};
    ModelOptions options{InternalForce::eq43, 1.0, 1.0};
    Vec3 load{150, 300, 900}; // N/m^2, multiplied by p(t)
    double end_time = 55;     // s
    double cfl = 0.3;
    bool time_step_check = true; // refuse dt above the predicted limit (vsm/stability.hpp)
};

struct LBlockSample
{
    double t;
    Vec3 linear;  // sum m v [kg m/s]
    Vec3 angular; // sum m x x v about the origin [kg m^2/s]
};

struct LBlockResult
{
    double linear_momentum_drift = 0;             // max_t |p(t) - p(0)| [kg m/s]
    double angular_momentum_drift_after_load = 0; // max_{t >= 5 s} |l(t) - l(5 s)| [kg m^2/s]
    Vec3 angular_momentum_after_load = Vec3::Zero();
    double impulse_scale = 0; // |A int T1 dt| over the pulse [N s]
    int particles = 0;
    long steps = 0;
    double dt = 0;
};

double l_block_pulse(double t); // p(t)

// Runs the block; observe(sample, positions) is called at t = 0, every `stride` steps and at the end;
// on_step, if given, at the start and every time step.
LBlockResult run_l_block(const LBlockSetup& setup, long stride,
                         const std::function<void(const LBlockSample&, const Points<3>&)>& observe,
                         const StepObserver& on_step = {});

} // namespace softgrain::vsm
