// SPD section 5 (Trivino et al.): uniaxial compaction of an assembly of frictionless core-shell rings.
//
// Protocol (decision spd-compaction-deposition): (1) rigid-disk deposition: disks of the rings' outer radii
// R_i + r fall under gravity into the box and come to rest by FIRE energy minimisation (cheap: 2 dof per
// particle); (2) the SPD rings are placed at the disk centres and relaxed under gravity by damped dynamics
// (relax, 5% of the critical damping of the ring's ovalisation mode) with the set's core stiffness eta and
// plasticity off, until the largest unbalanced force on a free vertex is below rest_tolerance times the
// particle weight; (3) gravity is removed, plasticity switched on, the top wall placed in contact with the
// highest ring (H = H0) and moved down at constant speed to eps = ln(H0/H) = strain_max (or until
// sigma = stress_max sigma*), then up at the same speed back to H0 (unloading). Time step 0.25 dt_c
// (decision spd-compaction-time-step). The packing of step (1) is a deterministic function of the seed, so
// the parameter sets of Fig. 27 share it exactly.
//
// Measures: sigma = top-wall force / (W s), sigma* = F*/(2 R s), F* = k_b/R (eq. 37, R the mean radius);
// V_s = sum of the particle areas A_i + P_i r + pi r^2 (each shell polygon dilated by the vertex radius r,
// Steiner's formula; decision spd-compaction-solid-volume); void ratio e = (W H - V_s)/V_s;
// Delta V_s/Delta V = (V_s0 - V_s)/(W (H0 - H)); per-particle elastic energy W_i
// (ShellModel::elastic_energy).
#pragma once

#include "core/fits.hpp"
#include "spd/assembly.hpp"

#include <functional>
#include <optional>
#include <vector>

namespace softgrain {
class Checkpoints;
}

namespace softgrain::spd {

struct CompactionSetup
{
    AssemblySetup assembly;       // particles, ring (nodes, eta, plastic_ratio, shell), spread, seed
    double gravity = 1e-2;        // particle weight m_p g over the ring stiffness EI/R^2 (R the mean radius)
    double rest_tolerance = 1e-2; // rest criterion: largest unbalanced vertex force over the particle weight
    double wall_speed = 1e-3; // top-wall speed V over R omega_2 (omega_2: ovalisation frequency, ring.hpp)
    double strain_max = 0.3;  // eps = ln(H0/H) at the end of loading
    // ... or earlier, when sigma reaches stress_max sigma*: incompressible rings (eta = inf) cannot reach
    // eps = ln(H0/H) > ln(V0/V_s) and a stiff sample would overlap its contacts first (exit 3).
    double stress_max = 50;
    int records = 100; // recorded states per half cycle
};

// The setup of the scene spd.compaction with its defaults (40 rings of 16 vertices, h = 0.1 R, a radius
// spread of 0.15, dt = 0.2 dt_c: decisions spd-compaction-time-step, spd-vertex-pair-stability), where
// they differ from the struct's.
CompactionSetup compaction_scene_defaults();

// Step (1): centres of frictionless disks (outer radii, unit weight each) at rest under gravity in a box of
// the given width (walls x = 0, x = width, y = 0), released from a jittered lattice drawn from `seed`.
struct DiskPacking
{
    std::vector<Vec2> centres;
    double top = 0; // highest point of the disks [m]
    long iterations = 0;
};
DiskPacking deposit_disks(const std::vector<double>& radii, double width, std::uint64_t seed);

// Steps (1)-(2): the rings at rest under gravity.
struct Deposit
{
    Assembly assembly;
    DiskPacking disks;
    double weight = 0;         // particle weight m_p g [N]
    double dt = 0;             // time step of the soft relaxation [s]
    long steps = 0;            // steps of the soft relaxation
    double residual_force = 0; // largest unbalanced vertex force at rest [N]
    double bottom_force = 0;   // vertical force on the bottom wall at rest [N]
};
Deposit deposit(const CompactionSetup& setup);
// Step (1) and the rings placed at the disk centres under gravity, not yet relaxed (steps = 0).
Deposit place_rings(const CompactionSetup& setup);
// Step (2): relaxes a placed deposit, continuing after `d.steps` steps already taken; after_check(d) is
// called at each unsuccessful rest check (where a checkpoint may be written).
void settle(const CompactionSetup& setup, Deposit& d, const std::function<void(const Deposit&)>& after_check);

// Width of the box: a square sample at the packing fraction 0.82 of random disk packings,
// W = sqrt(n pi <R^2> / 0.82) (decision spd-compaction-parameters).
double compaction_box_width(const std::vector<double>& radii);

// Area of particle `shell` with its shell thickness: polygon area + perimeter r + pi r^2 [m^2].
double solid_area(const ShellModel& model, int shell);

struct CompactionState
{
    double strain;         // ln(H0/H)
    double height;         // H [m]
    double force_top;      // vertical force of the particles on the top wall (upwards) [N]
    double force_bottom;   // on the bottom wall (downwards) [N]
    double solid_area;     // sum of solid_area [m^2]
    double kinetic_energy; // [J]
    bool loading;
    double time; // since the top wall started to move (the deposit's steps excluded) [s]
};

// The sample at one instant: vertex positions of each particle and its elastic energy W_i [J].
struct CompactionSnapshot
{
    double strain = 0, height = 0; // ln(H0/H), H [m]
    std::vector<std::vector<Vec2>> particles;
    std::vector<double> energy;
};

struct CompactionResult
{
    Deposit deposit;
    double height0 = 0, width = 0; // H0, W [m]
    double solid_area0 = 0;        // V_s / s at H0 [m^2]
    std::vector<CompactionState> states;
    // Snapshots of the loading at H0, eps_max/3, 2 eps_max/3 and its end (Fig. 26; the last is Fig. 29).
    std::vector<CompactionSnapshot> snapshots;
    double dt = 0, wall_speed = 0; // [s], [m/s]
    long steps = 0;
};
// observe(model, state) is called at each recorded state (for checks); progress(fraction) as it runs.
// With `checkpoints`, the run writes its whole state when one is due and, if asked to, starts from the last
// one: the result is the same, bit for bit, as that of an uninterrupted run.
CompactionResult compaction(const CompactionSetup& setup,
                            const std::function<void(const Assembly&, const CompactionState&)>& observe,
                            const std::function<void(double)>& progress, Checkpoints* checkpoints = nullptr);

// The measures above on a recorded state: sigma/sigma* (eq. (37)) on the top wall or the bottom wall, the void
// ratio e, and Delta V_s/Delta V (NaN at H >= H0, where Delta V = 0).
double top_stress_over_sigma_star(const CompactionSetup& setup, const CompactionResult& result,
                                  const CompactionState& state);
double bottom_stress_over_sigma_star(const CompactionSetup& setup, const CompactionResult& result,
                                     const CompactionState& state);
double void_ratio(const CompactionResult& result, const CompactionState& state);
double solid_volume_share(const CompactionResult& result, const CompactionState& state);

// What Figs. 27-28 read off the loading and unloading curves.
struct CompactionMeasures
{
    CompactionState end_of_loading; // the last loading state (eps = strain_max or sigma = stress_max)
    double stress_max = 0;          // largest sigma/sigma* of the loading
    double volume_share_peak = 0;   // largest Delta V_s/Delta V of the loading from eps = 0.05
    double residual_strain = NAN;   // eps where the top wall leaves the sample on unloading (NaN: never)
    // Quasi-static check: largest |F_top - F_bottom| over the loading, relative to the largest F_top.
    double wall_force_mismatch = 0;
    // Eq. (38), e = e0 - C log10(sigma/sigma*), fitted over the loading states within the last two decades
    // of stress (slope -C, intercept e0; absent below two states).
    std::optional<Line> compressibility;
    std::size_t compressibility_points = 0;
};
CompactionMeasures measure_compaction(const CompactionSetup& setup, const CompactionResult& result);

// Write or read the protocol's records for a checkpoint (core/checkpoint.hpp).
void transfer(Archive& archive, DiskPacking& packing);
void transfer(Archive& archive, Deposit& deposit);
void transfer(Archive& archive, CompactionSnapshot& snapshot);
void transfer(Archive& archive, CompactionResult& result);

} // namespace softgrain::spd
