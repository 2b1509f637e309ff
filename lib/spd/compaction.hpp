// SPD section 5: uniaxial compaction of an assembly of polydisperse core-shell rings (Figs. 26-29).
#pragma once

#include "spd/assembly.hpp"

#include <functional>
#include <vector>

namespace softgrain::spd {

// Protocol (section 5): the rings fall under gravity into the box from a loose staggered lattice and come to
// rest; gravity is removed and the packing relaxed; the top wall is placed on the highest particle (H = H0,
// first contact) and moves down at constant speed to eps = ln(H0/H) = strain_max, then back up to H = H0.
// The deposition always uses elastic rings with eta = 0 (decision spd-compaction-deposition): runs that
// differ only in eta and M^Y/M* start from one packing; their laws are set after it.
struct CompactionSetup
{
    AssemblySetup assembly; // assembly.ring.eta and plastic_ratio: the laws of the compaction
    double wall_speed =
        0.01; // in units of R omega_2 (omega_2: ovalisation frequency of a free ring of radius R)
    double strain_max = 0.3;     // ln(H0/H) at the turning point
    double strain_record = 0.01; // strain between two records
    double gravity_load = 0.1;   // weight of a column of rings over F*: g = gravity_load F* / (rows N m)
    double damping = 0.2; // global viscous damping c = damping m omega_2 (decision spd-compaction-damping)
};

struct CompactionState
{
    double strain; // eps = ln(H0/H)
    bool loading;
    double stress;              // sigma = F_top / (W s) [Pa]
    double stress_bottom;       // F_bottom / (W s) [Pa]
    double void_ratio;          // e = (W H s - V_s) / V_s
    double volume_change_ratio; // Delta V_s / Delta V (NaN at Delta V = 0)
    double kinetic_energy;      // [J]
};

struct CompactionResult
{
    std::vector<CompactionState> states;
    double H0 = 0, width = 0, sigma_star = 0, e0 = 0;
    double dt = 0, dt_critical = 0;
    long deposition_steps = 0, steps = 0;
    // At the turning point: per particle elastic energy W_i [J] and outline (vertex coordinates) [m].
    std::vector<double> energy_at_max;
    std::vector<std::vector<double>> shape_x, shape_y;
};

CompactionResult compaction(const CompactionSetup& setup, const std::function<void(double)>& progress);

} // namespace softgrain::spd
