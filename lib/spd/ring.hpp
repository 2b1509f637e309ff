// SPD section 4: a single circular particle (regular N-gon ring) under internal pressure (eqs. (19)-(25)) and
// in quasi-static diametral compression between two rigid walls (Figs. 10-25).
#pragma once

#include "spd/calibration.hpp"
#include "spd/shell_model.hpp"

#include <functional>
#include <vector>

namespace softgrain::spd {

struct RingSetup
{
    int nodes = 128;
    double radius = 1; // R0 [m]
    // E [Pa], nu, h [m], s [m], sigma_Y unused (see plastic_ratio).
    ShellMaterial material{1e6, 0.3, 0.02, 0.1};
    double eta = 0; // K_Omega / K_shell, eq. (24)
    // M_b^Y / M*, eq. (32); stretch stays elastic (decision spd-ring-plasticity).
    double plastic_ratio = INFINITY;
    double dt_factor = 0.5; // dt / dt_c
    double vertex_mass = 1; // m [kg]
};

// The ring's laws and scales: k_s, k_b from eqs. (10)-(11) with l0 = 2 R0 sin(pi/N);
// M_b^Y = plastic_ratio M*.
struct RingScales
{
    ShellLaws laws;
    double l0, K_shell, K_Omega, radius_vertex;
    CharacteristicScales characteristic;
    double flexural_rigidity; // EI_eff = k_b l0
};
RingScales ring_scales(const RingSetup& setup);

// Adds the ring (CCW, vertex 0 on the x axis) to a model; returns its shell index.
int add_ring(ShellModel& model, const RingSetup& setup, double pressure_applied);

// The ring between two rigid, frictionless walls touching its shell (section 4.1; decisions spd-ring-walls,
// spd-contact-damping: k_n = k_s, normal contact damping 2 sqrt(m k_n)), and the global damping 2 m omega_2
// used to relax it (omega_2 the ovalisation frequency of the free ring).
struct RingBetweenWalls
{
    ShellModel model;
    int ring = 0, top_wall = 0, bottom_wall = 0;
};
RingBetweenWalls ring_between_walls(const RingSetup& setup);
double ring_damping(const RingSetup& setup);

// Ring under a small internal pressure p, relaxed to equilibrium: the apparent modulus p / (dV/V0).
struct RingPressureResult
{
    double K_measured, volume_strain;
    long steps;
};
// relaxed, if given, sees the relaxed ring (shell `ring` of the model).
RingPressureResult ring_under_pressure(const RingSetup& setup, double pressure,
                                       const std::function<void(const ShellModel&, int ring)>& relaxed = {});

// One recorded state of the compression-decompression cycle.
struct CompressionState
{
    double strain;         // eps = 1 - b/b0 (b = wall gap of the shell mid-line)
    double width;          // a/b0
    double contact_length; // L_c/b0, L_c = N' l0 (N' contact vertices, decision spd-Lc-definition)
    double volume;         // V/V0
    double wall_force;     // F [N] (top wall)
    double stretch_energy, bending_energy; // W_s, W_b [J]
    double core_pressure;                  // p [Pa]
    int contact_vertices;                  // N'
    bool loading;
    // Top-wall contact vertices: x - x_centre [m], f/(s l0) [Pa].
    std::vector<double> profile_x, profile_pressure;
    std::vector<double> shape_x, shape_y; // all ring vertices [m]
};

struct CompressionResult
{
    std::vector<CompressionState> states;
    double shape_residual = 0; // after unloading and release: max | |x_k - centroid| - R0 | / R0
    std::vector<double> released_x, released_y; // the ring after release [m]
    double dt = 0, dt_critical = 0;
    long steps = 0;
};

// Quasi-static compression to strain_max in steps of strain_step (walls moved slowly, then relaxed until the
// largest unbalanced force is below relax_tolerance * force scale), then, if unload, back to eps = 0 and a
// release of the walls. observe(model, state) is called at each recorded state (after each relaxation).
using CompressionObserver = std::function<void(const RingBetweenWalls&, const CompressionState&)>;
CompressionResult ring_compression(const RingSetup& setup, double strain_max, double strain_step, bool unload,
                                   double relax_tolerance, const std::function<void(double)>& progress,
                                   const CompressionObserver& observe = {});

} // namespace softgrain::spd
