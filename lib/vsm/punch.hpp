// Punch test (Frenning 2022, section 6.4, Figs. 9-10).
//
// Specimen 0 <= X1 <= 1 m (width), 0 <= X2 <= 0.5 m (height), 0 <= X3 <= 0.1 m (thickness). A rigid punch
// moves the middle third of the top face X2 = 0.5 down at 0.1 m/s without slip (total displacement BC); the
// rest of the top face is free; every other face is symmetric (zero normal displacement). Neo-Hookean
// E = 1 MPa, nu = 0.45; artificial viscosity c1 = c2 = 0.1, eq. (51); contact stabilisation
// xi_n = xi_t = xi, eq. (50).
#pragma once

#include "vsm/dynamics.hpp"
#include "vsm/vsm_model.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace softgrain::vsm {

struct PunchSetup
{
    std::array<int, 3> counts{21, 11, 3}; // particles along X1, X2, X3 (counts[0] divisible by 3)
    double jitter = 0;                    // 0: regular; irregular arrangements use 0.2 of the spacing
    std::uint64_t seed = 1;
    Material material{1.0e6, 0.45, 1.0e3};
    ModelOptions options{InternalForce::eq43, 1.0, 1.0, 0.1, 0.1};
    double punch_velocity = 0.1;                     // m/s, downwards
    std::vector<double> snapshot_strains{0.15, 0.3}; // punch displacement / height; the run ends at the last
    double cfl = 0.3;
    bool time_step_check = true; // refuse dt above the predicted limit (vsm/stability.hpp)
};

struct PunchSnapshot
{
    double strain = 0, t = 0;
    Points<3> x;
    std::vector<double> pressure;  // Cauchy pressure of each particle [Pa]
    double punch_force = 0;        // downward reaction on the punch [N], the paper's D P_a A_ab of eq. (39)
    double punch_load_total = 0;   // punch_force plus the stabilisation's load on the punch, eq. (46) [N]
    double nonaffine_ratio = 0;    // sqrt(sum |u_loc|^2 / sum |x_ab - X_ab|^2) over real bonds
    double pressure_roughness = 0; // sqrt(sum (p_a - mean_b p_b)^2 / sum p_a^2), b real neighbours of a
};

struct PunchResult
{
    int particles = 0;
    long steps = 0;
    double dt = 0;
    double dt_limit = 0; // predicted stability limit (vsm/stability.hpp) [s]
    std::vector<PunchSnapshot> snapshots;
};

Domain punch_domain(double width, double height, double thickness); // labels: box 0..5, top free 3, punch 6

// observe, if given, sees each snapshot as it is taken (the result holds them all); on_step, if given, the
// start and every time step.
PunchResult run_punch(const PunchSetup& setup, const std::function<void(const PunchSnapshot&)>& observe = {},
                      const StepObserver& on_step = {});

} // namespace softgrain::vsm
