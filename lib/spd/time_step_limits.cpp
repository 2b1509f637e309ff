#include "spd/time_step_limits.hpp"

#include "core/errors.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace softgrain::spd {

double critical_time_step(const ShellModel& model)
{
    double k_max = model.contact_law().k_n;
    if (!model.links().empty()) k_max = std::max({k_max, model.link_law().k_n, model.link_law().k_t});
    const std::vector<Shell>& shells = model.shells();
    for (std::size_t index = 0; index < shells.size(); ++index) {
        const Shell& s = shells[index];
        if (s.rigid) continue;
        double l_min = INFINITY;
        for (int k = 0; k < s.elements(); ++k)
            l_min = std::min(l_min, model.element_length(s.first + k));
        k_max = std::max({k_max, s.laws.k_s, 4.0 * s.laws.k_b / (l_min * l_min)});
        k_max = std::max(k_max, model.core_stiffness(static_cast<int>(index)));
    }
    return std::sqrt(model.min_vertex_mass() / k_max);
}

namespace {
// Largest h of the damped oscillator v' = v - h (omega^2 x + gamma v), x' = x + h v': the root of
// h^2 omega^2 + 2 h gamma = 4.
double damped_oscillator_limit(double omega2, double gamma)
{
    return (std::sqrt(gamma * gamma + 4 * omega2) - gamma) / omega2;
}
} // namespace

double stable_time_step(const ShellModel& model)
{
    double limit = critical_time_step(model);
    const ContactLaw& contact = model.contact_law();
    if (contact.k_n > 0) { // the model has contacts
        const double m = model.min_vertex_mass(), omega2 = contact.k_n / m,
                     gamma = contact.normal_damping / m;
        limit = std::min(limit, damped_oscillator_limit(omega2, gamma)); // a vertex on a wall
        const std::vector<Shell>& shells = model.shells();
        const auto free_shells =
            std::count_if(shells.begin(), shells.end(), [](const Shell& s) { return !s.rigid; });
        if (free_shells > 1) limit = std::min(limit, damped_oscillator_limit(4 * omega2, 4 * gamma));
    }
    return limit;
}

void check_time_step(const ShellModel& model, double dt)
{
    const double dt_c = critical_time_step(model), limit = stable_time_step(model);
    if (!(dt > 0)) // a dt_factor that underflows: every step would leave the state as it is
        throw InputError("the time step dt = " + number_text(dt) + " s (dt_c = " + number_text(dt_c) +
                         " s); allowed: dt_factor giving dt > 0");
    if (dt <= limit) return;
    std::ostringstream cause;
    cause << "dt = " << dt << " s (dt/dt_c = " << dt / dt_c << ") is above the stability limit " << limit
          << " s (" << limit / dt_c << " dt_c, dt_c = sqrt(m/k_max) = " << dt_c
          << " s): the smallest of dt_c and the damped-contact limits (sqrt(gamma^2 + 4 omega^2) - "
             "gamma)/omega^2 of velocity Verlet for a vertex on a wall and, between free shells, for a "
             "vertex-vertex pair (decisions spd-stability-limit, spd-vertex-pair-stability)";
    throw NumericalError("time step", model.steps(), cause.str());
}

} // namespace softgrain::spd
