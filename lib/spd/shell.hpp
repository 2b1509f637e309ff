// One shell of the SPD shell model (Trivino et al., section 2): a closed ring or an open chain of mass
// points, its laws and its core, and its neighbours along the chain.
#pragma once

#include "spd/calibration.hpp"

#include <cmath>

namespace softgrain::spd {

// One shell: its vertex range, topology and laws. Stiffnesses of a frozen (rigid) shell are unused.
struct Shell
{
    int first = 0, count = 0; // vertices [first, first + count)
    bool closed = true;       // closed ring, or open chain ending on the absent vertex
    bool rigid = false;       // all vertices frozen, moved kinematically (walls, section 4.1)
    ShellLaws laws;
    double depth = 1;  // out-of-plane length s [m]
    double radius = 0; // vertex disk / sphero-segment radius r [m]
    // Undrained core modulus, eq. (4) [Pa]; 0: no core stiffness; INFINITY: incompressible core, the limit
    // eta -> inf of eq. (24), imposed as the exact constraint A(x) = A0 whose multiplier is the core pressure
    // (ShellModel::step, decision spd-eta-infinity).
    double K_Omega = 0;
    double pressure_applied = 0; // constant (drained) pressure acting inside the shell [Pa]
    int elements() const { return closed ? count : count - 1; }
    bool has_hinge(int local) const { return closed || (local > 0 && local < count - 1); }
    bool incompressible() const { return closed && std::isinf(K_Omega); }
};

// Neighbours along a shell (local index wrapped without an integer division: these run for every vertex of
// every step).
inline int next_vertex(const Shell& s, int local)
{
    return s.first + (local + 1 == s.count ? 0 : local + 1);
}
inline int previous_vertex(const Shell& s, int local)
{
    return s.first + (local == 0 ? s.count - 1 : local - 1);
}

} // namespace softgrain::spd
