// A mass on a linear spring integrated with velocity Verlet: the end-to-end analytic scene `core.harmonic`.
//
// Continuous solution from x(0) = A, v(0) = 0: x = A cos(omega t), omega = sqrt(k/m), T = 2 pi / omega.
// Velocity Verlet reproduces it with a shifted frequency and a bounded energy error, both known exactly:
//   * the discrete solution is x_n = A cos(omega~ n dt) with sin(omega~ dt / 2) = omega dt / 2, so the
//     period is T~ = 2 pi / omega~ = T (1 + (omega dt)^2 / 24 + O(dt^4)): second order in dt;
//   * it conserves the shadow energy H~ = m v^2/2 + k x^2 (1 - (omega dt/2)^2) / 2 exactly, so the energy
//     E = m v^2/2 + k x^2/2 oscillates between E0 (1 - q) and E0, q = (omega dt/2)^2 = (dt/dt_c)^2;
//   * it is stable for dt < dt_c = 2/omega; at and above dt_c the amplitude grows without bound.
#pragma once

#include <functional>

namespace softgrain {

struct HarmonicOscillator
{
    double mass;      // [kg]
    double stiffness; // [N/m]

    double angular_frequency() const;  // omega = sqrt(k/m) [rad/s]
    double period() const;             // T = 2 pi / omega [s]
    double critical_time_step() const; // dt_c = 2/omega [s], the stability limit of velocity Verlet
};

double verlet_period(const HarmonicOscillator& oscillator, double dt);             // T~ [s]
double verlet_energy_error_bound(const HarmonicOscillator& oscillator, double dt); // q = (dt/dt_c)^2 [1]

struct HarmonicRun
{
    double period = 0;           // mean spacing of upward zero crossings of x, linearly interpolated [s]
    double energy_error_max = 0; // max over all steps of |E/E0 - 1| [1]
    long steps = 0;
};

// Called after every step with t [s], x [m], v [m/s] and E/E0 - 1.
using HarmonicObserver = std::function<void(double, double, double, double)>;

// Velocity Verlet steps for `periods` periods at dt; an InputError when that is not 1 to 1e10 steps.
long harmonic_step_count(const HarmonicOscillator& oscillator, double dt, double periods);

// Integrates from x = 1 m, v = 0 over `periods` periods T. Throws NumericalError when the energy
// exceeds 4 E0 or is not finite (impossible for a stable run, whose energy never exceeds E0) and names
// the stability limit when dt >= dt_c.
HarmonicRun simulate_harmonic(const HarmonicOscillator& oscillator, double dt, double periods,
                              const HarmonicObserver& observe = {});

} // namespace softgrain
