// SPD assemblies (Trivino et al., section 5): many core-shell rings in a rectangular box of rigid walls.
#pragma once

#include "spd/ring.hpp"
#include "spd/shell_model.hpp"

#include <cstdint>
#include <vector>

namespace softgrain::spd {

// The rings share the shell material, eta, M^Y/M*, nodes per ring and vertex mass of `ring` (ring.radius is
// the mean radius R); radii are R (1 + spread g), g a standard normal truncated at |g| < 2 (decision
// spd-polydispersity), drawn from `seed`.
struct AssemblySetup
{
    int particles = 100;
    RingSetup ring;
    double radius_spread = 0; // Delta R / R (standard deviation)
    std::uint64_t seed = 1;
};

// Rings on a square lattice of pitch 2 (R_max + r) (neighbours touching), `columns` wide, inside a box of
// four rigid walls (radius 0) touching the outer rings. Contact law of the ring scenes (decisions
// spd-ring-walls, spd-contact-damping): k_n = k_s, frictionless, normal damping 2 sqrt(m k_n).
struct Assembly
{
    ShellModel model;
    std::vector<int> particles; // shell index of each ring
    std::vector<double> radii;  // initial radius of each ring [m]
    int bottom = 0, top = 0, left = 0, right = 0;
    double width = 0, height = 0; // inner box size between the wall lines [m]
};
Assembly rings_in_box(const AssemblySetup& setup, int columns);
// Writes or reads an assembly for a checkpoint (core/checkpoint.hpp).
void transfer(Archive& archive, Assembly& assembly);

// The ring radii of a setup: R (1 + spread g), g drawn from `seed` (decision spd-polydispersity).
std::vector<double> ring_radii(const AssemblySetup& setup);
// Rings of the given radii centred at `centres`, in the box [0, width] x [0, height] of four rigid walls
// (radius 0, the bottom wall on y = 0), with the contact law of rings_in_box.
Assembly rings_at(const AssemblySetup& setup, const std::vector<double>& radii,
                  const std::vector<Vec2>& centres, double width, double height);

// Free (non-rigid) vertices of the assembly.
int particle_vertices(const Assembly& assembly);

} // namespace softgrain::spd
